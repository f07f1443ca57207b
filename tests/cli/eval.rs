//! `torseur eval`, run as a user would: the JSON contract, the parameters it demands, the
//! unknowns it solves or takes given.

use super::*;

#[test]
fn eval_follows_the_json_contract() {
    let d = tmp();
    let at = d.path().join("values.json");
    // theta2 = 0, rates 1 and 0, accelerations 0: delta(O2,2/0).x2 = 0 by the formula
    // (sin 0 = 0, no ddot), V(G2,2/0) = [-(L1+L2)*1, 0, 0].
    std::fs::write(
        &at,
        r#"{"parameters":{"h1":0.1,"d1":0.2,"L1":0.3,"L2":0.5,"m1":1,"m2":2,
            "A1":1,"B1":1,"C1":1,"D1":0,"E1":0,"F1":0,"A2":1,"B2":1,"C2":1,"D2":0,"E2":0,"F2":0,
            "g":9.81,"f":0},
            "coordinates":{"theta1":[0.4,1,0],"theta2":[0,0,0]}}"#,
    )
    .unwrap();
    let o = run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        at.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-q",
        "delta(O2,2/0).x2",
        "-q",
        "{D(2/0)}_O2 in B2",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let q = v["quantities"].as_array().unwrap();
    assert_eq!(q[0]["id"], "V(G2,2/0) in B2");
    assert_eq!(q[0]["kind"], "vector");
    assert_eq!(q[0]["basis"], "B2");
    let vx = q[0]["value"][0].as_f64().unwrap();
    assert!((vx + 0.8).abs() < 1e-12, "{vx}");
    assert_eq!(q[1]["kind"], "scalar");
    assert!(q[1]["value"].as_f64().unwrap().abs() < 1e-12);
    assert_eq!(q[2]["kind"], "torsor");
    assert_eq!(q[2]["point"], "O2");
    assert_eq!(q[2]["resultant"].as_array().unwrap().len(), 3);
}

