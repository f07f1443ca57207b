//! Tests of the float backend against results derived by hand from the course's definitions.

use super::kin::{state, values};
use super::tests_regulator::regulator_sample;
use super::{NumValue, NumericError, NumericModel, Sample, cloud, la};
use crate::quantity::Quantity;
use crate::wire::SpecFile;
use nalgebra::{Matrix3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

pub(super) const REGULATOR: &str = include_str!("../../derivations/regulateur_centrifuge.json");

pub(super) fn model(json: &str) -> NumericModel {
    let spec: SpecFile = serde_json::from_str(json).expect("test spec is valid JSON");
    NumericModel::new(&spec).expect("test spec builds")
}

pub(super) fn spec_error(json: &str) -> NumericError {
    let spec: SpecFile = serde_json::from_str(json).expect("test spec is valid JSON");
    NumericModel::new(&spec).expect_err("the spec must be refused")
}

pub(super) fn sample(params: &[(&str, f64)], coords: &[(&str, [f64; 3])]) -> Sample {
    Sample {
        parameters: params.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
        coordinates: coords.iter().map(|(k, v)| (k.to_string(), *v)).collect(),
        time: 0.0,
    }
}

pub(super) fn eval(m: &NumericModel, q: &str, s: &Sample) -> NumValue {
    let q = Quantity::parse(q).expect("notation");
    m.evaluate(&q, s, "0")
        .unwrap_or_else(|e| panic!("{q}: {e}"))
}

pub(super) fn vector(m: &NumericModel, q: &str, s: &Sample) -> [f64; 3] {
    match eval(m, q, s) {
        NumValue::Vector { value, .. } => value,
        other => panic!("{q}: expected a vector, got {other:?}"),
    }
}

pub(super) fn scalar(m: &NumericModel, q: &str, s: &Sample) -> f64 {
    match eval(m, q, s) {
        NumValue::Scalar(x) => x,
        other => panic!("{q}: expected a scalar, got {other:?}"),
    }
}

pub(super) fn matrix(m: &NumericModel, q: &str, s: &Sample) -> [[f64; 3]; 3] {
    match eval(m, q, s) {
        NumValue::Matrix { value, .. } => value,
        other => panic!("{q}: expected a matrix, got {other:?}"),
    }
}

pub(super) fn torsor(m: &NumericModel, q: &str, s: &Sample) -> ([f64; 3], [f64; 3]) {
    match eval(m, q, s) {
        NumValue::Torsor {
            resultant, moment, ..
        } => (resultant, moment),
        other => panic!("{q}: expected a torsor, got {other:?}"),
    }
}

#[track_caller]
pub(super) fn close(a: &[f64], b: &[f64], tol: f64) {
    assert_eq!(a.len(), b.len());
    let size = b.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tol * size, "{a:?} != {b:?}");
    }
}

// The hand formulas work on the arrays of `NumValue`, with nalgebra's algebra.

pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    Vector3::from(a).cross(&Vector3::from(b)).into()
}

pub(super) fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    (Vector3::from(a) + Vector3::from(b)).into()
}

pub(super) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    (Vector3::from(a) - Vector3::from(b)).into()
}

pub(super) fn times(k: f64, a: [f64; 3]) -> [f64; 3] {
    (Vector3::from(a) * k).into()
}

