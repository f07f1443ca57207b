//! A body carried by a solid (`carried_by`, issue 37): a point mass fixed on a rotor or a rod,
//! with no link between them. Isolating the carrier isolates what it carries; isolating the
//! carried body alone, or one of two solids that share a frame without a link, is refused
//! instead of silently leaving out the action that holds them together.
//!
//! `derivations/pendule_masse_portee.json`, derived by hand: a rod S1 (m1, length L) turns
//! about (O, z0) by θ, OG1 = −(L/2) y1, I(G1) = diag(m1 L²/12, 0, m1 L²/12) in B1; a point mass
//! m2 at its end A, OA = −L y1; weight −g y0. With y1 = −sin θ x0 + cos θ y0, a point at OP =
//! −r y1 = r (sin θ x0 − cos θ y0) has Γ(P) = r (θ̈ cos θ − θ̇² sin θ) x0 + r (θ̈ sin θ + θ̇²
//! cos θ) y0, and its weight −m g y0 has the moment −m g r sin θ z0 at O.
//! - The rod alone: δ(O,1/0)·z0 = (m1 L²/12 + m1 L²/4) θ̈ = m1 L²/3 θ̈; Ec(1/0) = m1 L² θ̇²/6.
//! - The mass alone: δ(O,2/0)·z0 = m2 L² θ̈.
//! - The rod with its mass, the pivot transmitting no moment on z0: (m1/3 + m2) L² θ̈ =
//!   −(m1/2 + m2) g L sin θ; the resultant: X01 = (m1/2 + m2) L (θ̈ cos θ − θ̇² sin θ) and
//!   Y01 − (m1 + m2) g = (m1/2 + m2) L (θ̈ sin θ + θ̇² cos θ).

use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;

