//! The loop law in explicit form (« loi entrée-sortie explicite »), issue 37: the closure with
//! one term's direction eliminated is quadratic in a dependent length, solved for it on the
//! branch of the spec's assembly configuration.

use super::page::{DisplayRole, Doc, Inline};
use crate::derivation::{Assembly, Value};
use std::fmt::Write as _;

/// Each explicit law, in one sentence: the term eliminated, the branch and the law, inline
/// when it holds on one line (the slider–crank's), else displayed.
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
        let at = match &branch.at {
            Assembly::Scenario(n) => {
                format!("du scénario « {} »", super::escape_text(n))
            }
            Assembly::Drawn => "d'une configuration fermée du calcul numérique".into(),
        };
        let what = format!(
            "explicit loop law of {}",
            m.reg.coord_info(e.coordinate).name
        );
        let _ = write!(
            doc.o,
            "\n\\noindent\\textbf{{Loi entrée-sortie explicite.}} Le terme de la fermeture \
             porté par ${}$ isolé puis élevé au carré, la relation est du second degré en \
             ${name}$ ; sur la branche {at} (signe lu numériquement)",
            super::basis(&e.eliminated)
        );
        let value = Value::Scalar(branch.value.clone());
        match super::expr_lines(&branch.value, super::LINE - 4).as_slice() {
            [one] => {
                let latex = format!("{name} = {one}");
                // A blank line after: the next paragraph (Solide 1 : …) starts apart.
                let _ = writeln!(doc.o, ", ${latex}$.\n");
                doc.inline.push(Inline { what, latex, value });
            }
            several => {
                let _ = writeln!(doc.o, " :");
                let body = format!("{name} &= {}", several.join(" \\\\\n&\\phantom{=} "));
                doc.record(DisplayRole::Step, &what, body, &value, None, false);
            }
        }
    }
}
