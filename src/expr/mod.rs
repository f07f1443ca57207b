//! Exact expressions: the only module that sees symbolica.
//!
//! Every quantity of rigid-body kinematics and dynamics is a polynomial in cos qᵢ, sin qᵢ (angle
//! coordinates, and constant angle parameters), qᵢ (length coordinates, and the angles a spec
//! writes as themselves), q̇ᵢ, q̈ᵢ and the parameters, with rational coefficients. [`Expr`] stores exactly that, as a symbolica `MultivariatePolynomial` over ℚ
//! whose variables are fixed once per mechanism by a [`Registry`], and keeps it in the
//! **canonical form** of DESIGN.md: expanded, with every sin²qᵢ replaced by 1 − cos²qᵢ. Two
//! expressions are equal as functions iff their canonical forms are identical, so the zero
//! test is exact and costs nothing.

pub mod budget;
mod builder;
mod carry;
mod compile;
mod eval;
mod factor;
mod flat;
mod fourier;
mod fraction;
mod guard;
mod lexical;
mod names;
mod number_text;
mod parse;
pub(crate) mod present;
pub(crate) mod print;
mod rates;
mod reduce;
mod registry;
mod roots;
mod time;
mod vector_text;
mod words;

pub use builder::RegistryBuilder;
pub use flat::FlatEval;
pub use fourier::Fourier;
pub use fraction::Fraction;
pub(crate) use lexical::function_hint;
pub use names::{bare_names, divisors_in};
pub use number_text::evaluate_number;
pub(crate) use present::num_den;
pub use present::{
    Angle, Cost, Factor, Form, Leaf, Presentation, Product, SEARCH_LIMIT, signed_sum,
};
pub use registry::{
    MAX_EXPANDED_TERMS, MAX_INPUT_DEGREE, MAX_INPUT_LEN, MAX_SPEC_DEGREE, Registry,
};
pub use roots::RootId;
pub(crate) use roots::RootText;
pub use time::pulsations_in;
pub use words::{PI, RESERVED, char_hint, reserved_word, validate_identifier};

use crate::excerpt::{bounded, excerpt};
use std::collections::HashMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::rc::Rc;
use std::sync::Arc;
use symbolica::atom::{Atom, AtomCore, Symbol};
use symbolica::domains::rational::{Q, Rational, RationalField};
use symbolica::poly::PolyVariable;
use symbolica::poly::polynomial::MultivariatePolynomial;

/// Kind of a time coordinate.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize, schemars::JsonSchema,
)]
#[serde(rename_all = "lowercase")]
pub enum CoordinateKind {
    /// Enters through cos q and sin q, and as itself where an expression of the spec writes
    /// it so (a disc's centre at `R*theta*x1`).
    Angle,
    /// Enters polynomially.
    Length,
}

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

/// Typed index of a parameter of a [`Registry`], or beyond the parameters of an unknown of
/// the PFD (see [`Registry::param_id`]).
///
/// ```
/// use torseur::expr::{Registry, VarRole};
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::builder().parameters(&["m".into()]).unknowns(&["C_m".into()]).build().unwrap();
/// let cm = reg.param_id("C_m").unwrap();
/// assert!(reg.is_unknown(cm) && !reg.is_unknown(reg.param_id("m").unwrap()));
/// assert_eq!(reg.scalar_name(cm), "C_m");
/// let v = reg.index_of(VarRole::Parameter(cm)).unwrap();
/// assert_eq!(reg.variable(v), reg.parse("C_m").unwrap());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ParamId(pub(crate) usize);

impl ParamId {
    /// Index among the parameters, then the unknowns.
    pub fn index(self) -> usize {
        self.0
    }
}

