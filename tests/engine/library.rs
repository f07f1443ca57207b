//! The library of classic problems (`derivations/*.json`, besides the regulator) against hand
//! derivations in the course's notation, and against the independent float backend.
//!
//! Every expected value below was derived by hand from the course's theorems (written out in
//! the comment of each test) and confirmed with `torseur verify`, which uses the same function
//! as `assert_equivalent!`: exact equality of canonical forms (an equation of motion may be
//! written `lhs = rhs` and is compared up to a nonzero factor made of parameters).

/// Loads `derivations/<name>.json`.
macro_rules! problem {
    ($name:literal) => {
        torseur::spec::load(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/derivations/",
            $name,
            ".json"
        ))
        .expect($name)
    };
}

/// Every requested quantity of the spec agrees with the float backend (10 samples, seed 1).
fn assert_checked(m: &torseur::mechanism::Mechanism) {
    let report = torseur::check::check(m, 10, 1).unwrap_or_else(|e| panic!("{e}"));
    assert!(report.passed(), "{report}");
}

#[test]
fn cart_pendulum_equations_of_motion_by_hand() {
    // OG = (x + l sin θ) x0 − l cos θ y0, so V(G,2/0) = (ẋ + l θ̇ cos θ) x0 + l θ̇ sin θ y0 and
    // Γ(G,2/0) = (ẍ + l θ̈ cos θ − l θ̇² sin θ) x0 + l (θ̈ sin θ + θ̇² cos θ) y0.
    // Isolate E = {1, 2}, resultant theorem on x0: the slider transmits nothing on x0 and the
    // weight is vertical, so M ẍ + m Γ(G,2/0)·x0 = F.
    // Isolate 2, moment theorem at A on z0: δ(A,2/0)·z0 = C2 θ̈ + (AG ∧ m Γ(G,2/0))·z0
    // = (C2 + m l²) θ̈ + m l cos θ ẍ; the pivot transmits no moment on z0 and the weight gives
    // (AG ∧ −m g y0)·z0 = −m g l sin θ.
    // Resultant theorem on 2 on x1 = x0 and y1 = y0: X12 = m Γ(G)·x0, Y12 − m g = m Γ(G)·y0.
    // Ec = ½ M ẋ² + ½ m V(G)² + ½ C2 θ̇² (König).
    let m = problem!("pendule_sur_chariot");
    torseur::assert_equivalent!(
        m,
        "V(G,2/0) in B0",
        "[dot(x) + l*dot(theta)*cos(theta), l*dot(theta)*sin(theta), 0]"
    );
    torseur::assert_equivalent!(
        m,
        "eom(x)",
        "(M + m)*ddot(x) + m*l*(ddot(theta)*cos(theta) - \
            dot(theta)^2*sin(theta)) = F"
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "(C2 + m*l^2)*ddot(theta) + m*l*cos(theta)*ddot(x) = -m*g*l*sin(theta)"
    );
    torseur::assert_equivalent!(
        m,
        "X12",
        "m*(ddot(x) + l*ddot(theta)*cos(theta) - l*dot(theta)^2*sin(theta))"
    );
    torseur::assert_equivalent!(
        m,
        "Y12",
        "m*g + m*l*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta))"
    );
    torseur::assert_equivalent!(
        m,
        "Ec(E/0)",
        "1/2*M*dot(x)^2 + 1/2*m*((dot(x) + l*dot(theta)*cos(theta))^2 + \
            (l*dot(theta)*sin(theta))^2) + 1/2*C2*dot(theta)^2"
    );
}

#[test]
fn double_pendulum_equations_of_motion_by_hand() {
    // Absolute angles from the downward vertical; homogeneous rods, G at the middle, C = m L²/12.
    // OA = L1 (sin θ1, −cos θ1), AG2 = L2/2 (sin θ2, −cos θ2), so
    // Γ(G2) = L1 θ̈1 (c1, s1) + L1 θ̇1² (−s1, c1) + L2/2 θ̈2 (c2, s2) + L2/2 θ̇2² (−s2, c2).
    // Isolate 2, moment at A on z0: δ(A,2/0)·z0 = m2 L2²/12 θ̈2 + (AG2 ∧ m2 Γ(G2))·z0
    // = m2 L2²/3 θ̈2 + m2 L1 L2/2 (θ̈1 cos(θ2 − θ1) + θ̇1² sin(θ2 − θ1)); weight −m2 g L2/2 sin θ2.
    // Isolate E = {1, 2}, moment at O on z0: δ(O,1/0)·z0 = m1 L1²/3 θ̈1, and
    // δ(O,2/0)·z0 = δ(A,2/0)·z0 + (OA ∧ m2 Γ(G2))·z0 adds m2 L1² θ̈1
    // + m2 L1 L2/2 (θ̈2 cos(θ2 − θ1) − θ̇2² sin(θ2 − θ1)); weights −g (m1 L1/2 s1 + m2 L1 s1 + m2
    // L2/2 s2).
    // cos(θ2 − θ1) and sin(θ2 − θ1) are written expanded (the canonical form has no sums of
    // angles).
    let m = problem!("double_pendule");
    let c21 = "(cos(theta2)*cos(theta1) + sin(theta2)*sin(theta1))";
    let s21 = "(sin(theta2)*cos(theta1) - cos(theta2)*sin(theta1))";
    torseur::assert_equivalent!(
        m,
        "eom(theta2)",
        &format!(
            "m2*L2^2/3*ddot(theta2) + m2*L1*L2/2*(ddot(theta1)*{c21} + \
            dot(theta1)^2*{s21}) + m2*g*L2/2*sin(theta2) = 0"
        )
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta1)",
        &format!(
            "(m1*L1^2/3 + m2*L1^2)*ddot(theta1) + m2*L1*L2/2*(ddot(theta2)*{c21} - \
            dot(theta2)^2*{s21}) + m2*L2^2/3*ddot(theta2) + \
            m2*L1*L2/2*(ddot(theta1)*{c21} + dot(theta1)^2*{s21}) = \
            -g*(m1*L1/2*sin(theta1) + m2*L1*sin(theta1) + m2*L2/2*sin(theta2))"
        )
    );
    torseur::assert_equivalent!(
        m,
        "Ec(E/0)",
        &format!(
            "1/2*m1*L1^2/3*dot(theta1)^2 + 1/2*m2*(L1^2*dot(theta1)^2 + \
            L2^2/4*dot(theta2)^2 + L1*L2*dot(theta1)*dot(theta2)*{c21}) + \
            1/2*m2*L2^2/12*dot(theta2)^2"
        )
    );
}

