//! A trial motion (« régime forcé ») posed by a hypothesis, against hand derivations: the
//! forced mass-spring oscillator, undamped (x = X cos Ω t) and damped (x = X cos Ω t + Y sin Ω t),
//! and the refusals (a harmonic no unknown cancels, a name that clashes).
//!
//! By hand: isolate S1, resultant theorem on x0. M ẍ = −k x − c ẋ + F0 cos Ω t (the spring
//! pulls back towards O, the damper exerts −c ẋ x0, the exciter F0 cos Ω t x0), so
//! eom(x) = M ẍ + c ẋ + k x − F0 cos Ω t.
//! - c = 0, x = X cos Ω t, ẍ = −Ω² X cos Ω t: (k − M Ω²) X cos Ω t = F0 cos Ω t for every t,
//!   X = F0 / (k − M Ω²).
//! - x = X cos Ω t + Y sin Ω t, ẋ = Ω (Y cos Ω t − X sin Ω t), ẍ = −Ω² x:
//!   cos: (k − M Ω²) X + c Ω Y = F0; sin: (k − M Ω²) Y − c Ω X = 0; with D = k − M Ω²,
//!   X = F0 D / (D² + c² Ω²), Y = F0 c Ω / (D² + c² Ω²).

use super::*;
use torseur::derivation::{Value, derive_values};
use torseur::quantity::Quantity;

fn load(path: &str) -> Mechanism {
    torseur::spec::load(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).expect("the spec loads")
}

fn forced() -> Mechanism {
    load("derivations/masse_ressort_forcee.json")
}

fn damped() -> Mechanism {
    load("tests/specs/masse_ressort_amorti_force.json")
}

/// The value of `q`, as (numerator, denominator).
fn quotient(m: &Mechanism, q: &str) -> (Expr, Expr) {
    let d = derive_values(m, &[Quantity::parse(q).unwrap()]).unwrap();
    match &d[0].value {
        Value::Quotient(f) => (f.num.clone(), f.den.clone()),
        Value::Scalar(e) => (e.clone(), m.reg().one()),
        v => panic!("{q}: {v:?}"),
    }
}

/// n / d equals the hand-written `num / den`, by cross-multiplication.
fn assert_quotient(m: &Mechanism, q: &str, num: &str, den: &str) {
    let (n, d) = quotient(m, q);
    assert_eq!(&n * &ex(m, den), &ex(m, num) * &d, "{q} = ({n})/({d})");
}

#[test]
fn the_undamped_forced_amplitude_is_f0_over_k_minus_m_omega_squared() {
    let m = forced();
    assert_quotient(&m, "X", "F0", "k - M*Omega^2");
}

#[test]
fn the_damped_forced_motion_has_both_amplitudes_by_hand() {
    let m = damped();
    let den = "(k - M*Omega^2)^2 + c^2*Omega^2";
    assert_quotient(&m, "X", "F0*(k - M*Omega^2)", den);
    assert_quotient(&m, "Y", "F0*c*Omega", den);
}

#[test]
fn a_wrong_sign_is_not_the_amplitude() {
    let m = forced();
    let (n, d) = quotient(&m, "X");
    assert_ne!(&n * &ex(&m, "M*Omega^2 - k"), &ex(&m, "F0") * &d);
}

#[test]
fn under_the_trial_the_equation_of_motion_is_the_harmonic_balance() {
    let m = forced();
    let d = derive_values(&m, &[Quantity::parse("eom(x)").unwrap()]).unwrap();
    let h = m.hypotheses().iter().find(|h| h.name == "R").unwrap();
    let Value::Scalar(e) = d[0].value.under(h) else {
        panic!("a scalar")
    };
    assert_eq!(e, ex(&m, "((k - M*Omega^2)*X - F0)*cos(Omega*t)"));
}

#[test]
fn verify_accepts_the_hand_written_amplitude_under_the_hypothesis() {
    let m = forced();
    let v = torseur::verify::verify(&m, "X", "F0/(k - M*Omega^2)", Some("R")).unwrap();
    assert!(v.is_equivalent(), "{v}");
    let v = torseur::verify::verify(&m, "X", "F0/(M*Omega^2 - k)", Some("R")).unwrap();
    assert!(!v.is_equivalent(), "{v}");
}

fn spec_json(path: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn damping_with_only_a_cosine_says_to_add_the_sine() {
    let mut v = spec_json("tests/specs/masse_ressort_amorti_force.json");
    v["hypotheses"][0]["trial"] =
        serde_json::json!({"coordinate": "x", "motion": "X*cos(Omega*t)", "unknowns": ["X"]});
    v["quantities"] = serde_json::json!(["eom(x)"]);
    v["questions"] = serde_json::json!([]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let e = derive_values(&m, &[Quantity::parse("X").unwrap()]).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("sin(Omega*t)") && text.contains("Y*sin(Omega*t)"),
        "{text}"
    );
}

#[test]
fn an_unknown_that_is_a_parameter_is_refused_at_its_path() {
    let mut v = spec_json("derivations/masse_ressort_forcee.json");
    v["hypotheses"][1]["trial"]["unknowns"] = serde_json::json!(["F0"]);
    v["hypotheses"][1]["trial"]["motion"] = "F0*cos(Omega*t)".into();
    let e = torseur::spec::from_str(&v.to_string()).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("hypotheses[1].trial.unknowns[0]") && text.contains("`F0` is a parameter"),
        "{text}"
    );
}

#[test]
fn a_trial_on_an_unknown_coordinate_is_refused() {
    let mut v = spec_json("derivations/masse_ressort_forcee.json");
    v["hypotheses"][1]["trial"]["coordinate"] = "y".into();
    let e = torseur::spec::from_str(&v.to_string()).unwrap_err();
    assert!(e.to_string().contains("unknown coordinate `y`"), "{e}");
}

#[test]
fn the_float_backend_catches_a_wrong_amplitude_by_its_own_route() {
    use rand::SeedableRng;
    let m = forced();
    let model = torseur::numeric::NumericModel::new(m.spec()).unwrap();
    let h = m.hypotheses().iter().find(|h| h.name == "R").unwrap();
    let q = Quantity::parse("X").unwrap();
    let run = |x: &str| {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
        let f = torseur::expr::Fraction::new(ex(&m, x), ex(&m, "k - M*Omega^2")).unwrap();
        let v = [Value::Quotient(f)];
        torseur::check::compare_trial_values(&m, &model, &q, h, &v, 10, &mut rng)
            .unwrap()
            .worst
    };
    // The right amplitude makes the backend's own eom vanish along the motion.
    assert!(run("F0") < 1e-9, "{}", run("F0"));
    // Its opposite, or a forgotten factor, leaves the forcing's size in the residual.
    assert!(run("-F0") > 1e-2, "{}", run("-F0"));
    assert!(run("2*F0") > 1e-2, "{}", run("2*F0"));
}
