//! Tests of the PFD in the float backend (Ec, unknowns, equations of motion) against formulas
//! written out by hand here, and against the backend's kinematic route (δ, Rd, Ω, V), which
//! does not use the actions.

use super::{NumValue, NumericError, NumericModel, Sample};
use crate::quantity::Quantity;
use crate::wire::SpecFile;
use nalgebra::Vector3;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde_json::{Value, json};

const REGULATOR: &str = include_str!("../../derivations/regulateur_centrifuge.json");

fn model(json: &str) -> NumericModel {
    let spec: SpecFile = serde_json::from_str(json).expect("test spec is valid JSON");
    NumericModel::new(&spec).unwrap_or_else(|e| panic!("test spec builds: {e}"))
}

fn model_of(v: &Value) -> NumericModel {
    model(&v.to_string())
}

fn spec_error(v: &Value) -> String {
    let spec: SpecFile = serde_json::from_value(v.clone()).expect("test spec is valid JSON");
    NumericModel::new(&spec)
        .expect_err("the spec must be refused")
        .to_string()
}

fn sample(params: &[(&str, f64)], coords: &[(&str, [f64; 3])]) -> Sample {
    Sample {
        parameters: params.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
        coordinates: coords.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
        time: 0.0,
    }
}

fn try_scalar(m: &NumericModel, q: &str, s: &Sample) -> Result<f64, NumericError> {
    let q = Quantity::parse(q).expect("notation");
    match m.evaluate(&q, s, "0")? {
        NumValue::Scalar(x) => Ok(x),
        other => panic!("{q}: expected a scalar, got {other:?}"),
    }
}

fn scalar(m: &NumericModel, q: &str, s: &Sample) -> f64 {
    try_scalar(m, q, s).unwrap_or_else(|e| panic!("{q}: {e}"))
}

fn error(m: &NumericModel, q: &str, s: &Sample) -> String {
    try_scalar(m, q, s)
        .expect_err("the evaluation must fail")
        .to_string()
}

fn vector(m: &NumericModel, q: &str, s: &Sample) -> Vector3<f64> {
    let q = Quantity::parse(q).expect("notation");
    match m.evaluate(&q, s, "0") {
        Ok(NumValue::Vector { value, .. }) => Vector3::from(value),
        other => panic!("{q}: expected a vector, got {other:?}"),
    }
}

#[track_caller]
fn close(got: f64, expected: f64, tol: f64) {
    assert!(
        (got - expected).abs() <= tol * (1.0 + expected.abs()),
        "{got} != {expected}"
    );
}

/// With a JSON object's field replaced.
fn with(mut v: Value, key: &str, value: Value) -> Value {
    v[key] = value;
    v
}

// --------------------------------------------------------------------- a simple pendulum

