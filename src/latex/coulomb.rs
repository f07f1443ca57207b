//! Coulomb's law in the answer key, as the course writes it: after the bilan that holds a
//! contact with friction, the sliding case (T = −f N ε, ε the sign of the sliding velocity,
//! given with its value) and the sticking condition |T| ≤ f |N|; in the PFD's solve, the law
//! as an equation of the system, at the limit of sliding when a hypothesis gives the sign.

use super::page::Doc;
use super::words::solid;
use super::{Inline, name, point, quantity_tex};
use crate::derivation::{Step, StepKind, Value};
use crate::mechanism::{CoulombLaw, Mechanism};
use crate::quantity::{Motion, QuantityKind};
use std::fmt::Write;

/// The unknowns T and N of a law, in LaTeX.
fn names(law: &CoulombLaw) -> [String; 2] {
    [name(&law.unknowns[0]), name(&law.unknowns[1])]
}

/// A basis vector of a law's directions, in LaTeX.
fn direction(
    m: &Mechanism,
    names: &super::VectorNames,
    (f, a): (crate::frame::FrameId, crate::frame::Axis),
) -> String {
    names.basis_vector(a.letter(), m.frame_name(f))
}

/// Records an inline formula and returns its LaTeX.
fn inline(doc: &mut Doc, what: String, latex: String, value: crate::expr::Expr) -> String {
    doc.inline.push(Inline {
        what,
        latex: latex.clone(),
        value: Value::Scalar(value),
    });
    latex
}

/// After the torsors of a bilan (`actions`): Coulomb's law of each contact among them whose
/// law is not stated yet, each formula recorded.
pub(super) fn state_laws(doc: &mut Doc, actions: &[Step]) {
    let m = doc.m;
    for law in &m.dynamics.laws {
        let l = &m.links[law.link];
        let present = actions.iter().any(|s| match &s.kind {
            StepKind::Action {
                from, on, point, ..
            } => {
                *point == l.point
                    && ((*from == l.between[0] && *on == l.between[1])
                        || (*from == l.between[1] && *on == l.between[0]))
            }
            _ => false,
        });
        if !present || doc.laws_stated.contains(&law.link) {
            continue;
        }
        doc.laws_stated.push(law.link);
        state_law(doc, law);
    }
}

/// One contact's law: its unknowns and coefficient, the sliding case with the sign's meaning
/// and the sliding velocity's value, then the sticking condition.
fn state_law(doc: &mut Doc, law: &CoulombLaw) {
    let m = doc.m;
    let l = &m.links[law.link];
    let [t, n] = names(law);
    let p = point(&l.point);
    let id = &l.name;
    let f = inline(
        doc,
        format!("coefficient of {id}"),
        super::expr(&law.coefficient),
        law.coefficient.clone(),
    );
    let (moving, fixed) = (solid(&l.between[1]), solid(&l.between[0]));
    let _ = writeln!(
        doc.o,
        "Loi de Coulomb en ${p}$, de coefficient de frottement ${f}$ : ${t}$ est la composante \
         tangentielle de l'action, selon ${}$, et ${n}$ sa composante normale, selon ${}$, \
         positive tant que le contact est maintenu. Tant que ${moving}$ glisse sur ${fixed}$ \
         en ${p}$, l'action tangentielle s'oppose au glissement :",
        direction(m, &doc.names, law.directions[0]),
        direction(m, &doc.names, law.directions[1]),
    );
    let sign = super::expr(&law.sign);
    doc.show_law(
        &format!("Coulomb({id})"),
        &t,
        &Value::Scalar(law.values[0].clone()),
        &Value::Scalar(law.friction()),
    );
    let velocity = quantity_tex(&QuantityKind::Velocity {
        point: l.point.clone(),
        motion: Motion {
            moving: l.between[1].clone(),
            reference: l.between[0].clone(),
        },
    });
    let along = direction(m, &doc.names, law.directions[0]);
    let rate = inline(
        doc,
        format!("sliding velocity of {id}"),
        format!("{velocity} \\cdot {along} = {}", super::expr(&law.rate)),
        law.rate.clone(),
    );
    // |T| ≤ f |N|, recorded as T² − f² N² (≤ 0): the same condition, f being positive.
    let [tv, nv] = &law.values;
    let fv = &law.coefficient;
    let squares = &(tv * tv) - &(&(fv * fv) * &(nv * nv));
    let sticking = inline(
        doc,
        format!("sticking of {id}"),
        format!(
            "\\left|{t}\\right| \\leq {f}\\,\\left|{n}\\right|",
            f = super::expr(fv)
        ),
        squares,
    );
    let _ = writeln!(
        doc.o,
        "où ${sign} = \\pm 1$ est le signe de la vitesse de glissement, ${rate}$. Tant qu'il n'y \
         a pas glissement (adhérence), ${t}$ et ${n}$ ne sont liées que par la condition \
         ${sticking}$ ; à la limite du glissement, l'égalité est atteinte, ${t}$ opposée au \
         glissement imminent.\n"
    );
}

