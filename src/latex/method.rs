//! The method a corrigé teaches: each step of a derivation introduced by one typeset sentence
//! applied to the actual objects (« $O_1$ est fixe dans $\mathcal{R}_0$ … »), steps already
//! shown cited instead of re-derived, the dynamic moment at a fixed point written as the
//! derivative of the kinetic moment in one line, and the PFD as a bilan of the external
//! actions followed by one equality per theorem.

use super::omega::omega_sentence;
use super::page::{DisplayRole, Doc};
use super::routes::{
    derived_step, position_route, position_sentence, projected_moment_route, projected_set_route,
};
use super::sentences::sentence;
use super::words::{citation, french_list, mass_of, shown_value, solid, step_lhs};
use super::{frame, point, quantity_tex};
use crate::derivation::{Derivation, StepKind, Value, derive};
use crate::mechanism::{Hypothesis, Mechanism};
use crate::quantity::{Motion, Quantity, QuantityKind};
use std::fmt::Write;

/// The course's names of a torsor's elements: (resultant, moment).
pub(super) fn torsor_names(k: &QuantityKind) -> Option<(String, String)> {
    use QuantityKind::*;
    let (r, mo, p) = match k {
        KinematicTorsor { motion, point } => (
            Omega(motion.clone()),
            Velocity {
                point: point.clone(),
                motion: motion.clone(),
            },
            point,
        ),
        KineticTorsor { motion, point } => (
            KineticResultant(motion.clone()),
            KineticMoment {
                point: point.clone(),
                motion: motion.clone(),
            },
            point,
        ),
        DynamicTorsor { motion, point } => (
            DynamicResultant(motion.clone()),
            DynamicMoment {
                point: point.clone(),
                motion: motion.clone(),
            },
            point,
        ),
        _ => return None,
    };
    let _ = p;
    Some((quantity_tex(&r), quantity_tex(&mo)))
}

/// Writes the steps of a kinematic or kinetic derivation as the course shows them. Returns
/// whether the result was boxed where it was derived (so it is not repeated).
fn steps(doc: &mut Doc, d: &Derivation, result_lhs: &str) -> bool {
    let mut run = StepRun {
        d,
        result_lhs,
        elements: result_elements(d),
        cited: Vec::new(),
        last_is_result: false,
    };
    let n = d.steps.len();
    let mut i = 0;
    while i < n {
        if let Some(next) = run.massless(doc, i) {
            i = next;
            continue;
        }
        if run.dynamic_moment_as_derivative(doc, i) {
            i += 2;
            continue;
        }
        if !skipped_for_point_mass(doc.m, d, i) {
            run.step(doc, i);
        }
        i += 1;
    }
    run.flush(doc);
    run.last_is_result
}

/// (left side, where it was shown, its stage)
type Cited = (String, String, Option<(u8, String)>);

/// The writing of a derivation's steps: the result they lead to, the elements of a torsor
/// result (boxed where they are derived), the values cited since the last step written.
struct StepRun<'d> {
    d: &'d Derivation,
    result_lhs: &'d str,
    /// (left side, components) of a torsor result's resultant and moment.
    elements: Vec<(String, [crate::expr::Expr; 3])>,
    cited: Vec<Cited>,
    /// Whether the result was boxed where it was derived.
    last_is_result: bool,
}

/// The elements of a torsor result: (left side, components) of its resultant and its moment.
fn result_elements(d: &Derivation) -> Vec<(String, [crate::expr::Expr; 3])> {
    match (torsor_names(&d.quantity.kind), &d.value) {
        (
            Some((rn, mn)),
            Value::Torsor {
                resultant, moment, ..
            },
        ) => vec![(rn, resultant.clone()), (mn, moment.clone())],
        _ => Vec::new(),
    }
}

