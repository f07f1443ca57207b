//! The PFD in the answer key: the bilan of the external actions once per isolated system, each
//! theorem as its two sides, then the unknown or the equation of motion, boxed.

use super::page::{DisplayRole, Doc};
use super::words::{shown_value, solid, step_lhs};
use super::{name, point};
use crate::derivation::{Derivation, Step, StepKind, Value};
use crate::quantity::QuantityKind;
use std::fmt::Write;

/// The PFD: for each theorem, the bilan of the external actions (once per isolated system),
/// the theorem as one equality (dynamic side, actions), then the unknown or the equation of
/// motion.
pub(super) fn pfd_block(doc: &mut Doc, d: &Derivation, title: &str) {
    let _ = writeln!(doc.o, "\\TTitre{{${title}$}}");
    if linearised_from_above(doc, d) {
        return;
    }
    let steps = &d.steps;
    let mut k = 0;
    let mut last_equality: Option<(Value, Value)> = None;
    // The system the previous theorem isolated: the next one on the same system does not
    // say « On isole S » again.
    let mut isolated: Option<&str> = None;
    while k < steps.len() {
        match theorem_at(doc, d, k, &mut isolated, &mut last_equality) {
            Written::Theorem { next } => k = next,
            Written::Unknown => return,
            Written::End { at } => {
                k = at;
                break;
            }
        }
    }
    super::coulomb::law_steps(doc, &steps[k.min(steps.len())..]);
    pfd_result(doc, d, last_equality);
}

/// What writing the theorem that starts at a step did.
enum Written {
    /// A theorem; the next one starts at the step `next`.
    Theorem { next: usize },
    /// The theorem gave the unknown asked at once: the PFD is written.
    Unknown,
    /// No theorem starts at the step `at` (after the actions): what is left is the laws'.
    End { at: usize },
}

/// The theorem whose steps start at `start` (its actions, then its dynamic side and its
/// external actions, or the kinetic energy theorem's powers, energy and power side), the
/// bilan of its system first unless the previous theorem isolated it (`isolated`); its
/// equality (dynamic side, actions), when it has one, in `last_equality`.
fn theorem_at<'d>(
    doc: &mut Doc,
    d: &'d Derivation,
    start: usize,
    isolated: &mut Option<&'d str>,
    last_equality: &mut Option<(Value, Value)>,
) -> Written {
    let steps = &d.steps;
    let k = start
        + (steps[start..].iter())
            .take_while(|s| matches!(s.kind, StepKind::Action { .. }))
            .count();
    let actions = &steps[start..k];
    // The kinetic energy theorem: its powers, its energy, then its power side.
    if let Some(e) = energy_group(&steps[k..]).map(|e| e + k) {
        let StepKind::Powers { isolate, .. } = &steps[e].kind else {
            return Written::End { at: k };
        };
        isolate_once(doc, isolated, isolate, &solid(isolate), actions);
        *last_equality = super::energy::energy_theorem(doc, &steps[k..=e]);
        return Written::Theorem { next: e + 1 };
    }
    let (Some(dyn_step), Some(ext_step)) = (steps.get(k), steps.get(k + 1)) else {
        return Written::End { at: k };
    };
    let StepKind::External {
        isolate,
        point: at,
        on: (f, a),
    } = &ext_step.kind
    else {
        return Written::End { at: k };
    };
    let iso_name = solid(isolate);
    isolate_once(doc, isolated, isolate, &iso_name, actions);
    let mut title = theorem_title(&doc.names, &iso_name, at.as_deref(), f, *a);
    let (massless, massive) = members_by_mass(doc.m, isolate);
    if massive.is_empty() {
        // Of negligible mass: the dynamic torsor is zero, the theorem is the balance of
        // the actions.
        let ev = shown_value(doc, &ext_step.value);
        let el = step_lhs(&doc.names, &ext_step.kind);
        let iso = (isolate.as_str(), massless.as_slice());
        massless_theorem(doc, &ext_step.label, iso, &title, (&el, &ev));
        *last_equality = Some((Value::Scalar(doc.m.reg.zero()), ev));
        return Written::Theorem { next: k + 2 };
    }
    if !massless.is_empty() {
        title.push_str(&massless_members(&massless, &massive));
    }
    let theorem = Theorem {
        title,
        dynamic: (
            step_lhs(&doc.names, &dyn_step.kind),
            shown_value(doc, &dyn_step.value),
        ),
        external: (
            step_lhs(&doc.names, &ext_step.kind),
            shown_value(doc, &ext_step.value),
        ),
    };
    // When the actions reduce to the unknown asked (C_m), the theorem gives it at once.
    if k + 2 == steps.len() && unknown_at_once(doc, d, &theorem) {
        return Written::Unknown;
    }
    // Its dynamic side shown already (a question asked it, or an earlier theorem wrote it)
    // and longer than half a line: cited, only the actions written (a short one, M ẍ, is
    // clearer written again).
    let long = match &theorem.dynamic.1 {
        Value::Scalar(e) => super::width(&super::expr(e)) > doc.line / 2,
        _ => true,
    };
    if let Some(place) = doc
        .cited(&theorem.dynamic.0, &theorem.dynamic.1)
        .filter(|_| long)
    {
        *last_equality = Some(cited_dynamic_side(doc, &ext_step.label, theorem, &place));
        return Written::Theorem { next: k + 2 };
    }
    *last_equality = Some(theorem_equality(doc, &dyn_step.label, theorem));
    Written::Theorem { next: k + 2 }
}

