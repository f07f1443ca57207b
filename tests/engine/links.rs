//! The nine perfect links of the course: the components each one transmits, from the course's
//! table (« liaisons parfaites »), on both sides (the exact registry's unknowns and the float
//! backend's); and a mechanism for each kind that no spec of `derivations/` uses (encastrement,
//! pivot glissant, appui plan, linéaire rectiligne, ponctuelle), in `tests/specs/`, against
//! hand derivations and the float backend. Pivot, glissière, rotule and linéaire annulaire are
//! in the library (`library.rs`, `regulator.rs`).

use super::*;
use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;

/// One solid on the ground by one link of `kind`, axis (or normal) `axis`, line direction
/// `direction`, all in the solid's basis B1.
fn one_link(kind: &str, axis: &str, direction: Option<&str>) -> serde_json::Value {
    let mut link = serde_json::json!({"name": "01", "kind": kind, "between": ["0", "1"],
        "point": "P", "axis": axis});
    if let Some(d) = direction {
        link["direction"] = d.into();
    }
    serde_json::json!({"title": "une liaison",
        "parameters": [{"name": "m"}],
        "coordinates": [{"name": "q", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}}],
        "points": [{"name": "P", "from": "O0", "position": "0"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "P"}],
        "links": [link]})
}

#[test]
fn every_link_transmits_the_components_of_the_course_table() {
    // {T(0→1)} at P in the link's basis: X, Y, Z the resultant, L, M, N the moment; a
    // component the link cannot transmit (along a freedom of motion) is not an unknown.
    let table: [(&str, &str, Option<&str>, &[&str]); 21] = [
        ("fixed", "z1", None, &["X", "Y", "Z", "L", "M", "N"]),
        ("pivot", "z1", None, &["X", "Y", "Z", "L", "M"]),
        ("slider", "z1", None, &["X", "Y", "L", "M", "N"]),
        ("pivot_slider", "z1", None, &["X", "Y", "L", "M"]),
        ("ball", "z1", None, &["X", "Y", "Z"]),
        ("plane", "z1", None, &["Z", "L", "M"]),
        ("annular", "z1", None, &["X", "Y"]),
        // Normal z, line along x: the moment is along z ∧ x = y.
        ("line", "z1", Some("x1"), &["Z", "M"]),
        ("line", "z1", Some("y1"), &["Z", "L"]),
        ("point", "z1", None, &["Z"]),
        ("fixed", "x1", None, &["X", "Y", "Z", "L", "M", "N"]),
        ("pivot", "x1", None, &["X", "Y", "Z", "M", "N"]),
        ("slider", "x1", None, &["Y", "Z", "L", "M", "N"]),
        ("pivot_slider", "x1", None, &["Y", "Z", "M", "N"]),
        ("ball", "x1", None, &["X", "Y", "Z"]),
        ("plane", "x1", None, &["X", "M", "N"]),
        ("annular", "x1", None, &["Y", "Z"]),
        ("line", "x1", Some("y1"), &["X", "N"]),
        ("point", "x1", None, &["X"]),
        ("pivot", "y1", None, &["X", "Y", "Z", "L", "N"]),
        ("plane", "y1", None, &["Y", "L", "N"]),
    ];
    for (kind, axis, direction, components) in table {
        let spec = one_link(kind, axis, direction);
        let want: Vec<String> = components.iter().map(|c| format!("{c}01")).collect();
        let m = torseur::spec::from_str(&spec.to_string()).unwrap();
        assert_eq!(
            m.reg().unknowns(),
            want,
            "{kind} of axis {axis}: exact side"
        );
        let wire: torseur::spec::wire::SpecFile = serde_json::from_value(spec).unwrap();
        let float = torseur::numeric::NumericModel::new(&wire).unwrap();
        assert_eq!(
            float.unknown_names().collect::<Vec<_>>(),
            want,
            "{kind} of axis {axis}: float backend"
        );
    }
}

