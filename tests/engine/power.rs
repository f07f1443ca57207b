//! The power of the actions, P(from→on/R) and P_int(E) (issue 16, item 3: the kinetic energy
//! theorem): by hand, against Lagrange's equations (the energy theorem as an exact identity),
//! and against the float backend, which sums R·V + M·Ω over its own actions and point clouds.

use super::*;
use torseur::mechanism::BodyId;

/// Every solid of the mechanism (the whole of E for the energy theorem).
fn all_solids(m: &Mechanism) -> Vec<BodyId> {
    m.bodies()
        .iter()
        .flat_map(|b| m.solids_of(&b.name).unwrap())
        .collect()
}

#[test]
fn powers_by_hand() {
    // Inverted pendulum on a torsion spring k and a viscous friction f at O (OG = l y1, the
    // weight −m g y0): V(G,1/0) = −l θ̇ x1, so P(pes→1/0) = −m g y0·(−l θ̇ x1) = m g l θ̇ sin θ
    // (y0·x1 = −sin θ). The pivot transmits −(k θ + f θ̇) z0 as moment on z0, and
    // Ω(1/0) = θ̇ z0: P(0→1/0) = −(k θ + f θ̇) θ̇.
    let m = torseur::spec::load("derivations/pendule_inverse_ressort.json").unwrap();
    torseur::assert_equivalent!(m, "P(pes->1/0)", "m*g*l*sin(theta)*dot(theta)");
    torseur::assert_equivalent!(m, "P(0->1/0)", "-(k*theta + f*dot(theta))*dot(theta)");
    torseur::assert_equivalent!(
        m,
        "P(ext->1/0)",
        "(m*g*l*sin(theta) - k*theta - f*dot(theta))*dot(theta)"
    );
    let wrong =
        torseur::verify::verify(&m, "P(pes->1/0)", "-m*g*l*sin(theta)*dot(theta)", None).unwrap();
    assert!(!wrong.is_equivalent());
    // The regulator: the motor's torque C_m z0 on 1 turning at θ̇1 z0 gives C_m θ̇1; the pivot
    // 1–2 with viscous friction f on x1 gives the inter-effort power −f θ̇2²; the pivot 0–1 is
    // perfect and its point O1 fixed: no power. The weight of 2 lowers G2 by L2 sin θ2 (OG2·z0
    // holds L2 sin θ2): −m2 g L2 θ̇2 cos θ2.
    let m = regulator();
    torseur::assert_equivalent!(m, "P(moteur->E/0)", "C_m*dot(theta1)");
    torseur::assert_equivalent!(m, "Pint(E)", "-f*dot(theta2)^2");
    torseur::assert_equivalent!(m, "P(0->1/0)", "0");
    torseur::assert_equivalent!(
        m,
        "P(ext->E/0)",
        "C_m*dot(theta1) - m2*g*L2*cos(theta2)*dot(theta2)"
    );
    // Inside E, the actions of 1 on 2 are internal.
    assert!(
        torseur::derivation::derive(
            &m,
            &torseur::quantity::Quantity::parse("P(1->E/0)").unwrap()
        )
        .is_err()
    );
}

#[test]
fn the_kinetic_energy_theorem_is_lagrange_summed_over_the_rates() {
    // For the whole mechanism (every solid, R0 galilean, no imposed rate), the kinetic energy
    // theorem dEc/dt = P(ext→E/0) + P_int(E) is the sum of Lagrange's equations weighted by
    // the rates: Σ q̇ (d/dt ∂Ec/∂q̇ − ∂Ec/∂q + ∂Ep/∂q − Q_q) = dEc/dt − P, exactly, the links'
    // unknowns included. Lagrange's side is built by `pfd::lagrange` from the energies and
    // virtual powers (∂V/∂q̇), the power side from each action's R·V + M·Ω.
    let mut tried = 0;
    for path in specs_in(&["derivations", "tests/specs"]) {
        let m = torseur::spec::load(&path).unwrap();
        let reg = m.reg();
        // A constant imposed rate needs the torque that keeps it; a driven one (a gear
        // ratio) is a relation between the coordinates, which Lagrange's side follows.
        if reg
            .coordinates()
            .iter()
            // A nonholonomic relation (ẋ = R θ̇ cos ψ) needs multipliers, which Lagrange's
            // side does not have.
            .any(|c| (c.has_imposed_rate() && !c.is_driven()) || !c.is_holonomic())
            || m.bodies().is_empty()
        {
            continue;
        }
        let all = all_solids(&m);
        let g0 = m.frames().ground();
        let ec = torseur::pfd::kinetic_energy(&m, &all);
        let p_ext = torseur::pfd::power(&m, "ext", &all, "all", g0).unwrap();
        let p_int = torseur::pfd::internal_power(&m, &all);
        let theorem = &(&ec.dt() - &p_ext) - &p_int;
        let mut lagrange = reg.zero();
        for c in reg.coordinates().iter().filter(|c| !c.has_imposed_rate()) {
            let q = reg.coord(&c.name).unwrap();
            lagrange = &lagrange + &(&reg.dot(q) * &torseur::pfd::lagrange(&m, q));
        }
        assert_eq!(theorem, lagrange, "{}", path.display());
        tried += 1;
    }
    assert!(tried >= 10, "{tried} specs");
}

