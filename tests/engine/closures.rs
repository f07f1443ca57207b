//! Loop closures (issue 16, item 1): the crank–slider's loop law and dynamics by hand and
//! by Lagrange's equations, and bad closures refused by both sides with their place.

use super::*;

fn crank_slider() -> serde_json::Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/bielle_manivelle.json"
    ))
    .unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn the_crank_slider_loop_law_by_hand() {
    // OA + AB + BO = 0 on y0: R sin θ + L sin φ = 0, so R cos θ θ̇ + L cos φ φ̇ = 0 and
    // φ̇ = −R θ̇ cos θ / (L cos φ). On x0: ẋ = −R θ̇ sin θ − L φ̇ sin φ
    // = −R θ̇ sin(θ − φ) / cos φ, the piston's speed.
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    torseur::assert_equivalent!(m, "Omega(2/0)", "-R*dot(theta)*cos(theta)/(L*cos(phi))*z0");
    torseur::assert_equivalent!(
        m,
        "V(B,3/0)",
        "-R*dot(theta)*(sin(theta)*cos(phi) - cos(theta)*sin(phi))/cos(phi)*x0"
    );
    // The rates of the dependent coordinates are those forms, and q̈ their derivatives.
    let reg = m.reg();
    let phi = reg.coord("phi").unwrap();
    assert!(reg.coord_info(phi).is_driven() && reg.coord_info(phi).is_holonomic());
    assert_eq!(
        reg.dot(phi),
        ex(&m, "-R*dot(theta)*cos(theta)/(L*cos(phi))")
    );
    // (1/cos φ) cos φ = 1 exactly, and the wrong sign is caught.
    assert!((&ex(&m, "1/cos(phi)") * &ex(&m, "cos(phi)")).is_one());
    let wrong = torseur::verify::verify(
        &m,
        "Omega(2/0)",
        "R*dot(theta)*cos(theta)/(L*cos(phi))*z0",
        None,
    )
    .unwrap();
    assert!(!wrong.is_equivalent());
}

#[test]
fn the_crank_slider_equivalent_inertia_by_hand() {
    // Ec = ½ J1 θ̇² + ½ m2 V(G2)² + ½ (m2 L²/12) φ̇² + ½ m3 ẋ², with
    // V(G2) = θ̇ (−R sin θ + (R/2) cos θ tan φ, (R/2) cos θ) from V(A) + Ω ∧ AG2.
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    torseur::assert_equivalent!(
        m,
        "J_eq(theta)",
        "J1 + m2*((-R*sin(theta) + R/2*cos(theta)*sin(phi)/cos(phi))^2 + R^2/4*cos(theta)^2) \
         + m2*R^2/12*cos(theta)^2/cos(phi)^2 \
         + m3*R^2*(sin(theta) - cos(theta)*sin(phi)/cos(phi))^2"
    );
    // The gas pushes the piston back: P = C_m θ̇ − F ẋ.
    torseur::assert_equivalent!(
        m,
        "P(ext->E/0)",
        "C_m*dot(theta) - F*(-R*dot(theta)*(sin(theta) - cos(theta)*sin(phi)/cos(phi)))"
    );
    torseur::assert_equivalent!(m, "Pint(E)", "0");
}

#[test]
fn the_crank_slider_equation_of_motion_is_lagranges() {
    // The PFD (piston, rod, crank; the links' unknowns eliminated through the pivot L cos φ)
    // and Lagrange's equation of θ (energies and virtual powers, following φ(θ) and x(θ)
    // through their rates) are one equation: a second route of other code.
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    let sol = torseur::pfd::solve(&m).unwrap();
    let theta = m.reg().coord("theta").unwrap();
    let lagrange = torseur::pfd::lagrange(&m, theta);
    let eom = &sol.eom["theta"];
    assert!(
        (eom - &lagrange).is_zero() || (eom + &lagrange).is_zero(),
        "{eom}\n{lagrange}"
    );
    // Its θ̈ coefficient is the equivalent inertia.
    let jeq = torseur::derivation::derive(
        &m,
        &torseur::quantity::Quantity::parse("J_eq(theta)").unwrap(),
    )
    .unwrap();
    let torseur::derivation::Value::Scalar(j) = jeq.value else {
        panic!("J_eq is a scalar")
    };
    assert_eq!(eom.partial_rate(theta, 2), j);
    // The pivot L cos φ is stated as a condition of the solution.
    assert!(sol.conditions.iter().any(|c| *c == ex(&m, "L*cos(phi)")));
}

