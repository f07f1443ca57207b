//! Exact expressions: the only module that sees symbolica.
//!
//! Every quantity of rigid-body kinematics and dynamics is a polynomial in cos qᵢ, sin qᵢ (angle
//! coordinates, and constant angle parameters), qᵢ (length coordinates, and the angles a spec
//! writes as themselves), q̇ᵢ, q̈ᵢ and the parameters, with rational coefficients. [`Expr`] stores exactly that, as a symbolica `MultivariatePolynomial` over ℚ
//! whose variables are fixed once per mechanism by a [`Registry`], and keeps it in the
//! **canonical form** of DESIGN.md: expanded, with every sin²qᵢ replaced by 1 − cos²qᵢ. Two
//! expressions are equal as functions iff their canonical forms are identical, so the zero
//! test is exact and costs nothing.

mod eval;
mod factor;
mod flat;
mod parse;
pub(crate) mod print;

pub use flat::FlatEval;
pub use parse::bare_names;
pub use print::{Presentation, PresentationGroup};

use crate::excerpt::{bounded, excerpt};
use crate::spec::wire::CoordinateKind;
use std::collections::HashMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::rc::Rc;
use std::sync::Arc;
use symbolica::atom::{Atom, AtomCore, Symbol};
use symbolica::domains::rational::{Q, Rational, RationalField};
use symbolica::poly::PolyVariable;
use symbolica::poly::polynomial::MultivariatePolynomial;

type Poly = MultivariatePolynomial<RationalField, u8>;

/// Typed index of a time coordinate in a [`Registry`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct CoordId(pub(crate) usize);

impl CoordId {
    /// Index in declaration order.
    pub fn index(self) -> usize {
        self.0
    }
}

/// Errors of the expression layer: parsing and unsupported forms.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ExprError {
    /// The text is not an expression of the spec syntax.
    #[error("cannot parse `{}`: {}", excerpt(.input), bounded(.reason))]
    Parse {
        /// The text given.
        input: String,
        /// Why.
        reason: String,
    },
    /// A name that is neither a parameter nor a coordinate.
    #[error(
        "unknown name `{}` in `{}` (declare it as a parameter or a coordinate)",
        excerpt(.name),
        excerpt(.input)
    )]
    UnknownName {
        /// The name.
        name: String,
        /// The text given.
        input: String,
    },
    /// Valid syntax, outside what the exact engine handles.
    #[error("`{}`: {}", excerpt(.input), bounded(.reason))]
    Unsupported {
        /// The text given.
        input: String,
        /// Why.
        reason: String,
    },
    /// A registry declaration problem.
    #[error("{}", bounded(.0))]
    Declaration(String),
    /// Another thread is using symbolica (restricted mode: one thread at a time).
    #[error("{0}")]
    Thread(String),
}

/// How a coordinate enters expressions.
#[derive(Debug, Clone)]
pub struct CoordInfo {
    /// Name as declared (`theta1`).
    pub name: String,
    /// Angle or length.
    pub kind: CoordinateKind,
    /// Variable index of q (lengths).
    value: Option<usize>,
    /// Variable indices of cos q and sin q (angles).
    trig: Option<(usize, usize)>,
    /// Variable indices of q̇, q̈ and the third derivative, unless the rate is imposed.
    rates: Option<[usize; 3]>,
    /// Imposed constant rate q̇ (then q̈ = 0).
    imposed_rate: Option<Poly>,
    /// A constant angle parameter (`"kind": "angle"` in `parameters`): cos and sin variables,
    /// no rate; its value itself is the parameter's variable.
    constant: bool,
}

impl CoordInfo {
    /// The polynomial variable holding q itself, if the coordinate has one (a length, or an
    /// angle that enters as itself).
    pub fn value_var(&self) -> Option<usize> {
        self.value
    }

    /// Whether the rate is imposed (q̇ given, q̈ = 0).
    pub fn has_imposed_rate(&self) -> bool {
        self.imposed_rate.is_some()
    }

    /// Whether this is a constant angle parameter, not a time coordinate: it has cos and sin
    /// variables like an angle coordinate, and a zero rate.
    pub fn is_constant(&self) -> bool {
        self.constant
    }

