//! 3-vectors and 3×3 matrices over dual numbers (plain arrays, row-major).

use super::expr::Num;
use num_dual::Dual2_64;

pub(crate) type V3<T> = [T; 3];
pub(crate) type M3<T> = [[T; 3]; 3];

pub(crate) fn zero<T: Num>() -> T {
    T::from(0.0)
}

pub(crate) fn identity<T: Num>() -> M3<T> {
    let mut m = [[zero::<T>(); 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        row[i] = T::from(1.0);
    }
    m
}

pub(crate) fn mat_mul<T: Num>(a: &M3<T>, b: &M3<T>) -> M3<T> {
    let mut m = [[zero::<T>(); 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
        }
    }
    m
}

pub(crate) fn transpose<T: Num>(a: &M3<T>) -> M3<T> {
    let mut m = *a;
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = a[j][i];
        }
    }
    m
}

pub(crate) fn mat_vec<T: Num>(a: &M3<T>, v: &V3<T>) -> V3<T> {
    [
        a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
        a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
        a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2],
    ]
}

pub(crate) fn add<T: Num>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub(crate) fn sub<T: Num>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn scale<T: Num>(a: &V3<T>, k: f64) -> V3<T> {
    [a[0] * k, a[1] * k, a[2] * k]
}

pub(crate) fn cross<T: Num>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

pub(crate) fn dot<T: Num>(a: &V3<T>, b: &V3<T>) -> T {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Column `k` of a matrix (a basis vector when the matrix is an orientation).
pub(crate) fn column<T: Num>(a: &M3<T>, k: usize) -> V3<T> {
    [a[0][k], a[1][k], a[2][k]]
}

/// Real part, first and second time derivatives of a dual vector.
pub(crate) fn parts(v: &V3<Dual2_64>) -> [V3<f64>; 3] {
    [
        [v[0].re, v[1].re, v[2].re],
        [v[0].v1, v[1].v1, v[2].v1],
        [v[0].v2, v[1].v2, v[2].v2],
    ]
}

/// Real part and first time derivative of a dual matrix.
pub(crate) fn mat_parts(m: &M3<Dual2_64>) -> [M3<f64>; 2] {
    let mut re = [[0.0; 3]; 3];
    let mut d = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            re[i][j] = m[i][j].re;
            d[i][j] = m[i][j].v1;
        }
    }
    [re, d]
}

/// |d|² Id − d dᵀ: the inertia of a unit mass at d about the origin.
pub(crate) fn point_inertia(d: &V3<f64>) -> M3<f64> {
    let n2 = dot(d, d);
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = if i == j { n2 } else { 0.0 } - d[i] * d[j];
        }
    }
    m
}