/// The bilan of the external actions to `isolate` (its `actions`), unless the previous
/// theorem isolated it too (`isolated`, which then names it).
fn isolate_once<'d>(
    doc: &mut Doc,
    isolated: &mut Option<&'d str>,
    isolate: &'d str,
    iso_name: &str,
    actions: &[Step],
) {
    if *isolated != Some(isolate) {
        external_bilan(doc, isolate, iso_name, actions);
    }
    *isolated = Some(isolate);
}

/// What a theorem's title adds when members of the isolated system are of negligible mass:
/// they add nothing to the dynamic side.
fn massless_members(massless: &[String], massive: &[String]) -> String {
    format!(
        " ({} {} de masse négligeable : seul{} {} contribue{} au côté dynamique)",
        solids_list(massless),
        if massless.len() > 1 { "sont" } else { "est" },
        if massive.len() > 1 { "s" } else { "" },
        solids_list(massive),
        if massive.len() > 1 { "nt" } else { "" },
    )
}

/// A theorem as one equality, its title first (« …, $dl = el$ : »), then its dynamic side
/// and its actions each on its line; returns their values (dynamic side, actions).
fn theorem_equality(doc: &mut Doc, what: &str, theorem: Theorem) -> (Value, Value) {
    let Theorem {
        title,
        dynamic: (dl, dv),
        external: (el, ev),
    } = theorem;
    let _ = writeln!(doc.o, "{title}, ${dl} = {el}$ :");
    doc.show_equality(DisplayRole::Step, what, &dl, &dv, &el, &ev, false);
    (dv, ev)
}

/// A theorem whose dynamic side was shown at `place`: its title and equality, that side
/// cited, then the actions' side alone on its line; returns their values (dynamic side,
/// actions).
fn cited_dynamic_side(doc: &mut Doc, what: &str, theorem: Theorem, place: &str) -> (Value, Value) {
    let Theorem {
        title,
        dynamic: (dl, dv),
        external: (el, ev),
    } = theorem;
    let place = match place {
        "ce qui précède" => "ci-dessus".to_string(),
        p => format!("dans {p}"),
    };
    let _ = writeln!(
        doc.o,
        "{title}, ${dl} = {el}$, avec ${dl}$ établi {place} :"
    );
    doc.show_keyed(DisplayRole::Step, what, &el, &el, &ev, false);
    (dv, ev)
}

/// The index in `steps` of the power side of a kinetic energy theorem starting there, when
/// one does (no action and no other theorem's side before it).
fn energy_group(steps: &[Step]) -> Option<usize> {
    let e = (steps.iter()).position(|s| matches!(s.kind, StepKind::Powers { .. }))?;
    let other = |s: &Step| matches!(s.kind, StepKind::Action { .. } | StepKind::External { .. });
    (!steps[..e].iter().any(other)).then_some(e)
}

/// The members of the isolated system `isolate` (a solid or a set), by name: those of
/// negligible mass, then the others.
fn members_by_mass(m: &crate::mechanism::Mechanism, isolate: &str) -> (Vec<String>, Vec<String>) {
    let mut out = (Vec::new(), Vec::new());
    for s in m.solids_of(isolate).unwrap_or_default() {
        let b = m.body(s);
        if b.massless {
            out.0.push(b.name.clone());
        } else {
            out.1.push(b.name.clone());
        }
    }
    out
}