    /// Whether the value never changes: a constant angle parameter, or a coordinate whose
    /// imposed rate is 0.
    fn is_fixed(&self) -> bool {
        self.constant || self.imposed_rate.as_ref().is_some_and(|w| w.is_zero())
    }
}

/// What a polynomial variable stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum VarRole {
    /// A constant parameter (index in [`Registry::parameters`]), or beyond them an unknown
    /// of the PFD (index − number of parameters in [`Registry::unknowns`]).
    Parameter(usize),
    /// cos q of an angle coordinate (or of a constant angle parameter).
    Cos(CoordId),
    /// sin q of an angle coordinate (or of a constant angle parameter).
    Sin(CoordId),
    /// q itself, for a length coordinate (or an angle that enters as itself).
    Value(CoordId),
    /// q̇ (order 1), q̈ (order 2), third derivative (order 3).
    Rate(CoordId, u8),
}

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
    vars: Arc<Vec<PolyVariable>>,
    roles: Vec<VarRole>,
    role_index: HashMap<VarRole, usize>,
    /// Parameters, then unknowns.
    parameters: Vec<String>,
    n_params: usize,
    param_var: HashMap<String, usize>,
    /// The time coordinates, then the constant angle parameters.
    coords: Vec<CoordInfo>,
    /// Number of time coordinates (the first entries of `coords`).
    n_coords: usize,
    coord_by_name: HashMap<String, CoordId>,
}

/// Symbols used for the rate functions dot(q), ddot(q), dddot(q).
fn rate_symbol(order: u8) -> Symbol {
    match order {
        1 => symbolica::symbol!("dot"),
        2 => symbolica::symbol!("ddot"),
        _ => symbolica::symbol!("dddot"),
    }
}

/// How long a thread waits for another to finish with symbolica before getting an error.
const THREAD_WAIT: std::time::Duration = std::time::Duration::from_secs(2);

/// The thread that uses symbolica in this process, if any.
static OWNER: std::sync::Mutex<Option<std::thread::ThreadId>> = std::sync::Mutex::new(None);

/// Releases the ownership when the owning thread exits.
struct OwnerMark;

impl Drop for OwnerMark {
    fn drop(&mut self) {
        let me = std::thread::current().id();
        let mut owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        if *owner == Some(me) {
            *owner = None;
        }
    }
}

thread_local! {
    static MARK: OwnerMark = const { OwnerMark };
}

/// One thread at a time may use symbolica: its restricted mode aborts the process when a
/// second thread uses it while the first is alive (threads one after another are fine). The
/// first thread that creates a registry owns symbolica until it exits; another thread then
/// gets a clear error instead of an abort. Registries and expressions are `!Send` and `!Sync`,
/// so they never migrate. With `SYMBOLICA_LICENSE` set the limit does not apply.
#[derive(Debug)]
struct ThreadGuard {
    _not_send: std::marker::PhantomData<*const ()>,
}

impl ThreadGuard {
    fn acquire() -> Result<ThreadGuard, ExprError> {
        let guard = ThreadGuard {
            _not_send: std::marker::PhantomData,
        };
        if std::env::var_os("SYMBOLICA_LICENSE").is_some() {
            return Ok(guard);
        }
        let me = std::thread::current().id();
        // A thread that has just finished releases symbolica in its exit destructors: wait a
        // little for that before refusing (serialised hand-over between threads).
        let start = std::time::Instant::now();
        let mut owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        while owner.is_some_and(|id| id != me) && start.elapsed() < THREAD_WAIT {
            drop(owner);
            std::thread::sleep(std::time::Duration::from_millis(1));
            owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        }
        match *owner {
            Some(id) if id == me => {}
            Some(id) => {
                return Err(ExprError::Thread(format!(
                    "thread {me:?} cannot use torseur while thread {id:?} is using it: \
                     unlicensed symbolica allows one thread at a time (use torseur from one \
                     thread, let the other thread finish first, or set SYMBOLICA_LICENSE)"
                )));
            }
            None => {
                *owner = Some(me);
                MARK.with(|_| {});
            }
        }
        Ok(guard)
    }
}

