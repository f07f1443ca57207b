//! The method a corrigé teaches: each step of a derivation introduced by one typeset sentence
//! applied to the actual objects (« $O_1$ est fixe dans $\mathcal{R}_0$ … »), steps already
//! shown cited instead of re-derived, the dynamic moment at a fixed point written as the
//! derivative of the kinetic moment in one line, and the PFD as a bilan of the external
//! actions followed by one equality per theorem.

use super::document::{DisplayRole, Doc};
use super::{basis_vector, frame, name, point, quantity};
use crate::derivation::{Derivation, Step, StepKind, Value, derive};
use crate::frame::FrameId;
use crate::mechanism::Mechanism;
use crate::quantity::{Motion, Quantity, QuantityKind};
use std::fmt::Write;

/// `\overrightarrow{\Omega(2/1)}` from frame names.
fn omega_of(a: &str, b: &str) -> String {
    quantity(&QuantityKind::Omega(Motion {
        moving: a.to_string(),
        reference: b.to_string(),
    }))
}

/// The frames from `f` up to `r` (both included), when `r` is an ancestor of `f`.
fn chain(m: &Mechanism, f: FrameId, r: FrameId) -> Option<Vec<FrameId>> {
    let mut out = vec![f];
    let mut cur = f;
    while cur != r {
        cur = m.frames.get(cur).parent?;
        out.push(cur);
    }
    Some(out)
}

/// « Composition des vitesses de rotation : Ω(2/0) = Ω(2/1) + Ω(1/0) » along the frames that
/// turn, or « D'après le paramétrage » for one rotation.
fn omega_sentence(m: &Mechanism, mo: &Motion) -> String {
    let (Some(f), Some(r)) = (m.frames.find(&mo.moving), m.frames.find(&mo.reference)) else {
        return "Composition des vitesses de rotation :".to_string();
    };
    let Some(c) = chain(m, f, r) else {
        return "Composition des vitesses de rotation :".to_string();
    };
    let turning: Vec<(FrameId, FrameId)> = c
        .windows(2)
        .filter(|w| {
            m.frames.get(w[0]).rotation.is_some()
                && !crate::kinematics::omega(m, w[0], w[1]).is_zero(&m.frames)
        })
        .map(|w| (w[0], w[1]))
        .collect();
    if turning.len() <= 1 {
        return "D'après le paramétrage :".to_string();
    }
    let parts: Vec<String> = turning
        .iter()
        .map(|&(a, b)| omega_of(m.frame_name(a), m.frame_name(b)))
        .collect();
    format!(
        "Composition des vitesses de rotation, ${} = {}$ :",
        omega_of(&mo.moving, &mo.reference),
        parts.join(" + ")
    )
}

/// `S_2` for solid `2`, `E` for a set.
fn solid(n: &str) -> String {
    if n.chars().all(|c| c.is_ascii_digit()) {
        format!("S_{{{n}}}")
    } else {
        name(n)
    }
}

/// The mass of a solid in LaTeX (`m_{2}`), or `m` for a set.
fn mass_of(m: &Mechanism, s: &str) -> String {
    m.bodies
        .iter()
        .find(|b| b.name == s)
        .map(|b| super::expr(&b.mass))
        .unwrap_or_else(|| "m".to_string())
}

