//! `check` can fail: wrong formulas fed to the comparison are reported, right ones are not.

use super::*;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use torseur::check::{TOLERANCE, compare};
use torseur::derivation::Value;
use torseur::inertia::Inertia;
use torseur::kinematics::{omega, point_velocity, velocity};
use torseur::numeric::NumericModel;
use torseur::quantity::Quantity;
use torseur::torsor::{dynamic_moment_solid, inertia_at_centre, kinetic_moment_solid};

fn worst(m: &torseur::mechanism::Mechanism, q: &str, v: &Value) -> f64 {
    worst_seeded(m, q, v, 7)
}

/// The worst relative error of `v` as the value of `q`, over 10 samples from `seed`.
pub fn worst_seeded(m: &torseur::mechanism::Mechanism, q: &str, v: &Value, seed: u64) -> f64 {
    let model = NumericModel::new(m.spec()).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    compare(
        m,
        &model,
        &Quantity::parse(q).unwrap(),
        v,
        None,
        10,
        &mut rng,
    )
    .unwrap()
    .worst
}

fn in_b2(m: &torseur::mechanism::Mechanism, v: &Vector) -> Value {
    let b = frame(m, "2");
    Value::Vector {
        basis: b,
        components: v.express_in(m.frames(), b),
    }
}

#[test]
fn the_right_formulas_pass() {
    let m = regulator();
    let (s2, o2, f0) = (
        m.find_body("2").unwrap(),
        m.point("O2").unwrap(),
        m.frames().ground(),
    );
    assert!(
        worst(
            &m,
            "sigma(O2,2/0) in B2",
            &in_b2(&m, &kinetic_moment_solid(&m, s2, o2, f0))
        ) <= TOLERANCE
    );
    assert!(
        worst(
            &m,
            "delta(O2,2/0) in B2",
            &in_b2(&m, &dynamic_moment_solid(&m, s2, o2, f0))
        ) <= TOLERANCE
    );
}

#[test]
fn huygens_with_the_wrong_sign_is_caught() {
    let m = regulator();
    let (s2, o2, f0) = (
        m.find_body("2").unwrap(),
        m.point("O2").unwrap(),
        m.frames().ground(),
    );
    let b = m.body(s2);
    let ig = inertia_at_centre(&m, s2).unwrap();
    let og = m.points().vector(o2, b.centre);
    let term = Inertia::point_mass(m.frames(), ig.point, ig.basis, &b.mass, &og);
    let wrong_io2 = ig.minus(&term); // should be plus
    let om = omega(&m, b.frame, f0);
    let v_o2 = velocity(&m, o2, b.frame, f0);
    let sigma = wrong_io2
        .apply(m.frames(), &om)
        .add(&og.cross(m.frames(), &v_o2).scale(&b.mass));
    assert!(worst(&m, "sigma(O2,2/0) in B2", &in_b2(&m, &sigma)) > 1e-3);
}

#[test]
fn delta_without_the_complementary_term_is_caught() {
    let m = regulator();
    let (s2, o2, f0) = (
        m.find_body("2").unwrap(),
        m.point("O2").unwrap(),
        m.frames().ground(),
    );
    let d_sigma = kinetic_moment_solid(&m, s2, o2, f0).derivative_in(m.frames(), f0);
    assert!(!point_velocity(&m, o2, f0).is_zero(m.frames()));
    assert!(worst(&m, "delta(O2,2/0) in B2", &in_b2(&m, &d_sigma)) > 1e-3);
}