fn library(stem: &str) -> serde_json::Value {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join(format!("derivations/{stem}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn scalar(m: &torseur::mechanism::Mechanism, q: &str) -> torseur::expr::Expr {
    match derive(m, &Quantity::parse(q).unwrap()).unwrap().value {
        Value::Scalar(v) => v,
        other => panic!("{q} is a scalar: {other:?}"),
    }
}

/// Both sides' messages when they refuse `v`: the same path and message.
fn refused(v: &serde_json::Value) -> String {
    let (exact, float) = super::parity::verdicts(v).expect("a spec's shape");
    let exact = exact.expect_err("the exact side refuses");
    let float = float.expect_err("the float backend refuses");
    assert!(
        float.contains(exact.split(": ").last().unwrap()),
        "{exact}\n{float}"
    );
    exact
}

#[test]
fn the_rod_carrying_a_point_mass_gives_the_hand_values() {
    let mut v = library("pendule_masse_portee");
    // The float backend checks the set `1+2` too.
    let quantities = v["quantities"].as_array_mut().unwrap();
    quantities.push("delta(O,1+2/0).z0".into());
    quantities.push("Rd(1+2/0) in B0".into());
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let e = |s: &str| m.reg().parse(s).unwrap();
    for (q, hand) in [
        // Asked on the solid itself: the body's own, the mass it carries left out.
        ("delta(O,1/0).z0", "m1*L^2/3*ddot(theta)"),
        ("sigma(O,1/0).z0", "m1*L^2/3*dot(theta)"),
        ("Ec(1/0)", "m1*L^2/6*dot(theta)^2"),
        ("delta(O,2/0).z0", "m2*L^2*ddot(theta)"),
        // The theorems isolate the rod with the mass it carries.
        (
            "eom(theta)",
            "(m1/3 + m2)*L^2*ddot(theta) + (m1/2 + m2)*g*L*sin(theta)",
        ),
        (
            "X01",
            "(m1/2 + m2)*L*(ddot(theta)*cos(theta) - dot(theta)^2*sin(theta))",
        ),
        (
            "Y01",
            "(m1/2 + m2)*L*(ddot(theta)*sin(theta) + dot(theta)^2*cos(theta)) + (m1 + m2)*g",
        ),
        // The set written `1+2`: the rod and its mass together.
        ("delta(O,1+2/0).z0", "(m1/3 + m2)*L^2*ddot(theta)"),
    ] {
        assert_eq!(scalar(&m, q), e(hand), "{q}");
    }
    // The float backend, by its own reading of `carried_by`, agrees.
    let report = torseur::check::check(&m, 12, 7).unwrap();
    assert!(report.passed(), "{:?}", report.failures());
}

/// The balourd of `derivations/rotor_balourd.json` carried by the rotor, the rotor isolated
/// alone: the same bearing actions as the set E = {1, 2}. By hand (θ̇ = ω): Γ(P) = −e ω² x1,
/// x1 = cos θ x0 + sin θ y0, so X01 = −m e ω² cos θ, Y01 = (M + m) g − m e ω² sin θ, and the
/// moment at A on z0 of the balourd's weight, −m g e cos θ, gives C_m = m g e cos θ.
#[test]
fn the_rotor_isolated_alone_counts_the_balourd_it_carries() {
    let mut v = library("rotor_balourd");
    v["solids"][1]["carried_by"] = "1".into();
    v["solids"][1].as_object_mut().unwrap().remove("frame");
    for t in v["pfd"].as_array_mut().unwrap() {
        t["isolate"] = "1".into();
    }
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let e = |s: &str| m.reg().parse(s).unwrap();
    for (q, hand) in [
        ("X01", "-m*e*omega^2*cos(theta)"),
        ("Y01", "(M + m)*g - m*e*omega^2*sin(theta)"),
        ("C_m", "m*g*e*cos(theta)"),
    ] {
        assert_eq!(scalar(&m, q), e(hand), "{q}");
    }
    let report = torseur::check::check(&m, 12, 7).unwrap();
    assert!(report.passed(), "{:?}", report.failures());
    // The graph of links draws the balourd on the rotor.
    let graph = torseur::latex::link_graph(&m);
    assert!(graph.contains("solidaires (encastrement)"), "{graph}");
}

/// The defect of issue 37: the rotor isolated alone while the balourd shares its frame with
/// no link and no `carried_by` gave X01 = 0 without a word. Both sides now refuse it, naming
/// both solids and the fix; the set that holds both stays accepted.
#[test]
fn a_solid_isolated_without_another_on_its_frame_is_refused() {
    let mut v = library("rotor_balourd");
    for t in v["pfd"].as_array_mut().unwrap() {
        t["isolate"] = "1".into();
    }
    let e = refused(&v);
    assert!(e.starts_with("at pfd[0].isolate"), "{e}");
    assert!(
        e.contains("the solids `1` and `2` share a frame with no link between them")
            && e.contains("declare it `\"carried_by\": \"1\"`"),
        "{e}"
    );
    assert!(torseur::spec::from_str(&library("rotor_balourd").to_string()).is_ok());
}

#[test]
fn a_carried_solid_is_never_isolated_without_its_carrier() {
    let mut v = library("pendule_masse_portee");
    v["pfd"][2]["isolate"] = "2".into();
    let e = refused(&v);
    assert!(e.starts_with("at pfd[2].isolate"), "{e}");
    assert!(
        e.contains("the solid `2` is carried by `1`")
            && e.contains("isolated only with its carrier"),
        "{e}"
    );
    // Nor in a set without it.
    let mut v = library("pendule_masse_portee");
    v["sets"] = serde_json::json!({"E": ["2"]});
    v["pfd"][2]["isolate"] = "E".into();
    assert!(refused(&v).contains("the solid `2` is carried by `1`"));
}

#[test]
fn a_carrier_is_a_solid_of_the_spec_and_gives_its_frame() {
    let base = library("pendule_masse_portee");
    let with = |edit: &dyn Fn(&mut serde_json::Value)| {
        let mut v = base.clone();
        edit(&mut v);
        refused(&v)
    };
    let e = with(&|v| v["solids"][1]["frame"] = "0".into());
    assert!(e.starts_with("at solids[1].frame"), "{e}");
    assert!(
        e.contains("a carried solid is attached to its carrier's frame"),
        "{e}"
    );
    let e = with(&|v| v["solids"][1]["carried_by"] = "0".into());
    assert!(e.contains("`0` is the ground"), "{e}");
    let e = with(&|v| v["solids"][1]["carried_by"] = "3".into());
    assert!(
        e.starts_with("at solids[1].carried_by") && e.contains("unknown solid `3`"),
        "{e}"
    );
    let e = with(&|v| v["solids"][0]["carried_by"] = "2".into());
    assert!(e.contains("carried by itself"), "{e}");
    let e = with(&|v| {
        v["solids"][1].as_object_mut().unwrap().remove("carried_by");
    });
    assert!(
        e.starts_with("at solids[1].frame") && e.contains("missing"),
        "{e}"
    );
    // Its own frame named, when it is the carrier's, is accepted.
    let mut v = base.clone();
    v["solids"][1]["frame"] = "1".into();
    assert!(torseur::spec::from_str(&v.to_string()).is_ok());
}