#[test]
fn powers_agree_with_the_float_backend() {
    for (file, extra) in [
        (
            "derivations/regulateur_centrifuge.json",
            &[
                "P(ext->E/0)",
                "Pint(E)",
                "P(1->2/0)",
                "P(ext->2/1)",
                "P(pes->2/0)",
            ][..],
        ),
        (
            "derivations/pendule_inverse_ressort.json",
            &["P(ext->1/0)", "P(0->1/0)"][..],
        ),
        (
            "derivations/double_pendule.json",
            &["P(ext->E/0)", "Pint(E)", "P(1->2/0)", "P(2->1/0)"][..],
        ),
        (
            "tests/specs/roue_vitesse_imposee.json",
            &["P(ext->1/0)"][..],
        ),
    ] {
        let text = std::fs::read_to_string(file).unwrap();
        let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let qs = v["quantities"].as_array_mut().unwrap();
        for q in extra {
            qs.push((*q).into());
        }
        let m = match torseur::spec::from_str(&v.to_string()) {
            Ok(m) => m,
            Err(e) => panic!("{file}: {e}"),
        };
        let report = torseur::check::check(&m, 10, 2).unwrap();
        assert!(report.passed(), "{file}: {report}");
        for q in extra {
            assert!(
                report.rows.iter().any(|r| r.quantity == *q),
                "{file}: {q} not checked"
            );
        }
    }
}

#[test]
fn a_gear_train_and_its_equivalent_inertia_by_hand() {
    // Pinion 1 (J1, r1) on (O, z0), wheel 2 (J2, r2) on (O2, z0), OO2 = (r1 + r2) x0, meshing
    // at I, OI = r1 x0; the pitch circles roll without slipping: θ̇2 = −(r1/r2) θ̇1.
    // V(I,1/0) = θ̇1 z0 ∧ r1 x0 = r1 θ̇1 y0; V(I,2/0) = θ̇2 z0 ∧ (−r2 x0) = −r2 θ̇2 y0 = r1 θ̇1 y0:
    // the same, so the tooth force T y0 (1 on 2 at I) has no power inside E.
    // Ec = ½ J1 θ̇1² + ½ J2 θ̇2² = ½ (J1 + J2 r1²/r2²) θ̇1²: J_eq = J1 + J2 r1²/r2².
    // Isolate 2, moment at O2 on z0: J2 θ̈2 = (O2I ∧ T y0)·z0 + C_r = −r2 T + C_r, so
    // T = (C_r + J2 (r1/r2) θ̈1)/r2. Isolate 1, moment at O on z0: J1 θ̈1 = C_m − r1 T, so
    // (J1 + J2 r1²/r2²) θ̈1 = C_m − (r1/r2) C_r; the power of the exterior actions is
    // C_m θ̇1 + C_r θ̇2 = (C_m − (r1/r2) C_r) θ̇1.
    let m = torseur::spec::load("derivations/train_engrenages.json").unwrap();
    torseur::assert_equivalent!(m, "V(I,1/0) in B0", "r1*dot(theta1)*y0");
    torseur::assert_equivalent!(m, "V(I,2/0) in B0", "r1*dot(theta1)*y0");
    torseur::assert_equivalent!(m, "J_eq(theta1)", "J1 + J2*r1^2/r2^2");
    torseur::assert_equivalent!(m, "Ec(E/0)", "1/2*(J1 + J2*(r1/r2)^2)*dot(theta1)^2");
    torseur::assert_equivalent!(m, "T", "(C_r + J2*r1/r2*ddot(theta1))/r2");
    torseur::assert_equivalent!(
        m,
        "eom(theta1)",
        "(J1 + J2*r1^2/r2^2)*ddot(theta1) = C_m - r1/r2*C_r"
    );
    torseur::assert_equivalent!(m, "P(ext->E/0)", "(C_m - r1/r2*C_r)*dot(theta1)");
    torseur::assert_equivalent!(m, "Pint(E)", "0");
    // The ratio squared is what a wrong reduction forgets.
    let v = torseur::verify::verify(&m, "J_eq(theta1)", "J1 + J2*r1/r2", None).unwrap();
    assert!(!v.is_equivalent());
    // The float backend reads the driven rate `-r1/r2*dot(theta1)` with its own parser.
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
    // Two free rates: Ec is not ½ J θ̇1² alone.
    let free = torseur::spec::from_str(
        &std::fs::read_to_string("derivations/train_engrenages.json")
            .unwrap()
            .replace(", \"rate\": \"-r1/r2*dot(theta1)\"", ""),
    )
    .unwrap();
    let e = torseur::derivation::derive(
        &free,
        &torseur::quantity::Quantity::parse("J_eq(theta1)").unwrap(),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("another rate is free"), "{e}");
}

