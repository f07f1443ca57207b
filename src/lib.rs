//! torseur: exact derivation engine for rigid-body dynamics.
#![deny(missing_docs)]

pub mod derivation;
pub mod expr;
pub mod frame;
pub mod inertia;
pub mod kinematics;
pub mod lock;
pub mod mechanism;
pub mod numeric;
pub mod output;
pub mod point;
pub mod quantity;
pub mod spec;
pub mod torsor;
pub mod vector;
