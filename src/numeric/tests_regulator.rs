//! Tests of the float backend on the course's Application 1, the centrifugal regulator,
//! against results derived by hand (velocities, moments, δ(O2,2/0)·x2) and against the
//! course's relations between its own results; and the principal axes its inertia sampling
//! relies on.

use super::tests::*;
use super::{NumericModel, Sample, cloud};
use nalgebra::{Matrix3, Vector3};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

// ------------------------------------------------------------- the centrifugal regulator

/// `s` with a value for every parameter of `m` it lacks (the regulator's gravity and friction
/// parameters, which the kinematic tests do not use).
pub(super) fn completed(m: &NumericModel, mut s: Sample) -> Sample {
    for name in m.parameter_names() {
        s.parameters.entry(name.to_string()).or_insert(1.0);
    }
    s
}

pub(super) fn regulator_sample(t1: [f64; 3], t2: [f64; 3]) -> Sample {
    let s = sample(
        &[
            ("h1", 0.3),
            ("d1", 0.5),
            ("L1", 0.4),
            ("L2", 0.6),
            ("m1", 2.0),
            ("m2", 0.7),
            ("A1", 2.0),
            ("B1", 3.0),
            ("C1", 4.0),
            ("D1", 0.1),
            ("E1", 0.2),
            ("F1", 0.3),
            ("A2", 0.5),
            ("B2", 0.6),
            ("C2", 0.7),
            ("D2", 0.05),
            ("E2", 0.04),
            ("F2", 0.03),
        ],
        &[("theta1", t1), ("theta2", t2)],
    );
    completed(&model(REGULATOR), s)
}

#[test]
fn regulator_velocity_of_g2_by_hand() {
    let m = model(REGULATOR);
    let (t1, t2) = ([0.7, 1.3, -0.4], [-0.5, 0.8, 0.9]);
    let s = regulator_sample(t1, t2);
    let (l1, l2) = (0.4, 0.6);
    let (c2, s2) = (t2[0].cos(), t2[0].sin());
    // O0G2 = d1 z0 + L1 y1 + L2 y2, so V(G2,2/0) = −L1 θ̇1 x1 + L2 Ω(2/0) ∧ y2
    //   = −(L1 + L2 cos θ2) θ̇1 x2 + L2 θ̇2 z2   (x1 = x2).
    close(
        &vector(&m, "V(G2,2/0) in B2", &s),
        &[-(l1 + l2 * c2) * t1[1], 0.0, l2 * t2[1]],
        TOL,
    );
    // Ω(2/0) = θ̇2 x2 + θ̇1 z1, z1 = sin θ2 y2 + cos θ2 z2.
    close(
        &vector(&m, "Omega(2/0) in B2", &s),
        &[t2[1], t1[1] * s2, t1[1] * c2],
        TOL,
    );
    // Relative to 1: V(G2,2/1) = L2 θ̇2 z2, Γ(G2,2/1) = L2 θ̈2 z2 − L2 θ̇2² y2.
    close(
        &vector(&m, "V(G2,2/1) in B2", &s),
        &[0.0, 0.0, l2 * t2[1]],
        TOL,
    );
    close(
        &vector(&m, "Gamma(G2,2/1) in B2", &s),
        &[0.0, -l2 * t2[1] * t2[1], l2 * t2[2]],
        TOL,
    );
    close(&vector(&m, "Omega(2/1) in B1", &s), &[t2[1], 0.0, 0.0], TOL);
}

#[test]
fn regulator_rotor_moments_by_hand() {
    let m = model(REGULATOR);
    let t1 = [0.7, 1.3, -0.4];
    let s = regulator_sample(t1, [-0.5, 0.8, 0.9]);
    let (c1, d1, e1) = (4.0, 0.1, 0.2);
    let (w, a) = (t1[1], t1[2]);
    // O1 fixed and G1 on the axis: σ(O1,1/0) = I_G1 Ω = θ̇1 (−E1 x1 − D1 y1 + C1 z1).
    close(
        &vector(&m, "sigma(O1,1/0) in B1", &s),
        &[-e1 * w, -d1 * w, c1 * w],
        TOL,
    );
    // δ(O1,1/0) = d/dt σ(O1,1/0) with dx1/dt = θ̇1 y1, dy1/dt = −θ̇1 x1.
    let (r, mo) = torsor(&m, "{D(1/0)}_O1 in B1", &s);
    close(&r, &[0.0; 3], TOL);
    close(
        &mo,
        &[-e1 * a + d1 * w * w, -d1 * a - e1 * w * w, c1 * a],
        TOL,
    );
}