/// A solid on a pivot (O, z0), G at −l y1, any inertia at G, gravity −g y0.
fn pendulum() -> Value {
    json!({
        "title": "pendulum",
        "parameters": [
            {"name": "m", "unit": "kg"}, {"name": "l", "unit": "m"}, {"name": "g"},
            {"name": "A"}, {"name": "B"}, {"name": "C"},
            {"name": "D"}, {"name": "E"}, {"name": "F"}
        ],
        "coordinates": [{"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}}],
        "points": [{"name": "O", "position": "0"}, {"name": "G", "from": "O", "position": "-l*y1"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G",
            "inertia": {"point": "G", "basis": "1",
                "matrix": [["A", "-F", "-E"], ["-F", "B", "-D"], ["-E", "-D", "C"]]}}],
        "gravity": "-g*y0",
        "links": [{"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O", "axis": "z0"}],
        "pfd": [
            {"isolate": "1", "theorem": "moment", "point": "O", "on": "z0", "eom": "theta"},
            {"isolate": "1", "theorem": "resultant", "on": "x0"},
            {"isolate": "1", "theorem": "resultant", "on": "y0"},
            {"isolate": "1", "theorem": "resultant", "on": "z0"},
            {"isolate": "1", "theorem": "moment", "point": "O", "on": "x0"},
            {"isolate": "1", "theorem": "moment", "point": "O", "on": "y0"}
        ]
    })
}

fn pendulum_sample(theta: [f64; 3]) -> Sample {
    sample(
        &[
            ("m", 1.3),
            ("l", 0.8),
            ("g", 9.81),
            ("A", 0.5),
            ("B", 0.6),
            ("C", 0.7),
            ("D", 0.05),
            ("E", 0.04),
            ("F", 0.03),
        ],
        &[("theta", theta)],
    )
}

#[test]
fn pendulum_equation_of_motion_by_hand() {
    let m = model_of(&pendulum());
    for theta in [
        [0.3, 1.2, -0.7],
        [-2.5, -0.4, 2.0],
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
    ] {
        let s = pendulum_sample(theta);
        let p = &s.parameters;
        let (mass, l, g) = (p["m"], p["l"], p["g"]);
        // I_O θ̈ + m g l sin θ, I_O = C + m l².
        let i_o = p["C"] + mass * l * l;
        close(
            scalar(&m, "eom(theta)", &s),
            i_o * theta[2] + mass * g * l * theta[0].sin(),
            1e-12,
        );
        // Ec = ½ I_O θ̇².
        close(
            scalar(&m, "Ec(1/0)", &s),
            0.5 * i_o * theta[1] * theta[1],
            1e-12,
        );
    }
}

#[test]
fn pendulum_link_unknowns() {
    let m = model_of(&pendulum());
    assert_eq!(
        m.unknown_names().collect::<Vec<_>>(),
        ["X01", "Y01", "Z01", "L01", "M01"]
    );
    for theta in [[0.3, 1.2, -0.7], [-2.5, -0.4, 2.0], [2.0, 1.5, 0.5]] {
        let s = pendulum_sample(theta);
        let p = &s.parameters;
        let (mass, l, g) = (p["m"], p["l"], p["g"]);
        let (q, w, a) = (theta[0], theta[1], theta[2]);
        // OG = l sin θ x0 − l cos θ y0: Γ(G) by hand.
        let gx = l * (a * q.cos() - w * w * q.sin());
        let gy = l * (a * q.sin() + w * w * q.cos());
        close(scalar(&m, "X01", &s), mass * gx, 1e-12);
        close(scalar(&m, "Y01", &s), mass * gy + mass * g, 1e-12);
        close(scalar(&m, "Z01", &s), 0.0, 1e-12);
        // The weight's moment at O is along z0: the link carries δ(O,1/0) on x0 and y0.
        close(
            scalar(&m, "L01", &s),
            scalar(&m, "delta(O,1/0).x0", &s),
            1e-12,
        );
        close(
            scalar(&m, "M01", &s),
            scalar(&m, "delta(O,1/0).y0", &s),
            1e-12,
        );
        assert!(
            scalar(&m, "L01", &s).abs() > 1e-3,
            "products of inertia act"
        );
        // A pivot of axis z0 transmits no moment along z0.
        assert!(error(&m, "N01", &s).contains("is not an unknown of the PFD"));
    }
}

/// The moment theorem at G instead of O: the link's resultant, solved from the resultant
/// theorems, now has a moment GO ∧ R01 there, and the weight none; substituted, the equation of
/// motion is the same.
#[test]
fn pendulum_equation_of_motion_at_the_centre_of_inertia() {
    let mut v = pendulum();
    v["pfd"][0]["point"] = json!("G");
    let m = model_of(&v);
    for theta in [[0.3, 1.2, -0.7], [-2.5, -0.4, 2.0], [2.0, 1.5, 0.5]] {
        let s = pendulum_sample(theta);
        let p = &s.parameters;
        let (mass, l, g) = (p["m"], p["l"], p["g"]);
        let i_o = p["C"] + mass * l * l;
        close(
            scalar(&m, "eom(theta)", &s),
            i_o * theta[2] + mass * g * l * theta[0].sin(),
            1e-12,
        );
    }
}

#[test]
fn pendulum_at_random_samples() {
    let m = model_of(&pendulum());
    for seed in 0..20 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let p = &s.parameters;
        assert!((0.5..=2.0).contains(&p["g"]), "g is drawn positive");
        let t = s.coordinates["theta"];
        let i_o = p["C"] + p["m"] * p["l"] * p["l"];
        close(
            scalar(&m, "eom(theta)", &s),
            i_o * t[2] + p["m"] * p["g"] * p["l"] * t[0].sin(),
            1e-11,
        );
    }
}

// ---------------------------------------------------- a rotor, its motor, friction, spring

fn rotor() -> Value {
    json!({
        "title": "rotor",
        "parameters": [
            {"name": "m", "unit": "kg"}, {"name": "A"}, {"name": "C"}, {"name": "g"},
            {"name": "f"}, {"name": "k"}, {"name": "q0"}
        ],
        "coordinates": [{"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}}],
        "points": [{"name": "O", "position": "0"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "O",
            "inertia": {"point": "O", "basis": "1",
                "matrix": [["A", "0", "0"], ["0", "A", "0"], ["0", "0", "C"]]}}],
        "gravity": "-g*z0",
        "links": [{"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O",
            "axis": "z0", "friction": "f",
            "spring": {"coordinate": "theta", "stiffness": "k", "free": "q0"}}],
        "actions": [{"name": "moteur", "from": "0", "on": "1", "point": "O",
            "moment": "C_m*z0", "unknowns": ["C_m"]}],
        "pfd": [{"isolate": "1", "theorem": "moment", "point": "O", "on": "z0"}]
    })
}

fn rotor_sample(theta: [f64; 3]) -> Sample {
    sample(
        &[
            ("m", 2.0),
            ("A", 0.4),
            ("C", 0.5),
            ("g", 9.81),
            ("f", 0.3),
            ("k", 1.7),
            ("q0", 0.2),
        ],
        &[("theta", theta)],
    )
}

#[test]
fn rotor_motor_torque_by_hand() {
    let m = model_of(&rotor());
    assert_eq!(
        m.unknown_names().collect::<Vec<_>>(),
        ["X01", "Y01", "Z01", "L01", "M01", "C_m"]
    );
    for theta in [[0.3, 1.2, -0.7], [-2.5, -0.4, 2.0], [0.2, 0.0, 0.0]] {
        let s = rotor_sample(theta);
        let p = &s.parameters;
        // C_m − f θ̇ − k (θ − θ0) = C θ̈.
        let expected = p["C"] * theta[2] + p["f"] * theta[1] + p["k"] * (theta[0] - p["q0"]);
        close(scalar(&m, "C_m", &s), expected, 1e-12);
    }
    // Without friction and spring: C_m = C θ̈.
    let mut bare = rotor();
    bare["links"][0]
        .as_object_mut()
        .expect("link")
        .remove("friction");
    bare["links"][0]
        .as_object_mut()
        .expect("link")
        .remove("spring");
    let m = model_of(&bare);
    let s = rotor_sample([0.3, 1.2, -0.7]);
    close(scalar(&m, "C_m", &s), 0.5 * -0.7, 1e-12);
    // The unknown is not a parameter: a sample that gives it is refused, and drawn samples
    // give values to g, f and k (positive) but none to C_m.
    let mut given = s.clone();
    given.parameters.insert("C_m".into(), 1.0);
    assert_eq!(error(&m, "C_m", &given), "sample: unknown parameter `C_m`");
    let m = model_of(&rotor());
    let drawn = m.sample(&mut ChaCha8Rng::seed_from_u64(3)).expect("sample");
    for k in ["g", "f", "k"] {
        assert!((0.5..=2.0).contains(&drawn.parameters[k]), "{k}");
    }
    assert!(!drawn.parameters.contains_key("C_m"));
    assert_eq!(drawn.parameters.len(), 7);
}

/// An action between two solids acts on both: its reaction is received by the one that exerts
/// it, and it is internal to a set holding both.
#[test]
fn reactions_and_internal_actions() {
    let spec = json!({
        "title": "two rotors",
        "parameters": [{"name": "m1", "unit": "kg"}, {"name": "m2", "unit": "kg"},
            {"name": "C1"}, {"name": "C2"}],
        "coordinates": [{"name": "t1", "kind": "angle"}, {"name": "t2", "kind": "angle"}],
        "frames": [
            {"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "t1"}},
            {"name": "2", "parent": "0", "rotation": {"axis": "z", "angle": "t2"}}
        ],
        "points": [{"name": "O", "position": "0"}],
        "solids": [
            {"name": "1", "frame": "1", "mass": "m1", "centre": "O", "inertia": {"point": "O",
                "basis": "1", "matrix": [["C1", "0", "0"], ["0", "C1", "0"], ["0", "0", "C1"]]}},
            {"name": "2", "frame": "2", "mass": "m2", "centre": "O", "inertia": {"point": "O",
                "basis": "2", "matrix": [["C2", "0", "0"], ["0", "C2", "0"], ["0", "0", "C2"]]}}
        ],
        "sets": {"E": ["1", "2"]},
        "actions": [{"name": "coupleur", "from": "1", "on": "2", "point": "O",
            "moment": "Cr*z1", "unknowns": ["Cr"]}],
        "pfd": [
            {"isolate": "2", "theorem": "moment", "point": "O", "on": "z0"},
            {"isolate": "1", "theorem": "moment", "point": "O", "on": "z0", "eom": "t1"},
            {"isolate": "E", "theorem": "moment", "point": "O", "on": "z0", "eom": "t2"}
        ]
    });
    let m = model_of(&spec);
    let s = sample(
        &[("m1", 1.0), ("m2", 2.0), ("C1", 0.3), ("C2", 0.8)],
        &[("t1", [0.4, 1.1, 0.6]), ("t2", [-1.2, 0.5, -1.5])],
    );
    close(scalar(&m, "Cr", &s), 0.8 * -1.5, 1e-12);
    // Isolating 1: C1 θ̈1 − (−Cr) with Cr = C2 θ̈2.
    close(scalar(&m, "eom(t1)", &s), 0.3 * 0.6 + 0.8 * -1.5, 1e-12);
    // Isolating E = {1, 2}: the action is internal.
    close(scalar(&m, "eom(t2)", &s), 0.3 * 0.6 + 0.8 * -1.5, 1e-12);
}

// ------------------------------------------------------------- a slider on a turning arm

/// A point mass of solid 2 slides along the arm 1 (a point mass on the axis) turning about z0.
fn arm_slider() -> Value {
    json!({
        "title": "slider on an arm",
        "parameters": [{"name": "m", "unit": "kg"}, {"name": "g"}, {"name": "f"},
            {"name": "k"}, {"name": "r0", "unit": "m"}, {"name": "m1", "unit": "kg"}],
        "coordinates": [{"name": "theta", "kind": "angle"}, {"name": "r", "kind": "length"}],
        "frames": [
            {"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}},
            {"name": "2", "parent": "1", "origin": "P"}
        ],
        "points": [{"name": "P", "position": "r*x1"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m1", "centre": "O0"},
            {"name": "2", "frame": "2", "mass": "m", "centre": "P"}],
        "gravity": "-g*z0",
        "links": [{"name": "12", "kind": "slider", "between": ["1", "2"], "point": "P",
            "axis": "x1", "friction": "f",
            "spring": {"coordinate": "r", "stiffness": "k", "free": "r0"}}],
        "pfd": [
            {"isolate": "2", "theorem": "resultant", "on": "x1", "eom": "r"},
            {"isolate": "2", "theorem": "resultant", "on": "y1"},
            {"isolate": "2", "theorem": "resultant", "on": "z1"},
            {"isolate": "2", "theorem": "moment", "point": "P", "on": "x1"},
            {"isolate": "2", "theorem": "moment", "point": "P", "on": "y1"},
            {"isolate": "2", "theorem": "moment", "point": "P", "on": "z1"}
        ]
    })
}

#[test]
fn slider_unknowns_and_equation_of_motion_by_hand() {
    let m = model_of(&arm_slider());
    assert_eq!(
        m.unknown_names().collect::<Vec<_>>(),
        ["Y12", "Z12", "L12", "M12", "N12"]
    );
    let (mass, g, f, k, r0) = (1.4, 9.81, 0.35, 2.5, 0.9);
    for (t, r) in [
        ([0.3, 1.2, -0.7], [1.1, 0.4, 0.3]),
        ([-2.0, -0.5, 1.5], [0.6, -1.3, 0.8]),
    ] {
        let s = sample(
            &[
                ("m", mass),
                ("g", g),
                ("f", f),
                ("k", k),
                ("r0", r0),
                ("m1", 3.0),
            ],
            &[("theta", t), ("r", r)],
        );
        // Γ(P/0) = (r̈ − r θ̇²) x1 + (r θ̈ + 2 ṙ θ̇) y1.
        close(
            scalar(&m, "Y12", &s),
            mass * (r[0] * t[2] + 2.0 * r[1] * t[1]),
            1e-12,
        );
        close(scalar(&m, "Z12", &s), mass * g, 1e-12);
        for n in ["L12", "M12", "N12"] {
            close(scalar(&m, n, &s), 0.0, 1e-12);
        }
        close(
            scalar(&m, "eom(r)", &s),
            mass * (r[2] - r[0] * t[1] * t[1]) + f * r[1] + k * (r[0] - r0),
            1e-12,
        );
        let v2 = r[1] * r[1] + r[0] * r[0] * t[1] * t[1];
        close(scalar(&m, "Ec(2/0)", &s), 0.5 * mass * v2, 1e-12);
        close(scalar(&m, "Ec(2/1)", &s), 0.5 * mass * r[1] * r[1], 1e-12);
    }
}

/// The components each kind of link transmits, as unknowns.
#[test]
fn link_kinds_transmit_their_components() {
    let link = |name: &str, kind: &str, axis: Option<&str>, direction: Option<&str>| {
        let mut l = json!({"name": name, "kind": kind, "between": ["0", "1"], "point": "O"});
        if let Some(a) = axis {
            l["axis"] = json!(a);
        }
        if let Some(d) = direction {
            l["direction"] = json!(d);
        }
        l
    };
    let spec = json!({
        "title": "links",
        "parameters": [{"name": "m1", "unit": "kg"}],
        "frames": [{"name": "1", "parent": "0"}],
        "points": [{"name": "O", "position": "0"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m1", "centre": "O"}],
        "links": [
            link("a", "fixed", None, None),
            link("b", "pivot", Some("z0"), None),
            link("c", "slider", Some("x0"), None),
            link("d", "pivot_slider", Some("y0"), None),
            link("e", "ball", None, None),
            link("p", "plane", Some("z0"), None),
            link("n", "annular", Some("x0"), None),
            link("l", "line", Some("z0"), Some("x0")),
            link("q", "point", Some("y0"), None)
        ]
    });
    let m = model_of(&spec);
    // Links named by a letter: X_a, as the course writes X_A for the bearing A.
    let names: Vec<&str> = m.unknown_names().collect();
    assert_eq!(
        names,
        [
            "X_a", "Y_a", "Z_a", "L_a", "M_a", "N_a", // fixed
            "X_b", "Y_b", "Z_b", "L_b", "M_b", // pivot z
            "Y_c", "Z_c", "L_c", "M_c", "N_c", // slider x
            "X_d", "Z_d", "L_d", "N_d", // pivot slider y
            "X_e", "Y_e", "Z_e", // ball
            "Z_p", "L_p", "M_p", // plane of normal z
            "Y_n", "Z_n", // annular of axis x
            "Z_l", "M_l", // line of normal z, direction x
            "Y_q", // point of normal y
        ]
    );
}

/// Components are written in the basis of the axis' frame: a link of axis x1 on a turning
/// frame, isolating a point mass at rest (only its weight and the link act).
#[test]
fn link_components_in_the_axis_basis() {
    let spec = json!({
        "title": "mass on a turned support",
        "parameters": [{"name": "m", "unit": "kg"}, {"name": "g"}, {"name": "a", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "x", "angle": "a"}}],
        "points": [{"name": "O", "position": "0"}],
        "solids": [{"name": "1", "frame": "0", "mass": "m", "centre": "O"}],
        "gravity": "-g*z0",
        "links": [{"name": "01", "kind": "ball", "between": ["0", "1"], "point": "O",
            "axis": "x1"}],
        "pfd": [
            {"isolate": "1", "theorem": "resultant", "on": "x0"},
            {"isolate": "1", "theorem": "resultant", "on": "y0"},
            {"isolate": "1", "theorem": "resultant", "on": "z0"}
        ]
    });
    let m = model_of(&spec);
    let s = sample(&[("m", 2.0), ("g", 9.81), ("a", 0.6)], &[]);
    // R = X x1 + Y y1 + Z z1 = m g z0, with y1 = cos a y0 + sin a z0, z1 = −sin a y0 + cos a z0.
    let w = 2.0 * 9.81;
    close(scalar(&m, "X01", &s), 0.0, 1e-12);
    close(scalar(&m, "Y01", &s), w * 0.6f64.sin(), 1e-12);
    close(scalar(&m, "Z01", &s), w * 0.6f64.cos(), 1e-12);
}

// ------------------------------------------------------------- the centrifugal regulator

/// The regulator with its PFD as in the course (Application 1, Q6): the sections are set here,
/// whatever the file holds, and g and f are declared if it does not.
fn regulator(friction: bool) -> NumericModel {
    let mut v: Value = serde_json::from_str(REGULATOR).expect("json");
    let params = v["parameters"].as_array_mut().expect("parameters");
    for name in ["g", "f"] {
        if !params.iter().any(|p| p["name"] == name) {
            params.push(json!({"name": name}));
        }
    }
    let mut l12 = json!({"name": "12", "kind": "pivot", "between": ["1", "2"], "point": "O2",
        "axis": "x1"});
    if friction {
        l12["friction"] = json!("f");
    }
    v["gravity"] = json!("-g*z0");
    v["links"] = json!([
        {"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O1", "axis": "z0"},
        l12
    ]);
    v["actions"] = json!([{"name": "moteur", "from": "0", "on": "1", "point": "O1",
        "moment": "C_m*z0", "unknowns": ["C_m"]}]);
    v["pfd"] = json!([
        {"isolate": "E", "theorem": "moment", "point": "O1", "on": "z0"},
        {"isolate": "2", "theorem": "moment", "point": "O2", "on": "x2", "eom": "theta2"}
    ]);
    model_of(&v)
}

#[test]
fn regulator_motor_torque_is_the_dynamic_moment() {
    let m = regulator(true);
    for seed in 0..20 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        // Gravity along z0 has no moment on z0 at O1, friction is internal to E, the pivot
        // (O1, z0) transmits no moment on z0.
        close(
            scalar(&m, "C_m", &s),
            scalar(&m, "delta(O1,E/0).z0", &s),
            1e-11,
        );
    }
}

#[test]
fn regulator_equation_of_motion() {
    let (with_f, without_f) = (regulator(true), regulator(false));
    for seed in 0..20 {
        let s = with_f
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let p = &s.parameters;
        let t2 = s.coordinates["theta2"];
        let eom = scalar(&with_f, "eom(theta2)", &s);
        // Friction adds exactly f θ̇2.
        close(
            eom - scalar(&without_f, "eom(theta2)", &s),
            p["f"] * t2[1],
            1e-11,
        );
        // δ(O2,2/0)·x2 − M(O2, weight)·x2 + f θ̇2, the weight's moment by hand:
        // (L2 y2 ∧ −m2 g z0)·x2 = −m2 g L2 cos θ2.
        let expected = scalar(&with_f, "delta(O2,2/0).x2", &s)
            + p["m2"] * p["g"] * p["L2"] * t2[0].cos()
            + p["f"] * t2[1];
        close(eom, expected, 1e-11);
    }
}

/// The kinetic energy theorem on E: d/dt Ec(E/0) is the power of every action, the motor,
/// the weight, the friction (internal), and the torque r x1 of 1 on 2 that the sampled θ̈2
/// would need beyond them, r = eom(θ2); the perfect links have no power.
#[test]
fn regulator_energy_and_power() {
    let m = regulator(true);
    for seed in 0..10 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let p = &s.parameters;
        let (t1, t2) = (s.coordinates["theta1"], s.coordinates["theta2"]);
        let power = scalar(&m, "C_m", &s) * t1[1]
            - p["m2"] * p["g"] * p["L2"] * t2[0].cos() * t2[1]
            - p["f"] * t2[1] * t2[1]
            + scalar(&m, "eom(theta2)", &s) * t2[1];

        // Route 1: Ec along the trajectory q(t) = q + q̇ t + q̈ t²/2, central difference.
        let h = 1e-5;
        let at = |t: f64| {
            let mut st = s.clone();
            for q in st.coordinates.values_mut() {
                *q = [q[0] + q[1] * t + q[2] * t * t / 2.0, q[1] + q[2] * t, q[2]];
            }
            scalar(&m, "Ec(E/0)", &st)
        };
        let d_ec = (at(h) - at(-h)) / (2.0 * h);
        close(d_ec, power, 1e-7);

        // Route 2: d/dt Ec(S/0) = {D(S/0)}·{V(S/0)} per solid, the comoment at O1 (fixed) and O2.
        let comoment = vector(&m, "delta(O1,1/0)", &s).dot(&vector(&m, "Omega(1/0)", &s))
            + vector(&m, "Rd(2/0)", &s).dot(&vector(&m, "V(O2,2/0)", &s))
            + vector(&m, "delta(O2,2/0)", &s).dot(&vector(&m, "Omega(2/0)", &s));
        close(comoment, power, 1e-10);

        // And Ec itself as the sum over the solids.
        close(
            scalar(&m, "Ec(E/0)", &s),
            scalar(&m, "Ec(1/0)", &s) + scalar(&m, "Ec(2/0)", &s),
            1e-12,
        );
    }
}

#[test]
fn regulator_spec_quantities_evaluate() {
    let m = regulator(true);
    let s = m.sample(&mut ChaCha8Rng::seed_from_u64(5)).expect("sample");
    assert!(!s.parameters.contains_key("C_m"));
    for k in ["g", "f"] {
        assert!((0.5..=2.0).contains(&s.parameters[k]), "{k}");
    }
    assert_eq!(
        m.unknown_names().collect::<Vec<_>>(),
        [
            "X01", "Y01", "Z01", "L01", "M01", "X12", "Y12", "Z12", "M12", "N12", "C_m"
        ]
    );
    // The link unknowns appear in no equation without eom: nothing determines them.
    assert!(error(&m, "X01", &s).contains("nothing determines it"));
    // The file's own quantities, whatever its sections are now.
    let file = model(REGULATOR);
    let spec: SpecFile = serde_json::from_str(REGULATOR).expect("json");
    let s = file
        .sample(&mut ChaCha8Rng::seed_from_u64(5))
        .expect("sample");
    for q in &spec.quantities {
        let q = Quantity::parse(q).expect("notation");
        file.evaluate(&q, &s, "0")
            .unwrap_or_else(|e| panic!("{q}: {e}"));
    }
}

// ------------------------------------------------------------------------------- errors

#[test]
fn solving_errors() {
    let s = rotor_sample([0.3, 1.2, -0.7]);
    // Two unknowns that only appear as their sum: fixed together, neither alone
    // (hyperstatic), whether the equation is written twice or once.
    let mut v = rotor();
    v["actions"][0]["moment"] = json!("(Ca + Cb)*z0");
    v["actions"][0]["unknowns"] = json!(["Ca", "Cb"]);
    let one = v["pfd"][0].clone();
    let twice = with(v.clone(), "pfd", json!([one.clone(), one.clone()]));
    let m = model_of(&twice);
    let e = error(&m, "Ca", &s);
    assert!(e.starts_with("Ca: ") && e.contains("only together"), "{e}");
    let m = model_of(&v);
    let e = error(&m, "Cb", &s);
    assert!(e.starts_with("Cb: ") && e.contains("(hyperstatic)"), "{e}");

    // Names that are no unknown, and an equation of motion nobody declared.
    let m = model_of(&rotor());
    assert!(error(&m, "nope", &s).contains("`nope` is not an unknown of the PFD"));
    assert!(error(&m, "theta", &s).contains("is not an unknown"));
    assert!(error(&m, "eom(theta)", &s).contains("no equation of the PFD has eom `theta`"));
    assert!(error(&m, "eom(psi)", &s).contains("`psi` is not a time coordinate"));
    // An equation of motion that still holds an unknown no other equation determines.
    let mut v = pendulum();
    v["pfd"] = json!([{"isolate": "1", "theorem": "resultant", "on": "x0", "eom": "theta"}]);
    let m = model_of(&v);
    let s = pendulum_sample([0.3, 1.2, -0.7]);
    let e = error(&m, "eom(theta)", &s);
    assert!(e.contains("the unknown `X01`"), "{e}");
    assert!(error(&m, "X01", &s).contains("nothing determines it"));
    // An equation without eom in which no unknown appears: more equations than unknowns.
    let mut v = pendulum();
    v["pfd"] = json!([
        {"isolate": "1", "theorem": "moment", "point": "O", "on": "z0"},
        {"isolate": "1", "theorem": "moment", "point": "O", "on": "x0", "eom": "theta"}
    ]);
    let m = model_of(&v);
    let e = error(&m, "eom(theta)", &s);
    assert_eq!(
        e,
        "eom(theta): the PFD's equations without eom must determine the unknowns that appear \
         in them: 1 equation(s) for 0 unknown(s) (none)"
    );
    // Names are checked before the system: a wrong name is reported as such.
    assert!(error(&m, "nope", &s).contains("`nope` is not an unknown of the PFD"));
}

#[test]
fn spec_errors_of_the_pfd_sections() {
    let r = rotor();
    let e = spec_error(&with(
        r.clone(),
        "parameters",
        json!([{"name": "m"}, {"name": "A"}, {"name": "C"}, {"name": "g"}, {"name": "f"},
            {"name": "k"}, {"name": "q0"}, {"name": "C_m"}]),
    ));
    assert!(
        e.starts_with("spec, at actions[0].unknowns[0]: the unknown `C_m` is already a parameter"),
        "{e}"
    );
    for (moment, why) in [
        ("C_m^2*z0", "linearly"),
        ("C_m*C_m*z0", "linearly"),
        ("sin(C_m)*z0", "inside sin or cos"),
        ("z0/C_m", "an unknown divides"),
        ("X01*z0", "unknown name `X01`"),
    ] {
        let mut v = r.clone();
        v["actions"][0]["moment"] = json!(moment);
        let e = spec_error(&v);
        assert!(
            e.starts_with("spec, at actions[0].moment: ") && e.contains(why),
            "{e}"
        );
    }
    let mut v = r.clone();
    v["links"][0].as_object_mut().expect("link").remove("axis");
    assert!(spec_error(&v).starts_with("spec, at links[0].axis: a liaison pivot needs its axis"));
    let mut v = r.clone();
    v["links"][0]["kind"] = json!("ball");
    assert!(spec_error(&v).starts_with("spec, at links[0].friction: "));
    let mut v = r.clone();
    v["links"][0]["kind"] = json!("line");
    assert!(spec_error(&v).starts_with("spec, at links[0].direction: "));
    let mut v = r.clone();
    v["links"][0]["point"] = json!("Q");
    assert_eq!(
        spec_error(&v),
        "spec, at links[0].point: unknown point `Q` (declared: `O`, `O0`)"
    );
    let mut v = r.clone();
    v["links"][0]["between"] = json!(["0", "E"]);
    assert_eq!(
        spec_error(&v),
        "spec, at links[0].between[1]: `E` is neither a solid nor the ground `0` (declared: \
         `1`, `0`)"
    );
    let mut v = r.clone();
    v["pfd"][0]["isolate"] = json!("0");
    assert!(spec_error(&v).starts_with("spec, at pfd[0].isolate: `0` is the ground"));
    let mut v = r.clone();
    v["pfd"] = json!([
        {"isolate": "1", "theorem": "moment", "point": "O", "on": "z0", "eom": "theta"},
        {"isolate": "1", "theorem": "moment", "point": "O", "on": "z1", "eom": "theta"}
    ]);
    assert!(spec_error(&v).starts_with("spec, at pfd[1].eom: pfd[0] is already"));
    let mut v = r.clone();
    v["pfd"][0].as_object_mut().expect("pfd").remove("point");
    assert!(spec_error(&v).starts_with("spec, at pfd[0].point: "));
    let mut v = r.clone();
    v["pfd"][0]["on"] = json!("w0");
    assert!(spec_error(&v).starts_with("spec, at pfd[0].on: "));
    let v = with(r.clone(), "gravity", json!("-g*z1"));
    assert!(spec_error(&v).contains("gravity is constant in the ground frame"));
    let v = with(r.clone(), "gravity", json!("-g*theta*z0"));
    assert!(spec_error(&v).starts_with("spec, at gravity: `theta` is a time coordinate"));
    let v = with(r.clone(), "gravity", json!("-g"));
    assert!(spec_error(&v).starts_with("spec, at gravity: a vector was expected"));
    let mut v = r.clone();
    v["links"] = json!([r["links"][0].clone(), r["links"][0].clone()]);
    assert_eq!(
        spec_error(&v),
        "spec, at links[1].name: duplicate link `01`"
    );
}

/// A parameter read off a random body (a bare inertia entry) cannot also size an action.
#[test]
fn inertia_parameters_stay_out_of_the_actions() {
    let mut v = rotor();
    v["actions"][0]["resultant"] = json!("A*x0");
    let m = model_of(&v);
    let e = m
        .sample(&mut ChaCha8Rng::seed_from_u64(1))
        .expect_err("A is an inertia entry")
        .to_string();
    assert!(e.contains("also appears in actions[0]"), "{e}");
}
