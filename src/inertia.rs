//! Inertia operators: a matrix at a point in a basis; change of basis; Huygens transport;
//! the products of inertia that symmetries make vanish.

use crate::expr::Expr;
use crate::frame::{Axis, FrameId, Frames};
use crate::point::PointId;
use crate::vector::Vector;

/// A 3×3 matrix of exact expressions.
pub type Matrix3 = [[Expr; 3]; 3];

/// The inertia operator I_P(S) of a solid, written as a matrix in basis `basis`.
///
/// The course writes I_G(S) = [[A, −F, −E], [−F, B, −D], [−E, −D, C]] in B_S with
/// A = ∫(y²+z²)dm, D = ∫yz dm, E = ∫xz dm, F = ∫xy dm.
#[doc(alias = "opérateur d’inertie")]
#[derive(Debug, Clone)]
pub struct Inertia {
    /// Point at which the operator is taken.
    pub point: PointId,
    /// Basis of the matrix.
    pub basis: FrameId,
    /// The matrix.
    pub matrix: Matrix3,
}

impl Inertia {
    /// The same operator written in basis `b`: I_b = Pᵀ I_a P, where the columns of P are
    /// the vectors of `b` written in `a`.
    pub fn in_basis(&self, frames: &Frames, b: FrameId) -> Inertia {
        if b == self.basis {
            return self.clone();
        }
        let p = frames.dcm(self.basis, b);
        let m = &self.matrix;
        // T = I P, then Pᵀ T.
        let t: Matrix3 = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                &(&(&m[i][0] * &p[0][j]) + &(&m[i][1] * &p[1][j])) + &(&m[i][2] * &p[2][j])
            })
        });
        let r: Matrix3 = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                &(&(&p[0][i] * &t[0][j]) + &(&p[1][i] * &t[1][j])) + &(&p[2][i] * &t[2][j])
            })
        });
        Inertia {
            point: self.point,
            basis: b,
            matrix: r,
        }
    }

    /// I_P(S)·u, with the result in the matrix's basis.
    pub fn apply(&self, frames: &Frames, u: &Vector) -> Vector {
        let c = u.express_in(frames, self.basis);
        let m = &self.matrix;
        let r = std::array::from_fn(|i| {
            &(&(&m[i][0] * &c[0]) + &(&m[i][1] * &c[1])) + &(&m[i][2] * &c[2])
        });
        Vector::new(self.basis, r)
    }

    /// The Huygens term m [ (d·d) Id − d dᵀ ] for d = AG written in basis `b`: the operator of
    /// a point mass m at G, taken at A.
    pub fn point_mass(
        frames: &Frames,
        at: PointId,
        b: FrameId,
        mass: &Expr,
        ag: &Vector,
    ) -> Inertia {
        let d = ag.express_in(frames, b);
        let dd = &(&(&d[0] * &d[0]) + &(&d[1] * &d[1])) + &(&d[2] * &d[2]);
        let matrix = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let mut e = -(&d[i] * &d[j]);
                if i == j {
                    e = e + &dd;
                }
                mass * &e
            })
        });
        Inertia {
            point: at,
            basis: b,
            matrix,
        }
    }

    /// Entry-wise sum of two operators at the same point in the same basis.
    ///
    /// # Panics
    /// If the points or the bases differ (a programming error: transport or re-express first).
    pub fn plus(&self, other: &Inertia) -> Inertia {
        assert_eq!(
            self.point, other.point,
            "inertia operators at different points"
        );
        assert_eq!(
            self.basis, other.basis,
            "inertia operators in different bases"
        );
        Inertia {
            point: self.point,
            basis: self.basis,
            matrix: std::array::from_fn(|i| {
                std::array::from_fn(|j| &self.matrix[i][j] + &other.matrix[i][j])
            }),
        }
    }

    /// Entry-wise difference.
    pub fn minus(&self, other: &Inertia) -> Inertia {
        self.plus(&Inertia {
            point: other.point,
            basis: other.basis,
            matrix: std::array::from_fn(|i| std::array::from_fn(|j| -&other.matrix[i][j])),
        })
    }
}

/// A material symmetry of a solid, stated in the basis its inertia matrix is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Symmetry {
    /// A plane of symmetry through the centre of inertia, normal to the axis.
    Plane(Axis),
    /// An axis of revolution through the centre of inertia.
    Revolution(Axis),
}

impl Symmetry {
    /// Matrix entries (row, column, upper triangle) that the symmetry makes vanish.
    ///
    /// A plane normal to x (x ↦ −x leaves the solid unchanged) gives ∫xy dm = ∫xz dm = 0;
    /// an axis of revolution along z gives every product of inertia zero.
    pub fn zero_entries(self) -> Vec<(usize, usize)> {
        match self {
            Symmetry::Plane(n) => {
                let k = n.index();
                let mut v: Vec<(usize, usize)> = (0..3)
                    .filter(|&j| j != k)
                    .map(|j| (k.min(j), k.max(j)))
                    .collect();
                v.sort();
                v
            }
            Symmetry::Revolution(_) => vec![(0, 1), (0, 2), (1, 2)],
        }
    }

    /// For an axis of revolution, the two equal diagonal entries (the moments about the two
    /// axes orthogonal to it).
    pub fn equal_moments(self) -> Option<(usize, usize)> {
        match self {
            Symmetry::Revolution(a) => {
                let k = a.index();
                let o: Vec<usize> = (0..3).filter(|&j| j != k).collect();
                Some((o[0], o[1]))
            }
            Symmetry::Plane(_) => None,
        }
    }
}
