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
