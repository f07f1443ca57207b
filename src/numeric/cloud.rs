//! A solid realised as point masses with its mass, centre of inertia and inertia operator at G.

use super::expr;
use super::kin::{State, Values};
use super::la::{M3, V3, add, mat_mul, point_inertia, sub, transpose};
use super::{NumericError, NumericModel};
use nalgebra::{Matrix3, SymmetricEigen};

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
) -> Result<Vec<(f64, V3<f64>)>, NumericError> {
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
    let mut ib = [[0.0; 3]; 3];
    for (r, (row, nodes)) in ib.iter_mut().zip(&inr.matrix).enumerate() {
        for (c, (x, node)) in row.iter_mut().zip(nodes).enumerate() {
            *x = expr::eval_scalar(node, &env).map_err(|e| NumericError::Evaluation {
                what: format!("inertia entry [{r}][{c}] of solid {}", solid.name),
                message: e,
            })?;
        }
    }
    let size = ib.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
    if !size.is_finite() {
        return Err(not_physical("its inertia matrix is not finite".into()));
    }
    for (r, c) in [(1, 0), (2, 0), (2, 1)] {
        {
            if (ib[r][c] - ib[c][r]).abs() > TOL * size {
                return Err(not_physical(format!(
                    "its inertia matrix is not symmetric: entry [{r}][{c}] is {} but [{c}][{r}] \
                     is {}",
                    ib[r][c], ib[c][r]
                )));
            }
        }
    }
    // To the solid's basis: with C = R_fᵀ R_b (columns: b's vectors in f), I_f = C I_b Cᵀ.
    let c = mat_mul(&transpose(&st.rot0(f)), &st.rot0(inr.basis));
    let i_q = mat_mul(&mat_mul(&c, &ib), &transpose(&c));
    // Back from the given point Q to G: I_Q = I_G + m (|QG|² Id − QG QGᵀ).
    let qg = sub(&g, &st.local0(f, &st.pos0(inr.point)));
    let shift = point_inertia(&qg);
    let mut i_g = i_q;
    for r in 0..3 {
        for c in 0..3 {
            i_g[r][c] -= mass * shift[r][c];
        }
    }
    let scale = i_g
        .iter()
        .flatten()
        .chain(i_q.iter().flatten())
        .fold(0.0f64, |a, x| a.max(x.abs()));
    if mass == 0.0 {
        if scale == 0.0 {
            return Ok(Vec::new());
        }
        return Err(not_physical(
            "its mass is zero but its inertia is not".into(),
        ));
    }
    let half_trace = 0.5 * (i_g[0][0] + i_g[1][1] + i_g[2][2]);
    let j = Matrix3::from_fn(|r, c| if r == c { half_trace } else { 0.0 } - i_g[r][c]);
    let eig = SymmetricEigen::new(j);
    let mut cloud = Vec::with_capacity(6);
    for k in 0..3 {
        let jk = eig.eigenvalues[k];
        if jk < -TOL * scale.max(f64::MIN_POSITIVE) {
            let principal: Vec<f64> = (0..3).map(|l| half_trace - eig.eigenvalues[l]).collect();
            return Err(not_physical(format!(
                "its inertia at G has principal moments {principal:?}: one exceeds the sum of \
                 the other two, which no body can have (A ≤ B + C)"
            )));
        }
        let a = (3.0 * jk.max(0.0) / mass).sqrt();
        let e = [
            eig.eigenvectors[(0, k)],
            eig.eigenvectors[(1, k)],
            eig.eigenvectors[(2, k)],
        ];
        for sign in [1.0, -1.0] {
            let d = [e[0] * a * sign, e[1] * a * sign, e[2] * a * sign];
            cloud.push((mass / 6.0, add(&g, &d)));
        }
    }
    Ok(cloud)
}

/// Σ mₖ (|d + rₖ|² Id − (d + rₖ)(d + rₖ)ᵀ): inertia about a point from which the cloud's
/// reference point is at `d`.
pub(super) fn cloud_inertia(cloud: &[(f64, V3<f64>)], d: &V3<f64>) -> M3<f64> {
    let mut acc = [[0.0; 3]; 3];
    for (mk, r) in cloud {
        let pi = point_inertia(&add(d, r));
        for i in 0..3 {
            for j in 0..3 {
                acc[i][j] += mk * pi[i][j];
            }
        }
    }
    acc
}
