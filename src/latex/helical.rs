//! Helical links (« liaison hélicoïdale ») as the course writes them after the paramétrage:
//! the screw motion each imposes, V(P,2/1)·u = p/(2π) Ω(2/1)·u, projected with the
//! coordinates, and the torsor a perfect one transmits, its axial moment tied to its axial
//! resultant by zero power (N = −p Z/(2π) along z).

use super::page::{DisplayRole, Doc, Inline};
use super::words::solid;
use crate::derivation::Value;
use crate::mechanism::Link;
use crate::mechanism::{HelicalLaw, Mechanism};
use crate::quantity::{Motion, QuantityKind};
use crate::vector::Vector;
use crate::wire::LinkKind;
use std::fmt::Write as _;

/// Display lines of a broken formula, continued under its sign.
fn lines(l: &[String]) -> String {
    l.join(" \\\\\n&\\phantom{=} ")
}

/// A helical link's quantities of the relative motion, as the course writes them:
/// (V(P,2/1)·u, Ω(2/1)·u), the motion of its second solid on its first.
fn motion_quantities(m: &Mechanism, names: &super::VectorNames, l: &Link) -> (String, String) {
    let [a, b] = &l.between;
    let axis = l.axis.as_deref().unwrap_or("z0");
    let u = m
        .frames
        .basis_vector(axis)
        .map(|(f, x)| names.basis_vector(x.letter(), m.frame_name(f)))
        .unwrap_or_default();
    let motion = Motion {
        moving: b.clone(),
        reference: a.clone(),
    };
    let velocity = QuantityKind::Velocity {
        point: l.point.clone(),
        motion: motion.clone(),
    };
    (
        format!("{} \\cdot {u}", super::quantity_tex(&velocity)),
        format!(
            "{} \\cdot {u}",
            super::quantity_tex(&QuantityKind::Omega(motion))
        ),
    )
}

/// The link's pitch in the key's notation, recorded as an inline formula.
fn pitch_math(doc: &mut Doc, l: &Link) -> String {
    let Some(p) = l.pitch.clone() else {
        return String::new();
    };
    let latex = super::expr(&p);
    doc.inline.push(Inline {
        what: format!("pitch of link {}", l.name),
        latex: latex.clone(),
        value: Value::Scalar(p),
    });
    latex
}

/// The sentence that states a helical link's screw motion, and its axis' vector.
fn statement(doc: &mut Doc, l: &Link) -> String {
    let m = doc.m;
    let p = pitch_math(doc, l);
    let (v, w) = motion_quantities(m, &doc.names, l);
    let axis = l
        .axis
        .as_deref()
        .map(|s| super::figures::spec_vector(&doc.names, s))
        .unwrap_or_default();
    let pitch = match p.chars().count() {
        0 => String::new(),
        _ => format!(" et de pas ${p}$ (positif pour un pas à droite)"),
    };
    let [a, b] = &l.between;
    let frac = if p.chars().count() == 1 {
        format!("\\frac{{{p}}}{{2\\pi}}")
    } else {
        format!("\\frac{{1}}{{2\\pi}} \\left({p}\\right)")
    };
    format!(
        "La liaison hélicoïdale entre ${}$ et ${}$, d'axe $({}, {axis})${pitch}, impose au \
         mouvement de ${}$ par rapport à ${}$ d'être un mouvement de vis : ${v} = {frac}\\,{w}$",
        solid(a),
        solid(b),
        super::point(&l.point),
        solid(b),
        solid(a),
    )
}

/// The screw motion of each helical link that determines a coordinate: the relation, the
/// two factors with the coordinates, and the relation they give as the course writes it,
/// V(P,2/1)·u = p/(2π) Ω(2/1)·u with the factors put in (λ̇ = −p θ̇/(2π)): both sides are the
/// velocity once the solved rate stands for the dependent one.
pub(super) fn kinematics(doc: &mut Doc, laws: &[HelicalLaw]) {
    let m = doc.m;
    let title = if laws.len() == 1 {
        "Liaison hélicoïdale."
    } else {
        "Liaisons hélicoïdales."
    };
    let _ = writeln!(doc.o, "\\noindent\\textbf{{{title}}} ");
    for law in laws {
        let l = &m.links[law.link];
        let sentence = statement(doc, l);
        let _ = writeln!(doc.o, "{sentence}, avec :");
        let (v, w) = motion_quantities(m, &doc.names, l);
        let u = Vector::along(law.axis.0, law.axis.1, m.reg.one());
        let [fa, fb] = law.motion;
        let values = [
            crate::kinematics::velocity(m, law.point, fb, fa).dot(&m.frames, &u),
            crate::kinematics::omega(m, fb, fa).dot(&m.frames, &u),
        ];
        for ((lhs, shown), value) in [(v, &law.velocity), (w, &law.rotation)]
            .into_iter()
            .zip(values.clone())
        {
            let body = format!(
                "{lhs} &= {}",
                lines(&super::expr_lines(shown, super::LINE - 4))
            );
            doc.record(
                DisplayRole::Step,
                "helical factor",
                body,
                &Value::Scalar(value),
                None,
                false,
            );
        }
        let _ = writeln!(doc.o, "soit :");
        let velocity = Value::Scalar(values[0].clone());
        doc.record(
            DisplayRole::Step,
            "helical relation",
            format!(
                "{} &= {}",
                super::expr_lines(&law.velocity, super::LINE - 4).join(" "),
                lines(&super::expr_lines(&law.screw, super::LINE - 4))
            ),
            &velocity,
            Some(velocity.clone()),
            false,
        );
    }
}