/// The sentence that introduces a step: the theorem applied to the step's objects.
fn sentence(m: &Mechanism, s: &Step) -> String {
    use QuantityKind::*;
    let t = s.theorem.as_str();
    match &s.kind {
        StepKind::Quantity(Omega(mo)) => omega_sentence(m, mo),
        StepKind::Quantity(Inertia {
            point: a,
            solid: sn,
        }) => {
            if let Some(g) = t.strip_prefix("théorème de Huygens, de ") {
                let g = g.split(' ').next().unwrap_or(g);
                format!(
                    "Théorème de Huygens, de ${}$ en ${}$ (${} = I_{{{}}}({sn})$ + terme de transport de ${}$) :",
                    point(g),
                    point(a),
                    quantity(&Inertia {
                        point: a.clone(),
                        solid: sn.clone()
                    }),
                    point(g),
                    mass_of(m, sn)
                )
            } else if t == "masse ponctuelle" {
                format!("${}$ est une masse ponctuelle :", solid(sn))
            } else {
                "Opérateur d'inertie :".to_string()
            }
        }
        StepKind::Quantity(KineticMoment {
            point: a,
            motion: mo,
        }) => {
            let sigma = quantity(&KineticMoment {
                point: a.clone(),
                motion: mo.clone(),
            });
            let i = format!("I_{{{}}}({})", point(a), mo.moving);
            let om = omega_of(&mo.moving, &mo.reference);
            if t.starts_with("σ(G") {
                format!(
                    "${}$ est le centre d'inertie de ${}$ : ${sigma} = {i}\\cdot{om}$ :",
                    point(a),
                    solid(&mo.moving)
                )
            } else if t.starts_with("point fixe") {
                format!(
                    "${}$ est un point de ${}$ fixe dans ${}$ : ${sigma} = {i}\\cdot{om}$ :",
                    point(a),
                    solid(&mo.moving),
                    frame(&mo.reference)
                )
            } else {
                let g = m
                    .bodies
                    .iter()
                    .find(|b| b.name == mo.moving)
                    .map(|b| m.point_name(b.centre).to_string())
                    .unwrap_or_else(|| "G".into());
                format!(
                    "${sigma} = {i}\\cdot{om} + {}\\,\\overrightarrow{{{}{}}}\\wedge\\overrightarrow{{V({},{}/{})}}$ :",
                    mass_of(m, &mo.moving),
                    point(a),
                    point(&g),
                    point(a),
                    mo.moving,
                    mo.reference
                )
            }
        }
        StepKind::Derivative(_, r) => format!(
            "Dérivée dans ${}$ (formule de Bour, $\\left[\\frac{{\\mathrm{{d}}\\vec u}}{{\\mathrm{{d}}t}}\\right]_{{{}}} = \\left[\\frac{{\\mathrm{{d}}\\vec u}}{{\\mathrm{{d}}t}}\\right]_{{\\mathcal{{R}}_k}} + \\overrightarrow{{\\Omega(k/{r})}}\\wedge\\vec u$) :",
            frame(r),
            frame(r)
        ),
        StepKind::Complementary(a, _, r) => format!(
            "${}$ n'est pas fixe dans ${}$ : terme complémentaire",
            point(a),
            frame(r)
        ),
        StepKind::Quantity(DynamicMoment {
            point: a,
            motion: mo,
        }) => format!(
            "${} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{}\\right]_{{{}}} + \\overrightarrow{{V({}/{})}}\\wedge {}\\,\\overrightarrow{{V({}/{})}}$ :",
            quantity(&DynamicMoment {
                point: a.clone(),
                motion: mo.clone()
            }),
            quantity(&KineticMoment {
                point: a.clone(),
                motion: mo.clone()
            }),
            frame(&mo.reference),
            point(a),
            frame(&mo.reference),
            mass_of(m, &mo.moving),
            point(
                &m.bodies
                    .iter()
                    .find(|b| b.name == mo.moving)
                    .map(|b| m.point_name(b.centre).to_string())
                    .unwrap_or_else(|| "G".into())
            ),
            frame(&mo.reference)
        ),
        StepKind::Quantity(DynamicResultant(mo)) | StepKind::Quantity(KineticResultant(mo)) => {
            let dynamic = matches!(s.kind, StepKind::Quantity(DynamicResultant(_)));
            let g = m
                .bodies
                .iter()
                .find(|b| b.name == mo.moving)
                .map(|b| m.point_name(b.centre).to_string())
                .unwrap_or_else(|| "G".into());
            let (r, v) = if dynamic {
                (
                    DynamicResultant(mo.clone()),
                    Acceleration {
                        point: g,
                        motion: mo.clone(),
                    },
                )
            } else {
                (
                    KineticResultant(mo.clone()),
                    Velocity {
                        point: g,
                        motion: mo.clone(),
                    },
                )
            };
            format!(
                "${} = {}\\,{}$ :",
                quantity(&r),
                mass_of(m, &mo.moving),
                quantity(&v)
            )
        }
        StepKind::Quantity(k) if k.is_torsor() => {
            // A change of point: M(B) = M(A) + BA ∧ R.
            let from = t
                .split("= M(")
                .nth(1)
                .and_then(|x| x.split(')').next())
                .unwrap_or("A")
                .to_string();
            let to = match k {
                KineticTorsor { point: p, .. } | DynamicTorsor { point: p, .. } => p.clone(),
                _ => "B".into(),
            };
            format!(
                "Changement de point, de ${}$ à ${}$ ($\\vec{{M}}({}) = \\vec{{M}}({}) + \\overrightarrow{{{}{}}}\\wedge\\vec{{R}}$) :",
                point(&from),
                point(&to),
                point(&to),
                point(&from),
                point(&to),
                point(&from)
            )
        }
        _ => format!("{} :", super::escape_text(t)),
    }
}

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
    Some((quantity(&r), quantity(&mo)))
}