/// Typed index of a polynomial variable of a [`Registry`]: a parameter or an unknown, cos q or
/// sin q, q itself, a rate (see [`Registry::role`]).
///
/// ```
/// use torseur::expr::{Registry, VarRole};
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::new(&["m".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
/// let q = reg.coord("q").unwrap();
/// let qdd = reg.index_of(VarRole::Rate(q, 2)).unwrap();
/// assert_eq!(reg.role(qdd), VarRole::Rate(q, 2));
/// // The coefficient of q̈ in m q̈ + m sin q: the partial derivative in that variable.
/// let e = reg.parse("m*ddot(q) + m*sin(q)").unwrap();
/// assert_eq!(e.derivative(qdd), reg.parse("m").unwrap());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct VarId(pub(crate) usize);

impl VarId {
    /// Index among the registry's variables.
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
        "unknown name `{}` in `{}` ({})",
        excerpt(.name),
        excerpt(.input),
        match .hint.as_str() {
            "" => "declare it as a parameter or a coordinate",
            h => h,
        }
    )]
    UnknownName {
        /// The name.
        name: String,
        /// The text given.
        input: String,
        /// `did you mean `theta1`?` when a declared name is close (the crate's `hint`), else
        /// empty.
        hint: String,
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
    /// An expression outgrew the budget of terms (see [`budget`]).
    #[error(
        "{what} grew past {} terms ({detail}); --max-terms raises this budget if memory \
         allows",
        budget::grouped(.limit)
    )]
    Budget {
        /// What grew: `an expression`, or the derivation it belongs to
        /// (`the derivation of eom(theta12)`).
        what: String,
        /// How: `its expressions held 5,000,012 terms at once, the last one built 73,692`,
        /// `a product of 68,140 by 90 terms, would form 6,132,600 terms before like terms
        /// combine`.
        detail: String,
        /// The terms held, or for a product refused before it was formed, the terms it would
        /// form.
        terms: u128,
        /// The budget ([`budget::max_terms`]).
        limit: usize,
    },
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
    /// A phase Ω t (named `Omega*t`): the pulsation Ω, a parameter, is its imposed rate.
    phase: Option<String>,
    /// The imposed rate is a linear form of other coordinates' rates (a gear ratio, rolling
    /// without slipping): q̈ is its time derivative, not 0.
    driven: bool,
    /// A driven rate whose coefficients hold coordinates (ẋ = R θ̇ cos ψ).
    nonholonomic: bool,
    /// cos²q is reduced to 1 − sin²q instead of sin²q to 1 − cos²q: a loop closure divides
    /// by sin q (see [`RegistryBuilder::cosecants`]).
    cos_reduced: bool,
}

impl CoordInfo {
    /// The polynomial variable holding q itself, if the coordinate has one (a length, or an
    /// angle that enters as itself).
    pub fn value_var(&self) -> Option<VarId> {
        self.value.map(VarId)
    }

    /// Whether the rate is imposed: a constant (q̇ = ω, q̈ = 0), or driven by the rates of
    /// other coordinates (see [`CoordInfo::is_driven`]); the coordinate then has no rate
    /// variables and no equation of motion.
    pub fn has_imposed_rate(&self) -> bool {
        self.imposed_rate.is_some()
    }

    /// Whether the rate is driven by other coordinates' rates, a relation between
    /// coordinates that the spec declares as `"rate": "-r1/r2*dot(theta1)"` (a gear ratio,
    /// rolling without slipping ẋ = −R θ̇, or on a plane ẋ = R θ̇ cos ψ): q̇ is that form,
    /// linear in the free rates, q̈ its time derivative.
    pub fn is_driven(&self) -> bool {
        self.driven
    }

    /// Whether the driven rate's coefficients are constant (the relation integrates to one
    /// between the coordinates, θ2 = −(r1/r2) θ1 + c): Lagrange's equations of the free
    /// coordinates then follow it. A coefficient that holds a coordinate (ẋ = R θ̇ cos ψ, a
    /// disc rolling on a plane) is a nonholonomic constraint.
    pub fn is_holonomic(&self) -> bool {
        !self.nonholonomic
    }