pub(super) fn mat_vec(m: [[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    (Matrix3::from_fn(|r, c| m[r][c]) * Vector3::from(v)).into()
}

pub(super) const TOL: f64 = 1e-12;

// ---------------------------------------------------------------- a point mass on an arm

const ARM: &str = r#"{
  "title": "arm",
  "parameters": [{"name": "L", "unit": "m"}, {"name": "m", "unit": "kg"}],
  "coordinates": [{"name": "th", "kind": "angle"}],
  "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "th"}}],
  "points": [{"name": "P", "position": "L*x1"}],
  "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "P"}]
}"#;

#[test]
fn point_mass_on_a_rotating_arm() {
    let m = model(ARM);
    let (l, mass, q, w, a) = (0.8, 1.7, 0.4, 1.3, -0.6);
    let s = sample(&[("L", l), ("m", mass)], &[("th", [q, w, a])]);
    // V(P,1/0) = L θ̇ y1, Γ(P,1/0) = L θ̈ y1 − L θ̇² x1.
    close(&vector(&m, "V(P,1/0) in B1", &s), &[0.0, l * w, 0.0], TOL);
    close(
        &vector(&m, "Gamma(P,1/0) in B1", &s),
        &[-l * w * w, l * a, 0.0],
        TOL,
    );
    // The same in B0: y1 = −sin t x0 + cos t y0.
    close(
        &vector(&m, "V(P,1/0)", &s),
        &[-l * w * q.sin(), l * w * q.cos(), 0.0],
        TOL,
    );
    assert!((scalar(&m, "V(P,1/0).x1", &s)).abs() < TOL);
    close(&vector(&m, "Omega(1/0)", &s), &[0.0, 0.0, w], TOL);
    close(&vector(&m, "Omega(0/1)", &s), &[0.0, 0.0, -w], TOL);
    // σ(O0) = m L² θ̇ z, δ(O0) = m L² θ̈ z; Rc = m V(P), Rd = m Γ(P).
    close(
        &vector(&m, "sigma(O0,1/0)", &s),
        &[0.0, 0.0, mass * l * l * w],
        TOL,
    );
    close(
        &vector(&m, "delta(O0,1/0)", &s),
        &[0.0, 0.0, mass * l * l * a],
        TOL,
    );
    close(
        &vector(&m, "Rd(1/0) in B1", &s),
        &[-mass * l * w * w, mass * l * a, 0.0],
        TOL,
    );
    close(
        &vector(&m, "Rc(1/0) in B1", &s),
        &[0.0, mass * l * w, 0.0],
        TOL,
    );
    // At P itself the moments vanish.
    close(&vector(&m, "delta(P,1/0)", &s), &[0.0; 3], TOL);
    let (r, mo) = torsor(&m, "{V(1/0)}_O0 in B1", &s);
    close(&r, &[0.0, 0.0, w], TOL);
    close(&mo, &[0.0; 3], TOL);
    let (r, mo) = torsor(&m, "{D(1/0)}_O0 in B1", &s);
    close(&r, &[-mass * l * w * w, mass * l * a, 0.0], TOL);
    close(&mo, &[0.0, 0.0, mass * l * l * a], TOL);
}

#[test]
fn negative_axis_is_the_opposite_angle() {
    let m = model(&ARM.replace(r#""axis": "z""#, r#""axis": "-z""#));
    let (l, q, w) = (0.8, 0.4, 1.3);
    let s = sample(&[("L", l), ("m", 1.0)], &[("th", [q, w, 0.0])]);
    close(&vector(&m, "Omega(1/0)", &s), &[0.0, 0.0, -w], TOL);
    // x1 = cos t x0 − sin t y0.
    close(
        &vector(&m, "V(P,1/0)", &s),
        &[-l * w * q.sin(), -l * w * q.cos(), 0.0],
        TOL,
    );
}

// ------------------------------------------------ a slider on the arm: relative motion

const SLIDER: &str = r#"{
  "title": "slider",
  "coordinates": [{"name": "th", "kind": "angle"}, {"name": "lambda", "kind": "length"}],
  "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "th"}},
             {"name": "2", "parent": "1", "origin": "P"}],
  "points": [{"name": "P", "position": "lambda*x1"}]
}"#;

#[test]
fn slider_on_a_rotating_arm_has_coriolis_acceleration() {
    let m = model(SLIDER);
    let (lam, ld, ldd) = (1.2, 0.7, -0.3);
    let (w, a) = (1.1, 0.5);
    let s = sample(&[], &[("th", [0.2, w, a]), ("lambda", [lam, ld, ldd])]);
    // Γ(P,2/0) = (λ̈ − λ θ̇²) x1 + (λ θ̈ + 2 λ̇ θ̇) y1.
    close(
        &vector(&m, "Gamma(P,2/0) in B1", &s),
        &[ldd - lam * w * w, lam * a + 2.0 * ld * w, 0.0],
        TOL,
    );
    close(&vector(&m, "V(P,2/0) in B1", &s), &[ld, lam * w, 0.0], TOL);
    close(&vector(&m, "V(P,2/1) in B1", &s), &[ld, 0.0, 0.0], TOL);
    close(&vector(&m, "V(P,1/0) in B1", &s), &[0.0, lam * w, 0.0], TOL);
    // The point of 1 under P does not slide: its acceleration has no Coriolis term.
    close(
        &vector(&m, "Gamma(P,1/0) in B1", &s),
        &[-lam * w * w, lam * a, 0.0],
        TOL,
    );
    close(&vector(&m, "Omega(2/1)", &s), &[0.0; 3], TOL);
}

// ---------------------------------------------------- bodies spinning about a fixed axis

const ROTOR: &str = r#"{
  "title": "rotor",
  "parameters": [{"name": "m", "unit": "kg"}, {"name": "a", "unit": "m"}, {"name": "l", "unit": "m"},
                 {"name": "A"}, {"name": "C"}, {"name": "phi", "unit": "rad", "kind": "angle"}],
  "coordinates": [{"name": "th", "kind": "angle"}],
  "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "th"}},
             {"name": "3", "parent": "1", "rotation": {"axis": "z", "angle": "phi"}}],
  "points": [{"name": "G", "position": "a*x1"}, {"name": "E", "from": "G", "position": "-l/2*x1"}],
  "solids": [
    {"name": "disc", "frame": "1", "mass": "m", "centre": "O0",
     "inertia": {"point": "O0", "basis": "1", "matrix": [["A","0","0"],["0","A","0"],["0","0","C"]]},
     "symmetries": [{"kind": "revolution", "axis": "z1"}]},
    {"name": "rod", "frame": "1", "mass": "m", "centre": "G",
     "inertia": {"point": "G", "basis": "1",
                 "matrix": [["0","0","0"],["0","m*l^2/12","0"],["0","0","1/12*m*l^2"]]}},
    {"name": "rod_end", "frame": "1", "mass": "m", "centre": "G",
     "inertia": {"point": "E", "basis": "3",
                 "matrix": [["m*l^2/3*sin(phi)^2", "m*l^2/3*cos(phi)*sin(phi)", "0"],
                            ["m*l^2/3*cos(phi)*sin(phi)", "m*l^2/3*cos(phi)^2", "0"],
                            ["0", "0", "m*l^2/3"]]}}
  ]
}"#;

