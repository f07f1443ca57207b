//! The lines of the bilan of the external actions that the PFD's theorems, the kinetic energy
//! theorem and the actions' quantities share: each action's line in words and its torsor as a
//! step.

use super::{Step, StepKind, torsor_value};
use crate::mechanism::Mechanism;
use crate::pfd::Action;

/// A solid in a sentence: `$S_{2}$` for solid `2`, its name otherwise (free text).
fn solid_text(n: &str) -> String {
    if n.chars().all(|c| c.is_ascii_digit()) {
        format!("$S_{{{n}}}$")
    } else {
        n.to_string()
    }
}

/// The line of an action in the bilan of the external actions (free text for
/// [`crate::latex::rich_text`]).
pub(super) fn bilan_line(a: &Action) -> String {
    let (from, on) = (solid_text(&a.from_label), solid_text(&a.on_label));
    if a.from_label == "pes" {
        format!("pesanteur sur {on}")
    } else if a.description.starts_with("liaison") || a.description.starts_with("encastrement") {
        format!("{}, action de {from} sur {on}", a.description)
    } else {
        format!("{}, action sur {on}", a.label)
    }
}

/// The step of one action's torsor at its own point, as the bilan writes it.
pub(super) fn action_step(m: &Mechanism, act: &crate::pfd::Action) -> Step {
    Step {
        label: format!("T({}->{})", act.from_label, act.on_label),
        kind: StepKind::Action {
            from: act.from_label.clone(),
            on: act.on_label.clone(),
            point: m.point_name(act.point).to_string(),
            source: act.source.clone(),
            mark: act.mark.clone(),
        },
        theorem: bilan_line(act),
        value: torsor_value(m, &act.torsor(), act.basis),
    }
}
