//! Units and homogeneity: the dimension of every variable of a mechanism, read from the spec's
//! parameter units, and the check that every term of a result has its quantity's dimension.
//!
//! A [`Dimension`] is a product Mᵃ Lᵇ Tᶜ of mass, length and time. **The radian is
//! dimensionless**, as in SI and in the course: Ω(2/0) = θ̇1 z0 is in rad/s, and a velocity
//! Ω ∧ r must add to a slider's ẋ, so an angle cannot carry a base dimension of its own. A
//! friction coefficient f in N·m·s/rad times θ̇ in rad/s is then a moment in N·m, and a torsion
//! stiffness in N·m/rad times an angle is N·m. The angle comes back only when a dimension is
//! printed: [`UnitStyle::Angle`] writes a pure number as rad.
//!
//! Where dimensions come from ([`Dimensions::of`]):
//! - a parameter: its `unit` in the spec ([`Dimension::parse`]); a constant angle (`"kind":
//!   "angle"`) is dimensionless. **A parameter without a unit has an unknown dimension**: the
//!   terms that contain it are skipped by [`dimension`], so they never make a check fail (nor
//!   can they make it pass: they are not checked at all);
//! - a coordinate q: an angle is dimensionless, a length is L; cos q and sin q are
//!   dimensionless; q̇ is q/T, q̈ q/T², the third derivative q/T³;
//! - an unknown of the PFD: each action it appears in gives it one; a component of a
//!   resultant is a force (M L T⁻²), of a moment a moment (M L² T⁻²), so X01 is in N, L01 in
//!   N·m, and `C_m` in `C_m*z0` given as a moment is in N·m (the unknown's coefficient there
//!   divides the action's dimension).
//!
//! ```
//! use torseur::units::{dimension, Dimension, Dimensions, UnitStyle};
//! let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
//! let dims = Dimensions::of(&m);
//! // m2 L2² θ̈2 is a moment.
//! let e = m.reg().parse("m2*L2^2*ddot(theta2) + A2*ddot(theta2)")?;
//! let d = dimension(&e, &dims)?.unwrap();
//! assert_eq!(d, Dimension::MOMENT);
//! assert_eq!(d.si_text(UnitStyle::Mechanics), "N·m");
//! // A mass plus a length is refused, naming both terms.
//! let wrong = m.reg().parse("m2 + L2")?;
//! let err = dimension(&wrong, &dims).unwrap_err();
//! assert!(err.to_string().contains("`m2`") && err.to_string().contains("`L2`"), "{err}");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod dimension;

pub use dimension::{Dimension, UnitError, UnitStyle};

use crate::derivation::{Derivation, StepKind, Value};
use crate::expr::{CoordId, Expr, Registry, VarId, VarRole};
use crate::mechanism::Mechanism;
use crate::quantity::{Quantity, QuantityKind};
use crate::wire::{CoordinateKind, ParameterKind, TheoremKind};
use dimension::unit_or_one;
use std::rc::Rc;

/// The style a quantity's unit is written in: an energy in J, every other quantity in the
/// units of mechanics.
///
/// ```
/// use torseur::units::{unit_style, UnitStyle};
/// use torseur::quantity::Quantity;
/// assert_eq!(unit_style(&Quantity::parse("Ec(E/0)").unwrap().kind), UnitStyle::Energy);
/// assert_eq!(unit_style(&Quantity::parse("delta(O,1/0).z0").unwrap().kind), UnitStyle::Mechanics);
/// ```
pub fn unit_style(kind: &QuantityKind) -> UnitStyle {
    match kind {
        QuantityKind::KineticEnergy(_)
        | QuantityKind::Power { .. }
        | QuantityKind::InternalPower(_) => UnitStyle::Energy,
        _ => UnitStyle::Mechanics,
    }
}

