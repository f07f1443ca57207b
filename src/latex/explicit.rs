//! The loop law in explicit form (« loi entrée-sortie explicite », issue 37): the closure with
//! one term's direction eliminated is quadratic in a dependent length, (x − m)² = P, solved for
//! it on the branch of the spec's assembly configuration, x = m ± √P.

use super::page::{DisplayRole, Doc, Inline};
use crate::derivation::{Assembly, Value};
use std::fmt::Write as _;

/// Each explicit law: the term eliminated, the quadratic it leaves, the branch (the sign of
/// x − m at the assembly configuration) and the law.
pub(super) fn explicit_laws(doc: &mut Doc) {
    let m = doc.m;
    let Some(law) = &m.loop_law else { return };
    for e in &law.explicit {
        let Some(branch) = crate::derivation::explicit_law(m, e) else {
            continue;
        };
        let Some(x) = m.reg.value(e.coordinate) else {
            continue;
        };
        let name = super::expr(&x);
        let coordinate = &m.reg.coord_info(e.coordinate).name;
        let offset = &x - &e.center;
        let radicand = &e.root * &e.root;
        let _ = writeln!(
            doc.o,
            "\n\\noindent\\textbf{{Loi entrée-sortie explicite.}} En isolant dans la \
             fermeture le terme porté par ${}$ puis en élevant sa norme au carré, on élimine \
             l'orientation de cette base ; la relation obtenue est du second degré en ${name}$ :",
            super::basis(&e.eliminated)
        );
        let square = format!(
            "\\left({}\\right)^{{2}} &= {}",
            super::expr(&offset),
            super::expr(&radicand)
        );
        doc.record_equality(
            DisplayRole::Step,
            &format!("explicit loop law of {coordinate}, squared"),
            square,
            &Value::Scalar(&offset * &offset),
            Value::Scalar(radicand),
        );
        let at = match &branch.at {
            Assembly::Scenario(n) => format!(
                "la configuration initiale du scénario « {} »",
                super::escape_text(n)
            ),
            Assembly::Drawn => "une configuration fermée tirée par le calcul numérique".into(),
        };
        let sign = if branch.sign > 0 { ">" } else { "<" };
        let condition = format!("{} {sign} 0", super::expr(&offset));
        let _ = writeln!(
            doc.o,
            "La branche du mécanisme est celle de {at}, où ${condition}$ ; d'où :"
        );
        doc.inline.push(Inline {
            what: format!("branch of {coordinate}"),
            latex: condition,
            value: Value::Scalar(offset.clone()),
        });
        let body = format!(
            "{name} &= {}",
            super::expr_lines(&branch.value, super::LINE - 4).join(" \\\\\n&\\phantom{=} ")
        );
        doc.record(
            DisplayRole::Step,
            &format!("explicit loop law of {coordinate}"),
            body,
            &Value::Scalar(branch.value.clone()),
            None,
            false,
        );
        // A blank line: the next paragraph starts apart.
        let _ = writeln!(doc.o);
    }
}
