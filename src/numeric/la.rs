//! The few helpers the backend needs on top of nalgebra's `Vector3` and `Matrix3`.
//!
//! All the linear algebra (products, transposes, cross and scalar products, norms) is
//! nalgebra's, over `f64` and over num-dual's `Dual2_64` alike (a `Dual2_64` is a nalgebra
//! `RealField`). What stays here: splitting dual values into their time derivatives, the
//! conversion to the row arrays of the public [`NumValue`](super::NumValue), and the inertia
//! of a point mass.
//!
//! One nalgebra constructor must not be used with dual numbers: `Rotation3::from_axis_angle`
//! returns the identity when `angle == 0`, and a dual number compares by its real part only,
//! so a joint at exactly q = 0 would lose q̇ and q̈. Elementary rotations are written out
//! instead (`kin::elementary`).

use nalgebra::{Matrix3, Vector3};
use num_dual::Dual2_64;

/// Value, first and second time derivatives of a dual vector.
pub(crate) fn parts(v: &Vector3<Dual2_64>) -> [Vector3<f64>; 3] {
    [v.map(|x| x.re), v.map(|x| x.v1), v.map(|x| x.v2)]
}

/// Value and first time derivative of a dual matrix.
pub(crate) fn mat_parts(m: &Matrix3<Dual2_64>) -> [Matrix3<f64>; 2] {
    [m.map(|x| x.re), m.map(|x| x.v1)]
}

/// |d|² Id − d dᵀ: the inertia of a unit mass at d about the origin.
pub(crate) fn point_inertia(d: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::from_diagonal_element(d.norm_squared()) - d * d.transpose()
}

/// The rows of a matrix, as [`NumValue::Matrix`](super::NumValue::Matrix) holds them.
pub(crate) fn rows(m: &Matrix3<f64>) -> [[f64; 3]; 3] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}
