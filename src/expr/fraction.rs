//! Typed expressions with a denominator: published forms divide by parameters
//! (m e ω² / (k − M ω²), l0 − m g sin β / k). The engine stays polynomial; a typed text is read
//! as a pair numerator / denominator, the denominator a nonzero polynomial in the parameters,
//! and compared by cross-multiplication.

use super::parse::{Walker, pairwise_sum, parse_atom};
use super::*;
use symbolica::atom::AtomView;

/// An exact quotient `num / den` of two canonical forms, `den` a nonzero polynomial in the
/// parameters (what solving a PFD whose pivots are lengths gives: Y_B = −D ω² / L). Kept in
/// lowest terms, `den`'s first coefficient 1; `den` is 1 for a polynomial.
///
/// ```
/// use torseur::expr::{Fraction, Registry};
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::new(&["L".into(), "D".into(), "w".into()], &[]).unwrap();
/// let f = Fraction::new(reg.parse("-2*D*w^2*L").unwrap(), reg.parse("2*L^2").unwrap()).unwrap();
/// assert_eq!(f.num, reg.parse("-D*w^2").unwrap());
/// assert_eq!(f.den, reg.parse("L").unwrap());
/// assert!(!f.is_whole());
/// // Equality is exact, by cross-multiplication.
/// let g = Fraction::new(reg.parse("D*w^2").unwrap(), reg.parse("-L").unwrap()).unwrap();
/// assert!(f.same(&g));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Fraction {
    /// The numerator.
    pub num: Expr,
    /// The denominator: a nonzero polynomial in the parameters, its first coefficient 1.
    pub den: Expr,
}

impl Fraction {
    /// `num / den` in lowest terms; none when `den` is zero or holds a coordinate, a rate or
    /// an unknown.
    pub fn new(num: Expr, den: Expr) -> Option<Fraction> {
        if den.as_rational().is_some() {
            return Some(Fraction::whole(num.div_constant(&den)?));
        }
        // A product of parameters the mechanism divides by has an exact inverse.
        if let Ok(inv) = den.monomial_inverse() {
            return Some(Fraction::whole(&num * &inv));
        }
        if !den.is_parameter_polynomial() {
            return None;
        }
        let (num, den) = super::factor::lowest_terms(num, den);
        Some(Fraction { num, den })
    }

    /// A polynomial, over 1.
    pub fn whole(e: Expr) -> Fraction {
        let den = e.registry().one();
        Fraction { num: e, den }
    }

    /// Whether the denominator is 1.
    pub fn is_whole(&self) -> bool {
        self.den.is_one()
    }

    /// Whether every term of the numerator is negative, so that the quotient reads −(n′)/d
    /// (a teacher writes −(m g a + E ω²)/L, not (−m g a − E ω²)/L).
    pub fn reads_negative(&self) -> bool {
        !self.is_whole() && !self.num.is_zero() && self.num.terms().all(|(c, _)| c.is_negative())
    }

    /// Exact equality of the two quotients: n1 d2 = n2 d1.
    pub fn same(&self, other: &Fraction) -> bool {
        &self.num * &other.den == &other.num * &self.den
    }

    /// Applies `f` to the numerator and the denominator (a hypothesis, a substitution of
    /// parameters); none when the denominator becomes zero or stops being a polynomial in the
    /// parameters.
    pub fn map(&self, f: &impl Fn(&Expr) -> Expr) -> Option<Fraction> {
        Fraction::new(f(&self.num), f(&self.den))
    }
}