    /// The pulsation Ω when this is the phase Ω t of a forcing or an imposed law written
    /// with the time (`cos(Omega*t)`); its name is then `Omega*t`.
    pub fn phase(&self) -> Option<&str> {
        self.phase.as_deref()
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
    Parameter(ParamId),
    /// cos q of an angle coordinate (or of a constant angle parameter).
    Cos(CoordId),
    /// sin q of an angle coordinate (or of a constant angle parameter).
    Sin(CoordId),
    /// q itself, for a length coordinate (or an angle that enters as itself).
    Value(CoordId),
    /// q̇ (order 1), q̈ (order 2), third derivative (order 3).
    Rate(CoordId, u8),
    /// 1/p of a parameter the mechanism divides by (see [`RegistryBuilder::inverses`]):
    /// p·(1/p) is reduced to 1 after every product, as sin² is.
    Inverse(ParamId),
    /// 1/cos q or 1/sin q of an angle coordinate a loop closure divides by (see
    /// [`RegistryBuilder::secants`], [`RegistryBuilder::cosecants`]): cos q·(1/cos q), or
    /// sin q·(1/sin q), is reduced to 1 after every product.
    Reciprocal(CoordId, Trig),
    /// A square root of a declared radicand (see [`RegistryBuilder::roots`]): s² is reduced
    /// to its radicand after every product, as sin² is.
    Root(RootId),
}

/// Which trigonometric function of an angle: the cos or the sin.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Trig {
    /// cos q.
    Cos,
    /// sin q.
    Sin,
}

