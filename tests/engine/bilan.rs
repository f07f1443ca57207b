//! Each line of the course's « Bilan » table, checked by two routes on every solid and point.

use super::*;
use torseur::kinematics::{acceleration, point_velocity, velocity};
use torseur::mechanism::BodyId;
use torseur::torsor::*;

fn bodies(m: &torseur::mechanism::Mechanism) -> Vec<BodyId> {
    ["1", "2"].iter().map(|n| m.find_body(n).unwrap()).collect()
}

const POINTS: [&str; 6] = ["O0", "O1", "G1", "O2", "G2", "O0"];

#[test]
fn kinetic_resultant_is_the_derivative_of_the_mass_centre_position() {
    // Rc(S/R0) = m V(G, S/R0) = d/dt|R0 (m O0G), by components in B0 (no field formula).
    let m = regulator();
    let f0 = m.frames().ground();
    for s in bodies(&m) {
        let b = m.body(s);
        let pos = m
            .points()
            .vector(m.points().origin(), b.centre)
            .scale(&b.mass);
        let by_def = pos.derivative_by_components(m.frames(), f0);
        assert_vec_eq(&m, &kinetic_resultant(&m, &[s], f0), &by_def, "Rc");
        // Rd(S/R0) = d/dt Rc(S/R0).
        let rd = kinetic_resultant(&m, &[s], f0).derivative_by_components(m.frames(), f0);
        assert_vec_eq(&m, &dynamic_resultant(&m, &[s], f0), &rd, "Rd = dRc/dt");
    }
}

#[test]
fn kinetic_moment_at_any_point_agrees_with_the_change_of_point_from_g() {
    // σ(A) = I_A·Ω + m AG ∧ V(A, S/R0) (Huygens route) versus σ(G) + AG ∧ m V(G).
    let m = regulator();
    let f0 = m.frames().ground();
    for s in bodies(&m) {
        for a in POINTS {
            let a = m.point(a).unwrap();
            assert_vec_eq(
                &m,
                &kinetic_moment_solid(&m, s, a, f0),
                &kinetic_moment_via_centre(&m, s, a, f0),
                &format!("σ({},{}/0)", m.point_name(a), m.body(s).name),
            );
        }
    }
}

#[test]
fn kinetic_moment_at_a_fixed_point_is_inertia_times_rotation() {
    // O1 is fixed in S1 and R0: σ(O1,1/0) = I_O1(1)·Ω(1/0), with I_O1 by Huygens.
    let m = regulator();
    let f0 = m.frames().ground();
    let s1 = m.find_body("1").unwrap();
    let o1 = m.point("O1").unwrap();
    let i_o1 = inertia_at(&m, s1, o1);
    let direct = i_o1.apply(
        m.frames(),
        &torseur::kinematics::omega(&m, frame(&m, "1"), f0),
    );
    assert_vec_eq(
        &m,
        &kinetic_moment_solid(&m, s1, o1, f0),
        &direct,
        "σ(O1,1/0) = I_O1 Ω",
    );
    assert_components(
        &m,
        &direct,
        "1",
        ["-E1*dot(theta1)", "-D1*dot(theta1)", "C1*dot(theta1)"],
        "σ(O1,1/0)",
    );
}

#[test]
fn dynamic_moment_agrees_with_the_transport_of_delta_g() {
    // δ(A) = d/dt σ(A) + V(A/R0) ∧ m V(G/R0) versus δ(G) + AG ∧ m Γ(G), δ(G) = d/dt σ(G).
    let m = regulator();
    let f0 = m.frames().ground();
    for s in bodies(&m) {
        for a in POINTS {
            let a = m.point(a).unwrap();
            assert_vec_eq(
                &m,
                &dynamic_moment_solid(&m, s, a, f0),
                &dynamic_moment_via_centre(&m, s, a, f0),
                &format!("δ({},{}/0)", m.point_name(a), m.body(s).name),
            );
        }
    }
}

#[test]
fn at_a_fixed_point_and_at_g_delta_is_the_derivative_of_sigma() {
    let m = regulator();
    let f0 = m.frames().ground();
    for s in bodies(&m) {
        let g = m.body(s).centre;
        for a in [m.point("O1").unwrap(), m.point("O0").unwrap(), g] {
            let d_sigma = kinetic_moment_solid(&m, s, a, f0).derivative_in(m.frames(), f0);
            assert_vec_eq(
                &m,
                &dynamic_moment_solid(&m, s, a, f0),
                &d_sigma,
                "δ = dσ/dt",
            );
        }
    }
    // And at O2, which moves, the complementary term is not zero.
    let o2 = m.point("O2").unwrap();
    assert!(!point_velocity(&m, o2, f0).is_zero(m.frames()));
}