/// The left side of a step's display.
fn step_lhs(k: &StepKind) -> String {
    match k {
        StepKind::Quantity(q) => quantity(q),
        StepKind::Derivative(q, r) => format!(
            "\\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{}\\right]_{{{}}}",
            quantity(q),
            frame(r)
        ),
        StepKind::Complementary(a, g, r) => format!(
            "\\overrightarrow{{V({}/{})}} \\wedge m\\,\\overrightarrow{{V({}/{})}}",
            point(a),
            frame(r),
            point(g),
            frame(r)
        ),
        StepKind::Action { from, on, point: p } => format!(
            "\\left\\{{\\mathcal{{T}}({} \\rightarrow {})\\right\\}}_{{{}}}",
            action_side(from),
            action_side(on),
            point(p)
        ),
        StepKind::Projected(q, (f, a)) => format!("{} \\cdot {}", quantity(q), basis_vector(*a, f)),
        StepKind::External {
            isolate,
            point: p,
            on: (f, a),
        } => {
            let s = action_side(isolate);
            let arrow = format!("\\bar{{{s}}} \\rightarrow {s}");
            match p {
                Some(p) => format!(
                    "\\overrightarrow{{M({},{arrow})}} \\cdot {}",
                    point(p),
                    basis_vector(*a, f)
                ),
                None => format!(
                    "\\overrightarrow{{R({arrow})}} \\cdot {}",
                    basis_vector(*a, f)
                ),
            }
        }
    }
}

/// A solid number as is, a name (`pes`, `moteur`) upright.
pub(super) fn action_side(n: &str) -> String {
    if n.chars().all(|c| c.is_ascii_digit()) {
        n.to_string()
    } else if n.len() == 1 {
        name(n)
    } else {
        format!("\\mathrm{{{}}}", n.replace('_', "\\_"))
    }
}

/// A step's value under the question's hypothesis.
fn shown_value(doc: &Doc, v: &Value) -> Value {
    match doc.under {
        Some(h) => v.under(h),
        None => v.clone(),
    }
}

/// Writes the steps of a kinematic or kinetic derivation as the course shows them. Returns
/// whether the last step displayed equals the result (so the result is not repeated).
fn steps(doc: &mut Doc, d: &Derivation, result_lhs: &str) -> bool {
    let m = doc.m;
    // The elements of a torsor result are boxed where they are derived (the torsor is then
    // not written again): (left side, components) of its resultant and its moment.
    let elements: Vec<(String, [crate::expr::Expr; 3])> =
        match (torsor_names(&d.quantity.kind), &d.value) {
            (
                Some((rn, mn)),
                Value::Torsor {
                    resultant, moment, ..
                },
            ) => vec![(rn, resultant.clone()), (mn, moment.clone())],
            _ => Vec::new(),
        };
    let is_element = |lhs: &str, v: &Value| match v {
        Value::Vector { components, .. } => {
            elements.iter().any(|(l, c)| l == lhs && c == components)
        }
        _ => false,
    };
    let mut cited: Vec<(String, String)> = Vec::new();
    let flush = |doc: &mut Doc, cited: &mut Vec<(String, String)>| {
        if cited.is_empty() {
            return;
        }
        let mut by_place: Vec<(String, Vec<String>)> = Vec::new();
        for (lhs, place) in cited.drain(..) {
            match by_place.iter_mut().find(|(p, _)| *p == place) {
                Some((_, v)) => v.push(lhs),
                None => by_place.push((place, vec![lhs])),
            }
        }
        for (place, lhss) in by_place {
            let list: Vec<String> = lhss.iter().map(|l| format!("${l}$")).collect();
            let _ = writeln!(doc.o, "D'après {place} : {}.\n", french_list(&list));
        }
    };
    let n = d.steps.len();
    let mut i = 0;
    let mut last_is_result = false;
    while i < n {
        let s = &d.steps[i];
        let v = shown_value(doc, &s.value);
        // A derivative that is already the dynamic moment (no complementary term): one line.
        if let (StepKind::Derivative(sig, r), Some(next)) = (&s.kind, d.steps.get(i + 1))
            && let StepKind::Quantity(QuantityKind::DynamicMoment {
                point: a,
                motion: mo,
            }) = &next.kind
            && next.value.exprs() == s.value.exprs()
        {
            let delta = quantity(&next_kind(&next.kind));
            let lhs = format!("{delta} = {}", step_lhs(&s.kind));
            let _ = sig;
            let why = if mo_centre(m, a, mo) {
                format!("${}$ est le centre d'inertie", point(a))
            } else {
                format!("${}$ est fixe dans ${}$", point(a), frame(r))
            };
            if let Some(place) = doc.cited(&delta, &v) {
                cited.push((delta, place));
            } else {
                flush(doc, &mut cited);
                let _ = writeln!(
                    doc.o,
                    "{why} : le moment dynamique est la dérivée du moment cinétique dans ${}$ (cas particulier du cours) :",
                    frame(r)
                );
                let boxed = is_element(&delta, &next.value);
                doc.show_keyed(DisplayRole::Step, &next.label, &lhs, &delta, &v, boxed);
                last_is_result = i + 2 == n && delta == result_lhs;
            }
            i += 2;
            continue;
        }
        let lhs = match &s.kind {
            // V(A/R) ∧ m2 V(G2/R): the solid's own mass.
            StepKind::Complementary(..) => match &d.quantity.kind {
                QuantityKind::DynamicMoment { motion, .. }
                | QuantityKind::DynamicTorsor { motion, .. } => step_lhs(&s.kind).replace(
                    "\\wedge m\\,",
                    &format!("\\wedge {}\\,", mass_of(m, &motion.moving)),
                ),
                _ => step_lhs(&s.kind),
            },
            _ => step_lhs(&s.kind),
        };
        if let Some(place) = doc.cited(&lhs, &v) {
            cited.push((lhs, place));
            i += 1;
            continue;
        }
        // The last step is the result itself: the result display shows it.
        if i + 1 == n && lhs == result_lhs && d.value.exprs() == s.value.exprs() {
            last_is_result = true;
            flush(doc, &mut cited);
            let _ = writeln!(doc.o, "{}", sentence(m, s));
            i += 1;
            continue;
        }
        flush(doc, &mut cited);
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
                i += 1;
                continue;
            }
        }
        let _ = writeln!(doc.o, "{}", sentence(m, s));
        let boxed = is_element(&lhs, &s.value);
        doc.show_keyed(DisplayRole::Step, &s.label, &lhs, &lhs, &v, boxed);
        i += 1;
    }
    flush(doc, &mut cited);
    last_is_result
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

