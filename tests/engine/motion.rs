//! The equations of motion as M(q) q̈ + h(q, q̇, t) = Q(q, t) ([`EquationsOfMotion`]): a hand
//! derivation (the pendulum on a cart), the float backend on every spec of the library (its own
//! equations of motion, read column by column: they are linear in the accelerations), the
//! compiled evaluation against the exact entries, and the `Display` of derived values read back
//! by the spec's reader.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use torseur::numeric::{NumValue, NumericModel, Sample};
use torseur::output::{Values, numeric_point};
use torseur::pfd::EquationsOfMotion;
use torseur::quantity::Quantity;
use torseur::{Mechanism, derive};

fn cart() -> Mechanism {
    torseur::spec::from_str(
        r#"{"title": "Pendule sur chariot", "ground_origin": "O",
        "parameters": [{"name": "M", "unit": "kg"}, {"name": "m", "unit": "kg"},
            {"name": "l", "unit": "m"}, {"name": "A", "unit": "kg m^2"},
            {"name": "B", "unit": "kg m^2"}, {"name": "J", "unit": "kg m^2"},
            {"name": "g", "unit": "m/s^2"}, {"name": "F", "unit": "N"}],
        "coordinates": [{"name": "x", "kind": "length"}, {"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "origin": "A"},
            {"name": "2", "parent": "1", "rotation": {"axis": "z", "angle": "theta"}, "origin": "A"}],
        "points": [{"name": "A", "position": "x*x0"}, {"name": "G", "from": "A", "position": "-l*y2"}],
        "solids": [{"name": "1", "frame": "1", "mass": "M", "centre": "A"},
            {"name": "2", "frame": "2", "mass": "m", "centre": "G",
             "inertia": {"point": "G", "basis": "2", "matrix": [["A", "0", "0"], ["0", "B", "0"], ["0", "0", "J"]]}}],
        "sets": {"E": ["1", "2"]},
        "gravity": "-g*y0",
        "links": [{"name": "01", "kind": "slider", "between": ["0", "1"], "point": "A", "axis": "x0"},
            {"name": "12", "kind": "pivot", "between": ["1", "2"], "point": "A", "axis": "z0"}],
        "actions": [{"name": "poussee", "from": "0", "on": "1", "point": "A", "resultant": "F*x0"}],
        "pfd": [{"isolate": "E", "theorem": "resultant", "on": "x0", "eom": "x"},
            {"isolate": "2", "theorem": "moment", "point": "A", "on": "z0", "eom": "theta"}]}"#,
    )
    .expect("the cart loads")
}

#[test]
fn the_pendulum_on_a_cart_splits_as_derived_by_hand() {
    // By hand (Lagrange, T = ½ (M + m) ẋ² + m l ẋ θ̇ cos θ + ½ (J + m l²) θ̇², V = −m g l cos θ):
    //   (M + m) ẍ + m l cos θ θ̈ − m l sin θ θ̇² = F,
    //   m l cos θ ẍ + (J + m l²) θ̈ = −m g l sin θ.
    let m = cart();
    let eq = EquationsOfMotion::of(&m).unwrap();
    let e = |s: &str| crate::ex(&m, s);
    assert_eq!(eq.coordinates(), ["x", "theta"]);
    assert_eq!(eq.mass[0][0], e("M + m"));
    assert_eq!(eq.mass[0][1], e("m*l*cos(theta)"));
    assert_eq!(eq.mass[1][0], e("m*l*cos(theta)"));
    assert_eq!(eq.mass[1][1], e("J + m*l^2"));
    assert_eq!(eq.velocity_terms[0], e("-m*l*sin(theta)*dot(theta)^2"));
    assert!(eq.velocity_terms[1].is_zero());
    assert_eq!(eq.forces[0], e("F"));
    assert_eq!(eq.forces[1], e("-m*g*l*sin(theta)"));
    // The engine's own eom(q), rebuilt.
    for (i, q) in ["eom(x)", "eom(theta)"].iter().enumerate() {
        let d = derive(&m, &Quantity::parse(q).unwrap()).unwrap();
        assert_eq!(&eq.residual(i), d.value.exprs()[0], "{q}");
    }
    let text = eq.to_string();
    assert_eq!(
        text,
        "x: (M + m)*ddot(x) + m*l*cos(theta)*ddot(theta) - m*l*dot(theta)^2*sin(theta) = F\n\
         theta: m*l*cos(theta)*ddot(x) + (J + m*l^2)*ddot(theta) = -m*g*l*sin(theta)\n"
    );
}

