//! The PFD in the answer key: the bilan of the external actions once per isolated system, each
//! theorem as its two sides, then the unknown or the equation of motion, boxed.

use super::document::{DisplayRole, Doc};
use super::method::{action_side, shown_value, solid, step_lhs};
use super::{basis_vector, name, point, quantity};
use crate::derivation::{Derivation, StepKind, Value};
use crate::quantity::QuantityKind;
use std::fmt::Write;

/// The PFD: for each theorem, the bilan of the external actions (once per isolated system),
/// the theorem as one equality (dynamic side, actions), then the unknown or the equation of
/// motion.
pub(super) fn pfd_block(doc: &mut Doc, d: &Derivation, title: &str) {
    let m = doc.m;
    let _ = writeln!(doc.o, "\\subsubsection*{{${title}$}}");
    let mut k = 0;
    let steps = &d.steps;
    let mut last_equality: Option<(Value, Value)> = None;
    while k < steps.len() {
        // One theorem: actions…, projected dynamic side, external actions.
        let start = k;
        while k < steps.len() && matches!(steps[k].kind, StepKind::Action { .. }) {
            k += 1;
        }
        let (Some(dyn_step), Some(ext_step)) = (steps.get(k), steps.get(k + 1)) else {
            break;
        };
        let StepKind::External {
            isolate,
            point: at,
            on: (f, a),
        } = &ext_step.kind
        else {
            break;
        };
        let iso = action_side(isolate);
        let iso_name = solid(isolate);
        match doc.bilans.get(isolate).cloned() {
            Some(place) => {
                let _ = writeln!(
                    doc.o,
                    "On isole ${iso_name}$ ; le bilan des actions mécaniques extérieures est celui de {place}.\n"
                );
            }
            None => {
                let _ = writeln!(
                    doc.o,
                    "On isole ${iso_name}$. Bilan des actions mécaniques extérieures à ${iso_name}$ :"
                );
                for s in &steps[start..k] {
                    // « le moteur (action moteur de 0 sur 1) », capitalised.
                    let text = super::rich_text_or_escaped(&s.theorem);
                    let mut cs = text.chars();
                    let text = match cs.next() {
                        Some(c) => c.to_uppercase().chain(cs).collect::<String>(),
                        None => text,
                    };
                    let _ = writeln!(doc.o, "{text} :");
                    let v = shown_value(doc, &s.value);
                    let lhs = step_lhs(&s.kind);
                    doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, false);
                }
                let here = doc.here.clone();
                doc.bilans.insert(isolate.clone(), here);
            }
        }
        let theorem = match at {
            Some(p) => format!(
                "Théorème du moment dynamique appliqué à ${iso_name}$ en ${}$, en projection sur ${}$",
                point(p),
                basis_vector(*a, f)
            ),
            None => format!(
                "Théorème de la résultante dynamique appliqué à ${iso_name}$, en projection sur ${}$",
                basis_vector(*a, f)
            ),
        };
        let _ = iso;
        let dl = step_lhs(&dyn_step.kind);
        let el = step_lhs(&ext_step.kind);
        let dv = shown_value(doc, &dyn_step.value);
        let ev = shown_value(doc, &ext_step.value);
        // When the actions reduce to the unknown asked (C_m), the theorem gives it at once:
        // « C_m = δ(O1,E/0)·z0 », boxed below, without writing the dynamic side twice.
        if let (QuantityKind::Unknown(u), Value::Scalar(e)) = (&d.quantity.kind, &ev)
            && m.reg.param(u).as_ref() == Some(e)
            && k + 2 == steps.len()
        {
            let _ = writeln!(doc.o, "{theorem}, ${dl} = {el}$, soit :");
            let id = d.quantity.to_string();
            let hn = doc.under.map(|h| h.name.clone());
            let here = doc.here.clone();
            doc.results.push((id.clone(), hn.clone(), dv.clone(), here));
            let lhs = format!("{} = {dl}", name(u));
            doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, &dv, None);
            return;
        }
        let _ = writeln!(doc.o, "{theorem}, ${dl} = {el}$ :");
        doc.show_equality(
            DisplayRole::Step,
            &dyn_step.label,
            &dl,
            &dv,
            &el,
            &ev,
            false,
        );
        last_equality = Some((dv, ev));
        k += 2;
    }
    let id = d.quantity.to_string();
    let v = shown_value(doc, &d.value);
    let hn = doc.under.map(|h| h.name.clone());
    let here = doc.here.clone();
    doc.results.push((id.clone(), hn.clone(), v.clone(), here));
    match &d.quantity.kind {
        QuantityKind::Eom(q) => {
            // The equation of motion, dynamic side = actions, boxed; when the theorem's
            // equality is already it, box that.
            let Value::Scalar(e) = &v else { return };
            let _ = writeln!(doc.o, "D'où l'équation du mouvement en ${}$ :", name(q));
            let (lhs, rhs) = match &last_equality {
                Some((Value::Scalar(a), Value::Scalar(b))) if &(a - b) == e => {
                    (a.clone(), b.clone())
                }
                _ => split_equation(e),
            };
            doc.show_equation(DisplayRole::Result, &id, hn.as_deref(), &lhs, &rhs);
            if let Some(f) = first_integral(e) {
                let math = super::expr(&f);
                let _ = writeln!(
                    doc.o,
                    "Cette équation exprime que la dérivée par rapport au temps de ${math}$ est nulle : cette \
                     quantité se conserve au cours du mouvement (intégrale première).\n"
                );
                doc.inline.push(super::Inline {
                    what: format!("first integral of {id}"),
                    latex: math,
                    value: Value::Scalar(f),
                });
            }
        }
        _ => {
            let lhs = quantity(&d.quantity.kind);
            doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, &v, None);
        }
    }
    let _ = m;
}

/// F with dF/dt = e exactly, when e = 0 is a first integral in disguise: F = Σ (coefficient
/// of q̈ᵢ in e) q̇ᵢ, kept only if its time derivative is e (the top's d/dt[C (ψ̇ cos θ + φ̇)] = 0).
fn first_integral(e: &crate::expr::Expr) -> Option<crate::expr::Expr> {
    let reg = e.registry();
    let mut f = reg.zero();
    for c in reg.coordinates() {
        if c.has_imposed_rate() {
            continue;
        }
        let q = reg.coord(&c.name)?;
        let a = e.partial_rate(q, 2);
        if !a.is_zero() {
            f = &f + &(&a * &reg.dot(q));
        }
    }
    (!f.is_zero() && f.dt() == *e).then_some(f)
}

/// An equation e = 0 as (terms with a rate) = −(the others).
fn split_equation(e: &crate::expr::Expr) -> (crate::expr::Expr, crate::expr::Expr) {
    let (with, without) = e.split_by_rates();
    (with, -without)
}