/// A name usable in expressions (parameters, coordinates): an ASCII letter, then letters,
/// digits or `_`, at most 32 characters. (`21` would read as a number.)
///
/// ```
/// assert!(torseur::expr::check_identifier("theta1").is_ok());
/// assert!(torseur::expr::check_identifier("21").is_err());
/// assert!(torseur::expr::check_identifier("m-1").is_err());
/// ```
pub fn check_identifier(n: &str) -> Result<(), String> {
    let mut chars = n.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic());
    if !first_ok || n.len() > 32 || !n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        return Err(format!(
            "`{n}` is not a valid name for an expression: a letter, then letters, digits or `_` \
             (at most 32 characters)"
        ));
    }
    Ok(())
}

/// Longest expression text the parser accepts. A canonical form prints to a text that parses
/// back to it whenever that text is within this length.
pub const MAX_INPUT_LEN: usize = 20_000;

/// Largest degree in one variable an expression can have (exponents are stored in a byte).
/// Parsing refuses anything beyond it, so every expression's text parses back.
pub const MAX_INPUT_DEGREE: u32 = 255;

/// Largest degree in one variable of the expressions a spec gives (positions, masses, inertia
/// entries, rates): mechanics multiplies them a few times, staying within [`MAX_INPUT_DEGREE`].
pub const MAX_SPEC_DEGREE: u32 = 32;

/// Names reserved by the expression syntax.
pub const RESERVED: &[&str] = &["sin", "cos", "dot", "ddot", "dddot", "pi", "t"];

impl Registry {
    /// Declares parameters and coordinates (none with an imposed rate).
    pub fn new(
        parameters: &[String],
        coords: &[(String, CoordinateKind)],
    ) -> Result<Rc<Registry>, ExprError> {
        let with_rates: Vec<(String, CoordinateKind, Option<String>)> =
            coords.iter().map(|(n, k)| (n.clone(), *k, None)).collect();
        Registry::with_rates(parameters, &with_rates)
    }

    /// Declares parameters and coordinates; a coordinate may have an imposed constant rate,
    /// an expression in the parameters (`omega`), in which case q̇ is that expression and q̈ = 0.
    pub fn with_rates(
        parameters: &[String],
        coords: &[(String, CoordinateKind, Option<String>)],
    ) -> Result<Rc<Registry>, ExprError> {
        Registry::with_unknowns(parameters, coords, &[], &[], &[])
    }