impl Trig {
    /// `cos` or `sin`, as the syntax writes it.
    pub fn name(self) -> &'static str {
        match self {
            Trig::Cos => "cos",
            Trig::Sin => "sin",
        }
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
pub struct Expr {
    p: Poly,
    reg: Rc<Registry>,
}

impl Clone for Expr {
    fn clone(&self) -> Expr {
        self.with(self.p.clone())
    }
}

impl Drop for Expr {
    /// Its terms are no longer held (see [`budget`]).
    #[inline]
    fn drop(&mut self) {
        budget::freed(self.p.nterms());
    }
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
            VarRole::Parameter(_) | VarRole::Inverse(_) => true,
            VarRole::Cos(q) | VarRole::Sin(q) | VarRole::Value(q) | VarRole::Reciprocal(q, _)
                if self.reg.coords[q.0].is_fixed() =>
            {
                true
            }
            _ => self.p.degree(i) == 0,
        })
    }

    /// The variable index if the expression is exactly one variable (coefficient 1).
    pub fn single_variable(&self) -> Option<VarId> {
        if self.p.nterms() != 1 || !self.p.coefficients[0].is_one() {
            return None;
        }
        let e = self.p.exponents(0);
        let nz: Vec<usize> = (0..e.len()).filter(|&i| e[i] != 0).collect();
        match nz.as_slice() {
            [i] if e[*i] == 1 => Some(VarId(*i)),
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

    /// An upper bound on the terms of `self^n` before like terms combine: the fewer of the
    /// multinomial count C(n + k − 1, k − 1) for k terms, and the monomials the degrees allow.
    pub(crate) fn power_terms_bound(&self, n: u32) -> u128 {
        let k = self.nterms() as u128;
        if n == 0 || k <= 1 {
            return 1;
        }
        // C(n + k − 1, n), stopped once past the bound.
        let mut multinomial: u128 = 1;
        for i in 1..=n as u128 {
            multinomial = multinomial * (k - 1 + i) / i;
            if multinomial > MAX_EXPANDED_TERMS {
                break;
            }
        }
        let mut monomials: u128 = 1;
        for i in 0..self.reg.nvars() {
            monomials = monomials.saturating_mul(self.p.degree(i) as u128 * n as u128 + 1);
        }
        multinomial.min(monomials)
    }

    /// The machine words of the largest coefficient (numerator and denominator together, at
    /// least 1): what one product of two of its terms costs, in units of a small one.
    pub(crate) fn coefficient_words(&self) -> u128 {
        let digits = self
            .p
            .coefficients
            .iter()
            .map(|c| c.to_string().len())
            .max()
            .unwrap_or(1);
        // 19 decimal digits fill a 64-bit word.
        1 + digits as u128 / 19
    }

    /// Whether each variable occurs, read in one pass over the terms (asking per variable
    /// reads every term once per variable).
    pub(crate) fn occurring(&self) -> Vec<bool> {
        let mut seen = vec![false; self.reg.nvars()];
        for (_, e) in self.terms() {
            for (s, &k) in seen.iter_mut().zip(e) {
                *s |= k > 0;
            }
        }
        seen
    }

    /// Whether the variable `i` occurs.
    pub(crate) fn contains_var(&self, i: VarId) -> bool {
        self.p.degree(i.0) > 0
    }

    /// The polynomial, whose terms this expression no longer holds (see [`budget`]).
    fn into_poly(mut self) -> Poly {
        let zero = self.p.zero();
        let p = std::mem::replace(&mut self.p, zero);
        budget::freed(p.nterms());
        p
    }

    fn with(&self, p: Poly) -> Expr {
        budget::built(&p);
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
    ///
    /// A square root of a constant radicand is constant. One whose radicand moves has the
    /// derivative Ṗ/(2√P), which is no polynomial: such a root is compared and printed, never
    /// differentiated. No input reaches one here: a spec's own texts may not write a root
    /// (`Registry::refuse_roots_in_texts`, exit 2), the roots are the explicit loop laws',
    /// which are printed and verified only, and a relation typed to `verify` is compared, not
    /// differentiated (its `d/dt(Q)` are the engine's quantities). The assertion guards that.
    pub fn dt(&self) -> Expr {
        let reg = &self.reg;
        for r in self.roots_held() {
            assert!(
                reg.radicand(r).is_time_independent(),
                "the time derivative of sqrt({}) is not a polynomial",
                reg.radicand(r)
            );
        }
        let mut acc = self.p.zero();
        for (i, c) in reg.coords.iter().enumerate() {
            if c.constant {
                continue;
            }
            let q = CoordId(i);
            let qdot = reg.rate(q, 1).into_poly();
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
            // d(1/cos q)/dt = (1/cos q)² sin q q̇, d(1/sin q)/dt = −(1/sin q)² cos q q̇.
            for (w, d) in reg.reciprocal_derivatives(q) {
                if self.p.degree(w) > 0 {
                    acc = &acc + &(&(&self.p.derivative(w) * &d.p) * &qdot);
                }
            }
            if let Some(r) = c.rates {
                for k in 0..2 {
                    if self.p.degree(r[k]) > 0 {
                        let next = reg.var(r[k + 1]).into_poly();
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
    pub fn substitute(&self, var: VarId, value: &Expr) -> Expr {
        if self.p.degree(var.0) == 0 {
            return self.clone();
        }
        let p = self.p.replace_with_poly(var.0, &value.p);
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
        let rate = |i: usize| matches!(reg.role(VarId(i)), VarRole::Rate(..));
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

    /// Whether every term has a negative coefficient (−(J/R + m R) ẍ), so that the
    /// expression reads better negated on the other side of an equation.
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::new(&["m".into(), "R".into()], &[]).unwrap();
    /// assert!(reg.parse("-m - 2*R").unwrap().reads_negative());
    /// assert!(!reg.parse("m - 2*R").unwrap().reads_negative());
    /// assert!(!reg.zero().reads_negative());
    /// ```
    pub fn reads_negative(&self) -> bool {
        !self.is_zero() && self.terms().all(|(c, _)| c.is_negative())
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
    pub fn derivative(&self, i: VarId) -> Expr {
        if self.p.degree(i.0) == 0 {
            return self.zero_like();
        }
        self.with(self.p.derivative(i.0))
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
                acc = &acc - &(&self.derivative(VarId(ci)) * &reg.sin(q));
            }
            if self.p.degree(si) > 0 {
                acc = &acc + &(&self.derivative(VarId(si)) * &reg.cos(q));
            }
        }
        if let Some(vi) = c.value {
            acc = &acc + &self.derivative(VarId(vi));
        }
        for (w, d) in reg.reciprocal_derivatives(q) {
            if self.p.degree(w) > 0 {
                acc = &acc + &(&self.derivative(VarId(w)) * &d);
            }
        }
        acc
    }

    /// Partial derivative with respect to q̇ (order 1), q̈ (order 2) of a coordinate; zero for
    /// a coordinate whose rate is imposed (it has no rate variables).
    pub fn partial_rate(&self, q: CoordId, order: u8) -> Expr {
        match self.reg.coords[q.0].rates {
            Some(r) => self.derivative(VarId(r[order as usize - 1])),
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
                if $reduce {
                    budget::product([(self.p.nterms(), rhs.p.nterms())]);
                }
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
mod root_tests;
#[cfg(test)]
mod tests;
