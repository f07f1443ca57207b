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
            let an = m.point_name(a).to_string();
            let kind = if dynamic {
                QuantityKind::DynamicTorsor {
                    motion: mo,
                    point: an,
                }
            } else {
                QuantityKind::KineticTorsor {
                    motion: mo,
                    point: an,
                }
            };
            let zero = Torsor {
                point: a,
                resultant: Vector::zero(),
                moment: Vector::zero(),
            };
            steps.push(massless_step(kind, torsor_value(m, &zero, b)));
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
            let kind = if dynamic {
                QuantityKind::DynamicMoment {
                    point: an.clone(),
                    motion: mo,
                }
            } else {
                QuantityKind::KineticMoment {
                    point: an.clone(),
                    motion: mo,
                }
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
                kind: StepKind::Complementary {
                    point: an.clone(),
                    centre: m.point_name(body.centre).to_string(),
                    solid: sn.clone(),
                    reference: rn.clone(),
                },
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
