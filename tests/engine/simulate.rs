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
        .spec
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
        .spec
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
