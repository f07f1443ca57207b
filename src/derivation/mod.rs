//! Derivations: a requested quantity becomes ordered steps, each a value and the theorem that
//! produced it, following the course's « méthodologie de calcul ».

use crate::expr::VarId;
use crate::frame::{Axis, FrameId};

use crate::kinematics::{acceleration, omega, velocity};
use crate::mechanism::{BodyId, Hypothesis, Mechanism};
use crate::point::PointId;
use crate::quantity::{Motion, Quantity, QuantityKind};
use crate::torsor::{self, Torsor};
use crate::vector::Vector;

mod actions;
mod bind;
mod derivative;
mod dynamics;
mod energy;
mod explicit;
mod moments;
mod steps;
mod trial;
mod value;
pub use bind::{Bound, bind};
pub use dynamics::Shared;
pub(crate) use explicit::at_assembly;
pub use explicit::{Assembly, Branch, explicit_law};
pub(crate) use moments::massless_step;
use moments::{moment_steps, solids_torsor, torsor_value};
pub use trial::trial_of;
pub use value::Value;

/// A quantity that cannot be derived: it names what the spec does not have, or its PFD
/// cannot be solved.
///
/// ```
/// use torseur::derivation::{NotDerivable, derive};
/// use torseur::quantity::Quantity;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let e = derive(&m, &Quantity::parse("V(Q,2/0)").unwrap()).unwrap_err();
/// assert!(matches!(&e.reason, NotDerivable::UnknownName { what: "point", name, .. } if name == "Q"));
/// assert_eq!(
///     e.to_string(),
///     "V(Q,2/0): unknown point `Q` (declared: `O0`, `O1`, `G1`, `O2`, `G2`)"
/// );
/// // A name one letter away from a declared one is suggested.
/// let e = derive(&m, &Quantity::parse("V(g2,2/0)").unwrap()).unwrap_err();
/// assert_eq!(e.to_string(), "V(g2,2/0): unknown point `g2` (did you mean `G2`?)");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", message(.quantity, .reason))]
pub struct DeriveError {
    /// The quantity as written.
    pub quantity: String,
    /// Why it cannot be derived.
    pub reason: NotDerivable,
}

/// Why a quantity cannot be derived.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NotDerivable {
    /// A name the spec does not declare.
    #[error("unknown {what} `{name}`{hint}")]
    UnknownName {
        /// What was looked for (`point`, `solid or frame`, `coordinate`…).
        what: &'static str,
        /// The name as written.
        name: String,
        /// ` (did you mean `G2`?)` when a declared name of that kind is close
        /// (the crate's `hint::suggestion`), or the few declared ones; else empty.
        hint: String,
    },
    /// The PFD cannot be solved as declared.
    #[error(transparent)]
    Pfd(#[from] crate::pfd::PfdError),
    /// Anything else, said in a sentence.
    #[error("{0}")]
    Other(String),
    /// The derivation outgrew the budget of terms ([`crate::expr::ExprError::Budget`], whose
    /// `what` names the quantity: see [`crate::expr::budget`]).
    #[error(transparent)]
    Budget(crate::expr::ExprError),
}

/// `quantity: reason`, or for a derivation that outgrew the budget, the budget's sentence,
/// which names the quantity itself.
fn message(quantity: &str, reason: &NotDerivable) -> String {
    match reason {
        NotDerivable::Budget(e) => e.to_string(),
        reason => format!("{quantity}: {reason}"),
    }
}

impl DeriveError {
    /// `quantity` cannot be derived, for `reason`.
    pub fn new(quantity: &impl std::fmt::Display, reason: impl Into<NotDerivable>) -> Self {
        DeriveError {
            quantity: quantity.to_string(),
            reason: reason.into(),
        }
    }