#[test]
fn spinning_top_euler_equations_by_hand() {
    // In the nutation basis B2: Ω(3/0) = θ̇ x2 + ψ̇ sin θ y2 + (φ̇ + ψ̇ cos θ) z2; by Huygens
    // I(O,3) = diag(A', A', C) with A' = A + m h², the same in B2 (revolution about z3 = z2), so
    // σ(O,3/0) = A' θ̇ x2 + A' ψ̇ sin θ y2 + C r z2 with r = φ̇ + ψ̇ cos θ.
    // O is fixed: δ(O,3/0) = d/dt σ|B2 + Ω(2/0) ∧ σ, Ω(2/0) = θ̇ x2 + ψ̇ sin θ y2 + ψ̇ cos θ z2:
    // δ·x2 = A' θ̈ + ψ̇ sin θ (C r − A' ψ̇ cos θ), δ·y2 = A' (ψ̈ sin θ + 2 ψ̇ θ̇ cos θ) − C θ̇ r,
    // δ·z2 = δ·z3 = C (φ̈ + ψ̈ cos θ − ψ̇ θ̇ sin θ).
    // The ball joint has no moment at O; the weight's moment is h z3 ∧ (−m g z0) = m g h sin θ x2.
    // So eom(θ): δ·x2 = m g h sin θ; eom(ψ): δ·z0 = sin θ δ·y2 + cos θ δ·z2 = 0; eom(φ): δ·z3 = 0.
    // Resultant on z0: Z03 − m g = m d²/dt²(h cos θ).
    let m = problem!("toupie");
    let ap = "(A + m*h^2)";
    torseur::assert_equivalent!(
        m,
        "delta(O,3/0).z3",
        "C*(ddot(phi) + ddot(psi)*cos(theta) - dot(psi)*dot(theta)*sin(theta))"
    );
    torseur::assert_equivalent!(
        m,
        "sigma(O,3/0) in B2",
        &format!(
            "[{ap}*dot(theta), {ap}*dot(psi)*sin(theta), C*(dot(phi) + \
            dot(psi)*cos(theta))]"
        )
    );
    torseur::assert_equivalent!(
        m,
        "delta(O,3/0) in B2",
        &format!(
            "[{ap}*ddot(theta) + dot(psi)*sin(theta)*(C*(dot(phi) + \
            dot(psi)*cos(theta)) - {ap}*dot(psi)*cos(theta)), \
            {ap}*(ddot(psi)*sin(theta) + 2*dot(psi)*dot(theta)*cos(theta)) - \
            C*dot(theta)*(dot(phi) + dot(psi)*cos(theta)), C*(ddot(phi) + \
            ddot(psi)*cos(theta) - dot(psi)*dot(theta)*sin(theta))]"
        )
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        &format!(
            "{ap}*ddot(theta) + dot(psi)*sin(theta)*(C*(dot(phi) + \
            dot(psi)*cos(theta)) - {ap}*dot(psi)*cos(theta)) = m*g*h*sin(theta)"
        )
    );
    torseur::assert_equivalent!(m, "eom(theta)", under "H1", &format!("dot(psi)*sin(theta)*(C*(dot(phi) + dot(psi)*cos(theta)) - \
            {ap}*dot(psi)*cos(theta)) = m*g*h*sin(theta)"));
    torseur::assert_equivalent!(
        m,
        "eom(psi)",
        &format!(
            "sin(theta)*({ap}*(ddot(psi)*sin(theta) + \
            2*dot(psi)*dot(theta)*cos(theta)) - C*dot(theta)*(dot(phi) + \
            dot(psi)*cos(theta))) + cos(theta)*C*(ddot(phi) + ddot(psi)*cos(theta) \
            - dot(psi)*dot(theta)*sin(theta)) = 0"
        )
    );
    torseur::assert_equivalent!(
        m,
        "eom(phi)",
        "C*(ddot(phi) + ddot(psi)*cos(theta) - dot(psi)*dot(theta)*sin(theta)) \
            = 0"
    );
    torseur::assert_equivalent!(
        m,
        "Z03",
        "m*g - m*h*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta))"
    );
}