#[test]
fn eval_demands_only_the_parameters_the_quantities_hold() {
    let d = tmp();
    // δ(O2,2/0) holds L1, L2, m2, A2…F2 and both angles; not g, f, nor solid 1's data.
    let needed = r#""L1":0.3,"L2":0.5,"m2":2,"A2":1,"B2":0.7,"C2":0.4,"D2":0.1,"E2":0.2,"F2":0.05"#;
    let coordinates = r#""coordinates":{"theta1":[0.4,1.5,2],"theta2":[0.3,-0.7,3]}"#;
    let few = d.path().join("few.json");
    std::fs::write(
        &few,
        format!("{{\"parameters\":{{{needed}}},{coordinates}}}"),
    )
    .unwrap();
    let all = d.path().join("all.json");
    std::fs::write(
        &all,
        format!(
            "{{\"parameters\":{{{needed},\"h1\":0.1,\"d1\":0.2,\"m1\":1,\"A1\":1,\"B1\":1,\
             \"C1\":1,\"D1\":0,\"E1\":0,\"F1\":0,\"g\":9.81,\"f\":0.3}},{coordinates}}}"
        ),
    )
    .unwrap();
    let eval = |at: &Path| {
        run(&[
            "eval",
            spec().to_str().unwrap(),
            "--at",
            at.to_str().unwrap(),
            "-q",
            "delta(O2,2/0) in B2",
        ])
    };
    let (o_few, o_all) = (eval(&few), eval(&all));
    assert_eq!(o_few.status.code(), Some(0), "{}", stderr(&o_few));
    assert_eq!(o_all.status.code(), Some(0), "{}", stderr(&o_all));
    // The value does not depend on what else is given.
    assert_eq!(stdout(&o_few), stdout(&o_all));
    // Missing m2 and theta1: exactly those are named (exit 2), nothing on stdout.
    let missing = d.path().join("missing.json");
    std::fs::write(
        &missing,
        format!(
            "{{\"parameters\":{{{}}},\"coordinates\":{{\"theta2\":[0.3,-0.7,3]}}}}",
            needed.replace("\"m2\":2,", "")
        ),
    )
    .unwrap();
    let o = eval(&missing);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing parameter `m2` and coordinate `theta1`"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
    // The equation of motion of theta2 does hold g and f.
    let o = run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        few.to_str().unwrap(),
        "-q",
        "eom(theta2)",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("missing parameters `g`, `f` (the requested quantities hold them)"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn eval_solves_the_unknowns_an_action_holds_or_takes_them_given() {
    let d = tmp();
    let at = d.path().join("values.json");
    let values = |unknowns: &str| {
        format!(
            r#"{{"parameters":{{"h1":0.1,"d1":0.2,"L1":0.3,"L2":0.5,"m1":1,"m2":2,
            "A1":1,"B1":1.5,"C1":2,"A2":1,"B2":1.2,"C2":0.7,"D2":0.1,"E2":0.05,"F2":-0.02,
            "g":9.81,"f":0.05}},
            "coordinates":{{"theta1":[0.4,1.3,0.2],"theta2":[0.6,-0.4,0.9]}}{unknowns}}}"#
        )
    };
    std::fs::write(&at, values("")).unwrap();
    let spec = spec();
    let eval = |qs: &[&str]| {
        let mut args = vec!["eval", spec.to_str().unwrap(), "--at", at.to_str().unwrap()];
        for q in qs {
            args.extend(["-q", q]);
        }
        run(&args)
    };
    // The moment theorem on E at O1 on z0: the exterior actions' moment is the motor torque,
    // which the PFD solves for.
    let o = eval(&["M(O1,ext->E).z0", "C_m"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let (a, b) = (
        v["quantities"][0]["value"].as_f64().unwrap(),
        v["quantities"][1]["value"].as_f64().unwrap(),
    );
    assert!(
        (a - b).abs() <= 1e-12 * b.abs().max(1.0) && b != 0.0,
        "{a} {b}"
    );
    // X01 is determined by no equation: exit 2, named, nothing on stdout.
    let o = eval(&["R(0->1)"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("no value for `X01`"), "{}", stderr(&o));
    // Given, it is used as is.
    std::fs::write(&at, values(r#","unknowns":{"X01":1,"Y01":2,"Z01":3}"#)).unwrap();
    let o = eval(&["R(0->1) in B0"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(
        v["quantities"][0]["value"],
        serde_json::json!([1.0, 2.0, 3.0])
    );
    // A name that is not an unknown of the PFD.
    std::fs::write(&at, values(r#","unknowns":{"m1":1}"#)).unwrap();
    let o = eval(&["C_m"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("`m1` is not an unknown of the PFD"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn eval_and_derive_give_an_unknown_solved_as_a_quotient() {
    // Two bearings L apart: the moment at A on x1 gives L Y_B = −D ω² (hand derivation in
    // tests/engine/library.rs), so Y_B = −D ω²/L; the resultant on y1, Y_A = −Y_B.
    let d = tmp();
    let at = d.path().join("values.json");
    std::fs::write(
        &at,
        r#"{"parameters":{"m":2,"a":0.01,"c":0.2,"L":0.5,"A1":1,"B1":1,"C1":1,"D1":0.003,
        "E1":0.004,"F1":0,"omega":100,"g":9.81},"coordinates":{"theta":[0.3,100,0]}}"#,
    )
    .unwrap();
    let spec = "derivations/rotor_deux_paliers.json";
    let o = run(&[
        "eval",
        spec,
        "--at",
        at.to_str().unwrap(),
        "-q",
        "Y_B",
        "-q",
        "R(0->1).y1",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let y_b = v["quantities"][0]["value"].as_f64().unwrap();
    assert!((y_b - (-0.003 * 100.0 * 100.0 / 0.5)).abs() < 1e-9, "{y_b}");
    // R(0→1)·y1 = Y_A + Y_B = 0 (the bearings' y1 actions cancel).
    let r = v["quantities"][1]["value"].as_f64().unwrap();
    assert!(r.abs() < 1e-9, "{r}");
    // derive prints the quotient as it reads back; the JSON splits it.
    let o = run(&["derive", spec, "-q", "Y_B"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(stdout(&o).trim(), "Y_B = -D1*omega^2/L\n  under H: 0");
}

#[test]
fn eval_takes_values_written_as_expressions_of_the_others() {
    // The pendulum on a shaft turning at ω (hand derivation in tests/engine/library.rs):
    // A' θ̈ + (C − A') ω² sin θ cos θ + m g a sin θ = 0, A' = A + m a². Its relative
    // equilibrium off the axis is cos β = m g a / ((A' − C) ω²): given by an arccosine, the
    // equation of motion there is zero.
    let d = tmp();
    let at = d.path().join("values.json");
    std::fs::write(
        &at,
        r#"{"parameters": {"m": 0.5, "a": 0.2, "A": 0.01, "C": 0.002, "g": 9.81,
        "omega": 12, "beta": "acos(m*g*a/((A + m*a^2 - C)*omega^2))"},
        "coordinates": {"theta": ["beta", 0, 0]}}"#,
    )
    .unwrap();
    let spec = "derivations/pendule_arbre_tournant.json";
    let eval = |q: &str| run(&["eval", spec, "--at", at.to_str().unwrap(), "-q", q]);
    let o = eval("eom(theta)");
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = v["quantities"][0]["value"].as_f64().unwrap();
    assert!(r.abs() < 1e-12, "{r}");
    // The weight's moment there is m g a sin β, β from the same arccosine.
    let o = eval("M(O,pes->2).x1");
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let beta = (0.5f64 * 9.81 * 0.2 / ((0.01 + 0.5 * 0.04 - 0.002) * 144.0)).acos();
    let w = v["quantities"][0]["value"].as_f64().unwrap();
    assert!((w + 0.5 * 9.81 * 0.2 * beta.sin()).abs() < 1e-12, "{w}");
    // Values that refer to each other: exit 2, the entry named, nothing written.
    std::fs::write(&at, r#"{"parameters": {"m": "g*2", "g": "m/2"}}"#).unwrap();
    let o = eval("eom(theta)");
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("at parameters.g"), "{}", stderr(&o));
    // A function that is not a number's.
    std::fs::write(&at, r#"{"parameters": {"m": "dot(g)"}}"#).unwrap();
    let o = eval("eom(theta)");
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("the functions are sin, cos, tan"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn eval_and_verify_take_the_time_of_a_forced_oscillator() {
    // M ẍ + c ẋ + k x = F0 cos(Ω t) (hand derivation in tests/engine/library.rs): at t the
    // residual is computed here by hand.
    let d = tmp();
    let at = d.path().join("values.json");
    let spec = "derivations/masse_ressort_forcee.json";
    let eval = |q: &str| run(&["eval", spec, "--at", at.to_str().unwrap(), "-q", q]);
    std::fs::write(
        &at,
        r#"{"parameters": {"M": 2, "k": 50, "c": 0.3, "F0": 4, "Omega": 3, "g": 9.81, "X": 0},
        "coordinates": {"x": [0.1, 0.2, 0.3]}, "time": 0.7}"#,
    )
    .unwrap();
    let o = eval("eom(x)");
    assert!(o.status.success(), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    let r = v["quantities"][0]["value"].as_f64().unwrap();
    let hand = 2.0 * 0.3 + 0.3 * 0.2 + 50.0 * 0.1 - 4.0 * (3.0f64 * 0.7).cos();
    assert!((r - hand).abs() < 1e-12 * hand.abs(), "{r} {hand}");
    // Without the time: exit 2, the time named.
    std::fs::write(
        &at,
        r#"{"parameters": {"M": 2, "k": 50, "c": 0.3, "F0": 4, "Omega": 3, "g": 9.81},
        "coordinates": {"x": [0.1, 0.2, 0.3]}}"#,
    )
    .unwrap();
    let o = eval("eom(x)");
    assert_eq!(o.status.code(), Some(2));
    assert!(stdout(&o).is_empty());
    assert!(stderr(&o).contains("the time `t`"), "{}", stderr(&o));
    // The weight does not need it.
    assert!(eval("Y01").status.success());
    // A corrigé's equation divided by M, with the time in it.
    let o = run(&[
        "verify",
        spec,
        "-q",
        "eom(x)",
        "-e",
        "ddot(x) + c/M*dot(x) + k/M*x = F0/M*cos(Omega*t)",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("up to the factor M"), "{}", stdout(&o));
    let o = run(&[
        "verify",
        spec,
        "-q",
        "eom(x)",
        "-e",
        "M*ddot(x) + c*dot(x) + k*x = F0*sin(Omega*t)",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}