/// « $S_1$ et $S_2$ ».
fn solids_list(names: &[String]) -> String {
    let items: Vec<String> = names.iter().map(|n| format!("${}$", solid(n))).collect();
    super::words::french_list(&items)
}

/// The theorem `title` applied to a system of negligible mass (`isolate`, its solids
/// `members`): its dynamic torsor is zero, so the theorem is the balance of the external
/// actions, « $\overrightarrow{M(O,\bar{2}\rightarrow 2)}\cdot\vec{x}_2 = 0$ », shown
/// with their value `ev` (left side `el`).
fn massless_theorem(
    doc: &mut Doc,
    what: &str,
    (isolate, members): (&str, &[String]),
    title: &str,
    (el, ev): (&str, &Value),
) {
    let m = doc.m;
    let dynamic = format!(
        "\\TTorseur{{\\mathcal{{D}}(\\TMvt{{{}}}{{{}}})}}{{}} = \\left\\{{0\\right\\}}",
        super::escape_ident(isolate),
        super::escape_ident(m.frame_name(m.frames.ground()))
    );
    let verb = if members.len() > 1 { "sont" } else { "est" };
    let _ = writeln!(
        doc.o,
        "{} {verb} de masse négligeable : ${dynamic}$. {title}, ${el} = 0$ :",
        solids_list(members)
    );
    let Value::Scalar(e) = ev else { return };
    let zero = Value::Scalar(m.reg.zero());
    let body = format!("{} &= 0", super::expr(e));
    doc.record_equality(DisplayRole::Step, what, body, ev, zero);
}

/// One theorem of the PFD: its title (« Théorème du moment dynamique appliqué à … »), its
/// dynamic side and its external actions, each as (left side, value shown).
struct Theorem {
    title: String,
    dynamic: (String, Value),
    external: (String, Value),
}

/// « On isole S ; » and the bilan of the external actions to `isolate` (its `actions`): written
/// the first time, each action's line and torsor side by side when short, those already
/// shown cited; later, where it was written.
fn external_bilan(doc: &mut Doc, isolate: &str, iso_name: &str, actions: &[Step]) {
    if let Some(place) = doc.bilans.get(isolate).cloned() {
        let place = if place == doc.here {
            "établi ci-dessus".to_string()
        } else {
            format!("celui de {place}")
        };
        let what = isolated_words(doc.m, isolate, iso_name);
        let _ = writeln!(
            doc.o,
            "On isole {what} ; le bilan des actions mécaniques extérieures est {place}.\n"
        );
        return;
    }
    let m = doc.m;
    let what = isolated_words(m, isolate, iso_name);
    let _ = writeln!(
        doc.o,
        "On isole {what}. Bilan des actions mécaniques extérieures à ${iso_name}$ :"
    );
    // Actions already shown (asked as quantities above) are cited, not repeated.
    let mut by_place: Vec<(String, Vec<String>)> = Vec::new();
    for s in actions {
        let lhs = step_lhs(&doc.names, &s.kind);
        if let Some(place) = doc.cited(&lhs, &shown_value(doc, &s.value)) {
            match by_place.iter_mut().find(|(p, _)| *p == place) {
                Some((_, v)) => v.push(lhs),
                None => by_place.push((place, vec![lhs])),
            }
        }
    }
    if !by_place.is_empty() {
        // After « Bilan … à $S_1$ : », the sentence goes on in lower case.
        let c = super::words::citation(&by_place).replacen("On reprend", "on reprend", 1);
        let _ = writeln!(doc.o, "{c}");
    }
    // Each action's line and torsor, side by side when they are short.
    let mut cells = Vec::new();
    let mut widths = Vec::new();
    for s in actions {
        let text = action_line(m, &doc.names, s);
        let v = shown_value(doc, &s.value);
        let lhs = step_lhs(&doc.names, &s.kind);
        if doc.cited(&lhs, &v).is_some() {
            continue;
        }
        cells.push(doc.capture(|doc| {
            let _ = writeln!(doc.o, "{text} :");
            doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, false);
        }));
        widths.push(doc.last_width());
    }
    doc.rows(&cells, &widths, 3);
    super::coulomb::state_laws(doc, actions);
    let here = doc.here.clone();
    doc.bilans.insert(isolate.to_string(), here);
}