    /// [`Registry::with_rates`], plus the unknowns of the PFD (link components, a motor
    /// torque: scalars that enter linearly and are solved for), the angles that also enter
    /// as themselves (a torsion spring's −k(θ − θ0), a disc's centre at R θ x1), not only
    /// through sin and cos, and the parameters that are constant angles (an incline α: it
    /// gets cos α and sin α variables, with sin²α reduced like a coordinate's, and a zero
    /// rate; α itself stays the parameter's variable).
    pub fn with_unknowns(
        parameters: &[String],
        coords: &[(String, CoordinateKind, Option<String>)],
        unknowns: &[String],
        raw_angles: &[String],
        angle_parameters: &[String],
    ) -> Result<Rc<Registry>, ExprError> {
        // Before any symbolica call: a second thread using symbolica concurrently would abort
        // the process in its restricted mode.
        let guard = ThreadGuard::acquire()?;
        let mut vars: Vec<PolyVariable> = Vec::new();
        let mut roles = Vec::new();
        let mut seen: HashMap<String, ()> = HashMap::new();
        let mut check = |n: &str| -> Result<(), ExprError> {
            check_identifier(n).map_err(ExprError::Declaration)?;
            if RESERVED.contains(&n) {
                return Err(ExprError::Declaration(format!(
                    "`{n}` is reserved by the expression syntax"
                )));
            }
            if seen.insert(n.to_string(), ()).is_some() {
                return Err(ExprError::Declaration(format!("`{n}` is declared twice")));
            }
            Ok(())
        };
        let mut infos = Vec::new();
        for (i, (name, kind, rate)) in coords.iter().enumerate() {
            check(name)?;
            let id = CoordId(i);
            let q = Atom::var(symbolica::symbol!(name.as_str()));
            let mut info = CoordInfo {
                name: name.clone(),
                kind: *kind,
                value: None,
                trig: None,
                rates: None,
                imposed_rate: None,
                constant: false,
            };
            match kind {
                CoordinateKind::Angle => {
                    // sin before cos: in lex order sin² leads sin² + cos² − 1.
                    // A function variable holds the whole call, sin(q), not its argument.
                    vars.push(PolyVariable::Function(
                        Symbol::SIN,
                        symbolica::function!(Symbol::SIN, q.clone()),
                    ));
                    roles.push(VarRole::Sin(id));
                    vars.push(PolyVariable::Function(
                        Symbol::COS,
                        symbolica::function!(Symbol::COS, q.clone()),
                    ));
                    roles.push(VarRole::Cos(id));
                    info.trig = Some((vars.len() - 1, vars.len() - 2));
                    if raw_angles.contains(name) {
                        vars.push(PolyVariable::Symbol(symbolica::symbol!(name.as_str())));
                        roles.push(VarRole::Value(id));
                        info.value = Some(vars.len() - 1);
                    }
                }
                CoordinateKind::Length => {
                    vars.push(PolyVariable::Symbol(symbolica::symbol!(name.as_str())));
                    roles.push(VarRole::Value(id));
                    info.value = Some(vars.len() - 1);
                }
            }
            if rate.is_none() {
                let mut r = [0; 3];
                for (k, slot) in r.iter_mut().enumerate() {
                    let order = k as u8 + 1;
                    vars.push(PolyVariable::Function(
                        rate_symbol(order),
                        symbolica::function!(rate_symbol(order), q.clone()),
                    ));
                    roles.push(VarRole::Rate(id, order));
                    *slot = vars.len() - 1;
                }
                info.rates = Some(r);
            }
            infos.push(info);
        }
        let n_coords = infos.len();
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
            let a = Atom::var(symbolica::symbol!(name.as_str()));
            vars.push(PolyVariable::Function(
                Symbol::SIN,
                symbolica::function!(Symbol::SIN, a.clone()),
            ));
            roles.push(VarRole::Sin(id));
            vars.push(PolyVariable::Function(
                Symbol::COS,
                symbolica::function!(Symbol::COS, a),
            ));
            roles.push(VarRole::Cos(id));
            infos.push(CoordInfo {
                name: name.clone(),
                kind: CoordinateKind::Angle,
                value: None,
                trig: Some((vars.len() - 1, vars.len() - 2)),
                rates: None,
                imposed_rate: None,
                constant: true,
            });
        }
        let mut param_var = HashMap::new();
        let n_params = parameters.len();
        let parameters: Vec<String> = parameters.iter().chain(unknowns).cloned().collect();
        for (i, p) in parameters.iter().enumerate() {
            check(p)?;
            vars.push(PolyVariable::Symbol(symbolica::symbol!(p.as_str())));
            roles.push(VarRole::Parameter(i));
            param_var.insert(p.clone(), vars.len() - 1);
        }
        // Constant angle parameters are found by `angle`, not by `coord`.
        let coord_by_name = infos
            .iter()
            .enumerate()
            .map(|(i, c)| (c.name.clone(), CoordId(i)))
            .collect();
        let role_index = roles.iter().enumerate().map(|(i, r)| (*r, i)).collect();
        let mut reg = Registry {
            _guard: guard,
            vars: Arc::new(vars),
            role_index,
            roles,
            parameters,
            n_params,
            param_var,
            coords: infos,
            n_coords,
            coord_by_name,
        };
        // Imposed rates are expressions in the parameters: parse them with a registry that
        // shares the same variable list.
        if coords.iter().any(|c| c.2.is_some()) {
            let base = Rc::new(Registry {
                _guard: ThreadGuard::acquire()?,
                vars: reg.vars.clone(),
                roles: reg.roles.clone(),
                role_index: reg.role_index.clone(),
                parameters: reg.parameters.clone(),
                n_params: reg.n_params,
                param_var: reg.param_var.clone(),
                coords: reg.coords.clone(),
                n_coords: reg.n_coords,
                coord_by_name: reg.coord_by_name.clone(),
            });
            for (i, (_, _, rate)) in coords.iter().enumerate() {
                if let Some(r) = rate {
                    let e = base.parse(r)?;
                    if !e.is_time_independent() {
                        return Err(ExprError::Unsupported {
                            input: r.clone(),
                            reason: "an imposed rate must be a constant (parameters only)"
                                .to_string(),
                        });
                    }
                    reg.coords[i].imposed_rate = Some(e.p);
                }
            }
        }
        Ok(Rc::new(reg))
    }

    /// The parameters, in declaration order.
    pub fn parameters(&self) -> &[String] {
        &self.parameters[..self.n_params]
    }

    /// The unknowns of the PFD, in declaration order.
    pub fn unknowns(&self) -> &[String] {
        &self.parameters[self.n_params..]
    }

    /// Name of the parameter or unknown of a [`VarRole::Parameter`] index.
    pub fn scalar_name(&self, i: usize) -> &str {
        &self.parameters[i]
    }

    /// Whether variable `i` may enter a factor between two equations
    /// ([`Expr::parameter_ratio`]): a parameter, or the cos or sin of a constant angle
    /// parameter; not a coordinate, a rate or an unknown.
    pub fn is_factor_variable(&self, i: usize) -> bool {
        match self.roles[i] {
            VarRole::Parameter(k) => !self.is_unknown(k),
            VarRole::Cos(q) | VarRole::Sin(q) => self.coords[q.0].constant,
            VarRole::Value(_) | VarRole::Rate(..) => false,
        }
    }

    /// Whether a [`VarRole::Parameter`] index is an unknown of the PFD.
    pub fn is_unknown(&self, i: usize) -> bool {
        i >= self.n_params
    }

    /// The time coordinates, in declaration order (not the constant angle parameters).
    pub fn coordinates(&self) -> &[CoordInfo] {
        &self.coords[..self.n_coords]
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

    /// Coordinate (or constant angle parameter) information.
    pub fn coord_info(&self, id: CoordId) -> &CoordInfo {
        &self.coords[id.0]
    }

    /// Number of polynomial variables.
    pub fn nvars(&self) -> usize {
        self.vars.len()
    }

    /// The variable standing for `role`, if the registry has one.
    pub fn index_of(&self, role: VarRole) -> Option<usize> {
        self.role_index.get(&role).copied()
    }

    /// What variable `i` stands for.
    pub fn role(&self, i: usize) -> VarRole {
        self.roles[i]
    }

    fn poly_zero(&self) -> Poly {
        Poly::new(&Q, None, self.vars.clone())
    }

    fn wrap(self: &Rc<Self>, p: Poly) -> Expr {
        Expr {
            p,
            reg: self.clone(),
        }
    }

    /// The polynomial variable `i` as an expression (see [`Registry::role`]).
    pub fn variable(self: &Rc<Self>, i: usize) -> Expr {
        self.var(i)
    }

    fn var(self: &Rc<Self>, i: usize) -> Expr {
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
            _ => self.zero(),
        }
    }

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
                let text = e.presentation().to_string();
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

    /// Parses a vector expression `d1*z0 + L1*y1`, where `basis_vector(name)` recognises the
    /// basis vector names (returning a basis key and an axis index). Returns, per basis key,
    /// the three components.
    pub fn parse_vector<K: Ord + Copy>(
        self: &Rc<Self>,
        s: &str,
        basis_vector: &dyn Fn(&str) -> Option<(K, usize)>,
    ) -> Result<Vec<(K, [Expr; 3])>, ExprError> {
        parse::parse_vector(self, s, basis_vector)
    }
}