#[test]
fn torsors_change_point_consistently() {
    let m = regulator();
    let f0 = m.frames().ground();
    let e: Vec<BodyId> = bodies(&m);
    let (o1, o2) = (m.point("O1").unwrap(), m.point("O2").unwrap());
    let moved = dynamic_torsor(&m, &e, o2, f0).at(&m, o1);
    let direct = dynamic_torsor(&m, &e, o1, f0);
    assert_vec_eq(
        &m,
        &moved.moment,
        &direct.moment,
        "{D(E/0)} moved from O2 to O1",
    );
    let moved = kinetic_torsor(&m, &e, o1, f0).at(&m, o2);
    assert_vec_eq(
        &m,
        &moved.moment,
        &kinetic_torsor(&m, &e, o2, f0).moment,
        "{C(E/0)} moved",
    );
    // Sum over the set = sum of each solid's torsor at the same point.
    let sum = dynamic_torsor(&m, &e[..1], o2, f0)
        .plus(&m, &dynamic_torsor(&m, &e[1..], o2, f0))
        .unwrap();
    assert_vec_eq(&m, &sum.moment, &direct.at(&m, o2).moment, "sum over E");
    // Adding torsors at different points is an error, not a silent mistake.
    assert!(
        dynamic_torsor(&m, &e[..1], o1, f0)
            .plus(&m, &dynamic_torsor(&m, &e[1..], o2, f0))
            .is_err()
    );
}

#[test]
fn huygens_transport_round_trips_and_matches_the_point_mass_formula() {
    let m = regulator();
    let s2 = m.find_body("2").unwrap();
    let o2 = m.point("O2").unwrap();
    let i_o2 = inertia_at(&m, s2, o2);
    let i_g2 = inertia_at_centre(&m, s2).unwrap();
    // O2G2 = L2 y2: the Huygens term adds m2 L2² to the x and z moments only.
    let d = |r: usize, c: usize| &i_o2.matrix[r][c] - &i_g2.matrix[r][c];
    assert_eq!(d(0, 0), ex(&m, "m2*L2^2"));
    assert_eq!(d(2, 2), ex(&m, "m2*L2^2"));
    for (r, c) in [(1, 1), (0, 1), (0, 2), (1, 2)] {
        assert!(d(r, c).is_zero(), "entry {r},{c}");
    }
    // Change of basis there and back is exact.
    let back = i_o2
        .in_basis(m.frames(), frame(&m, "0"))
        .in_basis(m.frames(), frame(&m, "2"));
    for r in 0..3 {
        for c in 0..3 {
            assert_eq!(back.matrix[r][c], i_o2.matrix[r][c]);
        }
    }
    let _ = (velocity, acceleration);
}

#[test]
fn inertia_given_at_another_point_is_moved_to_g_by_huygens() {
    // The flyweight's inertia given at O2 instead of G2: O2G2 = L2 y2, so by hand
    // I_O2 = I_G2 + m2 diag(L2², 0, L2²). Every derived quantity must be unchanged.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["solids"][1]["inertia"]["point"] = "O2".into();
    v["solids"][1]["inertia"]["matrix"][0][0] = "A2 + m2*L2^2".into();
    v["solids"][1]["inertia"]["matrix"][2][2] = "C2 + m2*L2^2".into();
    v["solids"][1]["symmetries"] = serde_json::json!([]);
    v["hypotheses"] = serde_json::json!([]);
    v["questions"] = serde_json::json!([]);
    let moved = torseur::spec::from_str(&v.to_string()).unwrap();
    let m = regulator();
    for q in m.quantities() {
        let a = torseur::derive(&m, q).unwrap().value;
        let b = torseur::derive(&moved, q).unwrap().value;
        let (a, b): (Vec<String>, Vec<String>) = (
            a.exprs().iter().map(|e| e.to_string()).collect(),
            b.exprs().iter().map(|e| e.to_string()).collect(),
        );
        assert_eq!(a, b, "{q}");
    }
}
