//! The kinetic energy theorem in the answer key, as a theorem of the PFD: the power of each
//! exterior action (grouped by what exerts it), the power of the inter-efforts, the kinetic
//! energy and its derivative, then dEc(E/R0)/dt = P(ext→E/R0) + P_int(E) as one equality.
//! Every formula is recorded (see `document`).

use super::frame;
use super::page::{DisplayRole, Doc};
use super::words::{shown_value, solid, step_lhs};
use crate::derivation::{Step, StepKind, Value};
use crate::quantity::QuantityKind;
use std::fmt::Write;

/// The steps of one energy theorem, from the first power to the power side
/// ([`StepKind::Powers`]), written; returns the theorem's two sides (dEc/dt, P) shown.
pub(super) fn energy_theorem(doc: &mut Doc, group: &[Step]) -> Option<(Value, Value)> {
    let (last, rest) = group.split_last()?;
    let StepKind::Powers { isolate, reference } = &last.kind else {
        return None;
    };
    let (e, r) = (solid(isolate), frame(reference));
    let is = |s: &&Step, f: &dyn Fn(&QuantityKind) -> bool| matches!(&s.kind, StepKind::Quantity(k) if f(k));
    let powers: Vec<&Step> = (rest.iter())
        .filter(|s| is(s, &|k| matches!(k, QuantityKind::Power { .. })))
        .collect();
    let _ = writeln!(
        doc.o,
        "Puissance de chaque action extérieure à ${e}$ dans son mouvement par rapport à ${r}$, \
         $\\mathcal{{P}} = \\TVec{{R}}\\cdot\\TVecLong{{V(A\\in S/{reference})}} + \
         \\TVec{{M}}(A)\\cdot\\TVecLong{{\\Omega(S/{reference})}}$ au point $A$ de l'action :"
    );
    side_by_side(doc, &powers);
    for s in rest
        .iter()
        .filter(|s| !powers.iter().any(|p| std::ptr::eq(*p, *s)))
    {
        let sentence = match &s.kind {
            StepKind::Quantity(QuantityKind::InternalPower(_))
                if doc.m.solids_of(isolate).is_some_and(|s| s.len() == 1) =>
            {
                format!("${e}$ est un solide : la puissance des inter-efforts est nulle.")
            }
            StepKind::Quantity(QuantityKind::InternalPower(_)) => format!(
                "Puissance des inter-efforts (actions entre les solides de ${e}$, nulle pour une \
                 liaison parfaite) :"
            ),
            StepKind::Quantity(QuantityKind::KineticEnergy(_)) => format!(
                "Énergie cinétique de ${e}$ dans son mouvement par rapport à ${r}$ (théorème de \
                 König, solide par solide) :"
            ),
            StepKind::Quantity(QuantityKind::Derivative { .. }) => {
                "Sa dérivée par rapport au temps :".to_string()
            }
            _ => continue,
        };
        shown_or_cited(doc, s, &sentence);
    }
    let dynamic = rest.last()?;
    let (dl, dv) = (
        step_lhs(&doc.names, &dynamic.kind),
        shown_value(doc, &dynamic.value),
    );
    let (pl, pv) = (
        step_lhs(&doc.names, &last.kind),
        shown_value(doc, &last.value),
    );
    let _ = writeln!(
        doc.o,
        "Théorème de l'énergie cinétique appliqué à ${e}$ dans son mouvement par rapport à \
         ${r}$ galiléen, ${dl} = {pl}$ :"
    );
    doc.show_equality(DisplayRole::Step, &last.label, &dl, &dv, &pl, &pv, false);
    Some((dv, pv))
}

/// Each power on its own display, side by side when short; one already shown is cited.
fn side_by_side(doc: &mut Doc, steps: &[&Step]) {
    let mut cells = Vec::new();
    let mut widths = Vec::new();
    let mut cited: Vec<(String, Vec<String>)> = Vec::new();
    for s in steps {
        let v = shown_value(doc, &s.value);
        let lhs = step_lhs(&doc.names, &s.kind);
        if let Some(place) = doc.cited(&lhs, &v) {
            match cited.iter_mut().find(|(p, _)| *p == place) {
                Some((_, l)) => l.push(lhs),
                None => cited.push((place, vec![lhs])),
            }
            continue;
        }
        cells.push(doc.capture(|doc| {
            doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, false);
        }));
        widths.push(doc.last_width());
    }
    if !cited.is_empty() {
        let _ = writeln!(doc.o, "{}", super::words::citation(&cited));
    }
    doc.rows(&cells, &widths, 3);
}

/// A step's sentence and display, or the place it was shown.
fn shown_or_cited(doc: &mut Doc, s: &Step, sentence: &str) {
    let v = shown_value(doc, &s.value);
    let lhs = step_lhs(&doc.names, &s.kind);
    if let Some(place) = doc.cited(&lhs, &v) {
        let c = super::words::citation(&[(place, vec![lhs])]);
        let _ = writeln!(doc.o, "{c}");
        return;
    }
    let _ = writeln!(doc.o, "{sentence}");
    doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, false);
}

/// The sentence before the equation of motion the energy theorem gives: its two sides are
/// q̇ times the equation (the unknowns the other theorems determine replaced), divided by q̇.
pub(super) fn divided_by_rate(doc: &Doc, q: &str) -> Option<String> {
    let m = doc.m;
    let c = m.reg.coord(q)?;
    let energy = m
        .dynamics
        .theorems
        .iter()
        .any(|t| t.eom == Some(c) && t.kind == crate::wire::TheoremKind::Energy);
    if !energy {
        return None;
    }
    let rate = super::expr::rate(&m.reg, c, 1);
    Some(format!(
        "La différence des deux membres est ${rate}$ fois l'équation du mouvement : on la \
         divise par ${rate}$, non nul au cours du mouvement."
    ))
}