#[test]
fn unbalanced_rotor_bearing_reactions_by_hand() {
    // θ̇ = ω constant: Γ(P,2/0) = −e ω² x1. The rotor turns at constant rate about a principal axis
    // through G1: {D(1/0)} = 0. At A: Rd(E/0) = −m e ω² x1 and
    // δ(A,E/0) = AP ∧ m Γ(P) = (a z0 + e x1) ∧ (−m e ω² x1) = −m e a ω² y1.
    // Isolate E, PFD at A in B0 (x1 = cos θ x0 + sin θ y0, y1 = −sin θ x0 + cos θ y0), with the
    // weights −M g y0 at G1 = c z0 and −m g y0 at P:
    // X01 = −m e ω² cos θ, Y01 = (M + m) g − m e ω² sin θ, Z01 = 0,
    // L01 + M g c + m g a = m e a ω² sin θ, M01 = −m e a ω² cos θ,
    // C_m − m g e cos θ = 0 (moment of the unbalance's weight on z0).
    let m = problem!("rotor_balourd");
    torseur::assert_equivalent!(m, "Gamma(P,2/0) in B1", "[-e*omega^2, 0, 0]");
    torseur::assert_equivalent!(
        m,
        "{D(E/0)}_A in B1",
        "[[-m*e*omega^2, 0, 0], [0, -m*e*a*omega^2, 0]]"
    );
    torseur::assert_equivalent!(m, "X01", "-m*e*omega^2*cos(theta)");
    torseur::assert_equivalent!(m, "Y01", "(M + m)*g - m*e*omega^2*sin(theta)");
    torseur::assert_equivalent!(m, "Z01", "0");
    torseur::assert_equivalent!(m, "L01", "m*e*a*omega^2*sin(theta) - (M*c + m*a)*g");
    torseur::assert_equivalent!(m, "M01", "-m*e*a*omega^2*cos(theta)");
    torseur::assert_equivalent!(m, "C_m", "m*g*e*cos(theta)");
}

#[test]
fn two_axis_robot_motor_torques_by_hand() {
    // A = h z0 is fixed. In B2: Ω(2/0) = θ̇2 x2 + θ̇1 sin θ2 y2 + θ̇1 cos θ2 z2 = (p, q, r), and by
    // Huygens (AG2 = L2 y2) I(A,2) has A2 + m2 L2² and C' = C2 + m2 L2² on its diagonal, the
    // products unchanged. δ(A,2/0)·x2 = σ̇x + q σz − r σy with σ = I(A,2) Ω:
    // = (A2 + m2 L2²) θ̈2 − (F2 s + E2 c) θ̈1 + ((C' − B2) s c + D2 (c² − s²)) θ̇1².
    // Isolate 2, moment at A on x1: C_m2 − m2 g L2 cos θ2 = δ(A,2/0)·x2 (weight: L2 y2 ∧ −m2 g z0).
    // Isolate E, moment at O on z0 (O and z0 fixed; weight vertical; motor 2 internal):
    // σ(O,E/0)·z0 = (C1 + K) θ̇1 − (F2 s + E2 c) θ̇2, K = B2 s² + C' c² − 2 D2 s c,
    // so C_m1 = (C1 + K) θ̈1 + K' θ̇1 − (F2 s + E2 c) θ̈2 − (F2 c − E2 s) θ̇2², with
    // K' = (2 (B2 − C') s c − 2 D2 (c² − s²)) θ̇2. Under H1 (E2 = F2 = 0) the θ̈2, θ̇2² terms
    // vanish.
    let m = problem!("bras_robot_deux_axes");
    let s = "sin(theta2)";
    let c = "cos(theta2)";
    let cp = "(C2 + m2*L2^2)";
    let k = "(B2*sin(theta2)^2 + (C2 + m2*L2^2)*cos(theta2)^2 - \
            2*D2*sin(theta2)*cos(theta2))";
    let kp = "(2*(B2 - (C2 + m2*L2^2))*sin(theta2)*cos(theta2) - 2*D2*(cos(theta2)^2 \
            - sin(theta2)^2))";
    torseur::assert_equivalent!(
        m,
        "delta(A,2/0).x2",
        &format!(
            "(A2 + m2*L2^2)*ddot(theta2) - (F2*{s} + E2*{c})*ddot(theta1) + (({cp} \
            - B2)*{s}*{c} + D2*({c}^2 - {s}^2))*dot(theta1)^2"
        )
    );
    torseur::assert_equivalent!(
        m,
        "C_m2",
        &format!(
            "(A2 + m2*L2^2)*ddot(theta2) - (F2*{s} + E2*{c})*ddot(theta1) + (({cp} \
            - B2)*{s}*{c} + D2*({c}^2 - {s}^2))*dot(theta1)^2 + m2*g*L2*{c}"
        )
    );
    torseur::assert_equivalent!(
        m,
        "sigma(O,E/0).z0",
        &format!("(C1 + {k})*dot(theta1) - (F2*{s} + E2*{c})*dot(theta2)")
    );
    torseur::assert_equivalent!(
        m,
        "C_m1",
        &format!(
            "(C1 + {k})*ddot(theta1) + {kp}*dot(theta2)*dot(theta1) - (F2*{s} + \
            E2*{c})*ddot(theta2) - (F2*{c} - E2*{s})*dot(theta2)^2"
        )
    );
    torseur::assert_equivalent!(m, "C_m1", under "H1", &format!("(C1 + {k})*ddot(theta1) + {kp}*dot(theta2)*dot(theta1)"));
}

