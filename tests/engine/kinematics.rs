//! Frames and kinematics: DCM, Ω composition, V and Γ by two routes.

use super::*;
use torseur::kinematics::*;

#[test]
fn dcm_is_exactly_orthogonal_and_matches_the_elementary_rotations() {
    let m = regulator();
    let (f0, f2) = (frame(&m, "0"), frame(&m, "2"));
    let p = m.frames().dcm(f0, f2);
    for i in 0..3 {
        for j in 0..3 {
            let mut s = m.reg().zero();
            for k in 0..3 {
                s = s + &(&p[i][k] * &p[j][k]);
            }
            let expected = if i == j {
                m.reg().one()
            } else {
                m.reg().zero()
            };
            assert_eq!(s, expected, "P Pᵀ entry ({i},{j})");
        }
    }
    // Column y2 in B0, by hand: y2 = cos θ2 y1 + sin θ2 z1, y1 = −sin θ1 x0 + cos θ1 y0.
    assert_eq!(p[0][1], ex(&m, "-sin(theta1)*cos(theta2)"));
    assert_eq!(p[1][1], ex(&m, "cos(theta1)*cos(theta2)"));
    assert_eq!(p[2][1], ex(&m, "sin(theta2)"));
}

#[test]
fn angular_velocities_compose_along_the_chain() {
    let m = regulator();
    let (f0, f1, f2) = (frame(&m, "0"), frame(&m, "1"), frame(&m, "2"));
    let sum = omega(&m, f2, f1).add(&omega(&m, f1, f0));
    assert_vec_eq(&m, &omega(&m, f2, f0), &sum, "Ω(2/0) = Ω(2/1) + Ω(1/0)");
    assert_vec_eq(
        &m,
        &omega(&m, f0, f2),
        &omega(&m, f2, f0).neg(),
        "Ω(0/2) = −Ω(2/0)",
    );
    assert_components(
        &m,
        &omega(&m, f2, f0),
        "2",
        [
            "dot(theta2)",
            "sin(theta2)*dot(theta1)",
            "cos(theta2)*dot(theta1)",
        ],
        "Ω(2/0)",
    );
}

#[test]
fn velocity_field_agrees_with_derivation_of_positions() {
    let m = regulator();
    for (pt, solid) in [
        ("G1", "1"),
        ("O2", "1"),
        ("O2", "2"),
        ("G2", "2"),
        ("O1", "1"),
    ] {
        let p = m.point(pt).unwrap();
        let i = frame(&m, solid);
        let f0 = m.frames().ground();
        let by_field = velocity(&m, p, i, f0);
        let by_derivation = velocity_by_derivation(&m, p, i, f0).expect("fixed in the solid");
        assert_vec_eq(&m, &by_field, &by_derivation, &format!("V({pt},{solid}/0)"));
        let g_field = acceleration(&m, p, i, f0);
        let g_der = acceleration_by_derivation(&m, p, i, f0).unwrap();
        assert_vec_eq(&m, &g_field, &g_der, &format!("Γ({pt},{solid}/0)"));
    }
}

#[test]
fn velocities_compose_through_the_intermediate_solid() {
    let m = regulator();
    let (f0, f1, f2) = (frame(&m, "0"), frame(&m, "1"), frame(&m, "2"));
    let g2 = m.point("G2").unwrap();
    let composed = velocity(&m, g2, f2, f1).add(&velocity(&m, g2, f1, f0));
    assert_vec_eq(
        &m,
        &velocity(&m, g2, f2, f0),
        &composed,
        "V(G2,2/0) = V(G2,2/1) + V(G2,1/0)",
    );
}

#[test]
fn velocity_of_g2_matches_the_hand_derivation() {
    // O0G2 = d1 z0 + L1 y1 + L2 y2; d/dt|R0 gives −L1 θ̇1 x1 + L2 (θ̇2 z2 − cos θ2 θ̇1 x2).
    let m = regulator();
    let v = velocity(
        &m,
        m.point("G2").unwrap(),
        frame(&m, "2"),
        m.frames().ground(),
    );
    assert_components(
        &m,
        &v,
        "2",
        ["-(L1 + L2*cos(theta2))*dot(theta1)", "0", "L2*dot(theta2)"],
        "V(G2,2/0)",
    );
}

#[test]
fn a_point_not_fixed_in_the_solid_is_refused_by_the_derivation_route() {
    let m = regulator();
    let g2 = m.point("G2").unwrap();
    assert!(velocity_by_derivation(&m, g2, frame(&m, "1"), m.frames().ground()).is_none());
}