/// « a, b et c ».
fn french_list(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [a] => a.clone(),
        [init @ .., last] => format!("{} et {last}", init.join(", ")),
    }
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
    let vq = format!("V({g},{}/{r}) in B{bn}", mo.moving);
    let Ok(vd) = Quantity::parse(&vq)
        .map_err(|e| e.to_string())
        .and_then(|q| derive(m, &q).map_err(|e| e.to_string()))
    else {
        return false;
    };
    let vv = shown_value(doc, &vd.value);
    let vk = QuantityKind::Velocity {
        point: g.clone(),
        motion: mo.clone(),
    };
    let vlhs = quantity(&vk);
    if vv.exprs().iter().all(|e| e.is_zero()) {
        if doc.cited(&vlhs, &vv).is_none() {
            let _ = writeln!(
                doc.o,
                "${}$ est fixe dans ${}$ : ${} = \\vec{{0}}$, donc la résultante est nulle.\n",
                point(&g),
                frame(r),
                vlhs
            );
            doc.remember(&vlhs, &vv);
        }
        return true;
    }
    match doc.cited(&vlhs, &vv) {
        Some(place) => {
            let _ = writeln!(doc.o, "D'après {place} : ${vlhs}$.\n");
        }
        None => {
            let _ = writeln!(
                doc.o,
                "Dérivée dans ${}$ du vecteur position $\\overrightarrow{{{}{}}}$ (${}$ fixe dans ${}$) :",
                frame(r),
                point(&o),
                point(&g),
                point(&o),
                frame(r)
            );
            doc.show_keyed(DisplayRole::Step, &vq, &vlhs, &vlhs, &vv, false);
        }
    }
    if !dynamic {
        return false;
    }
    let aq = format!("Gamma({g},{}/{r}) in B{bn}", mo.moving);
    let Ok(ad) = Quantity::parse(&aq)
        .map_err(|e| e.to_string())
        .and_then(|q| derive(m, &q).map_err(|e| e.to_string()))
    else {
        return false;
    };
    let av = shown_value(doc, &ad.value);
    let alhs = quantity(&QuantityKind::Acceleration {
        point: g.clone(),
        motion: mo.clone(),
    });
    match doc.cited(&alhs, &av) {
        Some(place) => {
            let _ = writeln!(doc.o, "D'après {place} : ${alhs}$.\n");
        }
        None => {
            let _ = writeln!(
                doc.o,
                "${alhs} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{vlhs}\\right]_{{{}}}$ :",
                frame(r)
            );
            doc.show_keyed(DisplayRole::Step, &aq, &alhs, &alhs, &av, false);
        }
    }
    false
}

/// Shows a vector value computed by the engine, or cites it.
fn show_vector(
    doc: &mut Doc,
    what: &str,
    sentence: &str,
    lhs: &str,
    v: &crate::vector::Vector,
    b: FrameId,
) {
    let value = Value::Vector {
        basis: b,
        components: v.express_in(&doc.m.frames, b),
    };
    let value = shown_value(doc, &value);
    match doc.cited(lhs, &value) {
        Some(place) => {
            let _ = writeln!(doc.o, "D'après {place} : ${lhs}$.\n");
        }
        None => {
            let _ = writeln!(doc.o, "{sentence}");
            doc.show_keyed(DisplayRole::Step, what, lhs, lhs, &value, false);
        }
    }
}

/// Shows a scalar value computed by the engine.
fn show_scalar(doc: &mut Doc, what: &str, sentence: &str, lhs: &str, e: crate::expr::Expr) {
    let value = shown_value(doc, &Value::Scalar(e));
    let _ = writeln!(doc.o, "{sentence}");
    doc.show_keyed(DisplayRole::Step, what, lhs, lhs, &value, false);
}