/// Loads `tests/specs/<name>.json`.
fn spec(name: &str) -> Mechanism {
    torseur::spec::load(format!(
        "{}/tests/specs/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn scalar(m: &Mechanism, q: &str) -> Expr {
    match derive(m, &Quantity::parse(q).unwrap()).unwrap().value {
        Value::Scalar(e) => e,
        v => panic!("{q} is not a scalar: {v:?}"),
    }
}

/// Every requested quantity agrees with the float backend, and each `(quantity, value by hand)`
/// holds exactly.
fn assert_by_hand(m: &Mechanism, unknowns: &[&str], by_hand: &[(&str, &str)]) {
    assert_eq!(m.reg().unknowns(), unknowns, "{}", m.spec().title);
    for (q, e) in by_hand {
        assert_eq!(scalar(m, q), ex(m, e), "{}: {q}", m.spec().title);
    }
    let report = torseur::check::check(m, 10, 1).unwrap();
    assert!(report.passed(), "{}:\n{report}", m.spec().title);
}

#[test]
fn encastrement_of_a_blade_on_a_rotor() {
    // Γ(G2,2/0) = (a + b)(θ̈ y1 − θ̇² x1): the resultant theorem on the blade gives X12 and
    // Y12, and Z12 − m2 g = 0 (G2 stays at its height). At A, δ(A,2/0)·z1 = C2 θ̈ +
    // (AG2 ∧ m2 Γ(G2))·z1 = (C2 + m2 b (a + b)) θ̈, the weight has no moment on z1. At A on
    // x1: σ(G2) = θ̇ (−E2, −D2, C2) in B1, δ(G2)·x1 = −E2 θ̈ + D2 θ̇²; (AG2 ∧ m2 Γ)·x1 =
    // −h m2 (a + b) θ̈; the weight gives (AG2 ∧ −m2 g z1)·x1 = 0. On y1: δ(G2)·y1 =
    // −D2 θ̈ − E2 θ̇², (AG2 ∧ m2 Γ)·y1 = −h m2 (a + b) θ̇², the weight m2 g b.
    // Isolating E = {1, 2} at O0 on z0: (C1 + C2 + m2 (a + b)²) θ̈ = Cm.
    let m = spec("liaison_encastrement");
    assert_by_hand(
        &m,
        &[
            "X01", "Y01", "Z01", "L01", "M01", "X12", "Y12", "Z12", "L12", "M12", "N12",
        ],
        &[
            ("eom(theta)", "(C1 + C2 + m2*(a + b)^2)*ddot(theta) - Cm"),
            ("X12", "-m2*(a + b)*dot(theta)^2"),
            ("Y12", "m2*(a + b)*ddot(theta)"),
            ("Z12", "m2*g"),
            (
                "L12",
                "-E2*ddot(theta) + D2*dot(theta)^2 - h*m2*(a + b)*ddot(theta)",
            ),
            (
                "M12",
                "-D2*ddot(theta) - E2*dot(theta)^2 - h*m2*(a + b)*dot(theta)^2 - m2*g*b",
            ),
            ("N12", "(C2 + m2*b*(a + b))*ddot(theta)"),
        ],
    );
}

#[test]
fn pivot_glissant_of_an_eccentric_sleeve() {
    // Γ(G,1/0) = z̈ z0 + e (θ̈ y1 − θ̇² x1). σ(G) = θ̇ (−E, 0, C) in B1, so δ(G) =
    // (−E θ̈, −E θ̇², C θ̈); PG ∧ m Γ(G) = −m e z̈ y1 + m e² θ̈ z1. The weight at P:
    // e x1 ∧ (−m g z1) = m g e y1. The link transmits no force along z1 and no moment on z1:
    // those two equations are the equations of motion.
    let m = spec("liaison_pivot_glissant");
    assert_by_hand(
        &m,
        &["X01", "Y01", "L01", "M01"],
        &[
            ("eom(z)", "m*ddot(z) + m*g"),
            ("eom(theta)", "(C + m*e^2)*ddot(theta)"),
            ("X01", "-m*e*dot(theta)^2"),
            ("Y01", "m*e*ddot(theta)"),
            ("L01", "-E*ddot(theta)"),
            ("M01", "-E*dot(theta)^2 - m*e*ddot(z) - m*g*e"),
        ],
    );
}

#[test]
fn appui_plan_of_a_puck_on_a_table() {
    // G above P: Γ(G,1/0) = ẍ x0 + ÿ y0. σ(G) = θ̇ (−E, −D, C) in B1, δ(G) =
    // θ̈ (−E, −D, C) + θ̇² (D, −E, 0); PG ∧ m Γ(G) = m h (ẍ y0 − ÿ x0), with x0 = cos θ x1 −
    // sin θ y1 and y0 = sin θ x1 + cos θ y1. The weight passes through P.
    let m = spec("liaison_appui_plan");
    assert_by_hand(
        &m,
        &["Z01", "L01", "M01"],
        &[
            ("eom(x)", "m*ddot(x)"),
            ("eom(y)", "m*ddot(y)"),
            ("eom(theta)", "C*ddot(theta)"),
            ("Z01", "m*g"),
            (
                "L01",
                "-E*ddot(theta) + D*dot(theta)^2 + m*h*(ddot(x)*sin(theta) - ddot(y)*cos(theta))",
            ),
            (
                "M01",
                "-D*ddot(theta) - E*dot(theta)^2 + m*h*(ddot(x)*cos(theta) + ddot(y)*sin(theta))",
            ),
        ],
    );
}

#[test]
fn lineaire_rectiligne_of_a_bar_lying_on_a_table() {
    // PG = a x1: Γ(G,1/0) = ẍ x0 + ÿ y0 + a (θ̈ y1 − θ̇² x1). δ(G) = B θ̈ z1 (the bar is of
    // revolution about x1). On y1 at P: δ(P)·y1 = 0 and the weight gives a x1 ∧ (−m g z1) =
    // m g a y1, so M01 = −m g a. On z1: δ(P)·z1 = B θ̈ + m a Γ(G)·y1.
    let m = spec("liaison_lineaire_rectiligne");
    assert_by_hand(
        &m,
        &["Z01", "M01"],
        &[
            (
                "eom(x)",
                "m*ddot(x) - m*a*(sin(theta)*ddot(theta) + cos(theta)*dot(theta)^2)",
            ),
            (
                "eom(y)",
                "m*ddot(y) + m*a*(cos(theta)*ddot(theta) - sin(theta)*dot(theta)^2)",
            ),
            (
                "eom(theta)",
                "(B + m*a^2)*ddot(theta) + m*a*(cos(theta)*ddot(y) - sin(theta)*ddot(x))",
            ),
            ("Z01", "m*g"),
            ("M01", "-m*g*a"),
        ],
    );
}

#[test]
fn ponctuelle_of_a_ball_on_an_incline() {
    // y1 = cos α y0 + sin α z0 and z1 = −sin α y0 + cos α z0: the weight −m g z0 has
    // components −m g sin α on y1 and −m g cos α on z1; the contact only pushes along z1.
    let m = spec("liaison_ponctuelle");
    assert_by_hand(
        &m,
        &["Z02"],
        &[
            ("eom(x)", "m*ddot(x)"),
            ("eom(y)", "m*ddot(y) + m*g*sin(alpha)"),
            ("Z02", "m*g*cos(alpha)"),
        ],
    );
}
