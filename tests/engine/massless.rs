//! Bodies of negligible mass (« de masse négligeable »): a gimbal, a nacelle, a support that
//! carries links and actions. Their kinetic and dynamic torsors and their kinetic energy are
//! zero, said so and never derived; isolated, the PFD is the balance of the actions on them.
//! The gyroscope in a massless Cardan suspension (`derivations/gyroscope_cardan.json`) is
//! derived by hand below and checked against the float backend, which reads the massless
//! bodies with its own code (an empty point cloud).

use torseur::derivation::{StepKind, Value, derive};
use torseur::mechanism::Mechanism;
use torseur::quantity::Quantity;

fn gyroscope() -> Mechanism {
    torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/gyroscope_cardan.json"
    ))
    .expect("the gyroscope loads")
}

fn q(s: &str) -> Quantity {
    Quantity::parse(s).unwrap()
}

/// A vector value in B2 from three hand-typed components.
fn in_b2(m: &Mechanism, c: [&str; 3]) -> Value {
    Value::Vector {
        basis: m.frames().find("2").unwrap(),
        components: c.map(|x| m.reg().parse(x).unwrap()),
    }
}

/// Hand-typed value `v` of `quantity`: the exact derivation gives it, and the float backend
/// agrees with it (10 samples).
fn by_hand(m: &Mechanism, quantity: &str, v: &Value) {
    let d = derive(m, &q(quantity)).unwrap();
    assert_eq!(d.value.exprs(), v.exprs(), "{quantity}");
    let model = torseur::numeric::NumericModel::new(m.spec()).unwrap();
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(3);
    let report = torseur::check::compare(m, &model, &q(quantity), v, None, 10, &mut rng).unwrap();
    assert!(
        report.worst <= torseur::check::TOLERANCE,
        "{quantity}: {}",
        report.worst
    );
}

#[test]
fn gyroscope_in_a_massless_gimbal_by_hand() {
    // B1 = rot(z0, ψ), B2 = rot(x1, θ), B3 = rot(z2, φ); z0 = z1 = sin θ y2 + cos θ z2.
    // Ω(3/0) = ψ̇ z0 + θ̇ x1 + φ̇ z2 = θ̇ x2 + ψ̇ sin θ y2 + r z2, with r = ψ̇ cos θ + φ̇.
    // The rotor is of revolution about z3 = z2: I_O(3) = diag(A, A, C) in B2 too, so
    // σ(O,3/0) = A θ̇ x2 + A ψ̇ sin θ y2 + C r z2 (O fixed, centre of inertia).
    // δ(O,3/0) = [dσ/dt]_R0 (O fixed) = [dσ/dt]_B2 + Ω(2/0) ∧ σ, Ω(2/0) = (θ̇, ψ̇ s, ψ̇ c):
    //   Ω(2/0) ∧ σ = (C r ψ̇ s − A ψ̇² s c, A θ̇ ψ̇ c − C r θ̇, A θ̇ ψ̇ s − A ψ̇ s θ̇ = 0), so
    //   δ(O,3/0) = (A θ̈ + C r ψ̇ s − A ψ̇² s c, A ψ̈ s + 2 A ψ̇ θ̇ c − C r θ̇, C ṙ),
    //   ṙ = ψ̈ c − ψ̇ θ̇ s + φ̈.
    let m = gyroscope();
    let r = "(dot(psi)*cos(theta) + dot(phi))";
    let omega = [
        "dot(theta)".to_string(),
        "dot(psi)*sin(theta)".into(),
        r.into(),
    ];
    by_hand(
        &m,
        "Omega(3/0) in B2",
        &in_b2(&m, omega.each_ref().map(|s| s.as_str())),
    );
    let sigma = [
        "A*dot(theta)".to_string(),
        "A*dot(psi)*sin(theta)".into(),
        format!("C*{r}"),
    ];
    by_hand(
        &m,
        "sigma(O,3/0) in B2",
        &in_b2(&m, sigma.each_ref().map(|s| s.as_str())),
    );
    let r_dot = "(ddot(psi)*cos(theta) - dot(psi)*dot(theta)*sin(theta) + ddot(phi))";
    let delta = [
        format!("A*ddot(theta) + C*{r}*dot(psi)*sin(theta) - A*dot(psi)^2*sin(theta)*cos(theta)"),
        format!("A*ddot(psi)*sin(theta) + 2*A*dot(psi)*dot(theta)*cos(theta) - C*{r}*dot(theta)"),
        format!("C*{r_dot}"),
    ];
    by_hand(
        &m,
        "delta(O,3/0) in B2",
        &in_b2(&m, delta.each_ref().map(|s| s.as_str())),
    );
    // The inner gimbal 2 has no mass: {D(2/0)} = {0}. Isolated, the moment at O on x2 of the
    // actions on it is zero: the pivot 12 (axis x1 = x2) transmits none on x2, the motor's
    // reaction −C_m z2 none, the pivot 23 (axis z2, unknowns L23, M23 on x2, y2) gives −L23:
    // L23 = 0.
    torseur::assert_equivalent!(m, "L23", "0");
    // Rotor, moment at O on z2 (the pivot 23 transmits none, the weight acts at O):
    //   C ṙ = C_m.
    torseur::assert_equivalent!(m, "eom(phi)", &format!("C*{r_dot} = C_m"));
    // E = {2, 3}, moment at O on x1 = x2: the pivot 12 transmits none, the motor is inside,
    // the weight acts at O; δ(O,E/0) = δ(O,3/0) (2 has no mass):
    //   A θ̈ + C r ψ̇ sin θ − A ψ̇² sin θ cos θ = 0.
    torseur::assert_equivalent!(m, "eom(theta)", &format!("{} = 0", delta[0]));
    // T = {1, 2, 3}, moment at O on z0: the pivot 01 transmits none; δ(O,T/0)·z0 =
    // δ(O,3/0)·z0 = s (A ψ̈ s + 2 A ψ̇ θ̇ c − C r θ̇) + c C ṙ
    //   = (A s² + C c²) ψ̈ + 2 (A − C) ψ̇ θ̇ s c − C θ̇ φ̇ s + C c φ̈ = 0,
    // the derivative of σ(O,T/0)·z0 = A ψ̇ s² + C c r (z0 fixed, O fixed).
    torseur::assert_equivalent!(
        m,
        "eom(psi)",
        "(A*sin(theta)^2 + C*cos(theta)^2)*ddot(psi) \
         + 2*(A - C)*dot(psi)*dot(theta)*sin(theta)*cos(theta) \
         - C*dot(theta)*dot(phi)*sin(theta) + C*cos(theta)*ddot(phi) = 0"
    );
    let z0 = format!("A*dot(psi)*sin(theta)^2 + C*cos(theta)*{r}");
    let sigma_z0 = Value::Scalar(m.reg().parse(&z0).unwrap());
    by_hand(&m, "sigma(O,T/0).z0", &sigma_z0);
    // König, the gimbals without mass: Ec(T/0) = ½ Ω(3/0)·I_O(3) Ω(3/0)
    //   = ½ [A (θ̇² + ψ̇² sin² θ) + C r²].
    let ec = format!("1/2*(A*(dot(theta)^2 + dot(psi)^2*sin(theta)^2) + C*{r}^2)");
    by_hand(&m, "Ec(T/0)", &Value::Scalar(m.reg().parse(&ec).unwrap()));
    // The whole spec passes the float backend's check.
    let report = torseur::check::check(&m, 10, 1).unwrap_or_else(|e| panic!("{e}"));
    assert!(report.passed(), "{report}");
}