/// A point mass: σ = AP ∧ m V(P) needs neither its Ω nor an inertia operator, so step `i`
/// is not written.
fn skipped_for_point_mass(m: &Mechanism, d: &Derivation, i: usize) -> bool {
    let point_mass = |sn: &str| m.bodies.iter().any(|b| b.name == sn && b.inertia.is_none());
    let next = d.steps.get(i + 1).map(|x| &x.kind);
    match (&d.steps[i].kind, next) {
        (
            StepKind::Quantity(QuantityKind::Omega(mo)),
            Some(StepKind::Quantity(QuantityKind::Inertia { solid, .. })),
        ) => point_mass(&mo.moving) && solid == &mo.moving,
        (StepKind::Quantity(QuantityKind::Inertia { solid, .. }), _) => {
            point_mass(solid)
                && matches!(
                    next,
                    Some(StepKind::Quantity(QuantityKind::KineticMoment { .. }))
                )
        }
        _ => false,
    }
}

/// The left side of a step as displayed: V(A/R) ∧ m2 V(G2/R) with the mass of the solid
/// whose term it is (each solid of a set has its own term, and two solids may share their
/// centre of inertia: the mass is never looked up by the point).
fn displayed_lhs(m: &Mechanism, names: &super::VectorNames, k: &StepKind) -> String {
    match k {
        StepKind::Complementary { solid, .. } => {
            step_lhs(names, k).replace("\\wedge m\\,", &format!("\\wedge {}\\,", mass_of(m, solid)))
        }
        _ => step_lhs(names, k),
    }
}

