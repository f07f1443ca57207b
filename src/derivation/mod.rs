//! Derivations: a requested quantity becomes ordered steps, each a value and the theorem that
//! produced it, following the course's « méthodologie de calcul ».

use crate::frame::{Axis, FrameId};

use crate::kinematics::{acceleration, omega, point_velocity, velocity};
use crate::mechanism::{BodyId, Mechanism};
use crate::point::PointId;
use crate::quantity::{Motion, Quantity, QuantityKind};
use crate::torsor::{self, Torsor};
use crate::vector::Vector;

mod actions;
mod dynamics;
mod value;
pub use dynamics::Shared;
pub use value::Value;

/// A quantity that cannot be derived: it names what the spec does not have, or its PFD
/// cannot be solved.
///
/// ```
/// use torseur::derivation::{Unresolved, derive};
/// use torseur::quantity::Quantity;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let e = derive(&m, &Quantity::parse("V(Q,2/0)").unwrap()).unwrap_err();
/// assert_eq!(e.reason, Unresolved::UnknownName { what: "point", name: "Q".into() });
/// assert_eq!(e.to_string(), "V(Q,2/0): unknown point `Q`");
/// ```
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}", message(.quantity, .reason))]
pub struct ResolveError {
    /// The quantity as written.
    pub quantity: String,
    /// Why it cannot be derived.
    pub reason: Unresolved,
}