#[test]
fn regulator_delta_o2_x2_under_h2_by_hand() {
    let m = model(REGULATOR);
    for seed in 0..5 {
        let s = m
            .sample_under(&mut ChaCha8Rng::seed_from_u64(seed), "H2")
            .expect("sample under H2");
        let p = &s.parameters;
        let (t1, t2) = (s.coordinates["theta1"], s.coordinates["theta2"]);
        assert_eq!(t1[2], 0.0);
        assert_eq!(t2[2], 0.0);
        // Symmetries of H1: S1's products of inertia vanish, and S2's E2 and F2 (plane
        // (G2, y2, z2)); D2 stays.
        for k in ["D1", "E1", "F1", "E2", "F2"] {
            assert!(p[k].abs() < 1e-12, "{k} = {}", p[k]);
        }
        // δ(G2)·x2 = ((C2 − B2) sin θ2 cos θ2 + D2 cos 2θ2) θ̇1², and O2G2 ∧ m2 Γ(G2) · x2
        // = m2 L2 Γ(G2)·z2 = m2 L2 (L1 + L2 cos θ2) θ̇1² sin θ2.
        let (c2, s2) = (t2[0].cos(), t2[0].sin());
        let w2 = t1[1] * t1[1];
        let expected = (p["C2"] - p["B2"]) * w2 * s2 * c2
            + p["D2"] * (c2 * c2 - s2 * s2) * w2
            + p["m2"] * p["L2"] * (p["L1"] + p["L2"] * c2) * w2 * s2;
        let got = scalar(&m, "delta(O2,2/0).x2", &s);
        assert!(
            (got - expected).abs() < 1e-12 * (1.0 + expected.abs()),
            "{got} != {expected}"
        );
    }
}

/// The Bilan table and the change-of-point formulas hold between values the backend computes
/// from its point clouds (a second route to each).
#[test]
fn regulator_satisfies_the_course_relations() {
    let m = model(REGULATOR);
    for seed in 0..10 {
        let s = m
            .sample(&mut ChaCha8Rng::seed_from_u64(seed))
            .expect("sample");
        let p = &s.parameters;
        let v = |q: &str| vector(&m, q, &s);
        let tol = 1e-11;
        // σ(A) = I_A Ω + m AG ∧ V(A, S/0) at A = O2 (a moving point).
        let i_o2 = matrix(&m, "I(O2,2)", &s);
        let sigma = add(
            mat_vec(i_o2, v("Omega(2/0)")),
            times(
                p["m2"],
                cross(
                    sub(v_pos(&m, &s, "G2"), v_pos(&m, &s, "O2")),
                    v("V(O2,2/0)"),
                ),
            ),
        );
        close(&v("sigma(O2,2/0)"), &sigma, tol);
        // σ(G) = I_G Ω.
        close(
            &v("sigma(G2,2/0)"),
            &mat_vec(matrix(&m, "I(G2,2)", &s), v("Omega(2/0)")),
            tol,
        );
        // Rc = m V(G), Rd = m Γ(G).
        close(&v("Rc(2/0)"), &times(p["m2"], v("V(G2,2/0)")), tol);
        close(&v("Rd(2/0)"), &times(p["m2"], v("Gamma(G2,2/0)")), tol);
        // δ(B) = δ(A) + BA ∧ Rd, σ(B) = σ(A) + BA ∧ Rc.
        let ba = sub(v_pos(&m, &s, "O2"), v_pos(&m, &s, "G1"));
        close(
            &v("delta(G1,E/0)"),
            &add(v("delta(O2,E/0)"), cross(ba, v("Rd(E/0)"))),
            tol,
        );
        close(
            &v("sigma(G1,E/0)"),
            &add(v("sigma(O2,E/0)"), cross(ba, v("Rc(E/0)"))),
            tol,
        );
        // A set's torsor is the sum of its solids' torsors.
        let (r, mo) = torsor(&m, "{D(E/0)}_O2 in B1", &s);
        let (r1, m1) = torsor(&m, "{D(1/0)}_O2 in B1", &s);
        let (r2, m2) = torsor(&m, "{D(2/0)}_O2 in B1", &s);
        close(&r, &add(r1, r2), tol);
        close(&mo, &add(m1, m2), tol);
        // Composition of motions: Ω, V, and Γ with its Coriolis term.
        close(
            &v("Omega(2/0)"),
            &add(v("Omega(2/1)"), v("Omega(1/0)")),
            tol,
        );
        close(&v("V(G2,2/0)"), &add(v("V(G2,2/1)"), v("V(G2,1/0)")), tol);
        close(
            &v("Gamma(G2,2/0)"),
            &add(
                add(v("Gamma(G2,2/1)"), v("Gamma(G2,1/0)")),
                times(2.0, cross(v("Omega(1/0)"), v("V(G2,2/1)"))),
            ),
            tol,
        );
        // Varignon: V(O1,2/0) = V(O2,2/0) + O1O2 ∧ Ω(2/0).
        let o1o2 = sub(v_pos(&m, &s, "O2"), v_pos(&m, &s, "O1"));
        close(
            &v("V(O1,2/0)"),
            &add(v("V(O2,2/0)"), cross(o1o2, v("Omega(2/0)"))),
            tol,
        );
        // A fixed point of 1: σ(O1,1/0) = I_O1(1) Ω(1/0).
        close(
            &v("sigma(O1,1/0)"),
            &mat_vec(matrix(&m, "I(O1,1)", &s), v("Omega(1/0)")),
            tol,
        );
        // The projection is the component.
        let d = vector(&m, "delta(O2,2/0) in B2", &s);
        assert!((scalar(&m, "delta(O2,2/0).x2", &s) - d[0]).abs() < tol * (1.0 + d[0].abs()));
    }
}