/// Every helical link of the mechanism: the screw motion of those that determine no
/// coordinate (the positions follow it), then the torsor each transmits, perfect: its axial
/// moment is −p/(2π) times its axial resultant, by zero power.
pub(super) fn links(doc: &mut Doc) {
    let m = doc.m;
    let helical: Vec<usize> = (m.links.iter().enumerate())
        .filter(|(_, l)| l.kind == LinkKind::Helical)
        .map(|(i, _)| i)
        .collect();
    if helical.is_empty() {
        return;
    }
    let stated = m.loop_law.as_ref().map_or(&[][..], |law| &law.helical[..]);
    let unstated: Vec<usize> = (helical.iter().copied())
        .filter(|i| stated.iter().all(|h| h.link != *i))
        .collect();
    if stated.is_empty() {
        let title = if helical.len() == 1 {
            "Liaison hélicoïdale."
        } else {
            "Liaisons hélicoïdales."
        };
        let _ = writeln!(doc.o, "\\noindent\\textbf{{{title}}} ");
    }
    for &i in &unstated {
        free_motion(doc, i);
    }
    for &i in &helical {
        torsor(doc, i);
    }
}

/// A helical link that determines no coordinate: its two factors, which the positions make
/// satisfy the relation already.
fn free_motion(doc: &mut Doc, i: usize) {
    let m = doc.m;
    let l = &m.links[i];
    let sentence = statement(doc, l);
    let _ = writeln!(doc.o, "{sentence} ; le paramétrage la vérifie :");
    let Some(action) = m.dynamics.actions.get(i) else {
        return;
    };
    let (v, w) = motion_quantities(m, &doc.names, l);
    let Some((f, a)) = l.axis.as_deref().and_then(|x| m.frames.basis_vector(x)) else {
        return;
    };
    let u = Vector::along(f, a, m.reg.one());
    let fa = match action.from {
        crate::mechanism::Source::Body(b) => m.body(b).frame,
        crate::mechanism::Source::Outside => m.frames.ground(),
    };
    let fb = m.body(action.on).frame;
    let values = [
        crate::kinematics::velocity(m, action.point, fb, fa).dot(&m.frames, &u),
        crate::kinematics::omega(m, fb, fa).dot(&m.frames, &u),
    ];
    for (lhs, value) in [v, w].into_iter().zip(values) {
        let body = format!(
            "{lhs} &= {}",
            lines(&super::expr_lines(&value, super::LINE - 4))
        );
        doc.record(
            DisplayRole::Step,
            "helical factor",
            body,
            &Value::Scalar(value),
            None,
            false,
        );
    }
}

/// The torsor a perfect helical link transmits at its point, in its axis' basis, and the
/// relation of its axial moment to its axial resultant (zero power along the screw motion).
fn torsor(doc: &mut Doc, i: usize) {
    let m = doc.m;
    let l = &m.links[i];
    let Some(action) = m.dynamics.actions.get(i) else {
        return;
    };
    let Some((_, axis)) = l.axis.as_deref().and_then(|x| m.frames.basis_vector(x)) else {
        return;
    };
    let resultant = action.resultant.express_in(&m.frames, action.basis);
    let moment = action.moment.express_in(&m.frames, action.basis);
    let k = axis.index();
    let axial = resultant[k].to_string();
    // The axial moment's letter: L, M or N where the resultant's is X, Y or Z.
    let letter = ["L", "M", "N"][k];
    let moment_name = format!("{letter}{}", axial.get(1..).unwrap_or_default());
    let (v, w) = motion_quantities(m, &doc.names, l);
    let tied = super::expr(&moment[k]);
    let latex = format!("{} = {tied}", super::name(&moment_name));
    doc.inline.push(Inline {
        what: format!("axial moment of link {}", l.name),
        latex: latex.clone(),
        value: Value::Scalar(moment[k].clone()),
    });
    let _ = writeln!(
        doc.o,
        "Parfaite, la liaison hélicoïdale entre ${}$ et ${}$ ne dissipe aucune puissance : \
         ${}\\,{v} + {}\\,{w} = 0$, d'où ${latex}$ ; elle transmet le torseur :",
        solid(&l.between[0]),
        solid(&l.between[1]),
        super::expr(&resultant[k]),
        super::name(&moment_name),
    );
    let lhs = format!(
        "\\TTorseur{{\\mathcal{{T}}({} \\rightarrow {})}}{{{}}}",
        super::action_side(&l.between[0]),
        super::action_side(&l.between[1]),
        super::point(&l.point)
    );
    let value = Value::Torsor {
        point: action.point,
        basis: action.basis,
        resultant,
        moment,
    };
    doc.show_keyed(
        DisplayRole::Step,
        "helical torsor",
        &lhs,
        &lhs,
        &value,
        false,
    );
}