/// The float backend's eom(q) at a sample whose accelerations (and, for `rest`, rates) are
/// replaced, its inputs (a motor torque the equations of motion hold) at `inputs`.
fn float_eom(model: &NumericModel, s: &Sample, q: &str, inputs: &BTreeMap<String, f64>) -> f64 {
    let v = model
        .evaluate_with(
            &Quantity::parse(&format!("eom({q})")).unwrap(),
            s,
            inputs,
            "0",
        )
        .unwrap_or_else(|e| panic!("eom({q}): {e}"));
    match v {
        NumValue::Scalar(x) => x,
        other => panic!("eom({q}) is {other:?}"),
    }
}

#[test]
fn every_library_split_agrees_with_the_float_backend() {
    // The float backend's equations are linear in the accelerations: its Mᵢⱼ is eom(qᵢ) at
    // q̈ = eⱼ minus eom(qᵢ) at q̈ = 0; its Q is −eom at rest (every rate and acceleration 0);
    // its h is eom at q̈ = 0 plus Q.
    let mut seen = 0;
    for path in crate::specs_in(&["derivations"]) {
        let m = torseur::spec::load(&path).unwrap();
        let Ok(eq) = EquationsOfMotion::of(&m) else {
            continue;
        };
        // A loop, a rolling condition or a gear ties a dependent coordinate's acceleration to
        // the free ones, and a sample cannot move one acceleration alone: only specs whose
        // every coordinate has its equation or an imposed rate (a rate written with another
        // coordinate's is a gear's: dependent).
        let independent = m.spec().coordinates.iter().all(|c| {
            let imposed = c.rate.as_deref().is_some_and(|r| !r.contains("dot("));
            imposed || eq.coordinates().contains(&c.name.as_str())
        });
        // Coulomb's law on a contact's unknowns: its sign ε follows the sliding velocity, which
        // the float backend sets from each sample's rates (none at rest).
        let sliding = m.spec().links.iter().any(|l| l.contact_friction.is_some());
        if eq.mass.is_empty() || !independent || sliding {
            continue;
        }
        seen += 1;
        let model = NumericModel::new(m.spec()).unwrap();
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let names = eq.coordinates();
        // The inputs of the equations of motion (the robot's motor torques): random values,
        // the same on both sides.
        let inputs: BTreeMap<String, f64> = (torseur::pfd::solve(&m).unwrap().inputs.iter())
            .map(|n| (n.clone(), rng.random_range(-2.0..2.0)))
            .collect();
        for _ in 0..3 {
            let s = model.sample(&mut rng).unwrap();
            let mut zero_acc = s.clone();
            for n in &names {
                zero_acc.coordinates.get_mut(*n).unwrap()[2] = 0.0;
            }
            // At rest: every rate the spec does not impose (an imposed ω is a parameter).
            let mut rest = s.clone();
            for c in m.spec().coordinates.iter().filter(|c| c.rate.is_none()) {
                if let Some(v) = rest.coordinates.get_mut(&c.name) {
                    v[1] = 0.0;
                    v[2] = 0.0;
                }
            }
            let values = |s: &Sample| Values {
                parameters: s.parameters.clone(),
                coordinates: s.coordinates.clone(),
                unknowns: inputs.clone(),
                time: Some(s.time),
            };
            let point = numeric_point(&m, &values(&s)).unwrap();
            let rest_point = numeric_point(&m, &values(&rest)).unwrap();
            let close = |a: f64, b: f64, what: &str| {
                assert!(
                    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs())),
                    "{}: {what}: exact {a} float {b}",
                    path.display()
                )
            };
            for (i, qi) in names.iter().enumerate() {
                let base = float_eom(&model, &zero_acc, qi, &inputs);
                for (j, qj) in names.iter().enumerate() {
                    let mut unit = zero_acc.clone();
                    unit.coordinates.get_mut(*qj).unwrap()[2] = 1.0;
                    let mij = float_eom(&model, &unit, qi, &inputs) - base;
                    close(eq.mass[i][j].eval(&point), mij, &format!("M[{qi}][{qj}]"));
                }
                let q = -float_eom(&model, &rest, qi, &inputs);
                close(eq.forces[i].eval(&point), q, &format!("Q[{qi}]"));
                close(
                    eq.forces[i].eval(&rest_point),
                    q,
                    &format!("Q[{qi}] at rest"),
                );
                close(
                    eq.velocity_terms[i].eval(&point),
                    base + q,
                    &format!("h[{qi}]"),
                );
            }
        }
    }
    assert!(seen >= 8, "only {seen} specs with equations of motion");
    eprintln!("{seen} specs split as the float backend does");
}