/// In the PFD's solve: Coulomb's laws among `steps` (after the theorems), each as an equation
/// of the system, at the limit of sliding when the hypothesis worked under gives its sign.
pub(super) fn law_steps(doc: &mut Doc, steps: &[Step]) {
    let m = doc.m;
    for s in steps {
        let StepKind::Coulomb { link, tangential } = &s.kind else {
            continue;
        };
        let Some(law) = (m.dynamics.laws.iter()).find(|l| m.links[l.link].name == *link) else {
            continue;
        };
        let p = point(&m.links[law.link].point);
        let v = super::words::shown_value(doc, &s.value);
        let t = name(tangential);
        if let Some(place) = doc.cited(&t, &v) {
            let place = if place == "ce qui précède" {
                "ci-dessus".to_string()
            } else {
                format!("dans {place}")
            };
            let _ = writeln!(
                doc.o,
                "La loi de Coulomb en ${p}$, écrite {place}, complète le système.\n"
            );
            continue;
        }
        let fixed = doc
            .under
            .map(|h| h.apply(&law.sign))
            .filter(|e| *e != law.sign);
        match (fixed, doc.under) {
            (Some(e), Some(h)) => {
                let what = format!("sign of {link} under {}", h.name);
                let latex = format!("{} = {}", super::expr(&law.sign), super::expr(&e));
                let sign = inline(doc, what, latex, e);
                let _ = writeln!(
                    doc.o,
                    "À la limite du glissement en ${p}$, le glissement imminent a le sens que \
                     donne l'hypothèse {} (${sign}$) :",
                    super::escape_text(&h.name)
                );
            }
            _ => {
                let _ = writeln!(
                    doc.o,
                    "Loi de Coulomb en ${p}$, tant que le contact glisse :"
                );
            }
        }
        let value = Value::Scalar(law.values[0].clone());
        doc.show_law(&s.label, &t, &value, &v);
    }
}

/// The laws of Coulomb an equation of motion's other equations hold with them, for the
/// sentence that eliminates the unknowns (« et les lois de Coulomb en $A$ et $B$ »).
pub(super) fn laws_phrase(m: &Mechanism) -> Option<String> {
    let points: Vec<String> = (m.dynamics.laws.iter())
        .map(|l| format!("${}$", point(&m.links[l.link].point)))
        .collect();
    match points.len() {
        0 => None,
        1 => Some(format!("la loi de Coulomb en {}", points[0])),
        _ => Some(format!(
            "les lois de Coulomb en {}",
            super::words::french_list(&points)
        )),
    }
}

/// Before an equation of motion whose eliminated unknowns are quotients that do not divide
/// out (Coulomb's laws tie T to N, so the PFD's system no longer splits): the product of
/// pivots it is multiplied by, stated nonzero and recorded for the proof.
pub(super) fn eom_factor(doc: &mut Doc, id: &str, q: &str) {
    let Some(k) = factor(doc, q) else {
        return;
    };
    let latex = super::expr(&k);
    let _ = writeln!(
        doc.o,
        "Les inconnues éliminées sont des quotients par ${latex}$, supposé non nul : \
         l'équation est multipliée par ce facteur."
    );
    inline(doc, format!("factor of {id}"), latex, k);
}

/// The product of pivots the equation of motion of `q` is multiplied by, where the unknowns
/// it eliminates are quotients that do not divide out (under the hypothesis worked under).
fn factor(doc: &Doc, q: &str) -> Option<crate::expr::Expr> {
    let m = doc.m;
    if m.dynamics.theorems.iter().all(|t| t.eom.is_some()) {
        return None;
    }
    let k = crate::pfd::solve(m).ok()?.eom_factors.remove(q)?;
    let k = doc.under.map_or_else(|| k.clone(), |h| h.apply(&k));
    // A hypothesis may make it a number (f2 = 0): nothing to say then.
    k.as_rational().is_none().then_some(k)
}