/// The short route a teacher takes for a projected dynamic moment δ(A,S/R)·u of one solid:
/// at a point fixed in R on an axis fixed in R, the derivative of σ(A,S/R)·u; elsewhere
/// (A ≠ G), the change of point to the centre of inertia, δ(G)·u + (AG ∧ m Γ(G))·u. Returns
/// false when neither applies (the steps of the vector are then shown).
fn projected_moment_route(doc: &mut Doc, d: &Derivation) -> bool {
    use crate::kinematics::{acceleration, omega, point_velocity};
    let m = doc.m;
    let q = &d.quantity;
    let QuantityKind::DynamicMoment {
        point: a,
        motion: mo,
    } = &q.kind
    else {
        return false;
    };
    let Ok(r) = crate::derivation::resolve(m, q) else {
        return false;
    };
    let (Some((uf, ua)), [s], Some(pa)) = (r.projection, r.solids.as_slice(), r.point) else {
        return false;
    };
    let rf = r.reference.unwrap_or(m.frames.ground());
    let body = m.body(*s);
    let u = crate::vector::Vector::along(uf, ua, m.reg.one());
    let ul = basis_vector(ua.letter(), m.frame_name(uf));
    let rl = frame(&mo.reference);
    let sigma_a = quantity(&QuantityKind::KineticMoment {
        point: a.clone(),
        motion: mo.clone(),
    });
    let fixed_axis = omega(m, uf, rf).is_zero(&m.frames);
    // δ(A) = dσ(A)/dt + V(A/R) ∧ m V(G): a point A at rest in R suffices.
    let fixed_point = point_velocity(m, pa, rf).is_zero(&m.frames);
    let ib = crate::torsor::inertia_basis(m, *s);
    let Value::Scalar(result) = &d.value else {
        return false;
    };
    if fixed_point && fixed_axis {
        // The route must give the engine's value exactly, or it is not taken.
        let sig = crate::torsor::kinetic_moment_solid(m, *s, pa, rf);
        let proj = sig.dot(&m.frames, &u);
        if &proj.dt() != result {
            return false;
        }
        let om = omega(m, body.frame, rf);
        let oml = omega_of(&mo.moving, &mo.reference);
        show_vector(
            doc,
            &format!("Omega({})", mo),
            &omega_sentence(m, mo),
            &oml,
            &om,
            ib,
        );
        let il = format!("I_{{{}}}({})", point(a), mo.moving);
        // σ(A) = I_A Ω only when the point of S at A is at rest; else the general formula.
        let of_solid = crate::kinematics::velocity(m, pa, body.frame, rf).is_zero(&m.frames);
        let gn = m.point_name(body.centre).to_string();
        let sentence = if of_solid {
            format!(
                "${}$ est un point de ${}$ fixe dans ${rl}$ : ${sigma_a} = {il}\\cdot{oml}$ :",
                point(a),
                solid(&mo.moving)
            )
        } else {
            format!(
                "${sigma_a} = {il}\\cdot{oml} + {}\\,\\overrightarrow{{{}{}}}\\wedge\\overrightarrow{{V({},{}/{})}}$ :",
                mass_of(m, &mo.moving),
                point(a),
                point(&gn),
                point(a),
                mo.moving,
                mo.reference
            )
        };
        show_vector(
            doc,
            &format!("sigma({a},{mo})"),
            &sentence,
            &sigma_a,
            &sig,
            ib,
        );
        show_scalar(
            doc,
            &format!("sigma({a},{mo}).{}{}", ua.letter(), m.frame_name(uf)),
            &format!(
                "${}$ est fixe dans ${rl}$ et ${ul}$ aussi : ${} \\cdot {ul} = \\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}\\left({sigma_a}\\cdot {ul}\\right)$, avec :",
                point(a),
                quantity(&q.kind)
            ),
            &format!("{sigma_a}\\cdot {ul}"),
            proj,
        );
        return true;
    }
    let g = body.centre;
    if pa == g {
        return false;
    }
    let dg = crate::torsor::dynamic_moment_solid(m, *s, g, rf).dot(&m.frames, &u);
    let gam = acceleration(m, g, body.frame, rf);
    let ag = crate::kinematics::position(m, pa, g);
    let transport = ag
        .cross(&m.frames, &gam.scale(&body.mass))
        .dot(&m.frames, &u);
    // δ(A)·u = δ(G)·u + (AG ∧ m Γ(G))·u must give the engine's value exactly.
    if &(&dg + &transport) != result {
        return false;
    }
    let gn = m.point_name(g).to_string();
    let delta_g = QuantityKind::DynamicMoment {
        point: gn.clone(),
        motion: mo.clone(),
    };
    let gamma = QuantityKind::Acceleration {
        point: gn.clone(),
        motion: mo.clone(),
    };
    let mass = mass_of(m, &mo.moving);
    let _ = writeln!(
        doc.o,
        "Changement de point vers le centre d'inertie : ${} \\cdot {ul} = {} \\cdot {ul} + \\left(\\overrightarrow{{{}{}}}\\wedge {mass}\\,{}\\right)\\cdot {ul}$.\n",
        quantity(&q.kind),
        quantity(&delta_g),
        point(a),
        point(&gn),
        quantity(&gamma)
    );
    let om = omega(m, body.frame, rf);
    let oml = omega_of(&mo.moving, &mo.reference);
    show_vector(
        doc,
        &format!("Omega({mo})"),
        &omega_sentence(m, mo),
        &oml,
        &om,
        ib,
    );
    let sigma_g = quantity(&QuantityKind::KineticMoment {
        point: gn.clone(),
        motion: mo.clone(),
    });
    let sig = crate::torsor::kinetic_moment_solid(m, *s, g, rf);
    show_vector(
        doc,
        &format!("sigma({gn},{mo})"),
        &format!(
            "En ${}$, centre d'inertie : ${sigma_g} = I_{{{}}}({})\\cdot{oml}$ :",
            point(&gn),
            point(&gn),
            mo.moving
        ),
        &sigma_g,
        &sig,
        ib,
    );
    show_scalar(
        doc,
        &format!("delta({gn},{mo}).{}{}", ua.letter(), m.frame_name(uf)),
        &format!(
            "${} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{sigma_g}\\right]_{{{rl}}}$ (centre d'inertie), projeté sur ${ul}$ :",
            quantity(&delta_g)
        ),
        &format!("{} \\cdot {ul}", quantity(&delta_g)),
        dg,
    );
    show_vector(
        doc,
        &format!("Gamma({gn},{mo})"),
        &format!("Accélération de ${}$ :", point(&gn)),
        &quantity(&gamma),
        &gam,
        r.basis,
    );
    show_scalar(
        doc,
        "transport",
        "Terme de transport :",
        &format!(
            "\\left(\\overrightarrow{{{}{}}}\\wedge {mass}\\,{}\\right)\\cdot {ul}",
            point(a),
            point(&gn),
            quantity(&gamma)
        ),
        transport,
    );
    true
}