#[test]
fn tilted_rotor_dynamic_moment_by_hand() {
    // Ω(2/0) = ω z1 = ω (sin α y2 + cos α z2), constant in B2 where I(O,2) is constant, so
    // σ(O,2/0) = ω (−F s − E c, B s − D c, C c − D s) in B2 (s = sin α, c = cos α) and, O fixed,
    // δ(O,2/0) = Ω(2/0) ∧ σ(O,2/0)
    // = ω² [((C − B) s c + D (c² − s²)) x2 − c (F s + E c) y2 + s (F s + E c) z2].
    // In B1 (y1 = c y2 − s z2, z1 = s y2 + c z2): δ = ω² [((C − B) s c + D (c² − s²)) x1 − (F s + E
    // c) y1],
    // constant in the shaft's frame and normal to the axis. Isolate 2, PFD at O in B1: L01 = δ·x1,
    // M01 = δ·y1, C_m = δ·z1 = 0 (the weight is along the axis through O). Disc of revolution (H1):
    // δ = (C − A) ω² sin α cos α x1.
    let m = problem!("rotor_vitesse_imposee");
    let s = "sin(alpha)";
    let c = "cos(alpha)";
    torseur::assert_equivalent!(
        m,
        "sigma(O,2/0) in B2",
        &format!("[-omega*(F*{s} + E*{c}), omega*(B*{s} - D*{c}), omega*(C*{c} - D*{s})]")
    );
    torseur::assert_equivalent!(
        m,
        "delta(O,2/0) in B2",
        &format!(
            "[omega^2*((C - B)*{s}*{c} + D*({c}^2 - {s}^2)), -omega^2*{c}*(F*{s} + \
            E*{c}), omega^2*{s}*(F*{s} + E*{c})]"
        )
    );
    torseur::assert_equivalent!(
        m,
        "delta(O,2/0) in B1",
        &format!(
            "[omega^2*((C - B)*{s}*{c} + D*({c}^2 - {s}^2)), -omega^2*(F*{s} + \
            E*{c}), 0]"
        )
    );
    torseur::assert_equivalent!(m, "delta(O,2/0) in B1", under "H1", &format!("[(C - A)*omega^2*{s}*{c}, 0, 0]"));
    torseur::assert_equivalent!(
        m,
        "L02",
        &format!("omega^2*((C - B)*{s}*{c} + D*({c}^2 - {s}^2))")
    );
    torseur::assert_equivalent!(m, "M02", &format!("-omega^2*(F*{s} + E*{c})"));
    torseur::assert_equivalent!(m, "Z02", "m*g");
    torseur::assert_equivalent!(m, "C_m", "0");
}

#[test]
fn mass_spring_damper_on_a_slope_by_hand() {
    // Isolate 2, resultant theorem on x1: m ẍ = −k (x − l0) − c ẋ + (−m g y0)·x1, with
    // y0·x1 = sin β; the slider transmits nothing along x1. On y1: Y02 − m g cos β = 0.
    let m = problem!("systeme_masse_ressort");
    torseur::assert_equivalent!(
        m,
        "eom(x)",
        "m*ddot(x) + c*dot(x) + k*(x - l0) = -m*g*sin(beta)"
    );
    torseur::assert_equivalent!(m, "Y02", "m*g*cos(beta)");
    torseur::assert_equivalent!(m, "Ec(2/0)", "1/2*m*dot(x)^2");
}

#[test]
fn ball_in_a_rotating_tube_by_hand() {
    // OP = r x1 with θ̇ = ω: V(P,2/0) = ṙ x1 + r ω y1, Γ(P,2/0) = (r̈ − r ω²) x1 + 2 ω ṙ y1
    // (centripetal and Coriolis terms). Isolate the ball: the annular link transmits nothing on
    // x1, so m (r̈ − r ω²) = 0; on y1, Y12 = 2 m ω ṙ; on z1, Z12 − m g = 0.
    // Isolate E, moment at O on z0: δ(O,1/0)·z0 = C1 θ̈ = 0 and (OP ∧ m Γ(P))·z0 = 2 m ω r ṙ,
    // so C_m = 2 m ω r ṙ. Ec = ½ C1 ω² + ½ m (ṙ² + r² ω²).
    let m = problem!("bille_tube_tournant");
    torseur::assert_equivalent!(
        m,
        "Gamma(P,2/0) in B1",
        "[ddot(r) - r*omega^2, 2*omega*dot(r), 0]"
    );
    torseur::assert_equivalent!(m, "eom(r)", "m*(ddot(r) - omega^2*r) = 0");
    torseur::assert_equivalent!(m, "Y12", "2*m*omega*dot(r)");
    torseur::assert_equivalent!(m, "Z12", "m*g");
    torseur::assert_equivalent!(m, "C_m", "2*m*omega*r*dot(r)");
    torseur::assert_equivalent!(
        m,
        "Ec(E/0)",
        "1/2*C1*omega^2 + 1/2*m*(dot(r)^2 + r^2*omega^2)"
    );
}

