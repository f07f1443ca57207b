//! Messages that keep the contract (issue 32, item 6): short, the JSON path or the argument
//! named, nothing of symbolica's own; and the bounds and refusals that come with them (number
//! literals, durations, non-finite numbers, every coordinate imposed). Every expected message
//! is written by hand.

use serde_json::Value as Json;
use torseur::output::{Values, numeric_point_for, try_eval_value};
use torseur::quantity::Quantity;
use torseur::spec::{SpecError, from_str};
use torseur::verify::{VerifyError, verify};

/// The regulator's spec as JSON, to be changed by a test.
fn base() -> Json {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The path and message of the refusal of `v`.
fn refusal(v: &Json) -> (String, String) {
    match from_str(&v.to_string()) {
        Ok(_) => panic!("accepted a bad spec"),
        Err(SpecError::Invalid { path, message, .. } | SpecError::Json { path, message, .. }) => {
            (path, message)
        }
        Err(e) => panic!("not a spec error: {e}"),
    }
}

#[test]
fn a_division_by_an_expression_equal_to_zero_is_refused_in_our_words() {
    // symbolica simplifies L1 - L1 to 0 as it reads the text, and warned on the terminal.
    let mut v = base();
    v["points"][2]["position"] = "d1/(L1 - L1)*z0 + L1*y1".into();
    assert_eq!(
        refusal(&v),
        (
            "points[2].position".to_string(),
            "`d1/(L1 - L1)*z0 + L1*y1`: division by zero: a divisor is equal to 0".to_string()
        )
    );
    let mut v = base();
    v["aliases"] = serde_json::json!([{"name": "k", "value": "m2/(L1 - L1)"}]);
    v["points"][2]["position"] = "k*z0 + L1*y1".into();
    assert_eq!(
        refusal(&v),
        (
            "aliases[0].value".to_string(),
            "`m2/(L1 - L1)`: division by zero: a divisor is equal to 0".to_string()
        )
    );
    // The same in a typed result and in a number of a values file.
    let m = crate::regulator();
    let e = verify(&m, "Omega(2/0).x2", "dot(theta2)/(L1 - L1)", None).unwrap_err();
    assert_eq!(
        e.to_string(),
        "`dot(theta2)/(L1 - L1)`: division by zero: a divisor is equal to 0"
    );
    let e = Values::parse(r#"{"parameters": {"L1": "1/(L2 - L2)", "L2": 1}}"#).unwrap_err();
    assert_eq!(
        e.to_string(),
        "values: at parameters.L1: `1/(L2 - L2)`: division by zero: a divisor is equal to 0"
    );
}

#[test]
fn an_array_longer_than_its_fixed_length_names_its_path() {
    let mut v = base();
    v["solids"][1]["inertia"]["matrix"][0]
        .as_array_mut()
        .unwrap()
        .push("A2".into());
    assert_eq!(
        refusal(&v),
        (
            "solids[1].inertia.matrix[0]".to_string(),
            "more elements than the 3 this array holds".to_string()
        )
    );
    let mut v = base();
    v["solids"][1]["inertia"]["matrix"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!(["A2", "0", "0"]));
    assert_eq!(refusal(&v).0, "solids[1].inertia.matrix");
    let mut v = base();
    v["ground_basis"] = serde_json::json!(["x", "y", "z", "w"]);
    assert_eq!(
        refusal(&v),
        (
            "ground_basis".to_string(),
            "more elements than the 3 this array holds".to_string()
        )
    );
    let mut v = base();
    v["scenarios"][0]["initial"]["theta2"] = serde_json::json!([0.1, 0, 0]);
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].initial.theta2".to_string(),
            "more elements than the 2 this array holds".to_string()
        )
    );
    // A values file: a coordinate's [q, q̇, q̈]; column 38 is the extra `5`.
    let e = Values::parse(r#"{"coordinates": {"theta2": [0, 1, 0, 5]}}"#).unwrap_err();
    assert_eq!(
        e.to_string(),
        "values: at coordinates.theta2 (line 1, column 38): more than the 3 values \
         [q, dot(q), ddot(q)] of a coordinate"
    );
}

#[test]
fn a_duration_out_of_bounds_says_the_bounds() {
    for (d, shown) in [
        (1e12, "1000000000000"),
        (0.0, "0"),
        (-1.0, "-1"),
        (1000.5, "1000.5"),
    ] {
        let mut v = base();
        v["scenarios"][0]["duration"] = d.into();
        assert_eq!(
            refusal(&v),
            (
                "scenarios[0].duration".to_string(),
                format!("{shown} s: a duration is more than 0 s and at most 1000 s")
            )
        );
    }
    let mut v = base();
    v["scenarios"][0]["duration"] = 1000.0.into();
    from_str(&v.to_string()).expect("1000 s is within the bound");
}