/// V(P,S/R) and Γ(P,S/R) have no steps of their own: the method sentence (derivative of the
/// position from the ground origin, fixed in R), and for Γ the velocity first.
fn position_route(doc: &mut Doc, d: &Derivation) {
    let m = doc.m;
    let (p, mo, accel) = match &d.quantity.kind {
        QuantityKind::Velocity { point, motion } => (point, motion, false),
        QuantityKind::Acceleration { point, motion } => (point, motion, true),
        _ => return,
    };
    // d/dt O0P in R is V(P,S/R) only for P fixed in S, R the ground (where O0 is fixed).
    let moving = m
        .bodies
        .iter()
        .find(|b| b.name == mo.moving)
        .map(|b| b.frame)
        .or_else(|| m.frames.find(&mo.moving));
    let (Some(pid), Some(sf), Some(rf)) = (m.points.find(p), moving, m.frames.find(&mo.reference))
    else {
        return;
    };
    if rf != m.frames.ground() || !crate::kinematics::is_fixed_in(m, pid, sf) {
        return;
    }
    let o = m.point_name(m.points.origin()).to_string();
    let rl = frame(&mo.reference);
    let pos = format!("\\overrightarrow{{{}{}}}", point(&o), point(p));
    let vk = QuantityKind::Velocity {
        point: p.clone(),
        motion: mo.clone(),
    };
    let vl = quantity(&vk);
    if !accel {
        let _ = writeln!(
            doc.o,
            "${vl} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{pos}\\right]_{{{rl}}}$ (${}$ fixe dans ${rl}$) :",
            point(&o)
        );
        return;
    }
    // Γ: the velocity first (shown or cited), in the basis of the result.
    let Value::Vector { basis, .. } = &d.value else {
        return;
    };
    let vq = format!(
        "V({p},{}/{}) in B{}",
        mo.moving,
        mo.reference,
        m.frame_name(*basis)
    );
    let Ok(vd) = Quantity::parse(&vq)
        .map_err(|e| e.to_string())
        .and_then(|q| derive(m, &q).map_err(|e| e.to_string()))
    else {
        return;
    };
    let vv = shown_value(doc, &vd.value);
    match doc.cited(&vl, &vv) {
        Some(place) => {
            let _ = writeln!(doc.o, "D'après {place} : ${vl}$.\n");
        }
        None => {
            let _ = writeln!(
                doc.o,
                "${vl} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{pos}\\right]_{{{rl}}}$ (${}$ fixe dans ${rl}$) :",
                point(&o)
            );
            doc.show_keyed(DisplayRole::Step, &vq, &vl, &vl, &vv, false);
        }
    }
    let _ = writeln!(
        doc.o,
        "${} = \\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{vl}\\right]_{{{rl}}}$ :",
        quantity(&d.quantity.kind)
    );
}