    /// `quantity` names an unknown `what` (`point`, `solid`, `solid or set`, `solid or
    /// frame`, `coordinate`) called `name`: the refusal suggests the declared name of that
    /// kind in `m` it most likely misspells.
    pub fn unknown(
        m: &Mechanism,
        quantity: &impl std::fmt::Display,
        what: &'static str,
        name: &str,
    ) -> Self {
        let bodies = m.bodies.iter().map(|b| b.name.as_str());
        let declared: Vec<&str> = match what {
            "point" => m.points.names().collect(),
            "solid" => bodies.collect(),
            "solid or set" => bodies.chain(m.sets.keys().map(String::as_str)).collect(),
            "solid or frame" => {
                let mut all: Vec<&str> = m.frames.names().chain(bodies).collect();
                all.sort_unstable();
                all.dedup();
                all
            }
            "coordinate" => m
                .reg
                .coordinates()
                .iter()
                .map(|c| c.name.as_str())
                .collect(),
            _ => Vec::new(),
        };
        DeriveError::new(
            quantity,
            NotDerivable::UnknownName {
                what,
                name: name.to_string(),
                hint: crate::hint::suggestion(name, &declared),
            },
        )
    }
}

impl From<String> for NotDerivable {
    fn from(s: String) -> Self {
        NotDerivable::Other(s)
    }
}

/// What a step computes, for printing in the course's notation.
#[derive(Debug, Clone)]
pub enum StepKind {
    /// A quantity of the notation (Ω, I, σ, δ, Rc, Rd...).
    Quantity(QuantityKind),
    /// The derivative of a quantity in a frame: [d/dt σ(A,S/R)]_R.
    Derivative(QuantityKind, String),
    /// The complementary term V(A/R) ∧ m V(G/R) of δ(A,S/R), of one solid S: its mass m and
    /// its centre G.
    Complementary {
        /// The point A of the dynamic moment.
        point: String,
        /// The centre of inertia G of the solid.
        centre: String,
        /// The solid S whose term it is (its mass is m).
        solid: String,
        /// The reference frame R.
        reference: String,
    },
    /// A quantity of a body of negligible mass (its σ, δ, kinetic or dynamic torsor,
    /// resultants, inertia operator, kinetic energy): zero, said so without computing it.
    Massless(QuantityKind),
    /// An action torsor {T(from→on)} at a point.
    Action {
        /// What exerts it (`0`, `pes`, `moteur`).
        from: String,
        /// What receives it.
        on: String,
        /// Point of reduction.
        point: String,
        /// What exerts it, as printed ([`crate::pfd::Action::source`]).
        source: String,
        /// A link's index among the links joining the same two solids.
        mark: Option<crate::mechanism::Mark>,
    },
    /// A quantity projected on a basis vector (frame name, axis letter).
    Projected(QuantityKind, (String, char)),
    /// The power side of the kinetic energy theorem applied to a system in its motion
    /// relative to a frame: P(ext→E/R) + P_int(E).
    Powers {
        /// The isolated solid or set.
        isolate: String,
        /// The frame (the ground, galilean).
        reference: String,
    },
    /// The sum of the actions exterior to a system: its moment at a point (resultant when
    /// none), projected on a basis vector.
    External {
        /// The isolated solid or set.
        isolate: String,
        /// Point of the moments, none for the resultant.
        point: Option<String>,
        /// Projection vector (frame name, axis letter).
        on: (String, char),
    },
    /// The posed motion of a trial (« régime forcé »), q(t) = X cos(Ω t), or its derivative of
    /// this order: its value.
    TrialMotion {
        /// The coordinate q.
        coordinate: String,
        /// 0 for q itself, 2 for q̈.
        order: u8,
    },
    /// The equation of motion along a trial motion, under its hypothesis: its value is
    /// eom(q) with q and its rates replaced, to vanish at every t.
    Balance {
        /// The coordinate q.
        coordinate: String,
        /// The hypothesis that poses the trial motion.
        hypothesis: String,
        /// The trial's unknowns.
        unknowns: Vec<VarId>,
    },
    /// Coulomb's law of a contact while it slides, T = −f N ε: its value is −f N ε.
    Coulomb {
        /// The link's name.
        link: String,
        /// Its tangential unknown T, the left side.
        tangential: String,
    },
}