/// What « On isole » names: the system (`iso_name`), or for a carrier isolated with the
/// solids it carries (`1+2`), « $S_1$, avec la masse ponctuelle $S_2$ qu'il porte ».
fn isolated_words(m: &crate::mechanism::Mechanism, isolate: &str, iso_name: &str) -> String {
    let mut parts = isolate.split('+');
    let head = parts.next().unwrap_or(isolate);
    let carried: Vec<String> = parts
        .filter_map(|c| m.find_body(c))
        .map(|c| {
            let body = m.body(c);
            let noun = if body.inertia.is_none() {
                "la masse ponctuelle"
            } else {
                "le solide"
            };
            let by = body.carried_by.map(|k| m.body(k).name.as_str());
            match by {
                Some(k) if k == head => format!("{noun} ${}$ qu'il porte", solid(&body.name)),
                Some(k) => format!("{noun} ${}$ que porte ${}$", solid(&body.name), solid(k)),
                None => format!("{noun} ${}$", solid(&body.name)),
            }
        })
        .collect();
    if carried.is_empty() {
        return format!("${iso_name}$");
    }
    let list = super::words::french_list(&carried);
    format!("${}$, avec {list}", solid(head))
}

/// The theorem applied to the isolated system, at `at` (moment) or not (resultant), in
/// projection on the axis `a` of `f`.
fn theorem_title(
    names: &super::VectorNames,
    iso_name: &str,
    at: Option<&str>,
    f: &str,
    a: char,
) -> String {
    match at {
        Some(p) => format!(
            "Théorème du moment dynamique appliqué à ${iso_name}$ en ${}$, en projection sur ${}$",
            point(p),
            names.basis_vector(a, f)
        ),
        None => format!(
            "Théorème de la résultante dynamique appliqué à ${iso_name}$, en projection sur ${}$",
            names.basis_vector(a, f)
        ),
    }
}

/// When the last theorem's actions reduce to the unknown asked (C_m), the theorem gives it
/// at once: « C_m = δ(O1,E/0)·z0 », boxed, without writing the dynamic side twice; or, the
/// dynamic side being boxed already, that value said in words. Returns whether it did.
fn unknown_at_once(doc: &mut Doc, d: &Derivation, theorem: &Theorem) -> bool {
    let Theorem {
        title,
        dynamic: (dl, dv),
        external: (el, ev),
    } = theorem;
    let (QuantityKind::Unknown(u), Value::Scalar(e)) = (&d.quantity.kind, ev) else {
        return false;
    };
    if doc.m.reg.param(u).as_ref() != Some(e) {
        return false;
    }
    let id = d.quantity.to_string();
    let hn = doc.under.map(|h| h.name.clone());
    // The dynamic side was just boxed (asked as a quantity of its own): the unknown is that
    // value, said in words rather than printed a second time.
    if let Some(place) = doc.cited(dl, dv) {
        let place = if place == "ce qui précède" {
            "encadrée plus haut".to_string()
        } else {
            format!("encadrée dans {place}")
        };
        let _ = writeln!(
            doc.o,
            "{title}, ${dl} = {el}$, soit ${} = {dl}$ (valeur {place}).\n",
            name(u)
        );
        doc.results
            .push((d.quantity.clone(), hn, dv.clone(), doc.here.clone()));
        return true;
    }
    let _ = writeln!(doc.o, "{title}, ${dl} = {el}$, soit :");
    let here = doc.here.clone();
    doc.results
        .push((d.quantity.clone(), hn.clone(), dv.clone(), here));
    let lhs = format!("{} = {dl}", name(u));
    doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, dv, None);
    true
}

/// The PFD's result, recorded and boxed: the equation of motion (see [`eom_result`]), or the
/// unknown after the conditions of the solution.
fn pfd_result(doc: &mut Doc, d: &Derivation, last_equality: Option<(Value, Value)>) {
    let id = d.quantity.to_string();
    let v = shown_value(doc, &d.value);
    let hn = doc.under.map(|h| h.name.clone());
    let here = doc.here.clone();
    doc.results
        .push((d.quantity.clone(), hn.clone(), v.clone(), here));
    match &d.quantity.kind {
        QuantityKind::Eom(q) => {
            if let Value::Scalar(e) = &v {
                eom_result(doc, &d.quantity, q, e, &last_equality);
            }
        }
        _ => {
            if matches!(d.quantity.kind, QuantityKind::Unknown(_)) {
                state_conditions(doc);
            }
            let lhs = doc.names.quantity(&d.quantity.kind);
            doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, &v, None);
        }
    }
}