#[test]
fn bad_closures_are_refused_by_both_sides_with_their_place() {
    // Without its closure, the slide closes a loop.
    let mut v = crank_slider();
    v.as_object_mut().unwrap().remove("closures");
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[3].between") && e.contains("kinematic loop"),
        "{e}"
    );
    assert!(f.contains("links[3].between"), "{f}");
    // One dependent coordinate for two relations.
    let mut v = crank_slider();
    v["closures"][0]["dependent"] = serde_json::json!(["phi"]);
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("closures[0].vector") && e.contains("2 scalar relations"),
        "{e}"
    );
    assert!(f.contains("closures[0].vector"), "{f}");
    // A dependent coordinate with a rate of its own.
    let mut v = crank_slider();
    v["coordinates"][1]["rate"] = "dot(theta)".into();
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("closures[0].dependent[0]") && e.contains("rate of its own"),
        "{e}"
    );
    assert!(f.contains("closures[0].dependent[0]"), "{f}");
    // An imposed rate on the free coordinate, and lin(…), are not available with a closure.
    let mut v = crank_slider();
    v["coordinates"][0]["rate"] = "omega".into();
    v["parameters"]
        .as_array_mut()
        .unwrap()
        .push(serde_json::json!({"name": "omega", "unit": "rad/s"}));
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("coordinates[0].rate") && e.contains("free rates only"),
        "{e}"
    );
    assert!(f.contains("coordinates[0].rate"), "{f}");
    let mut v = crank_slider();
    v["small"] = serde_json::json!([{"coordinate": "theta", "around": "0"}]);
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let e = torseur::spec::build(&file).unwrap_err().to_string();
    assert!(e.contains("small[0]") && e.contains("loop closures"), "{e}");
    // An unknown coordinate.
    let mut v = crank_slider();
    v["closures"][0]["dependent"][1] = "y".into();
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("closures[0].dependent[1]") && e.contains("`y`"),
        "{e}"
    );
    assert!(f.contains("closures[0].dependent[1]"), "{f}");
    // A component without coordinate: the loop cannot close.
    let mut v = crank_slider();
    v["closures"][0]["vector"] = "R*x1 + L*x2 - x*x0 + L*z0".into();
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("closures[0].vector") && e.contains("does not close"),
        "{e}"
    );
    assert!(f.contains("closures[0].vector"), "{f}");
    // Relations that do not hold a dependent rate (φ̇ appears in neither).
    let mut v = crank_slider();
    v["closures"][0]["vector"] = "(R*cos(theta) - x)*x0 + (R*cos(theta) - x)*y0".into();
    let (e, f) = refused_by_both(&v);
    assert!(e.contains("do not hold the rate of `phi`"), "{e}");
    assert!(f.contains("redundant"), "{f}");
    // Redundant relations: the same relation twice.
    let mut v = crank_slider();
    v["closures"][0]["vector"] =
        "(R*cos(theta) + L*cos(phi) - x)*x0 + (R*cos(theta) + L*cos(phi) - x)*y0".into();
    let (e, f) = refused_by_both(&v);
    assert!(e.contains("redundant"), "{e}");
    assert!(f.contains("redundant"), "{f}");
}

#[test]
fn a_loop_that_cannot_close_is_found_by_the_float_backend() {
    // The exact side reads only the closure's derivative: a constant offset of 10 L on y0
    // changes no rate. The float backend, which places the loop, finds it cannot close
    // (|R sin θ + L sin φ| ≤ R + L < 10 L for the drawn lengths) and says so.
    let mut v = crank_slider();
    v["closures"][0]["vector"] = "R*x1 + L*x2 - x*x0 + 10*L*y0".into();
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let model = torseur::numeric::NumericModel::new(&file).unwrap();
    use rand::SeedableRng;
    let e = model
        .sample(&mut rand_chacha::ChaCha8Rng::seed_from_u64(1))
        .unwrap_err()
        .to_string();
    assert!(e.contains("does not close"), "{e}");
}

