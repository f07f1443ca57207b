//! The actions of the bilan as quantities: R(from→on), M(A, from→on), {T(from→on)}_A, each
//! the sum of the actions `from` exerts on `on`, moved to A by M(A) = M(P) + AP ∧ R; their
//! power P(from→on/R) and the power of the actions inside a set, P_int(E).

use super::steps::action_step;
use super::{Bound, DeriveError, Step};
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
    r: &Bound,
    steps: &mut Vec<Step>,
) -> Result<Torsor, DeriveError> {
    let a = r.point.unwrap_or(m.points.origin());
    let actions = crate::pfd::actions_of(m, &action.from, &r.solids, &action.on)
        .map_err(|e| DeriveError::new(q, e))?;
    let mut sum = Torsor {
        point: a,
        resultant: Vector::zero(),
        moment: Vector::zero(),
    };
    for act in &actions {
        steps.push(action_step(m, act));
        let moved = act.torsor().at(m, a);
        sum.resultant = sum.resultant.add(&moved.resultant);
        sum.moment = sum.moment.add(&moved.moment);
    }
    Ok(sum)
}

/// P(from→on/R) = Σ R·V(A∈S/R) + M(A)·Ω(S/R) over the actions `from` exerts on `on`, each
/// recorded as a step at its own point.
pub(super) fn power(
    m: &Mechanism,
    q: &Quantity,
    action: &ActionRef,
    r: &Bound,
    reference: crate::frame::FrameId,
    steps: &mut Vec<Step>,
) -> Result<crate::expr::Expr, DeriveError> {
    let actions = crate::pfd::actions_of(m, &action.from, &r.solids, &action.on)
        .map_err(|e| DeriveError::new(q, e))?;
    let mut sum = m.reg.zero();
    for act in &actions {
        steps.push(action_step(m, act));
        sum = &sum + &crate::pfd::action_power(m, act, reference);
    }
    Ok(sum)
}

/// P_int(E) = Σ {T(i→j)} ⊗ {V(j/i)} over the actions between two solids of E, each recorded
/// as a step.
pub(super) fn internal_power(m: &Mechanism, r: &Bound, steps: &mut Vec<Step>) -> crate::expr::Expr {
    for act in crate::pfd::internal_actions(m, &r.solids) {
        steps.push(action_step(m, act));
    }
    crate::pfd::internal_power(m, &r.solids)
}
