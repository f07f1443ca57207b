//! How the exact side refuses a spec: a message at the JSON path of the offending value. The
//! leaf every file of `spec/` reports through.

use super::SpecError;
use crate::expr::ExprError;
use crate::quantity::validate_name;

/// A refusal at the JSON path `path`.
pub(super) fn at(path: impl Into<String>, message: impl Into<String>) -> SpecError {
    SpecError::Invalid {
        path: path.into(),
        message: message.into(),
        location: None,
    }
}

/// An expression's refusal at `path`.
pub(super) fn expr_err(path: &str, e: ExprError) -> SpecError {
    at(path, e.to_string())
}

/// A refusal of the shared resolution, as the exact side reports it.
pub(super) fn refused(e: crate::resolve::Refusal) -> SpecError {
    at(e.path, e.message)
}

/// Bounds the degree of a spec expression (see [`crate::expr::MAX_SPEC_DEGREE`]).
pub(super) fn bounded(path: &str, e: crate::expr::Expr) -> Result<crate::expr::Expr, SpecError> {
    if e.max_degree() > crate::expr::MAX_SPEC_DEGREE {
        return Err(at(
            path,
            format!(
                "degree over {} in one variable",
                crate::expr::MAX_SPEC_DEGREE
            ),
        ));
    }
    Ok(e)
}

/// A name of the spec's syntax, refused at `path`.
pub(super) fn name_ok(path: &str, n: &str) -> Result<(), SpecError> {
    validate_name(n).map_err(|m| at(path, m))
}