/// One step of a derivation.
#[derive(Debug, Clone)]
pub struct Step {
    /// What is computed, in the notation (`sigma(O2,2/0)`).
    pub label: String,
    /// The same, structured.
    pub kind: StepKind,
    /// The theorem or definition used, in the course's words.
    pub theorem: String,
    /// The value.
    pub value: Value,
}

/// A derived quantity: its steps and its final value.
#[derive(Debug, Clone)]
pub struct Derivation {
    /// The quantity.
    pub quantity: Quantity,
    /// Intermediate results, in order.
    pub steps: Vec<Step>,
    /// The result.
    pub value: Value,
}

impl Derivation {
    /// The value under the hypothesis `h`: its substitutions, and its first order in small
    /// parameters; for a linearisation `lin(...)`, one first order in small parameters and
    /// small coordinates together ([`crate::pfd::first_order_jointly`]).
    pub fn value_under(&self, m: &Mechanism, h: &Hypothesis) -> Value {
        value_under(m, &self.quantity, &self.value, h)
    }
}

/// The value `v` of the quantity `q` under the hypothesis `h` (see [`Derivation::value_under`]).
pub fn value_under(m: &Mechanism, q: &Quantity, v: &Value, h: &Hypothesis) -> Value {
    match q.linear {
        true => v.map(&|e| crate::pfd::first_order_jointly(m, e, h)),
        false => v.under(h),
    }
}

fn vec_value(m: &Mechanism, v: &Vector, b: FrameId) -> Value {
    Value::Vector {
        basis: b,
        components: v.express_in(&m.frames, b),
    }
}

/// What a quantity's derivation finds: a vector, projected or written in the requested basis
/// at the end, or a value already in its final form.
// One per derivation, moved once: its size does not matter.
#[allow(clippy::large_enum_variant)]
enum Found {
    Vector(Vector),
    Value(Value),
}

/// Derives a quantity: its value written in the requested basis, and the steps that led to it.
///
/// ```
/// use torseur::{derivation::derive, quantity::Quantity, spec};
/// let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let d = derive(&m, &Quantity::parse("Omega(2/0) in B1").unwrap()).unwrap();
/// let reg = m.reg();
/// let expected = [reg.parse("dot(theta2)").unwrap(), reg.zero(), reg.parse("dot(theta1)").unwrap()];
/// match d.value { torseur::derivation::Value::Vector { components, .. } => assert_eq!(components, expected), _ => unreachable!() }
/// ```
///
/// The derivation runs under the budget of terms ([`crate::expr::budget`]): one that outgrows
/// it stops with [`NotDerivable::Budget`].
pub fn derive(m: &Mechanism, q: &Quantity) -> Result<Derivation, DeriveError> {
    within_budget(q, || derive_unbounded(m, q))
}

/// Runs `f`, the derivation of `q`, under the budget of terms: an expression that outgrows it
/// stops `f` with an error that names `q`.
fn within_budget<T>(
    q: &Quantity,
    f: impl FnOnce() -> Result<T, DeriveError>,
) -> Result<T, DeriveError> {
    match crate::expr::budget::bounded(f) {
        Ok(r) => r,
        Err(crate::expr::ExprError::Budget {
            detail,
            terms,
            limit,
            ..
        }) => Err(DeriveError::new(
            q,
            NotDerivable::Budget(crate::expr::ExprError::Budget {
                what: format!("the derivation of {q}"),
                detail,
                terms,
                limit,
            }),
        )),
        Err(e) => Err(DeriveError::new(q, NotDerivable::Budget(e))),
    }
}