/// Terms of two dimensions in one expression.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "the terms `{first}` ({first_dimension}, {}) and `{second}` ({second_dimension}, {}) have \
     different dimensions",
    unit_or_one(first_dimension),
    unit_or_one(second_dimension)
)]
pub struct Inhomogeneous {
    /// A term, in the plain-text syntax.
    pub first: String,
    /// Its dimension.
    pub first_dimension: Dimension,
    /// A term of another dimension.
    pub second: String,
    /// Its dimension.
    pub second_dimension: Dimension,
}

/// The dimension of every variable of a registry: parameters and unknowns (when known),
/// coordinates and their rates, cos and sin.
///
/// ```
/// use torseur::units::{Dimension, Dimensions};
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json")?;
/// let d = Dimensions::of(&m);
/// assert_eq!(d.scalar("F"), Some(Dimension::FORCE));
/// assert_eq!(d.scalar("X12"), Some(Dimension::FORCE));
/// assert_eq!(d.coordinate(m.reg().coord("x").unwrap()), Dimension::LENGTH);
/// assert_eq!(d.coordinate(m.reg().coord("theta").unwrap()), Dimension::NONE);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone)]
pub struct Dimensions {
    reg: Rc<Registry>,
    vars: Vec<Option<Dimension>>,
}

impl Dimensions {
    /// The dimensions a registry fixes by itself: coordinates (an angle is a pure number, a
    /// length L), their rates (q/Tⁿ), cos and sin (pure numbers) and the constant angle
    /// parameters; every other parameter and unknown is unknown until [`Dimensions::set`].
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// use torseur::units::{dimension, Dimension, Dimensions};
    /// let reg = Registry::new(&["k".into(), "m".into()], &[("x".into(), CoordinateKind::Length)]).unwrap();
    /// let mut d = Dimensions::new(&reg);
    /// let e = reg.parse("m*ddot(x) + k*x").unwrap();
    /// // k and m are unknown: no term is checked.
    /// assert_eq!(dimension(&e, &d).unwrap(), None);
    /// d.set("m", Some(Dimension::MASS));
    /// // m ẍ is a force; k x is still skipped.
    /// assert_eq!(dimension(&e, &d).unwrap(), Some(Dimension::FORCE));
    /// d.set("k", Some(Dimension::parse("N/m").unwrap()));
    /// assert_eq!(dimension(&e, &d).unwrap(), Some(Dimension::FORCE));
    /// d.set("k", Some(Dimension::parse("N").unwrap()));
    /// assert!(dimension(&e, &d).is_err());
    /// ```
    pub fn new(reg: &Rc<Registry>) -> Dimensions {
        let coordinate = |q: CoordId| match reg.coord_info(q).kind {
            CoordinateKind::Angle => Dimension::NONE,
            CoordinateKind::Length => Dimension::LENGTH,
        };
        let vars = reg
            .var_ids()
            .map(|i| match reg.role(i) {
                // π is a pure number.
                VarRole::Parameter(k) | VarRole::Inverse(k) if reg.is_pi(k) => {
                    Some(Dimension::NONE)
                }
                VarRole::Parameter(k) | VarRole::Inverse(k) => {
                    let is_angle = !reg.is_unknown(k)
                        && reg
                            .angle(reg.scalar_name(k))
                            .is_some_and(|q| reg.coord_info(q).is_constant());
                    is_angle.then_some(Dimension::NONE)
                }
                VarRole::Cos(_) | VarRole::Sin(_) | VarRole::Reciprocal(..) => {
                    Some(Dimension::NONE)
                }
                VarRole::Value(q) => Some(coordinate(q)),
                // The half of its radicand's, which the parameters' units give (see `set`).
                VarRole::Root(_) => None,
                VarRole::Rate(q, order) => {
                    Some(coordinate(q) / Dimension::TIME.pow(i32::from(order)))
                }
            })
            .collect();
        Dimensions {
            reg: reg.clone(),
            vars,
        }
    }

