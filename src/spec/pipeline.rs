//! The spec's build, at the top of `spec/`: validation with the loop closures solved by
//! `spec/closures.rs`, which itself builds the loop's geometry through the same validation
//! (passed the solver, so the two files do not import each other in a circle).

use super::SpecError;
use crate::mechanism::Mechanism;
use crate::wire::SpecFile;

/// Builds the mechanism described by a spec: every reference resolved, every expression
/// parsed, the loop closures and rolling conditions solved, every error naming the JSON path
/// of the offending value.
pub fn build(spec: &SpecFile) -> Result<Mechanism, SpecError> {
    super::validate::build_solving(spec, &super::closures::solve)
}