fn derive_unbounded(m: &Mechanism, q: &Quantity) -> Result<Derivation, DeriveError> {
    if q.linear {
        return linearised(
            m,
            q,
            derive_unbounded(
                m,
                &Quantity {
                    linear: false,
                    ..q.clone()
                },
            )?,
        );
    }
    let r = bind(m, q)?;
    let mut steps = Vec::new();
    let Some(found) = found(m, q, &r, &mut steps)? else {
        return dynamics::derive(m, q, &mut Shared::default(), true);
    };
    // A vector is projected where the quantity asks (Ω(2/0).x1), else written in its basis.
    let value = match found {
        Found::Value(v) => v,
        Found::Vector(v) => match r.projection {
            Some((f, axis)) => {
                let u = Vector::along(f, axis, m.reg.one());
                Value::Scalar(v.dot(&m.frames, &u))
            }
            None => vec_value(m, &v, r.basis),
        },
    };
    Ok(Derivation {
        quantity: q.clone(),
        steps,
        value,
    })
}

/// The value of `q`, whose names `r` holds, its steps pushed on `steps`: a vector still to
/// write in the requested basis, or a value in its final form; `None` for a quantity of the
/// PFD, derived by [`dynamics::derive`].
fn found(
    m: &Mechanism,
    q: &Quantity,
    r: &Bound,
    steps: &mut Vec<Step>,
) -> Result<Option<Found>, DeriveError> {
    use QuantityKind::*;
    let reference = r.reference.unwrap_or(m.frames.ground());
    let b = r.basis;
    Ok(Some(match &q.kind {
        KineticEnergy(_) | Unknown(_) | Eom(_) => return Ok(None),
        Omega(_) => Found::Vector(omega(m, r.moving_frame.unwrap_or(reference), reference)),
        Power { action, .. } => Found::Value(Value::Scalar(actions::power(
            m, q, action, r, reference, steps,
        )?)),
        EquivalentInertia(c) => {
            let coord = m
                .reg
                .coord(c)
                .ok_or_else(|| DeriveError::unknown(m, q, "coordinate", c))?;
            let j = crate::pfd::equivalent_inertia(m, coord).map_err(|e| DeriveError::new(q, e))?;
            Found::Value(Value::Scalar(j))
        }
        InternalPower(_) => Found::Value(Value::Scalar(actions::internal_power(m, r, steps))),
        // The registry holds each coordinate's rate: a dependent one's is the loop law's.
        Rate { coordinate, order } => {
            let coord = (m.reg.coord(coordinate))
                .ok_or_else(|| DeriveError::unknown(m, q, "coordinate", coordinate))?;
            Found::Value(Value::Scalar(m.reg.rate(coord, *order)))
        }
        Derivative { of, .. } => match derivative::derive(m, q, of, r.reference, b, steps)? {
            derivative::Derived::Scalar(e) => Found::Value(Value::Scalar(e)),
            derivative::Derived::Vector(v) => Found::Vector(v),
        },
        ActionResultant(action) | ActionMoment { action, .. } | ActionTorsor { action, .. } => {
            let t = actions::total(m, q, action, r, steps)?;
            match &q.kind {
                ActionResultant(_) => Found::Vector(t.resultant),
                ActionMoment { .. } => Found::Vector(t.moment),
                _ => Found::Value(torsor_value(m, &t, b)),
            }
        }
        Velocity { .. } => {
            let p = r.point.unwrap_or(m.points.origin());
            Found::Vector(velocity(
                m,
                p,
                r.moving_frame.unwrap_or(reference),
                reference,
            ))
        }
        Acceleration { .. } => {
            let p = r.point.unwrap_or(m.points.origin());
            Found::Vector(acceleration(
                m,
                p,
                r.moving_frame.unwrap_or(reference),
                reference,
            ))
        }
        Inertia { .. } if r.solids.len() == 1 => {
            let s = r.solids[0];
            let a = r.point.unwrap_or(m.body(s).centre);
            Found::Value(Value::Matrix(inertia_steps(m, s, a, b, steps)))
        }
        // A set: each solid's operator at the point (Huygens), then their sum.
        Inertia { point, .. } => Found::Value(Value::Matrix(set_inertia(m, r, point, steps))),
        KineticResultant(_) | DynamicResultant(_) => Found::Vector(resultant(m, q, r, steps)),
        KineticMoment { .. } | DynamicMoment { .. } => {
            let a = r.point.unwrap_or(m.points.origin());
            let dynamic = matches!(q.kind, DynamicMoment { .. });
            let total = moment_steps(m, &r.solids, a, reference, b, dynamic, steps);
            Found::Vector(total)
        }
        KinematicTorsor { .. } => {
            let a = r.point.unwrap_or(m.points.origin());
            let t = torsor::kinematic_torsor(m, r.moving_frame.unwrap_or(reference), reference, a);
            Found::Value(torsor_value(m, &t, b))
        }
        KineticTorsor { .. } | DynamicTorsor { .. } => {
            let a = r.point.unwrap_or(m.points.origin());
            let dynamic = matches!(q.kind, DynamicTorsor { .. });
            let t = solids_torsor(m, &r.solids, a, reference, b, dynamic, steps);
            Found::Value(torsor_value(m, &t, b))
        }
    }))
}

