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
//! let q1 = m.hypotheses.iter().find(|h| h.name == "H1").unwrap();
//! let Value::Scalar(delta) = d.value.under(q1) else { unreachable!() };
//! let by_hand = m.reg.parse(
//!     "(A2 + m2*L2^2)*ddot(theta2) \
//!      + (m2*L1*L2*sin(theta2) + 1/2*(C2 - B2 + m2*L2^2)*sin(2*theta2) + D2*cos(2*theta2))*dot(theta1)^2",
//! )?;
//! assert_eq!(delta, by_hand);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Layers: [`spec`] (JSON to [`mechanism::Mechanism`]), [`expr`] (the only module that uses
//! symbolica: canonical polynomial form), mechanics ([`frame`], [`vector`], [`point`],
//! [`inertia`], [`kinematics`], [`torsor`]), [`derivation`] (steps with their theorems),
//! [`pfd`] (actions, the Fundamental Principle of Dynamics, Lagrange), [`units`] (dimensions
//! and homogeneity), [`output`] (text, JSON, numbers).
#![deny(missing_docs)]
// Matrix and vector code indexes components as the formulas do (I[i][j], u[k]).
#![allow(clippy::needless_range_loop)]

pub mod atomic;
pub mod check;
pub mod derivation;
pub mod excerpt;
pub mod expr;
pub mod frame;
pub mod inertia;
pub mod kinematics;
pub mod latex;
pub mod lock;
pub mod mechanism;
pub mod numeric;
pub mod output;
pub mod pfd;
pub mod point;
pub mod quantity;
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
