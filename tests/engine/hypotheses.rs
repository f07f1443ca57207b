//! Hypotheses that fix motions (issue 15, item 5): a relative equilibrium, a rate given as a
//! parameter, a coordinate held fixed, a relation between parameters. Each checked by hand
//! and against the float backend, which draws its samples under the hypothesis on its own.

use super::*;
use torseur::check::check;

/// The regulator with H3: the rotor at the constant rate ω, the flyweight in relative
/// equilibrium at β0; and H4: θ2 held fixed, L2 = L1 and m1 = 2 m2.
fn regulator_with_motions() -> Mechanism {
    let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let params = v["parameters"].as_array_mut().unwrap();
    params.push(serde_json::json!({"name": "beta0", "kind": "angle"}));
    params.push(serde_json::json!({"name": "omega", "unit": "rad/s"}));
    let hs = v["hypotheses"].as_array_mut().unwrap();
    hs.push(
        serde_json::json!({"name": "H3", "symmetric_solids": ["1", "2"],
        "equilibrium": {"theta2": "beta0"}, "rates": {"theta1": "omega"}}),
    );
    hs.push(
        serde_json::json!({"name": "H4", "fixed_coordinates": ["theta2"],
        "relations": {"L2": "L1", "m1": "2*m2"}}),
    );
    torseur::spec::from_str(&v.to_string()).unwrap()
}

#[test]
fn a_relative_equilibrium_at_a_given_rate_by_hand() {
    let m = regulator_with_motions();
    // The general equation of θ2 with θ2 = β0, θ̇1 = ω, θ̈1 = θ̇2 = θ̈2 = 0 (and H1's zeros):
    // the balance of the centrifugal and gravity moments that fixes β0.
    torseur::assert_equivalent!(
        m,
        "eom(theta2)",
        under "H3",
        "((C2 - B2 + m2*L2^2)*sin(beta0)*cos(beta0) + D2*cos(2*beta0) + m2*L1*L2*sin(beta0))*omega^2 + m2*g*L2*cos(beta0) = 0"
    );
    // No motor torque is needed to keep the rate.
    torseur::assert_equivalent!(m, "C_m", under "H3", "0");
    // The rotation: ω z0 + 0 x1.
    torseur::assert_equivalent!(m, "Omega(2/0) in B1", under "H3", "omega*z0");
    // H4: θ̇2 = θ̈2 = 0 and L2 = L1: the flyweight's G2 turns on a circle of radius
    // L1 (1 + cos θ2) (O1O2 = d1 z0 + L1 y1, O2G2 = L1 y2).
    torseur::assert_equivalent!(
        m,
        "V(G2,2/0) in B1",
        under "H4",
        "-L1*(1 + cos(theta2))*dot(theta1)*x1"
    );
}

#[test]
fn motions_fixed_by_hypotheses_agree_with_the_float_backend() {
    let report = check(&regulator_with_motions(), 10, 3).unwrap();
    assert!(report.passed(), "{report}");
    assert!(
        report
            .rows
            .iter()
            .any(|r| r.hypothesis.as_deref() == Some("H3"))
    );
    assert!(
        report
            .rows
            .iter()
            .any(|r| r.hypothesis.as_deref() == Some("H4"))
    );
}

#[test]
fn the_key_states_what_a_motion_hypothesis_sets() {
    let m = torseur::spec::load("derivations/pendule_arbre_tournant.json").unwrap();
    let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    assert!(
        tex.contains(
            "Sous cette hypothèse : $\\theta = \\beta$, $\\dot{\\theta} = 0$, $\\ddot{\\theta} = 0$."
        ),
        "{}",
        &tex[tex.find("Hypothèse H").unwrap_or(0)..][..400]
    );
}