/// An angle Σ nᵢ aᵢ + k π/2, read by [`Registry::parse_angle`].
#[derive(Debug, Clone)]
pub struct LinearAngle {
    /// The angles (coordinates or constant angle parameters) with their nonzero integer
    /// coefficients, in the order written.
    pub terms: Vec<(CoordId, i64)>,
    /// The constant offset k of k π/2, as written (not reduced modulo 4).
    pub quarter_turns: i64,
    /// Exact cosine of the angle.
    pub cos: Expr,
    /// Exact sine of the angle.
    pub sin: Expr,
}

/// Default Horner-scheme iterations of [`Registry::compile`].
pub const COMPILE_HORNER: usize = 1;
/// Default common-pair elimination iterations of [`Registry::compile`].
pub const COMPILE_CPE: Option<usize> = None;

/// Expressions compiled for fast repeated numeric evaluation (see [`Registry::compile`]).
pub struct Compiled {
    ev: symbolica::evaluate::ExpressionEvaluator<f64>,
    outputs: usize,
}

impl Compiled {
    /// Number of results.
    pub fn outputs(&self) -> usize {
        self.outputs
    }

    /// Evaluates every expression at `point` (one value per registry variable) into `out`.
    pub fn evaluate(&mut self, point: &[f64], out: &mut [f64]) {
        self.ev.evaluate(point, out);
    }
}

