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
    let tex = torseur::latex::answer_key(&m).unwrap();
    assert!(
        tex.contains(
            "Sous cette hypothèse : $\\theta = \\beta$, $\\dot{\\theta} = 0$, $\\ddot{\\theta} = 0$."
        ),
        "{}",
        &tex[tex.find("Hypothèse H").unwrap_or(0)..][..400]
    );
}
