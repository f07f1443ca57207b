//! The helpers of a registry's build: the phases' coordinates, the names already taken, the
//! variables in their order.

use super::*;
use crate::expr::builder::ImposedRate;

/// The declared coordinates followed by one coordinate `w*t` per pulsation `w` (each a
/// parameter that is not an angle), whose imposed rate field holds `w`.
pub(super) fn with_phases(
    mut coords: Vec<(String, CoordinateKind, Option<ImposedRate>)>,
    phases: &[String],
    parameters: &[String],
    angle_parameters: &[String],
) -> Result<Vec<(String, CoordinateKind, Option<ImposedRate>)>, ExprError> {
    for w in phases {
        if !parameters.contains(w) || angle_parameters.contains(w) {
            return Err(ExprError::Declaration(format!(
                "the pulsation `{w}` of `{w}*t` is not a parameter (the time enters as \
                 cos(Omega*t), Omega a parameter declared in rad/s)"
            )));
        }
    }
    for w in phases {
        let name = format!("{w}*t");
        if !coords.iter().any(|c| c.0 == name) {
            coords.push((
                name,
                CoordinateKind::Angle,
                Some(ImposedRate::Text(w.clone())),
            ));
        }
    }
    Ok(coords)
}

/// The names declared so far, each checked once: an identifier, not reserved, not twice.
#[derive(Default)]
pub(super) struct Names(HashMap<String, ()>);

impl Names {
    /// Refuses `n` if it is not an identifier, is reserved, or was declared before.
    pub(super) fn claim(&mut self, n: &str) -> Result<(), ExprError> {
        validate_identifier(n).map_err(ExprError::Declaration)?;
        if RESERVED.contains(&n) {
            return Err(ExprError::Declaration(reserved_word(n)));
        }
        if self.0.insert(n.to_string(), ()).is_some() {
            return Err(ExprError::Declaration(format!("`{n}` is declared twice")));
        }
        Ok(())
    }
}

/// The polynomial variables of a registry being built, each with its role, in order.
#[derive(Default)]
pub(super) struct Variables {
    /// The polynomial variables, in the registry's order.
    pub(super) vars: Vec<PolyVariable>,
    /// What each one is.
    pub(super) roles: Vec<VarRole>,
}

impl Variables {
    /// Appends a variable with its role; returns its index.
    pub(super) fn push(&mut self, var: PolyVariable, role: VarRole) -> usize {
        self.vars.push(var);
        self.roles.push(role);
        self.vars.len() - 1
    }

    /// The variables sin q and cos q of the angle `q` (sin first: in lex order sin² leads
    /// sin² + cos² − 1); returns (cos, sin), as `CoordInfo::trig` holds them.
    pub(super) fn trig(&mut self, id: CoordId, q: &Atom) -> (usize, usize) {
        // A function variable holds the whole call, sin(q), not its argument.
        let s = self.push(
            PolyVariable::Function(Symbol::SIN, symbolica::function!(Symbol::SIN, q.clone())),
            VarRole::Sin(id),
        );
        let c = self.push(
            PolyVariable::Function(Symbol::COS, symbolica::function!(Symbol::COS, q.clone())),
            VarRole::Cos(id),
        );
        (c, s)
    }

    /// The variables of each time coordinate (its value or its sine and cosine, then its
    /// three rates unless imposed), its name checked; the coordinates from index
    /// `n_declared` on are the phases `w*t`.
    pub(super) fn coordinates(
        &mut self,
        coords: &[(String, CoordinateKind, Option<ImposedRate>)],
        n_declared: usize,
        raw_angles: &[String],
        names: &mut Names,
    ) -> Result<Vec<CoordInfo>, ExprError> {
        let mut infos = Vec::new();
        for (i, (name, kind, rate)) in coords.iter().enumerate() {
            let phase = (i >= n_declared)
                .then(|| rate.as_ref()?.text().map(str::to_string))
                .flatten();
            let id = CoordId(i);
            let q = match &phase {
                // The atom Ω t itself: no symbol of the user's can clash with it.
                Some(w) => {
                    Atom::var(symbolica::symbol!(w.as_str())) * Atom::var(symbolica::symbol!("t"))
                }
                None => {
                    names.claim(name)?;
                    Atom::var(symbolica::symbol!(name.as_str()))
                }
            };
            let mut info = CoordInfo {
                name: name.clone(),
                kind: *kind,
                value: None,
                trig: None,
                rates: None,
                imposed_rate: None,
                constant: false,
                phase,
                driven: false,
                nonholonomic: false,
                cos_reduced: false,
            };
            if *kind == CoordinateKind::Angle {
                info.trig = Some(self.trig(id, &q));
            }
            if *kind == CoordinateKind::Length || raw_angles.contains(name) {
                let v = PolyVariable::Symbol(symbolica::symbol!(name.as_str()));
                info.value = Some(self.push(v, VarRole::Value(id)));
            }
            if rate.is_none() {
                let mut r = [0; 3];
                for (k, slot) in r.iter_mut().enumerate() {
                    let order = k as u8 + 1;
                    let v = PolyVariable::Function(
                        rate_symbol(order),
                        symbolica::function!(rate_symbol(order), q.clone()),
                    );
                    *slot = self.push(v, VarRole::Rate(id, order));
                }
                info.rates = Some(r);
            }
            infos.push(info);
        }
        Ok(infos)
    }