impl StepRun<'_> {
    /// Whether `lhs = v` is an element of the torsor result (boxed where derived).
    fn is_element(&self, lhs: &str, v: &Value) -> bool {
        match v {
            Value::Vector { components, .. } => self
                .elements
                .iter()
                .any(|(l, c)| l == lhs && c == components),
            _ => false,
        }
    }

    /// The values cited since the last step written, in one sentence.
    fn flush(&mut self, doc: &mut Doc) {
        let cited = &mut self.cited;
        if cited.is_empty() {
            return;
        }
        // A value cited for what it was derived from is enough: δ(O,3/0) already holds
        // Ω(3/0), I_O(3) and σ(O,3/0), cited before it in the same run.
        let kept: Vec<(String, String)> = cited
            .iter()
            .enumerate()
            .filter(|(j, (_, _, stage))| {
                !cited[j + 1..]
                    .iter()
                    .any(|(_, _, later)| match (stage, later) {
                        (Some((r, s)), Some((lr, ls))) => lr > r && ls == s,
                        _ => false,
                    })
            })
            .map(|(_, (l, p, _))| (l.clone(), p.clone()))
            .collect();
        cited.clear();
        let mut by_place: Vec<(String, Vec<String>)> = Vec::new();
        for (lhs, place) in kept {
            match by_place.iter_mut().find(|(p, _)| *p == place) {
                Some((_, v)) => v.push(lhs),
                None => by_place.push((place, vec![lhs])),
            }
        }
        let _ = writeln!(doc.o, "{}", citation(&by_place));
    }

    /// A derivative (step `i`) that is already the dynamic moment (step `i + 1`, no
    /// complementary term): one line, boxed when it is the result. Returns whether it wrote
    /// (or cited) both steps.
    fn dynamic_moment_as_derivative(&mut self, doc: &mut Doc, i: usize) -> bool {
        let (d, m) = (self.d, doc.m);
        let s = &d.steps[i];
        let (StepKind::Derivative(_, r), Some(next)) = (&s.kind, d.steps.get(i + 1)) else {
            return false;
        };
        let StepKind::Quantity(QuantityKind::DynamicMoment {
            point: a,
            motion: mo,
        }) = &next.kind
        else {
            return false;
        };
        if next.value.exprs() != s.value.exprs() {
            return false;
        }
        let v = shown_value(doc, &s.value);
        let delta = doc.names.quantity(&next_kind(&next.kind));
        let lhs = format!("{delta} = {}", step_lhs(&doc.names, &s.kind));
        let why = if mo_centre(m, a, mo) {
            format!("${}$ est le centre d'inertie", point(a))
        } else {
            format!("${}$ est fixe dans ${}$", point(a), frame(r))
        };
        if let Some(place) = doc.cited(&delta, &v) {
            self.cited.push((delta, place, stage(&next.kind)));
        } else {
            self.flush(doc);
            let _ = writeln!(
                doc.o,
                "{why} : le moment dynamique est la dérivée du moment cinétique dans ${}$ (cas particulier du cours) :",
                frame(r)
            );
            // The last step that is the result itself is boxed as the result.
            let is_result = i + 2 == d.steps.len()
                && delta == self.result_lhs
                && next.value.exprs() == d.value.exprs();
            if is_result {
                let id = d.quantity.to_string();
                let hn = doc.under.map(|h| h.name.clone());
                let here = doc.here.clone();
                doc.results
                    .push((d.quantity.clone(), hn.clone(), v.clone(), here));
                doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, &v, None);
                doc.remember(&delta, &v);
                self.last_is_result = true;
            } else {
                let boxed = self.is_element(&delta, &next.value);
                doc.show_keyed(DisplayRole::Step, &next.label, &lhs, &delta, &v, boxed);
            }
        }
        // The derivative's own key too: a later projection cites it.
        let dl = step_lhs(&doc.names, &s.kind);
        doc.remember(&dl, &v);
        true
    }

    /// Step `i`: cited when already shown, its sentence alone when it is the result (the
    /// result's display shows it), else its sentence and display (V(G), Γ(G) first for a
    /// resultant).
    fn step(&mut self, doc: &mut Doc, i: usize) {
        let (d, m) = (self.d, doc.m);
        let s = &d.steps[i];
        let v = shown_value(doc, &s.value);
        let lhs = displayed_lhs(m, &doc.names, &s.kind);
        if let Some(place) = doc.cited(&lhs, &v) {
            self.cited.push((lhs, place, stage(&s.kind)));
            return;
        }
        // The last step is the result itself: the result display (boxed) shows it.
        if i + 1 == d.steps.len() && lhs == self.result_lhs && d.value.exprs() == s.value.exprs() {
            self.flush(doc);
            let _ = writeln!(doc.o, "{}", sentence(m, &doc.names, s));
            return;
        }
        self.flush(doc);
        // Rd = m Γ(G) and Rc = m V(G): the velocity and acceleration of G first.
        if let StepKind::Quantity(QuantityKind::DynamicResultant(mo))
        | StepKind::Quantity(QuantityKind::KineticResultant(mo)) = &s.kind
        {
            let dynamic = matches!(
                s.kind,
                StepKind::Quantity(QuantityKind::DynamicResultant(_))
            );
            if kinematics_of_centre(doc, mo, dynamic, &s.value) {
                // G is fixed: the sentence said the resultant is zero.
                doc.remember(&lhs, &v);
                return;
            }
        }
        let _ = writeln!(doc.o, "{}", sentence(m, &doc.names, s));
        let boxed = self.is_element(&lhs, &s.value);
        doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, boxed);
        if let StepKind::Complementary { solid, .. } = &s.kind {
            doc.names_solid(solid);
        }
    }

    /// The steps from `i` that say a quantity of a body of negligible mass is zero, in one
    /// sentence (« $S_1$ et $S_2$ sont de masse négligeable : leurs moments dynamiques sont
    /// nuls. »), nothing derived for them; when they are the whole derivation of a quantity
    /// of such bodies, the result's box shows the zero. Returns the step after them, if any.
    fn massless(&mut self, doc: &mut Doc, i: usize) -> Option<usize> {
        let steps = &self.d.steps;
        let kinds: Vec<&QuantityKind> = steps[i..]
            .iter()
            .map_while(|s| match &s.kind {
                StepKind::Massless(k) => Some(k),
                _ => None,
            })
            .collect();
        let first = kinds.first()?;
        self.flush(doc);
        let names: Vec<String> = kinds
            .iter()
            .filter_map(|k| massless_solid(k))
            .map(|n| format!("${}$", solid(&n)))
            .collect();
        let (noun, feminine) = massless_noun(first);
        let _ = writeln!(
            doc.o,
            "{}\n",
            massless_sentence(&french_list(&names), names.len() > 1, noun, feminine)
        );
        Some(i + kinds.len())
    }
}