/// σ(A,S/R)·u for each solid of a set, each shown with the formula that gives it; returns
/// their sum.
fn kinetic_projections(
    doc: &mut Doc,
    solids: &[crate::mechanism::BodyId],
    pa: crate::point::PointId,
    rf: FrameId,
    u: &crate::vector::Vector,
    ul: &str,
    reference: &str,
) -> crate::expr::Expr {
    let m = doc.m;
    let a = m.point_name(pa).to_string();
    let mut total = m.reg.zero();
    for &s in solids {
        let body = m.body(s);
        let mo = Motion {
            moving: body.name.clone(),
            reference: reference.to_string(),
        };
        let sigma = quantity(&QuantityKind::KineticMoment {
            point: a.clone(),
            motion: mo.clone(),
        });
        let fixed = crate::kinematics::velocity(m, pa, body.frame, rf).is_zero(&m.frames);
        let oml = omega_of(&mo.moving, &mo.reference);
        let sentence = if fixed {
            format!(
                "${}$ est un point de ${}$ fixe dans ${}$ : ${sigma} = I_{{{}}}({})\\cdot{oml}$ :",
                point(&a),
                solid(&mo.moving),
                frame(reference),
                point(&a),
                mo.moving
            )
        } else {
            let g = m.point_name(body.centre).to_string();
            format!(
                "${sigma} = {} + \\overrightarrow{{{}{}}}\\wedge {}\\,{}$ :",
                quantity(&QuantityKind::KineticMoment {
                    point: g.clone(),
                    motion: mo.clone()
                }),
                point(&a),
                point(&g),
                mass_of(m, &mo.moving),
                quantity(&QuantityKind::Velocity {
                    point: g.clone(),
                    motion: mo.clone()
                })
            )
        };
        let p = crate::torsor::kinetic_moment_solid(m, s, pa, rf).dot(&m.frames, u);
        total = &total + &p;
        let lhs = format!("{sigma} \\cdot {ul}");
        let v = shown_value(doc, &Value::Scalar(p.clone()));
        match doc.cited(&lhs, &v) {
            Some(place) => {
                let _ = writeln!(doc.o, "D'après {place} : ${lhs}$.\n");
            }
            None => show_scalar(doc, &format!("sigma({a},{mo})"), &sentence, &lhs, p),
        }
    }
    total
}

/// The short route for a projection on an axis u of the kinetic or dynamic moment of a set:
/// σ(A,E/R)·u as the sum of the solids' projections; δ(A,E/R)·u, at a point A fixed in R
/// and u fixed in R, as d/dt(σ(A,E/R)·u). Taken only when it gives the engine's value.
fn projected_set_route(doc: &mut Doc, d: &Derivation) -> bool {
    use crate::kinematics::{omega, point_velocity};
    let m = doc.m;
    let q = &d.quantity;
    let (a, mo, dynamic) = match &q.kind {
        QuantityKind::KineticMoment { point, motion } => (point, motion, false),
        QuantityKind::DynamicMoment { point, motion } => (point, motion, true),
        _ => return false,
    };
    let Ok(r) = crate::derivation::resolve(m, q) else {
        return false;
    };
    let (Some((uf, ua)), Some(pa)) = (r.projection, r.point) else {
        return false;
    };
    if r.solids.len() < 2 {
        return false;
    }
    let Value::Scalar(result) = &d.value else {
        return false;
    };
    let rf = r.reference.unwrap_or(m.frames.ground());
    let u = crate::vector::Vector::along(uf, ua, m.reg.one());
    let ul = basis_vector(ua.letter(), m.frame_name(uf));
    let sigma_e = quantity(&QuantityKind::KineticMoment {
        point: a.clone(),
        motion: mo.clone(),
    });
    let sum: crate::expr::Expr = r
        .solids
        .iter()
        .map(|&s| crate::torsor::kinetic_moment_solid(m, s, pa, rf).dot(&m.frames, &u))
        .fold(m.reg.zero(), |acc, p| &acc + &p);
    let members: Vec<String> = r
        .solids
        .iter()
        .map(|&s| {
            quantity(&QuantityKind::KineticMoment {
                point: a.clone(),
                motion: Motion {
                    moving: m.body(s).name.clone(),
                    reference: mo.reference.clone(),
                },
            })
        })
        .collect();
    if !dynamic {
        if &sum != result {
            return false;
        }
        let _ = writeln!(
            doc.o,
            "Le moment cinétique de ${}$ est la somme de ceux de ses solides, ${sigma_e} = {}$ ; en projection sur ${ul}$ :\n",
            solid(&mo.moving),
            members.join(" + ")
        );
        kinetic_projections(doc, &r.solids, pa, rf, &u, &ul, &mo.reference);
        return true;
    }
    let fixed = point_velocity(m, pa, rf).is_zero(&m.frames) && omega(m, uf, rf).is_zero(&m.frames);
    if !fixed || &sum.dt() != result {
        return false;
    }
    let lhs = format!("{sigma_e} \\cdot {ul}");
    let _ = writeln!(
        doc.o,
        "${}$ est fixe dans ${}$ et ${ul}$ aussi : ${} \\cdot {ul} = \\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}\\left({sigma_e}\\cdot {ul}\\right)$.\n",
        point(a),
        frame(&mo.reference),
        quantity(&q.kind)
    );
    let v = shown_value(doc, &Value::Scalar(sum.clone()));
    match doc.cited(&lhs, &v) {
        Some(place) => {
            let _ = writeln!(doc.o, "D'après {place} : ${lhs}$.\n");
        }
        None => {
            kinetic_projections(doc, &r.solids, pa, rf, &u, &ul, &mo.reference);
            show_scalar(
                doc,
                &format!("sigma({a},{mo})"),
                "d'où, en sommant :",
                &lhs,
                sum,
            );
        }
    }
    true
}

