//! The steps of the kinetic and dynamic moments and torsors of solids and sets, solid by
//! solid as the course derives them (Ω, I at the point, σ, its derivative, the complementary
//! term, δ), and the one step that says a body of negligible mass contributes nothing.

use super::{Step, StepKind, Value, vec_value};
use crate::frame::FrameId;
use crate::kinematics::{acceleration, omega, point_velocity, velocity};
use crate::mechanism::{BodyId, Mechanism};
use crate::point::PointId;
use crate::quantity::{Motion, QuantityKind};
use crate::torsor::{self, Torsor};
use crate::vector::Vector;
/// The kinetic (or, `dynamic`, the dynamic) torsor at `a` of the solids `solids` in their
/// motion relative to `reference`, each solid's resultant and moment recorded as a step.
pub(super) fn solids_torsor(
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
        if body.massless {
            steps.push(massless_torsor(m, mo, a, b, dynamic));
            continue;
        }
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
            moved_to(m, &t, a, mo, (b, dynamic), steps)
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

/// The torsor kind of `mo` at `point`: dynamic, or kinetic.
fn torsor_kind(mo: Motion, point: String, dynamic: bool) -> QuantityKind {
    if dynamic {
        QuantityKind::DynamicTorsor { motion: mo, point }
    } else {
        QuantityKind::KineticTorsor { motion: mo, point }
    }
}

/// The step that says the kinetic (or dynamic) torsor at `a` of a body of negligible mass,
/// in its motion `mo`, is zero.
fn massless_torsor(m: &Mechanism, mo: Motion, a: PointId, b: FrameId, dynamic: bool) -> Step {
    let kind = torsor_kind(mo, m.point_name(a).to_string(), dynamic);
    let zero = Torsor {
        point: a,
        resultant: Vector::zero(),
        moment: Vector::zero(),
    };
    massless_step(kind, torsor_value(m, &zero, b))
}

/// The torsor `t` of one solid in its motion `mo`, moved to `a` by the change of point, the
/// step recorded (values in `b`).
fn moved_to(
    m: &Mechanism,
    t: &Torsor,
    a: PointId,
    mo: Motion,
    (b, dynamic): (FrameId, bool),
    steps: &mut Vec<Step>,
) -> Torsor {
    let moved = t.at(m, a);
    let (pn, an) = (
        m.point_name(t.point).to_string(),
        m.point_name(a).to_string(),
    );
    let kind = torsor_kind(mo, an.clone(), dynamic);
    steps.push(Step {
        label: kind.to_string(),
        kind: StepKind::Quantity(kind),
        theorem: format!("changement de point : M({an}) = M({pn}) + {an}{pn} ∧ R"),
        value: torsor_value(m, &moved, b),
    });
    moved
}

/// The step that says a quantity of a body of negligible mass is zero, with its value.
pub(crate) fn massless_step(kind: QuantityKind, value: Value) -> Step {
    let solid = kind
        .motion()
        .map(|mo| mo.moving.clone())
        .or_else(|| match &kind {
            QuantityKind::Inertia { solid, .. } => Some(solid.clone()),
            _ => None,
        })
        .unwrap_or_default();
    // Solids are named by their number in the course: S2.
    let solid = if solid.chars().all(|c| c.is_ascii_digit()) {
        format!("S{solid}")
    } else {
        solid
    };
    Step {
        label: kind.to_string(),
        theorem: format!("{solid} est de masse négligeable : {kind} = 0"),
        kind: StepKind::Massless(kind),
        value,
    }
}

pub(super) fn torsor_value(m: &Mechanism, t: &Torsor, b: FrameId) -> Value {
    Value::Torsor {
        point: t.point,
        basis: b,
        resultant: t.resultant.express_in(&m.frames, b),
        moment: t.moment.express_in(&m.frames, b),
    }
}

/// The steps of σ(A) or δ(A) for each solid, and their sum.
pub(super) fn moment_steps(
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
        let mo = Motion {
            moving: sn.clone(),
            reference: rn.clone(),
        };
        if body.massless {
            let point = an.clone();
            let kind = if dynamic {
                QuantityKind::DynamicMoment { point, motion: mo }
            } else {
                QuantityKind::KineticMoment { point, motion: mo }
            };
            steps.push(massless_step(kind, vec_value(m, &Vector::zero(), b)));
            continue;
        }
        let om = omega(m, body.frame, r);
        let ib = torsor::inertia_basis(m, s);
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Omega(mo.clone())),
            label: format!("Omega({sn}/{rn})"),
            theorem: "composition des vecteurs rotation".into(),
            value: vec_value(m, &om, ib),
        });
        let ia = torsor::inertia_at(m, s, a);
        steps.push(Step {
            kind: StepKind::Quantity(QuantityKind::Inertia {
                point: an.clone(),
                solid: sn.clone(),
            }),
            label: format!("I({an},{sn})"),
            theorem: inertia_theorem(m, s, a),
            value: Value::Matrix(ia),
        });
        let sigma = torsor::kinetic_moment_solid(m, s, a, r);
        let sigma_kind = QuantityKind::KineticMoment {
            point: an.clone(),
            motion: mo.clone(),
        };
        steps.push(Step {
            kind: StepKind::Quantity(sigma_kind.clone()),
            label: format!("sigma({an},{sn}/{rn})"),
            theorem: sigma_theorem(m, s, a, r).into(),
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
        let mut delta = d_sigma;
        if let Some(extra) = complementary(m, s, a, (r, b), steps) {
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

/// The complementary term V(A/R) ∧ m V(G/R) of δ(A,S/R) of the solid `s`, with its own mass
/// and centre, its step recorded (values in `b`); none where A is fixed in R.
fn complementary(
    m: &Mechanism,
    s: BodyId,
    a: PointId,
    (r, b): (FrameId, FrameId),
    steps: &mut Vec<Step>,
) -> Option<Vector> {
    let v_a = point_velocity(m, a, r);
    if v_a.is_zero(&m.frames) {
        return None;
    }
    let body = m.body(s);
    let (an, rn) = (m.point_name(a), m.frame_name(r));
    let g = m.point_name(body.centre);
    let mv_g = velocity(m, body.centre, body.frame, r).scale(&body.mass);
    let extra = v_a.cross(&m.frames, &mv_g);
    steps.push(Step {
        kind: StepKind::Complementary {
            point: an.to_string(),
            centre: g.to_string(),
            solid: body.name.clone(),
            reference: rn.to_string(),
        },
        label: format!("V({an}/{rn}) ^ m V({g}/{rn})"),
        theorem: "terme complémentaire V(A/R0) ∧ m V(G/R0)".into(),
        value: vec_value(m, &extra, b),
    });
    Some(extra)
}

/// How I(A,S) is found: by Huygens from G, as a point mass, or as given at G.
pub(super) fn inertia_theorem(m: &Mechanism, s: BodyId, a: PointId) -> String {
    let body = m.body(s);
    if a != body.centre && body.inertia.is_some() {
        format!(
            "théorème de Huygens, de {g} en {an}",
            g = m.point_name(body.centre),
            an = m.point_name(a)
        )
    } else if body.inertia.is_none() {
        "masse ponctuelle".into()
    } else {
        "opérateur d'inertie en G".into()
    }
}

/// The formula that gives σ(A,S/R): at the centre, at a point fixed in the motion, at a
/// point of S of zero velocity (a rolling contact), or the general one.
fn sigma_theorem(m: &Mechanism, s: BodyId, a: PointId, r: FrameId) -> &'static str {
    let body = m.body(s);
    let fixed = velocity(m, a, body.frame, r).is_zero(&m.frames);
    if a == body.centre {
        "σ(G, S/R0) = I_G(S)·Ω(S/R0)"
    } else if fixed && point_velocity(m, a, r).is_zero(&m.frames) {
        "point fixe dans le mouvement : σ(A, S/R0) = I_A(S)·Ω(S/R0)"
    } else if fixed {
        // The point of S at A has no velocity, A itself moves (a rolling contact).
        "point de vitesse nulle : σ(A, S/R0) = I_A(S)·Ω(S/R0)"
    } else {
        "σ(A, S/R0) = I_A(S)·Ω(S/R0) + m AG ∧ V(A, S/R0)"
    }
}