#[test]
fn solid_of_revolution_about_its_fixed_axis() {
    let m = model(ROTOR);
    let (c, w, acc) = (0.9, 2.3, -1.1);
    let s = sample(
        &[
            ("m", 2.0),
            ("a", 0.5),
            ("l", 1.0),
            ("A", 0.6),
            ("C", c),
            ("phi", 0.4),
        ],
        &[("th", [1.0, w, acc])],
    );
    // σ(O, S/0) = C ω z, δ = C ω̇ z.
    close(&vector(&m, "sigma(O0,disc/0)", &s), &[0.0, 0.0, c * w], TOL);
    close(
        &vector(&m, "delta(O0,disc/0)", &s),
        &[0.0, 0.0, c * acc],
        TOL,
    );
    close(&vector(&m, "Rd(disc/0)", &s), &[0.0; 3], TOL);
}

#[test]
fn thin_rod_spinning_off_centre() {
    let m = model(ROTOR);
    let (mass, a, l, w, acc, t) = (2.0, 0.5, 1.2, 2.3, -1.1, 0.3);
    let s = sample(
        &[
            ("m", mass),
            ("a", a),
            ("l", l),
            ("A", 0.6),
            ("C", 0.9),
            ("phi", 0.4),
        ],
        &[("th", [t, w, acc])],
    );
    // σ(O) = (m l²/12 + m a²) ω z0 for a rod of length l centred at a x1, along x1.
    let j = mass * l * l / 12.0 + mass * a * a;
    close(&vector(&m, "sigma(O0,rod/0)", &s), &[0.0, 0.0, j * w], TOL);
    close(
        &vector(&m, "delta(O0,rod/0)", &s),
        &[0.0, 0.0, j * acc],
        TOL,
    );
    // The same rod described by its inertia at its end E, in the basis B3 turned by phi
    // about z1: there x1 = cos phi x3 − sin phi y3 and I_E = (m l²/3)(Id − x1 x1ᵀ).
    let s_end = s.clone();
    close(
        &vector(&m, "sigma(O0,rod_end/0)", &s_end),
        &[0.0, 0.0, j * w],
        TOL,
    );
    let i_g = matrix(&m, "I(G,rod_end) in B1", &s_end);
    let k = mass * l * l / 12.0;
    close(
        &i_g.concat(),
        &[0.0, 0.0, 0.0, 0.0, k, 0.0, 0.0, 0.0, k],
        TOL,
    );
    // Rd = m Γ(G) = −m a ω² x1 + m a ω̇ y1.
    close(
        &vector(&m, "Rd(rod/0) in B1", &s),
        &[-mass * a * w * w, mass * a * acc, 0.0],
        TOL,
    );
}