#[test]
fn a_small_offset_keeps_the_results_to_first_order() {
    let text = std::fs::read_to_string("derivations/rotor_balourd.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["hypotheses"] = serde_json::json!([{"name": "P", "small_parameters": ["e", "a"]}]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    // The unbalance P at AP = e x1 + a z0: I(A,2) = m [(e² + a²) Id − AP APᵀ]; to first order
    // in e and a together, every entry (of degree 2 in them) vanishes.
    torseur::assert_equivalent!(
        m,
        "I(A,2) in B1",
        "[[m*a^2, 0, -m*a*e], [0, m*(a^2 + e^2), 0], [-m*a*e, 0, m*e^2]]"
    );
    torseur::assert_equivalent!(m, "I(A,2) in B1", under "P", "[[0, 0, 0], [0, 0, 0], [0, 0, 0]]");
    // With e alone small: a² stays, e² and nothing else goes.
    v["hypotheses"] = serde_json::json!([{"name": "P", "small_parameters": ["e"]}]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    torseur::assert_equivalent!(
        m,
        "I(A,2) in B1",
        under "P",
        "[[m*a^2, 0, -m*a*e], [0, m*a^2, 0], [-m*a*e, 0, 0]]"
    );
    // Ec(2/0) = ½ m e² ω² is of second order: zero at first order.
    torseur::assert_equivalent!(m, "Ec(2/0)", "1/2*m*e^2*omega^2");
    torseur::assert_equivalent!(m, "Ec(2/0)", under "P", "0");
    // `check` compares the general results and leaves the first-order ones to the algebra.
    let report = check(&m, 5, 1).unwrap();
    assert!(report.passed(), "{report}");
    assert!(report.rows.iter().all(|r| r.hypothesis.is_none()));
    assert_eq!(report.not_compared.len(), 1);
    assert!(
        report
            .to_string()
            .contains("P: not compared with the float backend (results kept to first order")
    );
    // An unknown name is refused by both sides, with its place.
    v["hypotheses"] = serde_json::json!([{"name": "P", "small_parameters": ["eps"]}]);
    let e = torseur::spec::from_str(&v.to_string())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("hypotheses[0].small_parameters[0]") && e.contains("`eps`"),
        "{e}"
    );
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let f = torseur::numeric::NumericModel::new(&file)
        .unwrap_err()
        .to_string();
    assert!(f.contains("hypotheses[0].small_parameters[0]"), "{f}");
}

#[test]
fn a_relation_no_sample_can_satisfy_is_said_not_compared() {
    // A2 = C2 is an inertia entry of a body the float backend draws as a point cloud: that
    // hypothesis is left out of the comparison, said so, and the rest is still checked.
    let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["hypotheses"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "H5", "relations": {"A2": "C2"}}));
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let report = check(&m, 3, 1).unwrap();
    assert!(report.passed(), "{report}");
    assert_eq!(report.not_compared.len(), 1, "{report}");
    assert_eq!(report.not_compared[0].0, "H5");
    assert!(report.not_compared[0].1.contains("sets `A2`"), "{report}");
    assert!(
        report
            .rows
            .iter()
            .any(|r| r.hypothesis.as_deref() == Some("H2"))
    );
    // Derived under it all the same, exactly.
    torseur::assert_equivalent!(m, "I(G2,2)", under "H5", "[[C2, -F2, -E2], [-F2, B2, -D2], [-E2, -D2, C2]]");
}

/// The derived value of a scalar quantity, under hypothesis `h` if given.
fn scalar_under(m: &Mechanism, q: &str, h: Option<&str>) -> torseur::expr::Expr {
    let d =
        torseur::derivation::derive(m, &torseur::quantity::Quantity::parse(q).unwrap()).unwrap();
    let torseur::derivation::Value::Scalar(e) = d.value else {
        panic!("{q} is not a scalar")
    };
    match h {
        Some(h) => m
            .hypotheses()
            .iter()
            .find(|x| x.name == h)
            .unwrap()
            .apply(&e),
        None => e,
    }
}

#[test]
fn an_equilibrium_that_divides_by_a_parameter_by_hand() {
    // Issue 15, item 6: x_e = l0 − m g sin β / k, written in the spec. By hand, at rest
    // (ẋ = ẍ = 0) the resultant theorem on x1 gives 0 = −k (x_e − l0) − m g sin β, so the
    // equation of motion under E is exactly 0; k (x_e − l0) = −m g sin β, exactly.
    let m = torseur::spec::load("derivations/systeme_masse_ressort.json").unwrap();
    let eom = scalar_under(&m, "eom(x)", Some("E"));
    assert!(eom.is_zero(), "eom(x) under E = {eom}");
    let reg = m.reg();
    let xe = reg.parse("l0 - m*g*sin(beta)/k").unwrap();
    let k = reg.parse("k").unwrap();
    let lhs = &k * &(&xe - &reg.parse("l0").unwrap());
    assert_eq!(lhs, reg.parse("-m*g*sin(beta)").unwrap());
    // A wrong equilibrium (the sign of the weight's component) is not one.
    let wrong = torseur::spec::from_str(
        &std::fs::read_to_string("derivations/systeme_masse_ressort.json")
            .unwrap()
            .replace("l0 - m*g*sin(beta)/k\"", "l0 + m*g*sin(beta)/k\""),
    )
    .unwrap();
    let e = scalar_under(&wrong, "eom(x)", Some("E"));
    assert_eq!(e, wrong.reg().parse("2*m*g*sin(beta)").unwrap());
    // The text and the JSON write the quotient back as it reads.
    assert_eq!(xe.to_string(), "l0 - m*g*sin(beta)/k");
    assert_eq!(xe.presentation().to_string(), "l0 - m*g*sin(beta)/k");
}

