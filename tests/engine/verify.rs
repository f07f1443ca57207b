//! `verify` against hand derivations: an equation of motion up to a nonzero factor made of
//! parameters (found exactly and reported), relations between quantities, unknowns and
//! expressions, and the refusals (undeclared names, a vector inside an equation, an unknown
//! that no equation determines).

use super::*;
use torseur::verify::{Check, Factor, VerifyError, verify, verify_equation};

/// A point-mass pendulum (mass m at distance l) hung from a cart (mass M) on a slider along x0.
fn cart() -> Mechanism {
    torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/specs/pendule_simple_sur_chariot.json"
    ))
    .expect("the point-mass cart pendulum loads")
}

// By hand (library.rs, `cart_pendulum_equations_of_motion_by_hand`, with C2 = 0 for a point
// mass): isolate 2, moment theorem at A on z0:
//   δ(A,2/0)·z0 = (AG ∧ m Γ(G,2/0))·z0 = m l² θ̈ + m l cos θ ẍ, and the weight gives
//   (AG ∧ −m g y0)·z0 = −m g l sin θ, so eom(θ) = m l² θ̈ + m l cos θ ẍ + m g l sin θ
//   = m l (ẍ cos θ + l θ̈ + g sin θ): the corrigé's equation divided by m l.
const DIVIDED_BY_M_L: &str = "ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta) = 0";

fn factor(m: &Mechanism, numerator: &str, denominator: &str) -> Factor {
    Factor {
        numerator: ex(m, numerator),
        denominator: ex(m, denominator),
    }
}

