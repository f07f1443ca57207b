//! Property tests on random expressions, angles, rates and parameters: the canonical form,
//! evaluated, equals the float backend's independent evaluation of the text as written.

use proptest::prelude::*;
use torseur::numeric::{NumericModel, Sample};

fn atom() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("m2".to_string()),
        Just("L1".to_string()),
        Just("A2".to_string()),
        Just("dot(theta1)".to_string()),
        Just("dot(theta2)".to_string()),
        Just("ddot(theta2)".to_string()),
        (1i32..5).prop_map(|n| n.to_string()),
        (1i32..4, 2i32..5).prop_map(|(n, d)| format!("{n}/{d}")),
        (-3i32..4).prop_map(|k| format!("sin({k}*theta1)")),
        (-2i32..3, -2i32..3).prop_map(|(a, b)| format!("cos({a}*theta1 + {b}*theta2)")),
    ]
}

/// Random expression texts over the regulator's names.
pub(crate) fn expression() -> impl Strategy<Value = String> {
    atom().prop_recursive(4, 24, 3, |inner| {
        prop_oneof![
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a}) + ({b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a}) - ({b})")),
            (inner.clone(), inner.clone()).prop_map(|(a, b)| format!("({a})*({b})")),
            (inner, 2u32..4).prop_map(|(a, n)| format!("({a})^{n}")),
        ]
    })
}

fn sample(values: &[f64]) -> Sample {
    let mut s = Sample::default();
    for (k, n) in ["m2", "L1", "A2"].iter().enumerate() {
        s.parameters.insert(n.to_string(), values[k]);
    }
    for n in [
        "h1", "d1", "L2", "m1", "A1", "B1", "C1", "D1", "E1", "F1", "B2", "C2", "D2", "E2", "F2",
        "g", "f",
    ] {
        s.parameters.insert(n.to_string(), 0.5);
    }
    s.coordinates
        .insert("theta1".into(), [values[3], values[4], values[5]]);
    s.coordinates
        .insert("theta2".into(), [values[6], values[7], values[8]]);
    s
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn canonical_form_evaluates_like_the_text(
        e in expression(),
        v in proptest::collection::vec(-2.0f64..2.0, 9),
    ) {
        let m = super::regulator();
        let model = NumericModel::new(m.spec()).unwrap();
        let s = sample(&v);
        let exact = m.reg().parse(&e).unwrap();
        let vals = torseur::output::Values { parameters: s.parameters.clone(), coordinates: s.coordinates.clone(), ..Default::default() };
        let point = torseur::output::numeric_point(&m, &vals).unwrap();
        let a = exact.eval(&point);
        let b = model.evaluate_expression(&e, &s).unwrap();
        prop_assert!((a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs())), "{e}: {a} vs {b}");
        // The text form of the canonical form parses back to the same canonical form.
        prop_assert_eq!(m.reg().parse(&exact.to_string()).unwrap(), exact.clone());
        // So does the presentation form's (sin², cos 2θ, cos(θ2 − θ1), factored sums).
        // The search's form is exact before any check (the check never has to fall back).
        prop_assert_eq!(exact.presentation_candidate().to_expr(exact.registry()), exact.clone());
        let shown = exact.presentation().to_string();
        prop_assert_eq!(m.reg().parse(&shown).unwrap(), exact, "{}", shown);
    }

    #[test]
    fn trigonometric_rewritings_have_one_canonical_form(k in 1i64..5, a in -3i64..4) {
        let m = super::regulator();
        // cos(k t)^2 + sin(k t)^2 = 1 and sin(2u) = 2 sin u cos u for u = a θ1 + θ2.
        let one = m.reg().parse(&format!("cos({k}*theta1)^2 + sin({k}*theta1)^2")).unwrap();
        prop_assert!(one.is_one());
        let u = format!("{a}*theta1 + theta2");
        let l = m.reg().parse(&format!("sin(2*({u}))")).unwrap();
        let r = m.reg().parse(&format!("2*sin({u})*cos({u})")).unwrap();
        prop_assert_eq!(l, r);
    }
}
