//! A flat evaluator of canonical polynomials: each variable's powers are computed once per
//! point, then every term is its coefficient times a few table lookups. No interpretation
//! step and no allocation per point, which makes it the fastest route for the small
//! polynomials of mechanics (tens of terms).

use super::{Expr, ExprError};

/// Expressions flattened for repeated numeric evaluation (see [`FlatEval::new`]).
#[derive(Debug, Clone)]
pub struct FlatEval {
    outputs: usize,
    /// (variable index, highest degree, offset of its powers in `buf`).
    vars: Vec<(usize, u8, usize)>,
    /// (coefficient, first factor, number of factors, output).
    terms: Vec<(f64, u32, u16, u16)>,
    /// Indices into `buf` of each term's factors.
    factors: Vec<u32>,
    buf: Vec<f64>,
    nvars: usize,
}

impl FlatEval {
    /// Flattens expressions of one registry.
    ///
    /// ```
    /// use torseur::expr::{FlatEval, Registry};
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let e = reg.parse("m*cos(q)*dot(q)^2 + 1/2*m*ddot(q)").unwrap();
    /// let mut f = FlatEval::new(&[&e]).unwrap();
    /// let point: Vec<f64> = (0..reg.nvars()).map(|i| 0.3 + i as f64).collect();
    /// let mut out = [0.0];
    /// f.evaluate(&point, &mut out);
    /// assert!((out[0] - e.eval(&point)).abs() < 1e-12);
    /// ```
    pub fn new(exprs: &[&Expr]) -> Result<FlatEval, ExprError> {
        let Some(first) = exprs.first() else {
            return Ok(FlatEval {
                outputs: 0,
                vars: vec![],
                terms: vec![],
                factors: vec![],
                buf: vec![],
                nvars: 0,
            });
        };
        let nvars = first.reg.nvars();
        if exprs.len() > u16::MAX as usize {
            return Err(ExprError::Declaration(
                "too many expressions to flatten".into(),
            ));
        }
        let mut degree = vec![0u8; nvars];
        for e in exprs {
            for t in 0..e.p.nterms() {
                for (i, &k) in e.p.exponents(t).iter().enumerate() {
                    degree[i] = degree[i].max(k);
                }
            }
        }
        let mut vars = Vec::new();
        let mut offset = vec![0usize; nvars];
        let mut len = 0;
        for (i, &d) in degree.iter().enumerate() {
            if d > 0 {
                vars.push((i, d, len));
                offset[i] = len;
                len += d as usize;
            }
        }
        let mut terms = Vec::new();
        let mut factors = Vec::new();
        for (o, e) in exprs.iter().enumerate() {
            for t in 0..e.p.nterms() {
                let start = factors.len() as u32;
                for (i, &k) in e.p.exponents(t).iter().enumerate() {
                    if k > 0 {
                        factors.push((offset[i] + k as usize - 1) as u32);
                    }
                }
                let n = factors.len() as u32 - start;
                terms.push((e.p.coefficients[t].to_f64(), start, n as u16, o as u16));
            }
        }
        Ok(FlatEval {
            outputs: exprs.len(),
            vars,
            terms,
            factors,
            buf: vec![0.0; len],
            nvars,
        })
    }

    /// Number of results.
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// Evaluates every expression at `point` (one value per registry variable) into `out`.
    pub fn evaluate(&mut self, point: &[f64], out: &mut [f64]) {
        debug_assert!(point.len() >= self.nvars && out.len() >= self.outputs);
        for &(v, d, off) in &self.vars {
            let x = point[v];
            let mut p = x;
            self.buf[off] = x;
            for j in 1..d as usize {
                p *= x;
                self.buf[off + j] = p;
            }
        }
        out[..self.outputs].iter_mut().for_each(|o| *o = 0.0);
        for &(c, start, n, o) in &self.terms {
            let mut acc = c;
            for &f in &self.factors[start as usize..start as usize + n as usize] {
                acc *= self.buf[f as usize];
            }
            out[o as usize] += acc;
        }
    }
}