    /// The dimensions of a mechanism: [`Dimensions::new`], each parameter's from its `unit`
    /// (a constant angle is a pure number whatever its unit says; a unit that does not parse,
    /// which loading refuses, is unknown), and each unknown of the PFD's from the actions it
    /// appears in (a resultant component is a force, a moment component a moment, divided by
    /// the dimension of the unknown's coefficient there). An unknown whose coefficient has
    /// an unknown dimension stays unknown.
    pub fn of(m: &Mechanism) -> Dimensions {
        let mut d = Dimensions::new(&m.reg);
        for p in &m.spec.parameters {
            let dim = match (p.kind, &p.unit) {
                (ParameterKind::Angle, _) => Some(Dimension::NONE),
                (ParameterKind::Scalar, Some(u)) => Dimension::parse(u).ok(),
                (ParameterKind::Scalar, None) => None,
            };
            d.set(&p.name, dim);
        }
        // The sign ε of a link's relative rate under dry friction is a pure number.
        for dry in &m.dynamics.dry {
            d.set(&dry.sign, Some(Dimension::NONE));
        }
        let unknowns: Vec<(VarId, String)> = crate::pfd::unknown_vars(m)
            .into_iter()
            .map(|(n, v)| (v, n))
            .collect();
        let mut found: Vec<Option<Dimension>> = vec![None; unknowns.len()];
        for a in &m.dynamics.actions {
            for (vector, dim) in [
                (&a.resultant, Dimension::FORCE),
                (&a.moment, Dimension::MOMENT),
            ] {
                for c in vector.express_in(&m.frames, a.basis) {
                    for (k, (v, _)) in unknowns.iter().enumerate() {
                        if found[k].is_some() {
                            continue;
                        }
                        let coefficient = c.derivative(*v);
                        if coefficient.is_zero() {
                            continue;
                        }
                        if let Ok(Some(dc)) = dimension(&coefficient, &d) {
                            found[k] = Some(dim / dc);
                        }
                    }
                }
            }
        }
        for ((_, n), dim) in unknowns.iter().zip(found) {
            d.set(n, dim);
        }
        // A trial's unknown X of q = X cos(Ω t): q's dimension over its coefficient's.
        for t in m.hypotheses.iter().filter_map(|h| h.trial.as_ref()) {
            for (n, v) in &t.unknowns {
                let coefficient = t.motion.derivative(*v);
                let dim = match dimension(&coefficient, &d) {
                    Ok(Some(dc)) => Some(d.coordinate(t.coord) / dc),
                    _ => None,
                };
                d.set(n, dim);
            }
        }
        d
    }

    /// Sets the dimension of a parameter or unknown by name (`None`: unknown). Returns false
    /// when the registry has no such scalar.
    pub fn set(&mut self, name: &str, dimension: Option<Dimension>) -> bool {
        match self.scalar_var(name) {
            Some(i) => {
                self.vars[i.index()] = dimension;
                // 1/p, if the mechanism divides by p.
                if let VarRole::Parameter(p) = self.reg.role(i)
                    && let Some(j) = self.reg.index_of(VarRole::Inverse(p))
                {
                    self.vars[j.index()] = dimension.map(|d| Dimension::NONE / d);
                }
                self.fill_roots();
                true
            }
            None => false,
        }
    }

    /// Each square root's dimension: the half of its radicand's, when that is known and is a
    /// square (a radicand holds no root: one pass is enough).
    fn fill_roots(&mut self) {
        let reg = self.reg.clone();
        for r in reg.root_ids() {
            let Some(i) = reg.index_of(VarRole::Root(r)) else {
                continue;
            };
            let half = match dimension(&reg.radicand(r), self) {
                Ok(Some(d)) => d.sqrt(),
                _ => None,
            };
            self.vars[i.index()] = half;
        }
    }

    /// The dimension of the polynomial variable `i` (see [`Registry::role`]), if known.
    pub fn variable(&self, i: VarId) -> Option<Dimension> {
        self.vars.get(i.index()).copied().flatten()
    }

    /// The dimension of a parameter or unknown by name, if known.
    pub fn scalar(&self, name: &str) -> Option<Dimension> {
        self.scalar_var(name).and_then(|i| self.variable(i))
    }

