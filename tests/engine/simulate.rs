//! The run-up simulation of the regulator: energy balance and the relative equilibrium.

use super::*;
use torseur::derivation::{Value, derive};
use torseur::output::{Values, numeric_point};
use torseur::quantity::Quantity;
use torseur::simulate::{simulate, simulate_with};

fn scalar(m: &Mechanism, q: &str) -> Expr {
    match derive(m, &Quantity::parse(q).unwrap()).unwrap().value {
        Value::Scalar(e) => e,
        other => panic!("{other:?}"),
    }
}

#[test]
fn work_of_the_motor_equals_the_change_of_energy_without_friction() {
    // Free flyweight, no friction: W(C_m) = ∫ C_m θ̇1 dt = ΔEc(E/0) + ΔEp (gravity), to within
    // the integrator's tolerance (rtol 1e-10).
    let m = regulator();
    let sc = m
        .spec()
        .scenarios
        .iter()
        .find(|s| s.name == "sans_frottement")
        .unwrap();
    assert_eq!(sc.values["f"], 0.0);
    let power = &scalar(&m, "C_m") * &ex(&m, "dot(theta1)");
    let run = simulate_with(&m, sc, &[("P_m".to_string(), power)]).unwrap();
    let work = *run.column("int(P_m)").unwrap().last().unwrap();
    let ec = scalar(&m, "Ec(E/0)");
    let ep = torseur::pfd::potential_energy(&m);
    let energy = |k: usize| {
        let mut coordinates = std::collections::BTreeMap::new();
        for q in ["theta1", "theta2"] {
            let v = run.column(q).unwrap()[k];
            let w = run.column(&format!("dot({q})")).unwrap()[k];
            coordinates.insert(q.to_string(), [v, w, 0.0]);
        }
        let point = numeric_point(
            &m,
            &Values {
                parameters: sc.values.clone(),
                coordinates,
                ..Default::default()
            },
        )
        .unwrap();
        ec.eval(&point) + ep.eval(&point)
    };
    let last = run.times.len() - 1;
    let change = energy(last) - energy(0);
    assert!(work > 1.0, "the run-up does work: {work}");
    assert!(
        ((work - change) / work).abs() < 1e-7,
        "W = {work}, ΔE = {change}"
    );
}

#[test]
fn with_friction_the_flyweight_settles_at_its_relative_equilibrium() {
    // At constant θ̇1 = ω, relative equilibrium of the flyweight (by hand, from the moment
    // theorem at O2 on x2 with θ̈2 = θ̇2 = 0):
    // ω² s [(C2 − B2) c + m2 L2 (L1 + L2 c)] + m2 g L2 c = 0, solved here by bisection.
    let m = regulator();
    let run = simulate(&m, "avec_frottement").unwrap();
    let sc = m
        .spec()
        .scenarios
        .iter()
        .find(|s| s.name == "avec_frottement")
        .unwrap();
    let v = |k: &str| sc.values[k];
    let w = 2000.0 * 2.0 * std::f64::consts::PI / 60.0;
    let f = |t: f64| {
        let (s, c) = t.sin_cos();
        w * w * s * ((v("C2") - v("B2")) * c + v("m2") * v("L2") * (v("L1") + v("L2") * c))
            + v("m2") * v("g") * v("L2") * c
    };
    let (mut a, mut b) = (-0.5f64, 0.5f64);
    assert!(f(a) < 0.0 && f(b) > 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (a + b);
        if f(mid) < 0.0 { a = mid } else { b = mid }
    }
    let theta2 = *run.column("theta2").unwrap().last().unwrap();
    assert!((theta2 - a).abs() < 1e-6, "end {theta2}, equilibrium {a}");
    // At constant speed and at rest relative to 1, no torque is needed.
    let cm = *run.column("C_m").unwrap().last().unwrap();
    assert!(cm.abs() < 1e-6, "C_m at the end: {cm}");
    // The flyweight's run-up needs less torque with friction than without.
    let free = simulate(&m, "sans_frottement").unwrap();
    assert!(run.max_abs("C_m").unwrap().0 < free.max_abs("C_m").unwrap().0);
}