impl fmt::Debug for Compiled {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Compiled({} outputs)", self.outputs)
    }
}

/// An exact scalar expression in canonical form, tied to the [`Registry`] of its mechanism.
///
/// Arithmetic keeps the canonical form: after every product, sin²qᵢ is replaced by
/// 1 − cos²qᵢ. Equality is structural equality of canonical forms, hence exact.
#[derive(Clone)]
pub struct Expr {
    p: Poly,
    reg: Rc<Registry>,
}

impl fmt::Debug for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Expr({self})")
    }
}

impl PartialEq for Expr {
    fn eq(&self, other: &Expr) -> bool {
        Rc::ptr_eq(&self.reg, &other.reg) && self.p == other.p
    }
}

impl Eq for Expr {}

impl Expr {
    /// The registry this expression belongs to.
    pub fn registry(&self) -> &Rc<Registry> {
        &self.reg
    }

    /// 0 in the same registry.
    pub fn zero_like(&self) -> Expr {
        self.reg.zero()
    }

    /// Exact zero test (the canonical form is unique).
    pub fn is_zero(&self) -> bool {
        self.p.is_zero()
    }

    /// Number of terms of the canonical form.
    pub fn nterms(&self) -> usize {
        self.p.nterms()
    }

    /// Whether the expression depends on no coordinate (a constant in time).
    pub fn is_time_independent(&self) -> bool {
        (0..self.reg.nvars()).all(|i| match self.reg.roles[i] {
            VarRole::Parameter(_) => true,
            VarRole::Cos(q) | VarRole::Sin(q) | VarRole::Value(q)
                if self.reg.coords[q.0].is_fixed() =>
            {
                true
            }
            _ => self.p.degree(i) == 0,
        })
    }

    /// The variable index if the expression is exactly one variable (coefficient 1).
    pub fn single_variable(&self) -> Option<usize> {
        if self.p.nterms() != 1 || !self.p.coefficients[0].is_one() {
            return None;
        }
        let e = self.p.exponents(0);
        let nz: Vec<usize> = (0..e.len()).filter(|&i| e[i] != 0).collect();
        match nz.as_slice() {
            [i] if e[*i] == 1 => Some(*i),
            _ => None,
        }
    }

    /// The largest degree of any variable.
    pub fn max_degree(&self) -> u32 {
        (0..self.reg.nvars())
            .map(|i| self.p.degree(i) as u32)
            .max()
            .unwrap_or(0)
    }

    /// Whether `self * other` keeps every degree within [`MAX_INPUT_DEGREE`].
    pub(crate) fn product_fits(&self, other: &Expr, times: u32) -> bool {
        (0..self.reg.nvars()).all(|i| {
            let d = self.p.degree(i) as u32 * times + other.p.degree(i) as u32;
            d <= MAX_INPUT_DEGREE
        })
    }

    /// Whether the variable `i` occurs.
    pub(crate) fn contains_var(&self, i: usize) -> bool {
        self.p.degree(i) > 0
    }