#[test]
fn a_list_for_a_scalar_and_a_scalar_for_a_vector_say_what_the_quantity_is() {
    let m = crate::regulator();
    let shape = |q: &str, e: &str| match verify(&m, q, e, None) {
        Err(VerifyError::Shape(s)) => s,
        other => panic!("{q} = {e}: {other:?}"),
    };
    assert_eq!(
        shape("Omega(2/0).x2", "[1, 2, 3]"),
        "`Omega(2/0).x2` is a scalar: give one expression, not a list [x, y, z]"
    );
    assert_eq!(
        shape("C_m", "[1,2,3]"),
        "`C_m` is a scalar: give one expression, not a list [x, y, z]"
    );
    assert_eq!(
        shape("Omega(2/0) in B2", "dot(theta2)"),
        "`Omega(2/0) in B2` is a vector: give [x, y, z], its components in B2, or a sum over \
         the basis vectors (a*x1 + b*y2), not the scalar `dot(theta2)`"
    );
    // A vector over the bases is still read.
    assert!(
        verify(
            &m,
            "Omega(2/0) in B2",
            "dot(theta2)*x2 + dot(theta1)*z1",
            None
        )
        .unwrap()
        .is_equivalent()
    );
}

#[test]
fn a_result_that_is_not_a_finite_number_is_refused_naming_the_quantity() {
    let m = crate::regulator();
    let q = Quantity::parse("V(G2,2/0) in B2").unwrap();
    let v = torseur::derivation::derive(&m, &q).unwrap().value;
    let point = |big: &str| {
        let values = Values::parse(&format!(
            r#"{{"parameters": {{"L1": {big}, "L2": 1, "d1": 1, "h1": 1}},
                "coordinates": {{"theta1": [0, {big}, 0], "theta2": [0, 1, 0]}}}}"#
        ))
        .unwrap();
        numeric_point_for(&m, &values, &v.exprs()).unwrap()
    };
    // By hand: V(G2,2/0)·x2 = −(L1 + L2 cos θ2) θ̇1 = −(2 + cos 0)·2 = −6 at θ2 = 0.
    let ok = try_eval_value(&m, "V(G2,2/0) in B2", &v, &point("2")).unwrap();
    assert_eq!(ok["value"][0], -6.0);
    // L1 θ̇1 = 1e600 overflows.
    let e = try_eval_value(&m, "V(G2,2/0) in B2", &v, &point("1e300")).unwrap_err();
    assert_eq!(
        e.to_string(),
        "values: `V(G2,2/0) in B2` is not a finite number at these values (a result overflows \
         the floating-point range, or is undefined there)"
    );
}

