//! A hyperstatic mechanism (« hyperstatique de degré h »), said once before the first unknown
//! of the links: its degree, the unknowns the equations do not determine one by one, and each
//! relation they give between them, the unknowns on the left.

use super::page::{DisplayRole, Doc};
use crate::derivation::Value;
use crate::pfd::Hyperstatic;
use std::fmt::Write as _;

/// « Le mécanisme est hyperstatique de degré 1 : les équations du PFD ne déterminent pas
/// Z_A et Z_B séparément, seulement : Z_A + Z_B = m g », each relation recorded with the
/// values of its two sides.
pub(super) fn state(doc: &mut Doc, h: &Hyperstatic) {
    let m = doc.m;
    let names: Vec<String> = (h.undetermined.iter())
        .map(|n| format!("${}$", super::name(n)))
        .collect();
    let listed = match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} et {last}", rest.join(", ")),
        _ => names.join(""),
    };
    let _ = writeln!(
        doc.o,
        "Le mécanisme est hyperstatique de degré {} : les équations du PFD ne déterminent \
         pas {listed} séparément, seulement :",
        h.degree
    );
    let vars: Vec<_> = (crate::pfd::unknown_vars(m).into_iter())
        .filter(|(n, _)| h.undetermined.contains(n))
        .map(|(_, v)| v)
        .collect();
    for r in &h.relations {
        // The unknowns' terms on the left, the rest on the right.
        let left = crate::expr::Expr::sum(
            &m.reg,
            (vars.iter()).map(|&v| &r.derivative(v) * &m.reg.variable(v)),
        );
        let right = -&(r - &left);
        let body = format!("{} &= {}", super::expr(&left), super::expr(&right));
        doc.record_equality(
            DisplayRole::Step,
            "hyperstatic relation",
            body,
            &Value::Scalar(left),
            Value::Scalar(right),
        );
    }
    let _ = writeln!(
        doc.o,
        "Ces inconnues dépendent des déformations et des jeux des liaisons, que le modèle de \
         solides indéformables et de liaisons parfaites ne décrit pas.\n"
    );
}
