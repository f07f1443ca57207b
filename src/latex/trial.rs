//! A trial motion's unknown (« régime forcé »): the motion posed, its second derivative, the
//! equation of motion along it for every t, then the unknown boxed.

use super::page::{DisplayRole, Doc};
use crate::derivation::{Derivation, Step, StepKind, Value};
use crate::expr::Expr;
use std::fmt::Write as _;

/// The step of `d` of this kind.
fn step(d: &Derivation, f: impl Fn(&StepKind) -> bool) -> Option<&Step> {
    d.steps.iter().find(|s| f(&s.kind))
}

/// The block of a trial's unknown: « On cherche le régime forcé sous la forme x(t) = … :
/// ẍ = …. En reportant dans l'équation du mouvement : … pour tout t, d'où » and the result.
pub(super) fn trial_block(doc: &mut Doc, d: &Derivation, title: &str) {
    let _ = writeln!(doc.o, "\\TTitre{{${title}$}}");
    let hyp = doc.under.map(|h| h.name.clone());
    let motion = step(d, |k| matches!(k, StepKind::TrialMotion { order: 0, .. }));
    let second = step(d, |k| matches!(k, StepKind::TrialMotion { order: 2, .. }));
    let balance = step(d, |k| matches!(k, StepKind::Balance { .. }));
    if let (Some(motion), Some(second), Some(balance)) = (motion, second, balance) {
        let lhs = super::words::step_lhs(&doc.names, &balance.kind);
        if doc.cited(&lhs, &balance.value).is_some() {
            let _ = writeln!(doc.o, "Avec les coefficients établis ci-dessus :\n");
        } else {
            let _ = writeln!(doc.o, "On cherche le régime forcé sous la forme");
            for s in [motion, second] {
                let l = super::words::step_lhs(&doc.names, &s.kind);
                doc.show_keyed(DisplayRole::Step, &s.label, &l, &l, &s.value, false);
                if s.label == motion.label {
                    let _ = writeln!(doc.o, "d'où, en dérivant deux fois par rapport au temps,");
                }
            }
            let _ = writeln!(
                doc.o,
                "En reportant dans l'équation du mouvement, pour tout $t$ :"
            );
            balance_display(doc, balance);
            doc.remember(&lhs, &balance.value);
            let _ = writeln!(doc.o, "d'où");
        }
    }
    let v = match doc.under {
        Some(h) => d.value.under(h),
        None => d.value.clone(),
    };
    let id = d.quantity.to_string();
    // Recorded for the bilan, as every result is.
    let here = doc.here.clone();
    doc.results
        .push((d.quantity.clone(), hyp.clone(), v.clone(), here));
    doc.show_result(DisplayRole::Result, &id, hyp.as_deref(), title, &v, None);
}

/// The equation of motion along the motion, `(k − M Ω²) X cos(Ω t) = F0 cos(Ω t)`: the terms
/// that hold the unknowns on the left, the others on the right.
fn balance_display(doc: &mut Doc, s: &Step) {
    let (Value::Scalar(r), StepKind::Balance { unknowns, .. }) = (&s.value, &s.kind) else {
        return;
    };
    let zero = r.registry().zero();
    let rest = unknowns
        .iter()
        .fold(r.clone(), |e, v| e.substitute(*v, &zero));
    let left: Expr = r - &rest;
    let right = -&rest;
    let lhs = super::expr(&left);
    let rv = Value::Scalar(right);
    let body = super::values::value_within(doc.m, &doc.names, doc.style, &lhs, &rv, None, doc.line);
    doc.record_equality(DisplayRole::Step, &s.label, body, &Value::Scalar(left), rv);
}
