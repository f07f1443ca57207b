//! The actions of the bilan as quantities: R(from→on), M(A, from→on), {T(from→on)}_A, each
//! the sum of the actions `from` exerts on `on`, moved to A by M(A) = M(P) + AP ∧ R.

use super::{ResolveError, Resolved, Step, StepKind, torsor_value};
use crate::mechanism::Mechanism;
use crate::quantity::{ActionRef, Quantity};
use crate::torsor::Torsor;
use crate::vector::Vector;

/// The torsor at `r.point` (the ground origin for a resultant) of the actions `action.from`
/// exerts on `action.on`, each action recorded as a step at its own point.
pub(super) fn total(
    m: &Mechanism,
    q: &Quantity,
    action: &ActionRef,
    r: &Resolved,
    steps: &mut Vec<Step>,
) -> Result<Torsor, ResolveError> {
    let a = r.point.unwrap_or(m.points.origin());
    let actions = crate::pfd::actions_of(m, &action.from, &r.solids, &action.on)
        .map_err(|e| ResolveError::new(q, e))?;
    let mut sum = Torsor {
        point: a,
        resultant: Vector::zero(),
        moment: Vector::zero(),
    };
    for act in &actions {
        let t = act.torsor();
        let point = m.point_name(act.point).to_string();
        steps.push(Step {
            label: format!("T({}->{})", act.from_label, act.on_label),
            kind: StepKind::Action {
                from: act.from_label.clone(),
                on: act.on_label.clone(),
                point,
            },
            theorem: super::dynamics::bilan_line(act),
            value: torsor_value(m, &t, act.basis),
        });
        let moved = t.at(m, a);
        sum.resultant = sum.resultant.add(&moved.resultant);
        sum.moment = sum.moment.add(&moved.moment);
    }
    Ok(sum)
}