#[test]
fn compiled_accelerations_solve_the_exact_entries() {
    // The compiled evaluator (symbolica's instruction list) against the exact entries
    // evaluated term by term, solved by hand for two coordinates (Cramer's rule).
    let m = cart();
    let eq = EquationsOfMotion::of(&m).unwrap();
    let mut c = eq.compile().unwrap();
    let values = Values::parse(
        r#"{"parameters": {"M": 3, "m": 1.5, "l": 0.7, "A": 0.2, "B": 0.3, "J": 0.25,
            "g": 9.81, "F": 2}, "coordinates": {"x": [0.1, 0.4, 0], "theta": [0.9, -1.3, 0]}}"#,
    )
    .unwrap();
    let p = numeric_point(&m, &values).unwrap();
    let (a, b) = (eq.mass[0][0].eval(&p), eq.mass[0][1].eval(&p));
    let (c2, d) = (eq.mass[1][0].eval(&p), eq.mass[1][1].eval(&p));
    let r0 = eq.forces[0].eval(&p) - eq.velocity_terms[0].eval(&p);
    let r1 = eq.forces[1].eval(&p) - eq.velocity_terms[1].eval(&p);
    let det = a * d - b * c2;
    let (x, th) = ((r0 * d - b * r1) / det, (a * r1 - c2 * r0) / det);
    let acc = c.accelerations(&p).unwrap();
    assert!(
        (acc[0] - x).abs() < 1e-12 && (acc[1] - th).abs() < 1e-12,
        "{acc} vs {x}, {th}"
    );
    // And by the formulas themselves: with l = 0.7, the numbers of the hand derivation.
    let (mm, ml, l, j, g, f) = (3.0, 1.5, 0.7, 0.25, 9.81, 2.0);
    let (q, w) = (0.9_f64, -1.3_f64);
    let a2 = [
        [mm + ml, ml * l * q.cos()],
        [ml * l * q.cos(), j + ml * l * l],
    ];
    let rhs = [f + ml * l * q.sin() * w * w, -ml * g * l * q.sin()];
    let det2 = a2[0][0] * a2[1][1] - a2[0][1] * a2[1][0];
    let x2 = (rhs[0] * a2[1][1] - a2[0][1] * rhs[1]) / det2;
    assert!((acc[0] - x2).abs() < 1e-12, "{} vs {x2}", acc[0]);
}

#[test]
fn displayed_vectors_and_torsors_read_back_to_the_same_value() {
    // Every vector and torsor the library's specs ask for, shown, then read by the spec's own
    // vector reader (which shares no code with the printer) and compared exactly.
    let mut checked = 0;
    for path in crate::specs_in(&["derivations"]) {
        let m = torseur::spec::load(&path).unwrap();
        let axis = |n: &str| {
            let k = "xyz".find(n.get(..1)?)?;
            Some((m.frames().find(n.get(1..)?)?, k))
        };
        for q in m.quantities() {
            let Ok(d) = derive(&m, q) else { continue };
            let shown = d.value.display(&m).to_string();
            let read = |text: &str| -> Vec<_> {
                m.reg()
                    .parse_vector(text, &axis)
                    .unwrap_or_else(|e| panic!("{}: {q}: `{text}`: {e}", path.display()))
            };
            let same = |text: &str, basis, c: &[torseur::Expr; 3]| {
                let parts = read(text);
                let zero = m.reg().zero();
                for k in 0..3 {
                    let got = parts
                        .iter()
                        .find(|(b, _)| *b == basis)
                        .map_or(&zero, |(_, v)| &v[k]);
                    assert_eq!(got, &c[k], "{}: {q}: `{text}`", path.display());
                }
                assert!(parts.iter().all(|(b, _)| *b == basis), "{text}");
            };
            match &d.value {
                torseur::Value::Vector { basis, components } => {
                    same(&shown, *basis, components);
                    checked += 1;
                }
                torseur::Value::Torsor {
                    point,
                    basis,
                    resultant,
                    moment,
                } => {
                    let inner = shown
                        .strip_prefix("{ R = ")
                        .and_then(|s| s.strip_suffix(" }"))
                        .unwrap();
                    let sep = format!(", M({}) = ", m.point_name(*point));
                    let (r, mo) = inner.split_once(&sep).unwrap();
                    same(r, *basis, resultant);
                    same(mo, *basis, moment);
                    checked += 1;
                }
                _ => {}
            }
        }
    }
    assert!(checked >= 20, "only {checked} vectors and torsors");
}
