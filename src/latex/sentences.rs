//! The sentence that introduces each step of a derivation in the corrigé: the theorem applied
//! to the step's objects (« $O_1$ est fixe dans $\mathcal{R}_0$ … », Huygens at the centre of
//! inertia, the change of point of a torsor's moment).

use super::omega::{omega_of, omega_sentence};
use super::words::{mass_of, solid};
use super::{frame, point, quantity_tex};
use crate::derivation::{Step, StepKind};
use crate::mechanism::Mechanism;
use crate::quantity::{Motion, QuantityKind};

/// The sentence that introduces a step: the theorem applied to the step's objects.
pub(super) fn sentence(m: &Mechanism, names: &super::VectorNames, s: &Step) -> String {
    use QuantityKind::*;
    let t = s.theorem.as_str();
    match &s.kind {
        StepKind::Quantity(Omega(mo)) => omega_sentence(m, mo),
        StepKind::Quantity(Inertia {
            point: a,
            solid: sn,
        }) => inertia_sentence(m, t, a, sn),
        StepKind::Quantity(KineticMoment {
            point: a,
            motion: mo,
        }) => kinetic_moment_sentence(m, t, a, mo),
        StepKind::Derivative(_, r) => format!(
            "Dérivée dans ${}$ (formule de Bour, $\\TDeriv{{{}}}{{\\TVec{{u}}}} = \\TDeriv{{\\mathcal{{R}}_k}}{{\\TVec{{u}}}} + \\TVecLong{{\\Omega(k/{r})}}\\wedge\\TVec{{u}}$) :",
            frame(r),
            frame(r)
        ),
        StepKind::Complementary {
            point: a,
            reference: r,
            ..
        } => format!(
            "${}$ n'est pas fixe dans ${}$ : terme complémentaire",
            point(a),
            frame(r)
        ),
        StepKind::Quantity(DynamicMoment {
            point: a,
            motion: mo,
        }) => dynamic_moment_sentence(m, a, mo),
        StepKind::Quantity(DynamicResultant(mo)) => resultant_sentence(m, mo, true),
        StepKind::Quantity(KineticResultant(mo)) => resultant_sentence(m, mo, false),
        StepKind::Quantity(k) if k.is_torsor() => change_of_point_sentence(t, k),
        StepKind::Action { .. } => format!("{} :", super::theorems::action_line(m, names, s)),
        _ => format!("{} :", super::escape_text(t)),
    }
}

/// The name of the centre of inertia of the solid `moving`, `G` for a set.
fn centre_name(m: &Mechanism, moving: &str) -> String {
    m.bodies
        .iter()
        .find(|b| b.name == moving)
        .map(|b| m.point_name(b.centre).to_string())
        .unwrap_or_else(|| "G".into())
}

/// The sentence of I_A(S) (theorem `t`): Huygens from G, a point mass, or the operator given.
fn inertia_sentence(m: &Mechanism, t: &str, a: &str, sn: &str) -> String {
    if let Some(g) = t.strip_prefix("théorème de Huygens, de ") {
        let g = g.split(' ').next().unwrap_or(g);
        format!(
            "Théorème de Huygens, de ${}$ en ${}$ (${} = I_{{{}}}({sn})$ + terme de transport de ${}$) :",
            point(g),
            point(a),
            quantity_tex(&QuantityKind::Inertia {
                point: a.to_string(),
                solid: sn.to_string()
            }),
            point(g),
            mass_of(m, sn)
        )
    } else if t == "masse ponctuelle" {
        format!("${}$ est une masse ponctuelle :", solid(sn))
    } else {
        "Opérateur d'inertie :".to_string()
    }
}