impl Walker<'_> {
    /// (numerator, denominator) of a text: sums over a common denominator, products and
    /// integer powers; a negative power only of what is made of parameters.
    fn fraction(&self, v: AtomView) -> Result<(Expr, Expr), ExprError> {
        let reg = self.reg;
        match v {
            AtomView::Add(a) => {
                let mut parts = Vec::new();
                for t in a.iter() {
                    parts.push(self.fraction(t)?);
                }
                // Without a denominator, the polynomial reading (summed pairwise: a chain's
                // equation holds 10^5 terms, and adding them one by one is quadratic).
                if parts.iter().all(|(_, d)| d.is_one()) {
                    let sums = parts.into_iter().map(|(n, _)| n).collect();
                    return Ok((pairwise_sum(reg, sums), reg.one()));
                }
                let mut acc = (reg.zero(), reg.one());
                for (n, d) in parts {
                    acc = if d == acc.1 {
                        (&acc.0 + &n, d)
                    } else {
                        (
                            &self.times(&acc.0, &d)? + &self.times(&n, &acc.1)?,
                            self.times(&acc.1, &d)?,
                        )
                    };
                }
                Ok(acc)
            }
            AtomView::Mul(m) => {
                let mut acc = (reg.one(), reg.one());
                for t in m.iter() {
                    let (n, d) = self.fraction(t)?;
                    acc = (self.times(&acc.0, &n)?, self.times(&acc.1, &d)?);
                }
                Ok(acc)
            }
            AtomView::Pow(p) => {
                let (base, exp) = p.get_base_exp();
                if !super::names::negative_number(exp) {
                    return Ok((self.scalar(v)?, reg.one()));
                }
                let n = exp
                    .try_to_polynomial::<_, u8>(&symbolica::domains::rational::Q, None)
                    .map(|e| e.get_constant())
                    .map_err(|_| self.unsupported("only integer powers are allowed"))?;
                if !n.is_integer() || n.to_f64().abs() > 8.0 {
                    return Err(
                        self.unsupported("a denominator is raised to an integer power up to 8")
                    );
                }
                let k = (-n.to_f64()) as u32;
                let (bn, bd) = self.fraction(base)?;
                if bn.is_zero() {
                    return Err(self.unsupported("division by zero"));
                }
                // A number below the line stays a rational coefficient.
                if let Some(r) = bn.as_rational() {
                    let mut num = reg.constant(r.inv().pow(k as u64));
                    for _ in 0..k {
                        num = self.times(&num, &bd)?;
                    }
                    return Ok((num, reg.one()));
                }
                // A product of parameters and cosines a loop closure divides by has an
                // exact inverse: it goes above the line.
                if let Ok(inv) = bn.monomial_inverse() {
                    let mut num = reg.one();
                    for _ in 0..k {
                        num = self.times(&num, &self.times(&bd, &inv)?)?;
                    }
                    return Ok((num, reg.one()));
                }
                if reg
                    .var_ids()
                    .any(|i| bn.contains_var(i) && !reg.is_factor_variable(i))
                {
                    return Err(self.unsupported(
                        "a denominator is made of parameters only (no coordinate, rate or \
                         unknown): the exact forms are polynomials in those",
                    ));
                }
                let (mut num, mut den) = (reg.one(), reg.one());
                for _ in 0..k {
                    num = self.times(&num, &bd)?;
                    den = self.times(&den, &bn)?;
                }
                Ok((num, den))
            }
            _ => Ok((self.scalar(v)?, reg.one())),
        }
    }
}

impl Registry {
    /// Reads a scalar that may divide by a nonzero polynomial in the parameters, as a pair
    /// (numerator, denominator) of canonical forms; a number denominator is divided out.
    /// `names` gives the value of names the registry does not know (as in
    /// [`Registry::parse_with`]).
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into(), "g".into(), "k".into(), "l0".into()],
    ///     &[("x".into(), CoordinateKind::Length)]).unwrap();
    /// let (n, d) = reg.parse_fraction_with("l0 - m*g/k", &|_| None).unwrap();
    /// assert_eq!((n, d), (reg.parse("k*l0 - m*g").unwrap(), reg.parse("k").unwrap()));
    /// let (n, d) = reg.parse_fraction_with("x/2 + 1/(k - m)", &|_| None).unwrap();
    /// assert_eq!(d, reg.parse("k - m").unwrap());
    /// assert_eq!(n, reg.parse("(k - m)*x/2 + 1").unwrap());
    /// // A coordinate below the line is refused: the result would not be a polynomial in it.
    /// assert!(reg.parse_fraction_with("1/x", &|_| None).is_err());
    /// assert!(reg.parse_fraction_with("m/(k - k)", &|_| None).is_err());
    /// ```
    pub fn parse_fraction_with(
        self: &Rc<Self>,
        s: &str,
        names: &dyn Fn(&str) -> Option<Expr>,
    ) -> Result<(Expr, Expr), ExprError> {
        let a = parse_atom(s)?;
        let w = Walker::new(self, s, names);
        let (n, d) = w.fraction(a.as_view())?;
        w.numbers_bounded(&n)?;
        w.numbers_bounded(&d)?;
        match d.as_rational() {
            Some(r) if !r.is_zero() => Ok((n.div_constant(&d).unwrap_or(n), self.one())),
            _ => Ok((n, d)),
        }
    }
}
