//! `verify` on a closed chain (issue 37): the relations a teacher writes from the loop
//! closure hold at position level only, so they are not identities of the canonical form.
//! They are decided from the closure as the course writes it: the slider–crank
//! (`derivations/bielle_manivelle.json`), O A = R x1 (θ), A B = L x2 (φ, from the ground),
//! O B = x x0, closes by R x1 + L x2 − x x0 = 0; projected on x0 and y0, by hand:
//! R cos θ + L cos φ = x and R sin θ + L sin φ = 0; eliminating φ (isolate L x2, square):
//! (x − R cos θ)² + R² sin² θ = L².

use torseur::mechanism::Mechanism;
use torseur::verify::{Check, verify, verify_equation};

fn slider_crank() -> Mechanism {
    torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/bielle_manivelle.json"
    ))
    .unwrap()
}

/// The relation's words and factor in a verdict decided by the closure.
fn by_closure(m: &Mechanism, text: &str) -> (String, String) {
    let v = verify_equation(m, text, None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    let Check::Closure { relations } = &v.check else {
        panic!("{text}: {:?}", v.check)
    };
    assert_eq!(relations.len(), 1);
    (relations[0].0.clone(), relations[0].1.to_string())
}

#[test]
fn the_closure_written_by_hand_is_equivalent_modulo_the_loop() {
    let m = slider_crank();
    assert_eq!(
        by_closure(&m, "R*cos(theta) + L*cos(phi) = x"),
        ("the loop closure projected on x0".into(), "1".into())
    );
    assert_eq!(
        by_closure(&m, "R*sin(theta) + L*sin(phi) = 0"),
        ("the loop closure projected on y0".into(), "1".into())
    );
    // Divided by L: sin φ = −(R/L) sin θ.
    assert_eq!(
        by_closure(&m, "sin(phi) = -R/L*sin(theta)"),
        ("the loop closure projected on y0".into(), "1/L".into())
    );
    assert_eq!(
        by_closure(&m, "(x - R*cos(theta))^2 + R^2*sin(theta)^2 = L^2"),
        (
            "the loop closure with the direction of its term in B2 eliminated".into(),
            "1".into()
        )
    );
    // The velocity of the slider written with a term that the closure makes zero.
    let v = verify(
        &m,
        "V(B,3/0).x0",
        "R*dot(theta)*sin(phi - theta)/cos(phi) + dot(theta)*(R*sin(theta) + L*sin(phi))",
        None,
    )
    .unwrap();
    assert!(v.is_equivalent(), "{v}");
    assert!(matches!(v.check, Check::Closure { .. }), "{:?}", v.check);
}

/// A false relation is not equivalent, with a closed configuration of the float backend at
/// which it fails: there, the true projection holds (the configuration is closed) and the
/// false one is off by x (2x written for x).
#[test]
fn a_false_relation_fails_at_a_closed_configuration() {
    let m = slider_crank();
    let v = verify_equation(&m, "R*cos(theta) + L*cos(phi) = 2*x", None).unwrap();
    assert!(!v.is_equivalent());
    let at = v.counterexample.clone().expect("a counterexample");
    assert!(at.starts_with("at the closed configuration phi = "), "{at}");
    // lhs − rhs = −x there: the value printed is minus the x printed.
    let x: f64 = at.split("x = ").nth(1).unwrap()[..6].parse().unwrap();
    let value: f64 = at.rsplit("lhs − rhs = ").next().unwrap().parse().unwrap();
    assert!((value + x).abs() < 1e-3, "{at}");
    let text = v.to_string();
    assert!(
        text.contains("not a consequence of the loop closure"),
        "{text}"
    );
}

/// The explicit loop law, solved by hand from (x − R cos θ)² + R² sin²θ = L²:
/// x = R cos θ ± √(L² − R² sin²θ). At the scenario `demarrage`'s initial configuration
/// (θ = 0, x = 0.25 = R + L with R = 0.05, L = 0.2), x − R cos θ = L > 0: the + branch holds
/// there, the − branch is off by 2√(L² − R² sin²θ) = 2 L = 0.4.
#[test]
fn the_explicit_loop_law_holds_on_the_assembly_branch_only() {
    let m = slider_crank();
    let plus = "x = R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)";
    let (relation, _) = by_closure(&m, plus);
    assert!(
        relation.contains("direction of its term in B2 eliminated"),
        "{relation}"
    );
    assert!(relation.contains("scenario `demarrage`"), "{relation}");
    // Written the other way round, and with the root's radicand times a square.
    by_closure(
        &m,
        "x - R*cos(theta) = 1/2*sqrt(4*L^2 - 4*R^2*sin(theta)^2)",
    );
    let minus =
        verify_equation(&m, "x = R*cos(theta) - sqrt(L^2 - R^2*sin(theta)^2)", None).unwrap();
    assert!(!minus.is_equivalent());
    let at = minus.counterexample.clone().expect("a counterexample");
    let value: f64 = at.split("lhs − rhs = ").nth(1).unwrap()[..6]
        .parse()
        .unwrap();
    assert!((value - 0.4).abs() < 1e-9, "{at}");
    // The key's law is the + branch, read at that configuration.
    let law = &m.loop_law().unwrap().explicit[0];
    let branch = torseur::derivation::explicit_law(&m, law).unwrap();
    assert_eq!(branch.sign, 1);
    assert_eq!(
        branch.value,
        m.reg()
            .parse("R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)")
            .unwrap()
    );
}

/// The slider–crank's spec with one text replaced (`from` → `to`, which must occur).
fn slider_crank_with(from: &str, to: &str) -> Result<Mechanism, String> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/bielle_manivelle.json"
    );
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.contains(from), "{from}");
    torseur::spec::from_str(&text.replacen(from, to, 1)).map_err(|e| e.to_string())
}