    /// The dimension of a coordinate's value: a pure number for an angle, L for a length.
    pub fn coordinate(&self, q: CoordId) -> Dimension {
        match self.reg.coord_info(q).kind {
            CoordinateKind::Angle => Dimension::NONE,
            CoordinateKind::Length => Dimension::LENGTH,
        }
    }

    fn scalar_var(&self, name: &str) -> Option<VarId> {
        let k = self.reg.param_id(name)?;
        self.reg.index_of(VarRole::Parameter(k))
    }
}

/// The dimension of one term (its exponents), none if a factor's is unknown.
fn term_dimension(exponents: &[u8], dims: &Dimensions) -> Option<Dimension> {
    let mut acc = Dimension::NONE;
    for (i, &k) in exponents.iter().enumerate() {
        if k != 0 {
            acc = acc * dims.vars.get(i).copied().flatten()?.pow(i32::from(k));
        }
    }
    Some(acc)
}

/// The text of one term of `e`.
fn term_text(e: &Expr, term: usize) -> String {
    e.terms()
        .nth(term)
        .map(|(c, x)| Expr::from_terms(e.registry(), vec![(c.clone(), x.to_vec())]).to_string())
        .unwrap_or_default()
}

/// The common dimension of the terms of `e` whose dimension is known, with the index of the
/// first of them.
fn scan(e: &Expr, dims: &Dimensions) -> Result<Option<(Dimension, usize)>, Inhomogeneous> {
    let mut first: Option<(Dimension, usize)> = None;
    for (t, (_, x)) in e.terms().enumerate() {
        let Some(d) = term_dimension(x, dims) else {
            continue;
        };
        match first {
            None => first = Some((d, t)),
            Some((d0, _)) if d0 == d => {}
            Some((d0, t0)) => {
                return Err(Inhomogeneous {
                    first: term_text(e, t0),
                    first_dimension: d0,
                    second: term_text(e, t),
                    second_dimension: d,
                });
            }
        }
    }
    Ok(first)
}

/// The dimension of an expression: the common dimension of its terms (`None` for zero, or
/// when every term holds a variable of unknown dimension: those terms are skipped), or the
/// two terms that differ.
///
/// ```
/// use torseur::units::{dimension, Dimension, Dimensions};
/// let m = torseur::spec::load("derivations/systeme_masse_ressort.json")?;
/// let d = Dimensions::of(&m);
/// // k in N/m, c in N s/m, x a length: k (x - l0) + c ẋ is a force.
/// let e = m.reg().parse("k*(x - l0) + c*dot(x) + m*ddot(x)")?;
/// assert_eq!(dimension(&e, &d)?, Some(Dimension::FORCE));
/// assert_eq!(dimension(&m.reg().zero(), &d)?, None);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn dimension(e: &Expr, dims: &Dimensions) -> Result<Option<Dimension>, Inhomogeneous> {
    debug_assert!(
        Rc::ptr_eq(e.registry(), &dims.reg),
        "dimensions of another registry"
    );
    Ok(scan(e, dims)?.map(|(d, _)| d))
}

/// The dimension a quantity has whatever its value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExpectedDimension {
    /// A scalar, a vector or an inertia operator: every component has this dimension (`None`
    /// when it is unknown: an unknown of the PFD whose dimension nothing gives).
    Components(Option<Dimension>),
    /// A torsor: the dimensions of its resultant and of its moment.
    Torsor {
        /// Of the resultant's components.
        resultant: Dimension,
        /// Of the moment's components.
        moment: Dimension,
    },
}

impl ExpectedDimension {
    /// The dimension of the k-th expression of a value, in the order of [`Value::exprs`].
    pub fn component(&self, k: usize) -> Option<Dimension> {
        match *self {
            ExpectedDimension::Components(d) => d,
            ExpectedDimension::Torsor { resultant, moment } => {
                Some(if k < 3 { resultant } else { moment })
            }
        }
    }

