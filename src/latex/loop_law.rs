//! The loop law (« loi entrée-sortie ») after the paramétrage of a mechanism with loop
//! closures.

use super::document::{DisplayRole, Doc, Inline};
use super::name;
use crate::derivation::Value;
use std::fmt::Write as _;

/// The loop law after the paramétrage: each closure projected on the ground's basis, the
/// relations' time derivatives, and the dependent rates they give where the determinant is
/// not zero; every formula recorded with its value (a derivative reads 0 once the solved
/// rates stand for the dependent ones).
pub(super) fn loop_law(doc: &mut Doc) {
    let m = doc.m;
    let Some(law) = &m.loop_law else { return };
    let ground = m.frames.ground();
    let lines = |l: &[String]| l.join(" \\\\\n&\\phantom{=} ");
    let _ = writeln!(doc.o, "\\noindent\\textbf{{Loi entrée-sortie.}} ");
    for (c, v) in m.spec.closures.iter().zip(m.closure_vectors()) {
        let comps = v.express_in(&m.frames, ground);
        let latex = format!("\\vec{{0}} = {}", super::vector_over_bases(m, &v));
        let _ = writeln!(
            doc.o,
            "La fermeture géométrique ${latex}$, projetée sur ${}$, donne :",
            super::basis(m.frame_name(ground))
        );
        doc.inline.push(Inline {
            what: format!("closure {}", c.vector),
            latex,
            value: Value::Vector {
                basis: ground,
                components: comps.clone(),
            },
        });
        for e in comps.iter().filter(|e| !e.is_zero()) {
            let body = format!("0 &= {}", lines(&super::expr_lines(e, super::LINE - 4)));
            doc.record(
                DisplayRole::Step,
                "loop relation",
                body,
                &Value::Scalar(e.clone()),
                None,
                false,
            );
        }
    }
    let _ = writeln!(doc.o, "En dérivant par rapport au temps :");
    let zero = m.reg.zero();
    for d in &law.derivatives {
        let body = format!("0 &= {}", lines(d));
        doc.record(
            DisplayRole::Step,
            "loop relation's derivative",
            body,
            &Value::Scalar(zero.clone()),
            None,
            false,
        );
    }
    let condition = match m.reg.parse(&law.determinant) {
        Ok(d) if d.as_rational().is_none() => {
            let math = format!("{} \\neq 0", super::expr(&d));
            let s = format!(", tant que ${math}$");
            doc.inline.push(Inline {
                what: "loop determinant".into(),
                latex: math,
                value: Value::Scalar(d),
            });
            s
        }
        _ => String::new(),
    };
    let _ = writeln!(doc.o, "D'où{condition} :");
    let dependent = m.spec.closures.iter().flat_map(|c| &c.dependent);
    for q in dependent.filter_map(|n| m.reg.coord(n)) {
        let rate = m.reg.dot(q);
        let body = format!(
            "\\dot{{{}}} &= {}",
            name(&m.reg.coord_info(q).name),
            lines(&super::expr_lines(&rate, super::LINE - 4))
        );
        let what = format!("dot({})", m.reg.coord_info(q).name);
        doc.record(
            DisplayRole::Step,
            &what,
            body,
            &Value::Scalar(rate),
            None,
            false,
        );
    }
}