#[test]
fn inertia_transported_and_rotated_numerically() {
    let m = model(ROTOR);
    let (mass, a, l) = (2.0, 0.5, 1.2);
    let s = sample(
        &[
            ("m", mass),
            ("a", a),
            ("l", l),
            ("A", 0.6),
            ("C", 0.9),
            ("phi", 0.4),
        ],
        &[("th", [0.7, 1.0, 0.0])],
    );
    // Huygens at O0: I_O = I_G + m (a² Id − a² x1 x1ᵀ) in B1.
    let io = matrix(&m, "I(O0,rod) in B1", &s);
    let k = mass * l * l / 12.0;
    let h = mass * a * a;
    close(
        &io.concat(),
        &[0.0, 0.0, 0.0, 0.0, k + h, 0.0, 0.0, 0.0, k + h],
        TOL,
    );
    // A set sums its solids.
    let both = matrix(&m, "I(O0,disc) in B1", &s);
    close(
        &both.concat(),
        &[0.6, 0.0, 0.0, 0.0, 0.6, 0.0, 0.0, 0.0, 0.9],
        TOL,
    );
}

/// Position of a point at the sample, ground components (through the internal state).
pub(super) fn v_pos(m: &NumericModel, s: &Sample, point: &str) -> [f64; 3] {
    let vals = values(m, s).expect("values");
    let st = state(m, &vals).expect("state");
    st.pos0(m.point_index[point]).into()
}

#[test]
fn sampled_inertia_is_read_back_exactly() {
    let m = model(REGULATOR);
    let s = m
        .sample(&mut ChaCha8Rng::seed_from_u64(42))
        .expect("sample");
    let p = &s.parameters;
    let i2 = matrix(&m, "I(G2,2) in B2", &s);
    let expected = [
        [p["A2"], -p["F2"], -p["E2"]],
        [-p["F2"], p["B2"], -p["D2"]],
        [-p["E2"], -p["D2"], p["C2"]],
    ];
    close(&i2.concat(), &expected.concat(), TOL);
    // A generic body: no product of inertia vanishes.
    for k in ["D1", "E1", "F1", "D2", "E2", "F2"] {
        assert!(p[k].abs() > 1e-6, "{k} = {}", p[k]);
    }
}

#[test]
fn cloud_reproduces_mass_centre_and_inertia() {
    let m = model(REGULATOR);
    for seed in 0..10 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let vals = values(&m, &s).expect("values");
        let st = state(&m, &vals).expect("state");
        for (solid, g, mass, names) in [
            (0, "G1", "m1", ["A1", "B1", "C1", "D1", "E1", "F1"]),
            (1, "G2", "m2", ["A2", "B2", "C2", "D2", "E2", "F2"]),
        ] {
            let pts = cloud::solid_cloud(&m, &st, &vals, solid).expect("cloud");
            let total: f64 = pts.iter().map(|p| p.0).sum();
            assert!((total - s.parameters[mass]).abs() < TOL * s.parameters[mass]);
            let frame = m.solids[solid].frame;
            let g_local = st.local0(frame, &st.pos0(m.point_index[g]));
            let centre: Vector3<f64> = pts.iter().map(|(mk, u)| u * (mk / total)).sum();
            close(centre.as_slice(), g_local.as_slice(), TOL);
            let rel: Vec<(f64, Vector3<f64>)> =
                pts.iter().map(|(mk, u)| (*mk, u - g_local)).collect();
            let i = la::rows(&cloud::cloud_inertia(&rel, &Vector3::zeros()));
            let p = |k: usize| s.parameters[names[k]];
            let expected = [
                [p(0), -p(5), -p(4)],
                [-p(5), p(1), -p(3)],
                [-p(4), -p(3), p(2)],
            ];
            close(&i.concat(), &expected.concat(), TOL);
        }
    }
}