    fn map(self, f: impl Fn(Dimension) -> Dimension) -> ExpectedDimension {
        match self {
            ExpectedDimension::Components(d) => ExpectedDimension::Components(d.map(f)),
            ExpectedDimension::Torsor { resultant, moment } => ExpectedDimension::Torsor {
                resultant: f(resultant),
                moment: f(moment),
            },
        }
    }
}

/// The dimension of a quantity from its kind alone: Ω T⁻¹, V L T⁻¹, Γ L T⁻², I M L²,
/// Rc M L T⁻¹, σ M L² T⁻¹, Rd and R(from→on) M L T⁻² (N), δ and M(A, from→on) M L² T⁻²
/// (N·m), Ec M L² T⁻² (J); a torsor its
/// resultant's and moment's; an unknown of the PFD its own ([`Dimensions::of`]); eom(q) that
/// of the theorem it comes from (a force for a resultant theorem, a moment for a moment
/// theorem). A projection or `lin(...)` keeps the dimension.
///
/// ```
/// use torseur::quantity::Quantity;
/// use torseur::units::{expected_dimension, Dimension, Dimensions, ExpectedDimension};
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json")?;
/// let d = Dimensions::of(&m);
/// let e = |q: &str| expected_dimension(&m, &d, &Quantity::parse(q).unwrap());
/// assert_eq!(e("V(G,2/0) in B0"), ExpectedDimension::Components(Some(Dimension::VELOCITY)));
/// assert_eq!(e("eom(x)"), ExpectedDimension::Components(Some(Dimension::FORCE)));
/// assert_eq!(e("eom(theta)"), ExpectedDimension::Components(Some(Dimension::MOMENT)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn expected_dimension(m: &Mechanism, dims: &Dimensions, q: &Quantity) -> ExpectedDimension {
    use ExpectedDimension::{Components, Torsor};
    use QuantityKind::*;
    let one = |d: Dimension| Components(Some(d));
    match &q.kind {
        Omega(_) => one(Dimension::ANGULAR_VELOCITY),
        Velocity { .. } => one(Dimension::VELOCITY),
        Acceleration { .. } => one(Dimension::ACCELERATION),
        Inertia { .. } => one(Dimension::INERTIA),
        KineticResultant(_) => one(Dimension::MOMENTUM),
        KineticMoment { .. } => one(Dimension::ANGULAR_MOMENTUM),
        DynamicResultant(_) => one(Dimension::FORCE),
        DynamicMoment { .. } | ActionMoment { .. } => one(Dimension::MOMENT),
        ActionResultant(_) => one(Dimension::FORCE),
        KineticEnergy(_) => one(Dimension::ENERGY),
        Power { .. } | InternalPower(_) => one(Dimension::POWER),
        EquivalentInertia(c) => one(match m.reg.coord(c).map(|q| m.reg.coord_info(q).kind) {
            Some(CoordinateKind::Length) => Dimension::MASS,
            _ => Dimension::INERTIA,
        }),
        KinematicTorsor { .. } => Torsor {
            resultant: Dimension::ANGULAR_VELOCITY,
            moment: Dimension::VELOCITY,
        },
        KineticTorsor { .. } => Torsor {
            resultant: Dimension::MOMENTUM,
            moment: Dimension::ANGULAR_MOMENTUM,
        },
        DynamicTorsor { .. } | ActionTorsor { .. } => Torsor {
            resultant: Dimension::FORCE,
            moment: Dimension::MOMENT,
        },
        Unknown(name) => Components(dims.scalar(name)),
        Rate { coordinate, order } => Components(
            m.reg
                .coord(coordinate)
                .map(|q| (0..*order).fold(dims.coordinate(q), |d, _| d / Dimension::TIME)),
        ),
        // d/dt(Q): Q's dimension over a time.
        Derivative { of, .. } => expected_dimension(m, dims, of).map(|x| x / Dimension::TIME),
        Eom(c) => Components(m.reg.coord(c).and_then(|q| {
            m.dynamics
                .theorems
                .iter()
                .find(|t| t.eom == Some(q))
                .map(|t| match t.kind {
                    TheoremKind::Resultant => Dimension::FORCE,
                    TheoremKind::Moment => Dimension::MOMENT,
                    // A power over the coordinate's rate.
                    TheoremKind::Energy => Dimension::POWER / dims.coordinate(q) * Dimension::TIME,
                })
        })),
    }
}