#[test]
fn a_rate_divided_by_a_radius_by_hand() {
    // A wheel rolling without slipping at the imposed speed V: OC = x x0 + R y0, ẋ = V,
    // θ̇ = −V/R. By hand: Ω(1/0) = −V/R z0; V(I,1/0) = V(C,1/0) + IC ∧ Ω(1/0)
    // = V x0 + R y0 ∧ (−V/R) z0 = V x0 − V x0 = 0 (the rolling condition, exact only once
    // R·(1/R) = 1); σ(C,1/0) = C1 θ̇ z0, σ(I,1/0) = σ(C,1/0) + IC ∧ m V(C,1/0)
    // = −C1 V/R z0 − m R V z0; Ec = ½ m V² + ½ C1 V²/R².
    let m = torseur::spec::load("tests/specs/roue_vitesse_imposee.json").unwrap();
    torseur::assert_equivalent!(m, "Omega(1/0) in B0", "[0, 0, -V/R]");
    torseur::assert_equivalent!(m, "V(I,1/0) in B0", "[0, 0, 0]");
    torseur::assert_equivalent!(m, "sigma(I,1/0).z0", "-(C1/R + m*R)*V");
    torseur::assert_equivalent!(m, "Ec(1/0)", "1/2*m*V^2 + 1/2*C1*V^2/R^2");
    // A sign error in the rolling condition is caught.
    let v = torseur::verify::verify(&m, "sigma(I,1/0).z0", "(C1/R - m*R)*V", None).unwrap();
    assert!(!v.is_equivalent());
    // The float backend reads `-V/R` with its own parser and agrees.
    let report = check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn a_parameter_the_spec_divides_by_cannot_be_set_to_zero_or_a_sum() {
    let text = std::fs::read_to_string("derivations/systeme_masse_ressort.json").unwrap();
    let with = |relation: &str| {
        text.replace(
            "\"equilibrium\": {\"x\": \"l0 - m*g*sin(beta)/k\"}}",
            &format!(
                "\"equilibrium\": {{\"x\": \"l0 - m*g*sin(beta)/k\"}}, \"relations\": {{\"k\": \"{relation}\"}}}}"
            ),
        )
    };
    let zero = torseur::spec::from_str(&with("0")).unwrap_err().to_string();
    assert!(
        zero.contains("hypotheses[0]") && zero.contains("sets `k` to 0"),
        "{zero}"
    );
    let sum = torseur::spec::from_str(&with("m + c"))
        .unwrap_err()
        .to_string();
    assert!(
        sum.contains("hypotheses[0]") && sum.contains("the sum"),
        "{sum}"
    );
    // A product of parameters is fine: 1/k becomes 1/(2 m g) and x_e = l0 − sin β / 2.
    let m = torseur::spec::from_str(&with("2*m*g")).unwrap();
    let h = m.hypotheses().iter().find(|x| x.name == "E").unwrap();
    let xe = m.reg().parse("x").unwrap();
    let xe = h.apply(&xe);
    assert_eq!(xe, m.reg().parse("l0 - 1/2*sin(beta)").unwrap());
    // A sum below the line in a spec is refused, naming the place.
    let bad = text.replace("l0 - m*g*sin(beta)/k\"", "l0 - m*g*sin(beta)/(k + c)\"");
    let e = torseur::spec::from_str(&bad).unwrap_err().to_string();
    assert!(
        e.contains("hypotheses[0].equilibrium.x") && e.contains("the sum"),
        "{e}"
    );
}
