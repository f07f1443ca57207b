//! A solid realised as point masses with its mass, centre of inertia and inertia operator at G.

use super::expr;
use super::kin::{State, Values};
use super::la::{parts, point_inertia};
use super::{NumericError, NumericModel};
use nalgebra::{Matrix3, Vector3};

/// Relative tolerance on the symmetry of a matrix and on negative principal second moments.
const TOL: f64 = 1e-10;

/// Builds the point masses (mass, coordinates in the solid's frame from its origin) of solid
/// `s` at the sampled values.
///
/// With an inertia operator: J = (tr I_G / 2) Id − I_G is the matrix of second moments
/// Σ m r rᵀ; on its principal axes eₖ with values jₖ ≥ 0, six masses m/6 at G ± aₖ eₖ with
/// aₖ = √(3 jₖ / m) have mass m, centre G and second moments jₖ, hence inertia I_G. Without
/// one, the solid is a point mass at G.
pub(super) fn solid_cloud(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    s: usize,
) -> Result<Vec<(f64, Vector3<f64>)>, NumericError> {
    let solid = &m.solids[s];
    let not_physical = |message: String| NumericError::NotPhysical {
        solid: solid.name.clone(),
        message,
    };
    let env = vals.constants();
    let mass = expr::eval_scalar(&solid.mass, &env).map_err(|e| NumericError::Evaluation {
        what: format!("mass of solid {}", solid.name),
        message: e,
    })?;
    if !mass.is_finite() || mass < 0.0 {
        return Err(not_physical(format!("its mass is {mass}")));
    }
    let f = solid.frame;
    let g = st.local0(f, &st.pos0(solid.centre));
    let Some(inr) = &solid.inertia else {
        return Ok(if mass == 0.0 {
            Vec::new()
        } else {
            vec![(mass, g)]
        });
    };
    let mut ib = Matrix3::zeros();
    for (r, nodes) in inr.matrix.iter().enumerate() {
        for (c, node) in nodes.iter().enumerate() {
            ib[(r, c)] = expr::eval_scalar(node, &env).map_err(|e| NumericError::Evaluation {
                what: format!("inertia entry [{r}][{c}] of solid {}", solid.name),
                message: e,
            })?;
        }
    }
    if !ib.iter().all(|x| x.is_finite()) {
        return Err(not_physical("its inertia matrix is not finite".into()));
    }
    let size = ib.amax();
    for (r, c) in [(1, 0), (2, 0), (2, 1)] {
        if (ib[(r, c)] - ib[(c, r)]).abs() > TOL * size {
            return Err(not_physical(format!(
                "its inertia matrix is not symmetric: entry [{r}][{c}] is {} but [{c}][{r}] is {}",
                ib[(r, c)],
                ib[(c, r)]
            )));
        }
    }
    // To the solid's basis: with C = R_fᵀ R_b (columns: b's vectors in f), I_f = C I_b Cᵀ.
    let c = st.rot0(f).transpose() * st.rot0(inr.basis);
    let i_q = c * ib * c.transpose();
    // Back from the given point Q to G: I_Q = I_G + m (|QG|² Id − QG QGᵀ).
    let qg = g - st.local0(f, &st.pos0(inr.point));
    let i_g = i_q - point_inertia(&qg) * mass;
    let scale = i_g.amax().max(i_q.amax());
    if mass == 0.0 {
        if scale == 0.0 {
            return Ok(Vec::new());
        }
        return Err(not_physical(
            "its mass is zero but its inertia is not".into(),
        ));
    }
    let half_trace = 0.5 * i_g.trace();
    let j = Matrix3::from_diagonal_element(half_trace) - i_g;
    let (values, axes) = symmetric_eigen(&j);
    let mut cloud = Vec::with_capacity(6);
    for (k, jk) in values.into_iter().enumerate() {
        if jk < -TOL * scale.max(f64::MIN_POSITIVE) {
            let principal = values.map(|l| half_trace - l);
            return Err(not_physical(format!(
                "its inertia at G has principal moments {principal:?}: one exceeds the sum of \
                 the other two, which no body can have (A ≤ B + C)"
            )));
        }
        let a = (3.0 * jk.max(0.0) / mass).sqrt();
        let e = axes.column(k);
        for sign in [1.0, -1.0] {
            cloud.push((mass / 6.0, g + e * (a * sign)));
        }
    }
    Ok(cloud)
}

/// Σ mₖ (|d + rₖ|² Id − (d + rₖ)(d + rₖ)ᵀ): inertia about a point from which the cloud's
/// reference point is at `d`.
pub(super) fn cloud_inertia(cloud: &[(f64, Vector3<f64>)], d: &Vector3<f64>) -> Matrix3<f64> {
    cloud.iter().fold(Matrix3::zeros(), |acc, (mk, r)| {
        acc + point_inertia(&(d + r)) * *mk
    })
}