/// δ(O2,2/0)·x2 by hand (Euler's equations at G2 for I_G2 with E2 = F2 = 0 in B2, then the
/// transport to O2): (A2 + m2 L2²) θ̈2 + [sin θ2 (m2 L1 L2 + (C2 − B2 + m2 L2²) cos θ2)
/// + D2 cos 2θ2] θ̇1².
fn regulator_delta_o2_x2_hand(s: &Sample) -> f64 {
    let p = &s.parameters;
    let (t1, t2) = (s.coordinates["theta1"], s.coordinates["theta2"]);
    let (m2, l1, l2) = (p["m2"], p["L1"], p["L2"]);
    let (c2, s2) = (t2[0].cos(), t2[0].sin());
    (p["A2"] + m2 * l2 * l2) * t2[2]
        + s2 * (m2 * l1 * l2 + (p["C2"] - p["B2"] + m2 * l2 * l2) * c2) * t1[1] * t1[1]
        + p["D2"] * (c2 * c2 - s2 * s2) * t1[1] * t1[1]
}

/// A sample drawn under the former hypothesis Q1 (exactly diagonal inertia, signed zeros) once gave −5.7911...
#[test]
fn regulator_delta_o2_x2_diagonal_inertia_regression() {
    let m = model(REGULATOR);
    let s = completed(
        &m,
        sample(
            &[
                ("A1", 0.10751785437735437),
                ("A2", 0.45463361815135467),
                ("B1", 0.10751785437735437),
                ("B2", 0.19302692859932108),
                ("C1", 0.09730515755372715),
                ("C2", 0.3300930407199903),
                ("D1", -2.168404344971009e-19),
                ("D2", -0.0),
                ("E1", -0.0),
                ("E2", -0.0),
                ("F1", -0.0),
                ("F2", -0.0),
                ("L1", 0.9831449611249415),
                ("L2", 1.9493208320643345),
                ("d1", 1.8037184852301271),
                ("h1", 0.5474312312749883),
                ("m1", 1.3669761823722646),
                ("m2", 1.8729056984295582),
            ],
            &[
                (
                    "theta1",
                    [1.0660226263051014, 0.7304457436127683, 0.12798499598703827],
                ),
                (
                    "theta2",
                    [1.9974716586931711, -0.5454215664701474, -0.8126133752476417],
                ),
            ],
        ),
    );
    let expected = regulator_delta_o2_x2_hand(&s);
    assert!((expected - -5.867315907923602).abs() < 1e-12 * 5.87);
    let got = scalar(&m, "delta(O2,2/0).x2", &s);
    assert!(
        (got - expected).abs() <= 1e-12 * expected.abs(),
        "{got} != {expected}"
    );
}