#[test]
fn the_four_bar_linkage_by_hand() {
    // The loop's derivative L1 θ̇1 y1 + L2 ω2 y2 + L3 ω3 y3 = 0 (ω2 = θ̇1 + α̇, ω3 = ω2 + ψ̇)
    // dotted with x2 (y1·x2 = sin α, y3·x2 = −sin ψ) gives ω3 = L1 θ̇1 sin α / (L3 sin ψ);
    // with x3 (y1·x3 = sin(α + ψ), y2·x3 = sin ψ), ω2 = −L1 θ̇1 sin(α + ψ) / (L2 sin ψ).
    let m = torseur::spec::load("derivations/quadrilatere_articule.json").unwrap();
    torseur::assert_equivalent!(
        m,
        "Omega(3/0)",
        "L1*dot(theta1)*sin(alpha)/(L3*sin(psi))*z0"
    );
    torseur::assert_equivalent!(
        m,
        "Omega(2/0)",
        "-L1*dot(theta1)*(sin(alpha)*cos(psi) + cos(alpha)*sin(psi))/(L2*sin(psi))*z0"
    );
    // König: the crank about O, the coupler V(G2) = L1 θ̇1 y1 + (L2/2) ω2 y2 (y1·y2 = cos α)
    // with m2 L2²/12, the rocker about C with m3 L3²/3; with r2 = ω2/θ̇1, r3 = ω3/θ̇1,
    // J_eq = J1 + m2 L1² + m2 L2² r2²/3 + m2 L1 L2 r2 cos α + m3 L3² r3²/3.
    let r2 = "(-L1*(sin(alpha)*cos(psi) + cos(alpha)*sin(psi))/(L2*sin(psi)))";
    let r3 = "(L1*sin(alpha)/(L3*sin(psi)))";
    torseur::assert_equivalent!(
        m,
        "J_eq(theta1)",
        &format!("J1 + m2*L1^2 + m2*L2^2*{r2}^2/3 + m2*L1*L2*{r2}*cos(alpha) + m3*L3^2*{r3}^2/3")
    );
    // The resisting torque's power through the loop law; the perfect pivots do no work.
    torseur::assert_equivalent!(
        m,
        "P(ext->E/0)",
        "C_m*dot(theta1) - C_r*L1*dot(theta1)*sin(alpha)/(L3*sin(psi))"
    );
    torseur::assert_equivalent!(m, "Pint(E)", "0");
    // The sine a closure divides by turns the angle's rule: cos²ψ → 1 − sin²ψ.
    let psi = m.reg().coord("psi").unwrap();
    assert!((&ex(&m, "1/sin(psi)") * &m.reg().sin(psi)).is_one());
    // Under sin²ψ → 1 − cos²ψ with 1/sin ψ, cos²ψ/sin ψ and 1/sin ψ − sin ψ would be two
    // canonical forms of one value; under the turned rule they are one.
    assert_eq!(
        ex(&m, "cos(psi)^2/sin(psi)"),
        ex(&m, "1/sin(psi) - sin(psi)")
    );
    // The PFD (rocker, coupler, crank; pivots L3 and L2 sin ψ) and Lagrange agree.
    let sol = torseur::pfd::solve(&m).unwrap();
    let theta1 = m.reg().coord("theta1").unwrap();
    let lagrange = torseur::pfd::lagrange(&m, theta1);
    let eom = &sol.eom["theta1"];
    assert!((eom - &lagrange).is_zero() || (eom + &lagrange).is_zero());
    assert!(sol.conditions.iter().any(|c| *c == ex(&m, "L2*sin(psi)")));
}

#[test]
fn a_loop_determinant_that_is_not_a_product_is_refused_by_name() {
    // The four-bar with absolute angles: the determinant L2 L3 sin(α − ψ) is a sum in the
    // canonical form, which cannot be inverted exactly; the message says which angles work.
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/quadrilatere_articule.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["frames"][1]["parent"] = "0".into();
    v["frames"][2]["parent"] = "0".into();
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let e = torseur::spec::build(&file).unwrap_err().to_string();
    assert!(
        e.starts_with("at closures:") && e.contains("not supported yet"),
        "{e}"
    );
}