    /// Brings a product back to canonical form: sin²q → 1 − cos²q for every angle.
    fn reduce(mut p: Poly, reg: &Registry) -> Poly {
        for c in &reg.coords {
            let Some((ci, si)) = c.trig else { continue };
            while p.degree(si) >= 2 {
                let n = p.nvars();
                let mut low = p.zero();
                let mut high = p.zero();
                for t in 0..p.nterms() {
                    let e = p.exponents(t);
                    if e[si] >= 2 {
                        high.coefficients.push(p.coefficients[t].clone());
                        high.exponents.extend_from_slice(e);
                        let k = high.exponents.len() - n + si;
                        high.exponents[k] -= 2;
                    } else {
                        low.coefficients.push(p.coefficients[t].clone());
                        low.exponents.extend_from_slice(e);
                    }
                }
                // Dividing every term by sin² keeps the lex order of the subsequence.
                let mut cos2 = vec![0u8; n];
                cos2[ci] = 2;
                let minus_cos2 = high.clone().mul_monomial(&Rational::new(-1, 1), &cos2);
                p = low + high + minus_cos2;
            }
        }
        p
    }

    fn with(&self, p: Poly) -> Expr {
        Expr {
            p,
            reg: self.reg.clone(),
        }
    }

    /// self^n.
    pub fn pow(&self, n: u32) -> Expr {
        let mut r = self.reg.one();
        for _ in 0..n {
            r = &r * self;
        }
        r
    }

    /// Total time derivative d/dt = Σ ∂/∂qᵢ q̇ᵢ + ∂/∂q̇ᵢ q̈ᵢ + ∂/∂q̈ᵢ q⃛ᵢ, with
    /// d(cos q)/dt = −sin q q̇ and d(sin q)/dt = cos q q̇.
    pub fn dt(&self) -> Expr {
        let reg = &self.reg;
        let mut acc = self.p.zero();
        for (i, c) in reg.coords.iter().enumerate() {
            if c.constant {
                continue;
            }
            let q = CoordId(i);
            let qdot = reg.rate(q, 1).p;
            if let Some((ci, si)) = c.trig {
                if self.p.degree(ci) > 0 {
                    let d = self.p.derivative(ci);
                    acc = &acc - &(&(&d * &reg.sin(q).p) * &qdot);
                }
                if self.p.degree(si) > 0 {
                    let d = self.p.derivative(si);
                    acc = &acc + &(&(&d * &reg.cos(q).p) * &qdot);
                }
            }
            if let Some(vi) = c.value
                && self.p.degree(vi) > 0
            {
                acc = &acc + &(&self.p.derivative(vi) * &qdot);
            }
            if let Some(r) = c.rates {
                for k in 0..2 {
                    if self.p.degree(r[k]) > 0 {
                        let next = reg.var(r[k + 1]).p;
                        acc = &acc + &(&self.p.derivative(r[k]) * &next);
                    }
                }
            }
        }
        self.with(Expr::reduce(acc, reg))
    }

    /// Substitutes a variable by an expression (used by hypotheses: a product of inertia set
    /// to zero, two moments set equal, q̈ set to zero). Stays canonical when the value has no
    /// sine (which is the case of every hypothesis).
    pub fn substitute(&self, var: usize, value: &Expr) -> Expr {
        if self.p.degree(var) == 0 {
            return self.clone();
        }
        let p = self.p.replace_with_poly(var, &value.p);
        self.with(Expr::reduce(p, &self.reg))
    }

    /// The terms that contain a rate (q̇, q̈, …), and the others: `e = with + without`.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into(), "g".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let e = reg.parse("m*ddot(q) + m*g*sin(q)").unwrap();
    /// let (with, without) = e.split_by_rates();
    /// assert_eq!(with, reg.parse("m*ddot(q)").unwrap());
    /// assert_eq!(without, reg.parse("m*g*sin(q)").unwrap());
    /// ```
    pub fn split_by_rates(&self) -> (Expr, Expr) {
        let reg = self.registry();
        let rate = |i: usize| matches!(reg.role(i), VarRole::Rate(..));
        let (mut with, mut without) = (Vec::new(), Vec::new());
        for (c, e) in self.terms() {
            let t = (c.clone(), e.to_vec());
            if e.iter().enumerate().any(|(i, &k)| k > 0 && rate(i)) {
                with.push(t);
            } else {
                without.push(t);
            }
        }
        (Expr::from_terms(reg, with), Expr::from_terms(reg, without))
    }

