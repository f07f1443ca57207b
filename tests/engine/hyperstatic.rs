//! Hyperstatic mechanisms (issue 37): declared equations that fix two link unknowns only
//! through their sum. The shaft of `derivations/arbre_deux_rotules.json` turns at ω about
//! (A, z0) on two ball joints A and B (AB = L z0), G at a x1 + c z0, products of inertia
//! D1, E1 at G, weight −m g z0. Derived by hand in B1 (θ̈ = 0):
//! - Γ(G) = −a ω² x1; σ(G) = ω (−E1 x1 − D1 y1 + C1 z1), so δ(G) = ω z1 ∧ σ(G) =
//!   ω² (D1 x1 − E1 y1); AG ∧ m Γ(G) = −m a c ω² y1: δ(A) = D1 ω² x1 − (E1 + m a c) ω² y1.
//! - Moments at A: B's force gives L z1 ∧ (X_B x1 + Y_B y1) = L X_B y1 − L Y_B x1, the
//!   weight a x1 ∧ (−m g z1) = m g a y1, the motor C_m z1.
//! - So Y_B = −D1 ω²/L, X_B = −((g + c ω²) m a + E1 ω²)/L, C_m = 0; the resultant gives
//!   X_A = −m a ω² − X_B, Y_A = −Y_B, and on z1 only Z_A + Z_B = m g: seven unknowns, six
//!   independent equations, hyperstatic of degree 1.

use torseur::derivation::{Value, derive};
use torseur::pfd::{PfdError, solve};
use torseur::quantity::Quantity;

fn shaft() -> torseur::mechanism::Mechanism {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    torseur::spec::load(root.join("derivations/arbre_deux_rotules.json")).unwrap()
}

#[test]
fn the_shaft_on_two_ball_joints_gives_what_it_determines_by_hand() {
    let m = shaft();
    let e = |s: &str| m.reg().parse(s).unwrap();
    // Each value times L, by hand.
    for (q, hand) in [
        ("Y_B", "-D1*omega^2"),
        ("X_B", "-(m*g*a + m*a*c*omega^2 + E1*omega^2)"),
        ("Y_A", "D1*omega^2"),
        ("X_A", "-m*a*omega^2*L + m*g*a + m*a*c*omega^2 + E1*omega^2"),
        ("C_m", "0"),
    ] {
        let d = derive(&m, &Quantity::parse(q).unwrap()).unwrap();
        // A quotient n/d by a pivot (the length L): n L = hand × d, exactly.
        let (num, den) = match &d.value {
            Value::Scalar(v) => (v.clone(), e("1")),
            Value::Quotient(f) => (f.num.clone(), f.den.clone()),
            other => panic!("{q} is a scalar: {other:?}"),
        };
        assert_eq!(&num * &e("L"), &e(hand) * &den, "{q}");
    }
    let s = solve(&m).unwrap();
    let h = s.hyperstatic.expect("hyperstatic");
    assert_eq!(h.degree, 1);
    assert_eq!(h.undetermined, ["Z_A", "Z_B"]);
    assert_eq!(h.relations, [e("Z_A + Z_B - m*g")]);
    assert!(!s.unknowns.contains_key("Z_A") && !s.unknowns.contains_key("Z_B"));
    for q in ["Z_A", "Z_B"] {
        let err = derive(&m, &Quantity::parse(q).unwrap())
            .unwrap_err()
            .to_string();
        assert!(
            err.contains("hyperstatic of degree 1")
                && err.contains("do not determine Z_A, Z_B separately, only Z_A + Z_B - m*g = 0"),
            "{err}"
        );
    }
}

/// A declared system short of an equation is not called hyperstatic: the rotor on a ball
/// joint and an annular joint (isostatic) without its moment on y1 leaves X_A and X_B tied
/// by the resultant, but the PFD of the solid would give X_B: the spec is refused, naming
/// them.
#[test]
fn an_equation_missing_is_not_hyperstatic() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("derivations/rotor_deux_paliers.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let pfd = v["pfd"].as_array_mut().unwrap();
    pfd.retain(|t| !(t["theorem"] == "moment" && t["on"] == "y1"));
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    match solve(&m) {
        Err(PfdError::MissingEquation { unknowns }) => assert_eq!(unknowns, ["X_A", "X_B"]),
        other => panic!("refused for a missing equation: {other:?}"),
    }
    let err = derive(&m, &Quantity::parse("X_A").unwrap())
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("do not determine X_A, X_B, which the PFD of each solid would determine"),
        "{err}"
    );
}

/// The float backend, with its own solve (least norm by the singular value decomposition),
/// gives the determined unknowns the exact values at every sample (`check`), the sum
/// Z_A + Z_B = m g, and refuses Z_A alone.
#[test]
fn the_float_backend_agrees_on_the_determined_unknowns() {
    use torseur::numeric::{NumValue, NumericModel, Sample};
    let m = shaft();
    let report = torseur::check::check(&m, 5, 7).unwrap();
    assert!(report.passed(), "{report}");
    assert_eq!(report.rows.len(), 5, "X_B, Y_B, X_A, Y_A and C_m compared");
    let model = NumericModel::new(m.spec()).unwrap();
    let params = [
        ("m", 2.0),
        ("a", 0.1),
        ("c", 0.3),
        ("L", 0.8),
        ("omega", 12.0),
        ("g", 9.81),
    ];
    let mut parameters: std::collections::BTreeMap<String, f64> =
        params.map(|(n, v)| (n.to_string(), v)).into();
    for (p, v) in [
        ("A1", 0.05),
        ("B1", 0.05),
        ("C1", 0.05),
        ("D1", 0.01),
        ("E1", 0.01),
        ("F1", 0.01),
    ] {
        parameters.insert(p.to_string(), v);
    }
    let s = Sample {
        parameters,
        coordinates: [("theta".to_string(), [0.4, 12.0, 0.0])].into(),
        time: 0.0,
    };
    let err = model
        .evaluate(&Quantity::parse("Z_A").unwrap(), &s, "0")
        .unwrap_err();
    assert!(err.to_string().contains("only together"), "{err}");
    let y = model
        .evaluate(&Quantity::parse("Y_B").unwrap(), &s, "0")
        .unwrap();
    assert!(
        matches!(y, NumValue::Scalar(x) if (x + 0.01 * 144.0 / 0.8).abs() < 1e-9),
        "{y:?}"
    );
}
