//! Dry (Coulomb) friction (issue 16, item 4): the sign law in the equations, checked by hand
//! and against the float backend (which sets the sign from its own kinematics), and the
//! stick–slip motion `simulate` gives, against its closed form.

use crate::refused_by_both;

fn spec(path: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn the_block_on_the_incline_by_hand() {
    // Along x1: m ẍ = −m g sin α − f m g cos α ε; on y1: Y02 = m g cos α. The power of the
    // actions on the block: the weight's −m g sin α ẋ and the friction's −f m g cos α ε ẋ
    // (= −f N |ẋ| ≤ 0 when ε = sgn ẋ).
    let m = torseur::spec::load("derivations/bloc_frottement_sec.json").unwrap();
    torseur::assert_equivalent!(
        m,
        "eom(x)",
        "m*ddot(x) + m*g*sin(alpha) + f*m*g*cos(alpha)*epsilon02 = 0"
    );
    torseur::assert_equivalent!(m, "Y02", "m*g*cos(alpha)");
    torseur::assert_equivalent!(
        m,
        "P(ext->2/0)",
        "-m*g*(sin(alpha) + f*epsilon02*cos(alpha))*dot(x)"
    );
    let report = torseur::check::check(&m, 10, 5).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn dry_friction_in_a_pivot_opposes_the_relative_rate_as_the_float_backend_finds() {
    // The double pendulum with dry friction C in the pivot between its bars (absolute angles:
    // the relative rate is θ̇2 − θ̇1, whose sign the float backend takes from its own frames).
    let mut v = spec("derivations/double_pendule.json");
    v["links"][1]["coulomb"] = "C".into();
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "C", "unit": "N m"}));
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    // Bar 2 alone, moment at A on z0.
    let plain = torseur::spec::load("derivations/double_pendule.json").unwrap();
    let eom =
        |m: &torseur::mechanism::Mechanism| torseur::pfd::solve(m).unwrap().eom["theta2"].clone();
    let with = eom(&m);
    let without = m.reg().parse(&eom(&plain).to_string()).unwrap();
    let friction = m.reg().parse("C*epsilon12").unwrap();
    // eom is the dynamic side minus the actions: the friction's moment −C ε12 on bar 2
    // (ε12 the sign of θ̇2 − θ̇1) adds +C ε12.
    assert_eq!(with, &without + &friction, "{with}");
    let report = torseur::check::check(&m, 12, 2).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn the_block_stops_and_sticks_or_slides_back_as_its_closed_form_says() {
    // Up the slope, ε = 1: ẍ = −g (sin α + f cos α) until ẋ = 0 at t1 = v0/a1, x1 = v0²/(2 a1).
    // Then the friction can hold the block if tan α ≤ f (α = 0.3, f = 0.5): x stays x1.
    // Otherwise (α = 0.6) it slides back, ε = −1: x = x1 − ½ g (sin α − f cos α)(t − t1)².
    let m = torseur::spec::load("derivations/bloc_frottement_sec.json").unwrap();
    let (g, f, v0) = (9.81_f64, 0.5, 2.0);
    for alpha in [0.3_f64, 0.6] {
        let sc: torseur::wire::ScenarioSpec = serde_json::from_value(serde_json::json!({
            "name": "lancer",
            "duration": 1.2,
            "values": {"m": 2.0, "f": f, "g": g, "alpha": alpha},
            "initial": {"x": [0.0, v0]}
        }))
        .unwrap();
        let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
        let a1 = g * (alpha.sin() + f * alpha.cos());
        let (t1, x1) = (v0 / a1, v0 * v0 / (2.0 * a1));
        let back = g * (alpha.sin() - f * alpha.cos());
        for k in 0..run.times.len() {
            let t = run.times[k];
            let x = run.column("x").unwrap()[k];
            let expected = if t <= t1 {
                v0 * t - 0.5 * a1 * t * t
            } else if alpha.tan() <= f {
                x1
            } else {
                x1 - 0.5 * back * (t - t1) * (t - t1)
            };
            // The switch at t1 is found by the step control, within the stick band's speed.
            assert!(
                (x - expected).abs() < 1e-6,
                "α = {alpha}: x({t}) = {x}, {expected}"
            );
        }
    }
    // The sign is the simulation's to set.
    let mut sc: torseur::wire::ScenarioSpec = serde_json::from_value(serde_json::json!({
        "name": "lancer", "duration": 1.0,
        "values": {"m": 2.0, "f": f, "g": g, "alpha": 0.3, "epsilon02": 1.0}
    }))
    .unwrap();
    let e = torseur::simulate::simulate_with(&m, &sc, &[])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("`epsilon02`") && e.contains("simulation sets it"),
        "{e}"
    );
    sc.values.remove("epsilon02");
    assert!(torseur::simulate::simulate_with(&m, &sc, &[]).is_ok());
}

#[test]
fn bad_dry_friction_is_refused_by_both_sides_with_its_place() {
    // On a link that neither turns nor slides.
    let mut v = spec("derivations/bloc_frottement_sec.json");
    v["links"][0]["kind"] = "plane".into();
    v["links"][0]["axis"] = "y1".into();
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[0].coulomb") && e.contains("pivot or a slider"),
        "{e}"
    );
    assert!(f.contains("links[0].coulomb"), "{f}");
    // A parameter already named like the sign.
    let mut v = spec("derivations/bloc_frottement_sec.json");
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "epsilon02", "unit": "1"}));
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[0].coulomb") && e.contains("`epsilon02`"),
        "{e}"
    );
    assert!(f.contains("links[0].coulomb"), "{f}");
    // A magnitude that holds an unknown of the PFD (f N with N the normal force).
    let mut v = spec("derivations/bloc_frottement_sec.json");
    v["links"][0]["coulomb"] = "f*Y02".into();
    let (e, f) = refused_by_both(&v);
    assert!(e.contains("links[0].coulomb") && e.contains("`Y02`"), "{e}");
    assert!(f.contains("links[0].coulomb"), "{f}");
    // A magnitude that moves.
    let mut v = spec("derivations/bloc_frottement_sec.json");
    v["links"][0]["coulomb"] = "f*m*g*x".into();
    let (e, f) = refused_by_both(&v);
    assert!(e.contains("links[0].coulomb"), "{e}");
    assert!(f.contains("links[0].coulomb"), "{f}");
}