/// The equation of motion `e` in `q`, boxed in the course's form (dynamic side, each
/// acceleration once, = actions, and its J_eq form: [`super::motion::show`]; the theorem's
/// equality when `e` is not linear in the accelerations), its first integral, and the
/// equation under each hypothesis stated so far.
fn eom_result(
    doc: &mut Doc,
    quantity: &crate::quantity::Quantity,
    q: &str,
    e: &crate::expr::Expr,
    last_equality: &Option<(Value, Value)>,
) {
    let id = &quantity.to_string();
    let m = doc.m;
    let hn = doc.under.map(|h| h.name.clone());
    if let Some((_, Value::Scalar(actions))) = last_equality
        && let Some(s) = eliminated(m, &doc.names, actions)
    {
        let _ = writeln!(doc.o, "{s}");
    }
    super::coulomb::eom_factor(doc, id, q);
    if let Some(s) = super::energy::divided_by_rate(doc, q) {
        let _ = writeln!(doc.o, "{s}");
    }
    let _ = writeln!(doc.o, "D'où l'équation du mouvement en ${}$ :", name(q));
    if !super::motion::show(doc, (id, hn.as_deref()), e, q, true) {
        let (lhs, rhs) = upright(match last_equality {
            Some((Value::Scalar(a), Value::Scalar(b))) if &(a - b) == e => (a.clone(), b.clone()),
            _ => split_equation(e),
        });
        doc.show_equation(DisplayRole::Result, id, hn.as_deref(), &lhs, &rhs);
    }
    if let Some(f) = first_integral(e) {
        let math = super::expr(&f);
        let _ = writeln!(
            doc.o,
            "Intégrale première : cette équation dit que la dérivée par rapport au temps de \
             ${math}$ est nulle ; cette quantité se conserve.\n"
        );
        doc.inline.push(super::Inline {
            what: format!("first integral of {id}"),
            latex: math,
            value: Value::Scalar(f),
        });
    }
    // Under each hypothesis stated so far, as the other results are.
    if doc.under.is_none() {
        eom_under_stated(doc, quantity, e);
    }
}

/// The equation of motion `e` (of the quantity `q`, linearised or not) under each hypothesis
/// stated so far: unchanged, identically satisfied (no « 0 = 0 » in a box), or boxed.
fn eom_under_stated(doc: &mut Doc, q: &crate::quantity::Quantity, e: &crate::expr::Expr) {
    let m = doc.m;
    let QuantityKind::Eom(own) = &q.kind else {
        return;
    };
    let id = &q.to_string();
    let stated: Vec<_> = m
        .hypotheses
        .iter()
        .filter(|h| doc.is_stated(&h.name))
        .collect();
    for h in stated {
        let eh = crate::derivation::value_under(m, q, &Value::Scalar(e.clone()), h);
        let Value::Scalar(eh) = eh else {
            unreachable!("a scalar stays one")
        };
        let hname = super::escape_text(&h.name);
        if eh == *e {
            let _ = writeln!(doc.o, "Sous l'hypothèse {hname}, elle est inchangée.\n");
            continue;
        }
        // An equilibrium (or an imposed motion) that the equation admits: no « 0 = 0 » in a
        // box.
        if eh.is_zero() {
            let _ = writeln!(
                doc.o,
                "Sous l'hypothèse {hname}, l'équation est identiquement vérifiée : \
                 le mouvement que pose l'hypothèse en est une solution.\n"
            );
            continue;
        }
        let _ = writeln!(doc.o, "Sous l'hypothèse {hname} :");
        doc.results.push((
            q.clone(),
            Some(h.name.clone()),
            Value::Scalar(eh.clone()),
            doc.here.clone(),
        ));
        show_eom(doc, (id, Some(&h.name)), &eh, own);
    }
}

