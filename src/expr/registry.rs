//! The variables of one mechanism (parameters, unknowns, coordinates and their rates) and the
//! guard that keeps symbolica on one thread.

use super::builder::{ImposedRate, RegistryBuilder};
use super::guard::ThreadGuard;
use super::*;

mod steps;
use steps::{Names, Variables, with_phases};

/// The variables of one mechanism: its parameters and time coordinates.
///
/// ```
/// use torseur::expr::Registry;
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::new(
///     &["m".to_string(), "L".to_string()],
///     &[("theta".to_string(), CoordinateKind::Angle)],
/// ).unwrap();
/// let e = reg.parse("m*L^2*(sin(theta)^2 + cos(theta)^2)").unwrap();
/// assert_eq!(e, reg.parse("L^2*m").unwrap());
/// ```
#[derive(Debug)]
pub struct Registry {
    /// Ownership of symbolica for this thread while the registry lives (also makes the
    /// registry, and every expression, `!Send` and `!Sync`).
    _guard: ThreadGuard,
    pub(super) vars: Arc<Vec<PolyVariable>>,
    pub(super) roles: Vec<VarRole>,
    pub(super) role_index: HashMap<VarRole, usize>,
    /// Parameters, then unknowns, then `pi`, the constant π (see [`Registry::pi`]).
    pub(super) parameters: Vec<String>,
    pub(super) n_params: usize,
    /// The slot of π: the last of `parameters`.
    pub(super) pi: ParamId,
    pub(super) param_var: HashMap<String, usize>,
    /// The time coordinates, then the constant angle parameters.
    pub(super) coords: Vec<CoordInfo>,
    /// Number of time coordinates (the first entries of `coords`).
    pub(super) n_coords: usize,
    pub(super) coord_by_name: HashMap<String, CoordId>,
    /// Rank of each parameter in the written order of a product (see
    /// [`RegistryBuilder::display_ranks`]).
    display_ranks: Vec<u32>,
    /// Named expressions of the parameters, in declaration order (see
    /// [`RegistryBuilder::aliases`]).
    pub(super) aliases: Vec<(String, Poly)>,
    /// (p, variable of p, variable of 1/p) for each parameter the mechanism divides by (see
    /// [`RegistryBuilder::inverses`]).
    pub(super) inverses: Vec<(ParamId, usize, usize)>,
    /// (q, cos or sin, variable of cos q or sin q, variable of its reciprocal) for each
    /// angle coordinate a loop closure divides by (see [`RegistryBuilder::secants`]).
    pub(super) reciprocals: Vec<(CoordId, Trig, usize, usize)>,
    /// (variable of s, radicand P) for each square root (see [`RegistryBuilder::roots`]).
    pub(super) roots: Vec<(usize, Poly)>,
    /// Whether a text may not write a root (`sqrt(...)`): set while a spec's own texts are
    /// read (see [`Registry::refuse_roots_in_texts`]).
    pub(super) roots_refused: std::cell::Cell<bool>,
}

/// The symbol of the variable 1/p, `inv(p)` in symbolica's atoms (never in a text: a text
/// writes `/p`).
pub(super) fn inverse_symbol() -> Symbol {
    symbolica::symbol!("inv")
}

/// The symbol of the variable 1/cos q, `sec(q)`, or 1/sin q, `csc(q)`, in symbolica's atoms
/// (never in a text: a text writes `/cos(q)`).
pub(super) fn reciprocal_symbol(t: Trig) -> Symbol {
    match t {
        Trig::Cos => symbolica::symbol!("sec"),
        Trig::Sin => symbolica::symbol!("csc"),
    }
}

/// Symbols used for the rate functions dot(q), ddot(q), dddot(q).
pub(super) fn rate_symbol(order: u8) -> Symbol {
    match order {
        1 => symbolica::symbol!("dot"),
        2 => symbolica::symbol!("ddot"),
        _ => symbolica::symbol!("dddot"),
    }
}

/// Longest expression text the parser accepts: 16 MiB, which holds every derived result of
/// the chains up to 8 links (the longest, an equation of motion of chain 8, prints to 3.5 MB)
/// and sympy's printed equations of the same size; beyond it a text is refused, naming the
/// bound. A canonical form prints to a text that parses back to it whenever that text is
/// within this length.
pub const MAX_INPUT_LEN: usize = 16 << 20;

/// Largest degree in one variable an expression can have (exponents are stored in a byte).
/// Parsing refuses anything beyond it, so every expression's text parses back.
pub const MAX_INPUT_DEGREE: u32 = 255;

/// Most terms a typed product or power may expand to before like terms combine (an upper
/// bound computed from the factors, checked before multiplying). A canonical text never comes
/// near it: it multiplies monomials only; `(m + L + k + x + y + z)^40` is refused, in no time, instead
/// of expanding for minutes.
pub const MAX_EXPANDED_TERMS: u128 = 500_000;

/// Largest degree in one variable of the expressions a spec gives (positions, masses, inertia
/// entries, rates): mechanics multiplies them a few times, staying within [`MAX_INPUT_DEGREE`].
pub const MAX_SPEC_DEGREE: u32 = 32;

impl Registry {
    /// Declares parameters and coordinates (none with an imposed rate): the short form of
    /// [`Registry::builder`].
    pub fn new(
        parameters: &[String],
        coords: &[(String, CoordinateKind)],
    ) -> Result<Rc<Registry>, ExprError> {
        coords
            .iter()
            .fold(Registry::builder().parameters(parameters), |b, (n, k)| {
                b.coordinate(n, *k)
            })
            .build()
    }

    /// Declarations to build a registry from, one by one.
    pub fn builder() -> RegistryBuilder {
        RegistryBuilder::default()
    }

    /// Builds the registry from its declarations: the variables in their fixed order
    /// (coordinates and their rates, constant angles, parameters and unknowns, π, inverses,
    /// reciprocals), then the aliases and the imposed rates, parsed against them.
    pub(super) fn build(b: RegistryBuilder) -> Result<Rc<Registry>, ExprError> {
        let RegistryBuilder {
            parameters,
            coords,
            unknowns,
            raw_angles,
            angle_parameters,
            phases,
            aliases,
            inverses,
            secants,
            cosecants,
            holonomic,
            display_ranks,
            roots,
        } = b;
        let n_declared = coords.len();
        let coords = with_phases(coords, &phases, &parameters, &angle_parameters)?;
        // Before any symbolica call: a second thread using symbolica concurrently would abort
        // the process in its restricted mode.
        let guard = ThreadGuard::acquire()?;
        let mut vars = Variables::default();
        let mut names = Names::default();
        let mut infos = vars.coordinates(&coords, n_declared, &raw_angles, &mut names)?;
        let n_coords = infos.len();
        vars.angle_parameters(&angle_parameters, &parameters, &mut infos)?;
        let n_params = parameters.len();
        let mut parameters: Vec<String> = parameters.iter().chain(&unknowns).cloned().collect();
        let param_var = vars.parameters(&parameters, &mut names)?;
        let (pi, pi_var) = vars.pi(&mut parameters);
        let inverse_pairs =
            vars.inverses(&inverses, &parameters, n_params, &param_var, (pi, pi_var))?;
        let reciprocals = vars.reciprocals(&secants, &cosecants, &mut infos, n_declared)?;
        let root_vars: Vec<(usize, RootText)> = (roots.into_iter().enumerate())
            .map(|(k, r)| {
                let atom = symbolica::function!(super::roots::root_symbol(), Atom::num(k as i64));
                let v = PolyVariable::Function(super::roots::root_symbol(), atom);
                (vars.push(v, VarRole::Root(RootId(k))), r)
            })
            .collect();
        for (n, _) in &aliases {
            names.claim(n)?;
        }
        // Constant angle parameters are found by `angle`, not by `coord`.
        let coord_by_name = infos
            .iter()
            .enumerate()
            .map(|(i, c)| (c.name.clone(), CoordId(i)))
            .collect();
        let Variables { vars, roles } = vars;
        let role_index = roles.iter().enumerate().map(|(i, r)| (*r, i)).collect();
        let mut reg = Registry {
            _guard: guard,
            vars: Arc::new(vars),
            role_index,
            roles,
            parameters,
            n_params,
            pi,
            param_var,
            coords: infos,
            n_coords,
            coord_by_name,
            display_ranks,
            aliases: Vec::new(),
            inverses: inverse_pairs,
            reciprocals,
            roots: Vec::new(),
            roots_refused: std::cell::Cell::new(false),
        };
        reg.read_aliases(&aliases)?;
        // The imposed rates before the roots: a rate is differentiated, a moving root is not.
        reg.impose_rates(&coords, &holonomic)?;
        reg.read_roots(&root_vars)?;
        Ok(Rc::new(reg))
    }

    /// A registry that shares this one's variable list and the aliases read so far: aliases,
    /// then imposed rates, are expressions in the parameters, parsed with it.
    pub(super) fn snapshot(&self) -> Result<Rc<Registry>, ExprError> {
        Ok(Rc::new(Registry {
            _guard: ThreadGuard::acquire()?,
            vars: self.vars.clone(),
            roles: self.roles.clone(),
            role_index: self.role_index.clone(),
            parameters: self.parameters.clone(),
            n_params: self.n_params,
            pi: self.pi,
            param_var: self.param_var.clone(),
            coords: self.coords.clone(),
            n_coords: self.n_coords,
            coord_by_name: self.coord_by_name.clone(),
            display_ranks: Vec::new(),
            aliases: self.aliases.clone(),
            inverses: self.inverses.clone(),
            reciprocals: self.reciprocals.clone(),
            roots: self.roots.clone(),
            roots_refused: self.roots_refused.clone(),
        }))
    }

    /// Reads each alias, in declaration order, as an expression of the parameters only.
    fn read_aliases(&mut self, aliases: &[(String, String)]) -> Result<(), ExprError> {
        for (name, text) in aliases {
            let e = self.snapshot()?.parse(text)?;
            if !(e.is_zero() || e.is_parameter_polynomial()) {
                return Err(ExprError::Unsupported {
                    input: text.clone(),
                    reason: format!(
                        "the alias `{name}` is an expression of the parameters only (no \
                         coordinate, rate, time or unknown)"
                    ),
                });
            }
            self.aliases.push((name.clone(), e.into_poly()));
        }
        Ok(())
    }

    /// Reads the imposed rates (the third field of `coords`) and records, per coordinate,
    /// whether it is driven and whether its rate is nonholonomic.
    fn impose_rates(
        &mut self,
        coords: &[(String, CoordinateKind, Option<ImposedRate>)],
        holonomic: &[String],
    ) -> Result<(), ExprError> {
        if !coords.iter().any(|c| c.2.is_some()) {
            return Ok(());
        }
        let base = self.snapshot()?;
        let imposed: Vec<&str> = (coords.iter())
            .filter(|c| c.2.is_some())
            .map(|c| c.0.as_str())
            .collect();
        for (i, (_, _, rate)) in coords.iter().enumerate() {
            let Some(rate) = rate else {
                continue;
            };
            let (e, input) = match rate {
                ImposedRate::Text(r) => (imposed_text(&base, r, &imposed)?, r.clone()),
                ImposedRate::Quotient(n, d) => {
                    let e = quotient(&base, n, d, &imposed)?;
                    let input = e.to_string();
                    (e, input)
                }
            };
            let driven = super::rates::driven_by(&base, CoordId(i), &e)
                .map_err(|reason| ExprError::Unsupported { input, reason })?;
            self.coords[i].imposed_rate = Some(e.into_poly());
            self.coords[i].driven = driven.is_some();
            // A rate solved from a loop closure f(q) = 0 is holonomic, whatever its
            // coefficients hold.
            self.coords[i].nonholonomic =
                driven == Some(false) && !holonomic.contains(&self.coords[i].name);
        }
        Ok(())
    }

    /// The parameters, in declaration order.
    pub fn parameters(&self) -> &[String] {
        &self.parameters[..self.n_params]
    }

    /// The unknowns of the PFD, in declaration order.
    pub fn unknowns(&self) -> &[String] {
        &self.parameters[self.n_params..self.pi.0]
    }

    /// Name of a parameter or unknown (`pi` for π).
    pub fn scalar_name(&self, i: ParamId) -> &str {
        &self.parameters[i.0]
    }

    /// A parameter or an unknown of the PFD by name (never π, which no statement sets).
    pub fn param_id(&self, name: &str) -> Option<ParamId> {
        self.parameters[..self.pi.0]
            .iter()
            .position(|p| p == name)
            .map(ParamId)
    }

    /// Whether variable `i` may enter a factor between two equations
    /// ([`Expr::parameter_ratio`]): a parameter, or the cos or sin of a constant angle
    /// parameter; not a coordinate, a rate or an unknown.
    pub fn is_factor_variable(&self, i: VarId) -> bool {
        match self.roles[i.0] {
            VarRole::Parameter(k) => !self.is_unknown(k),
            VarRole::Inverse(_) => true,
            VarRole::Cos(q) | VarRole::Sin(q) => self.coords[q.0].constant,
            VarRole::Reciprocal(..) | VarRole::Root(_) => false,
            VarRole::Value(_) | VarRole::Rate(..) => false,
        }
    }

    /// The written rank of parameter (or unknown) `p`: see [`RegistryBuilder::display_ranks`].
    pub fn display_rank(&self, p: ParamId) -> u32 {
        if self.is_unknown(p) {
            return u32::MAX;
        }
        // π before every parameter, as a number is (2 π R); the others keep their order.
        if self.is_pi(p) {
            return 0;
        }
        (self.display_ranks.get(p.0).copied())
            .unwrap_or(u32::MAX - 1)
            .saturating_add(1)
    }

    /// Whether a parameter slot holds an unknown of the PFD.
    pub fn is_unknown(&self, i: ParamId) -> bool {
        i.0 >= self.n_params && i != self.pi
    }

    /// The time coordinates, in declaration order (not the constant angle parameters).
    pub fn coordinates(&self) -> &[CoordInfo] {
        &self.coords[..self.n_coords]
    }
    /// ` (did you mean `theta1`?)` after a refusal of the coordinate `name`, or the few
    /// declared coordinates (the crate's `hint::suggestion`).
    pub fn coordinate_hint(&self, name: &str) -> String {
        let declared: Vec<&str> = self.coordinates().iter().map(|c| c.name.as_str()).collect();
        crate::hint::suggestion(name, &declared)
    }

    /// ` (did you mean `L1`?)` after a refusal of the parameter `name` (the PFD's unknowns
    /// are not parameters).
    pub fn parameter_hint(&self, name: &str) -> String {
        let declared: Vec<&str> = (self.parameters().iter().map(String::as_str))
            .filter(|n| !self.unknowns().iter().any(|u| u == n))
            .collect();
        crate::hint::suggestion(name, &declared)
    }

    /// Time coordinate by name (not a constant angle parameter: it has no rate, no equation
    /// of motion, no value in a sample's coordinates).
    pub fn coord(&self, name: &str) -> Option<CoordId> {
        self.coord_by_name
            .get(name)
            .copied()
            .filter(|q| q.0 < self.n_coords)
    }

    /// An angle by name: an angle coordinate or a constant angle parameter (what sin, cos and
    /// a rotation take).
    pub fn angle(&self, name: &str) -> Option<CoordId> {
        self.coord_by_name
            .get(name)
            .copied()
            .filter(|q| self.coords[q.0].kind == CoordinateKind::Angle)
    }

    /// The value of the alias `name`, if the mechanism poses one.
    pub fn alias(self: &Rc<Self>, name: &str) -> Option<Expr> {
        self.aliases
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, p)| self.wrap(p.clone()))
    }

    /// The aliases (name, value), in declaration order.
    pub fn aliases(self: &Rc<Self>) -> impl Iterator<Item = (&str, Expr)> + '_ {
        self.aliases
            .iter()
            .map(|(n, p)| (n.as_str(), self.wrap(p.clone())))
    }

    /// The phase Ω t of the pulsation `w`, if the mechanism has one.
    pub fn phase(&self, w: &str) -> Option<CoordId> {
        self.coords[..self.n_coords]
            .iter()
            .position(|c| c.phase() == Some(w))
            .map(CoordId)
    }

    /// Coordinate (or constant angle parameter) information.
    pub fn coord_info(&self, id: CoordId) -> &CoordInfo {
        &self.coords[id.0]
    }

    /// Number of polynomial variables.
    pub fn nvars(&self) -> usize {
        self.vars.len()
    }

    /// Every polynomial variable, in order.
    pub fn var_ids(&self) -> impl Iterator<Item = VarId> + use<> {
        (0..self.vars.len()).map(VarId)
    }

    /// The variable standing for `role`, if the registry has one.
    pub fn index_of(&self, role: VarRole) -> Option<VarId> {
        self.role_index.get(&role).copied().map(VarId)
    }

    /// (variable of 1/cos q or 1/sin q, its derivative in q) for the reciprocals of q a
    /// loop closure divides by: ∂(1/cos q)/∂q = (1/cos q)² sin q, ∂(1/sin q)/∂q =
    /// −(1/sin q)² cos q.
    pub(super) fn reciprocal_derivatives(self: &Rc<Self>, q: CoordId) -> Vec<(usize, Expr)> {
        self.reciprocals
            .iter()
            .filter(|r| r.0 == q)
            .map(|&(_, t, _, w)| {
                let r = self.var(w);
                let d = match t {
                    Trig::Cos => &(&r * &r) * &self.sin(q),
                    Trig::Sin => -&(&(&r * &r) * &self.cos(q)),
                };
                (w, d)
            })
            .collect()
    }

    /// (v, w) for every pair reduced v·w → 1: a parameter and its inverse, cos q and 1/cos q.
    pub(super) fn inverse_pairs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.inverses
            .iter()
            .map(|&(_, v, w)| (v, w))
            .chain(self.reciprocals.iter().map(|&(_, _, v, w)| (v, w)))
    }

    /// What variable `i` stands for.
    pub fn role(&self, i: VarId) -> VarRole {
        self.roles[i.0]
    }

    pub(super) fn poly_zero(&self) -> Poly {
        Poly::new(&Q, None, self.vars.clone())
    }

    pub(super) fn wrap(self: &Rc<Self>, p: Poly) -> Expr {
        super::budget::built(&p);
        Expr {
            p,
            reg: self.clone(),
        }
    }

    /// The polynomial variable `i` as an expression (see [`Registry::role`]).
    pub fn variable(self: &Rc<Self>, i: VarId) -> Expr {
        self.var(i.0)
    }

    pub(super) fn var(self: &Rc<Self>, i: usize) -> Expr {
        let mut e = vec![0u8; self.vars.len()];
        e[i] = 1;
        let p = self.poly_zero().monomial(Rational::one(), e);
        self.wrap(p)
    }

    /// 0.
    pub fn zero(self: &Rc<Self>) -> Expr {
        self.wrap(self.poly_zero())
    }

    /// 1.
    pub fn one(self: &Rc<Self>) -> Expr {
        self.integer(1)
    }

    /// An integer constant.
    pub fn integer(self: &Rc<Self>, n: i64) -> Expr {
        self.rational(n, 1)
    }

    /// The rational constant n/d (d ≠ 0).
    pub fn rational(self: &Rc<Self>, n: i64, d: i64) -> Expr {
        let r = Rational::new(n, d);
        self.constant(r)
    }

    pub(crate) fn constant(self: &Rc<Self>, r: Rational) -> Expr {
        let p = self.poly_zero().constant(r);
        self.wrap(p)
    }

    /// A parameter, by name.
    pub fn param(self: &Rc<Self>, name: &str) -> Option<Expr> {
        self.param_var.get(name).map(|&i| self.var(i))
    }

    /// cos q (for a length coordinate, which has none, this is 1: never used so).
    pub fn cos(self: &Rc<Self>, q: CoordId) -> Expr {
        match self.coords[q.0].trig {
            Some((c, _)) => self.var(c),
            None => self.one(),
        }
    }

    /// sin q (0 for a length coordinate).
    pub fn sin(self: &Rc<Self>, q: CoordId) -> Expr {
        match self.coords[q.0].trig {
            Some((_, s)) => self.var(s),
            None => self.zero(),
        }
    }

    /// q itself: a length coordinate, or an angle written as itself somewhere in the spec
    /// (None for an angle that enters only by cos and sin).
    pub fn value(self: &Rc<Self>, q: CoordId) -> Option<Expr> {
        self.coords[q.0].value.map(|i| self.var(i))
    }

    /// q̇.
    pub fn dot(self: &Rc<Self>, q: CoordId) -> Expr {
        self.rate(q, 1)
    }

    /// q̈.
    pub fn ddot(self: &Rc<Self>, q: CoordId) -> Expr {
        self.rate(q, 2)
    }

    /// Derivative of order 1 to 3 of q.
    pub fn rate(self: &Rc<Self>, q: CoordId, order: u8) -> Expr {
        let c = &self.coords[q.0];
        match (&c.rates, &c.imposed_rate) {
            (Some(r), _) => self.var(r[(order.clamp(1, 3) - 1) as usize]),
            (None, Some(w)) if order == 1 => self.wrap(w.clone()),
            // Driven by the other rates: q̈ = d/dt q̇, with constant coefficients.
            (None, Some(w)) if c.driven => {
                (1..order.clamp(1, 3)).fold(self.wrap(w.clone()), |e, _| e.dt())
            }
            _ => self.zero(),
        }
    }

    /// While `refused`, a text that writes a square root is refused (exit 2): a spec's own
    /// texts are differentiated (velocities, powers, Lagrange's equations), and the time
    /// derivative of a root whose radicand moves, Ṗ/(2√P), is not a polynomial. The roots of
    /// a mechanism are its explicit loop laws', read in the texts typed after loading (a
    /// relation to verify), never differentiated.
    pub(crate) fn refuse_roots_in_texts(&self, refused: bool) {
        self.roots_refused.set(refused);
    }

    /// Parses an expression of the spec syntax (see DESIGN.md) into canonical form.
    pub fn parse(self: &Rc<Self>, s: &str) -> Result<Expr, ExprError> {
        parse::parse_scalar(self, s)
    }

    /// [`Registry::parse`], where `names` gives the value of the names that are neither
    /// parameters, unknowns nor coordinates (a quantity written inside an equation, replaced by
    /// a placeholder name); any other name is still an [`ExprError::UnknownName`].
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let w = reg.parse("m*dot(q)").unwrap();
    /// let e = reg.parse_with("2*W - m*dot(q)", &|n| (n == "W").then(|| w.clone())).unwrap();
    /// assert_eq!(e, w);
    /// assert!(reg.parse_with("2*U", &|n| (n == "W").then(|| w.clone())).is_err());
    /// ```
    pub fn parse_with(
        self: &Rc<Self>,
        s: &str,
        names: &dyn Fn(&str) -> Option<Expr>,
    ) -> Result<Expr, ExprError> {
        parse::parse_scalar_with(self, s, names)
    }

    /// Parses an angle that is a sum of angles with integer coefficients and a multiple of
    /// π/2 (`pi/2 - q1`, `theta - alpha`, `2*q`): its terms, offset and exact cos and sin,
    /// by the angle-addition formulas. What a frame's rotation takes (the spec then allows one
    /// time coordinate in it).
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&[], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let a = reg.parse_angle("pi/2 - q").unwrap();
    /// assert_eq!(a.quarter_turns, 1);
    /// assert_eq!(a.cos, reg.parse("sin(q)").unwrap());
    /// assert_eq!(a.sin, reg.parse("cos(q)").unwrap());
    /// ```
    pub fn parse_angle(self: &Rc<Self>, s: &str) -> Result<LinearAngle, ExprError> {
        parse::parse_angle(self, s)
    }
}