/// A requested quantity of the kinematics or kinetics: its steps, then the boxed result.
pub(super) fn quantity_block(doc: &mut Doc, d: &Derivation, title: &str, lhs: &str) {
    let m = doc.m;
    let _ = writeln!(doc.o, "\\subsubsection*{{${title}$}}");
    // A projection asked alone is computed by the short route when all its steps were not
    // already shown.
    let all_shown = d.steps.iter().all(|s| {
        let v = shown_value(doc, &s.value);
        doc.cited(&step_lhs(&s.kind), &v).is_some()
    });
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
    let last_is_result =
        if !all_shown && (projected_moment_route(doc, d) || projected_set_route(doc, d)) {
            false
        } else {
            position_route(doc, d);
            steps(doc, d, lhs)
        };
    let id = d.quantity.to_string();
    let names = torsor_names(&d.quantity.kind);
    // Results under a hypothesis only once it has been stated (never before its question).
    let hyps: Vec<_> = match doc.under {
        Some(h) => vec![Some(h)],
        None => std::iter::once(None)
            .chain(
                m.hypotheses
                    .iter()
                    .filter(|h| doc.is_stated(&h.name))
                    .map(Some),
            )
            .collect(),
    };
    let general = d.value.clone();
    for h in hyps {
        let v = match h {
            Some(h) => general.under(h),
            None => general.clone(),
        };
        if doc.under.is_none()
            && let Some(h) = h
        {
            if v.exprs() == general.exprs() {
                let _ = writeln!(
                    doc.o,
                    "Sous l'hypothèse {}, le résultat est inchangé.\n",
                    super::escape_text(&h.name)
                );
                continue;
            }
            let _ = writeln!(doc.o, "Sous l'hypothèse {} :", super::escape_text(&h.name));
        } else if h.is_none() && last_is_result {
            // The last step is the result: box it without repeating a sentence.
        }
        // A torsor whose elements were just shown: its notation, boxed, not its values again.
        if let (
            Some((rn, mn)),
            Value::Torsor {
                basis,
                resultant,
                moment,
                point: p,
            },
        ) = (&names, &v)
        {
            let res = Value::Vector {
                basis: *basis,
                components: resultant.clone(),
            };
            let mom = Value::Vector {
                basis: *basis,
                components: moment.clone(),
            };
            let here = doc.here.clone();
            doc.results
                .push((id.clone(), h.map(|h| h.name.clone()), v.clone(), here));
            let short = resultant
                .iter()
                .chain(moment.iter())
                .all(|e| e.nterms() <= 1);
            if !short && doc.cited(rn, &res).is_some() && doc.cited(mn, &mom).is_some() {
                let _ = writeln!(
                    doc.o,
                    "D'où ${lhs} = \\left\\{{ \\begin{{array}}{{l}} {rn} \\\\ {mn} \\end{{array}} \\right\\}}_{{{}}}$, ses éléments de réduction étant encadrés ci-dessus.\n",
                    point(m.point_name(*p))
                );
                doc.remember(lhs, &v);
                continue;
            }
        }
        let hn = h.map(|h| h.name.clone());
        if names.is_none() || !matches!(v, Value::Torsor { .. }) {
            let here = doc.here.clone();
            doc.results.push((id.clone(), hn.clone(), v.clone(), here));
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
        }
        _ => {
            let lhs = quantity(&d.quantity.kind);
            doc.show_result(DisplayRole::Result, &id, hn.as_deref(), &lhs, &v, None);
        }
    }
    let _ = m;
}

/// An equation e = 0 as (terms with a rate) = −(the others).
fn split_equation(e: &crate::expr::Expr) -> (crate::expr::Expr, crate::expr::Expr) {
    let (with, without) = e.split_by_rates();
    (with, -without)
}
