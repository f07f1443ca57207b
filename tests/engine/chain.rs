//! The « chain N » benchmark family: τk by two routes, exactly, and against the float backend.

use torseur::derivation::{derive, derive_values};

fn chain(n: usize) -> torseur::mechanism::Mechanism {
    torseur::spec::load(format!(
        "{}/derivations/chain/chain_{n}.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
}

#[test]
fn tau_by_the_definition_of_delta_equals_tau_by_transport_of_delta_g() {
    // derive: δ(Ok, j/0) = d/dt σ(Ok) + V(Ok/0) ∧ m V(Gj) for each solid (the course's route);
    // derive_values: Σ δ(Gj) + OkGj ∧ m Γ(Gj), projected by triple products.
    for n in 1..=4 {
        let m = chain(n);
        let fast = derive_values(&m, &m.quantities).unwrap();
        for (q, f) in m.quantities.iter().zip(&fast) {
            let course = derive(&m, q).unwrap();
            assert_eq!(course.value.exprs(), f.value.exprs(), "chain {n}: {q}");
        }
    }
}

#[test]
fn term_counts_match_the_published_reference() {
    // sympy.physics.mechanics with sin² reduced to 1 − cos²: 199 terms at N=3 (issue 7).
    let m = chain(3);
    let total: usize = derive_values(&m, &m.quantities)
        .unwrap()
        .iter()
        .map(|d| d.value.nterms())
        .sum();
    assert_eq!(total, 199);
}

#[test]
fn chains_up_to_four_agree_with_the_float_backend() {
    for n in 1..=4 {
        let r = torseur::check::check(&chain(n), 5, n as u64).unwrap();
        assert!(r.passed(), "chain {n}:\n{r}");
    }
}