/// Every quantity of a massless body is zero in one step that says so (no Ω, no inertia
/// operator, no σ derived for it); in a set, its members of negligible mass add one such step
/// each and nothing else; the bilan lists no weight for them.
#[test]
fn a_massless_body_is_said_so_and_never_derived() {
    let m = gyroscope();
    for s in [
        "sigma(O,1/0)",
        "delta(O,2/0)",
        "{C(1/0)}_O",
        "{D(2/0)}_O",
        "Rc(1/0)",
        "Rd(2/0)",
        "Ec(1/0)",
        "I(O,2)",
    ] {
        let d = derive(&m, &q(s)).unwrap();
        assert!(d.value.exprs().iter().all(|e| e.is_zero()), "{s}");
        assert_eq!(d.steps.len(), 1, "{s}: {:#?}", d.steps);
        assert!(
            matches!(d.steps[0].kind, StepKind::Massless(_)),
            "{s}: {:?}",
            d.steps[0].kind
        );
        assert!(d.steps[0].theorem.contains("masse négligeable"), "{s}");
    }
    let d = derive(&m, &q("delta(O,T/0)")).unwrap();
    let massless: Vec<_> = d
        .steps
        .iter()
        .filter(|s| matches!(s.kind, StepKind::Massless(_)))
        .collect();
    assert_eq!(massless.len(), 2);
    // Nothing else of 1 or 2: every other step is of the rotor 3.
    for s in &d.steps {
        if let StepKind::Quantity(k) = &s.kind {
            let of = match k {
                torseur::quantity::QuantityKind::Inertia { solid, .. } => Some(solid.clone()),
                _ => k.motion().map(|mo| mo.moving.clone()),
            };
            assert_eq!(of.as_deref(), Some("3"), "{}", s.label);
        }
    }
    let t = m.solids_of("T").unwrap();
    let weights: Vec<String> = torseur::pfd::external_actions(&m, &t)
        .iter()
        .filter(|a| a.from_label == "pes")
        .map(|a| a.on_label.clone())
        .collect();
    assert_eq!(weights, ["3"]);
}

/// The key says « est de masse négligeable » in the set-up and where the PFD isolates the
/// gimbal ({D(2/0)} = {0}, then the actions' balance), never « masse ponctuelle », never
/// ½·0·V², never a complementary term with a zero mass.
#[test]
fn the_key_of_a_massless_gimbal_reads_as_the_course() {
    let m = gyroscope();
    let key = torseur::latex::answer_key_document(
        &m,
        torseur::latex::VectorStyle::Sum,
        &torseur::simulate::question_runs(&m),
    )
    .unwrap();
    let tex = &super::printed::course(&key.tex);
    assert!(
        tex.contains("Le solide $S_{1}$ est de masse négligeable"),
        "{tex}"
    );
    assert!(
        tex.contains("Le solide $S_{2}$ est de masse négligeable"),
        "{tex}"
    );
    assert!(
        tex.contains(
            "$S_{2}$ est de masse négligeable : $\\left\\{\\mathcal{D}(2/0)\\right\\}_{} = \\left\\{0\\right\\}$"
        ),
        "{tex}"
    );
    for wrong in [
        "masse ponctuelle",
        "\\frac{1}{2}\\,0",
        "\\wedge 0\\,",
        "m_{1}",
        "m_{2}",
    ] {
        assert!(!tex.contains(wrong), "`{wrong}` in the key");
    }
    // No display derives σ, δ or Ω of a gimbal: the only one of 2 is its zero torsor, boxed.
    for d in &key.displays {
        let of_gimbal = ["(O,1/", "(O,2/", "I(O,1", "I(O,2"]
            .iter()
            .any(|p| d.what.contains(p));
        if of_gimbal {
            assert!(d.value.exprs().iter().all(|e| e.is_zero()), "{}", d.what);
        }
    }
}
