//! # torseur
//!
//! Exact derivations of rigid-body dynamics in the torsor formalism of French engineering
//! courses: frames turned by angles θᵢ(t), inertia operators, Ω, V, Γ, the kinetic torsor
//! {C(S/R0)} (resultant m V(G), moment σ(A,S/R0)), the dynamic torsor {D(S/R0)} (resultant
//! m Γ(G), moment δ(A,S/R0)), change of point and Huygens, in closed form and exactly.
//!
//! ```
//! use torseur::{derivation::{derive, Value}, quantity::Quantity, spec};
//!
//! // Application 1 of the course: the DIRAVI centrifugal regulator.
//! let m = spec::load("derivations/regulateur_centrifuge.json")?;
//! let d = derive(&m, &Quantity::parse("delta(O2,2/0).x2")?)?;
//!
//! // Under H1 (the planes of symmetry zero E2 and F2; D2 stays), compare with the hand-written
//! // result: the test is exact, modulo sin² + cos² = 1, sin 2θ = 2 sin θ cos θ, any order.
//! let q1 = m.hypotheses().iter().find(|h| h.name == "H1").unwrap();
//! let Value::Scalar(delta) = d.value.under(q1) else { unreachable!() };
//! let by_hand = m.reg().parse(
//!     "(A2 + m2*L2^2)*ddot(theta2) \
//!      + (m2*L1*L2*sin(theta2) + 1/2*(C2 - B2 + m2*L2^2)*sin(2*theta2) + D2*cos(2*theta2))*dot(theta1)^2",
//! )?;
//! assert_eq!(delta, by_hand);
//! # Ok::<(), torseur::Error>(())
//! ```
//!
//! The public surface, in layer order (ARCHITECTURE.md, « Layers », checked by a test): each
//! module listed here is API (the command line, the Python module, the tests, the examples
//! and the doc tests use it); the rest (`point`, the points' arena behind
//! [`mechanism::Mechanism`]; `hint`, the « did you mean » of refusals) is private, and the
//! items most callers need are re-exported at the root ([`derive()`], [`Derivation`],
//! [`Value`], [`Expr`], [`Registry`], [`Mechanism`], [`Quantity`], [`Error`], [`Result`]):
//! - [`expr`]: the only module that uses symbolica (the canonical polynomial form, parsing,
//!   printing, the presentation form); [`wire`]: the spec's JSON data types; [`resolve`]:
//!   its names, trees and every section's references resolved once for both sides;
//! - mechanics: [`frame`], [`vector`], [`inertia`], [`quantity`] (the course's
//!   notation), [`mechanism`] (the store, read through its accessors), [`kinematics`],
//!   [`torsor`];
//! - [`pfd`] (actions, the Fundamental Principle of Dynamics, Lagrange), [`derivation`]
//!   (steps with their theorems), [`units`] (dimensions and homogeneity);
//! - [`numeric`] (the independent float backend), [`simulate`], [`latex`] (the answer key),
//!   [`output`] (text, JSON, numbers), [`verify`], [`check`];
//! - [`spec`] (JSON to [`mechanism::Mechanism`]); [`Error`] gathers every module's error.
//!
//! Utilities for the command line: [`lock`] (one symbolica process at a time), [`input`]
//! (inputs read with a bound) and [`excerpt`] (bounded quotes in messages). Output files
//! (what an output path may name, written once a run has succeeded) are exposed in
//! [`output`]: [`output::target`], [`output::write_outputs`], [`output::write_atomic`].
//!
//! One word per concept, through the crate:
//! - **validate**: refuse what a spec may not say, naming where it says it: the exact side's
//!   build of a [`mechanism::Mechanism`] ([`spec::build`], `spec/validate.rs`, its scenarios
//!   included) and the float backend's own reading (`numeric/validate.rs`); a guard that
//!   refuses an input is a `validate_*` function;
//! - **homogeneous**: the dimension analysis of a value or a derivation's steps
//!   ([`units::homogeneous_value`], [`units::homogeneous_derivation`]);
//! - **verify**: compare a formula someone wrote (a student's, a teacher's) with the engine's
//!   value, exactly ([`verify`], `torseur verify`);
//! - **check**: compare the exact engine with the independent float backend on sampled
//!   states ([`check`], `torseur check`);
//! - **resolve**: the spec's names, trees and references, read once for both sides
//!   ([`resolve`]); a quantity's names are **bound** to a mechanism's ids
//!   ([`derivation::bind`]).
//!
//! The command line's own dependencies (clap, anyhow, signal-hook, mimalloc) sit behind the
//! default feature `cli`; a library user leaves them out with
//! `torseur = { version = "0.1", default-features = false }`: every module above stays.
#![deny(missing_docs)]
// Matrix and vector code indexes components as the formulas do (I[i][j], u[k]).
#![allow(clippy::needless_range_loop)]