/// The solid a quantity of a body of negligible mass is of.
fn massless_solid(k: &QuantityKind) -> Option<String> {
    match k {
        QuantityKind::Inertia { solid, .. } => Some(solid.clone()),
        _ => k.motion().map(|mo| mo.moving.clone()),
    }
}

/// The noun of a quantity that a zero mass makes zero, and whether it is feminine.
fn massless_noun(k: &QuantityKind) -> (&'static str, bool) {
    use QuantityKind::*;
    match k {
        KineticMoment { .. } => ("moment cinétique", false),
        DynamicMoment { .. } => ("moment dynamique", false),
        KineticTorsor { .. } => ("torseur cinétique", false),
        DynamicTorsor { .. } => ("torseur dynamique", false),
        KineticResultant(_) => ("résultante cinétique", true),
        DynamicResultant(_) => ("résultante dynamique", true),
        KineticEnergy(_) => ("énergie cinétique", true),
        _ => ("opérateur d'inertie", false),
    }
}

/// « $S_1$ est de masse négligeable : son moment dynamique est nul. », or for several
/// solids « … sont de masse négligeable : leurs moments dynamiques sont nuls. »
pub(super) fn massless_sentence(who: &str, several: bool, noun: &str, feminine: bool) -> String {
    let e = if feminine { "le" } else { "" };
    if several {
        let plural: Vec<String> = noun.split(' ').map(plural_word).collect();
        format!(
            "{who} sont de masse négligeable : leurs {} sont nul{e}s.",
            plural.join(" ")
        )
    } else {
        let its = if feminine && !noun.starts_with(['é', 'e']) {
            "sa"
        } else {
            "son"
        };
        format!("{who} est de masse négligeable : {its} {noun} est nul{e}.")
    }
}

/// The plural of a word of these nouns (« moment » → « moments », « d'inertie » kept).
fn plural_word(w: &str) -> String {
    if w.starts_with("d'") {
        w.to_string()
    } else {
        format!("{w}s")
    }
}

/// Where a step stands in the derivation of a solid's dynamics, and of which solid: Ω, V,
/// Γ and I first (1), then σ and Rc (2), then δ and Rd (3). A later stage of the same solid
/// was derived from the earlier ones.
fn stage(k: &StepKind) -> Option<(u8, String)> {
    use QuantityKind as Q;
    let StepKind::Quantity(q) = k else {
        return None;
    };
    match q {
        Q::Omega(mo) | Q::Velocity { motion: mo, .. } | Q::Acceleration { motion: mo, .. } => {
            Some((1, mo.moving.clone()))
        }
        Q::Inertia { solid, .. } => Some((1, solid.clone())),
        Q::KineticResultant(mo) | Q::KineticMoment { motion: mo, .. } => {
            Some((2, mo.moving.clone()))
        }
        Q::DynamicResultant(mo) | Q::DynamicMoment { motion: mo, .. } => {
            Some((3, mo.moving.clone()))
        }
        _ => None,
    }
}

fn next_kind(k: &StepKind) -> QuantityKind {
    match k {
        StepKind::Quantity(q) => q.clone(),
        _ => unreachable!("called on a quantity step"),
    }
}

/// Whether `a` is the centre of inertia of the moving solid.
fn mo_centre(m: &Mechanism, a: &str, mo: &Motion) -> bool {
    m.bodies
        .iter()
        .any(|b| b.name == mo.moving && m.point_name(b.centre) == a)
}

