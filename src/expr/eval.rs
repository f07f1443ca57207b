//! Numeric evaluation of the canonical form, summed in double-double so that an expanded
//! polynomial whose terms cancel keeps full precision.

use super::*;

impl Expr {
    /// Numeric value, given a value for every variable (see [`Registry::role`]).
    ///
    /// Terms are summed in double-double arithmetic (error-free transformations, about 32
    /// significant digits), because an expanded polynomial may cancel: cos(2θ2 − 2θ1)¹² has
    /// 313 terms of size up to 10¹⁰ whose sum is 0.013, and a plain f64 sum of them (what
    /// symbolica's `evaluate` gives) was 7 % off. The result is the exact value of the
    /// polynomial at the given point to within a few units of the last place.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&[], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let e = reg.parse("cos(2*q)^12").unwrap();
    /// // Variables: cos q, sin q, then the rates (unused here).
    /// let q: f64 = 0.3996;
    /// let mut point = vec![0.0; reg.nvars()];
    /// point[reg.index_of(torseur::expr::VarRole::Cos(reg.coord("q").unwrap())).unwrap().index()] = q.cos();
    /// point[reg.index_of(torseur::expr::VarRole::Sin(reg.coord("q").unwrap())).unwrap().index()] = q.sin();
    /// let want = (2.0 * q).cos().powi(12);
    /// assert!((e.eval(&point) - want).abs() < 1e-14 * want);
    /// ```
    pub fn eval(&self, point: &[f64]) -> f64 {
        let mut acc = DoubleDouble::ZERO;
        for (c, e) in self.terms() {
            let mut t = DoubleDouble::rational(c);
            for (i, &k) in e.iter().enumerate() {
                for _ in 0..k {
                    t = t.mul(point[i]);
                }
            }
            acc = acc.add(t);
        }
        acc.hi + acc.lo
    }
}

impl Expr {
    /// The sum of the magnitudes of the terms at `point`: the size against which
    /// [`Expr::eval`] is small or not (a value 1e-12 of it is rounding, not a nonzero
    /// polynomial).
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::new(&["a".into()], &[]).unwrap();
    /// let e = reg.parse("a - 2").unwrap();
    /// let point = vec![2.0; reg.nvars()];
    /// assert_eq!((e.eval(&point), e.eval_magnitude(&point)), (0.0, 4.0));
    /// ```
    pub fn eval_magnitude(&self, point: &[f64]) -> f64 {
        let mut acc = 0.0;
        for (c, e) in self.terms() {
            let mut t = DoubleDouble::rational(c).hi.abs();
            for (i, &k) in e.iter().enumerate() {
                t *= point[i].abs().powi(i32::from(k));
            }
            acc += t;
        }
        acc
    }
}

/// A number as an unevaluated sum hi + lo of two f64 (|lo| ≤ ulp(hi)/2): Dekker's and
/// Knuth's error-free transformations, for [`Expr::eval`].
#[derive(Debug, Clone, Copy)]
struct DoubleDouble {
    hi: f64,
    lo: f64,
}

impl DoubleDouble {
    const ZERO: DoubleDouble = DoubleDouble { hi: 0.0, lo: 0.0 };

    /// a + b exactly, as (rounded sum, error).
    fn two_sum(a: f64, b: f64) -> DoubleDouble {
        let s = a + b;
        let v = s - a;
        DoubleDouble {
            hi: s,
            lo: (a - (s - v)) + (b - v),
        }
    }

    /// A rational coefficient: numerator and denominator exact in f64 (below 2^53) give the
    /// quotient to double-double precision; larger ones are rounded once.
    fn rational(c: &Rational) -> DoubleDouble {
        let text = c.to_string();
        let (n, d) = text.split_once('/').unwrap_or((&text, "1"));
        let exact = |s: &str| s.trim_start_matches('-').len() <= 15 && s.parse::<f64>().is_ok();
        if !(exact(n) && exact(d)) {
            return DoubleDouble {
                hi: c.to_f64(),
                lo: 0.0,
            };
        }
        let (n, d): (f64, f64) = (n.parse().unwrap_or(0.0), d.parse().unwrap_or(1.0));
        let q = n / d;
        // n − q d is exact (fma), so the quotient's error is its rounding only.
        let r = (-q).mul_add(d, n);
        Self::two_sum(q, r / d)
    }

    /// self × x.
    fn mul(self, x: f64) -> DoubleDouble {
        let p = self.hi * x;
        let e = self.hi.mul_add(x, -p);
        Self::two_sum(p, e + self.lo * x)
    }

    /// self + other.
    fn add(self, o: DoubleDouble) -> DoubleDouble {
        let s = Self::two_sum(self.hi, o.hi);
        Self::two_sum(s.hi, s.lo + self.lo + o.lo)
    }
}