#[test]
fn sampling_is_reproducible_and_valid() {
    let m = model(REGULATOR);
    let a = m.sample(&mut ChaCha8Rng::seed_from_u64(7)).expect("sample");
    let b = m.sample(&mut ChaCha8Rng::seed_from_u64(7)).expect("sample");
    let c = m.sample(&mut ChaCha8Rng::seed_from_u64(8)).expect("sample");
    assert_eq!(a, b);
    assert_ne!(a, c);
    let names: Vec<&str> = m.parameter_names().collect();
    assert_eq!(a.parameters.len(), names.len());
    for (k, v) in &a.parameters {
        assert!(v.is_finite(), "{k}");
    }
    for k in ["h1", "d1", "L1", "L2", "m1", "m2"] {
        assert!((0.5..=2.0).contains(&a.parameters[k]), "{k}");
    }
    for q in a.coordinates.values() {
        assert!((-std::f64::consts::PI..=std::f64::consts::PI).contains(&q[0]));
        assert!((-2.0..=2.0).contains(&q[1]) && (-2.0..=2.0).contains(&q[2]));
    }
    // Every quantity of the spec evaluates at many samples.
    let spec: SpecFile = serde_json::from_str(REGULATOR).expect("json");
    for seed in 0..20 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        for q in &spec.quantities {
            let q = Quantity::parse(q).expect("notation");
            m.evaluate(&q, &s, "0")
                .unwrap_or_else(|e| panic!("{q}: {e}"));
        }
    }
    assert!(matches!(
        m.sample_under(&mut ChaCha8Rng::seed_from_u64(1), "H9"),
        Err(NumericError::Unknown { .. })
    ));
}

