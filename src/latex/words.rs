//! The words the sections of the answer key share: a solid's name and mass, a step's left
//! side, a step's value under the question's hypothesis, a French list and the sentence that
//! cites values already shown.

use super::page::Doc;
use super::{action_side, frame, name, point, quantity_tex};
use crate::derivation::{StepKind, Value};
use crate::mechanism::Mechanism;
use crate::quantity::QuantityKind;

/// `S_2` for solid `2`, `E` for a set.
pub(super) fn solid(n: &str) -> String {
    // A carrier isolated with what it carries: `1+2` is S₁ + S₂.
    if n.contains('+') {
        return n.split('+').map(solid).collect::<Vec<_>>().join(" + ");
    }
    if n.chars().all(|c| c.is_ascii_digit()) {
        format!("S_{{{n}}}")
    } else {
        name(n)
    }
}

/// The mass of a solid in LaTeX (`m_{2}`), as a factor (a sum in parentheses), or `m` for a
/// set.
pub(super) fn mass_of(m: &Mechanism, s: &str) -> String {
    m.bodies
        .iter()
        .find(|b| b.name == s)
        .map(|b| {
            let t = super::expr(&b.mass);
            if t.contains(" + ") || t.contains(" - ") {
                format!("\\left({t}\\right)")
            } else {
                t
            }
        })
        .unwrap_or_else(|| "m".to_string())
}

/// The left side of a step's display.
pub(super) fn step_lhs(names: &super::VectorNames, k: &StepKind) -> String {
    match k {
        StepKind::Quantity(q) => names.quantity(q),
        StepKind::Derivative(q, r) => format!("\\TDeriv{{{}}}{{{}}}", frame(r), names.quantity(q)),
        StepKind::Complementary {
            point: a,
            centre: g,
            reference: r,
            ..
        } => format!(
            "\\TVecLong{{V({}/{})}} \\wedge m\\,\\TVecLong{{V({}/{})}}",
            point(a),
            frame(r),
            point(g),
            frame(r)
        ),
        StepKind::Massless(q) => names.quantity(q),
        StepKind::Action {
            on,
            point: p,
            source,
            mark,
            ..
        } => format!(
            "\\TTorseur{{{}({} \\rightarrow {})}}{{{}}}",
            super::source::torsor_letter(mark.as_ref()),
            super::action_source(source),
            action_side(on),
            point(p)
        ),
        StepKind::Projected(q, (f, a)) => {
            format!("{} \\cdot {}", names.quantity(q), names.basis_vector(*a, f))
        }
        StepKind::Coulomb { tangential, .. } => super::name(tangential),
        StepKind::TrialMotion { coordinate, order } => {
            let c = super::name(coordinate);
            match order {
                0 => format!("{c}(t)"),
                1 => format!("\\dot{{{c}}}"),
                _ => format!("\\ddot{{{c}}}"),
            }
        }
        StepKind::Balance { .. } => "0".to_string(),
        StepKind::Powers { isolate, reference } => format!(
            "{} + {}",
            quantity_tex(&QuantityKind::Power {
                action: crate::quantity::ActionRef {
                    from: "ext".into(),
                    on: isolate.clone(),
                },
                reference: reference.clone(),
            }),
            quantity_tex(&QuantityKind::InternalPower(isolate.clone()))
        ),
        StepKind::External {
            isolate,
            point: p,
            on: (f, a),
        } => {
            let s = action_side(isolate);
            let arrow = format!("{} \\rightarrow {s}", super::exterior(&s));
            match p {
                Some(p) => format!(
                    "\\TVecLong{{M({},{arrow})}} \\cdot {}",
                    point(p),
                    names.basis_vector(*a, f)
                ),
                None => format!(
                    "\\TVecLong{{R({arrow})}} \\cdot {}",
                    names.basis_vector(*a, f)
                ),
            }
        }
    }
}

/// A step's value under the question's hypothesis.
pub(super) fn shown_value(doc: &Doc, v: &Value) -> Value {
    match doc.under {
        Some(h) => v.under(h),
        None => v.clone(),
    }
}

/// « a, b et c ».
pub(super) fn french_list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [a] => a.clone(),
        [init @ .., last] => format!("{} et {last}", init.join(", ")),
    }
}

/// Values already shown, said in one sentence with where they are: « On reprend
/// $\Omega(3/0)$ (question 1) et $I_O(3)$ (ci-dessus). »
pub(super) fn citation(by_place: &[(String, Vec<String>)]) -> String {
    let items: Vec<String> = by_place
        .iter()
        .map(|(place, lhss)| {
            let list: Vec<String> = lhss.iter().map(|l| format!("${l}$")).collect();
            let at = match place.as_str() {
                "ce qui précède" => "ci-dessus",
                p => p.strip_prefix("la ").or(p.strip_prefix("le ")).unwrap_or(p),
            };
            format!("{} ({at})", french_list(&list))
        })
        .collect();
    format!("On reprend {}.\n", french_list(&items))
}