#[test]
fn inverted_pendulum_with_torsion_spring_by_hand() {
    // OG = l y1 = l (−sin θ, cos θ): the weight's moment at O is (OG ∧ −m g y0)·z0 = m g l sin θ.
    // Isolate 1, moment at O on z0 (O fixed): (C + m l²) θ̈ = −k θ − f θ̇ + m g l sin θ.
    // Linearised about θ = 0 (sin θ ≈ θ): (C + m l²) θ̈ + f θ̇ + (k − m g l) θ = 0.
    // Resultant on x0 and y0: X01 = m Γ(G)·x0, Y01 − m g = m Γ(G)·y0 with
    // Γ(G) = l (−θ̈ cos θ + θ̇² sin θ) x0 − l (θ̈ sin θ + θ̇² cos θ) y0.
    let m = problem!("pendule_inverse_ressort");
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "(C + m*l^2)*ddot(theta) + f*dot(theta) + k*theta = m*g*l*sin(theta)"
    );
    torseur::assert_equivalent!(
        m,
        "lin(eom(theta))",
        "(C + m*l^2)*ddot(theta) + f*dot(theta) + (k - m*g*l)*theta = 0"
    );
    torseur::assert_equivalent!(
        m,
        "X01",
        "m*l*(dot(theta)^2*sin(theta) - ddot(theta)*cos(theta))"
    );
    torseur::assert_equivalent!(
        m,
        "Y01",
        "m*g - m*l*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta))"
    );
}

#[test]
fn pendulum_on_a_slider_down_an_incline_of_constant_angle_parameter_by_hand() {
    // Frame 1 turned by the constant angle parameter α (kind angle) about z0, frame 2 from 1
    // by θ − α, so (x0, x2) = θ: x1 = (cos α, sin α), y1 = (−sin α, cos α) and x2 = (cos θ,
    // sin θ), y2 = (−sin θ, cos θ) in B0. Ω(2/0) = θ̇ z0 (α has no rate).
    // OA = x x1, AG = −l y2: V(G,2/0) = ẋ x1 + l θ̇ x2 and Γ(G,2/0) = ẍ x1 + l θ̈ x2 + l θ̇² y2
    // (dx2/dt = θ̇ y2, dy2/dt = −θ̇ x2). On B1: x2·x1 = cos(θ − α), x2·y1 = sin(θ − α),
    // y2·x1 = −sin(θ − α), y2·y1 = cos(θ − α), written expanded below:
    // cos(θ − α) = cos θ cos α + sin θ sin α, sin(θ − α) = sin θ cos α − cos θ sin α.
    // Isolate E, resultant on x1 (the slider transmits nothing along x1, weight
    // −(M + m) g y0·x1 = −(M + m) g sin α):
    // (M + m) ẍ + m l (θ̈ cos(θ − α) − θ̇² sin(θ − α)) = −(M + m) g sin α.
    // Isolate 2, moment at A on z0 (A moves: δ(A) = δ(G) + AG ∧ m Γ(G), δ(G)·z0 = C2 θ̈):
    // (−l y2 ∧ m ẍ x1)·z0 = m l ẍ cos(θ − α), (−l y2 ∧ m l θ̈ x2)·z0 = m l² θ̈; the pivot
    // transmits no moment on z1 = z0 and the weight gives (−l y2 ∧ −m g y0)·z0 = −m g l sin θ:
    // (C2 + m l²) θ̈ + m l cos(θ − α) ẍ = −m g l sin θ.
    // Isolate E, resultant on y1: m Γ(G)·y1 = Y01 − (M + m) g cos α, so
    // Y01 = (M + m) g cos α + m l (θ̈ sin(θ − α) + θ̇² cos(θ − α)).
    // Ec = ½ M ẋ² + ½ m |V(G)|² + ½ C2 θ̇², |V(G)|² = ẋ² + l² θ̇² + 2 l ẋ θ̇ cos(θ − α).
    let m = problem!("pendule_plan_incline");
    let c = "(cos(theta)*cos(alpha) + sin(theta)*sin(alpha))";
    let s = "(sin(theta)*cos(alpha) - cos(theta)*sin(alpha))";
    torseur::assert_equivalent!(m, "Omega(2/0)", "[0, 0, dot(theta)]");
    torseur::assert_equivalent!(
        m,
        "V(G,2/0) in B1",
        &format!("[dot(x) + l*dot(theta)*{c}, l*dot(theta)*{s}, 0]")
    );
    torseur::assert_equivalent!(
        m,
        "Gamma(G,2/0) in B1",
        &format!(
            "[ddot(x) + l*ddot(theta)*{c} - l*dot(theta)^2*{s}, \
            l*ddot(theta)*{s} + l*dot(theta)^2*{c}, 0]"
        )
    );
    torseur::assert_equivalent!(
        m,
        "eom(x)",
        &format!(
            "(M + m)*ddot(x) + m*l*(ddot(theta)*{c} - dot(theta)^2*{s}) = -(M + m)*g*sin(alpha)"
        )
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        &format!("(C2 + m*l^2)*ddot(theta) + m*l*{c}*ddot(x) = -m*g*l*sin(theta)")
    );
    torseur::assert_equivalent!(
        m,
        "Y01",
        &format!("(M + m)*g*cos(alpha) + m*l*(ddot(theta)*{s} + dot(theta)^2*{c})")
    );
    torseur::assert_equivalent!(
        m,
        "Ec(E/0)",
        &format!(
            "1/2*M*dot(x)^2 + 1/2*m*(dot(x)^2 + l^2*dot(theta)^2 + \
            2*l*dot(x)*dot(theta)*{c}) + 1/2*C2*dot(theta)^2"
        )
    );
}

