//! The float backend's linear solve of the PFD's equations without `eom`, independent of the
//! exact side's elimination: LU, or the singular value decomposition for a hyperstatic system.

use super::{APPEARS, SINGULAR};
use nalgebra::{DMatrix, DVector};

/// Solves the scaled system a y = b: by LU when it is square and regular; else, when it has
/// fewer independent equations than unknowns (a hyperstatic mechanism), by the singular value
/// decomposition: the least-norm solution, whose component j is the value every solution
/// shares exactly when the unit vector eⱼ lies in the row space of a (the right singular
/// vectors of the nonzero singular values span it), and the columns that do not, free.
/// Err when the equations contradict each other or determine nothing.
pub(in crate::numeric) fn determined(
    a: &DMatrix<f64>,
    b: &DVector<f64>,
) -> Result<(DVector<f64>, Vec<usize>), ()> {
    let (k, c) = a.shape();
    if k == c {
        let lu = a.clone().lu();
        let pivot = lu.u().diagonal().amin();
        if pivot > SINGULAR
            && let Some(y) = lu.solve(b)
        {
            return Ok((y, Vec::new()));
        }
    }
    let svd = a.clone().svd(true, true);
    let (Some(vt), true) = (
        svd.v_t.as_ref(),
        svd.singular_values.iter().all(|s| s.is_finite()),
    ) else {
        return Err(());
    };
    let kept: Vec<usize> = (0..svd.singular_values.len())
        .filter(|&i| svd.singular_values[i] > SINGULAR)
        .collect();
    if kept.is_empty() {
        return Err(());
    }
    let y = svd.solve(b, SINGULAR).map_err(|_| ())?;
    // The equations must hold at the least-norm solution (no contradiction between them).
    if (a * &y - b).amax() > APPEARS * b.amax().max(1.0) {
        return Err(());
    }
    let free = (0..c)
        .filter(|&j| {
            let inside: f64 = kept.iter().map(|&i| vt[(i, j)] * vt[(i, j)]).sum();
            inside < 1.0 - APPEARS
        })
        .collect();
    Ok((y, free))
}

#[cfg(test)]
mod tests {
    use nalgebra::{DMatrix, DVector};

    /// The scaled linear solve, by hand: a regular system, a hyperstatic one (x + y = 3, z = 2:
    /// z alone is determined), and one whose equations contradict each other.
    #[test]
    fn the_solve_keeps_what_a_hyperstatic_system_determines() {
        let solve = super::determined;
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 3.0, 4.0]);
        let (y, free) = solve(&a, &DVector::from_vec(vec![5.0, 6.0])).unwrap();
        assert!(free.is_empty());
        assert!(
            (y[0] + 4.0).abs() < 1e-12 && (y[1] - 4.5).abs() < 1e-12,
            "{y}"
        );
        let a = DMatrix::from_row_slice(2, 3, &[1.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
        let (y, free) = solve(&a, &DVector::from_vec(vec![3.0, 2.0])).unwrap();
        assert_eq!(free, [0, 1]);
        assert!(
            (y[2] - 2.0).abs() < 1e-12 && (y[0] + y[1] - 3.0).abs() < 1e-12,
            "{y}"
        );
        // The same equation written twice, then contradicted.
        let a = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 1.0, 1.0]);
        let (_, free) = solve(&a, &DVector::from_vec(vec![1.0, 1.0])).unwrap();
        assert_eq!(free, [0, 1]);
        assert!(solve(&a, &DVector::from_vec(vec![1.0, 2.0])).is_err());
    }
}