/// A spec's own text may not write a root, even the one its explicit loop law declares: the
/// spec's texts are differentiated (the gas force's power, the velocities), and the time
/// derivative of √(L² − R² sin²θ) is no polynomial. Refused at loading, never a panic
/// (`sqrt(0)`, which symbolica reads as 0, is zero).
#[test]
fn a_spec_text_with_a_square_root_is_refused_at_loading() {
    for root in [
        "sqrt(L^2 - R^2*sin(theta)^2)",
        "sqrt(-1)",
        "sqrt(x^2)",
        "sqrt(F)",
    ] {
        let e = slider_crank_with(
            "\"resultant\": \"-F*x0\"",
            &format!("\"resultant\": \"-F*{root}*x0\""),
        )
        .err()
        .unwrap_or_else(|| panic!("{root}: loaded"));
        assert!(e.contains("actions[1].resultant"), "{root}: {e}");
    }
    let e = slider_crank_with(
        "\"resultant\": \"-F*x0\"",
        "\"resultant\": \"-F*sqrt(L^2 - R^2*sin(theta)^2)*x0\"",
    )
    .unwrap_err();
    assert!(e.contains("a spec's text writes no square root"), "{e}");
}

/// Hostile roots typed to `verify` are answered (not equivalent, or a refusal), never a
/// panic: a negative number, zero, a square, a radicand that is not the loop's.
#[test]
fn hostile_square_roots_in_a_relation_are_answered() {
    let m = slider_crank();
    for text in [
        "x = R*cos(theta) + sqrt(-1)",
        "x = R*cos(theta) + sqrt(-L^2)",
        "x = sqrt(x^2)",
        "x = R*cos(theta) + sqrt(L^2 + R^2)",
        "x = R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)^3",
        "x = R*cos(theta) + 1/sqrt(L^2 - R^2*sin(theta)^2)",
    ] {
        if let Ok(v) = verify_equation(&m, text, None) {
            assert!(!v.is_equivalent(), "{text}: {v}");
        }
    }
    // √0 = 0 and √(x²) is refused as no root: x = R cos θ is false at the assembly (x = R + L).
    let v = verify_equation(&m, "x = R*cos(theta) + sqrt(0)", None).unwrap();
    assert!(!v.is_equivalent(), "{v}");
    assert!(verify_equation(&m, "x = sqrt(x^2)", None).is_err());
}