#[test]
fn a_disc_rolling_down_an_incline_by_hand() {
    // OC = x x1 + R y1, CI = −R y1, θ̇ = −ẋ/R (driven). V(I,2/0) = ẋ x1 + θ̇ z0 ∧ (−R y1)
    // = (ẋ + R θ̇) x1 = 0. Ec = ½ m ẋ² + ½ J θ̇² = ½ (m + J/R²) ẋ²: the equivalent mass.
    // Moment at I on z0 (the contact force passes through I; V(I/0) = ẋ x1 ∥ V(C), so
    // δ(I) = dσ(I)/dt): σ(I)·z0 = J θ̇ + (IC ∧ m V(C))·z0 = −(J/R + m R) ẋ, and the weight
    // gives (R y1 ∧ −m g y0)·z0 = m g R sin α: −(J/R + m R) ẍ = m g R sin α. On x1 and y1:
    // m ẍ = T − m g sin α, 0 = N − m g cos α. The contact does not work: P = −m g ẋ sin α.
    let m = torseur::spec::load("derivations/disque_plan_incline.json").unwrap();
    torseur::assert_equivalent!(m, "V(I,2/0) in B1", "[0, 0, 0]");
    torseur::assert_equivalent!(m, "J_eq(x)", "m + J/R^2");
    torseur::assert_equivalent!(m, "eom(x)", "(m + J/R^2)*ddot(x) + m*g*sin(alpha) = 0");
    torseur::assert_equivalent!(m, "T", "m*(ddot(x) + g*sin(alpha))");
    torseur::assert_equivalent!(m, "N", "m*g*cos(alpha)");
    torseur::assert_equivalent!(m, "P(ext->2/0)", "-m*g*sin(alpha)*dot(x)");
    torseur::assert_equivalent!(m, "P(contact->2/0)", "0");
    // Rolling the wrong way (θ̇ = +ẋ/R) slips: V(I,2/0) = 2 ẋ x1.
    let mut v: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string("derivations/disque_plan_incline.json").unwrap(),
    )
    .unwrap();
    v.as_object_mut().unwrap().remove("rolling");
    v["coordinates"][1]["rate"] = "dot(x)/R".into();
    let slipping = torseur::spec::from_str(&v.to_string()).unwrap();
    torseur::assert_equivalent!(slipping, "V(I,2/0) in B1", "2*dot(x)*x1");
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn a_wheel_rolling_on_a_plane_by_hand() {
    // A vertical wheel, heading ψ about z0, spin θ about y1, OC = x x0 + y y0 + R z0, rolling
    // at I (CI = −R z0): V(I,2/0) = V(C) + (ψ̇ z0 + θ̇ y1) ∧ (−R z0) = V(C) − R θ̇ x1 = 0, so
    // ẋ = R θ̇ cos ψ, ẏ = R θ̇ sin ψ (nonholonomic: the coefficients hold ψ).
    // Γ(C,2/0) = d/dt (R θ̇ x1) = R θ̈ x1 + R θ̇ ψ̇ y1.
    // σ(C) = A ψ̇ z0 + C2 θ̇ y1 (axisymmetric), δ(C) = A ψ̈ z0 + C2 θ̈ y1 − C2 θ̇ ψ̇ x1;
    // δ(I) = δ(C) + IC ∧ m Γ(C) = δ(C) + R z0 ∧ m (R θ̈ x1 + R θ̇ ψ̇ y1)
    //      = −(C2 + m R²) θ̇ ψ̇ x1 + (C2 + m R²) θ̈ y1 + A ψ̈ z0.
    // The plane's action passes through I and the weight through C on the vertical of I: no
    // moment at I on y1 or z0, so (C2 + m R²) θ̈ = 0 and A ψ̈ = 0; the x1 component is the
    // guide's couple. X x0 + Y y0 + (Z − m g) z0 = m Γ(C).
    let m = torseur::spec::load("derivations/roue_sur_plan.json").unwrap();
    let reg = m.reg();
    assert!(!reg.coord_info(reg.coord("x").unwrap()).is_holonomic());
    torseur::assert_equivalent!(m, "V(I,2/0) in B1", "[0, 0, 0]");
    torseur::assert_equivalent!(
        m,
        "Gamma(C,2/0) in B1",
        "R*ddot(theta)*x1 + R*dot(theta)*dot(psi)*y1"
    );
    torseur::assert_equivalent!(
        m,
        "delta(I,2/0) in B1",
        "-(C2 + m*R^2)*dot(theta)*dot(psi)*x1 + (C2 + m*R^2)*ddot(theta)*y1 + A*ddot(psi)*z0"
    );
    torseur::assert_equivalent!(m, "eom(theta)", "(C2 + m*R^2)*ddot(theta) = 0");
    torseur::assert_equivalent!(m, "eom(psi)", "A*ddot(psi) = 0");
    torseur::assert_equivalent!(
        m,
        "X",
        "m*R*(ddot(theta)*cos(psi) - dot(theta)*dot(psi)*sin(psi))"
    );
    torseur::assert_equivalent!(m, "Z", "m*g");
    // The kinetic energy theorem along the constrained motion: neither the contact (V(I) = 0)
    // nor the weight (V(C) horizontal) works, so dEc/dt = θ̇ eom(θ) + ψ̇ eom(ψ) exactly.
    let scalar = |q: &str| match torseur::derivation::derive(
        &m,
        &torseur::quantity::Quantity::parse(q).unwrap(),
    )
    .unwrap()
    .value
    {
        torseur::derivation::Value::Scalar(e) => e,
        _ => panic!("{q}"),
    };
    let sum = &(&reg.parse("dot(theta)").unwrap() * &scalar("eom(theta)"))
        + &(&reg.parse("dot(psi)").unwrap() * &scalar("eom(psi)"));
    assert_eq!(scalar("Ec(2/0)").dt(), sum);
    assert!(scalar("P(ext->2/0)").is_zero());
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn lagrange_follows_a_driven_coordinate_through_its_ratio() {
    // The gear train with a torsion spring k2 on the wheel's pivot: Ep = ½ k2 θ2² depends on
    // the driven coordinate's value, so Lagrange's ∂Ep/∂θ1 is (∂θ2/∂θ1) k2 θ2 = −(r1/r2) k2 θ2
    // (`total_partial`). The energy theorem (powers, with the spring's −k2 θ2 θ̇2) must equal
    // θ̇1 · Lagrange(θ1) exactly; without the ratio term it would not.
    let text = std::fs::read_to_string("derivations/train_engrenages.json").unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "k2", "unit": "N m/rad"}));
    v["links"][1]["spring"] = serde_json::json!({"coordinate": "theta2", "stiffness": "k2"});
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let reg = m.reg();
    let all = all_solids(&m);
    let g0 = m.frames().ground();
    let ec = torseur::pfd::kinetic_energy(&m, &all);
    let p = &torseur::pfd::power(&m, "ext", &all, "E", g0).unwrap()
        + &torseur::pfd::internal_power(&m, &all);
    let t1 = reg.coord("theta1").unwrap();
    let lagrange = torseur::pfd::lagrange(&m, t1);
    assert_eq!(&ec.dt() - &p, &reg.dot(t1) * &lagrange);
    // By hand: Lagrange(θ1) = J_eq θ̈1 − C_m + (r1/r2) C_r − (r1/r2) k2 θ2.
    assert_eq!(
        lagrange,
        reg.parse("(J1 + J2*r1^2/r2^2)*ddot(theta1) - C_m + r1/r2*C_r - r1/r2*k2*theta2")
            .unwrap()
    );
    // And it is the PFD's equation of motion (moment on the pinion, T eliminated).
    torseur::assert_equivalent!(
        m,
        "eom(theta1)",
        "(J1 + J2*r1^2/r2^2)*ddot(theta1) = C_m - r1/r2*C_r + r1/r2*k2*theta2"
    );
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}
