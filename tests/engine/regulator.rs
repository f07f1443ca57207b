//! Application 1 (the centrifugal regulator) against hand derivations from the course.

use super::*;
use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;

fn value(m: &torseur::mechanism::Mechanism, q: &str) -> Value {
    derive(m, &Quantity::parse(q).unwrap()).unwrap().value
}

fn components(v: &Value) -> Vec<Expr> {
    v.exprs().into_iter().cloned().collect()
}

#[test]
fn every_requested_quantity_derives() {
    let m = regulator();
    assert_eq!(m.quantities().len(), 12);
    for q in m.quantities() {
        derive(&m, q).unwrap_or_else(|e| panic!("{q}: {e}"));
    }
}

#[test]
fn dynamic_torsor_of_the_rotor_at_o1() {
    // σ(O1,1/0) = I_O1(1)·θ̇1 z1 = (−E1, −D1, C1) θ̇1 (Huygens adds nothing to the third
    // column since G1 is on the axis), then δ = dσ/dt|R0 = σ̇ + θ̇1 z1 ∧ σ.
    let m = regulator();
    let d = components(&value(&m, "{D(1/0)}_O1 in B1"));
    let expected = [
        "0",
        "0",
        "0",
        "-E1*ddot(theta1) + D1*dot(theta1)^2",
        "-D1*ddot(theta1) - E1*dot(theta1)^2",
        "C1*ddot(theta1)",
    ];
    for (k, e) in expected.iter().enumerate() {
        assert_eq!(d[k], ex(&m, e), "component {k}");
    }
}

#[test]
fn delta_o2_on_x2_matches_euler_equations_plus_transport() {
    // By hand, under the symmetries of H1 (the plane (G2, y2, z2): E2 = F2 = 0, D2 stays):
    // Ω(2/0) = ω = (θ̇2, sθ2 θ̇1, cθ2 θ̇1) in B2, I ω = (A2 θ̇2, (B2 s − D2 c) θ̇1,
    // (C2 c − D2 s) θ̇1); Euler at G2: δ(G2)·x2 = (I ω̇)·x2 + ω_y (Iω)_z − ω_z (Iω)_y
    // = A2 θ̈2 + ((C2 − B2) s c + D2 (c² − s²)) θ̇1²,
    // Γ(G2)·z2 = L2 θ̈2 + s (L1 + L2 c) θ̇1², and δ(O2)·x2 = δ(G2)·x2 + m2 L2 Γ(G2)·z2.
    let m = regulator();
    let q1 = m.hypotheses().iter().find(|h| h.name == "H1").unwrap();
    let v = value(&m, "delta(O2,2/0).x2").under(q1);
    let expected = ex(
        &m,
        "A2*ddot(theta2) + (C2 - B2)*sin(theta2)*cos(theta2)*dot(theta1)^2 \
         + D2*(cos(theta2)^2 - sin(theta2)^2)*dot(theta1)^2 \
         + m2*L2*(L2*ddot(theta2) + sin(theta2)*(L1 + L2*cos(theta2))*dot(theta1)^2)",
    );
    assert_eq!(components(&v)[0], expected);
}

#[test]
fn delta_o2_general_inertia_matches_euler_with_products_of_inertia() {
    // General I_G2 = [[A,−F,−E],[−F,B,−D],[−E,−D,C]]: δ(G2) = I ω̇ + ω ∧ (I ω) in B2 (the basis
    // of the solid, where I is constant), written out here independently of the engine.
    let m = regulator();
    let (s, c) = ("sin(theta2)", "cos(theta2)");
    let w = [
        "dot(theta2)".to_string(),
        format!("{s}*dot(theta1)"),
        format!("{c}*dot(theta1)"),
    ];
    let wd = [
        "ddot(theta2)".to_string(),
        format!("{c}*dot(theta2)*dot(theta1) + {s}*ddot(theta1)"),
        format!("-{s}*dot(theta2)*dot(theta1) + {c}*ddot(theta1)"),
    ];
    let i = [
        ["A2", "-F2", "-E2"],
        ["-F2", "B2", "-D2"],
        ["-E2", "-D2", "C2"],
    ];
    let iw = |v: &[String; 3], r: usize| {
        format!(
            "(({})*({}) + ({})*({}) + ({})*({}))",
            i[r][0], v[0], i[r][1], v[1], i[r][2], v[2]
        )
    };
    // x component of I ω̇ + ω ∧ (I ω): (Iω̇)_x + ω_y (Iω)_z − ω_z (Iω)_y.
    let delta_g_x = format!(
        "{} + ({})*{} - ({})*{}",
        iw(&wd, 0),
        w[1],
        iw(&w, 2),
        w[2],
        iw(&w, 1)
    );
    let full = format!("{delta_g_x} + m2*L2*(L2*ddot(theta2) + {s}*(L1 + L2*{c})*dot(theta1)^2)");
    let v = value(&m, "delta(O2,2/0).x2");
    assert_eq!(components(&v)[0], ex(&m, &full));
}

#[test]
fn dynamic_torsor_of_e_at_o2_is_the_sum_of_the_moved_torsors() {
    // Q5: {D(E/0)}_O2 = {D(1/0)} moved to O2 + {D(2/0)}_O2.
    let m = regulator();
    let d1 = components(&value(&m, "{D(1/0)}_O2 in B1"));
    let d2 = components(&value(&m, "{D(2/0)}_O2 in B1"));
    let de = components(&value(&m, "{D(E/0)}_O2 in B1"));
    for k in 0..6 {
        assert_eq!(de[k], &d1[k] + &d2[k], "component {k}");
    }
    // δ(O2,1/0) by the change of point from O1: δ(O2) = δ(O1) + O2O1 ∧ Rd, and Rd(1/0) = 0
    // because G1 is on the fixed axis: the moment does not depend on the point.
    let d1o1 = components(&value(&m, "{D(1/0)}_O1 in B1"));
    for k in 0..6 {
        assert_eq!(d1[k], d1o1[k]);
    }
}

#[test]
fn hypotheses_zero_the_products_of_inertia_named_by_the_symmetries() {
    let m = regulator();
    // S1's planes (O1, y1, z1) and (O1, x1, z1): every product of S1 vanishes, A1 ≠ B1;
    // S2's plane (G2, y2, z2) (normal x2): the products with x, E2 and F2, vanish; D2 stays.
    let q1 = m.hypotheses().iter().find(|h| h.name == "H1").unwrap();
    let mut effects: Vec<String> = q1.effects.iter().map(ToString::to_string).collect();
    effects.sort();
    assert_eq!(effects, ["D1 = 0", "E1 = 0", "E2 = 0", "F1 = 0", "F2 = 0"]);
    let q2 = m.hypotheses().iter().find(|h| h.name == "H2").unwrap();
    assert!(
        q2.effects
            .iter()
            .any(|e| e.to_string() == "ddot(theta1) = 0")
    );
    // Under H2 (constant rates, symmetries), δ(O1,1/0) vanishes: C1 θ̈1 = 0.
    let d = value(&m, "{D(1/0)}_O1 in B1").under(q2);
    assert!(d.exprs().iter().all(|e| e.is_zero()));
}

#[test]
fn results_are_small() {
    // The canonical δ(O2,2/0)·x2 with general inertia has 13 terms: no swell.
    let m = regulator();
    let v = value(&m, "delta(O2,2/0).x2");
    assert!(v.nterms() <= 16, "{} terms", v.nterms());
}
