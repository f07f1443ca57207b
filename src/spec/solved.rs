//! What solving the loop closures hands the build (`spec/closures.rs` produces it,
//! `spec/validate.rs` and `spec/statement.rs` read it).

use crate::mechanism::HelicalLaw;

/// What the loop closures give the registry: the dependent coordinates' rates and what they
/// divide by, and how the answer key writes the loop law (built by `spec/closures.rs`).
pub(super) struct Solved {
    /// (index in `coordinates`, the rate's numerator: a linear form of the free rates over
    /// the geometry's registry, to divide by `determinant`).
    pub rates: Vec<(usize, crate::expr::Expr)>,
    /// The angles whose cosine the rates divide by.
    pub secants: Vec<String>,
    /// The angles whose sine the rates divide by.
    pub cosecants: Vec<String>,
    /// The parameters the rates divide by.
    pub inverses: Vec<String>,
    /// The names the rates write below a division line, per dependent coordinate (index
    /// in `coordinates`): the determinant's parameters and π, and those the numerator
    /// divides by; the registry declares their inverses where the coordinate's rate stands
    /// among the spec's texts.
    pub divisors: Vec<(usize, Vec<String>)>,
    /// The coordinates a loop closure determines (holonomic driven rates).
    pub dependent: Vec<String>,
    /// Each relation's time derivative, the dependent rates as symbols (over the geometry).
    pub derivatives: Vec<crate::expr::Expr>,
    /// Each rolling condition as the answer key writes it.
    pub rolling: Vec<crate::mechanism::RollingLaw>,
    /// Each helical link that determines a coordinate, as the answer key writes its relation.
    pub helical: Vec<HelicalLaw>,
    /// The determinant the rates divide by, over the geometry's registry.
    pub determinant: crate::expr::Expr,
    /// The loop laws in explicit form, over the geometry's registry.
    pub explicit: Vec<SolvedExplicit>,
}

/// A dependent length in explicit form, x = m ± √P, over the geometry's registry.
pub(super) struct SolvedExplicit {
    /// x's name.
    pub coordinate: String,
    /// The closure's index in the spec.
    pub closure: usize,
    /// The frame whose term's direction was eliminated.
    pub eliminated: String,
    /// m.
    pub center: crate::expr::Expr,
    /// P.
    pub radicand: crate::expr::Expr,
}
