//! Numeric evaluation demands only the parameters and coordinates the requested quantities
//! hold; the value then agrees with the independent float backend.

use super::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use torseur::derivation::{Value, derive_values};
use torseur::numeric::NumericModel;
use torseur::output::{Values, numeric_point_for};
use torseur::quantity::Quantity;

#[test]
fn a_dynamic_moment_is_evaluated_without_g_and_f() {
    // δ(O2,2/0) is kinematics and inertia only: gravity g and friction f enter the PFD, not it.
    let m = regulator();
    let q = Quantity::parse("delta(O2,2/0) in B2").unwrap();
    let d = derive_values(&m, std::slice::from_ref(&q))
        .unwrap()
        .remove(0);
    let Value::Vector { components, .. } = &d.value else {
        panic!("a vector");
    };
    let model = NumericModel::new(m.spec()).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..5 {
        let s = model.sample(&mut rng).unwrap();
        let mut values = Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            ..Default::default()
        };
        values.parameters.remove("g");
        values.parameters.remove("f");
        let exprs: Vec<&Expr> = components.iter().collect();
        let point = numeric_point_for(&m, &values, &exprs).unwrap();
        let symbolic: Vec<f64> = components.iter().map(|e| e.eval(&point)).collect();
        // The float backend, from the definitions, with the whole sample.
        let float = model.evaluate(&q, &s, "2").unwrap().numbers();
        for (a, b) in symbolic.iter().zip(&float) {
            assert!(
                (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
                "{symbolic:?} vs {float:?}"
            );
        }
    }
}

#[test]
fn the_missing_parameters_and_coordinates_are_named_exactly() {
    let m = regulator();
    // δ(O2,2/0)·x2 holds A2, B2, C2, D2, E2, F2, L1, L2, m2, θ1 and θ2 (README's closed form).
    let e = ex(
        &m,
        "-(E2*cos(theta2) + F2*sin(theta2))*ddot(theta1) + m2*L1*L2*sin(theta2)*dot(theta1)^2",
    );
    let values = Values::parse(
        r#"{"parameters": {"E2": 1, "L1": 1, "L2": 1},
            "coordinates": {"theta2": [0, 0, 0]}}"#,
    )
    .unwrap();
    let err = numeric_point_for(&m, &values, &[&e]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "values: missing parameters `m2`, `F2` and coordinate `theta1` (the requested \
         quantities hold them)"
    );
    // Everything it holds given, nothing else: it evaluates.
    let values = Values::parse(
        r#"{"parameters": {"E2": 1, "F2": 0, "L1": 1, "L2": 1, "m2": 2},
            "coordinates": {"theta1": [0, 3, 0.5], "theta2": [0, 0, 0]}}"#,
    )
    .unwrap();
    let point = numeric_point_for(&m, &values, &[&e]).unwrap();
    // θ2 = 0: −E2 θ̈1 + 0 = −0.5.
    assert_eq!(e.eval(&point), -0.5);
}