#[test]
fn sampling_follows_the_written_matrix() {
    let m = model(ROTOR);
    for seed in 0..5 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let (a, c) = (s.parameters["A"], s.parameters["C"]);
        // A solid of revolution about z: 0 < A, C ≤ 2A (C = Jx + Jy, A = Jy + Jz).
        assert!(
            a > 0.0 && c > 0.0 && c <= 2.0 * a + 1e-12,
            "A = {a}, C = {c}"
        );
        // The written matrix is that of a real body.
        let i = matrix(&m, "I(O0,disc) in B1", &s);
        close(&i.concat(), &[a, 0.0, 0.0, 0.0, a, 0.0, 0.0, 0.0, c], TOL);
    }
    // B = 2 A is a flat body of revolution about y (a disc in the plane (x, z): A = C = Σ x²,
    // B = 2 Σ x²): read off such a cloud.
    let flat = ROTOR.replace(r#"["0","A","0"]"#, r#"["0","2*A","0"]"#);
    let m = model(&flat);
    let s = m
        .sample(&mut ChaCha8Rng::seed_from_u64(0))
        .expect("a flat disc");
    let (a, c) = (s.parameters["A"], s.parameters["C"]);
    let i = matrix(&m, "I(O0,disc) in B1", &s);
    close(
        &i.concat(),
        &[a, 0.0, 0.0, 0.0, 2.0 * a, 0.0, 0.0, 0.0, c],
        TOL,
    );
    // B = 3 A forces a ratio no symmetry gives: refused, naming the matrix.
    let bad = ROTOR.replace(r#"["0","A","0"]"#, r#"["0","3*A","0"]"#);
    let m = model(&bad);
    let e = m
        .sample(&mut ChaCha8Rng::seed_from_u64(0))
        .expect_err("B = 3 A cannot be read off a cloud");
    assert!(e.to_string().contains("\"3*A\""), "{e}");
    // An entry linear in a parameter of its own is solved for it: C + m a² read off the body
    // gives C = Jz − m a², so the written entry equals the body's.
    let sum = ROTOR.replace(r#"["0","0","C"]"#, r#"["0","0","C + m*a^2"]"#);
    let m = model(&sum);
    for seed in 0..5 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let (a, c, mass, arm) = (
            s.parameters["A"],
            s.parameters["C"],
            s.parameters["m"],
            s.parameters["a"],
        );
        let i = matrix(&m, "I(O0,disc) in B1", &s);
        close(
            &i.concat(),
            &[a, 0.0, 0.0, 0.0, a, 0.0, 0.0, 0.0, c + mass * arm * arm],
            TOL,
        );
    }
}

#[test]
fn imposed_rate_is_kept() {
    let json = ARM
        .replace(
            r#"{"name": "th", "kind": "angle"}"#,
            r#"{"name": "th", "kind": "angle", "rate": "2*w"}"#,
        )
        .replace(
            r#"{"name": "m", "unit": "kg"}"#,
            r#"{"name": "m", "unit": "kg"}, {"name": "w"}"#,
        );
    let m = model(&json);
    let s = m.sample(&mut ChaCha8Rng::seed_from_u64(3)).expect("sample");
    let t = s.coordinates["th"];
    assert_eq!(t[1], 2.0 * s.parameters["w"]);
    assert_eq!(t[2], 0.0);
    eval(&m, "V(P,1/0)", &s);
    let mut wrong = s.clone();
    wrong
        .coordinates
        .insert("th".into(), [t[0], t[1] + 1.0, 0.0]);
    let e = m
        .evaluate(&Quantity::parse("V(P,1/0)").expect("q"), &wrong, "0")
        .expect_err("contradicts the imposed rate");
    assert!(matches!(e, NumericError::Sample(_)), "{e}");
}

#[test]
fn impossible_bodies_are_refused() {
    let m = model(ROTOR);
    let q = Quantity::parse("sigma(O0,disc/0)").expect("q");
    let base = [
        ("m", 2.0),
        ("a", 0.5),
        ("l", 1.0),
        ("A", 0.6),
        ("C", 0.9),
        ("phi", 0.4),
    ];
    let with = |k: &str, v: f64| {
        let mut p = base.to_vec();
        for e in &mut p {
            if e.0 == k {
                e.1 = v;
            }
        }
        sample(&p, &[("th", [0.0, 1.0, 0.0])])
    };
    // C > 2A: one principal moment exceeds the sum of the other two.
    let e = m.evaluate(&q, &with("C", 1.3), "0").expect_err("C > A + B");
    assert!(
        matches!(&e, NumericError::NotPhysical { solid, .. } if solid == "disc"),
        "{e}"
    );
    let e = m.evaluate(&q, &with("m", -1.0), "0").expect_err("m < 0");
    assert!(matches!(e, NumericError::NotPhysical { .. }), "{e}");
    // Kinematics do not need the bodies.
    assert!(
        m.evaluate(
            &Quantity::parse("Omega(disc/0)").expect("q"),
            &with("C", 5.0),
            "0"
        )
        .is_ok()
    );
}

#[test]
fn sample_and_quantity_errors_name_the_object() {
    let m = model(REGULATOR);
    let s = regulator_sample([0.1, 0.2, 0.3], [0.4, 0.5, 0.6]);
    let err = |q: &str, s: &Sample| {
        m.evaluate(&Quantity::parse(q).expect("q"), s, "0")
            .expect_err("must fail")
            .to_string()
    };
    assert_eq!(err("V(Q,2/0)", &s), "unknown point `Q`");
    assert_eq!(err("Rc(7/0)", &s), "unknown solid or set `7`");
    assert_eq!(err("V(O2,2/0) in B9", &s), "unknown frame `9`");
    assert!(err("Omega(E/0)", &s).contains("`E` is a set"));
    let mut missing = s.clone();
    missing.parameters.remove("L2");
    assert_eq!(
        err("Omega(1/0)", &missing),
        "sample: missing parameter `L2`"
    );
    let mut extra = s.clone();
    extra.parameters.insert("L3".into(), 1.0);
    assert_eq!(err("Omega(1/0)", &extra), "sample: unknown parameter `L3`");
    let mut nan = s.clone();
    nan.coordinates
        .insert("theta1".into(), [f64::NAN, 0.0, 0.0]);
    assert!(err("Omega(1/0)", &nan).contains("theta1"));
}

#[test]
fn spec_errors_name_the_json_path() {
    let e = spec_error(
        r#"{"title": "t", "frames": [{"name": "1", "parent": "2"}, {"name": "2", "parent": "1"}]}"#,
    );
    assert!(e.to_string().contains("form a cycle through `1`"), "{e}");
    let e = spec_error(r#"{"title": "t", "points": [{"name": "P", "position": "L*x1"}]}"#);
    assert_eq!(
        e.to_string(),
        "spec, at points[0].position: unknown name `L`"
    );
    let e = spec_error(
        r#"{"title": "t", "parameters": [{"name": "L"}], "points": [{"name": "P", "position": "L"}]}"#,
    );
    assert!(e.to_string().contains("points[0].position"), "{e}");
    let e = spec_error(
        r#"{"title": "t", "parameters": [{"name": "L"}],
            "points": [{"name": "P", "position": "L*x0*x0"}]}"#,
    );
    assert!(e.to_string().contains("two basis vectors"), "{e}");
    let e = spec_error(
        r#"{"title": "t", "coordinates": [{"name": "q", "kind": "angle"}],
            "solids": [{"name": "1", "frame": "0", "mass": "q", "centre": "O0"}]}"#,
    );
    assert!(e.to_string().contains("solids[0].mass"), "{e}");
    let e = spec_error(
        r#"{"title": "t", "coordinates": [{"name": "q", "kind": "angle"}],
            "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "w", "angle": "q"}}]}"#,
    );
    assert!(e.to_string().contains("frames[0].rotation.axis"), "{e}");
}