/// I(A,E) of a set at the point named `point`: each solid's operator at A (Huygens, its steps
/// and a step of its own), then their sum.
fn set_inertia(
    m: &Mechanism,
    r: &Bound,
    point: &str,
    steps: &mut Vec<Step>,
) -> crate::inertia::Inertia {
    let b = r.basis;
    let a = r.point.unwrap_or(m.points.origin());
    let mut total: Option<crate::inertia::Inertia> = None;
    for &s in &r.solids {
        let ia = inertia_steps(m, s, a, b, steps);
        let solid = m.body(s).name.clone();
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Inertia {
                point: point.to_string(),
                solid: solid.clone(),
            }),
            label: format!("I({point},{solid})"),
            theorem: moments::inertia_theorem(m, s, a),
            value: Value::Matrix(ia.clone()),
        });
        total = Some(match total {
            None => ia,
            Some(t) => t.plus(&ia),
        });
    }
    total.expect("a set holds at least one solid")
}

/// Rc or Rd of the solids `r` holds (a step when all are massless, it is then zero).
fn resultant(m: &Mechanism, q: &Quantity, r: &Bound, steps: &mut Vec<Step>) -> Vector {
    let reference = r.reference.unwrap_or(m.frames.ground());
    let v = if matches!(q.kind, QuantityKind::DynamicResultant(_)) {
        torsor::dynamic_resultant(m, &r.solids, reference)
    } else {
        torsor::kinetic_resultant(m, &r.solids, reference)
    };
    if r.solids.iter().all(|&s| m.body(s).massless) {
        let kind = q.kind.clone();
        steps.push(massless_step(kind, vec_value(m, &v, r.basis)));
    }
    v
}

/// Values only, by the fastest exact route: kinetic and dynamic moments and torsors by
/// transport from the centres of inertia (each solid's σ(G), δ(G), m V(G), m Γ(G) computed
/// once for all the quantities), the rest as [`derive()`] does. The returned derivations have no
/// steps; their values are identical (same canonical forms) to those of [`derive()`], which
/// follows the course's methodology and records every step.
///
/// ```
/// use torseur::{derivation::{derive, derive_values}, spec};
/// let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let fast = derive_values(&m, &m.quantities()).unwrap();
/// for (q, d) in m.quantities().iter().zip(&fast) {
///     assert_eq!(d.value.exprs(), derive(&m, q).unwrap().value.exprs());
/// }
/// ```
pub fn derive_values(m: &Mechanism, qs: &[Quantity]) -> Result<Vec<Derivation>, DeriveError> {
    derive_values_with(m, qs, |_, _| {})
}

/// [`derive_values`], calling `done(k, q)` after the k-th quantity (1-based), for progress.
/// Each quantity is derived under the budget of terms, as by [`derive()`].
pub fn derive_values_with(
    m: &Mechanism,
    qs: &[Quantity],
    mut done: impl FnMut(usize, &Quantity),
) -> Result<Vec<Derivation>, DeriveError> {
    let mut cache = Shared::default();
    cache.expect(m, qs);
    let mut out = Vec::with_capacity(qs.len());
    for (k, q) in qs.iter().enumerate() {
        out.push(within_budget(q, || derive_value(m, q, &mut cache))?);
        done(k + 1, q);
    }
    Ok(out)
}

