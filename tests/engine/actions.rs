//! Actions of the bilan asked as quantities (issue 15, item 3): R(from→on), M(A, from→on),
//! {T(from→on)}_A. Checked by hand derivations, by the mutual-action law, against the float
//! backend (which sums the weight over each solid's point cloud and moves every action by its
//! own code), and by the moment theorem read back as an equation of motion.

use super::*;
use torseur::check::TOLERANCE;
use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;
use torseur::verify::{Check, verify_equation};

fn value(m: &Mechanism, q: &str) -> Value {
    derive(m, &Quantity::parse(q).unwrap()).unwrap().value
}

fn scalar(m: &Mechanism, q: &str) -> Expr {
    match value(m, q) {
        Value::Scalar(e) => e,
        v => panic!("{q}: not a scalar: {v:?}"),
    }
}

fn library(name: &str) -> Mechanism {
    torseur::spec::load(format!("derivations/{name}.json")).unwrap()
}

#[test]
fn moments_of_the_weights_by_hand() {
    // Regulator: O1G2 = d1 z0 + L1 y1 + L2 y2 and y2 = cos θ2 y1 + sin θ2 z1, so
    // O1G2 ∧ (−m2 g z0) = −m2 g (L1 + L2 cos θ2) y1 ∧ z0 = −m2 g (L1 + L2 cos θ2) x1; the weight
    // of S1 acts at G1 on the axis (O1, z0) and has no moment at O1.
    let m = regulator();
    let Value::Vector { components, .. } = value(&m, "M(O1,pes->E) in B1") else {
        panic!("a vector");
    };
    assert_eq!(components[0], ex(&m, "-m2*g*(L1 + L2*cos(theta2))"));
    assert!(components[1].is_zero() && components[2].is_zero());
    // The resultant of everything exterior to E: the pivot (0, 1) and both weights.
    let Value::Vector { components, .. } = value(&m, "R(ext->E) in B0") else {
        panic!("a vector");
    };
    assert_eq!(
        components,
        [ex(&m, "X01"), ex(&m, "Y01"), ex(&m, "Z01 - (m1 + m2)*g")]
    );
    // The pivot (O2, x1) with viscous friction: −f θ̇2 on x1, the rest its unknowns.
    let Value::Torsor {
        resultant, moment, ..
    } = value(&m, "{T(1->2)}_O2 in B1")
    else {
        panic!("a torsor");
    };
    assert_eq!(resultant, [ex(&m, "X12"), ex(&m, "Y12"), ex(&m, "Z12")]);
    assert_eq!(
        moment,
        [ex(&m, "-f*dot(theta2)"), ex(&m, "M12"), ex(&m, "N12")]
    );

    // Inverted pendulum: OG = l y1, y1 = −sin θ x0 + cos θ y0, (l y1) ∧ (−m g y0) = m g l sin θ z0;
    // the pivot's spring and friction give −k θ − f θ̇ on z0.
    let m = library("pendule_inverse_ressort");
    assert_eq!(scalar(&m, "M(O,pes->1).z0"), ex(&m, "m*g*l*sin(theta)"));
    assert_eq!(
        scalar(&m, "M(O,0->1).z0"),
        ex(&m, "-k*theta - f*dot(theta)")
    );
    // Winch: the load hangs at B, R x0 from the axis: (R x0) ∧ (−m g y0) = −m g R z0.
    let m = library("treuil");
    assert_eq!(scalar(&m, "M(O,pes->E).z0"), ex(&m, "-m*g*R"));
}

#[test]
fn a_motor_between_two_arms_acts_on_both_under_its_name() {
    // Bras robot: the motor M2, fixed on arm 1, turns arm 2 with C_m2 x1 at A; its reaction
    // −C_m2 x1 acts on arm 1, still named after the motor, and is not an action of 2 on 1.
    let m = library("bras_robot_deux_axes");
    assert_eq!(scalar(&m, "M(A,moteur2->2).x1"), ex(&m, "C_m2"));
    assert_eq!(scalar(&m, "M(A,moteur2->1).x1"), ex(&m, "-C_m2"));
    assert_eq!(scalar(&m, "M(A,2->1).x1"), ex(&m, "0"));
}