#[test]
fn the_pendulum_equation_divided_by_m_l_is_equivalent_up_to_the_factor_m_l() {
    let m = cart();
    let v = verify(&m, "eom(theta)", DIVIDED_BY_M_L, None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(
        v.check,
        Check::EquationOfMotion {
            coordinate: "theta".into()
        }
    );
    assert_eq!(v.factor, Some(factor(&m, "m*l", "1")));
    assert!(
        v.to_string().contains("equivalent, up to the factor m*l"),
        "{v}"
    );
    // Without --quantity, as a relation: it is found to be the equation of motion of θ.
    let v = verify_equation(&m, DIVIDED_BY_M_L, None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(
        v.check,
        Check::EquationOfMotion {
            coordinate: "theta".into()
        }
    );
    assert_eq!(v.factor, Some(factor(&m, "m*l", "1")));
    // The hand form itself, sides swapped: factor 1, reported as plainly equivalent.
    let v = verify(
        &m,
        "eom(theta)",
        "-m*g*l*sin(theta) = m*l^2*ddot(theta) + m*l*cos(theta)*ddot(x)",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.factor, Some(factor(&m, "-1", "1")));
}

#[test]
fn a_factor_that_is_a_polynomial_or_a_fraction_of_parameters_is_found_in_lowest_terms() {
    let m = cart();
    // (M + m)·(ẍ cos θ + l θ̈ + g sin θ) = 0: eom(θ) = m l/(M + m) × (lhs − rhs).
    let v = verify(
        &m,
        "eom(theta)",
        "(M + m)*(ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta)) = 0",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.factor, Some(factor(&m, "m*l", "M + m")));
    // m² l² θ̈ + … = the eom times m l: the factor is 1/(m l), gcd taken out.
    let v = verify(
        &m,
        "eom(theta)",
        "m^2*l^2*(l*ddot(theta) + cos(theta)*ddot(x)) + m^2*l^2*g*sin(theta) = 0",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.factor, Some(factor(&m, "1", "m*l")));
    assert_eq!(v.factor.unwrap().to_string(), "1/(m*l)");
}

#[test]
fn a_factor_holding_a_rate_or_a_coordinate_makes_another_equation() {
    let m = cart();
    // Multiplied by θ̇: an equation that also holds at every rest (θ̇ = 0), not the same one.
    // As a relation it still holds along every motion (issue 37): (by/(m l)) × eom(θ), with
    // eom(θ) = m l (ẍ cos θ + l θ̈ + g sin θ) (by hand, above).
    for by in ["dot(theta)", "cos(theta)", "x", "ddot(x)"] {
        let text = format!("{by}*(ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta)) = 0");
        let v = verify(&m, "eom(theta)", &text, None).unwrap();
        assert!(!v.is_equivalent(), "{text}: {v}");
        match verify_equation(&m, &text, None) {
            Ok(v) => {
                assert!(v.is_equivalent(), "{text}: {v}");
                let sum = format!("lhs − rhs = {by}/(m*l) × eom(theta)");
                assert!(v.to_string().contains(&sum), "{text}: {v}");
            }
            // ẍ times an acceleration: not linear in them, undecided (never « NOT
            // equivalent » for this true relation).
            Err(e) => assert!(
                by == "ddot(x)" && matches!(e, torseur::verify::VerifyError::OutOfReach(_)),
                "{text}: {e}"
            ),
        }
    }
    // 0 = 0 is no equation, and the factor 0 is refused.
    let v = verify(&m, "eom(theta)", "0 = 0", None).unwrap();
    assert!(!v.is_equivalent(), "{v}");
}

#[test]
fn a_wrong_equation_fails_and_shows_the_term_that_differs() {
    let m = cart();
    // The sign of the weight's moment wrong: with the factor m l that matches the two other
    // terms, m l (ẍ cos θ + l θ̈ − g sin θ) − eom(θ) = −2 m g l sin θ.
    let v = verify(
        &m,
        "eom(theta)",
        "ddot(x)*cos(theta) + l*ddot(theta) - g*sin(theta) = 0",
        None,
    )
    .unwrap();
    assert!(!v.is_equivalent());
    assert_eq!(v.factor, Some(factor(&m, "m*l", "1")));
    assert_eq!(v.difference, [ex(&m, "-2*m*g*l*sin(theta)")]);
    // The slider's equation is not the pendulum's.
    let v = verify(
        &m,
        "eom(theta)",
        "(M + m)*ddot(x) + m*l*(ddot(theta)*cos(theta) - dot(theta)^2*sin(theta)) = F",
        None,
    )
    .unwrap();
    assert!(!v.is_equivalent());
}

#[test]
fn relations_between_unknowns_quantities_and_expressions_by_hand() {
    let m = cart();
    // Resultant theorem on 2, on y1 = y0: Y12 − m g = m Γ(G,2/0)·y0, with
    // Γ(G,2/0)·y0 = l (θ̈ sin θ + θ̇² cos θ) (y_G = −l cos θ, twice differentiated).
    let v = verify_equation(
        &m,
        "Y12 - m*g = m*l*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta))",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.check, Check::Relation);
    assert_eq!(v.substituted, ["Y12"]);
    // The same theorem written with the dynamic resultant, a quantity inside the equation.
    let v = verify_equation(&m, "Y12 - m*g = Rd(2/0).y0", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.substituted, ["Y12", "Rd(2/0).y0"]);
    // On x1 = x0 only the pivot acts along x0: X12 = Rd(2/0)·x0; with --quantity X12.
    let v = verify(&m, "X12", "X12 = Rd(2/0).x0", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    // A relation that forgets the accelerations: Y12 = m g fails by exactly
    // −m l (θ̈ sin θ + θ̇² cos θ), lhs − rhs with Y12 solved.
    let v = verify_equation(&m, "Y12 = m*g", None).unwrap();
    assert!(!v.is_equivalent());
    assert_eq!(v.check, Check::Relation);
    assert_eq!(
        v.difference,
        [ex(
            &m,
            "m*l*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta))"
        )]
    );
}

#[test]
fn the_motor_torque_relation_of_the_regulator_by_hand_under_h1() {
    // pfd.rs `motor_torque_of_the_regulator_by_hand`: under H1,
    // C_m = C1 θ̈1 + d/dt(K θ̇1), K = B2 s² + C2 c² − 2 D2 s c + m2 (L1 + L2 c)².
    let m = regulator();
    let (s, c) = ("sin(theta2)", "cos(theta2)");
    let k = format!("(B2*{s}^2 + C2*{c}^2 - 2*D2*{s}*{c} + m2*(L1 + L2*{c})^2)");
    let kp = format!("(2*(B2 - C2)*{s}*{c} - 2*D2*({c}^2 - {s}^2) - 2*m2*(L1 + L2*{c})*L2*{s})");
    let relation =
        format!("C_m - C1*ddot(theta1) = {k}*ddot(theta1) + {kp}*dot(theta2)*dot(theta1)");
    let v = verify_equation(&m, &relation, Some("H1")).unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.hypothesis.as_deref(), Some("H1"));
    // Without H1 the products of inertia D1, E1, F1, E2, F2 remain: not the same relation.
    assert!(
        !verify_equation(&m, &relation, None)
            .unwrap()
            .is_equivalent()
    );
    // The course's answer to Q6, written with a quantity: C_m = δ(O1,E/0)·z0.
    let v = verify_equation(&m, "C_m = delta(O1,E/0).z0", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    // Forgetting the flyweight is caught.
    let v = verify_equation(&m, "C_m = delta(O1,1/0).z0", None).unwrap();
    assert!(!v.is_equivalent());
}

#[test]
fn bad_equations_are_refused_naming_what_is_wrong() {
    let m = regulator();
    // Every undeclared name at once.
    match verify_equation(&m, "C_m = foo + bar*sin(baz)", None) {
        Err(VerifyError::UnknownNames { names, .. }) => assert_eq!(names, ["foo", "bar", "baz"]),
        other => panic!("{other:?}"),
    }
    // A vector inside an equation.
    let e = verify_equation(&m, "C_m = delta(O1,E/0)", None).unwrap_err();
    assert!(
        e.to_string().contains("`delta(O1,E/0)` is not a scalar"),
        "{e}"
    );
    // The pivot's unknowns are not solved by the regulator's pfd (two moment equations).
    let e = verify_equation(&m, "X01 = 0", None).unwrap_err();
    assert!(e.to_string().contains("`X01`"), "{e}");
    // Two `=`, an empty side, no `=` at all without a quantity.
    for text in ["C_m = 0 = 0", " = C_m", "C_m"] {
        assert!(verify_equation(&m, text, None).is_err(), "{text}");
    }
    // --quantity Q with an equation that does not hold Q.
    let e = verify(&m, "C_m", "A2 = A2", None).unwrap_err();
    assert!(e.to_string().contains("does not contain C_m"), "{e}");
    // An equation for a vector quantity.
    assert!(verify(&m, "V(G2,2/0) in B2", "C_m = 0", None).is_err());
}

#[test]
fn the_point_mass_cart_pendulum_agrees_with_the_float_backend() {
    // The equations the tests above compare with, checked against the definitions.
    let report = torseur::check::check(&cart(), 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

// By hand, the regulator: O0G2 = d1 z0 + L1 y1 + L2 y2, Ω(1/0) = θ̇1 z0, Ω(2/0) = θ̇1 z0 + θ̇2 x1;
// dy1/dt = θ̇1 z0 ∧ y1 = −θ̇1 x1, dy2/dt = Ω(2/0) ∧ y2 = −θ̇1 cos θ2 x1 + θ̇2 z2, so
//   V(G2,2/0) = −(L1 + L2 cos θ2) θ̇1 x1 + L2 θ̇2 z2,
// and V(O2,2/0) = d/dt(d1 z0 + L1 y1) = −L1 θ̇1 x1.
const V_G2_OVER_BASES: &str = "-(L1 + L2*cos(theta2))*dot(theta1)*x1 + L2*dot(theta2)*z2";

#[test]
fn a_vector_typed_over_several_bases_is_read_in_the_quantitys_basis() {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    // Asked in B2 (x1 = x2) and in the ground basis: the same typed vector.
    for q in ["V(G2,2/0)", "V(G2,2/0) in B0", "V(G2,2/0) in B1"] {
        let v = verify(&m, q, V_G2_OVER_BASES, None).unwrap();
        assert!(v.is_equivalent(), "{q}: {v}");
    }
    // z2 written over B1 (z2 = −sin θ2 y1 + cos θ2 z1), terms in any order, a basis vector
    // repeated.
    let mixed = "L2*dot(theta2)*(cos(theta2)*z1 - sin(theta2)*y1) - L1*dot(theta1)*x1 \
                 - L2*cos(theta2)*dot(theta1)*x2";
    assert!(
        verify(&m, "V(G2,2/0)", mixed, None)
            .unwrap()
            .is_equivalent()
    );
    // A sign error in one term is caught, and the difference shown in the quantity's basis.
    let wrong = "(L1 + L2*cos(theta2))*dot(theta1)*x1 + L2*dot(theta2)*z2";
    let v = verify(&m, "V(G2,2/0) in B2", wrong, None).unwrap();
    assert!(!v.is_equivalent());
    assert_eq!(
        v.difference[0],
        ex(&m, "2*(L1 + L2*cos(theta2))*dot(theta1)")
    );
    assert!(v.difference[1].is_zero() && v.difference[2].is_zero());
    // A torsor [R, M], each element over the bases or as a list.
    let torsor = "[dot(theta2)*x1 + dot(theta1)*z0, -L1*dot(theta1)*x1]";
    let v = verify(&m, "{V(2/0)}_O2", torsor, None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    let half = "[dot(theta2)*x1 + dot(theta1)*z0, [-L1*dot(theta1), 0, 0]]";
    assert!(
        verify(&m, "{V(2/0)}_O2 in B1", half, None)
            .unwrap()
            .is_equivalent()
    );
}

#[test]
fn a_bad_vector_expression_is_refused_naming_what_is_wrong() {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    let refused = |text: &str| match verify(&m, "V(G2,2/0)", text, None) {
        Err(e) => e.to_string(),
        Ok(v) => panic!("{text} accepted: {v}"),
    };
    assert!(refused("L2*dot(theta2)").contains("basis vector"));
    assert!(refused("L2*x1*y2").contains("two basis vectors"));
    assert!(refused("L2*x1^2").contains("power"));
    assert!(refused("L2*dot(theta2)*z7").contains("z7"));
    assert!(refused("[1, 2]").contains("3 components"));
}

/// Published forms divide by parameters (issue 15, item 6): a typed text may divide by a
/// nonzero polynomial in the parameters, and is compared by cross-multiplication.
#[test]
fn typed_fractions_of_parameters_are_compared_exactly() {
    let m = cart();
    // The corrigé's equation divided by m l, written with fractions: θ̈ + ẍ cos θ / l +
    // g sin θ / l = 0 is eom(θ) = m l² × (lhs − rhs).
    let v = verify_equation(
        &m,
        "ddot(theta) + ddot(x)*cos(theta)/l + g*sin(theta)/l = 0",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(v.factor, Some(factor(&m, "m*l^2", "1")));
    // A sign error under the line is caught, and shown multiplied by the denominator l.
    let v = verify_equation(
        &m,
        "ddot(theta) + ddot(x)*cos(theta)/l - g*sin(theta)/l = 0",
        None,
    )
    .unwrap();
    assert!(!v.is_equivalent());
    assert_eq!(v.denominators, [ex(&m, "l")]);
    // A value: eom(θ)/(m l) typed as a fraction of the corrigé's form.
    let v = verify(
        &m,
        "eom(theta)",
        "m*l^2*(ddot(x)*cos(theta)/l + ddot(theta) + g*sin(theta)/l) = 0",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    let v = verify(
        &m,
        "eom(theta)",
        "(m*l^2*ddot(theta) + m*l*ddot(x)*cos(theta))/(m*l) = -g*sin(theta)",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    // A denominator that holds a coordinate, a rate or that is zero is refused.
    for bad in ["ddot(theta)/x = 0", "g/dot(theta) = 0", "g/(l - l) = 0"] {
        assert!(verify_equation(&m, bad, None).is_err(), "{bad}");
    }
}

#[test]
fn a_relative_equilibrium_written_as_a_quotient_is_the_equation_of_motion() {
    // Mass-spring on an incline: eom(x) = m (ẍ + g sin β) + c ẋ + k (x − l0). At the
    // equilibrium x = x_e (ẋ = ẍ = 0): k (x_e − l0) + m g sin β = 0, the published
    // x_e = l0 − m g sin β / k.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/systeme_masse_ressort.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "x_e", "unit": "m"}));
    v["hypotheses"] = serde_json::json!([{"name": "E", "equilibrium": {"x": "x_e"}}]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let v = verify_equation(&m, "x_e = l0 - m*g*sin(beta)/k", Some("E")).unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert_eq!(
        v.check,
        Check::EquationOfMotion {
            coordinate: "x".into()
        }
    );
    assert_eq!(v.factor, Some(factor(&m, "k", "1")));
    assert!(
        !verify_equation(&m, "x_e = l0 + m*g*sin(beta)/k", Some("E"))
            .unwrap()
            .is_equivalent()
    );
}

#[test]
fn a_relation_of_parameters_only_is_not_any_relation() {
    // At the pendulum's relative equilibrium, eom(θ) under H holds parameters only; a wrong
    // relation (1 = 0, g = 0) must not be accepted up to its own quotient with the engine's.
    let m = torseur::spec::load("derivations/pendule_arbre_tournant.json").unwrap();
    for wrong in [
        "1 = 0",
        "g = 0",
        "sin(beta)*(m*g*a + (A + m*a^2 - C)*omega^2*cos(beta)) = 0",
    ] {
        let v = torseur::verify::verify(&m, "eom(theta)", wrong, Some("H")).unwrap();
        assert!(!v.is_equivalent(), "{wrong}: {v}");
    }
    let right = "sin(beta)*(m*g*a - (A + m*a^2 - C)*omega^2*cos(beta)) = 0";
    let v = torseur::verify::verify(&m, "eom(theta)", right, Some("H")).unwrap();
    assert!(v.is_equivalent(), "{v}");
    // Up to a product of parameters it is still the same relation.
    let scaled = "m*a*sin(beta)*(g - (A + m*a^2 - C)/(m*a)*omega^2*cos(beta)) = 0";
    let v = torseur::verify::verify(&m, "eom(theta)", scaled, Some("H")).unwrap();
    assert!(v.is_equivalent(), "{v}");
}