#[test]
fn the_crank_slider_runs_up_on_its_loop_and_the_work_is_the_energy() {
    // The motor's torque against the gas from rest at θ = 0 (then φ = 0, x = R + L). The
    // dependent coordinates are integrated from their rates: they stay on the loop (checked
    // here from the columns, R sin θ + L sin φ = 0 and x = R cos θ + L cos φ, and by the
    // drift simulate reports), and the work of the external actions is the change of Ec
    // (the pivots and the slide do no work).
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    let sc: torseur::wire::ScenarioSpec = serde_json::from_value(serde_json::json!({
        "name": "demarrage",
        "duration": 0.4,
        "values": {"J1": 0.02, "A1": 0.01, "m1": 1.0, "m2": 0.5, "m3": 0.8,
                   "R": 0.05, "L": 0.2, "C_m": 2.0, "F": 10.0},
        "initial": {"theta": [0.0, 0.0], "phi": [0.0, 0.0], "x": [0.25, 0.0]}
    }))
    .unwrap();
    let all: Vec<_> = m
        .bodies()
        .iter()
        .flat_map(|b| m.solids_of(&b.name).unwrap())
        .collect();
    let p = torseur::pfd::power(&m, "ext", &all, "all", m.frames().ground()).unwrap();
    let run = torseur::simulate::simulate_with(&m, &sc, &[("P".to_string(), p)]).unwrap();
    let last = run.times.len() - 1;
    let col = |c: &str| run.column(c).unwrap()[last];
    let (theta, phi, x) = (col("theta"), col("phi"), col("x"));
    assert!(theta > 3.0, "the crank turns: θ = {theta}");
    assert!((0.05 * theta.sin() + 0.2 * phi.sin()).abs() < 1e-8);
    assert!((x - 0.05 * theta.cos() - 0.2 * phi.cos()).abs() < 1e-8);
    let drift = run.drift.expect("a closure's drift");
    assert!(drift < 1e-8, "drift {drift:e}");
    let ec = torseur::pfd::kinetic_energy(&m, &all);
    let energy = |k: usize| {
        let mut coordinates = std::collections::BTreeMap::new();
        for q in ["theta", "phi", "x"] {
            let v = run.column(q).unwrap()[k];
            let w = run.column(&format!("dot({q})")).unwrap()[k];
            coordinates.insert(q.to_string(), [v, w, 0.0]);
        }
        let point = torseur::output::numeric_point(
            &m,
            &torseur::output::Values {
                parameters: sc.values.clone(),
                coordinates,
                ..Default::default()
            },
        )
        .unwrap();
        ec.eval(&point)
    };
    let work = col("int(P)");
    assert!(work > 0.1, "the motor does work: {work}");
    let change = energy(last) - energy(0);
    assert!(
        ((work - change) / work).abs() < 1e-7,
        "W = {work}, ΔEc = {change}"
    );
    // Initial values off the loop are refused, naming the dependent coordinates.
    let mut off = sc.clone();
    off.initial.insert("x".into(), [0.3, 0.0]);
    let e = torseur::simulate::simulate_with(&m, &off, &[])
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("do not close the loop") && e.contains("phi, x"),
        "{e}"
    );
}

#[test]
fn both_new_problems_agree_with_the_float_backend_quantity_by_quantity() {
    // The float backend places each sample on the loop by Newton's method and its rates and
    // accelerations by least squares, from its own frames; every requested quantity (the
    // unknowns of the links and the equations of motion, which read the accelerations,
    // included) must agree to 1e-9.
    for file in [
        "derivations/bielle_manivelle.json",
        "derivations/quadrilatere_articule.json",
    ] {
        let m = torseur::spec::load(file).unwrap();
        let mut qs = m.quantities().to_vec();
        let eom = m.spec().pfd.iter().filter_map(|t| t.eom.clone());
        qs.extend(eom.map(|q| torseur::quantity::Quantity::parse(&format!("eom({q})")).unwrap()));
        for q in &qs {
            let v = torseur::derivation::derive(&m, q).unwrap().value;
            let w = super::check::worst_seeded(&m, &q.to_string(), &v, 7);
            assert!(w < 1e-9, "{file}: {q}: {w:e}");
        }
    }
}