#[test]
fn a_pendulum_on_an_incline_of_angle_parameter_conserves_its_energy() {
    // The incline α is a parameter of kind angle (cos α and sin α are set from its value).
    // No friction: Ec + Ep is constant, both written by hand with plain floats:
    // Ec = ½ (M + m) ẋ² + m l cos(θ − α) ẋ θ̇ + ½ (C2 + m l²) θ̇²,
    // Ep = (M + m) g x sin α − m g l cos θ (heights y0·OA = x sin α, y0·AG = −l cos θ).
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/pendule_plan_incline.json"
    ))
    .unwrap();
    let values: std::collections::BTreeMap<String, f64> = [
        ("M", 2.0),
        ("m", 0.5),
        ("l", 0.4),
        ("A2", 0.01),
        ("B2", 0.01),
        ("C2", 0.02),
        ("g", 9.81),
        ("alpha", 0.3),
    ]
    .into_iter()
    .map(|(k, v)| (k.to_string(), v))
    .collect();
    let sc = torseur::spec::wire::ScenarioSpec {
        name: "glisse".into(),
        description: None,
        label: None,
        duration: 1.0,
        values: values.clone(),
        initial: [
            ("x".to_string(), [0.0, 0.0]),
            ("theta".to_string(), [0.5, 0.0]),
        ]
        .into(),
        imposed: vec![],
        record: vec![],
    };
    let run = simulate_with(&m, &sc, &[]).unwrap();
    let v = |k: &str| values[k];
    let energy = |k: usize| {
        let col = |c: &str| run.column(c).unwrap()[k];
        let (x, xd, th, thd) = (col("x"), col("dot(x)"), col("theta"), col("dot(theta)"));
        let ec = 0.5 * (v("M") + v("m")) * xd * xd
            + v("m") * v("l") * (th - v("alpha")).cos() * xd * thd
            + 0.5 * (v("C2") + v("m") * v("l") * v("l")) * thd * thd;
        let ep =
            (v("M") + v("m")) * v("g") * x * v("alpha").sin() - v("m") * v("g") * v("l") * th.cos();
        ec + ep
    };
    let last = run.times.len() - 1;
    let x_end = run.column("x").unwrap()[last];
    assert!(x_end < -1.0, "the slider goes down the slope: x = {x_end}");
    let (e0, e1) = (energy(0), energy(last));
    assert!(
        (e1 - e0).abs() < 1e-7 * e0.abs().max(1.0),
        "E0 = {e0}, E1 = {e1}"
    );
}

/// The plots speak the course's notation: θ̇1 in tr/min, C_m in N·m, the scenario's label as
/// legend (issue 12, item 3).
#[test]
fn plots_are_labelled_in_the_course_notation() {
    let m = regulator();
    let run = simulate(&m, "sans_frottement").unwrap();
    assert_eq!(run.label, "sans frottement");
    let fig = torseur::simulate::figure(
        "t",
        &[(run.label.as_str(), &run)],
        &["theta2", "dot(theta1)", "C_m"],
        true,
    );
    let labels: Vec<&str> = fig.panels.iter().map(|p| p.y_label.as_str()).collect();
    assert_eq!(
        labels,
        ["θ₂ (°)", "θ\u{307}₁ (tr/min)", "Cₘ (N·m)"],
        "{labels:?}"
    );
    for p in &fig.panels {
        assert_eq!(p.series[0].name, "sans frottement");
    }
}

#[test]
fn a_forced_oscillator_settles_to_the_amplitude_of_the_course() {
    // M ẍ + c ẋ + k x = F0 cos(Ω t), from rest at x = 0: once the transient has died out
    // (e^(−c t / 2M) = e^(−5) at t = 40 s), |x| reaches F0 / √((k − M Ω²)² + (c Ω)²).
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/masse_ressort_forcee.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let (mass, k, c, f0, w): (f64, f64, f64, f64, f64) = (1.0, 100.0, 0.25, 1.0, 9.0);
    v["scenarios"] = serde_json::json!([{
        "name": "force", "duration": 60.0,
        "values": {"M": mass, "k": k, "c": c, "F0": f0, "Omega": w, "g": 9.81, "X": 0.0},
        "initial": {"x": [0.0, 0.0]}
    }]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let run = simulate(&m, "force").unwrap();
    // The phase Ω t is the time itself: no column of its own.
    let ids: Vec<&str> = run.columns.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(ids, ["x", "dot(x)"]);
    let late = run
        .times
        .iter()
        .zip(&run.columns[0].values)
        .filter(|(t, _)| **t > 40.0)
        .map(|(_, x)| x.abs())
        .fold(0.0, f64::max);
    let amplitude = f0 / ((k - mass * w * w).powi(2) + (c * w).powi(2)).sqrt();
    assert!(
        (late - amplitude).abs() < 0.01 * amplitude,
        "{late} vs {amplitude}"
    );
}