mod atomic;
pub mod check;
pub mod derivation;
pub mod excerpt;
pub mod expr;
pub mod frame;
mod hint;
pub mod inertia;
pub mod input;
pub mod kinematics;
pub mod latex;
pub mod lock;
pub mod mechanism;
pub mod numeric;
pub mod output;
pub mod pfd;
mod point;
#[cfg(feature = "python")]
mod python;
pub mod quantity;
pub mod resolve;
pub mod simulate;
pub mod spec;
pub mod torsor;
pub mod units;
pub mod vector;
pub mod verify;
pub mod wire;

pub use derivation::{Derivation, Value, derive};
pub use expr::{Expr, Registry};
pub use mechanism::Mechanism;
pub use quantity::Quantity;

/// Every error of the library, for a caller that handles them alike: each variant is a
/// module's own error, which keeps the user's objects (the JSON path of a spec, the quantity,
/// the PFD's equation and unknowns) and converts with `?`.
///
/// ```
/// fn motor_torque(path: &str) -> torseur::Result<torseur::expr::Expr> {
///     let m = torseur::spec::load(path)?;
///     let q = torseur::quantity::Quantity::parse("C_m")?;
///     match torseur::derivation::derive(&m, &q)?.value {
///         torseur::derivation::Value::Scalar(e) => Ok(e),
///         _ => unreachable!("an unknown is a scalar"),
///     }
/// }
/// assert!(motor_torque("derivations/regulateur_centrifuge.json").is_ok());
/// let e = motor_torque("no/such/spec.json").unwrap_err();
/// assert!(matches!(e, torseur::Error::Spec(_)), "{e}");
/// ```
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A spec that cannot be read or built.
    #[error(transparent)]
    Spec(#[from] spec::SpecError),
    /// A quantity written outside the course's notation.
    #[error(transparent)]
    Notation(#[from] quantity::NotationError),
    /// A quantity naming what the spec does not have.
    #[error(transparent)]
    Resolve(#[from] derivation::DeriveError),
    /// A PFD that cannot be solved as declared.
    #[error(transparent)]
    Pfd(#[from] pfd::PfdError),
    /// An expression that cannot be read.
    #[error(transparent)]
    Expr(#[from] expr::ExprError),
    /// A comparison that cannot be posed.
    #[error(transparent)]
    Verify(#[from] verify::VerifyError),
    /// The float backend's check could not run.
    #[error(transparent)]
    Check(#[from] check::CheckError),
    /// The float backend refused a spec or a quantity.
    #[error(transparent)]
    Numeric(#[from] numeric::NumericError),
    /// A simulation that could not run.
    #[error(transparent)]
    Simulate(#[from] simulate::SimulateError),
    /// A value that breaks homogeneity.
    #[error(transparent)]
    Dimension(#[from] units::DimensionError),
}

/// A result of the library (see [`Error`]).
pub type Result<T> = std::result::Result<T, Error>;
