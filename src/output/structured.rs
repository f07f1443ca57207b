//! The structured form as text and JSON: the named subexpressions in order, each quantity over
//! them, and the equations of motion M(q) q̈ + h(q, q̇) = Q(q) over them.

use crate::derivation::Derivation;
use crate::expr::Expr;
use crate::mechanism::Mechanism;
use crate::pfd::named::Lin;
use crate::pfd::structured::Structured;
use crate::quantity::Quantity;
use serde_json::{Value as Json, json};

fn text(v: &Lin) -> String {
    v.text(Expr::to_string)
}

/// A quantity's value: over the names, or the engine's canonical one from `others`.
fn value_text(m: &Mechanism, s: &Structured, q: &Quantity, others: &[Derivation]) -> String {
    match s.value(q) {
        Some(v) => text(v),
        None => others
            .iter()
            .find(|d| &d.quantity == q)
            .map(|d| super::value_text_in(m, &d.value, super::TextForm::Canonical))
            .unwrap_or_default(),
    }
}

/// Each row of the equations of motion as (label, value): `M(q1,q2)`, `h(q1)`, `Q(q1)`.
fn motion_rows(m: &Mechanism, s: &Structured) -> Vec<(String, String)> {
    let Some(eq) = &s.motion else {
        return Vec::new();
    };
    let name = |k: usize| m.reg.coord_info(eq.coordinates[k]).name.clone();
    let mut rows = Vec::new();
    for i in 0..eq.coordinates.len() {
        for (j, mij) in eq.mass[i].iter().enumerate() {
            rows.push((format!("M({},{})", name(i), name(j)), text(mij)));
        }
        rows.push((format!("h({})", name(i)), text(&eq.velocity_terms[i])));
        rows.push((format!("Q({})", name(i)), text(&eq.forces[i])));
    }
    rows
}

/// The structured form as text: `N1 = …` with its meaning as a comment, then each quantity
/// (the structured ones over the names, the others canonical), then M, h and Q.
pub fn structured_text(
    m: &Mechanism,
    s: &Structured,
    qs: &[Quantity],
    others: &[Derivation],
) -> String {
    let mut out = String::from("# Named subexpressions, each over the ones before it.\n");
    for (k, d) in s.program.definitions().iter().enumerate() {
        out.push_str(&format!(
            "N{} = {}  # {}\n",
            k + 1,
            text(&d.value),
            d.meaning
        ));
    }
    out.push_str("# The quantities.\n");
    for q in qs {
        out.push_str(&format!("{q} = {}\n", value_text(m, s, q, others)));
    }
    let rows = motion_rows(m, s);
    if !rows.is_empty() {
        out.push_str("# The equations of motion, M(q) q'' + h(q, q') = Q(q).\n");
        for (label, v) in rows {
            out.push_str(&format!("{label} = {v}\n"));
        }
    }
    out
}

/// The structured form as JSON: `names` (name, meaning, value), `quantities` (id, `named`:
/// whether the value is over the names or the engine's canonical one, value) and
/// `equations_of_motion` (coordinates, mass, velocity_terms, forces), every value text in the
/// spec syntax with the names `N1`, `N2`, … .
pub fn structured_json(
    m: &Mechanism,
    s: &Structured,
    qs: &[Quantity],
    others: &[Derivation],
) -> Json {
    let names: Vec<Json> = s
        .program
        .definitions()
        .iter()
        .enumerate()
        .map(|(k, d)| json!({"name": format!("N{}", k + 1), "meaning": d.meaning, "value": text(&d.value)}))
        .collect();
    let qs: Vec<Json> = qs
        .iter()
        .map(|q| {
            json!({"id": q.to_string(), "named": s.value(q).is_some(),
                "value": value_text(m, s, q, others)})
        })
        .collect();
    let mut o = json!({"title": m.title, "names": names, "quantities": qs});
    if let Some(eq) = &s.motion {
        let coords: Vec<&str> = eq
            .coordinates
            .iter()
            .map(|&q| m.reg.coord_info(q).name.as_str())
            .collect();
        let mass: Vec<Vec<String>> = eq
            .mass
            .iter()
            .map(|r| r.iter().map(text).collect())
            .collect();
        o["equations_of_motion"] = json!({
            "coordinates": coords,
            "mass": mass,
            "velocity_terms": eq.velocity_terms.iter().map(text).collect::<Vec<_>>(),
            "forces": eq.forces.iter().map(text).collect::<Vec<_>>(),
        });
    }
    o
}