#[test]
fn a_constant_angle_between_bases_turns_components_but_adds_no_rotation() {
    // Frame 1 turned by the constant angle alpha (a coordinate with rate 0) about z0, frame 2
    // by q about x1: Ω(2/0) = q̇ x1 only, and x1 = cos α x0 + sin α y0.
    let spec = r#"{"title": "t", "parameters": [{"name": "L"}],
      "coordinates": [{"name": "alpha", "kind": "angle", "rate": "0"}, {"name": "q", "kind": "angle"}],
      "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "alpha"}},
                 {"name": "2", "parent": "1", "rotation": {"axis": "x", "angle": "q"}}],
      "points": [{"name": "P", "from": "O0", "position": "L*y2"}]}"#;
    let m = torseur::spec::from_str(spec).unwrap();
    let (f0, f2) = (m.frames().ground(), frame(&m, "2"));
    assert_components(&m, &omega(&m, f2, f0), "1", ["dot(q)", "0", "0"], "Ω(2/0)");
    assert_components(
        &m,
        &omega(&m, f2, f0),
        "0",
        ["cos(alpha)*dot(q)", "sin(alpha)*dot(q)", "0"],
        "Ω(2/0) in B0",
    );
    assert!(ex(&m, "dot(alpha)").is_zero());
    // V(P,2/0) = L q̇ z2 (P turns with q about x1).
    let v = velocity(&m, m.point("P").unwrap(), f2, f0);
    assert_components(&m, &v, "2", ["0", "0", "L*dot(q)"], "V(P,2/0)");
}

#[test]
fn a_negative_axis_turns_the_other_way() {
    // Rotation by q about −z0: Ω(1/0) = −q̇ z0 and x1 = cos q x0 − sin q y0.
    let spec = r#"{"title": "t", "coordinates": [{"name": "q", "kind": "angle"}],
      "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "-z", "angle": "q"}}]}"#;
    let m = torseur::spec::from_str(spec).unwrap();
    let (f0, f1) = (m.frames().ground(), frame(&m, "1"));
    assert_components(&m, &omega(&m, f1, f0), "0", ["0", "0", "-dot(q)"], "Ω(1/0)");
    let p = m.frames().dcm(f0, f1);
    assert_eq!(p[0][0], ex(&m, "cos(q)"));
    assert_eq!(p[1][0], ex(&m, "-sin(q)"));
}

/// Frame 1 turned by π/2 − q1 about z0 (a constant offset, refused before as « not a
/// coordinate »), its centre of rotation I at R q1 x0 (the angle itself in a position,
/// refused before as « enters only through sin and cos »), G at L x1 from I.
const OFFSET_AND_RAW_ANGLE: &str = r#"{"title": "t",
  "parameters": [{"name": "R"}, {"name": "L"}, {"name": "m"}, {"name": "C"}],
  "coordinates": [{"name": "q1", "kind": "angle"}],
  "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "pi/2 - q1"},
              "origin": "G"}],
  "points": [{"name": "I", "from": "O0", "position": "R*q1*x0"},
             {"name": "G", "from": "I", "position": "L*x1"}],
  "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G",
    "inertia": {"point": "G", "basis": "1",
                "matrix": [["C", "0", "0"], ["0", "C", "0"], ["0", "0", "C"]]}}],
  "quantities": ["Omega(1/0)", "V(G,1/0) in B0", "sigma(O0,1/0).z0", "delta(O0,1/0).z0",
                 "Ec(1/0)"]}"#;