/// V(G) (derivative of the position from the ground origin) and Γ(G) (derivative of V(G)),
/// shown before the resultant m V(G) or m Γ(G), in the basis of the resultant. Returns
/// whether G is fixed (the resultant is then said to be zero).
fn kinematics_of_centre(doc: &mut Doc, mo: &Motion, dynamic: bool, res: &Value) -> bool {
    let m = doc.m;
    let Some(body) = m.bodies.iter().find(|b| b.name == mo.moving) else {
        return false;
    };
    let Value::Vector { basis: b, .. } = res else {
        return false;
    };
    let g = m.point_name(body.centre).to_string();
    let bn = m.frame_name(*b).to_string();
    let o = m.point_name(m.points.origin()).to_string();
    let r = &mo.reference;
    // The position is taken from the ground origin, fixed only in the ground frame.
    if m.frames.find(r) != Some(m.frames.ground()) {
        return false;
    }
    let in_b = |kind: QuantityKind| Quantity {
        kind,
        basis: Some(bn.clone()),
        projection: None,
        linear: false,
    };
    let vq = in_b(QuantityKind::Velocity {
        point: g.clone(),
        motion: mo.clone(),
    });
    let vlhs = quantity_tex(&vq.kind);
    // G fixed: one sentence says the resultant is zero.
    if let Ok(vd) = derive(m, &vq)
        && vd.value.exprs().iter().all(|e| e.is_zero())
    {
        let vv = shown_value(doc, &vd.value);
        if doc.cited(&vlhs, &vv).is_none() {
            let _ = writeln!(
                doc.o,
                "${}$ est fixe dans ${}$ : ${} = \\TVec{{0}}$, donc la résultante est nulle.\n",
                point(&g),
                frame(r),
                vlhs
            );
            doc.remember(&vlhs, &vv);
        }
        return true;
    }
    if derived_step(doc, &vq, &vlhs, &position_sentence(&vlhs, &o, &g, r)).is_none() || !dynamic {
        return false;
    }
    let aq = in_b(QuantityKind::Acceleration {
        point: g.clone(),
        motion: mo.clone(),
    });
    let alhs = quantity_tex(&aq.kind);
    let sentence = format!("${alhs} = \\TDeriv{{{}}}{{{vlhs}}}$ :", frame(r));
    derived_step(doc, &aq, &alhs, &sentence);
    false
}

/// A requested quantity of the kinematics or kinetics: its steps, then the boxed result.
pub(super) fn quantity_block(doc: &mut Doc, d: &Derivation, title: &str, lhs: &str) {
    let _ = writeln!(doc.o, "\\TTitre{{${title}$}}");
    // A projection asked alone is computed by the short route when all its steps were not
    // already shown.
    let all_shown = d.steps.iter().all(|s| {
        let v = shown_value(doc, &s.value);
        doc.cited(&step_lhs(&doc.names, &s.kind), &v).is_some()
    });
    let last_is_result =
        if !all_shown && (projected_moment_route(doc, d) || projected_set_route(doc, d)) {
            false
        } else {
            position_route(doc, d);
            steps(doc, d, lhs)
        };
    method_notes(doc, d);
    let names = torsor_names(&d.quantity.kind);
    for h in result_hypotheses(doc) {
        let v = match h {
            Some(h) => d.value_under(doc.m, h),
            None => d.value.clone(),
        };
        if doc.under.is_none()
            && let Some(h) = h
        {
            if v.exprs() == d.value.exprs() {
                let _ = writeln!(
                    doc.o,
                    "Sous l'hypothèse {}, le résultat est inchangé.\n",
                    super::escape_text(&h.name)
                );
                continue;
            }
            let _ = writeln!(doc.o, "Sous l'hypothèse {} :", super::escape_text(&h.name));
        }
        let hn = h.map(|h| h.name.clone());
        if let Some(names) = &names
            && torsor_by_its_elements(doc, d, lhs, names, hn.clone(), &v)
        {
            continue;
        }
        if h.is_none() && last_is_result {
            // Already boxed where it was derived.
            continue;
        }
        let id = d.quantity.to_string();
        if names.is_none() || !matches!(v, Value::Torsor { .. }) {
            let here = doc.here.clone();
            doc.results
                .push((d.quantity.clone(), hn.clone(), v.clone(), here));
        }
        doc.show_result(
            DisplayRole::Result,
            &id,
            hn.as_deref(),
            lhs,
            &v,
            names.as_ref(),
        );
    }
}