/// Once, before the first unknown: the pivots of the PFD's solution that are not numbers,
/// each stated nonzero (« elle suppose $L \neq 0$ »), each formula recorded for the proof.
fn state_conditions(doc: &mut Doc) {
    if doc.conditions_stated {
        return;
    }
    doc.conditions_stated = true;
    let Ok(sol) = crate::pfd::solve(doc.m) else {
        return;
    };
    if let Some(h) = &sol.hyperstatic {
        super::hyperstatic::state(doc, h);
    }
    if sol.conditions.is_empty() {
        return;
    }
    let mut said = Vec::new();
    // Under the hypothesis worked under (1 + f1 f2 at the limit of sliding), numbers left out.
    let conditions: Vec<crate::expr::Expr> = (sol.conditions.iter())
        .map(|c| doc.under.map_or_else(|| c.clone(), |h| h.apply(c)))
        .filter(|c| c.as_rational().is_none())
        .collect();
    if conditions.is_empty() {
        return;
    }
    for c in &conditions {
        let latex = super::expr(c);
        said.push(format!("${latex}$"));
        doc.inline.push(super::Inline {
            what: format!("divisor {c}"),
            latex,
            value: Value::Scalar(c.clone()),
        });
    }
    // As a teacher says it: what solving the whole system divides by (for one unknown or
    // another, not necessarily the one shown next), assumed nonzero.
    let (assumed, nonzero) = if said.len() == 1 {
        ("supposé", "non nul")
    } else {
        ("supposés", "non nuls")
    };
    let _ = writeln!(
        doc.o,
        "La résolution du système des équations du PFD divise par {}, {assumed} {nonzero}.\n",
        said.join(" et ")
    );
}

/// A linearised equation of motion whose full equation was just boxed: the small-motion
/// hypothesis in words, then the linear equation boxed, without repeating the theorem.
fn linearised_from_above(doc: &mut Doc, d: &Derivation) -> bool {
    let m = doc.m;
    // Under a hypothesis with small parameters: one combined first order.
    let v = match doc.under {
        Some(h) => d.value_under(m, h),
        None => d.value.clone(),
    };
    let (QuantityKind::Eom(q), true, Value::Scalar(e)) = (&d.quantity.kind, d.quantity.linear, &v)
    else {
        return false;
    };
    let full = crate::quantity::Quantity {
        linear: false,
        ..d.quantity.clone()
    }
    .to_string();
    let hn = doc.under.map(|h| h.name.clone());
    if !doc
        .results
        .iter()
        .any(|r| r.0.to_string() == full && r.1 == hn)
    {
        return false;
    }
    let small: Vec<String> = m
        .dynamics
        .small
        .iter()
        .map(|s| {
            let c = name(&m.reg.coord_info(s.coord).name);
            format!("${c}$ autour de ${}$", super::expr(&s.around))
        })
        .collect();
    let _ = writeln!(
        doc.o,
        "Pour de petits mouvements ({}), au premier ordre ($\\sin$ d'un petit angle remplacé \
         par l'angle, $\\cos$ par 1, les produits de petites quantités négligés), l'équation \
         du mouvement en ${}$ devient :",
        super::words::french_list(&small),
        name(q)
    );
    let id = d.quantity.to_string();
    doc.results
        .push((d.quantity.clone(), hn.clone(), v.clone(), doc.here.clone()));
    show_eom(doc, (&id, hn.as_deref()), e, q);
    if doc.under.is_none() {
        eom_under_stated(doc, &d.quantity, e);
    }
    true
}

/// The equation of motion `e` = 0 in `q`, boxed in the course's form (see
/// [`super::motion::show`], without the J_eq form), else as rates = the rest.
fn show_eom(doc: &mut Doc, (id, hyp): (&str, Option<&str>), e: &crate::expr::Expr, q: &str) {
    if !super::motion::show(doc, (id, hyp), e, q, false) {
        let (lhs, rhs) = upright(split_equation(e));
        doc.show_equation(DisplayRole::Result, id, hyp, &lhs, &rhs);
    }
}

/// The bilan's line for an action, typeset: a link's action is named by its kind and
/// geometry (« liaison pivot d'axe $(O_1, \vec{z}_0)$, action de $S_0$ sur $S_1$ »); other
/// actions keep the derivation's wording (« pesanteur sur $S_1$ », « le moteur, action sur
/// $S_1$ »).
fn bilan_text(
    m: &crate::mechanism::Mechanism,
    names: &super::VectorNames,
    s: &crate::derivation::Step,
) -> String {
    if let StepKind::Action {
        from, on, point, ..
    } = &s.kind
    {
        let between = |l: &&crate::mechanism::Link| {
            (l.between[0] == *from && l.between[1] == *on)
                || (l.between[0] == *on && l.between[1] == *from)
        };
        let mut links: Vec<_> = m.links.iter().filter(between).collect();
        // Two bearings between the same solids: each is reduced at its own centre.
        if links.len() > 1 {
            links.retain(|l| l.point == *point);
        }
        if let [l] = links.as_slice() {
            return format!(
                "liaison {}, action de ${}$ sur ${}$",
                super::figures::link_text_with(names, l),
                solid(from),
                solid(on)
            );
        }
    }
    super::rich_text_or_escaped(&s.theorem)
}

