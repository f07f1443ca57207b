//! torseur: exact derivation engine for rigid-body dynamics.
#![deny(missing_docs)]

pub mod expr;
pub mod frame;
pub mod inertia;
pub mod point;
pub mod quantity;
pub mod spec;
pub mod vector;