#[test]
fn winch_whose_load_rises_by_r_theta_by_hand() {
    // OB = R x0 + (R θ − h) y0, the angle θ itself in a position: V(B,2/0) = R θ̇ y0,
    // Γ(B,2/0) = R θ̈ y0. Composition: V(B,1/0) = θ̇ z0 ∧ OB = θ̇ (R y0 − (R θ − h) x0), so
    // V(B,2/1) = V(B,2/0) − V(B,1/0) = (R θ − h) θ̇ x0.
    // σ(O,E/0)·z0 = J θ̇ + (OB ∧ m R θ̇ y0)·z0 = (J + m R²) θ̇, δ(O,E/0)·z0 = (J + m R²) θ̈
    // (O fixed). Isolate E, moment at O on z0: the pivot transmits none, the motor C_m, the
    // drum's weight acts at O, the load's gives (OB ∧ −m g y0)·z0 = −m g R:
    // (J + m R²) θ̈ = C_m − m g R. Resultant on x0: 0 = X01; on y0: m R θ̈ = Y01 − (M1 + m) g.
    // Ec = ½ J θ̇² + ½ m R² θ̇².
    let m = problem!("treuil");
    torseur::assert_equivalent!(m, "V(B,2/0) in B0", "[0, R*dot(theta), 0]");
    torseur::assert_equivalent!(m, "V(B,2/1) in B0", "[(R*theta - h)*dot(theta), 0, 0]");
    torseur::assert_equivalent!(m, "sigma(O,E/0).z0", "(J + m*R^2)*dot(theta)");
    torseur::assert_equivalent!(m, "delta(O,E/0).z0", "(J + m*R^2)*ddot(theta)");
    torseur::assert_equivalent!(m, "eom(theta)", "(J + m*R^2)*ddot(theta) = C_m - m*g*R");
    torseur::assert_equivalent!(m, "X01", "0");
    torseur::assert_equivalent!(m, "Y01", "(M1 + m)*g + m*R*ddot(theta)");
    torseur::assert_equivalent!(m, "Ec(E/0)", "1/2*(J + m*R^2)*dot(theta)^2");
}

#[test]
fn pendulum_on_a_turning_shaft_and_its_relative_equilibrium_by_hand() {
    // Ω(2/0) = ω z1 + θ̇ x1, z1 = sin θ y2 + cos θ z2. O is fixed on the axis; with
    // OG = −a z2, I_O(2) = diag(A + m a², A + m a², C) in B2 (Huygens), so
    // σ(O,2/0) = A' θ̇ x2 + A' ω sin θ y2 + C ω cos θ z2 (A' = A + m a²) and
    // δ(O,2/0)·x2 = A' θ̈ + (Ω ∧ σ)·x2 = A' θ̈ + (C − A') ω² sin θ cos θ. The weight:
    // (−a z2) ∧ (−m g z1) = m g a z2 ∧ z1 = −m g a sin θ x1. The pivot (O, x1) transmits no
    // moment on x1: A' θ̈ + (C − A') ω² sin θ cos θ + m g a sin θ = 0. At the relative
    // equilibrium θ = β (θ̇ = θ̈ = 0): sin β [m g a − (A' − C) ω² cos β] = 0.
    let m = problem!("pendule_arbre_tournant");
    torseur::assert_equivalent!(m, "Omega(2/0) in B2", "dot(theta)*x2 + omega*z1");
    torseur::assert_equivalent!(
        m,
        "delta(O,2/0).x1",
        "(A + m*a^2)*ddot(theta) + (C - A - m*a^2)*omega^2*sin(theta)*cos(theta)"
    );
    torseur::assert_equivalent!(m, "M(O,pes->2).x1", "-m*g*a*sin(theta)");
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "(A + m*a^2)*ddot(theta) + (C - A - m*a^2)*omega^2*sin(theta)*cos(theta) + m*g*a*sin(theta) = 0"
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        under "H",
        "sin(beta)*(m*g*a - (A + m*a^2 - C)*omega^2*cos(beta)) = 0"
    );
    torseur::assert_equivalent!(m, "Omega(2/0) in B2", under "H", "omega*z1");
    assert_checked(&m);
}

