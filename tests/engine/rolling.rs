//! Rolling conditions (issue 16, item 1): V(I,2/0) = 0⃗ declared in the spec gives the
//! dependent rates a teacher derives by hand, holonomic or not; the float backend solves the
//! same condition from its own frames; bad conditions are refused by both sides with their
//! place; the constrained motions simulate as their closed forms say.

use crate::refused_by_both;

fn spec(path: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn rate_is(m: &torseur::mechanism::Mechanism, q: &str, hand: &str) {
    let id = m.reg().coord(q).unwrap();
    assert_eq!(m.reg().dot(id), m.reg().parse(hand).unwrap(), "dot({q})");
}

#[test]
fn rolling_conditions_give_the_rates_derived_by_hand() {
    // Disc on the incline: V(I,2/0) = ẋ x1 + θ̇ z0 ∧ (−R y1) = (ẋ + R θ̇) x1, so θ̇ = −ẋ/R,
    // holonomic (θ = −x/R + const).
    let m = torseur::spec::load("derivations/disque_plan_incline.json").unwrap();
    rate_is(&m, "theta", "-dot(x)/R");
    assert!(
        m.reg()
            .coord_info(m.reg().coord("theta").unwrap())
            .is_holonomic()
    );
    // Wheel on the plane: V(I,2/0) = ẋ x0 + ẏ y0 − R θ̇ x1, on B0: ẋ = R θ̇ cos ψ,
    // ẏ = R θ̇ sin ψ, nonholonomic.
    let m = torseur::spec::load("derivations/roue_sur_plan.json").unwrap();
    rate_is(&m, "x", "R*dot(theta)*cos(psi)");
    rate_is(&m, "y", "R*dot(theta)*sin(psi)");
    assert!(
        !m.reg()
            .coord_info(m.reg().coord("y").unwrap())
            .is_holonomic()
    );
    // The guide's couple keeps the wheel vertical: with Ω(2/0) = ψ̇ z0 + θ̇ y1,
    // δ(C)·x1 = d(C2 θ̇ y1)/dt·x1 = −C2 θ̇ ψ̇ (ẏ1 = −ψ̇ x1), and Γ(C) = R θ̈ x1 + R θ̇ ψ̇ y1
    // gives IC ∧ m Γ(C)·x1 = −m R² θ̇ ψ̇; the plan and gravity have no moment at I on x1.
    torseur::assert_equivalent!(m, "C_g", "-(C2 + m*R^2)*dot(theta)*dot(psi)");
    // The skate (a blade: no sliding across y1 only): V(C,1/0)·y1 = −ẋ sin ψ + ẏ cos ψ = 0,
    // so ẏ = ẋ sin ψ / cos ψ and V(C,1/0) = (ẋ / cos ψ) x1 = u x1. Then Γ(C) = u̇ x1 + u ψ̇ y1,
    // u̇ = ẍ / cos ψ + ẋ ψ̇ sin ψ / cos² ψ; the ice's lateral force is Y = m u ψ̇.
    let m = torseur::spec::load("tests/specs/patin.json").unwrap();
    rate_is(&m, "y", "dot(x)*sin(psi)/cos(psi)");
    assert!(
        !m.reg()
            .coord_info(m.reg().coord("y").unwrap())
            .is_holonomic()
    );
    torseur::assert_equivalent!(m, "V(C,1/0) in B1", "dot(x)/cos(psi)*x1");
    torseur::assert_equivalent!(
        m,
        "Gamma(C,1/0) in B1",
        "(ddot(x)/cos(psi) + dot(x)*dot(psi)*sin(psi)/cos(psi)^2)*x1 + dot(x)*dot(psi)/cos(psi)*y1"
    );
    torseur::assert_equivalent!(m, "Y", "m*dot(x)*dot(psi)/cos(psi)");
    torseur::assert_equivalent!(m, "Ec(1/0)", "1/2*m*dot(x)^2/cos(psi)^2 + 1/2*J*dot(psi)^2");
    // The float backend solves V(C,1/0)·y1 = 0 and its derivative from its own frames.
    let report = torseur::check::check(&m, 10, 3).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn bad_rolling_conditions_are_refused_by_both_sides_with_their_place() {
    let disc = spec("derivations/disque_plan_incline.json");
    let wheel = spec("derivations/roue_sur_plan.json");
    let both = |v: &serde_json::Value, place: &str, exact: &str, float: &str| {
        let (e, f) = refused_by_both(v);
        assert!(e.contains(place) && e.contains(exact), "{e}");
        assert!(f.contains(place) && f.contains(float), "{f}");
    };
    let mut v = disc.clone();
    v["rolling"][0]["velocity"] = "V(K,2/0)".into();
    both(
        &v,
        "rolling[0].velocity",
        "unknown point `K`",
        "unknown point `K`",
    );
    let mut v = disc.clone();
    v["rolling"][0]["velocity"] = "Omega(2/0)".into();
    both(
        &v,
        "rolling[0].velocity",
        "not a velocity",
        "not a velocity",
    );
    // A velocity zero whatever the rates imposes nothing.
    let mut v = disc.clone();
    v["rolling"][0]["velocity"] = "V(I,2/2)".into();
    both(
        &v,
        "rolling[0].velocity",
        "imposes nothing",
        "imposes nothing",
    );
    // One relation for two dependent coordinates.
    let mut v = disc.clone();
    v["rolling"][0]["dependent"] = serde_json::json!(["theta", "x"]);
    both(&v, "rolling", "redundant", "independent relations for 2");
    // A condition that does not hold the dependent rate (the centre's velocity, not the
    // contact's): θ̇ is not in V(C,2/0) = ẋ x1.
    let mut v = disc.clone();
    v["rolling"][0]["velocity"] = "V(C,2/0)".into();
    both(
        &v,
        "rolling",
        "do not hold the rate of `theta`",
        "redundant",
    );
    // A dependent coordinate with a rate of its own.
    let mut v = wheel.clone();
    v["coordinates"][2]["rate"] = "R*dot(theta)".into();
    both(
        &v,
        "rolling[0].dependent[0]",
        "rate of its own",
        "rate of its own",
    );
    // Directions: an unknown one, or not as many as the dependent coordinates.
    let mut v = disc.clone();
    v["rolling"][0]["on"] = serde_json::json!(["w1"]);
    both(&v, "rolling[0].on[0]", "`w1`", "`w1`");
    let mut v = disc.clone();
    v["rolling"][0]["on"] = serde_json::json!(["x1", "y1"]);
    let (e, _) = refused_by_both(&v);
    assert!(e.contains("rolling[0].on"), "{e}");
    // The skate's blade cannot slide along its edge and across at once with one dependent.
    let mut v = spec("tests/specs/patin.json");
    v["rolling"][0]["on"] = serde_json::json!(["x1", "y1"]);
    both(&v, "rolling[0].on", "as many", "as many");
}

#[test]
fn the_disc_rolls_down_the_incline_as_its_closed_form_says() {
    // From rest, (m + J/R²) ẍ = −m g sin α: x = −½ a t², a = g sin α / (1 + J/(m R²)), and
    // θ, integrated from θ̇ = −ẋ/R, is −x/R.
    let m = torseur::spec::load("derivations/disque_plan_incline.json").unwrap();
    let sc: torseur::wire::ScenarioSpec = serde_json::from_value(serde_json::json!({
        "name": "descente",
        "duration": 1.5,
        "values": {"m": 2.0, "R": 0.1, "J": 0.01, "A": 0.005, "g": 9.81, "alpha": 0.3},
        "initial": {"x": [0.0, 0.0], "theta": [0.0, 0.0]}
    }))
    .unwrap();
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let a = 9.81 * 0.3_f64.sin() / (1.0 + 0.01 / (2.0 * 0.01));
    for k in 0..run.times.len() {
        let t = run.times[k];
        let x = run.column("x").unwrap()[k];
        let theta = run.column("theta").unwrap()[k];
        assert!((x + 0.5 * a * t * t).abs() < 1e-8, "x({t}) = {x}");
        assert!((theta + x / 0.1).abs() < 1e-7, "θ({t}) = {theta}");
    }
}

#[test]
fn the_skate_turns_on_a_circle_as_its_closed_form_says() {
    // Torque-free: ψ̇ = ω; along the blade m u̇ = 0: u = ẋ / cos ψ constant. So C runs on a
    // circle of radius u/ω: x = (u/ω)(sin ψ − sin ψ0), y = −(u/ω)(cos ψ − cos ψ0), with y
    // integrated from the nonholonomic ẏ = ẋ tan ψ. Ec stays ½ m u² + ½ J ω².
    let m = torseur::spec::load("tests/specs/patin.json").unwrap();
    let (psi0, omega, u) = (-0.5_f64, 0.5, 2.0);
    let sc: torseur::wire::ScenarioSpec = serde_json::from_value(serde_json::json!({
        "name": "virage",
        "duration": 1.8,
        "values": {"m": 60.0, "J": 2.0, "A": 3.0, "g": 9.81},
        "initial": {"x": [0.0, u * psi0.cos()], "psi": [psi0, omega], "y": [0.0, 0.0]}
    }))
    .unwrap();
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let r = u / omega;
    let last = run.times.len() - 1;
    assert!(run.times[last] > 1.79);
    for k in 0..run.times.len() {
        let t = run.times[k];
        let psi = psi0 + omega * t;
        let col = |c: &str| run.column(c).unwrap()[k];
        assert!((col("psi") - psi).abs() < 1e-8, "ψ({t})");
        assert!(
            (col("x") - r * (psi.sin() - psi0.sin())).abs() < 1e-7,
            "x({t})"
        );
        assert!(
            (col("y") + r * (psi.cos() - psi0.cos())).abs() < 1e-7,
            "y({t})"
        );
    }
}

#[test]
fn the_pfd_equations_are_lagranges_with_multipliers() {
    // Lagrange's equations of the mechanism without its rolling condition (every coordinate
    // free; the contact's action, whose unknowns are the multipliers, a generalised force),
    // E_k = 0, from the energies and virtual powers only. The condition q̇_d = Σ_f c_df q̇_f
    // makes E_f + Σ_d c_df E_d free of the multipliers (their virtual power vanishes on every
    // motion that respects it); along the constrained motion it is the PFD's equation of
    // motion of f, up to a factor (compared by cross-multiplying the q̈_f coefficients).
    let cases: [(&str, &[&str]); 3] = [
        ("tests/specs/patin.json", &["x", "psi"]),
        ("derivations/roue_sur_plan.json", &["theta", "psi"]),
        ("derivations/disque_plan_incline.json", &["x"]),
    ];
    for (path, free_coords) in cases {
        let m = torseur::spec::load(path).unwrap();
        let mut v = spec(path);
        let dependent: Vec<String> = v["rolling"][0]["dependent"]
            .as_array()
            .unwrap()
            .iter()
            .map(|d| d.as_str().unwrap().to_string())
            .collect();
        v.as_object_mut().unwrap().remove("rolling");
        let unconstrained = torseur::spec::from_str(&v.to_string()).unwrap();
        let ureg = &unconstrained.reg();
        // Each E_k read into the constrained mechanism, where the dependent rates (and their
        // derivatives) are the condition's.
        let e = |k: &str| {
            let r = torseur::pfd::lagrange(&unconstrained, ureg.coord(k).unwrap());
            m.reg().parse(&r.to_string()).unwrap()
        };
        let sol = torseur::pfd::solve(&m).unwrap();
        for f in free_coords {
            let qf = m.reg().coord(f).unwrap();
            let mut combination = e(f);
            for d in &dependent {
                let c = m.reg().dot(m.reg().coord(d).unwrap()).partial_rate(qf, 1);
                combination = &combination + &(&c * &e(d));
            }
            let eom = &sol.eom[*f];
            let (a, b) = (combination.partial_rate(qf, 2), eom.partial_rate(qf, 2));
            assert!(!a.is_zero() && !b.is_zero(), "{path}: {f}");
            assert_eq!(
                &combination * &b,
                eom * &a,
                "{path}: Lagrange with multipliers and the PFD differ on {f}"
            );
        }
    }
}