/// Why a value fails the homogeneity check.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{at}: {problem}")]
pub struct DimensionError {
    /// What was checked: the quantity or step, and the component (`V(G,2/0) in B0, y0`).
    pub at: String,
    /// What is wrong.
    pub problem: DimensionProblem,
}

/// What is wrong with a component's dimension.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum DimensionProblem {
    /// Two terms of different dimensions.
    #[error("inhomogeneous: {0}")]
    Inhomogeneous(Inhomogeneous),
    /// Homogeneous, but not of the quantity's dimension.
    #[error(
        "dimension {found} ({}) where the quantity is {expected} ({}), e.g. the term `{term}`",
        unit_or_one(found),
        unit_or_one(expected)
    )]
    Unexpected {
        /// A term of the component, in the plain-text syntax.
        term: String,
        /// Its dimension (every known term has it).
        found: Dimension,
        /// The quantity's.
        expected: Dimension,
    },
}

/// Names of the expressions of a value, in the order of [`Value::exprs`]: the basis vector of
/// each component (`y2`), `R.x1` and `M.x1` for a torsor, `[0][1]` for an inertia entry.
fn component_names(m: &Mechanism, v: &Value) -> Vec<String> {
    let axes = |b: crate::frame::FrameId| {
        let f = m.frame_name(b);
        ["x", "y", "z"].map(|a| format!("{a}{f}"))
    };
    match v {
        Value::Scalar(_) => vec![String::new()],
        Value::Quotient(_) => vec![String::new(), "denominator".to_string()],
        Value::Vector { basis, .. } => axes(*basis).to_vec(),
        Value::Matrix(_) => (0..9).map(|k| format!("[{}][{}]", k / 3, k % 3)).collect(),
        Value::Torsor { basis, .. } => {
            let a = axes(*basis);
            a.iter()
                .map(|c| format!("R.{c}"))
                .chain(a.iter().map(|c| format!("M.{c}")))
                .collect()
        }
    }
}

/// Checks that every component of a value is homogeneous and, where the dimension expected
/// is known, of that dimension. `what` names the value in the error (a quantity, a step).
pub fn homogeneous_as(
    m: &Mechanism,
    dims: &Dimensions,
    what: &str,
    expected: ExpectedDimension,
    v: &Value,
) -> Result<(), DimensionError> {
    if let Value::Quotient(q) = v {
        // Each side homogeneous, the quotient of the quantity's dimension.
        let side = |e: &Expr, at: String| {
            scan(e, dims).map_err(|h| DimensionError {
                at,
                problem: DimensionProblem::Inhomogeneous(h),
            })
        };
        let num = side(&q.num, what.to_string())?;
        let den = side(&q.den, format!("{what}, denominator"))?;
        if let (Some((n, t)), Some((d, _)), Some(want)) = (num, den, expected.component(0))
            && n / d != want
        {
            return Err(DimensionError {
                at: what.to_string(),
                problem: DimensionProblem::Unexpected {
                    term: term_text(&q.num, t),
                    found: n / d,
                    expected: want,
                },
            });
        }
        return Ok(());
    }
    let names = component_names(m, v);
    for (k, e) in v.exprs().into_iter().enumerate() {
        let at = match names.get(k).map(String::as_str) {
            None | Some("") => what.to_string(),
            Some(c) => format!("{what}, {c}"),
        };
        let found = scan(e, dims).map_err(|h| DimensionError {
            at: at.clone(),
            problem: DimensionProblem::Inhomogeneous(h),
        })?;
        if let (Some((found, t)), Some(want)) = (found, expected.component(k))
            && found != want
        {
            return Err(DimensionError {
                at,
                problem: DimensionProblem::Unexpected {
                    term: term_text(e, t),
                    found,
                    expected: want,
                },
            });
        }
    }
    Ok(())
}