#[test]
fn expression_syntax() {
    let m = model(
        r#"{"title": "t", "parameters": [{"name": "x"}, {"name": "L_2"}],
            "coordinates": [{"name": "q", "kind": "angle"}]}"#,
    );
    let s = sample(&[("x", 3.0), ("L_2", 0.5)], &[("q", [0.3, 2.0, -1.0])]);
    let ev = |t: &str| m.evaluate_expression(t, &s);
    let ok = |t: &str| ev(t).unwrap_or_else(|e| panic!("{t}: {e}"));
    assert_eq!(ok("-x^2"), -9.0);
    assert_eq!(ok("x^-1"), 1.0 / 3.0);
    assert_eq!(ok("x^(-2)"), 1.0 / 9.0);
    assert_eq!(ok("1/2*x"), 1.5);
    assert_eq!(ok("x - 1 - 1"), 1.0);
    assert_eq!(ok("2*(x + L_2)"), 7.0);
    assert_eq!(ok("12/x/2"), 2.0);
    assert_eq!(ok("0.25 * x"), 0.75);
    assert_eq!(ok("dot(q)^2 + ddot(q)"), 3.0);
    assert!((ok("sin(q)^2 + cos(q)^2") - 1.0).abs() < 1e-15);
    assert_eq!(ok("cos(2*q)"), (0.6f64).cos());
    // `pi` is π, as on the symbolic side.
    assert_eq!(ok("pi"), std::f64::consts::PI);
    assert_eq!(ok("x*pi/2"), 1.5 * std::f64::consts::PI);
    assert!((ok("cos(q + pi/2)") + (0.3f64).sin()).abs() < 1e-15);
    assert!((ok("sin(pi - q)") - (0.3f64).sin()).abs() < 1e-15);
    for bad in [
        "2x", "x^y", "x^2^2", "sin x", "tan(q)", "(x", "x)", "x +", "", "y", "dot(x)", "x;", "x1",
        "1/0", "pi(q)", "2pi", "dot(pi)",
    ] {
        assert!(ev(bad).is_err(), "`{bad}` must be refused");
    }
}