/// The bilan's line for an action, capitalised: « Liaison pivot d'axe $(O_1, \vec{z}_0)$,
/// action de $S_0$ sur $S_1$ ».
pub(super) fn action_line(
    m: &crate::mechanism::Mechanism,
    names: &super::VectorNames,
    s: &crate::derivation::Step,
) -> String {
    let text = bilan_text(m, names, s);
    let mut cs = text.chars();
    match cs.next() {
        Some(c) => c.to_uppercase().chain(cs).collect::<String>(),
        None => text,
    }
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

/// The sentence naming the unknowns that the actions' side of an equation of motion's
/// theorem still holds, and the other equations of the PFD that eliminate them, grouped by
/// what they isolate (« $X_{12}$ et $Y_{12}$ s'éliminent avec les autres équations du PFD,
/// obtenues en isolant $S_3$ (résultante sur $\vec{x}_0$) et … »); None when it holds none.
fn eliminated(
    m: &crate::mechanism::Mechanism,
    names: &super::VectorNames,
    side: &crate::expr::Expr,
) -> Option<String> {
    let occurs = side.occurring();
    let held: Vec<String> = (crate::pfd::unknown_vars(m).into_iter())
        .filter(|(_, v)| occurs[v.index()])
        .map(|(n, _)| format!("${}$", name(&n)))
        .collect();
    // Per isolated system: the vectors of its resultant theorems, then its moment theorems.
    let mut groups: Vec<(&str, Vec<String>, Vec<String>)> = Vec::new();
    for t in m.dynamics.theorems.iter().filter(|t| t.eom.is_none()) {
        let on = format!(
            "${}$",
            names.basis_vector(t.on.1.letter(), m.frame_name(t.on.0))
        );
        let g = match groups.iter().position(|g| g.0 == t.isolate) {
            Some(k) => &mut groups[k],
            None => {
                groups.push((&t.isolate, Vec::new(), Vec::new()));
                groups.last_mut().expect("just pushed")
            }
        };
        match t.kind {
            crate::wire::TheoremKind::Resultant => g.1.push(on),
            crate::wire::TheoremKind::Moment => g.2.push(format!(
                "moment en ${}$ sur {on}",
                point(m.point_name(t.point))
            )),
            crate::wire::TheoremKind::Energy => g.2.push("énergie cinétique".to_string()),
        }
    }
    if held.is_empty() || groups.is_empty() {
        return None;
    }
    let list = super::words::french_list;
    let isolated: Vec<String> = (groups.iter())
        .map(|(s, res, mom)| {
            let res = (!res.is_empty()).then(|| format!("résultante sur {}", list(res)));
            let what: Vec<String> = res.into_iter().chain(mom.iter().cloned()).collect();
            format!("${}$ ({})", solid(s), what.join(", "))
        })
        .collect();
    // Coulomb's laws are equations of the system too.
    let laws = super::coulomb::laws_phrase(m).map_or(String::new(), |l| format!(", et {l}"));
    Some(format!(
        "{} s'élimin{} avec les autres équations du PFD, obtenues en isolant {}{laws}.",
        super::words::french_list(&held),
        if held.len() > 1 { "ent" } else { "e" },
        super::words::french_list(&isolated)
    ))
}

/// An equation a = b as a teacher writes it: a left side whose every term is negative,
/// −(J/R + m R) ẍ = m g R sin α, is written (J/R + m R) ẍ = −m g R sin α.
fn upright(
    (a, b): (crate::expr::Expr, crate::expr::Expr),
) -> (crate::expr::Expr, crate::expr::Expr) {
    if a.reads_negative() {
        (-&a, -&b)
    } else {
        (a, b)
    }
}

/// An equation e = 0 as (terms with a rate) = −(the others).
fn split_equation(e: &crate::expr::Expr) -> (crate::expr::Expr, crate::expr::Expr) {
    let (with, without) = e.split_by_rates();
    (with, -without)
}
