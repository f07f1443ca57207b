//! The loop law (« loi entrée-sortie »), the rolling conditions (« roulement sans
//! glissement ») and the helical links' screw motions after the paramétrage of a mechanism
//! with dependent coordinates.

use super::page::{DisplayRole, Doc, Inline};
use crate::derivation::Value;
use crate::mechanism::RollingLaw;
use std::fmt::Write as _;

/// Display lines of a broken formula, continued under its sign.
fn lines(l: &[String]) -> String {
    l.join(" \\\\\n&\\phantom{=} ")
}

/// The loop law and the rolling conditions after the paramétrage: each closure projected on
/// the ground's basis and its time derivative, each rolling condition projected, and the
/// dependent rates they give where the determinant is not zero; every formula recorded with
/// its value (a relation reads 0 once the solved rates stand for the dependent ones).
pub(super) fn loop_law(doc: &mut Doc) {
    let m = doc.m;
    let Some(law) = &m.loop_law else { return };
    if !m.closures.is_empty() {
        closures(doc, &law.derivatives);
    }
    if !law.rolling.is_empty() {
        rolling(doc, &law.rolling);
    }
    if !law.helical.is_empty() {
        super::helical::kinematics(doc, &law.helical);
    }
    let condition = match &law.determinant {
        // A condition on the coordinates only: a length R ≠ 0 goes without saying.
        Some(d) if !d.is_time_independent() => {
            let math = format!("{} \\neq 0", super::expr(d));
            let s = format!(", tant que ${math}$");
            doc.inline.push(Inline {
                what: "loop determinant".into(),
                latex: math,
                value: Value::Scalar(d.clone()),
            });
            s
        }
        _ => String::new(),
    };
    let _ = writeln!(doc.o, "D'où{condition} :");
    for q in m.dependent.iter().map(|d| d.coord) {
        let rate = m.reg.dot(q);
        let body = format!(
            "{} &= {}",
            super::expr::rate(&m.reg, q, 1),
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
    super::explicit::explicit_laws(doc);
}

/// Each closure projected on the ground's basis, then the relations' time derivatives.
fn closures(doc: &mut Doc, derivatives: &[crate::expr::Expr]) {
    let m = doc.m;
    let ground = m.frames.ground();
    let _ = writeln!(doc.o, "\\noindent\\textbf{{Loi entrée-sortie.}} ");
    for c in &m.closures {
        let v = &c.vector;
        let comps = v.express_in(&m.frames, ground);
        let latex = format!(
            "\\TVec{{0}} = {}",
            super::values::vector_over_bases(m, &doc.names, v)
        );
        let _ = writeln!(
            doc.o,
            "La fermeture géométrique ${latex}$, projetée sur ${}$, donne :",
            super::basis(m.frame_name(ground))
        );
        doc.inline.push(Inline {
            what: format!("closure {}", c.written),
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
    for d in derivatives {
        let body = format!("0 &= {}", lines(&super::expr_lines(d, super::LINE - 4)));
        doc.record(
            DisplayRole::Step,
            "loop relation's derivative",
            body,
            &Value::Scalar(zero.clone()),
            None,
            false,
        );
    }
}

/// Each rolling condition V(I,2/0) = 0⃗, projected on its basis (or along its directions):
/// relations linear in the rates, which read 0 once the solved rates stand in.
fn rolling(doc: &mut Doc, laws: &[RollingLaw]) {
    let m = doc.m;
    let whole = laws.iter().all(|r| r.on.is_empty());
    let title = match (whole, laws.len()) {
        (true, 1) => "Roulement sans glissement.",
        (true, _) => "Roulements sans glissement.",
        (false, 1) => "Condition de non-glissement.",
        (false, _) => "Conditions de non-glissement.",
    };
    let _ = writeln!(doc.o, "\\noindent\\textbf{{{title}}} ");
    let zero = m.reg.zero();
    for law in laws {
        let v = doc.names.quantity(&law.velocity.kind);
        let ground = m.frames.ground();
        let [i, j] = law.motion;
        let velocity = crate::kinematics::velocity(m, law.point, i, j);
        let written = &law.written;
        let mut stated = Vec::new();
        if law.on.is_empty() {
            let latex = format!("{v} = \\TVec{{0}}");
            doc.inline.push(Inline {
                what: format!("rolling condition {written}"),
                latex: latex.clone(),
                value: Value::Vector {
                    basis: ground,
                    components: velocity.express_in(&m.frames, ground),
                },
            });
            stated.push(format!("${latex}$"));
        } else {
            for &(f, a) in &law.on {
                let u = doc.names.basis_vector(a.letter(), m.frame_name(f));
                let latex = format!("{v} \\cdot {u} = 0");
                doc.inline.push(Inline {
                    what: format!("rolling condition {written} on {u}"),
                    latex: latex.clone(),
                    value: Value::Scalar(velocity.express_in(&m.frames, f)[a.index()].clone()),
                });
                stated.push(format!("${latex}$"));
            }
        }
        let (what, projected) = match &law.basis {
            Some(b) => (
                "La condition de roulement sans glissement",
                format!(", projetée sur ${}$", super::basis(b)),
            ),
            None => ("La condition de non-glissement", String::new()),
        };
        let _ = writeln!(
            doc.o,
            "{what} en ${}$, {}{projected}, donne :",
            super::point(m.point_name(law.point)),
            stated.join(" et ")
        );
        for row in &law.rows {
            doc.record(
                DisplayRole::Step,
                "rolling relation",
                format!("0 &= {}", lines(&super::expr_lines(row, super::LINE - 4))),
                &Value::Scalar(zero.clone()),
                None,
                false,
            );
        }
    }
}

/// Before the boxed rate of a coordinate (`dot(x)`, `ddot(x)`), where it comes from: the
/// loop law, the rolling condition or the screw that determines it, or the paramétrage; for
/// the second derivative of a determined coordinate, its rate first (cited where the page
/// already shows it), then « en dérivant par rapport au temps ».
pub(super) fn rate_note(doc: &mut Doc, d: &crate::derivation::Derivation) {
    let crate::quantity::QuantityKind::Rate { coordinate, order } = &d.quantity.kind else {
        return;
    };
    let m = doc.m;
    let Some(q) = m.reg.coord(coordinate) else {
        return;
    };
    let source = match super::omega::rate_source(m, q) {
        Some(s) => format!("D'après {s}"),
        None => "D'après le paramétrage".to_string(),
    };
    let rate = m.reg.rate(q, 1);
    if *order == 1 || !m.reg.coord_info(q).is_driven() {
        let _ = writeln!(doc.o, "{source} :");
        return;
    }
    let lhs = super::expr::rate_of(coordinate, 1);
    let value = super::words::shown_value(doc, &Value::Scalar(rate));
    match doc.cited(&lhs, &value) {
        Some(place) => {
            let cited = super::words::citation(&[(place, vec![lhs])]);
            let cited = cited.trim_end().trim_end_matches('.');
            let _ = writeln!(doc.o, "{cited} ; en dérivant par rapport au temps :");
        }
        None => {
            let _ = writeln!(doc.o, "{source} :");
            doc.show_keyed(DisplayRole::Step, "rate", &lhs, &lhs, &value, false);
            let _ = writeln!(doc.o, "D'où, en dérivant par rapport au temps :");
        }
    }
}