    /// Terms of the canonical form: (numerator, denominator, exponent per variable).
    pub(crate) fn terms(&self) -> impl Iterator<Item = (&Rational, &[u8])> {
        (0..self.p.nterms()).map(move |t| (&self.p.coefficients[t], self.p.exponents(t)))
    }

    /// Builds an expression from terms (any order; like terms are combined).
    pub(crate) fn from_terms(reg: &Rc<Registry>, terms: Vec<(Rational, Vec<u8>)>) -> Expr {
        if terms.is_empty() {
            // No term: symbolica's list constructor is not asked to size an empty list.
            return reg.zero();
        }
        let mut coefficients = Vec::with_capacity(terms.len());
        let mut exponents = Vec::with_capacity(terms.len() * reg.nvars());
        for (c, e) in terms {
            coefficients.push(c);
            exponents.extend_from_slice(&e);
        }
        // Sorts and combines like terms in one pass.
        let p = Poly::from_coefficient_list(coefficients, exponents, reg.vars.clone(), &Q);
        reg.wrap(p)
    }

    /// The symbolica expression (for the compiled evaluator and interoperability).
    pub fn to_atom(&self) -> Atom {
        self.p.to_expression()
    }

    /// Whether the expression is exactly 1.
    pub fn is_one(&self) -> bool {
        self.p.is_one()
    }

    /// Partial derivative with respect to polynomial variable `i`, every other variable held
    /// fixed (the coefficient of an unknown that enters linearly).
    pub fn derivative(&self, i: usize) -> Expr {
        if self.p.degree(i) == 0 {
            return self.zero_like();
        }
        self.with(self.p.derivative(i))
    }

    /// Partial derivative ∂/∂q with respect to a coordinate's value, its rates held fixed:
    /// through cos q and sin q for an angle (∂cos q/∂q = −sin q, ∂sin q/∂q = cos q), and q
    /// itself where it enters as itself.
    pub fn partial_coordinate(&self, q: CoordId) -> Expr {
        let reg = &self.reg;
        let c = &reg.coords[q.0];
        let mut acc = self.zero_like();
        if let Some((ci, si)) = c.trig {
            if self.p.degree(ci) > 0 {
                acc = &acc - &(&self.derivative(ci) * &reg.sin(q));
            }
            if self.p.degree(si) > 0 {
                acc = &acc + &(&self.derivative(si) * &reg.cos(q));
            }
        }
        if let Some(vi) = c.value {
            acc = &acc + &self.derivative(vi);
        }
        acc
    }

    /// Partial derivative with respect to q̇ (order 1), q̈ (order 2) of a coordinate; zero for
    /// a coordinate whose rate is imposed (it has no rate variables).
    pub fn partial_rate(&self, q: CoordId, order: u8) -> Expr {
        match self.reg.coords[q.0].rates {
            Some(r) => self.derivative(r[order as usize - 1]),
            None => self.zero_like(),
        }
    }
}

macro_rules! binop {
    ($trait:ident, $method:ident, $op:tt, $reduce:expr) => {
        impl $trait<&Expr> for &Expr {
            type Output = Expr;
            fn $method(self, rhs: &Expr) -> Expr {
                debug_assert!(Rc::ptr_eq(&self.reg, &rhs.reg), "expressions of two registries");
                let p = &self.p $op &rhs.p;
                let p = if $reduce { Expr::reduce(p, &self.reg) } else { p };
                self.with(p)
            }
        }
        impl $trait<&Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: &Expr) -> Expr {
                (&self).$method(rhs)
            }
        }
        impl $trait<Expr> for Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                (&self).$method(&rhs)
            }
        }
        impl $trait<Expr> for &Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                self.$method(&rhs)
            }
        }
    };
}

binop!(Add, add, +, false);
binop!(Sub, sub, -, false);
binop!(Mul, mul, *, true);

impl Neg for &Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        self.with(-self.p.clone())
    }
}

impl Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        -&self
    }
}

impl fmt::Display for Expr {
    /// Plain text in the spec syntax (parsable back), terms in a stable order.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&print::to_text(self))
    }
}

#[cfg(test)]
mod tests;