/// The sentence of σ(A,S/R) (theorem `t`): a point mass, at G, at a point fixed or of zero
/// velocity (I_A Ω), or the general formula.
fn kinetic_moment_sentence(m: &Mechanism, t: &str, a: &str, mo: &Motion) -> String {
    let sigma = quantity_tex(&QuantityKind::KineticMoment {
        point: a.to_string(),
        motion: mo.clone(),
    });
    let i = format!("I_{{{}}}({})", point(a), mo.moving);
    let om = omega_of(&mo.moving, &mo.reference);
    let point_mass = m
        .bodies
        .iter()
        .find(|b| b.name == mo.moving)
        .filter(|b| b.inertia.is_none())
        .map(|b| m.point_name(b.centre).to_string());
    if let Some(p) = point_mass {
        // σ(A) = AP ∧ m V(P): no inertia operator for a point mass.
        format!(
            "${}$ est une masse ponctuelle : ${sigma} = \\TVecLong{{{}{}}}\\wedge {}\\,{}$ :",
            point(&p),
            point(a),
            point(&p),
            mass_of(m, &mo.moving),
            quantity_tex(&QuantityKind::Velocity {
                point: p.clone(),
                motion: mo.clone()
            })
        )
    } else if t.starts_with("σ(G") {
        format!(
            "${}$ est le centre d'inertie de ${}$ : ${sigma} = {i}\\cdot{om}$ :",
            point(a),
            solid(&mo.moving)
        )
    } else if t.starts_with("point fixe") {
        format!(
            "${}$ est un point de ${}$ fixe dans ${}$ : ${sigma} = {i}\\cdot{om}$ :",
            point(a),
            solid(&mo.moving),
            frame(&mo.reference)
        )
    } else if t.starts_with("point de vitesse nulle") {
        format!(
            "${}$ est un point de ${}$ de vitesse nulle dans ${}$ : ${sigma} = {i}\\cdot{om}$ :",
            point(a),
            solid(&mo.moving),
            frame(&mo.reference)
        )
    } else {
        let g = centre_name(m, &mo.moving);
        format!(
            "${sigma} = {i}\\cdot{om} + {}\\,\\TVecLong{{{}{}}}\\wedge\\TVecLong{{V({},\\TMvt{{{}}}{{{}}})}}$ :",
            mass_of(m, &mo.moving),
            point(a),
            point(&g),
            point(a),
            mo.moving,
            mo.reference
        )
    }
}

/// The sentence of δ(A,S/R): the derivative of σ(A) plus the term of a moving point.
fn dynamic_moment_sentence(m: &Mechanism, a: &str, mo: &Motion) -> String {
    let delta = quantity_tex(&QuantityKind::DynamicMoment {
        point: a.to_string(),
        motion: mo.clone(),
    });
    let sigma = quantity_tex(&QuantityKind::KineticMoment {
        point: a.to_string(),
        motion: mo.clone(),
    });
    format!(
        "${} = \\TDeriv{{{}}}{{{}}} + \\TVecLong{{V({}/{})}}\\wedge {}\\,\\TVecLong{{V({}/{})}}$ :",
        delta,
        frame(&mo.reference),
        sigma,
        point(a),
        frame(&mo.reference),
        mass_of(m, &mo.moving),
        point(&centre_name(m, &mo.moving)),
        frame(&mo.reference)
    )
}

/// The sentence of Rd = m Γ(G) (`dynamic`) or Rc = m V(G).
fn resultant_sentence(m: &Mechanism, mo: &Motion, dynamic: bool) -> String {
    let g = centre_name(m, &mo.moving);
    let (r, v) = if dynamic {
        (
            QuantityKind::DynamicResultant(mo.clone()),
            QuantityKind::Acceleration {
                point: g,
                motion: mo.clone(),
            },
        )
    } else {
        (
            QuantityKind::KineticResultant(mo.clone()),
            QuantityKind::Velocity {
                point: g,
                motion: mo.clone(),
            },
        )
    };
    format!(
        "${} = {}\\,{}$ :",
        quantity_tex(&r),
        mass_of(m, &mo.moving),
        quantity_tex(&v)
    )
}

/// The sentence of a torsor moved to another point (theorem `t`, « … = M(A) … »):
/// M(B) = M(A) + BA ∧ R.
fn change_of_point_sentence(t: &str, k: &QuantityKind) -> String {
    let from = t
        .split("= M(")
        .nth(1)
        .and_then(|x| x.split(')').next())
        .unwrap_or("A")
        .to_string();
    let to = match k {
        QuantityKind::KineticTorsor { point: p, .. }
        | QuantityKind::DynamicTorsor { point: p, .. } => p.clone(),
        _ => "B".into(),
    };
    format!(
        "Changement de point, de ${}$ à ${}$ ($\\TVec{{M}}({}) = \\TVec{{M}}({}) + \\TVecLong{{{}{}}}\\wedge\\TVec{{R}}$) :",
        point(&from),
        point(&to),
        point(&to),
        point(&from),
        point(&to),
        point(&from)
    )
}
