//! The time derivative of a quantity, d/dt(Ec(E/0)) and [d/dt σ(A,S/0)]_R0 =
//! `d/dt(sigma(A,S/0))|0` (issue 37): hand-derived values at a moving point, the course's
//! relation δ(A,S/0) = [d/dt σ(A,S/0)]_R0 + m V(A/0) ∧ V(G,S/0) on every spec by a route
//! that shares nothing with the derivative's, and the float backend.

use super::*;
use torseur::derivation::{Value, derive_values};
use torseur::quantity::Quantity;

fn cart() -> Mechanism {
    torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/pendule_sur_chariot.json"
    ))
    .unwrap()
}

#[test]
fn the_kinetic_moment_at_the_moving_pivot_of_the_cart_pendulum_by_hand() {
    // Cart at A (OA = x x0), pendulum 2 about (A, z0), AG = −l y2, I_G(2) diagonal (A2, B2,
    // C2) in B2. V(G,2/0) = ẋ x0 + θ̇ z0 ∧ (−l y2) = ẋ x0 + l θ̇ x2.
    // σ(A,2/0) = σ(G,2/0) + AG ∧ m V(G,2/0) = C2 θ̇ z0 − m l ẋ (y2 ∧ x0) − m l² θ̇ (y2 ∧ x2),
    // with y2 ∧ x0 = −cos θ z0 and y2 ∧ x2 = −z0:
    //   σ(A,2/0) = [(C2 + m l²) θ̇ + m l ẋ cos θ] z0.
    // z0 is fixed in R0, so [d/dt σ(A,2/0)]_R0 = [(C2 + m l²) θ̈ + m l (ẍ cos θ − ẋ θ̇ sin θ)] z0.
    // A moves (V(A/0) = ẋ x0): δ(A,2/0) = [d/dt σ]_R0 + V(A/0) ∧ m V(G,2/0), and
    // ẋ x0 ∧ m l θ̇ x2 = m l ẋ θ̇ sin θ z0 cancels the last term: δ(A,2/0)·z0 =
    // (C2 + m l²) θ̈ + m l ẍ cos θ, which the library's hand derivation has.
    let m = cart();
    torseur::assert_equivalent!(
        m,
        "sigma(A,2/0) in B0",
        "((C2 + m*l^2)*dot(theta) + m*l*dot(x)*cos(theta))*z0"
    );
    let hand =
        "((C2 + m*l^2)*ddot(theta) + m*l*(ddot(x)*cos(theta) - dot(x)*dot(theta)*sin(theta)))*z0";
    torseur::assert_equivalent!(m, "d/dt(sigma(A,2/0))|0 in B0", hand);
    torseur::assert_equivalent!(m, "d/dt(sigma(A,2/0))|0 in B2", hand);
    // The projection of the derivative, and the derivative of the projection (z0 is fixed in
    // R0: the same scalar).
    let z = "(C2 + m*l^2)*ddot(theta) + m*l*(ddot(x)*cos(theta) - dot(x)*dot(theta)*sin(theta))";
    torseur::assert_equivalent!(m, "d/dt(sigma(A,2/0))|0.z0", z);
    torseur::assert_equivalent!(m, "d/dt(sigma(A,2/0).z0)", z);
    torseur::assert_equivalent!(
        m,
        "delta(A,2/0).z0",
        "(C2 + m*l^2)*ddot(theta) + m*l*ddot(x)*cos(theta)"
    );
    // A wrong sign on the term of the moving point is caught.
    let wrong = torseur::verify::verify(
        &m,
        "d/dt(sigma(A,2/0))|0.z0",
        "(C2 + m*l^2)*ddot(theta) + m*l*(ddot(x)*cos(theta) + dot(x)*dot(theta)*sin(theta))",
        None,
    )
    .unwrap();
    assert!(!wrong.is_equivalent());
}

