//! The factor by which a hand-written equation of motion differs from the engine's.

use crate::expr::Expr;
use std::fmt;

/// A nonzero factor made of parameters, numerator / denominator, in lowest terms.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Factor {
    /// Numerator (a polynomial in the parameters).
    pub numerator: Expr,
    /// Denominator (a polynomial in the parameters; 1 for a polynomial factor).
    pub denominator: Expr,
}

impl Factor {
    /// Whether the factor is exactly 1 (the equation as derived).
    pub fn is_one(&self) -> bool {
        self.numerator.is_one() && self.denominator.is_one()
    }

    /// Whether the factor is a number (no parameter).
    pub fn is_number(&self) -> bool {
        self.numerator.as_rational().is_some() && self.denominator.as_rational().is_some()
    }
}

impl fmt::Display for Factor {
    /// `m*l`, `1/(L*m)`, `(M + m)/m`, in the expression syntax.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let wrap = |e: &Expr| {
            if e.nterms() > 1 || e.to_string().contains(['*', '/']) {
                format!("({e})")
            } else {
                e.to_string()
            }
        };
        if self.denominator.is_one() {
            // A sum multiplies as a whole: eom = (A + m*a^2) × (lhs − rhs).
            if self.numerator.nterms() > 1 {
                write!(f, "({})", self.numerator)
            } else {
                write!(f, "{}", self.numerator)
            }
        } else {
            let n = if self.numerator.nterms() > 1 {
                format!("({})", self.numerator)
            } else {
                self.numerator.to_string()
            };
            write!(f, "{n}/{}", wrap(&self.denominator))
        }
    }
}