/// Why a quantity cannot be derived.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum Unresolved {
    /// A name the spec does not declare.
    #[error("unknown {what} `{name}`")]
    UnknownName {
        /// What was looked for (`point`, `solid or frame`, `coordinate`…).
        what: &'static str,
        /// The name as written.
        name: String,
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
fn message(quantity: &str, reason: &Unresolved) -> String {
    match reason {
        Unresolved::Budget(e) => e.to_string(),
        reason => format!("{quantity}: {reason}"),
    }
}

impl ResolveError {
    /// `quantity` cannot be derived, for `reason`.
    pub fn new(quantity: &impl std::fmt::Display, reason: impl Into<Unresolved>) -> Self {
        ResolveError {
            quantity: quantity.to_string(),
            reason: reason.into(),
        }
    }

    /// `quantity` names an unknown `what` (a point, a solid…) called `name`.
    pub fn unknown(quantity: &impl std::fmt::Display, what: &'static str, name: &str) -> Self {
        ResolveError::new(
            quantity,
            Unresolved::UnknownName {
                what,
                name: name.to_string(),
            },
        )
    }
}

impl From<String> for Unresolved {
    fn from(s: String) -> Self {
        Unresolved::Other(s)
    }
}

/// A quantity with its names resolved to ids.
#[derive(Debug, Clone)]
pub struct Resolved {
    /// Point involved (if any).
    pub point: Option<PointId>,
    /// Frame of the moving solid or frame (for Ω, V, Γ, {V}).
    pub moving_frame: Option<FrameId>,
    /// Solids of the moving solid or set (for kinetic and dynamic quantities, I).
    pub solids: Vec<BodyId>,
    /// Reference frame.
    pub reference: Option<FrameId>,
    /// Basis the result is written in.
    pub basis: FrameId,
    /// Projection vector (basis, axis).
    pub projection: Option<(FrameId, Axis)>,
}

/// Resolves the names of a quantity in a mechanism.
pub fn resolve(m: &Mechanism, q: &Quantity) -> Result<Resolved, ResolveError> {
    let unknown = |what: &'static str, n: &str| ResolveError::unknown(q, what, n);
    let frame = |n: &str| m.frame_of(n).ok_or_else(|| unknown("solid or frame", n));
    let point = |n: &str| m.point(n).ok_or_else(|| unknown("point", n));
    let solids = |n: &str| m.solids_of(n).ok_or_else(|| unknown("solid or set", n));
    let mut r = Resolved {
        point: None,
        moving_frame: None,
        solids: vec![],
        reference: None,
        basis: m.default_basis,
        projection: None,
    };
    let kinetic = |mo: &Motion, r: &mut Resolved| -> Result<(), ResolveError> {
        r.solids = solids(&mo.moving)?;
        r.reference = Some(frame(&mo.reference)?);
        Ok(())
    };
    let kinematic = |mo: &Motion, r: &mut Resolved| -> Result<(), ResolveError> {
        r.moving_frame = Some(frame(&mo.moving)?);
        r.reference = Some(frame(&mo.reference)?);
        Ok(())
    };
    use QuantityKind::*;
    match &q.kind {
        Omega(mo) => kinematic(mo, &mut r)?,
        Velocity { point: p, motion } | Acceleration { point: p, motion } => {
            r.point = Some(point(p)?);
            kinematic(motion, &mut r)?;
        }
        KinematicTorsor { motion, point: p } => {
            r.point = Some(point(p)?);
            kinematic(motion, &mut r)?;
        }
        Inertia { point: p, solid } => {
            r.point = Some(point(p)?);
            let b = m.find_body(solid).ok_or_else(|| unknown("solid", solid))?;
            r.solids = vec![b];
            r.basis = torsor::inertia_basis(m, b);
        }
        KineticResultant(mo) | DynamicResultant(mo) | KineticEnergy(mo) => kinetic(mo, &mut r)?,
        // Named objects checked here, before the PFD is solved: a spec's `quantities` are
        // resolved when it is loaded.
        Unknown(name) => {
            if !m.reg.unknowns().contains(name) {
                return Err(ResolveError::new(q, dynamics::not_an_unknown(name)));
            }
        }
        Eom(c) => {
            let coord = m.reg.coord(c).ok_or_else(|| unknown("coordinate", c))?;
            if !m.dynamics.theorems.iter().any(|t| t.eom == Some(coord)) {
                return Err(ResolveError::new(q, dynamics::no_eom_marked(c)));
            }
        }
        ActionResultant(a) => r.solids = solids(&a.on)?,
        Power { action, reference } => {
            r.solids = solids(&action.on)?;
            r.reference = Some(frame(reference)?);
        }
        InternalPower(set) => r.solids = solids(set)?,
        EquivalentInertia(c) => {
            m.reg.coord(c).ok_or_else(|| unknown("coordinate", c))?;
        }
        ActionMoment { point: p, action } | ActionTorsor { action, point: p } => {
            r.point = Some(point(p)?);
            r.solids = solids(&action.on)?;
        }
        KineticMoment { point: p, motion }
        | DynamicMoment { point: p, motion }
        | KineticTorsor { motion, point: p }
        | DynamicTorsor { motion, point: p } => {
            r.point = Some(point(p)?);
            kinetic(motion, &mut r)?;
        }
    }
    // The action must be in the bilan of what it acts on.
    if let Some(a) = q.kind.action() {
        crate::pfd::actions_of(m, &a.from, &r.solids, &a.on)
            .map_err(|e| ResolveError::new(q, e))?;
    }
    if let Some(b) = &q.basis {
        r.basis = m
            .frames
            .find(b)
            .ok_or_else(|| unknown("basis", &format!("B{b}")))?;
    }
    if let Some((f, axis)) = &q.projection {
        // Intermediate steps are written in the basis of the projection vector.
        let fid = m
            .frames
            .find(f)
            .ok_or_else(|| unknown("basis vector", &format!("{axis}{f}")))?;
        if q.basis.is_none() {
            r.basis = fid;
        }
        r.projection = Some((
            fid,
            Axis::parse(&axis.to_string()).ok_or_else(|| unknown("axis", &axis.to_string()))?,
        ));
    }
    Ok(r)
}

/// What a step computes, for printing in the course's notation.
#[derive(Debug, Clone)]
pub enum StepKind {
    /// A quantity of the notation (Ω, I, σ, δ, Rc, Rd...).
    Quantity(QuantityKind),
    /// The derivative of a quantity in a frame: [d/dt σ(A,S/R)]_R.
    Derivative(QuantityKind, String),
    /// The complementary term V(A/R) ∧ m V(G/R) of δ: (point A, centre G, frame R).
    Complementary(String, String, String),
    /// An action torsor {T(from→on)} at a point.
    Action {
        /// What exerts it (`0`, `pes`, `moteur`).
        from: String,
        /// What receives it.
        on: String,
        /// Point of reduction.
        point: String,
    },
    /// A quantity projected on a basis vector (frame name, axis letter).
    Projected(QuantityKind, (String, char)),
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
/// it stops with [`Unresolved::Budget`].
pub fn derive(m: &Mechanism, q: &Quantity) -> Result<Derivation, ResolveError> {
    within_budget(q, || derive_unbounded(m, q))
}

/// Runs `f`, the derivation of `q`, under the budget of terms: an expression that outgrows it
/// stops `f` with an error that names `q`.
fn within_budget<T>(
    q: &Quantity,
    f: impl FnOnce() -> Result<T, ResolveError>,
) -> Result<T, ResolveError> {
    match crate::expr::budget::bounded(f) {
        Ok(r) => r,
        Err(crate::expr::ExprError::Budget {
            detail,
            terms,
            limit,
            ..
        }) => Err(ResolveError::new(
            q,
            Unresolved::Budget(crate::expr::ExprError::Budget {
                what: format!("the derivation of {q}"),
                detail,
                terms,
                limit,
            }),
        )),
        Err(e) => Err(ResolveError::new(q, Unresolved::Budget(e))),
    }
}

fn derive_unbounded(m: &Mechanism, q: &Quantity) -> Result<Derivation, ResolveError> {
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
    let r = resolve(m, q)?;
    let b = r.basis;
    let mut steps = Vec::new();
    let reference = r.reference.unwrap_or(m.frames.ground());
    use QuantityKind::*;
    let found = match &q.kind {
        KineticEnergy(_) | Unknown(_) | Eom(_) => {
            return dynamics::derive(m, q, &mut Shared::default(), true);
        }
        Omega(_) => Found::Vector(omega(m, r.moving_frame.unwrap_or(reference), reference)),
        Power { action, .. } => Found::Value(Value::Scalar(actions::power(
            m, q, action, &r, reference, &mut steps,
        )?)),
        EquivalentInertia(c) => {
            let coord = m
                .reg
                .coord(c)
                .ok_or_else(|| ResolveError::unknown(q, "coordinate", c))?;
            let j =
                crate::pfd::equivalent_inertia(m, coord).map_err(|e| ResolveError::new(q, e))?;
            Found::Value(Value::Scalar(j))
        }
        InternalPower(_) => Found::Value(Value::Scalar(actions::internal_power(m, &r, &mut steps))),
        ActionResultant(action) | ActionMoment { action, .. } | ActionTorsor { action, .. } => {
            let t = actions::total(m, q, action, &r, &mut steps)?;
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
        Inertia { .. } => {
            let s = r.solids[0];
            let a = r.point.unwrap_or(m.body(s).centre);
            if let Some(ig) = torsor::inertia_at_centre(m, s) {
                steps.push(Step {
                    kind: StepKind::Quantity(QuantityKind::Inertia {
                        point: m.point_name(m.body(s).centre).to_string(),
                        solid: m.body(s).name.clone(),
                    }),
                    label: format!("I({},{})", m.point_name(m.body(s).centre), m.body(s).name),
                    theorem: "opérateur d'inertie donné par l'énoncé".into(),
                    value: Value::Matrix(ig),
                });
            }
            let ia = torsor::inertia_at(m, s, a).in_basis(&m.frames, b);
            Found::Value(Value::Matrix(ia))
        }
        KineticResultant(_) => Found::Vector(torsor::kinetic_resultant(m, &r.solids, reference)),
        DynamicResultant(_) => Found::Vector(torsor::dynamic_resultant(m, &r.solids, reference)),
        KineticMoment { .. } | DynamicMoment { .. } => {
            let a = r.point.unwrap_or(m.points.origin());
            let dynamic = matches!(q.kind, DynamicMoment { .. });
            let total = moment_steps(m, &r.solids, a, reference, b, dynamic, &mut steps);
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
            let t = solids_torsor(m, &r.solids, a, reference, b, dynamic, &mut steps);
            Found::Value(torsor_value(m, &t, b))
        }
    };
    // A vector is projected where the quantity asks (Ω(2/0).x1), else written in its basis.
    let value = match found {
        Found::Value(v) => v,
        Found::Vector(v) => match r.projection {
            Some((f, axis)) => {
                let u = Vector::along(f, axis, m.reg.one());
                Value::Scalar(v.dot(&m.frames, &u))
            }
            None => vec_value(m, &v, b),
        },
    };
    Ok(Derivation {
        quantity: q.clone(),
        steps,
        value,
    })
}

/// The kinetic (or, `dynamic`, the dynamic) torsor at `a` of the solids `solids` in their
/// motion relative to `reference`, each solid's resultant and moment recorded as a step.
fn solids_torsor(
    m: &Mechanism,
    solids: &[BodyId],
    a: PointId,
    reference: FrameId,
    b: FrameId,
    dynamic: bool,
    steps: &mut Vec<Step>,
) -> Torsor {
    let rn = m.frame_name(reference).to_string();
    let set = solids.len() > 1;
    let mut res_total = Vector::zero();
    let mut mom_total = Vector::zero();
    for &s in solids {
        let body = m.body(s);
        let mo = Motion {
            moving: body.name.clone(),
            reference: rn.clone(),
        };
        // Each solid of a set is taken where its torsor is simplest (the course's
        // method): at A if A is its frame origin or its centre, else at its frame
        // origin when that point is fixed in the reference frame; then moved to A.
        let origin = m.origin(body.frame);
        let p = if !set || a == origin || a == body.centre {
            a
        } else if point_velocity(m, origin, reference).is_zero(&m.frames) {
            origin
        } else {
            a
        };
        let res = if dynamic {
            acceleration(m, body.centre, body.frame, reference).scale(&body.mass)
        } else {
            velocity(m, body.centre, body.frame, reference).scale(&body.mass)
        };
        steps.push(Step {
            kind: StepKind::Quantity(if dynamic {
                QuantityKind::DynamicResultant(mo.clone())
            } else {
                QuantityKind::KineticResultant(mo.clone())
            }),
            label: format!("{}({mo})", if dynamic { "Rd" } else { "Rc" }),
            theorem: if dynamic {
                "Rd = m Γ(G, S/R0)".into()
            } else {
                "Rc = m V(G, S/R0)".into()
            },
            value: vec_value(m, &res, b),
        });
        let mom = moment_steps(m, &[s], p, reference, b, dynamic, steps);
        let t = Torsor {
            point: p,
            resultant: res,
            moment: mom,
        };
        let t = if p == a {
            t
        } else {
            let moved = t.at(m, a);
            let (pn, an) = (m.point_name(p).to_string(), m.point_name(a).to_string());
            let kind = if dynamic {
                QuantityKind::DynamicTorsor {
                    motion: mo.clone(),
                    point: an.clone(),
                }
            } else {
                QuantityKind::KineticTorsor {
                    motion: mo.clone(),
                    point: an.clone(),
                }
            };
            steps.push(Step {
                label: kind.to_string(),
                kind: StepKind::Quantity(kind),
                theorem: format!("changement de point : M({an}) = M({pn}) + {an}{pn} ∧ R"),
                value: torsor_value(m, &moved, b),
            });
            moved
        };
        res_total = res_total.add(&t.resultant);
        mom_total = mom_total.add(&t.moment);
    }
    Torsor {
        point: a,
        resultant: res_total,
        moment: mom_total,
    }
}

fn torsor_value(m: &Mechanism, t: &Torsor, b: FrameId) -> Value {
    Value::Torsor {
        point: t.point,
        basis: b,
        resultant: t.resultant.express_in(&m.frames, b),
        moment: t.moment.express_in(&m.frames, b),
    }
}

/// The steps of σ(A) or δ(A) for each solid, and their sum.
fn moment_steps(
    m: &Mechanism,
    solids: &[BodyId],
    a: PointId,
    r: FrameId,
    b: FrameId,
    dynamic: bool,
    steps: &mut Vec<Step>,
) -> Vector {
    let rn = m.frame_name(r).to_string();
    let an = m.point_name(a).to_string();
    let mut total = Vector::zero();
    for &s in solids {
        let body = m.body(s);
        let sn = &body.name;
        let om = omega(m, body.frame, r);
        let ib = torsor::inertia_basis(m, s);
        let mo = Motion {
            moving: sn.clone(),
            reference: rn.clone(),
        };
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Omega(mo.clone())),
            label: format!("Omega({sn}/{rn})"),
            theorem: "composition des vecteurs rotation".into(),
            value: vec_value(m, &om, ib),
        });
        let ia = torsor::inertia_at(m, s, a);
        let huygens = a != body.centre && body.inertia.is_some();
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Inertia {
                point: an.clone(),
                solid: sn.clone(),
            }),
            label: format!("I({an},{sn})"),
            theorem: if huygens {
                format!(
                    "théorème de Huygens, de {g} en {an}",
                    g = m.point_name(body.centre)
                )
            } else if body.inertia.is_none() {
                "masse ponctuelle".into()
            } else {
                "opérateur d'inertie en G".into()
            },
            value: Value::Matrix(ia),
        });
        let sigma = torsor::kinetic_moment_solid(m, s, a, r);
        let fixed = crate::kinematics::velocity(m, a, body.frame, r).is_zero(&m.frames);
        let sigma_kind = QuantityKind::KineticMoment {
            point: an.clone(),
            motion: mo.clone(),
        };
        steps.push(Step {
            kind: StepKind::Quantity(sigma_kind.clone()),
            label: format!("sigma({an},{sn}/{rn})"),
            theorem: if a == body.centre {
                "σ(G, S/R0) = I_G(S)·Ω(S/R0)".into()
            } else if fixed && point_velocity(m, a, r).is_zero(&m.frames) {
                "point fixe dans le mouvement : σ(A, S/R0) = I_A(S)·Ω(S/R0)".into()
            } else if fixed {
                // The point of S at A has no velocity, A itself moves (a rolling contact).
                "point de vitesse nulle : σ(A, S/R0) = I_A(S)·Ω(S/R0)".into()
            } else {
                "σ(A, S/R0) = I_A(S)·Ω(S/R0) + m AG ∧ V(A, S/R0)".into()
            },
            value: vec_value(m, &sigma, b),
        });
        if !dynamic {
            total = total.add(&sigma);
            continue;
        }
        let d_sigma = sigma.derivative_in(&m.frames, r);
        steps.push(Step {
            kind: StepKind::Derivative(sigma_kind, rn.clone()),
            label: format!("d/dt sigma({an},{sn}/{rn})|{rn}"),
            theorem: "dérivation vectorielle (formule de Bour)".into(),
            value: vec_value(m, &d_sigma, b),
        });
        let v_a = point_velocity(m, a, r);
        let mut delta = d_sigma;
        if !v_a.is_zero(&m.frames) {
            let mv_g = velocity(m, body.centre, body.frame, r).scale(&body.mass);
            let extra = v_a.cross(&m.frames, &mv_g);
            steps.push(Step {
                kind: StepKind::Complementary(
                    an.clone(),
                    m.point_name(body.centre).to_string(),
                    rn.clone(),
                ),
                label: format!("V({an}/{rn}) ^ m V({}/{rn})", m.point_name(body.centre)),
                theorem: "terme complémentaire V(A/R0) ∧ m V(G/R0)".into(),
                value: vec_value(m, &extra, b),
            });
            delta = delta.add(&extra);
        }
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::DynamicMoment {
                point: an.clone(),
                motion: mo.clone(),
            }),
            label: format!("delta({an},{sn}/{rn})"),
            theorem: "δ(A, S/R0) = d/dt σ(A, S/R0)|R0 + V(A/R0) ∧ m V(G/R0)".into(),
            value: vec_value(m, &delta, b),
        });
        total = total.add(&delta);
    }
    total
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
pub fn derive_values(m: &Mechanism, qs: &[Quantity]) -> Result<Vec<Derivation>, ResolveError> {
    derive_values_with(m, qs, |_, _| {})
}

/// [`derive_values`], calling `done(k, q)` after the k-th quantity (1-based), for progress.
/// Each quantity is derived under the budget of terms, as by [`derive()`].
pub fn derive_values_with(
    m: &Mechanism,
    qs: &[Quantity],
    mut done: impl FnMut(usize, &Quantity),
) -> Result<Vec<Derivation>, ResolveError> {
    let mut cache = Shared::default();
    cache.expect(qs);
    let mut out = Vec::with_capacity(qs.len());
    for (k, q) in qs.iter().enumerate() {
        out.push(within_budget(q, || derive_value(m, q, &mut cache))?);
        done(k + 1, q);
    }
    Ok(out)
}

/// The linearised value of a derivation (its steps are kept as derived).
fn linearised(m: &Mechanism, q: &Quantity, d: Derivation) -> Result<Derivation, ResolveError> {
    if m.dynamics.small.is_empty() {
        return Err(ResolveError::new(
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
) -> Result<Derivation, ResolveError> {
    if q.linear {
        let inner = Quantity {
            linear: false,
            ..q.clone()
        };
        return linearised(m, q, derive_value(m, &inner, cache)?);
    }
    use QuantityKind::*;
    let r = resolve(m, q)?;
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