#[test]
fn a_velocity_derived_in_two_frames_by_hand() {
    // V(G,2/0) = ẋ x0 + l θ̇ x2. In R0 (dx2/dt = θ̇ y2): Γ(G,2/0) = ẍ x0 + l θ̈ x2 + l θ̇² y2.
    // In R2 its components on B2, x0 = cos θ x2 − sin θ y2, are (ẋ cos θ + l θ̇, −ẋ sin θ, 0),
    // whose derivatives are (ẍ cos θ − ẋ θ̇ sin θ + l θ̈, −ẍ sin θ − ẋ θ̇ cos θ, 0).
    let m = cart();
    torseur::assert_equivalent!(
        m,
        "d/dt(V(G,2/0))|0 in B0",
        "ddot(x)*x0 + l*ddot(theta)*x2 + l*dot(theta)^2*y2"
    );
    torseur::assert_equivalent!(
        m,
        "d/dt(V(G,2/0))|2 in B2",
        "[ddot(x)*cos(theta) - dot(x)*dot(theta)*sin(theta) + l*ddot(theta), \
          -ddot(x)*sin(theta) - dot(x)*dot(theta)*cos(theta), 0]"
    );
    // Ω(2/0) = θ̇ z0: its derivative in R0, and in R2 (the same, Ω ∧ Ω = 0).
    torseur::assert_equivalent!(m, "d/dt(Omega(2/0))|0 in B0", "ddot(theta)*z0");
    torseur::assert_equivalent!(m, "d/dt(Omega(2/0))|2 in B2", "ddot(theta)*z2");
}

#[test]
fn the_kinetic_energy_of_the_cart_pendulum_derived_by_hand() {
    // Ec(E/0) = ½ M ẋ² + ½ m |ẋ x0 + l θ̇ x2|² + ½ C2 θ̇²
    //         = ½ (M + m) ẋ² + m l ẋ θ̇ cos θ + ½ (C2 + m l²) θ̇²,
    // dEc/dt  = (M + m) ẋ ẍ + m l (ẍ θ̇ cos θ + ẋ θ̈ cos θ − ẋ θ̇² sin θ) + (C2 + m l²) θ̇ θ̈.
    let m = cart();
    torseur::assert_equivalent!(
        m,
        "d/dt(Ec(E/0))",
        "(M + m)*dot(x)*ddot(x) + m*l*(ddot(x)*dot(theta)*cos(theta) + dot(x)*ddot(theta)*cos(theta) \
         - dot(x)*dot(theta)^2*sin(theta)) + (C2 + m*l^2)*dot(theta)*ddot(theta)"
    );
}

/// The value of a derived quantity as a vector in the ground basis.
fn ground_vector(m: &Mechanism, q: &str) -> [Expr; 3] {
    let g = m.frames().ground();
    match derive_values(m, &[Quantity::parse(q).unwrap()])
        .unwrap()
        .remove(0)
        .value
    {
        Value::Vector { basis, components } => {
            Vector::new(basis, components).express_in(m.frames(), g)
        }
        v => panic!("{q}: {v:?}"),
    }
}

#[test]
fn delta_is_the_derivative_of_sigma_plus_the_moving_points_term_on_every_spec() {
    // δ(A,S/0) by the fast route (each solid's δ(G) and m Γ(G) carried to A, no derivative
    // of σ(A)), against d/dt(sigma(A,S/0))|0 + m V(A/0) ∧ V(G,S/0), where V(A/0), the
    // velocity of the geometric point A, is taken here as the derivative of the components
    // of OA in B0 (the origin fixed in R0), with no Bour formula.
    let mut checked = 0;
    for path in specs_in(&["derivations", "tests/specs"]) {
        let m = torseur::spec::load(&path).unwrap();
        let g = m.frames().ground();
        let g0 = m.frame_name(g).to_string();
        for b in m.bodies() {
            if b.mass.is_zero() {
                continue;
            }
            let s = &b.name;
            let gn = m.point_name(b.centre).to_string();
            // Two points per solid: its centre and its frame's origin (a pivot, often moving).
            let origin = m.point_name(m.origin(b.frame)).to_string();
            for a in [gn.clone(), origin] {
                let d_sigma = ground_vector(&m, &format!("d/dt(sigma({a},{s}/{g0}))|{g0}"));
                let delta = ground_vector(&m, &format!("delta({a},{s}/{g0}) in B{g0}"));
                let o = m.origin(g);
                let oa = torseur::kinematics::position(&m, o, m.point(&a).unwrap())
                    .derivative_by_components(m.frames(), g);
                let vg = ground_vector(&m, &format!("V({gn},{s}/{g0}) in B{g0}"));
                let term = oa.cross(m.frames(), &Vector::new(g, vg)).scale(&b.mass);
                let sum = Vector::new(g, d_sigma).add(&term).express_in(m.frames(), g);
                assert_eq!(sum, delta, "{}: δ({a},{s}/0)", path.display());
                checked += 1;
            }
        }
    }
    assert!(checked >= 60, "{checked} relations");
}