#[test]
fn quantities_plots_and_rate_laws_are_refused_when_the_spec_is_loaded() {
    let n = base()["quantities"].as_array().unwrap().len();
    let mut v = base();
    v["quantities"]
        .as_array_mut()
        .unwrap()
        .push("eom(nosuch)".into());
    assert_eq!(
        refusal(&v),
        (
            format!("quantities[{n}]"),
            "eom(nosuch): unknown coordinate `nosuch` (declared: `theta1`, `theta2`)".to_string()
        )
    );
    let mut v = base();
    v["quantities"].as_array_mut().unwrap().push("C_x".into());
    assert_eq!(
        refusal(&v),
        (
            format!("quantities[{n}]"),
            "C_x: `C_x` is not an unknown of the PFD (links' components, actions' unknowns)"
                .to_string()
        )
    );
    // A plot panel that names no column of the runs.
    let mut v = base();
    let (k, _) = (v["questions"].as_array().unwrap().iter().enumerate())
        .find(|(_, q)| q.get("simulation").is_some())
        .unwrap();
    v["questions"][k]["simulation"]["plot"]
        .as_array_mut()
        .unwrap()
        .push("nothing".into());
    assert_eq!(
        refusal(&v),
        (
            format!("questions[{k}].simulation.plot[3]"),
            "`nothing` is not a column of the simulation (its columns: theta1, dot(theta1), \
             theta2, dot(theta2), C_m)"
                .to_string()
        )
    );
    let mut v = base();
    v["questions"][k]["simulation"]["scenarios"][1] = "nulle_part".into();
    assert_eq!(
        refusal(&v),
        (
            format!("questions[{k}].simulation.scenarios[1]"),
            "no scenario `nulle_part` in the spec's `scenarios`".to_string()
        )
    );
    // A rate law that divides by zero where it starts, at t = 0 or at the end of the piece
    // before.
    let mut v = base();
    v["scenarios"][0]["imposed"][0]["rate"][0]["value"] = "1/t".into();
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].imposed[0].rate[0].value".to_string(),
            "the rate at t = 0 s, where this piece starts: division by zero".to_string()
        )
    );
    let mut v = base();
    v["scenarios"][0]["imposed"][0]["rate"][1]["value"] = "1/(t - 0.5)".into();
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].imposed[0].rate[1].value".to_string(),
            "the rate at t = 0.5 s, where this piece starts: division by zero".to_string()
        )
    );
    let mut v = base();
    v["scenarios"][0]["imposed"][0]["coordinate"] = "theta9".into();
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].imposed[0].coordinate".to_string(),
            "`theta9` is not a coordinate".to_string()
        )
    );
    let mut v = base();
    v["scenarios"][0]["record"][0] = "X9".into();
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].record[0]".to_string(),
            "`X9` is not an unknown of the PFD (links' components, actions' unknowns)".to_string()
        )
    );
    let mut v = base();
    v["scenarios"][0]["values"]["m9"] = 1.0.into();
    assert_eq!(
        refusal(&v),
        (
            "scenarios[0].values.m9".to_string(),
            "`m9` is not a parameter".to_string()
        )
    );
    // A parameter the scenario gives no value is refused when it runs, not when the spec is
    // loaded (a spec may gain a parameter its scenarios do not need).
    let mut v = base();
    v["scenarios"][0]["values"]
        .as_object_mut()
        .unwrap()
        .remove("m2");
    let m = from_str(&v.to_string()).expect("loads");
    let e = torseur::simulate::simulate(&m, "sans_frottement").unwrap_err();
    assert_eq!(
        e.to_string(),
        "scenario `sans_frottement`: no value for the parameter `m2`"
    );
}

