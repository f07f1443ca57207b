//! The rate of a coordinate as a quantity, `dot(q)` and `ddot(q)` (issue 37: « λ and λ̇ cannot
//! be asked for as quantities »): the slider–crank's piston speed from its loop law, by hand
//! and by the kinematics of the piston's point; a rolling and a screw coordinate; a free, an
//! imposed and a geared rate; the float backend by its own solution of the loop; the
//! dimensions; and what is refused.

use super::*;
use torseur::quantity::Quantity;
use torseur::units::{Dimension, Dimensions, ExpectedDimension, expected_dimension};

fn library(stem: &str) -> serde_json::Value {
    let path = format!("{}/derivations/{stem}.json", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The value of a scalar quantity.
fn scalar(m: &Mechanism, q: &str) -> Expr {
    let d = torseur::derive(m, &Quantity::parse(q).unwrap()).unwrap();
    match d.value {
        torseur::Value::Scalar(e) => e,
        v => panic!("{q} is not a scalar: {v:?}"),
    }
}

/// OA + AB + BO = 0 gives, on y0, R sin θ + L sin φ = 0, so φ̇ = −R θ̇ cos θ / (L cos φ); on
/// x0, x = R cos θ + L cos φ, so ẋ = −R θ̇ sin θ − L φ̇ sin φ = R θ̇ sin(φ − θ) / cos φ. Its
/// derivative, written out with the product rule and φ̇ put back in:
/// ẍ = R θ̈ sin(φ − θ)/cos φ + R θ̇ [(φ̇ − θ̇) cos(φ − θ) cos φ + φ̇ sin(φ − θ) sin φ]/cos² φ.
#[test]
fn the_piston_speed_is_the_loop_law_by_hand() {
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    let phidot = "(-R*dot(theta)*cos(theta)/(L*cos(phi)))";
    let hand = format!("-R*dot(theta)*sin(theta) - L*{phidot}*sin(phi)");
    assert_eq!(scalar(&m, "dot(x)"), ex(&m, &hand));
    assert_eq!(
        scalar(&m, "dot(x)"),
        ex(&m, "R*dot(theta)*sin(phi - theta)/cos(phi)")
    );
    let hand2 = format!(
        "R*ddot(theta)*sin(phi - theta)/cos(phi) + R*dot(theta)*(({phidot} - dot(theta))\
         *cos(phi - theta)*cos(phi) + {phidot}*sin(phi - theta)*sin(phi))/cos(phi)^2"
    );
    assert_eq!(scalar(&m, "ddot(x)"), ex(&m, &hand2));
    // The same by the kinematics of the point B of the piston (OB = R x1 + L x2 derived in
    // R0), a route that never reads the closure's x.
    assert_eq!(scalar(&m, "dot(x)"), scalar(&m, "V(B,3/0).x0"));
    assert_eq!(scalar(&m, "ddot(x)"), scalar(&m, "Gamma(B,3/0).x0"));
    // And the bielle's angle: φ̇ as Ω(2/0)·z0.
    assert_eq!(scalar(&m, "dot(phi)"), ex(&m, phidot));
    assert_eq!(scalar(&m, "dot(phi)"), scalar(&m, "Omega(2/0).z0"));
    // A wrong sign is caught.
    let v = torseur::verify::verify(&m, "dot(x)", "R*dot(theta)*sin(theta - phi)/cos(phi)", None)
        .unwrap();
    assert!(!v.is_equivalent());
}

/// The float backend evaluates a coordinate's rates from its own solution of the loop
/// (Newton on the positions, its own Jacobian for the rates), and agrees to 1e-9.
#[test]
fn the_float_backend_gives_the_rates_of_its_own_loop() {
    let mut v = library("bielle_manivelle");
    v["quantities"] = serde_json::json!(["dot(x)", "ddot(x)", "dot(phi)", "ddot(phi)"]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let report = torseur::check::check(&m, 12, 3).unwrap();
    assert!(report.passed(), "{:?}", report.failures());
    assert_eq!(report.rows.len(), 4);
}

/// A wheel rolling without slipping (its centre's x and y driven by ψ and θ), a screw (λ
/// driven by the screw's angle), a gear (θ2 = −r1/r2 θ1 by its `rate`), an imposed rate and a
/// free coordinate, each against its own relation written by hand.
#[test]
fn rolling_screw_gear_imposed_and_free_rates() {
    let wheel = torseur::spec::load("derivations/roue_sur_plan.json").unwrap();
    // V(C) = V(I) + Ω ∧ IC with V(I ∈ 2/0) = 0: the centre's speed is the rolling condition's.
    assert_eq!(scalar(&wheel, "dot(x)"), scalar(&wheel, "V(C,2/0).x0"));
    assert_eq!(scalar(&wheel, "dot(y)"), scalar(&wheel, "V(C,2/0).y0"));
    assert_eq!(scalar(&wheel, "ddot(x)"), scalar(&wheel, "Gamma(C,2/0).x0"));
    let gear = torseur::spec::load("derivations/train_engrenages.json").unwrap();
    assert_eq!(
        scalar(&gear, "dot(theta2)"),
        ex(&gear, "-r1/r2*dot(theta1)")
    );
    assert_eq!(
        scalar(&gear, "ddot(theta2)"),
        ex(&gear, "-r1/r2*ddot(theta1)")
    );
    let imposed = torseur::spec::load("derivations/rotor_vitesse_imposee.json").unwrap();
    assert_eq!(scalar(&imposed, "dot(theta)"), ex(&imposed, "omega"));
    assert!(scalar(&imposed, "ddot(theta)").is_zero());
    assert!(scalar(&imposed, "dot(alpha)").is_zero());
    let free = regulator();
    assert_eq!(scalar(&free, "dot(theta1)"), ex(&free, "dot(theta1)"));
    assert_eq!(scalar(&free, "ddot(theta2)"), ex(&free, "ddot(theta2)"));
}

/// A screw jack: the spec's screw turns the other way (its key writes λ̇ = −p θ̇/(2π)); the
/// carriage's velocity along the screw's axis says the same by the kinematics.
#[test]
fn the_screw_gives_the_carriage_speed() {
    let m = torseur::spec::load("derivations/verin_a_vis.json").unwrap();
    assert_eq!(scalar(&m, "dot(lambda)"), ex(&m, "-p*dot(theta)/(2*pi)"));
    assert_eq!(scalar(&m, "ddot(lambda)"), ex(&m, "-p*ddot(theta)/(2*pi)"));
}

#[test]
fn a_rate_has_the_dimension_of_its_coordinate_over_a_time() {
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    let d = Dimensions::of(&m);
    let e = |q: &str| expected_dimension(&m, &d, &Quantity::parse(q).unwrap());
    let one = |x| ExpectedDimension::Components(Some(x));
    assert_eq!(e("dot(x)"), one(Dimension::VELOCITY));
    assert_eq!(e("ddot(x)"), one(Dimension::ACCELERATION));
    assert_eq!(e("dot(theta)"), one(Dimension::ANGULAR_VELOCITY));
}

#[test]
fn a_rate_of_no_coordinate_or_written_as_a_vector_is_refused() {
    let m = torseur::spec::load("derivations/bielle_manivelle.json").unwrap();
    let e = torseur::derive(&m, &Quantity::parse("dot(nope)").unwrap()).unwrap_err();
    let e = e.to_string();
    assert!(
        e.contains("unknown coordinate `nope`") && e.contains("`theta`"),
        "{e}"
    );
    let e = Quantity::parse("dot(x).x0").unwrap_err().to_string();
    assert!(e.contains("scalar"), "{e}");
    let e = torseur::derive(&m, &Quantity::parse("x").unwrap()).unwrap_err();
    let e = e.to_string();
    assert!(
        e.contains("`x` is a coordinate") && e.contains("dot(x)"),
        "{e}"
    );
    assert!(Quantity::parse("dddot(x)").is_err());
    assert!(Quantity::parse("dot(2x)").is_err());
}
