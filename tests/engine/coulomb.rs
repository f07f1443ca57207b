//! Coulomb's law on a contact's unknowns (issue 37): T = −f N ε while the contact slides, an
//! equation of the PFD beside the theorems, on a point, plane and line contact and on a slider;
//! the limit of sliding as a hypothesis that gives ε; each result derived by hand here and
//! checked against the float backend, which reads the law with its own code; the sliding
//! ladder simulated against its equation integrated here; the refusals, with their place.

use crate::refused_by_both;
use serde_json::json;

fn spec(path: &str) -> serde_json::Value {
    let text = std::fs::read_to_string(format!("{}/{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

fn load(v: &serde_json::Value) -> torseur::mechanism::Mechanism {
    torseur::spec::from_str(&v.to_string()).unwrap()
}

/// The ladder's equation of motion while it slides, by hand, as `lhs = rhs` for `verify`.
///
/// The ladder AB (length L, mass m, centre G in its middle, J about (G, z0)) makes the angle
/// θ = (y0, y1) with the wall: A = L sin θ x0 on the floor, B = L cos θ y0 on the wall,
/// G = (L/2)(sin θ, cos θ), so ẍ_G = h (c θ̈ − s θ̇²), ÿ_G = −h (s θ̈ + c θ̇²) with h = L/2,
/// s = sin θ, c = cos θ. Actions: T_A x0 + N_A y0 at A, N_B x0 + T_B y0 at B, −m g y0 at G.
///   x0: m ẍ_G = T_A + N_B          y0: m ÿ_G = N_A + T_B − m g
///   Coulomb: T_A = −f1 N_A εA,  T_B = −f2 N_B εB
/// so N_B = m ẍ_G + f1 εA N_A and N_A = m (g + ÿ_G) + f2 εB N_B, that is
///   D N_A = m (g + ÿ_G) + f2 εB m ẍ_G,   D = 1 − f1 f2 εA εB,
///   D N_B = D m ẍ_G + f1 εA (D N_A).
/// Moment at G on z0, GA = h (s, −c), GB = h (−s, c):
///   J θ̈ = h (N_A s + T_A c − T_B s − N_B c) = h [N_A (s − f1 εA c) + N_B (f2 εB s − c)],
/// multiplied by D to clear the quotients.
fn ladder_sliding() -> String {
    let xg = "(L/2*(cos(theta)*ddot(theta) - sin(theta)*dot(theta)^2))";
    let yg = "(-L/2*(sin(theta)*ddot(theta) + cos(theta)*dot(theta)^2))";
    let d = "(1 - f1*f2*epsilonA*epsilonB)";
    let dna = format!("(m*(g + {yg}) + f2*epsilonB*m*{xg})");
    let dnb = format!("({d}*m*{xg} + f1*epsilonA*{dna})");
    format!(
        "{d}*J*ddot(theta) = L/2*({dna}*(sin(theta) - f1*epsilonA*cos(theta)) \
         + {dnb}*(f2*epsilonB*sin(theta) - cos(theta)))"
    )
}

#[test]
fn the_ladder_slides_and_holds_at_its_limit_as_derived_by_hand() {
    let m = torseur::spec::load("derivations/echelle_frottement.json").unwrap();
    torseur::assert_equivalent!(m, "eom(theta)", &ladder_sliding());
    // At the limit of sliding (θ = β at rest, εA = 1, εB = −1): D = 1 + f1 f2,
    //   N_A = m g / (1 + f1 f2), N_B = f1 N_A, T_A = −f1 N_A, T_B = f2 N_B,
    // and the moment: N_A [(s − f1 c) − f1 f2 s − f1 c] = 0, so (1 − f1 f2) sin β = 2 f1 cos β.
    torseur::assert_equivalent!(m, "N_A", under "H", "m*g/(1 + f1*f2)");
    torseur::assert_equivalent!(m, "N_B", under "H", "f1*m*g/(1 + f1*f2)");
    torseur::assert_equivalent!(m, "T_A", under "H", "-f1*m*g/(1 + f1*f2)");
    torseur::assert_equivalent!(m, "T_B", under "H", "f1*f2*m*g/(1 + f1*f2)");
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        under "H",
        "(1 - f1*f2)*sin(beta) = 2*f1*cos(beta)"
    );
    // A smooth wall (f2 = 0): tan β = 2 f1, that is f1 = (1/2) cot α with α = π/2 − β the
    // angle with the floor; N_A = m g carries the whole weight.
    torseur::assert_equivalent!(m, "eom(theta)", under "H2", "sin(beta) = 2*f1*cos(beta)");
    torseur::assert_equivalent!(m, "N_A", under "H2", "m*g");
    // A wrong sign of the impending motion is not the limit found.
    let v = torseur::verify::verify(
        &m,
        "eom(theta)",
        "(1 + f1*f2)*sin(beta) = 2*f1*cos(beta)",
        Some("H"),
    )
    .unwrap();
    assert!(!v.is_equivalent(), "{v}");
    let report = torseur::check::check(&m, 12, 3).unwrap();
    assert!(report.passed(), "{report}");
}

/// The block of `bloc_frottement_sec` on its incline, its friction written as Coulomb's law on
/// the unknowns of a link of kind `kind`: whatever the link, m ẍ = −m g sin α − f N ε with
/// N = m g cos α (resultant on y1), and T = −f m g cos α ε.
fn block_on(kind: &str) -> serde_json::Value {
    let mut v = spec("derivations/bloc_frottement_sec.json");
    let link = &mut v["links"][0];
    link.as_object_mut().unwrap().remove("coulomb");
    let unknowns = json!({"T": "T", "N": "N"});
    match kind {
        "slider" => {
            link["contact_friction"] =
                json!({"coefficient": "f", "normal": "y1", "unknowns": unknowns});
        }
        _ => {
            link["kind"] = kind.into();
            link["axis"] = "y1".into();
            if kind == "line" {
                link["direction"] = "z1".into();
            }
            link["contact_friction"] =
                json!({"coefficient": "f", "tangent": "x1", "unknowns": unknowns});
        }
    }
    v["quantities"] = json!(["eom(x)", "N", "T", "P(ext->2/0)"]);
    v.as_object_mut().unwrap().remove("questions");
    v.as_object_mut().unwrap().remove("scenarios");
    v
}

#[test]
fn a_block_slides_alike_on_a_point_a_plane_a_line_contact_and_a_slider() {
    for kind in ["slider", "point", "plane", "line"] {
        let m = load(&block_on(kind));
        torseur::assert_equivalent!(
            m,
            "eom(x)",
            "m*ddot(x) + m*g*sin(alpha) + f*m*g*cos(alpha)*epsilon02 = 0"
        );
        torseur::assert_equivalent!(m, "N", "m*g*cos(alpha)");
        torseur::assert_equivalent!(m, "T", "-f*m*g*cos(alpha)*epsilon02");
        // The power of the actions on the block: the weight's −m g sin α ẋ and T ẋ, T kept as
        // the unknown it is (its value gives −f N |ẋ| ≤ 0 when ε = sgn ẋ).
        torseur::assert_equivalent!(m, "P(ext->2/0)", "(T - m*g*sin(alpha))*dot(x)");
        let report = torseur::check::check(&m, 8, 4).unwrap();
        assert!(report.passed(), "{kind}: {report}");
    }
}

#[test]
fn a_hypothesis_that_gives_the_sign_is_sampled_with_it() {
    // The float backend used to draw ε from its own sampled rates even where a hypothesis
    // sets it: with ε02 = −1 (the block slides down) and ẋ drawn either way, it disagreed.
    for with_law in [false, true] {
        let mut v = if with_law {
            block_on("slider")
        } else {
            spec("derivations/bloc_frottement_sec.json")
        };
        v["hypotheses"] = json!([{"name": "D", "relations": {"epsilon02": "-1"}}]);
        let m = load(&v);
        torseur::assert_equivalent!(
            m,
            "eom(x)",
            under "D",
            "m*ddot(x) + m*g*sin(alpha) - f*m*g*cos(alpha) = 0"
        );
        let report = torseur::check::check(&m, 10, 6).unwrap();
        assert!(report.passed(), "law {with_law}: {report}");
    }
}

/// The ladder sliding from rest, integrated here (RK4) from the equations of the comment of
/// [`ladder_sliding`] with εA = 1, εB = −1 (A moves away from the wall, B down): θ̈, N_A and
/// N_B solve
///   N_B − f1 N_A − m h c θ̈ = −m h s θ̇²,
///   N_A + f2 N_B + m h s θ̈ = m g − m h c θ̇²,
///   J θ̈ − h [N_A (s − f1 c) − N_B (f2 s + c)] = 0.
fn ladder_by_hand(theta: f64, w: f64) -> (f64, f64) {
    let (m, l, j, g, f1, f2) = (10.0, 3.0, 7.5, 9.81, 0.3, 0.3);
    let (h, s, c) = (l / 2.0, theta.sin(), theta.cos());
    // Unknowns (θ̈, N_A, N_B).
    let mut a = [
        [-m * h * c, -f1, 1.0, -m * h * s * w * w],
        [m * h * s, 1.0, f2, m * g - m * h * c * w * w],
        [j, -h * (s - f1 * c), h * (f2 * s + c), 0.0],
    ];
    for p in 0..3 {
        let r = (p..3)
            .max_by(|&x, &y| a[x][p].abs().total_cmp(&a[y][p].abs()))
            .unwrap();
        a.swap(p, r);
        for q in 0..3 {
            if q != p {
                let k = a[q][p] / a[p][p];
                for col in 0..4 {
                    a[q][col] -= k * a[p][col];
                }
            }
        }
    }
    (a[0][3] / a[0][0], a[2][3] / a[2][2])
}

#[test]
fn the_ladder_released_beyond_its_limit_slides_as_integrated_by_hand() {
    let m = torseur::spec::load("derivations/echelle_frottement.json").unwrap();
    let sc = m.spec().scenarios[0].clone();
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let (ts, th) = (&run.times, run.column("theta").unwrap());
    // RK4 on (θ, θ̇) with a small fixed step, compared at each output instant.
    let (mut t, mut y) = (0.0_f64, [0.7_f64, 0.0]);
    let f = |y: [f64; 2]| [y[1], ladder_by_hand(y[0], y[1]).0];
    let dt = 1e-4;
    for (k, &tk) in ts.iter().enumerate() {
        while t + dt <= tk + 1e-12 {
            crate::rk4_step(&f, &mut y, dt);
            t += dt;
        }
        // The last partial step, to the output instant.
        let rest = tk - t;
        if rest > 0.0 {
            crate::rk4_step(&f, &mut y, rest);
            t = tk;
        }
        // The wall still pushes: Coulomb's law with N_B ≥ 0 holds all along.
        assert!(ladder_by_hand(y[0], y[1]).1 > 0.0, "t = {tk}: contact lost");
        assert!(
            (th[k] - y[0]).abs() < 1e-6,
            "t = {tk}: θ = {}, by hand {}",
            th[k],
            y[0]
        );
    }
    // It did slide: from 0.7 rad, well past the limit.
    assert!(*th.last().unwrap() > 0.75, "{:?}", th.last());
}

#[test]
fn the_ladder_below_its_limit_angle_stays() {
    // Against a smooth wall (f2 = 0), released at 0.5 rad < β = atan(2 f1) = 0.5404 rad: the
    // floor's friction holds it (|T_A| = (m g/2) tan θ ≤ f1 m g).
    let m = torseur::spec::load("derivations/echelle_frottement.json").unwrap();
    let mut sc = m.spec().scenarios[0].clone();
    sc.values.insert("f2".into(), 0.0);
    sc.initial.insert("theta".into(), [0.5, 0.0]);
    let run = torseur::simulate::simulate_with(&m, &sc, &[]).unwrap();
    let th = run.column("theta").unwrap();
    assert!(th.iter().all(|x| (x - 0.5).abs() < 1e-6), "{:?}", th.last());
}

#[test]
fn bad_coulomb_laws_are_refused_by_both_sides_with_their_place() {
    let ladder = spec("derivations/echelle_frottement.json");
    let law = "links[0].contact_friction";
    type Change = Box<dyn Fn(&mut serde_json::Value)>;
    let cases: Vec<(Change, &str, &str)> = vec![
        // A link that transmits no tangential force tied to a normal one.
        (
            Box::new(|v| v["links"][0]["kind"] = "ball".into()),
            law,
            "contact (point, plane, line) or a slider",
        ),
        // A coefficient with a unit.
        (
            Box::new(|v| v["links"][0]["contact_friction"]["coefficient"] = "m".into()),
            "links[0].contact_friction.coefficient",
            "pure number",
        ),
        // A coefficient that moves, or holds an unknown.
        (
            Box::new(|v| v["links"][0]["contact_friction"]["coefficient"] = "f1*theta".into()),
            "links[0].contact_friction.coefficient",
            "",
        ),
        (
            Box::new(|v| v["links"][0]["contact_friction"]["coefficient"] = "-1/2".into()),
            "links[0].contact_friction.coefficient",
            "not negative",
        ),
        // The tangent along the normal, in another basis, or missing.
        (
            Box::new(|v| v["links"][0]["contact_friction"]["tangent"] = "y0".into()),
            "links[0].contact_friction.tangent",
            "another basis vector",
        ),
        (
            Box::new(|v| v["links"][0]["contact_friction"]["tangent"] = "x1".into()),
            "links[0].contact_friction.tangent",
            "another basis vector",
        ),
        (
            Box::new(|v| {
                let c = v["links"][0]["contact_friction"].as_object_mut().unwrap();
                c.remove("tangent");
            }),
            law,
            "`tangent`",
        ),
        (
            Box::new(|v| v["links"][0]["contact_friction"]["normal"] = "y0".into()),
            "links[0].contact_friction.normal",
            "its axis",
        ),
        // A sign set to something else than ±1.
        (
            Box::new(|v| v["hypotheses"][0]["relations"]["epsilonA"] = "2".into()),
            "hypotheses[0].relations.epsilonA",
            "1 or -1",
        ),
        // T and N given one name, or T named like another contact's unknown.
        (
            Box::new(|v| v["links"][0]["contact_friction"]["unknowns"]["T"] = "N_A".into()),
            "links[0].contact_friction.unknowns.N",
            "declared twice",
        ),
        (
            Box::new(|v| v["links"][0]["contact_friction"]["unknowns"]["T"] = "T_B".into()),
            "links[1].contact_friction.unknowns.T",
            "declared twice",
        ),
        // T named like a parameter.
        (
            Box::new(|v| v["links"][0]["contact_friction"]["unknowns"]["T"] = "m".into()),
            "links[0].contact_friction.unknowns.T",
            "already a parameter",
        ),
    ];
    for (k, (change, path, why)) in cases.iter().enumerate() {
        let mut v = ladder.clone();
        change(&mut v);
        let (e, f) = refused_by_both(&v);
        assert!(e.contains(path) && e.contains(why), "case {k}: {e}");
        assert!(f.contains(path), "case {k}: {f}");
    }
    // A slider needs its normal, and only that.
    let mut v = block_on("slider");
    v["links"][0]["contact_friction"]
        .as_object_mut()
        .unwrap()
        .remove("normal");
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[0].contact_friction") && e.contains("`normal`"),
        "{e}"
    );
    assert!(f.contains("links[0].contact_friction"), "{f}");
    let mut v = block_on("slider");
    v["links"][0]["contact_friction"]["tangent"] = "x1".into();
    let (e, _) = refused_by_both(&v);
    assert!(e.contains("contact_friction.tangent"), "{e}");
    // Two dry frictions on one link.
    let mut v = block_on("slider");
    v["links"][0]["coulomb"] = "f*m*g".into();
    let (e, f) = refused_by_both(&v);
    assert!(e.contains(law) && e.contains("one or the other"), "{e}");
    assert!(f.contains(law), "{f}");
}

#[test]
fn a_contact_that_does_not_slide_along_its_tangent_is_refused() {
    // The block's contact said to slide along z1, across the slope: it slides along x1.
    let mut v = block_on("point");
    v["links"][0]["contact_friction"]["tangent"] = "z1".into();
    // Each side reads the sliding velocity with its own kinematics: the exact side finds it
    // zero along z1 whatever the motion, the float backend at every state it draws.
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[0].contact_friction") && e.contains("nothing slides"),
        "{e}"
    );
    assert!(
        f.contains("links[0].contact_friction") && f.contains("nothing slides"),
        "{f}"
    );
    // A point that slides along x1 and z1 (a ball on a plane, x and z both free) with the
    // friction said along x1 only.
    let ball = spec("tests/specs/liaison_ponctuelle.json");
    let mut v = ball.clone();
    v["links"][0]["contact_friction"] = json!({"coefficient": "1/2", "tangent": "x1"});
    let (e, f) = refused_by_both(&v);
    assert!(
        e.contains("links[0].contact_friction") && e.contains("across the tangent"),
        "{e}"
    );
    assert!(
        f.contains("links[0].contact_friction") && f.contains("across the tangent"),
        "{f}"
    );
}