/// The linearised value of a derivation (its steps are kept as derived).
fn linearised(m: &Mechanism, q: &Quantity, d: Derivation) -> Result<Derivation, DeriveError> {
    if m.dynamics.small.is_empty() {
        return Err(DeriveError::new(
            q,
            "the spec declares no small coordinates (`small`) to linearise around".to_string(),
        ));
    }
    Ok(Derivation {
        quantity: q.clone(),
        steps: d.steps,
        value: d.value.map(&|e| crate::pfd::linearise(m, e)),
    })
}

fn derive_value(
    m: &Mechanism,
    q: &Quantity,
    cache: &mut Shared,
) -> Result<Derivation, DeriveError> {
    if q.linear {
        let inner = Quantity {
            linear: false,
            ..q.clone()
        };
        return linearised(m, q, derive_value(m, &inner, cache)?);
    }
    use QuantityKind::*;
    let r = bind(m, q)?;
    let reference = r.reference.unwrap_or(m.frames.ground());
    let a = r.point.unwrap_or(m.points.origin());
    let b = r.basis;
    let done = |value: Value| Derivation {
        quantity: q.clone(),
        steps: vec![],
        value,
    };
    match &q.kind {
        KineticMoment { .. } | DynamicMoment { .. } => {
            let dynamic = matches!(q.kind, DynamicMoment { .. });
            let u = r
                .projection
                .map(|(f, axis)| Vector::along(f, axis, m.reg.one()));
            let (v, s) = torsor::moment_by_transport(
                m,
                &mut cache.centre,
                &r.solids,
                a,
                reference,
                dynamic,
                u.as_ref(),
            );
            Ok(done(match s {
                Some(s) => Value::Scalar(s),
                None => vec_value(m, &v, b),
            }))
        }
        KineticTorsor { .. } | DynamicTorsor { .. } => {
            let dynamic = matches!(q.kind, DynamicTorsor { .. });
            let (mom, _) = torsor::moment_by_transport(
                m,
                &mut cache.centre,
                &r.solids,
                a,
                reference,
                dynamic,
                None,
            );
            let res = r.solids.iter().fold(Vector::zero(), |acc, &s| {
                acc.add(&cache.centre.at_centre(m, s, reference, dynamic).1)
            });
            Ok(done(torsor_value(
                m,
                &Torsor {
                    point: a,
                    resultant: res,
                    moment: mom,
                },
                b,
            )))
        }
        KineticEnergy(_) | Unknown(_) | Eom(_) => {
            dynamics::derive(m, q, cache, false).map(|d| done(d.value))
        }
        _ => derive(m, q).map(|d| done(d.value)),
    }
}

/// I(A,S) of one solid in the basis `b`, with the steps the course shows before it: the
/// operator the statement gives at the centre, or the one step that says the body has no
/// mass.
fn inertia_steps(
    m: &Mechanism,
    s: BodyId,
    a: PointId,
    b: FrameId,
    steps: &mut Vec<Step>,
) -> crate::inertia::Inertia {
    let body = m.body(s);
    let ia = torsor::inertia_at(m, s, a).in_basis(&m.frames, b);
    if body.massless {
        let kind = QuantityKind::Inertia {
            point: m.point_name(a).to_string(),
            solid: body.name.clone(),
        };
        steps.push(massless_step(kind, Value::Matrix(ia.clone())));
    }
    if let Some(ig) = torsor::inertia_at_centre(m, s) {
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Inertia {
                point: m.point_name(body.centre).to_string(),
                solid: body.name.clone(),
            }),
            label: format!("I({},{})", m.point_name(body.centre), body.name),
            theorem: "opérateur d'inertie donné par l'énoncé".into(),
            value: Value::Matrix(ig),
        });
    }
    ia
}