#[test]
fn mutual_actions_are_opposite_in_every_library_spec() {
    // {T(a→b)} = −{T(b→a)} for every link of every spec, at its own point.
    let mut seen = 0;
    for path in specs_in(&["derivations"]) {
        let m = torseur::spec::load(&path).unwrap();
        for l in &m.spec().links {
            let [a, b] = [&l.between[0], &l.between[1]];
            let solid = |n: &str| m.find_body(n).is_some();
            if !solid(a) || !solid(b) {
                continue;
            }
            let t = |x: &str, y: &str| value(&m, &format!("{{T({x}->{y})}}_{} in B0", l.point));
            let (
                Value::Torsor {
                    resultant: r1,
                    moment: m1,
                    ..
                },
                Value::Torsor {
                    resultant: r2,
                    moment: m2,
                    ..
                },
            ) = (t(a, b), t(b, a))
            else {
                panic!("torsors");
            };
            for (x, y) in r1.iter().chain(&m1).zip(r2.iter().chain(&m2)) {
                assert!(
                    (x + y).is_zero(),
                    "{}: T({a}->{b}) + T({b}->{a}) = {}",
                    path.display(),
                    x + y
                );
            }
            seen += 1;
        }
    }
    assert!(seen >= 3, "{seen} links between two solids");
}

fn worst(m: &Mechanism, q: &str, v: &Value) -> f64 {
    super::check::worst_seeded(m, q, v, 11)
}

#[test]
fn the_float_backend_catches_a_wrong_action() {
    let m = regulator();
    // Right: the weights' moment, and the pivot's resultant holding its unknowns (the samples
    // give them random values, the same on both sides).
    for q in [
        "M(O1,pes->E) in B1",
        "R(0->1) in B0",
        "{T(ext->2)}_O1 in B1",
    ] {
        assert!(worst(&m, q, &value(&m, q)) <= TOLERANCE, "{q}");
    }
    // A sign error in the moment of a weight.
    let v = value(&m, "M(O1,pes->E) in B1").map(&|e| -e);
    assert!(worst(&m, "M(O1,pes->E) in B1", &v) > 1e-3);
    // X01 and Y01 exchanged.
    let Value::Vector { basis, components } = value(&m, "R(0->1) in B0") else {
        panic!("a vector");
    };
    let swapped = Value::Vector {
        basis,
        components: [
            components[1].clone(),
            components[0].clone(),
            components[2].clone(),
        ],
    };
    assert!(worst(&m, "R(0->1) in B0", &swapped) > 1e-3);
    // The moment of the exterior actions at O1 taken at O2 instead (transport forgotten).
    let at_o2 = value(&m, "M(O2,ext->2) in B1");
    assert!(worst(&m, "M(O1,ext->2) in B1", &at_o2) > 1e-3);
}

#[test]
fn the_moment_theorem_written_with_an_action_is_the_equation_of_motion() {
    // δ(O,1/0)·z0 = M(O, ext→1)·z0 is the pendulum's equation of motion (factor 1).
    let m = library("pendule_inverse_ressort");
    let v = verify_equation(&m, "delta(O,1/0).z0 = M(O,ext->1).z0", None).unwrap();
    assert!(v.is_equivalent(), "{v:?}");
    assert_eq!(
        v.check,
        Check::EquationOfMotion {
            coordinate: "theta".into()
        }
    );
    // With the weight's moment of the wrong sign, it is not.
    let v = verify_equation(&m, "delta(O,1/0).z0 = M(O,0->1).z0 - M(O,pes->1).z0", None).unwrap();
    assert!(!v.is_equivalent());
}

#[test]
fn an_action_that_is_not_there_is_refused_by_name() {
    let m = regulator();
    let e = |q: &str| {
        derive(&m, &Quantity::parse(q).unwrap())
            .unwrap_err()
            .to_string()
    };
    assert_eq!(
        e("R(2->E)"),
        "R(2->E): `2` is part of `E`: its actions on `E` are internal"
    );
    assert_eq!(
        e("R(foo->2)"),
        "R(foo->2): no action of `foo` on `2` is declared (the actions on `2` come from: 1, \
         pes, ext)"
    );
    assert_eq!(
        e("M(Q,0->1)"),
        "M(Q,0->1): unknown point `Q` (declared: `O0`, `O1`, `G1`, `O2`, `G2`)"
    );
    assert_eq!(
        e("R(0->F)"),
        "R(0->F): unknown solid or set `F` (declared: `1`, `2`, `E`)"
    );
    // In a spec, at load, with its place.
    let text = std::fs::read_to_string("derivations/pendule_inverse_ressort.json").unwrap();
    let text = text.replacen("\"quantities\": [", "\"quantities\": [\"M(O,foo->1)\", ", 1);
    let err = torseur::spec::from_str(&text).unwrap_err().to_string();
    assert!(
        err.starts_with("at quantities[0]") && err.contains("no action of `foo` on `1`"),
        "{err}"
    );
    for bad in ["R(0/1)", "M(O1,0->1->2)", "{T(0->1)}", "M(0->1)"] {
        assert!(Quantity::parse(bad).is_err(), "{bad}");
    }
}