#[test]
fn a_rotation_by_pi_over_2_minus_q_and_the_angle_itself_in_a_position() {
    // x1 = cos(π/2 − q1) x0 + sin(π/2 − q1) y0 = sin q1 x0 + cos q1 y0, Ω(1/0) = −q̇1 z0.
    // OG = (R q1 + L sin q1) x0 + L cos q1 y0, so V(G,1/0) = (R + L cos q1) q̇1 x0
    // − L sin q1 q̇1 y0.
    // σ(O0,1/0)·z0 = C Ω·z0 + (OG ∧ m V(G))·z0
    // = −C q̇1 + m [(R q1 + L s)(−L s q̇1) − L c (R + L c) q̇1]
    // = −(C + m L² + m R L (q1 sin q1 + cos q1)) q̇1;
    // δ(O0,1/0)·z0 = d/dt of it (O0 fixed): d/dt (q1 sin q1 + cos q1) = q1 cos q1 q̇1.
    // Ec = ½ m |V(G)|² + ½ C q̇1² = ½ (C + m R² + 2 m R L cos q1 + m L²) q̇1².
    let m = torseur::spec::from_str(OFFSET_AND_RAW_ANGLE).unwrap();
    let (f0, f1) = (m.frames().ground(), frame(&m, "1"));
    let p = m.frames().dcm(f0, f1);
    assert_eq!(p[0][0], ex(&m, "sin(q1)"));
    assert_eq!(p[1][0], ex(&m, "cos(q1)"));
    torseur::assert_equivalent!(m, "Omega(1/0)", "[0, 0, -dot(q1)]");
    torseur::assert_equivalent!(
        m,
        "V(G,1/0) in B0",
        "[(R + L*cos(q1))*dot(q1), -L*sin(q1)*dot(q1), 0]"
    );
    let sigma = "-(C + m*L^2 + m*R*L*(q1*sin(q1) + cos(q1)))*dot(q1)";
    torseur::assert_equivalent!(m, "sigma(O0,1/0).z0", sigma);
    torseur::assert_equivalent!(
        m,
        "delta(O0,1/0).z0",
        "-(C + m*L^2 + m*R*L*(q1*sin(q1) + cos(q1)))*ddot(q1) - m*R*L*q1*cos(q1)*dot(q1)^2"
    );
    torseur::assert_equivalent!(
        m,
        "Ec(1/0)",
        "1/2*(C + m*R^2 + 2*m*R*L*cos(q1) + m*L^2)*dot(q1)^2"
    );
    // The angle itself is a polynomial variable: d/dt q1 = q̇1, independent of cos and sin.
    assert_eq!(ex(&m, "q1").dt(), ex(&m, "dot(q1)"));
    assert!(!(&ex(&m, "q1") - &ex(&m, "sin(q1)")).is_zero());
    // Text and LaTeX of a term holding q1 itself: the text parses back to the same value.
    let s = ex(&m, sigma);
    let text = s.to_string();
    assert!(text.contains("*q1*") || text.contains("*q1"), "{text}");
    assert_eq!(ex(&m, &text), s);
    assert_eq!(ex(&m, &s.presentation().to_string()), s);
    let tex = torseur::latex::expr(&s);
    assert!(tex.contains("q_{1}"), "{tex}");
    // The float backend agrees.
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn a_constant_angle_parameter_turns_a_frame_without_a_rate() {
    // α declared in `parameters` with kind angle: x1 = cos α x0 + sin α y0, Ω(1/0) = 0; frame 2
    // turned from 1 by q + α about z1: Ω(2/0) = q̇ z0 and x2 = cos(q + 2α) x0 + sin(q + 2α) y0
    // = (cos q (cos²α − sin²α) − 2 sin q sin α cos α) x0 + ….
    let spec = r#"{"title": "t", "parameters": [{"name": "L"}, {"name": "alpha", "kind": "angle"}],
      "coordinates": [{"name": "q", "kind": "angle"}],
      "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "alpha"}},
                 {"name": "2", "parent": "1", "rotation": {"axis": "z", "angle": "q + alpha"}}],
      "points": [{"name": "P", "from": "O0", "position": "L*x2"}],
      "solids": [{"name": "2", "frame": "2", "mass": "L", "centre": "P"}],
      "quantities": ["V(P,2/0) in B0", "Omega(2/0)", "Gamma(P,2/0) in B1"]}"#;
    let m = torseur::spec::from_str(spec).unwrap();
    let (f0, f1, f2) = (m.frames().ground(), frame(&m, "1"), frame(&m, "2"));
    assert_eq!(
        omega(&m, f1, f0).express_in(m.frames(), f0)[2],
        m.reg().zero()
    );
    assert_components(&m, &omega(&m, f2, f0), "0", ["0", "0", "dot(q)"], "Ω(2/0)");
    let p = m.frames().dcm(f0, f2);
    assert_eq!(
        p[0][0],
        ex(
            &m,
            "cos(q)*(cos(alpha)^2 - sin(alpha)^2) - 2*sin(q)*sin(alpha)*cos(alpha)"
        )
    );
    // sin²α is reduced like a coordinate's, and cos α is constant.
    assert_eq!(
        ex(&m, "sin(alpha)^2 + cos(alpha)^2"),
        m.reg().one(),
        "sin² + cos² = 1"
    );
    assert!(ex(&m, "L*cos(alpha)").is_time_independent());
    assert!(ex(&m, "cos(alpha)").dt().is_zero());
    // α is not a time coordinate: no rate.
    assert!(m.reg().parse("dot(alpha)").is_err());
    // V(P,2/0) = L q̇ y2 (P turns with q about z0, α constant).
    let v = velocity(&m, m.point("P").unwrap(), f2, f0);
    assert_components(&m, &v, "2", ["0", "L*dot(q)", "0"], "V(P,2/0)");
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}