/// The refusal of a rate that holds the rate of `other`, a coordinate whose rate is imposed
/// too (it would read as 0 in the registry the rates are read with).
fn imposed_too(input: String, other: &str) -> ExprError {
    ExprError::Unsupported {
        input,
        reason: format!(
            "the rate of `{other}` is imposed too: write the rate with the coordinates whose \
             rates are free"
        ),
    }
}

/// An imposed rate given as a text, read with `base` (the registry before any rate is
/// imposed); `imposed` names the coordinates whose rates are imposed.
fn imposed_text(base: &Rc<Registry>, r: &str, imposed: &[&str]) -> Result<Expr, ExprError> {
    // The rate of a coordinate whose rate is itself imposed reads as 0 in `base`: refused
    // by name rather than silently dropped.
    let compact: String = r.chars().filter(|c| !c.is_whitespace()).collect();
    if let Some(other) = (imposed.iter()).find(|n| compact.contains(&format!("dot({n})"))) {
        return Err(imposed_too(r.to_string(), other));
    }
    base.parse(r)
}

/// A rate given as numerator / denominator over another registry, carried onto `base`: the
/// denominator a monomial `base` inverts; a rate of an imposed coordinate is refused as in a
/// text.
fn quotient(base: &Rc<Registry>, n: &Expr, d: &Expr, imposed: &[&str]) -> Result<Expr, ExprError> {
    let from = n.registry();
    for v in from.var_ids().filter(|&v| n.contains_var(v)) {
        if let VarRole::Rate(q, _) = from.role(v)
            && let Some(other) = imposed.iter().find(|n| **n == from.coord_info(q).name)
        {
            return Err(imposed_too(n.to_string(), other));
        }
    }
    let (n, d) = (n.carried(base)?, d.carried(base)?);
    let inverse = match d.as_rational() {
        Some(r) if !r.is_zero() => Ok(base.constant(r.inv())),
        _ => d.monomial_inverse(),
    };
    let inverse = inverse.map_err(|reason| ExprError::Unsupported {
        input: d.to_string(),
        reason,
    })?;
    Ok(&n * &inverse)
}