#[test]
fn derivatives_agree_with_the_float_backend() {
    // The float backend differentiates its own dual-number motion: σ(A) = Σ mₖ (rₖ − a) ∧ vₖ
    // gives Σ mₖ [(vₖ − ȧ) ∧ vₖ + (rₖ − a) ∧ Γₖ], a vector's components in the frame asked are
    // differentiated there (no Bour formula), Ec gives Σ mₖ vₖ·Γₖ.
    for (file, extra) in [
        (
            "derivations/regulateur_centrifuge.json",
            &[
                "d/dt(sigma(O2,2/0))|0",
                "d/dt(sigma(O2,2/0))|1 in B2",
                "d/dt(sigma(O1,E/0))|0.z0",
                "d/dt(sigma(G2,2/0).x2)",
                "d/dt(V(G2,2/0))|1",
                "d/dt(V(O2,2/1))|0",
                "d/dt(Omega(2/0))|0 in B2",
                "d/dt(Rc(E/0))|0",
                "d/dt(Ec(E/0))",
            ][..],
        ),
        (
            "derivations/pendule_sur_chariot.json",
            &[
                "d/dt(sigma(A,2/0))|0",
                "d/dt(sigma(A,E/0))|2",
                "d/dt(V(G,2/0))|2",
                "d/dt(Ec(E/0))",
            ][..],
        ),
        (
            "derivations/bielle_manivelle.json",
            &["d/dt(Ec(E/0))", "d/dt(V(B,3/0))|0"][..],
        ),
        (
            "derivations/roue_sur_plan.json",
            &["d/dt(sigma(I,2/0))|0", "d/dt(V(I,2/0))|0", "d/dt(Ec(2/0))"][..],
        ),
        (
            "derivations/toupie.json",
            &[
                "d/dt(sigma(O,3/0))|0 in B2",
                "d/dt(sigma(G,3/0))|2",
                "d/dt(Omega(3/0))|0",
                "d/dt(Ec(3/0))",
            ][..],
        ),
    ] {
        let text = std::fs::read_to_string(file).unwrap();
        let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let qs = v["quantities"].as_array_mut().unwrap();
        for q in extra {
            qs.push((*q).into());
        }
        let m = match torseur::spec::from_str(&v.to_string()) {
            Ok(m) => m,
            Err(e) => panic!("{file}: {e}"),
        };
        let report = torseur::check::check(&m, 10, 3).unwrap();
        assert!(report.passed(), "{file}: {report}");
        for q in extra {
            assert!(
                report.rows.iter().any(|r| r.quantity == *q),
                "{file}: {q} not checked"
            );
        }
    }
}

#[test]
fn a_wrong_derivative_is_caught_by_the_float_backend() {
    // The derivative of σ(O2,2/0) taken as the derivative of its components in B2 (forgetting
    // that B2 turns): the float backend must see it.
    let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    let model = torseur::numeric::NumericModel::new(m.spec()).unwrap();
    let q = Quantity::parse("d/dt(sigma(O2,2/0))|0 in B2").unwrap();
    let sigma = Quantity::parse("sigma(O2,2/0) in B2").unwrap();
    let Value::Vector { basis, components } = derive_values(&m, &[sigma]).unwrap().remove(0).value
    else {
        panic!()
    };
    let wrong = Value::Vector {
        basis,
        components: components.map(|c| c.dt()),
    };
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(4);
    let row = torseur::check::compare(&m, &model, &q, &wrong, None, 5, &mut rng).unwrap();
    assert!(row.worst > 1e-3, "{row:?}");
    let right = derive_values(&m, std::slice::from_ref(&q))
        .unwrap()
        .remove(0)
        .value;
    let row = torseur::check::compare(&m, &model, &q, &right, None, 5, &mut rng).unwrap();
    assert!(row.worst < 1e-9, "{row:?}");
}