/// `pi` in a rotation angle and in a position: frame 1 is turned by θ + π/2 about z0, so
/// P = L x1 = L (−sin θ x0 + cos θ y0) and its velocity and acceleration follow; the dual parts
/// go through the constant.
#[test]
fn pi_in_angles_and_positions() {
    let m = model(
        r#"{"title": "t", "parameters": [{"name": "L", "unit": "m"}],
            "coordinates": [{"name": "theta2", "kind": "angle"}],
            "frames": [{"name": "1", "parent": "0",
                        "rotation": {"axis": "z", "angle": "theta2 + pi/2"}}],
            "points": [{"name": "P", "position": "L*x1"},
                       {"name": "Q", "position": "L*cos(theta2 + pi/2)*x0"}]}"#,
    );
    let (l, q, w, a) = (1.3, 0.7, -0.9, 0.4);
    let s = sample(&[("L", l)], &[("theta2", [q, w, a])]);
    let (c, sn) = (q.cos(), q.sin());
    close(&v_pos(&m, &s, "P"), &[-l * sn, l * c, 0.0], TOL);
    close(&v_pos(&m, &s, "Q"), &[-l * sn, 0.0, 0.0], TOL);
    close(
        &vector(&m, "V(P,1/0)", &s),
        &[-l * w * c, -l * w * sn, 0.0],
        TOL,
    );
    close(
        &vector(&m, "Gamma(P,1/0)", &s),
        &[
            -l * a * c + l * w * w * sn,
            -l * a * sn - l * w * w * c,
            0.0,
        ],
        TOL,
    );
    close(&vector(&m, "Omega(1/0)", &s), &[0.0, 0.0, w], TOL);
    // `pi` is reserved: no parameter or coordinate takes the name.
    let e = spec_error(r#"{"title": "t", "parameters": [{"name": "L"}, {"name": "pi"}]}"#);
    assert_eq!(
        e.to_string(),
        "spec, at parameters[1].name: `pi` is reserved by the expression syntax: it is the \
         constant π"
    );
    let e = spec_error(r#"{"title": "t", "coordinates": [{"name": "pi", "kind": "angle"}]}"#);
    assert!(e.to_string().contains("coordinates[0].name"), "{e}");
}

/// A joint at exactly q = 0 keeps its rates: the dual angle's real part is zero but not its
/// derivatives (nalgebra's `Rotation3::from_axis_angle` would return the identity there).
#[test]
fn a_joint_at_exactly_zero_keeps_its_rates() {
    let m = model(ARM);
    let (l, w, a) = (0.8, 1.3, -0.6);
    let s = sample(&[("L", l), ("m", 1.0)], &[("th", [0.0, w, a])]);
    close(&vector(&m, "V(P,1/0)", &s), &[0.0, l * w, 0.0], TOL);
    close(
        &vector(&m, "Gamma(P,1/0)", &s),
        &[-l * w * w, l * a, 0.0],
        TOL,
    );
    close(&vector(&m, "Omega(1/0)", &s), &[0.0, 0.0, w], TOL);
}

/// What the public documentation states of the float backend, at values other than the
/// examples' (where a wrong formula could still give the example's number), against results
/// worked out by hand: an error names the JSON path; an expression of the spec syntax is
/// evaluated; the weight's moment; a torsor's numbers list the resultant, then the moment.
#[test]
fn documented_behaviour_by_hand() {
    use std::f64::consts::PI;
    let e = spec_error(r#"{"title": "t", "frames": [{"name": "1", "parent": "7"}]}"#);
    assert_eq!(
        e.to_string(),
        "spec, at frames[0].parent: unknown frame `7` (declared: `0`, `1`)"
    );

    // m cos q q̇² + q̈ at m = 3, q = π/3, q̇ = 2, q̈ = 0.5: 3 · 1/2 · 4 + 1/2 = 6.5.
    let m = model(
        r#"{"title": "t", "parameters": [{"name": "m"}],
        "coordinates": [{"name": "q", "kind": "angle"}]}"#,
    );
    let s = sample(&[("m", 3.0)], &[("q", [PI / 3.0, 2.0, 0.5])]);
    let v = m
        .evaluate_expression("m*cos(q)*dot(q)^2 + ddot(q)", &s)
        .unwrap();
    assert!((v - 6.5).abs() < TOL, "{v}");

    // The weight −m g y0 at G = L x1: M(O, pes→1) = OG ∧ (−m g y0) = −m g L cos q z0, which is
    // −3 · 10 · 2 · 1/2 = −30 at q = π/3 (and does not depend on the rates).
    let m = model(
        r#"{"title": "arm", "ground_origin": "O",
        "parameters": [{"name": "L"}, {"name": "m"}, {"name": "g"}],
        "coordinates": [{"name": "q", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}}],
        "points": [{"name": "G", "position": "L*x1"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G"}],
        "gravity": "-g*y0"}"#,
    );
    let s = sample(
        &[("L", 2.0), ("m", 3.0), ("g", 10.0)],
        &[("q", [PI / 3.0, 0.7, -1.1])],
    );
    let q = Quantity::parse("M(O,pes->1)").unwrap();
    match m.evaluate_with(&q, &s, &Default::default(), "0").unwrap() {
        NumValue::Vector { value, .. } => close(&value, &[0.0, 0.0, -30.0], TOL),
        other => panic!("expected a vector, got {other:?}"),
    }

    // {D(1/0)}_O in B1 of the point mass at G: Rd = m Γ(G) = m (−L q̇² x1 + L q̈ y1),
    // δ(O) = OG ∧ m Γ(G) = m L² q̈ z1; numbered resultant first.
    let (l, mass, w, a) = (2.0, 3.0, 0.7, -1.1);
    let numbers = eval(&m, "{D(1/0)}_O in B1", &s).numbers();
    close(
        &numbers,
        &[
            -mass * l * w * w,
            mass * l * a,
            0.0,
            0.0,
            0.0,
            mass * l * l * a,
        ],
        TOL,
    );
}