#[test]
fn a_transposed_dcm_is_caught() {
    let m = regulator();
    let (g2, f0, f2) = (m.point("G2").unwrap(), m.frames().ground(), frame(&m, "2"));
    let v = velocity(&m, g2, f2, f0);
    let c0 = v.express_in(m.frames(), f0);
    // Right: components in B2 = Pᵀ c0 with P = dcm(B0, B2). Wrong: P c0.
    let p = m.frames().dcm(f0, f2);
    let wrong: [Expr; 3] = std::array::from_fn(|i| {
        &(&(&p[i][0] * &c0[0]) + &(&p[i][1] * &c0[1])) + &(&p[i][2] * &c0[2])
    });
    let right: [Expr; 3] = std::array::from_fn(|i| {
        &(&(&p[0][i] * &c0[0]) + &(&p[1][i] * &c0[1])) + &(&p[2][i] * &c0[2])
    });
    let q = "V(G2,2/0) in B2";
    assert!(
        worst(
            &m,
            q,
            &Value::Vector {
                basis: f2,
                components: right
            }
        ) <= TOLERANCE
    );
    assert!(
        worst(
            &m,
            q,
            &Value::Vector {
                basis: f2,
                components: wrong
            }
        ) > 1e-3
    );
}

#[test]
fn the_whole_regulator_passes_check_under_every_hypothesis() {
    let m = regulator();
    let r = torseur::check::check(&m, 10, 3).unwrap();
    assert_eq!(
        r.rows.len(),
        m.quantities().len() * (1 + m.hypotheses().len())
    );
    assert!(r.passed(), "{r}");
}

/// The pendulum on a cart with the inertia of its pendulum written as the course often does:
/// entries that are sums (`C2 + m*l^2/3`), or read through an alias. `matrix[2][2]` is given.
fn cart_with_inertia(aliases: serde_json::Value, c: &str) -> torseur::mechanism::Mechanism {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/pendule_sur_chariot.json"
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["aliases"] = aliases;
    v["solids"][1]["inertia"]["matrix"] =
        serde_json::json!([["A2 + m*l^2", "0", "0"], ["0", "B2", "0"], ["0", "0", c]]);
    torseur::spec::from_str(&v.to_string()).expect("the spec loads")
}

/// The float backend samples what the exact side accepts: inertia entries that are sums of
/// parameters, or hold an alias. Each such entry is linear in one parameter found nowhere
/// else, which the backend solves for from its random body. `check` then passes, and still
/// catches a wrong value: σ(G,2/0)·z0 = C_G θ̇ by the definition (Ω(2/0) = θ̇ z0 and G the
/// centre), with C_G the written entry, against C2 θ̇ which forgets the m l²/3.
#[test]
fn inertia_entries_that_are_sums_or_aliases_are_sampled_and_checked() {
    for (m, c_g) in [
        (
            cart_with_inertia(serde_json::json!([]), "C2 + m*l^2/3"),
            "(C2 + m*l^2/3)*dot(theta)",
        ),
        (
            cart_with_inertia(
                serde_json::json!([{"name": "J", "value": "C2 + 4*m*l^2/3"}]),
                "J - m*l^2",
            ),
            "(C2 + m*l^2/3)*dot(theta)",
        ),
    ] {
        let r = torseur::check::check(&m, 10, 3).unwrap();
        assert!(r.passed(), "{r}");
        let right = Value::Scalar(ex(&m, c_g));
        assert!(worst(&m, "sigma(G,2/0).z0", &right) <= TOLERANCE);
        let wrong = Value::Scalar(ex(&m, "C2*dot(theta)"));
        assert!(worst(&m, "sigma(G,2/0).z0", &wrong) > 1e-3);
    }
}

/// A hypothesis that fixes the sign of dry friction (« the block slides down »,
/// `epsilon02 = 1`) is read as given by both sides: the float backend keeps the sign instead
/// of drawing it from its sampled rate, so a true result is never a MISMATCH (before, eom(x)
/// and the power of the actions were reported MISMATCH under H1 at every sample whose drawn
/// rate was negative).
#[test]
fn a_hypothesis_that_fixes_a_friction_sign_is_sampled_with_it() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/bloc_frottement_sec.json"
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["hypotheses"] = serde_json::json!([
        {"name": "H1", "text": "Le bloc descend la pente.", "relations": {"epsilon02": "1"}}
    ]);
    let m = torseur::spec::from_str(&v.to_string()).expect("the spec loads");
    let r = torseur::check::check(&m, 20, 1).unwrap();
    assert!(r.passed(), "{r}");
    assert!(
        r.rows
            .iter()
            .any(|row| row.hypothesis.as_deref() == Some("H1"))
    );
}