#[test]
fn number_literals_are_bounded_in_every_expression_text() {
    let long = format!("1{}", "0".repeat(100)); // 101 digits
    let fits = format!("1{}", "0".repeat(99)); // 100 digits
    let mut v = base();
    v["points"][2]["position"] = format!("{long}*d1*z0 + L1*y1").into();
    let (path, message) = refusal(&v);
    assert_eq!(path, "points[2].position");
    assert!(
        message.ends_with(": a number of 101 digits: a number has at most 100"),
        "{message}"
    );
    // The float backend refuses the same spec with the same words.
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let float = match torseur::numeric::NumericModel::new(&file) {
        Ok(_) => panic!("the float backend accepted it"),
        Err(e) => e.to_string(),
    };
    assert!(
        float.contains("a number of 101 digits: a number has at most 100"),
        "{float}"
    );
    // Decimals count, the point does not.
    let mut v = base();
    v["points"][2]["position"] = format!("0.{}*d1*z0 + L1*y1", "0".repeat(101)).into();
    assert!(
        refusal(&v)
            .1
            .ends_with("a number of 102 digits: a number has at most 100")
    );
    let mut v = base();
    v["points"][2]["position"] = format!("{fits}*d1*z0 + L1*y1").into();
    from_str(&v.to_string()).expect("100 digits are within the bound");
    // A typed result and a number of a values file.
    let m = crate::regulator();
    let e = verify(&m, "C_m", &long, None).unwrap_err().to_string();
    assert!(
        e.ends_with("a number of 101 digits: a number has at most 100"),
        "{e}"
    );
    let e = Values::parse(&format!(r#"{{"parameters": {{"L1": "{long}"}}}}"#)).unwrap_err();
    assert!(
        e.to_string()
            .ends_with("a number of 101 digits: a number has at most 100"),
        "{e}"
    );
    // A number the text computes is bounded as a typed one: what parses prints to a text that
    // parses back (found by the fuzzer: the 544 digits of 6·777777777777777777777²⁶ printed
    // as one literal the parser then refused).
    let e = verify(&m, "C_m", "-6*(777777777777777777777)^26", None)
        .unwrap_err()
        .to_string();
    assert!(
        e.ends_with("it computes a number of 544 digits: a number has at most 100"),
        "{e}"
    );
    let big = format!("10^{}", 99);
    let text = verify(&m, "C_m", &big, None)
        .map(|_| ())
        .map_err(|e| e.to_string());
    assert!(text.is_ok(), "10^99 has 100 digits: {text:?}");
    // A million digits are refused at once, not read for minutes.
    let start = std::time::Instant::now();
    let mut v = base();
    v["points"][2]["position"] = format!("{}*d1*z0", "7".repeat(1_000_000)).into();
    refusal(&v);
    assert!(start.elapsed().as_secs() < 10, "{:?}", start.elapsed());
}

#[test]
fn a_scenario_that_imposes_every_motion_runs_with_nothing_to_solve() {
    // The regulator with θ1 at a constant rate and θ2 held: a steady rotation. By hand,
    // θ1 = 10 t, θ2 = 0.3 throughout, and the motor torque is zero (σ(O1,E/0)·z0 is constant,
    // so δ(O1,E/0)·z0 = 0, and no other external action has a moment about z0).
    let m = crate::regulator();
    let mut sc = m.spec().scenarios[0].clone();
    sc.name = "tout_impose".into();
    sc.imposed = serde_json::from_value(serde_json::json!([
        {"coordinate": "theta1", "initial": 0.0, "rate": [{"value": "10"}]},
        {"coordinate": "theta2", "initial": 0.3, "rate": [{"value": "0"}]}
    ]))
    .unwrap();
    sc.initial.clear();
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let last = run.times.len() - 1;
    assert_eq!(run.times[last], 1.0);
    let col = |id: &str| run.column(id).unwrap_or_else(|| panic!("no column {id}"));
    assert!(
        (col("theta1")[last] - 10.0).abs() < 1e-9,
        "{}",
        col("theta1")[last]
    );
    assert!(col("theta2").iter().all(|x| (x - 0.3).abs() < 1e-12));
    assert!(col("dot(theta1)").iter().all(|x| *x == 10.0));
    assert!(
        col("C_m").iter().all(|x| x.abs() < 1e-12),
        "{:?}",
        col("C_m").iter().fold(0.0_f64, |a, x| a.max(x.abs()))
    );
}

/// What a teacher types from habit is refused with what to write instead (issue 37, messages
/// that say the fix): a prime or `diff` for a time derivative, `pi` as a factor, `sqrt`.
#[test]
fn habits_of_other_tools_are_refused_with_the_fix() {
    let reg = torseur::expr::Registry::new(&["L".into()], &[]).unwrap();
    let said = |text: &str| reg.parse(text).unwrap_err().to_string();
    assert_eq!(
        said("L*psi'"),
        "cannot parse `L*psi'`: `psi'`: a time derivative is written dot(psi)"
    );
    assert_eq!(
        said("diff(psi, t)*L"),
        "cannot parse `diff(psi, t)*L`: `diff(...)`: a time derivative is written dot(q) or \
         ddot(q) for a coordinate q; the functions are sin, cos, dot, ddot and sqrt"
    );
    // A root is read only as one of the mechanism's (an explicit loop law's); this one has none.
    assert!(
        said("sqrt(L)")
            .contains("sqrt(L) is not one of the mechanism's square roots (it has none)")
    );
    // π typed as a Greek letter, or pasted from a document in a mathematical form, is `pi`.
    for (typed, c) in [("2*π*L", 'π'), ("2*𝜋*L", '𝜋'), ("2*ϖ*L", 'ϖ')] {
        assert_eq!(
            said(typed),
            format!(
                "cannot parse `{typed}`: character `{c}` is not allowed (the constant π is \
                 written pi: 2*pi*R)"
            )
        );
    }
    assert!(said("𝜃*L").ends_with("(names are ASCII letters: theta, m…)"));
    // `pi` is read (the constant π); where it cannot stand the message quotes what was
    // typed, never symbolica's own name for the constant.
    assert_eq!(reg.parse("2*pi*L").unwrap().to_string(), "2*L*pi");
    for typed in ["dot(pi)*L", "L*sin(pi*t)", "L*pi(2)"] {
        let e = said(typed);
        assert!(!e.contains('𝜋'), "quotes only what was typed: {e}");
    }
    assert!(said("dot(pi)*L").ends_with("dot(pi): `pi` is not a coordinate"));
    // The quantity reader says the same of a derivative written as a function.
    let e = Quantity::parse("diff(theta1)").unwrap_err().to_string();
    assert!(
        e.contains("unknown quantity `diff` (a time derivative is written dot(q)"),
        "{e}"
    );
}
