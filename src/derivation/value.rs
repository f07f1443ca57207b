//! A derived value: a scalar, a quotient, a vector, an inertia operator or a torsor.

use crate::expr::{Expr, Fraction};
use crate::frame::FrameId;
use crate::inertia::Inertia;
use crate::mechanism::Hypothesis;
use crate::point::PointId;

/// A derived value.
#[derive(Debug, Clone)]
pub enum Value {
    /// A scalar (a projection).
    Scalar(Expr),
    /// A scalar quotient by a polynomial in the parameters: an unknown of a PFD whose pivot
    /// is a length (Y_B = −D ω² / L).
    Quotient(Fraction),
    /// A vector written in a basis.
    Vector {
        /// Basis.
        basis: FrameId,
        /// Components.
        components: [Expr; 3],
    },
    /// An inertia operator.
    Matrix(Inertia),
    /// A torsor written in a basis.
    Torsor {
        /// Point of reduction.
        point: PointId,
        /// Basis.
        basis: FrameId,
        /// Resultant components.
        resultant: [Expr; 3],
        /// Moment components.
        moment: [Expr; 3],
    },
}

impl Value {
    /// Maps every expression.
    pub fn map(&self, f: &impl Fn(&Expr) -> Expr) -> Value {
        let m3 = |c: &[Expr; 3]| [f(&c[0]), f(&c[1]), f(&c[2])];
        match self {
            Value::Scalar(e) => Value::Scalar(f(e)),
            Value::Quotient(q) => match q.map(f) {
                Some(q) if q.is_whole() => Value::Scalar(q.num),
                Some(q) => Value::Quotient(q),
                // The map made the denominator zero (a hypothesis relating parameters).
                None => Value::Quotient(Fraction {
                    num: f(&q.num),
                    den: f(&q.den),
                }),
            },
            Value::Vector { basis, components } => Value::Vector {
                basis: *basis,
                components: m3(components),
            },
            Value::Matrix(i) => Value::Matrix(Inertia {
                point: i.point,
                basis: i.basis,
                matrix: std::array::from_fn(|r| m3(&i.matrix[r])),
            }),
            Value::Torsor {
                point,
                basis,
                resultant,
                moment,
            } => Value::Torsor {
                point: *point,
                basis: *basis,
                resultant: m3(resultant),
                moment: m3(moment),
            },
        }
    }

    /// The value under a hypothesis.
    pub fn under(&self, h: &Hypothesis) -> Value {
        self.map(&|e| h.apply(e))
    }

    /// Every expression, in a fixed order (a quotient's numerator then denominator).
    pub fn exprs(&self) -> Vec<&Expr> {
        match self {
            Value::Scalar(e) => vec![e],
            Value::Quotient(q) => vec![&q.num, &q.den],
            Value::Vector { components, .. } => components.iter().collect(),
            Value::Matrix(i) => i.matrix.iter().flatten().collect(),
            Value::Torsor {
                resultant, moment, ..
            } => resultant.iter().chain(moment.iter()).collect(),
        }
    }

    /// The numbers of the value at a point of the registry's variables, in the order of
    /// [`Value::exprs`] but one number for a quotient.
    pub fn numbers(&self, point: &[f64]) -> Vec<f64> {
        match self {
            Value::Quotient(q) => vec![q.num.eval(point) / q.den.eval(point)],
            _ => self.exprs().iter().map(|e| e.eval(point)).collect(),
        }
    }

    /// Each scalar of the value as numerator and denominator (the denominator 1 but for a
    /// quotient), in the order of [`Value::exprs`].
    pub fn fractions(&self) -> Vec<Fraction> {
        match self {
            Value::Quotient(q) => vec![q.clone()],
            _ => self
                .exprs()
                .into_iter()
                .map(|e| Fraction::whole(e.clone()))
                .collect(),
        }
    }

    /// Total number of terms of the canonical forms.
    pub fn nterms(&self) -> usize {
        self.exprs().iter().map(|e| e.nterms()).sum()
    }
}
