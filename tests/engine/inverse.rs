//! Inverse and direct dynamics in one spec (issue 37): a motor torque declared as an action's
//! unknown that only an equation of motion holds is the input of that equation. Asked for
//! itself, it is that equation solved for it (the torque an imposed motion needs); in
//! `eom(θ)` it stays a symbol, given in a scenario for the direct dynamics.
//!
//! The motorised physical pendulum, by hand: the bar 1 turns by θ about (O, z0) on a pivot;
//! OG = a x1, inertia J about (G, z0), mass m; weight −m g y0; the motor C_m z0 on 1. The moment
//! of the weight at O on z0 is a x1 ∧ (−m g y0) · z0 = −m g a cos θ, and J_O = J + m a²
//! (Huygens), so the moment theorem at O on z0 reads (J + m a²) θ̈ = C_m − m g a cos θ.

use torseur::derivation::derive;
use torseur::pfd::{PfdError, solve};
use torseur::quantity::Quantity;

fn pendulum() -> serde_json::Value {
    serde_json::json!({
        "title": "Pendule motorisé",
        "ground_origin": "O",
        "parameters": [{"name": "m"}, {"name": "a"}, {"name": "J"}, {"name": "g"},
                       {"name": "omega"}],
        "coordinates": [{"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}}],
        "points": [{"name": "G", "from": "O", "position": "a*x1"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G",
                    "inertia": {"point": "G", "basis": "1",
                                "matrix": [["0", "0", "0"], ["0", "J", "0"], ["0", "0", "J"]]}}],
        "gravity": "-g*y0",
        "links": [{"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O",
                   "axis": "z0"}],
        "actions": [{"name": "moteur", "from": "0", "on": "1", "point": "O",
                     "moment": "C_m*z0", "unknowns": ["C_m"]}],
        "hypotheses": [{"name": "H", "text": "vitesse constante", "rates": {"theta": "omega"}}],
        "quantities": ["C_m", "eom(theta)"],
        "pfd": [{"isolate": "1", "theorem": "moment", "point": "O", "on": "z0",
                 "eom": "theta"}],
        "scenarios": [{"name": "lache", "duration": 0.5,
                       "values": {"m": 1.0, "a": 0.3, "J": 0.01, "g": 9.81, "omega": 0.0,
                                  "C_m": 1.5},
                       "initial": {"theta": [0.2, 0.0]}}]
    })
}

fn load(v: &serde_json::Value) -> torseur::mechanism::Mechanism {
    torseur::spec::from_str(&v.to_string()).unwrap()
}

#[test]
fn the_motor_torque_is_found_for_an_imposed_motion_and_given_for_a_free_one() {
    let m = load(&pendulum());
    let e = |s: &str| m.reg().parse(s).unwrap();
    let sol = solve(&m).unwrap();
    assert_eq!(sol.inputs, ["C_m"]);
    let value = |q: &str| {
        let d = derive(&m, &Quantity::parse(q).unwrap()).unwrap();
        d.value.exprs()[0].clone()
    };
    // Inverse dynamics: the torque the motion θ(t) needs.
    assert_eq!(
        value("C_m"),
        e("(J + m*a^2)*ddot(theta) + m*g*a*cos(theta)")
    );
    // Direct dynamics: the torque stays the equation's input (dynamic side minus actions).
    assert_eq!(
        value("eom(theta)"),
        e("(J + m*a^2)*ddot(theta) + m*g*a*cos(theta) - C_m")
    );
    // At the constant rate ω of the hypothesis, only the weight's moment is left to balance.
    let h = &m.hypotheses()[0];
    let d = derive(&m, &Quantity::parse("C_m").unwrap()).unwrap();
    assert_eq!(d.value.under(h).exprs()[0], &e("m*g*a*cos(theta)"));
    // The float backend agrees by its own route (its LU solve of the equation for C_m).
    let report = torseur::check::check(&m, 10, 3).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn a_given_torque_drives_the_simulation_as_integrated_by_hand() {
    let m = load(&pendulum());
    let sc = m.spec().scenarios[0].clone();
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let (ts, th) = (&run.times, run.column("theta").unwrap());
    // θ̈ = (C_m − m g a cos θ)/(J + m a²), RK4 with a small fixed step.
    let acc = |t: f64| (1.5 - 9.81 * 0.3 * t.cos()) / (0.01 + 0.09);
    let (mut t, mut y, dt) = (0.0_f64, [0.2_f64, 0.0], 1e-4);
    let f = |y: [f64; 2]| [y[1], acc(y[0])];
    for (k, &tk) in ts.iter().enumerate() {
        while t + dt <= tk + 1e-12 {
            crate::rk4_step(&f, &mut y, dt);
            t += dt;
        }
        // The last partial step, to the output instant.
        if tk > t {
            crate::rk4_step(&f, &mut y, tk - t);
            t = tk;
        }
        assert!(
            (th[k] - y[0]).abs() < 1e-6,
            "t = {tk}: {} against {}",
            th[k],
            y[0]
        );
    }
    // Without the torque's value, the free motion cannot be integrated: said, not zero.
    let mut bare = sc.clone();
    bare.values.remove("C_m");
    let e = torseur::simulate::simulate_with(&m, &bare, &[])
        .unwrap_err()
        .to_string();
    assert!(e.contains("holds the input `C_m`"), "{e}");
}

#[test]
fn inputs_that_the_equations_of_motion_cannot_give_are_refused() {
    // Two torques on the one bar: its one equation cannot give both.
    let mut v = pendulum();
    v["actions"].as_array_mut().unwrap().push(serde_json::json!(
        {"name": "frein", "from": "0", "on": "1", "point": "O", "moment": "C_f*z0",
         "unknowns": ["C_f"]}));
    v["scenarios"] = serde_json::json!([]);
    let m = load(&v);
    match solve(&m) {
        Err(PfdError::Inputs {
            unknowns,
            equations,
        }) => {
            assert_eq!(unknowns, ["C_m", "C_f"]);
            assert_eq!(equations, ["eom(theta)"]);
        }
        other => panic!("{other:?}"),
    }
    // A link's unknown left in an equation of motion is still a modelling error, not an
    // input: the resultant theorem holds the pivot's X01.
    let mut v = pendulum();
    v["pfd"] = serde_json::json!([{"isolate": "1", "theorem": "resultant", "on": "x0",
                                   "eom": "theta"}]);
    v["scenarios"] = serde_json::json!([]);
    let m = load(&v);
    assert!(
        matches!(solve(&m), Err(PfdError::Undetermined { ref unknown, .. }) if unknown == "X01"),
        "{:?}",
        solve(&m)
    );
}
