//! An expression of one registry read over another registry's variables, matched by what
//! they stand for and by name: how a loop closure's rates, solved over the geometry's
//! registry, enter the mechanism's registry without being printed and parsed again.

use super::*;

impl Expr {
    /// This expression over the variables of `to`: each variable becomes the one of `to`
    /// that stands for the same thing under the same name (a parameter, π, 1/p, cos q, sin q,
    /// q, a rate, 1/cos q), reduced by `to`'s rules (a rate `to` imposes reads as its
    /// value). An error names the first variable `to` lacks.
    pub(crate) fn carried(&self, to: &Rc<Registry>) -> Result<Expr, ExprError> {
        let from = self.registry();
        let vars: Vec<Option<Expr>> = (0..from.nvars())
            .map(|i| match self.contains_var(VarId(i)) {
                true => carried_var(from, VarId(i), to).map(Some),
                false => Ok(None),
            })
            .collect::<Result<_, _>>()?;
        let mut parts = Vec::with_capacity(self.nterms());
        for (c, x) in self.terms() {
            let mut t = to.constant(c.clone());
            for (i, &k) in x.iter().enumerate() {
                if let (true, Some(v)) = (k > 0, &vars[i]) {
                    t = &t * &v.pow(u32::from(k));
                }
            }
            parts.push(t);
        }
        Ok(super::parse::pairwise_sum(to, parts))
    }
}

/// The expression of `to` that stands for variable `v` of `from`.
fn carried_var(from: &Rc<Registry>, v: VarId, to: &Rc<Registry>) -> Result<Expr, ExprError> {
    let missing = |what: String| {
        ExprError::Declaration(format!(
            "{what} has no variable in the registry it is carried to"
        ))
    };
    let param = |p: ParamId| match from.is_pi(p) {
        true => Some(to.pi()),
        false => to.param(from.scalar_name(p)),
    };
    let angle = |q: CoordId| to.angle(&from.coord_info(q).name);
    let coord = |q: CoordId| to.coord(&from.coord_info(q).name);
    let found = match from.role(v) {
        VarRole::Parameter(p) => param(p),
        VarRole::Inverse(p) => {
            let target = match from.is_pi(p) {
                true => Some(to.pi),
                false => to.param_id(from.scalar_name(p)),
            };
            (target.and_then(|t| to.index_of(VarRole::Inverse(t)))).map(|i| to.variable(i))
        }
        VarRole::Cos(q) => angle(q).map(|t| to.cos(t)),
        VarRole::Sin(q) => angle(q).map(|t| to.sin(t)),
        VarRole::Value(q) => {
            (to.coord_by_name.get(&from.coord_info(q).name)).and_then(|&t| to.value(t))
        }
        VarRole::Rate(q, order) => coord(q).map(|t| to.rate(t, order)),
        VarRole::Root(r) => {
            let radicand = from.radicand(r).carried(to)?;
            to.sqrt_of(&radicand).ok()
        }
        VarRole::Reciprocal(q, f) => (angle(q))
            .and_then(|t| to.index_of(VarRole::Reciprocal(t, f)))
            .map(|i| to.variable(i)),
    };
    found.ok_or_else(|| missing(format!("`{}`", from.variable(v))))
}
