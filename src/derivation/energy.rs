//! The steps of the kinetic energy theorem applied to an isolated system E, as a corrigé
//! writes them: the bilan of the exterior actions, the power of each (grouped by what exerts
//! it, P(pes→E/R0), P(0→E/R0), …), the power of the actions between the solids of E,
//! P_int(E), the kinetic energy and its derivative, then the theorem
//! dEc(E/R0)/dt = P(ext→E/R0) + P_int(E).

use super::{Step, StepKind, Value, steps::action_step};
use crate::expr::Expr;
use crate::mechanism::Mechanism;
use crate::pfd::{Action, Source, Theorem, kinetic_energy};
use crate::quantity::{ActionRef, Motion, Quantity, QuantityKind};

/// The steps of the theorem `th`, its dynamic side dEc/dt (`dynamic`) and each action's
/// power (`parts`, as [`crate::pfd::theorem_sides`] gives them).
pub(super) fn theorem_steps(
    m: &Mechanism,
    th: &Theorem,
    dynamic: Expr,
    parts: &[(Action, Expr)],
    steps: &mut Vec<Step>,
) {
    let r0 = m.frame_name(m.frames.ground()).to_string();
    let iso = th.isolate.clone();
    let inside = |a: &Action| matches!(a.from, Source::Body(b) if th.solids.contains(&b));
    type Parts<'a> = Vec<&'a (Action, Expr)>;
    let (interior, exterior): (Parts, Parts) = parts.iter().partition(|(a, _)| inside(a));
    for (a, _) in &exterior {
        steps.push(action_step(m, a));
    }
    // The power of each source, in the bilan's order.
    let mut sources: Vec<(String, Vec<Expr>)> = Vec::new();
    for (a, p) in &exterior {
        match sources.iter_mut().find(|(f, _)| *f == a.from_label) {
            Some((_, ps)) => ps.push(p.clone()),
            None => sources.push((a.from_label.clone(), vec![p.clone()])),
        }
    }
    for (from, ps) in sources {
        let kind = QuantityKind::Power {
            action: ActionRef {
                from: from.clone(),
                on: iso.clone(),
            },
            reference: r0.clone(),
        };
        steps.push(Step {
            label: kind.to_string(),
            kind: StepKind::Quantity(kind),
            theorem: format!("puissance des actions de {from} sur {iso} dans son mouvement"),
            value: Value::Scalar(Expr::sum(&m.reg, ps)),
        });
    }
    let internal = QuantityKind::InternalPower(iso.clone());
    steps.push(Step {
        label: internal.to_string(),
        kind: StepKind::Quantity(internal),
        theorem: "puissance des inter-efforts".into(),
        value: Value::Scalar(Expr::sum(&m.reg, interior.iter().map(|(_, p)| p.clone()))),
    });
    let ec = Quantity {
        kind: QuantityKind::KineticEnergy(Motion {
            moving: iso.clone(),
            reference: r0.clone(),
        }),
        basis: None,
        projection: None,
        linear: false,
    };
    steps.push(Step {
        label: ec.to_string(),
        kind: StepKind::Quantity(ec.kind.clone()),
        theorem: "théorème de König".into(),
        value: Value::Scalar(kinetic_energy(m, &th.solids)),
    });
    let derivative = QuantityKind::Derivative {
        of: Box::new(ec),
        frame: None,
    };
    steps.push(Step {
        label: derivative.to_string(),
        kind: StepKind::Quantity(derivative),
        theorem: format!(
            "Théorème de l'énergie cinétique appliqué à {iso} dans son mouvement par rapport \
             à {r0} : côté énergie"
        ),
        value: Value::Scalar(dynamic),
    });
    steps.push(Step {
        label: format!("powers on {iso}"),
        kind: StepKind::Powers {
            isolate: iso,
            reference: r0,
        },
        theorem: "Puissance des actions extérieures et des inter-efforts".into(),
        value: Value::Scalar(Expr::sum(&m.reg, parts.iter().map(|(_, p)| p.clone()))),
    });
}