/// Samples under H1 (E2 = F2 = 0 in B2, the case of the regression above with D2 free) and
/// random diagonal inertias, against the hand formula.
#[test]
fn regulator_delta_o2_x2_diagonal_inertia_by_hand() {
    let m = model(REGULATOR);
    let mut failures = Vec::new();
    for seed in 0..200 {
        let s = m
            .sample_under(&mut ChaCha8Rng::seed_from_u64(seed), "H1")
            .expect("sample under H1");
        let expected = regulator_delta_o2_x2_hand(&s);
        let got = scalar(&m, "delta(O2,2/0).x2", &s);
        if (got - expected).abs() > 1e-12 * (1.0 + expected.abs()) {
            failures.push((seed, got, expected));
        }
    }
    assert!(failures.is_empty(), "H1 seeds failing: {failures:?}");
    // Diagonal inertias given directly: principal moments A = jy + jz, B = jz + jx,
    // C = jx + jy from second moments jₖ ≥ 0, products of inertia ±0.
    use rand::Rng;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    for _ in 0..200 {
        let mut s = m.sample(&mut rng).expect("sample");
        let j = [0, 1, 2].map(|_| rng.random_range(0.0..=1.0));
        for (k, v) in [
            ("A2", j[1] + j[2]),
            ("B2", j[2] + j[0]),
            ("C2", j[0] + j[1]),
            ("D2", -0.0),
            ("E2", 0.0),
            ("F2", -0.0),
        ] {
            s.parameters.insert(k.into(), v);
        }
        let expected = regulator_delta_o2_x2_hand(&s);
        let got = scalar(&m, "delta(O2,2/0).x2", &s);
        assert!(
            (got - expected).abs() <= 1e-12 * (1.0 + expected.abs()),
            "{s:?}: {got} != {expected}"
        );
    }
}

/// The principal axes: V diag(λ) Vᵀ gives the matrix back and V is orthonormal, including for
/// diagonal matrices carrying rounding noise at the deflation threshold of nalgebra's
/// `SymmetricEigen` (which swapped two axes of the first matrix below), repeated eigenvalues
/// and zeros.
#[test]
fn principal_axes_recompose_the_matrix() {
    use rand::Rng;
    let mut cases: Vec<Matrix3<f64>> = vec![
        // J = tr(I_G2)/2 Id − I_G2 of the regression sample, in B2.
        Matrix3::new(
            0.034243175583978325,
            0.0,
            -4.35610802358069e-17,
            0.0,
            0.2958498651360119,
            0.0,
            -4.35610802358069e-17,
            0.0,
            0.1587837530153427,
        ),
        Matrix3::zeros(),
        Matrix3::from_diagonal_element(2.0),
        Matrix3::from_diagonal(&Vector3::new(1.0, 3.0, 0.0)),
        Matrix3::new(1.0, 1e-300, 0.0, 1e-300, 1.0, 5e-324, 0.0, 5e-324, -0.0),
        Matrix3::repeat(1.0),
    ];
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    for _ in 0..300 {
        let mut a = Matrix3::zeros();
        let noise = [1.0, 1e-8, 1e-16, 1e-17][rng.random_range(0..4)];
        for r in 0..3 {
            a[(r, r)] = rng.random_range(-1.0..=1.0);
            for c in 0..r {
                let x = noise * rng.random_range(-1.0..=1.0);
                a[(r, c)] = x;
                a[(c, r)] = x;
            }
        }
        if rng.random_bool(0.3) {
            a[(1, 1)] = a[(0, 0)];
        }
        cases.push(a);
    }
    for a in cases {
        let (values, v) = cloud::symmetric_eigen(&a);
        let back = v * Matrix3::from_diagonal(&Vector3::from(values)) * v.transpose();
        // Entry by entry (`amax` would pass over a NaN).
        let tol = 1e-14 * a.amax();
        assert!(
            (back - a).iter().all(|x| x.abs() <= tol),
            "{a}: V diag{values:?} Vᵀ = {back}"
        );
        let gram = v.transpose() * v - Matrix3::identity();
        assert!(
            gram.iter().all(|x| x.abs() <= 1e-14),
            "{a}: V = {v} is not orthonormal"
        );
    }
}