/// What the method says beyond its steps, before the result: Huygens for I_A(S) at a point
/// other than G, the composition for Ω asked alone, the sentence of an action or of a
/// kinetic energy.
fn method_notes(doc: &mut Doc, d: &Derivation) {
    let m = doc.m;
    super::loop_law::rate_note(doc, d);
    // I_A(S) at a point other than G: Huygens, named before the result.
    if let QuantityKind::Inertia {
        point: a,
        solid: sn,
    } = &d.quantity.kind
        && let Some(b) = m.bodies.iter().find(|b| &b.name == sn)
        && m.point_name(b.centre) != a
        && b.inertia.is_some()
    {
        let g = m.point_name(b.centre).to_string();
        let _ = writeln!(
            doc.o,
            "Théorème de Huygens, de ${}$ en ${}$ ($I_{{{}}}({sn}) = I_{{{}}}({sn})$ + terme de transport de ${}$) :",
            point(&g),
            point(a),
            point(a),
            point(&g),
            mass_of(m, sn)
        );
    }
    // I_A(E) of a set: the sum of its solids' operators at the same point, said in words
    // before the result (each solid's operator is a step above).
    if let QuantityKind::Inertia {
        point: a,
        solid: sn,
    } = &d.quantity.kind
        && let Some(members) = m.sets.get(sn)
    {
        let names: Vec<String> = (members.iter())
            .map(|&b| format!("${}$", solid(&m.body(b).name)))
            .collect();
        let _ = writeln!(
            doc.o,
            "L'opérateur d'inertie de ${}$ en ${}$ est la somme de ceux de {} en ${}$ :",
            solid(sn),
            point(a),
            french_list(&names),
            point(a)
        );
    }
    // Ω asked by itself has no steps: its method is the composition along the frames (or
    // the paramétrage, for one rotation).
    if let QuantityKind::Omega(mo) = &d.quantity.kind
        && d.steps.is_empty()
    {
        let _ = writeln!(doc.o, "{}", omega_sentence(m, mo));
    }
    if let Some(s) = super::action_method::action_sentence(m, d)
        .or_else(|| super::action_method::kinetic_energy_sentence(m, d))
    {
        let _ = writeln!(doc.o, "{s}");
    }
}

/// The hypotheses a result is shown under: the question's; or in general, then under each
/// hypothesis stated so far (never before its question).
fn result_hypotheses<'m>(doc: &Doc<'m>) -> Vec<Option<&'m Hypothesis>> {
    match doc.under {
        Some(h) => vec![Some(h)],
        None => std::iter::once(None)
            .chain(
                doc.m
                    .hypotheses
                    .iter()
                    .filter(|h| doc.is_stated(&h.name))
                    .map(Some),
            )
            .collect(),
    }
}

/// A torsor result `v` (under `hn`) whose elements `names` were just shown: recorded, and,
/// when they are long and both boxed above, its notation written instead of its values
/// again. Returns whether it was written so.
fn torsor_by_its_elements(
    doc: &mut Doc,
    d: &Derivation,
    lhs: &str,
    (rn, mn): &(String, String),
    hn: Option<String>,
    v: &Value,
) -> bool {
    let Value::Torsor {
        basis,
        resultant,
        moment,
        point: p,
    } = v
    else {
        return false;
    };
    let res = Value::Vector {
        basis: *basis,
        components: resultant.clone(),
    };
    let mom = Value::Vector {
        basis: *basis,
        components: moment.clone(),
    };
    let here = doc.here.clone();
    doc.results.push((d.quantity.clone(), hn, v.clone(), here));
    let short = resultant
        .iter()
        .chain(moment.iter())
        .all(|e| e.nterms() <= 1);
    if short || doc.cited(rn, &res).is_none() || doc.cited(mn, &mom).is_none() {
        return false;
    }
    let _ = writeln!(
        doc.o,
        "D'où ${lhs} = \\TTorseur{{\\begin{{array}}{{l}} {rn} \\\\ {mn} \\end{{array}}}}{{{}}}$, ses éléments de réduction étant encadrés ci-dessus.\n",
        point(doc.m.point_name(*p))
    );
    doc.remember(lhs, v);
    true
}
