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
        let fast = derive_values(&m, m.quantities()).unwrap();
        for (q, f) in m.quantities().iter().zip(&fast) {
            let course = derive(&m, q).unwrap();
            assert_eq!(course.value.exprs(), f.value.exprs(), "chain {n}: {q}");
        }
    }
}

#[test]
fn term_counts_match_the_published_reference() {
    // sympy.physics.mechanics with sin² reduced to 1 − cos²: 199 terms at N=3 (issue 7).
    let m = chain(3);
    let total: usize = derive_values(&m, m.quantities())
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

/// Issue 17: a derived result longer than the float parser's former 20,000-character bound
/// (the planar chain 8's equations, the chain 5's δ(O1,E1/0)·z0) is read by the float
/// backend's own parser and evaluates to the exact value; a sum of a million terms (7 MB)
/// evaluates without a recursion as deep as its length; past 16 MiB, the message states the
/// bound.
#[test]
fn long_derived_results_are_read_back_by_the_float_parser() {
    use rand::SeedableRng;
    use torseur::numeric::NumericModel;
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/derivations/chain");
    let mut longest = 0;
    for name in ["planar_8", "chain_5"] {
        let m = torseur::spec::load(format!("{dir}/{name}.json")).unwrap();
        let model = NumericModel::new(m.spec()).unwrap();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(17);
        let s = model.sample(&mut rng).unwrap();
        let values = torseur::output::Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            ..Default::default()
        };
        let point = torseur::output::numeric_point(&m, &values).unwrap();
        for d in derive_values(&m, m.quantities()).unwrap() {
            for e in d.value.exprs() {
                let text = e.to_string();
                longest = longest.max(text.len());
                let (a, b) = (
                    e.eval(&point),
                    model.evaluate_expression(&text, &s).unwrap(),
                );
                assert!(
                    (a - b).abs() <= 1e-9 * (1.0 + a.abs()),
                    "{name}: {a} against {b}"
                );
            }
        }
    }
    assert!(
        longest > 20_000,
        "the longest result has {longest} characters"
    );
    let m = super::regulator();
    let model = NumericModel::new(m.spec()).unwrap();
    let mut s = torseur::numeric::Sample::default();
    for n in model.parameter_names() {
        s.parameters.insert(n.to_string(), 0.5);
    }
    s.coordinates.insert("theta1".into(), [0.1, 2.0, 0.0]);
    s.coordinates.insert("theta2".into(), [0.3, 0.0, 0.0]);
    let sum = "dot(theta1) - m2 + ".repeat(400_000) + "1";
    let v = model.evaluate_expression(&sum, &s).unwrap();
    assert!((v - (400_000.0 * 1.5 + 1.0)).abs() < 1e-6, "{v}");
    let product = "dot(theta1)/2*".repeat(500_000) + "1";
    assert_eq!(model.evaluate_expression(&product, &s).unwrap(), 1.0);
    let too_long = "m2 + ".repeat((16 << 20) / 5 + 1);
    let err = model
        .evaluate_expression(&too_long, &s)
        .unwrap_err()
        .to_string();
    assert!(err.contains("16 MiB"), "{err}");
    assert!(err.len() < 300, "{err}");
}