#[test]
fn rotor_deux_paliers_by_hand() {
    // Rotor on a vertical axis (A, z0) at the imposed rate ω, AG = a x1 + c z1, I_G(1) with
    // products D1, E1, F1 in B1; a ball joint at A and an annular joint of axis (B, z1) at
    // AB = L z1; gravity −g z1. In B1 (x1' = ω y1, y1' = −ω x1):
    //   m Γ(G) = −m a ω² x1;
    //   σ(G) = I_G Ω = ω (−E1 x1 − D1 y1 + C1 z1), so δ(G) = dσ(G)/dt = ω² (D1 x1 − E1 y1);
    //   δ(A) = δ(G) + AG ∧ m Γ(G) = ω² (D1 x1 − E1 y1) − m a c ω² y1.
    // Moments at A: of the bearing B, L z1 ∧ (X_B x1 + Y_B y1) = −L Y_B x1 + L X_B y1; of the
    // weight, (a x1 + c z1) ∧ (−m g z1) = m g a y1; of the motor, C_m z1. Hence
    //   x1: D1 ω² = −L Y_B;  y1: −(E1 + m a c) ω² = L X_B + m g a;  z1: 0 = C_m;
    // and the resultant: −m a ω² = X_A + X_B, 0 = Y_A + Y_B, 0 = Z_A − m g.
    let m = problem!("rotor_deux_paliers");
    torseur::assert_equivalent!(
        m,
        "{D(1/0)}_A in B1",
        "[-m*a*omega^2*x1, D1*omega^2*x1 - (E1 + m*a*c)*omega^2*y1]"
    );
    torseur::assert_equivalent!(m, "Y_B", "-D1*omega^2/L");
    torseur::assert_equivalent!(m, "X_B", "-(m*g*a + (E1 + m*a*c)*omega^2)/L");
    torseur::assert_equivalent!(m, "Y_A", "D1*omega^2/L");
    torseur::assert_equivalent!(m, "X_A", "-m*a*omega^2 + (m*g*a + (E1 + m*a*c)*omega^2)/L");
    torseur::assert_equivalent!(m, "Z_A", "m*g");
    torseur::assert_equivalent!(m, "C_m", "0");
    // A wrong sign in the dynamic part is caught.
    let wrong = torseur::verify::verify(&m, "X_B", "-(m*g*a - (E1 + m*a*c)*omega^2)/L", None);
    assert!(!wrong.unwrap().is_equivalent());
    // The solution divides by L, and says so.
    let sol = torseur::pfd::solve(&m).unwrap();
    assert_eq!(sol.conditions, vec![m.reg().parse("L").unwrap()]);
    // Balanced (a = D1 = E1 = 0): the bearings carry the weight alone, whatever ω.
    for u in ["X_A", "Y_A", "X_B", "Y_B"] {
        torseur::assert_equivalent!(m, u, under "H", "0");
    }
    torseur::assert_equivalent!(m, "Z_A", under "H", "m*g");
    assert_checked(&m);
}

#[test]
fn pendule_plan_incline_agrees_with_the_float_backend() {
    assert_checked(&problem!("pendule_plan_incline"));
}

#[test]
fn treuil_agrees_with_the_float_backend() {
    assert_checked(&problem!("treuil"));
}

#[test]
fn pendule_sur_chariot_agrees_with_the_float_backend() {
    assert_checked(&problem!("pendule_sur_chariot"));
}

#[test]
fn double_pendule_agrees_with_the_float_backend() {
    assert_checked(&problem!("double_pendule"));
}

#[test]
fn toupie_agrees_with_the_float_backend() {
    assert_checked(&problem!("toupie"));
}

#[test]
fn rotor_balourd_agrees_with_the_float_backend() {
    assert_checked(&problem!("rotor_balourd"));
}

#[test]
fn bras_robot_deux_axes_agrees_with_the_float_backend() {
    assert_checked(&problem!("bras_robot_deux_axes"));
}

#[test]
fn rotor_vitesse_imposee_agrees_with_the_float_backend() {
    assert_checked(&problem!("rotor_vitesse_imposee"));
}

#[test]
fn systeme_masse_ressort_agrees_with_the_float_backend() {
    assert_checked(&problem!("systeme_masse_ressort"));
}

#[test]
fn bille_tube_tournant_agrees_with_the_float_backend() {
    assert_checked(&problem!("bille_tube_tournant"));
}

#[test]
fn pendule_inverse_ressort_agrees_with_the_float_backend() {
    assert_checked(&problem!("pendule_inverse_ressort"));
}

#[test]
fn masse_ressort_forcee_by_hand() {
    // A mass M on a slider along x0 (OP = x x0), spring k (free at x = 0), damper c, and the
    // exciter's force F0 cos(Ω t) x0. Resultant on x0: M ẍ = −k x − c ẋ + F0 cos(Ω t);
    // on y0: 0 = Y01 − M g.
    let m = problem!("masse_ressort_forcee");
    torseur::assert_equivalent!(m, "Gamma(P,1/0) in B0", "[ddot(x), 0, 0]");
    torseur::assert_equivalent!(m, "R(exc->1) in B0", "F0*cos(Omega*t)*x0");
    torseur::assert_equivalent!(m, "eom(x)", "M*ddot(x) + c*dot(x) + k*x - F0*cos(Omega*t)");
    torseur::assert_equivalent!(m, "Y01", "M*g");
    // The phase Ω t turns at the imposed rate Ω: d/dt cos(Ω t) = −Ω sin(Ω t).
    let f = m.reg().parse("F0*cos(Omega*t)").unwrap();
    assert_eq!(f.dt(), m.reg().parse("-F0*Omega*sin(Omega*t)").unwrap());
    // A sign error on the forcing is caught.
    let wrong = torseur::verify::verify(
        &m,
        "eom(x)",
        "M*ddot(x) + c*dot(x) + k*x + F0*cos(Omega*t)",
        None,
    );
    assert!(!wrong.unwrap().is_equivalent());
    // The forced regime without damping: x = X cos(Ω t), so ẋ = −X Ω sin(Ω t) and
    // ẍ = −X Ω² cos(Ω t), put into eom(x) under H (c = 0) by hand, gives
    // ((k − M Ω²) X − F0) cos(Ω t): zero for all t when X = F0/(k − M Ω²).
    let h = m.hypotheses().iter().find(|h| h.name == "H").unwrap();
    let d = torseur::derivation::derive_values(
        &m,
        &[torseur::quantity::Quantity::parse("eom(x)").unwrap()],
    )
    .unwrap();
    let eom = match &d[0].value {
        torseur::derivation::Value::Scalar(e) => h.apply(e),
        v => panic!("{v:?}"),
    };
    let reg = m.reg();
    let x = reg.coord("x").unwrap();
    let var = |role| reg.index_of(role).unwrap();
    use torseur::expr::VarRole;
    let forced = eom
        .substitute(
            var(VarRole::Rate(x, 2)),
            &reg.parse("-X*Omega^2*cos(Omega*t)").unwrap(),
        )
        .substitute(
            var(VarRole::Rate(x, 1)),
            &reg.parse("-X*Omega*sin(Omega*t)").unwrap(),
        )
        .substitute(
            var(VarRole::Value(x)),
            &reg.parse("X*cos(Omega*t)").unwrap(),
        );
    assert_eq!(
        forced,
        reg.parse("((k - M*Omega^2)*X - F0)*cos(Omega*t)").unwrap()
    );
    assert_checked(&m);
}

