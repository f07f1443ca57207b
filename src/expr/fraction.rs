//! Typed expressions with a denominator: published forms divide by parameters
//! (m e ω² / (k − M ω²), l0 − m g sin β / k). The engine stays polynomial; a typed text is read
//! as a pair numerator / denominator, the denominator a nonzero polynomial in the parameters,
//! and compared by cross-multiplication.

use super::parse::{Walker, pairwise_sum, parse_atom};
use super::*;
use symbolica::atom::AtomView;

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
                let negative = matches!(exp, AtomView::Num(_))
                    && exp
                        .try_to_polynomial::<_, u8>(&symbolica::domains::rational::Q, None)
                        .is_ok_and(|e| e.is_constant() && e.get_constant().is_negative());
                if !negative {
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
        let w = Walker {
            reg: self,
            input: s,
            names,
        };
        let (n, d) = w.fraction(a.as_view())?;
        match d.as_rational() {
            Some(r) if !r.is_zero() => Ok((n.div_constant(&d).unwrap_or(n), self.one())),
            _ => Ok((n, d)),
        }
    }
}
