//! Expressions compiled into one fast evaluator (symbolica's instruction lists), for
//! simulation and repeated numeric evaluation.

use super::*;

impl Registry {
    /// Compiles expressions of this registry into one fast evaluator (symbolica's optimised
    /// instruction list: Horner schemes and common subexpressions). Its input is the value of
    /// every variable, as [`Expr::eval`] takes it.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let e = reg.parse("m*cos(q)*dot(q)^2 + 1/2*m*ddot(q)").unwrap();
    /// let mut c = reg.compile(&[&e]).unwrap();
    /// let point: Vec<f64> = (0..reg.nvars()).map(|i| 0.3 + i as f64).collect();
    /// let mut out = [0.0];
    /// c.evaluate(&point, &mut out);
    /// assert!((out[0] - e.eval(&point)).abs() < 1e-12);
    /// ```
    pub fn compile(&self, exprs: &[&Expr]) -> Result<Compiled, ExprError> {
        self.compile_with(exprs, COMPILE_HORNER, COMPILE_CPE)
    }

    /// [`Registry::compile`] with explicit optimisation effort (Horner scheme iterations,
    /// common-pair elimination iterations). One core: symbolica's restricted mode allows no
    /// more.
    pub fn compile_with(
        &self,
        exprs: &[&Expr],
        horner: usize,
        cpe: Option<usize>,
    ) -> Result<Compiled, ExprError> {
        // The factored presentation form (groups by kinematic monomial, common factors out)
        // is a better starting point for the optimiser than the expanded polynomial.
        let atoms: Vec<Atom> = exprs
            .iter()
            .map(|e| {
                let text = e.grouped().to_string();
                symbolica::try_parse!(&text).unwrap_or_else(|_| e.to_atom())
            })
            .collect();
        let params: Vec<Atom> = self.vars.iter().map(|v| v.to_atom()).collect();
        let ev = Atom::evaluator_multiple(&atoms, &params)
            .cores(1)
            .horner_iterations(horner)
            .cpe_iterations(cpe)
            .build()
            .map_err(|e| ExprError::Declaration(format!("cannot compile: {e:?}")))?
            .map_coeff(&|c| c.re.to_f64());
        Ok(Compiled {
            ev,
            outputs: exprs.len(),
        })
    }
}