/// Checks a quantity's value (in general or under a hypothesis): every component homogeneous
/// and of the quantity's dimension ([`expected_dimension`]).
///
/// ```
/// use torseur::derivation::derive;
/// use torseur::quantity::Quantity;
/// use torseur::units::{homogeneous_value, Dimensions};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
/// let dims = Dimensions::of(&m);
/// let q = Quantity::parse("delta(O2,2/0).x2")?;
/// let d = derive(&m, &q)?;
/// homogeneous_value(&m, &dims, &q, &d.value)?;
/// // The same value taken for a velocity is refused.
/// let v = Quantity::parse("V(G2,2/0).x2")?;
/// let err = homogeneous_value(&m, &dims, &v, &d.value).unwrap_err();
/// assert!(err.to_string().contains("where the quantity is L·T⁻¹ (m/s)"), "{err}");
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn homogeneous_value(
    m: &Mechanism,
    dims: &Dimensions,
    q: &Quantity,
    v: &Value,
) -> Result<(), DimensionError> {
    homogeneous_as(m, dims, &q.to_string(), expected_dimension(m, dims, q), v)
}

/// Checks every step of a derivation (what the answer key displays) and its result: each step
/// of the dimension of what it computes (a derivative of σ is a moment, a complementary
/// term a moment, an action torsor a force and a moment, a sum of actions a force or a
/// moment).
///
/// ```
/// use torseur::derivation::derive;
/// use torseur::quantity::Quantity;
/// use torseur::units::{homogeneous_derivation, Dimensions};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
/// let d = derive(&m, &Quantity::parse("C_m")?)?;
/// homogeneous_derivation(&m, &Dimensions::of(&m), &d)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn homogeneous_derivation(
    m: &Mechanism,
    dims: &Dimensions,
    d: &Derivation,
) -> Result<(), DimensionError> {
    let of_kind = |kind: &QuantityKind| {
        let q = Quantity {
            kind: kind.clone(),
            basis: None,
            projection: None,
            linear: false,
        };
        expected_dimension(m, dims, &q)
    };
    let torsor = |resultant, moment| ExpectedDimension::Torsor { resultant, moment };
    for s in &d.steps {
        let expected = match &s.kind {
            StepKind::Quantity(k) | StepKind::Projected(k, _) | StepKind::Massless(k) => of_kind(k),
            StepKind::Derivative(k, _) => of_kind(k).map(|x| x / Dimension::TIME),
            StepKind::Complementary { .. } => {
                ExpectedDimension::Components(Some(Dimension::MOMENT))
            }
            StepKind::Action { .. } => torsor(Dimension::FORCE, Dimension::MOMENT),
            StepKind::Coulomb { .. } => ExpectedDimension::Components(Some(Dimension::FORCE)),
            StepKind::TrialMotion { coordinate, order } => ExpectedDimension::Components(
                m.reg
                    .coord(coordinate)
                    .map(|q| dims.coordinate(q) / Dimension::TIME.pow(i32::from(*order))),
            ),
            StepKind::Balance { coordinate, .. } => of_kind(&QuantityKind::Eom(coordinate.clone())),
            StepKind::Powers { .. } => ExpectedDimension::Components(Some(Dimension::POWER)),
            StepKind::External { point, .. } => {
                ExpectedDimension::Components(Some(if point.is_some() {
                    Dimension::MOMENT
                } else {
                    Dimension::FORCE
                }))
            }
        };
        homogeneous_as(
            m,
            dims,
            &format!("{} (step {})", d.quantity, s.label),
            expected,
            &s.value,
        )?;
    }
    homogeneous_value(m, dims, &d.quantity, &d.value)
}
