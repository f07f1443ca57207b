//! The two routes of `src/derivation/` agree exactly: `derive` (the answer key's route, the
//! course's methodology step by step: σ at the point, then δ by derivation and the
//! complementary term, the PFD through its theorems) and `derive_values` (the fast route:
//! transport from the centres of inertia, one cache for the run).
//!
//! `printed/mod.rs` proves the key's displayed formulas equal to the fast route's values; here every
//! quantity of every spec is compared, shown in the key or not, in general and under every
//! hypothesis. The chain family is compared in `chain.rs`.

use super::specs_in;
use torseur::derivation::{Value, derive, derive_values};
use torseur::quantity::Quantity;

/// Equal kinds, bases, points and canonical forms.
fn same(a: &Value, b: &Value) -> bool {
    let shape = |v: &Value| match v {
        Value::Scalar(_) => (0, None, None),
        Value::Quotient(_) => (4, None, None),
        Value::Vector { basis, .. } => (1, Some(*basis), None),
        Value::Matrix(i) => (2, Some(i.basis), Some(i.point)),
        Value::Torsor { point, basis, .. } => (3, Some(*basis), Some(*point)),
    };
    shape(a) == shape(b) && a.exprs() == b.exprs()
}

#[test]
fn derive_equals_derive_values_on_every_quantity_of_every_spec_under_every_hypothesis() {
    let mut compared = 0;
    for path in specs_in(&["derivations", "tests/specs"]) {
        let m = torseur::spec::load(&path).unwrap();
        // The requested quantities, then those the questions derive or write in an equation.
        let mut ids: Vec<String> = m.quantities().iter().map(|q| q.to_string()).collect();
        for q in &m.spec().questions {
            ids.extend(q.quantities.iter().cloned());
            ids.extend(q.equations.iter().map(|e| e.quantity.clone()));
        }
        let mut seen = std::collections::HashSet::new();
        ids.retain(|id| seen.insert(id.clone()));
        let qs: Vec<Quantity> = ids.iter().map(|q| Quantity::parse(q).unwrap()).collect();
        let fast = derive_values(&m, &qs).unwrap();
        for (q, f) in qs.iter().zip(&fast) {
            let course = derive(&m, q).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            let cases = std::iter::once((None, course.value.clone(), f.value.clone())).chain(
                m.hypotheses()
                    .iter()
                    .map(|h| (Some(&h.name), course.value.under(h), f.value.under(h))),
            );
            for (h, a, b) in cases {
                assert!(
                    same(&a, &b),
                    "{}: {q} under {h:?}: derive gives {a:?}, derive_values {b:?}",
                    path.display()
                );
                compared += 1;
            }
        }
    }
    assert!(compared > 150, "only {compared} values compared");
}