/// Eigenvalues and orthonormal eigenvectors (the columns of the matrix) of a symmetric 3×3
/// matrix, by cyclic Jacobi rotations: J = V diag(λ) Vᵀ.
///
/// Each rotation is applied to the matrix and accumulated into V together, so column k of V
/// always belongs to the diagonal entry k: no pairing step that could mismatch them.
///
/// Not nalgebra's `SymmetricEigen`: in nalgebra 0.33.3 it can return eigenvalues and
/// eigenvectors in different orders, so that V diag(λ) Vᵀ is not the matrix (the same symptom
/// as dimforge/nalgebra#1109, open, a 4×4 matrix there). It happened here on the second
/// moments J = (tr I_G / 2) Id − I_G of a diagonal I_G carrying rounding noise,
///
/// ```text
/// [ 0.034243175583978325   0                    −4.35610802358069e-17 ]
/// [ 0                      0.2958498651360119    0                    ]
/// [ −4.35610802358069e-17  0                     0.1587837530153427   ]
/// ```
///
/// for which it pairs x with 0.1588 and z with 0.0342 (V diag(λ) Vᵀ off by 0.12): the cloud
/// then had the wrong inertia and δ(O2, 2/0)·x2 of the regulator came out wrong
/// (test `regulator_delta_o2_x2_diagonal_inertia_regression`). The cause is its 2×2 step:
/// for a block whose off-diagonal entry sits at the deflation threshold (about 1e-16
/// relative), it takes the block's eigenvalues in their own order but skips the rotation of
/// the eigenvectors when the Givens rotation's norm is below that threshold.
pub(super) fn symmetric_eigen(m: &Matrix3<f64>) -> ([f64; 3], Matrix3<f64>) {
    /// Far more sweeps than convergence needs (quadratic: a handful from any start).
    const MAX_SWEEPS: usize = 64;
    // Exactly symmetric from the start: the mean of the two triangles.
    let mut a = *m;
    for (p, q) in [(0, 1), (0, 2), (1, 2)] {
        let x = 0.5 * (a[(p, q)] + a[(q, p)]);
        a[(p, q)] = x;
        a[(q, p)] = x;
    }
    let mut v = Matrix3::identity();
    for _ in 0..MAX_SWEEPS {
        if a[(0, 1)] == 0.0 && a[(0, 2)] == 0.0 && a[(1, 2)] == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let apq = a[(p, q)];
            if apq == 0.0 {
                continue;
            }
            // The rotation R (R_pp = R_qq = c, R_pq = s, R_qp = −s) with Rᵀ A R zero at (p, q):
            // t = tan φ is the smaller root of t² + 2θ t − 1 = 0, θ = (a_qq − a_pp) / 2a_pq.
            let theta = (a[(q, q)] - a[(p, p)]) / (2.0 * apq);
            let t = if theta.is_finite() {
                1.0f64.copysign(theta) / (theta.abs() + theta.hypot(1.0))
            } else {
                0.0
            };
            let c = 1.0 / t.hypot(1.0);
            let s = t * c;
            let r = 3 - p - q;
            let (app, aqq, arp, arq) = (a[(p, p)], a[(q, q)], a[(r, p)], a[(r, q)]);
            a[(p, p)] = app - t * apq;
            a[(q, q)] = aqq + t * apq;
            a[(p, q)] = 0.0;
            a[(q, p)] = 0.0;
            a[(r, p)] = c * arp - s * arq;
            a[(p, r)] = a[(r, p)];
            a[(r, q)] = s * arp + c * arq;
            a[(q, r)] = a[(r, q)];
            // V ← V R: columns p and q turn together.
            let (vp, vq) = (v.column(p).into_owned(), v.column(q).into_owned());
            v.set_column(p, &(vp * c - vq * s));
            v.set_column(q, &(vp * s + vq * c));
        }
    }
    ([a[(0, 0)], a[(1, 1)], a[(2, 2)]], v)
}

/// Σ mₖ V, Σ mₖ APₖ ∧ V, Σ mₖ Γ, Σ mₖ APₖ ∧ Γ over the clouds of `solids`, motion relative
/// to frame `j`, A = point `a`; ground components.
pub(super) fn kinetic(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    solids: &[usize],
    j: usize,
    a: usize,
) -> Result<[Vector3<f64>; 4], NumericError> {
    let a_j = st.local0(j, &st.pos0(a));
    let mut acc = [Vector3::zeros(); 4];
    for s in solids {
        let f = m.solids[*s].frame;
        for (mk, u) in solid_cloud(m, st, vals, *s)? {
            let [r, v, g] = parts(&st.track(f, &u, j));
            let ap = r - a_j;
            acc[0] += v * mk;
            acc[1] += ap.cross(&v) * mk;
            acc[2] += g * mk;
            acc[3] += ap.cross(&g) * mk;
        }
    }
    let rj = st.rot0(j);
    Ok(acc.map(|x| rj * x))
}

/// Ec = Σ ½ mₖ |V(Pₖ/Rj)|² over the clouds of `solids`, motion relative to frame `j`.
pub(super) fn kinetic_energy(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    solids: &[usize],
    j: usize,
) -> Result<f64, NumericError> {
    let mut e = 0.0;
    for s in solids {
        let f = m.solids[*s].frame;
        for (mk, u) in solid_cloud(m, st, vals, *s)? {
            let [_, v, _] = parts(&st.track(f, &u, j));
            e += 0.5 * mk * v.norm_squared();
        }
    }
    Ok(e)
}