    /// The sine and cosine of each constant angle parameter, appended to `infos` after the
    /// time coordinates; each must be a declared parameter, named once.
    pub(super) fn angle_parameters(
        &mut self,
        angle_parameters: &[String],
        parameters: &[String],
        infos: &mut Vec<CoordInfo>,
    ) -> Result<(), ExprError> {
        for (k, name) in angle_parameters.iter().enumerate() {
            if !parameters.contains(name) {
                return Err(ExprError::Declaration(format!(
                    "the angle parameter `{name}` is not a parameter"
                )));
            }
            if angle_parameters[..k].contains(name) {
                return Err(ExprError::Declaration(format!(
                    "`{name}` is declared twice"
                )));
            }
            let id = CoordId(infos.len());
            let trig = self.trig(id, &Atom::var(symbolica::symbol!(name.as_str())));
            infos.push(CoordInfo {
                name: name.clone(),
                kind: CoordinateKind::Angle,
                value: None,
                trig: Some(trig),
                rates: None,
                imposed_rate: None,
                constant: true,
                phase: None,
                driven: false,
                nonholonomic: false,
                cos_reduced: false,
            });
        }
        Ok(())
    }

    /// A variable per parameter and unknown (`declared`, names checked): the variable of each
    /// name.
    pub(super) fn parameters(
        &mut self,
        declared: &[String],
        names: &mut Names,
    ) -> Result<HashMap<String, usize>, ExprError> {
        let mut param_var = HashMap::new();
        for (i, p) in declared.iter().enumerate() {
            names.claim(p)?;
            let v = self.push(
                PolyVariable::Symbol(symbolica::symbol!(p.as_str())),
                VarRole::Parameter(ParamId(i)),
            );
            param_var.insert(p.clone(), v);
        }
        Ok(param_var)
    }

    /// π, a positive constant of no dimension: a variable of its own, after every declared
    /// scalar (so that no other variable moves), read from `pi` and printed `pi`; its name goes
    /// last in `parameters`. Returns its id and its variable.
    pub(super) fn pi(&mut self, parameters: &mut Vec<String>) -> (ParamId, usize) {
        let pi = ParamId(parameters.len());
        parameters.push(PI.to_string());
        (
            pi,
            self.push(PolyVariable::Symbol(Symbol::PI), VarRole::Parameter(pi)),
        )
    }

    /// The variable 1/p of each parameter (or π) the mechanism divides by, once each: (p,
    /// variable of p, variable of 1/p). A coordinate, a rate or an unknown is refused.
    pub(super) fn inverses(
        &mut self,
        inverses: &[String],
        parameters: &[String],
        n_params: usize,
        param_var: &HashMap<String, usize>,
        (pi, pi_var): (ParamId, usize),
    ) -> Result<Vec<(ParamId, usize, usize)>, ExprError> {
        let mut inverse_pairs = Vec::new();
        for name in inverses {
            let found = match name.as_str() {
                PI => Some((pi, pi_var)),
                _ => param_var
                    .get(name)
                    .filter(|_| parameters[..n_params].contains(name))
                    .map(|&v| {
                        (
                            ParamId(
                                parameters
                                    .iter()
                                    .position(|x| x == name)
                                    .unwrap_or_default(),
                            ),
                            v,
                        )
                    }),
            };
            let Some((p, v)) = found else {
                return Err(ExprError::Declaration(format!(
                    "cannot divide by `{name}`: a text may divide only by parameters (not by a \
                     coordinate, a rate or an unknown)"
                )));
            };
            if inverse_pairs.iter().any(|&(q, _, _)| q == p) {
                continue;
            }
            let inv = PolyVariable::Function(
                inverse_symbol(),
                symbolica::function!(inverse_symbol(), self.vars[v].to_atom()),
            );
            inverse_pairs.push((p, v, self.push(inv, VarRole::Inverse(p))));
        }
        Ok(inverse_pairs)
    }

    /// The variable 1/cos q of each angle coordinate in `secants` and 1/sin q of each in
    /// `cosecants` (never both for one q): (q, cos or sin, its variable, its reciprocal's).
    /// A q divided by sin q has its cos² reduced instead (`cos_reduced`).
    pub(super) fn reciprocals(
        &mut self,
        secants: &[String],
        cosecants: &[String],
        infos: &mut [CoordInfo],
        n_declared: usize,
    ) -> Result<Vec<(CoordId, Trig, usize, usize)>, ExprError> {
        let mut reciprocals = Vec::new();
        let over = secants
            .iter()
            .map(|n| (n, Trig::Cos))
            .chain(cosecants.iter().map(|n| (n, Trig::Sin)));
        for (name, t) in over {
            let found = infos
                .iter()
                .enumerate()
                .take(n_declared)
                .find(|(_, c)| &c.name == name && c.kind == CoordinateKind::Angle);
            let Some((q, (ci, si))) = found.and_then(|(q, c)| Some((q, c.trig?))) else {
                return Err(ExprError::Declaration(format!(
                    "cannot divide by `{}({name})`: `{name}` is not an angle coordinate",
                    t.name()
                )));
            };
            if secants.contains(name) && cosecants.contains(name) {
                return Err(ExprError::Declaration(format!(
                    "cannot divide by both `cos({name})` and `sin({name})`"
                )));
            }
            let rec = PolyVariable::Function(
                reciprocal_symbol(t),
                symbolica::function!(
                    reciprocal_symbol(t),
                    Atom::var(symbolica::symbol!(name.as_str()))
                ),
            );
            let r = self.push(rec, VarRole::Reciprocal(CoordId(q), t));
            let v = if t == Trig::Cos { ci } else { si };
            reciprocals.push((CoordId(q), t, v, r));
            infos[q].cos_reduced = t == Trig::Sin;
        }
        Ok(reciprocals)
    }
}