#[test]
fn pendule_support_oscillant_by_hand() {
    // The support's imposed motion OA = a cos(Ω t) y0; a point mass m at AG = −l y2,
    // θ = (y0, y2). Γ(G) = −a Ω² cos(Ω t) y0 + l θ̈ x2 + l θ̇² y2, and as δ(G) = 0,
    // δ(A)·z0 = (AG ∧ m Γ(G))·z0 = m l² θ̈ − m l a Ω² cos(Ω t) sin θ (y2 ∧ y0 = −sin θ z0).
    // The weight's moment at A: (−l y2) ∧ (−m g y0) = −m g l sin θ z0. Hence
    //   m l² θ̈ + m l (g − a Ω² cos(Ω t)) sin θ = 0.
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/specs/pendule_support_oscillant.json"
    ))
    .unwrap();
    torseur::assert_equivalent!(m, "V(A,1/0)", "-a*Omega*sin(Omega*t)*y0");
    // The spec names its bases as the statement does, (x, y, z) and (u, v, w): a typed
    // vector may use them too. Γ(G) = −a Ω² cos(Ω t) y + l θ̈ u + l θ̇² v.
    torseur::assert_equivalent!(
        m,
        "Gamma(G,2/0)",
        "-a*Omega^2*cos(Omega*t)*y + l*ddot(theta)*u + l*dot(theta)^2*v"
    );
    torseur::assert_equivalent!(
        m,
        "delta(A,2/0).z0",
        "m*l^2*ddot(theta) - m*l*a*Omega^2*cos(Omega*t)*sin(theta)"
    );
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "m*l^2*ddot(theta) + m*l*(g - a*Omega^2*cos(Omega*t))*sin(theta)"
    );
    // As a corrigé writes it, divided by m l.
    let v = torseur::verify::verify(
        &m,
        "eom(theta)",
        "l*ddot(theta) + (g - a*Omega^2*cos(Omega*t))*sin(theta) = 0",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent());
    assert_checked(&m);
}

#[test]
fn aliases_are_written_once_and_read_by_name_everywhere() {
    // The pendulum on a shaft at ω, with the aliases a statement poses: J = A + m a² (the
    // inertia about the pivot's axis, Huygens) and K = J − C; its equation of motion by hand
    // (pendulum_on_a_turning_shaft_and_its_relative_equilibrium_by_hand) is then
    // J θ̈ + (m g a − K ω² cos θ) sin θ = 0. An alias also stands in the spec (the inertia
    // entry `Cz`), read by both sides.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/pendule_arbre_tournant.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["aliases"] = serde_json::json!([
        {"name": "J", "value": "A + m*a^2", "description": "moment d'inertie en $O$"},
        {"name": "K", "value": "J - C"},
        {"name": "Cz", "value": "C"}
    ]);
    v["solids"][1]["inertia"]["matrix"][2][2] = "Cz".into();
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "J*ddot(theta) + (m*g*a - K*omega^2*cos(theta))*sin(theta)"
    );
    let wrong = torseur::verify::verify(
        &m,
        "eom(theta)",
        "J*ddot(theta) + (m*g*a + K*omega^2*cos(theta))*sin(theta)",
        None,
    );
    assert!(!wrong.unwrap().is_equivalent());
    assert_eq!(
        m.reg().alias("K").unwrap(),
        m.reg().parse("A + m*a^2 - C").unwrap()
    );
    assert_checked(&m);
    // The key states them, and printed/mod.rs proves the statement with the rest.
    let key = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
    assert!(key.contains("On pose $J = A + m\\,a^{2}$"), "{key}");
    // Refused, with the place: a coordinate in an alias, a name taken, an alias used before
    // it is posed.
    for (aliases, path, why) in [
        (
            serde_json::json!([{"name": "J", "value": "A*cos(theta)"}]),
            "aliases[0].value",
            "parameters only",
        ),
        (
            serde_json::json!([{"name": "m", "value": "A"}]),
            "aliases[0].name",
            "duplicate",
        ),
        (
            serde_json::json!([{"name": "K", "value": "J"}, {"name": "J", "value": "A"}]),
            "aliases[0].value",
            "`J`",
        ),
    ] {
        let mut w: serde_json::Value = serde_json::from_str(&text).unwrap();
        w["aliases"] = aliases.clone();
        let e = torseur::spec::from_str(&w.to_string()).unwrap_err();
        assert!(e.to_string().contains(path), "{aliases}: {e}");
        assert!(e.to_string().contains(why), "{aliases}: {e}");
        let float = torseur::numeric::NumericModel::new(&serde_json::from_value(w).unwrap());
        assert!(float.unwrap_err().to_string().contains(path), "{aliases}");
    }
}
