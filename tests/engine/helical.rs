//! The constant π in every expression, and the helical link (« liaison hélicoïdale », vis–
//! écrou): hand derivations of the screw jack of the library (`derivations/verin_a_vis.json`)
//! and of a screw turning in a fixed nut (`tests/specs/vis_ecrou_fixe.json`), the float
//! backend's verdict on both, the components the link transmits on both sides, and the
//! refusals of a helical link written wrong.
//!
//! The sign convention, from the course: a helical link of axis (P, u) and pitch p between S1
//! and S2 imposes the screw motion V(P ∈ 2/1)·u = p/(2π) Ω(2/1)·u, p > 0 for a right-hand
//! thread; perfect, its power X V·u + L Ω·u is zero, so its axial moment is L = −p X/(2π).

use super::*;
use torseur::derivation::{Value, derive};
use torseur::quantity::Quantity;

fn library(name: &str) -> Mechanism {
    torseur::spec::load(format!(
        "{}/derivations/{name}.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn test_spec(name: &str) -> Mechanism {
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

#[test]
fn pi_is_an_exact_constant_of_no_dimension() {
    let reg = torseur::expr::Registry::builder()
        .parameters(&["p".into(), "R".into()])
        .coordinate("theta", torseur::spec::wire::CoordinateKind::Angle)
        .inverses(&["pi".into()])
        .build()
        .unwrap();
    let e = |s: &str| reg.parse(s).unwrap_or_else(|err| panic!("{s}: {err}"));
    // Kept as itself: never a number, so 2 π R − π R = π R exactly and π/π = 1.
    assert_eq!(e("2*pi*R - pi*R"), e("R*pi"));
    assert_ne!(e("pi"), e("355/113"));
    assert_eq!(e("pi/pi"), e("1"));
    assert_eq!(e("p/(2*pi)*2*pi"), e("p"));
    assert_eq!(e("(p/(2*pi))^2*4*pi^2"), e("p^2"));
    // Printed `pi`, and read back.
    let lead = e("p*dot(theta)/(2*pi)");
    assert_eq!(lead.to_string(), "1/2*p*dot(theta)/pi");
    assert_eq!(e(&lead.to_string()), lead);
    assert_eq!(torseur::latex::expr(&e("2*pi*R")), "2\\,\\pi\\,R");
    // Its angles keep their meaning: π/2 turns cos into −sin.
    assert_eq!(e("cos(theta + pi/2)*pi"), e("-pi*sin(theta)"));
    // Evaluated to π by the canonical form's evaluation and by the compiled evaluator.
    let pi_at = reg
        .var_ids()
        .map(|i| match reg.role(i) {
            torseur::expr::VarRole::Parameter(k) => reg.constant_value(k).unwrap_or(0.5),
            torseur::expr::VarRole::Inverse(k) => 1.0 / reg.constant_value(k).unwrap_or(0.5),
            torseur::expr::VarRole::Rate(_, 1) => 3.0,
            _ => 0.0,
        })
        .collect::<Vec<f64>>();
    let want = 0.5 * 3.0 / (2.0 * std::f64::consts::PI);
    assert!((lead.eval(&pi_at) - want).abs() < 1e-15);
    let mut compiled = reg.compile(&[&lead]).unwrap();
    let mut out = [0.0];
    compiled.evaluate(&pi_at, &mut out);
    assert!((out[0] - want).abs() < 1e-14, "{}", out[0]);
}

#[test]
fn pi_refused_where_it_cannot_stand_says_why() {
    let reg = torseur::expr::Registry::new(&["L".into()], &[]).unwrap();
    let said = |text: &str| reg.parse(text).unwrap_err().to_string();
    // A constant angle whose sine is no rational.
    let e = said("L*sin(pi/3)");
    assert!(
        e.contains("multiple of pi/2") && e.contains("sin(pi/3) is not"),
        "{e}"
    );
    // Division by π in a registry that was not told: the spec's registries are.
    let e = said("L/pi");
    assert!(e.contains("division by `pi`"), "{e}");
    // A name `pi` is the constant.
    let e = torseur::spec::from_str(r#"{"title": "t", "parameters": [{"name": "pi"}]}"#)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("at parameters[0].name ")
            && e.ends_with("`pi` is reserved by the expression syntax: it is the constant π"),
        "{e}"
    );
}

/// A disc of radius R, thickness e and density ρ turning about its axis: m = ρ π R² e and
/// C = ρ π R⁴ e / 2, so σ(O,1/0)·z0 = ρ π R⁴ e θ̇ / 2 and Ec = ρ π R⁴ e θ̇² / 4; a motor of
/// power P0 = C_m θ̇ at speed ω = 2π N (N in turns per second). Masses, inertia entries,
/// actions and aliases hold π; the float backend reads it with its own parser.
const DISC: &str = r#"{"title": "disque",
    "parameters": [{"name": "rho", "unit": "kg/m^3"}, {"name": "R", "unit": "m"},
                   {"name": "e", "unit": "m"}, {"name": "N", "unit": "Hz"},
                   {"name": "P0", "unit": "W"}],
    "aliases": [{"name": "w", "value": "2*pi*N"}],
    "coordinates": [{"name": "theta", "kind": "angle"}],
    "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}}],
    "solids": [{"name": "1", "frame": "1", "mass": "rho*pi*R^2*e", "centre": "O0",
                "inertia": {"point": "O0", "basis": "1", "matrix": [
                    ["rho*pi*R^4*e/4", "0", "0"], ["0", "rho*pi*R^4*e/4", "0"],
                    ["0", "0", "rho*pi*R^4*e/2"]]}}],
    "hypotheses": [{"name": "H", "rates": {"theta": "w"}}],
    "quantities": ["sigma(O0,1/0).z0", "Ec(1/0)", "M(O0,moteur->1).z0", "eom(theta)"],
    "links": [{"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O0", "axis": "z0"}],
    "actions": [{"name": "moteur", "from": "0", "on": "1", "point": "O0",
                 "moment": "P0/(2*pi*N)*z0"}],
    "pfd": [{"isolate": "1", "theorem": "moment", "point": "O0", "on": "z0", "eom": "theta"}]}"#;

#[test]
fn pi_in_masses_inertia_actions_and_aliases_by_hand_and_by_the_float_backend() {
    let m = torseur::spec::from_str(DISC).unwrap();
    torseur::assert_equivalent!(m, "sigma(O0,1/0).z0", "rho*pi*R^4*e*dot(theta)/2");
    torseur::assert_equivalent!(m, "Ec(1/0)", "pi*rho*e*R^4/4*dot(theta)^2");
    torseur::assert_equivalent!(m, "Ec(1/0)", under "H", "pi^3*rho*e*R^4*N^2");
    torseur::assert_equivalent!(m, "M(O0,moteur->1).z0", "P0/(2*pi*N)");
    torseur::assert_equivalent!(m, "eom(theta)", "rho*pi*R^4*e/2*ddot(theta) = P0/(2*pi*N)");
    // `verify` reads π in a typed relation, dividing by it on either side.
    torseur::assert_equivalent!(m, "M(O0,moteur->1).z0", "P0/w");
    let v = torseur::verify::verify_equation(&m, "2*pi*N*M(O0,moteur->1).z0 = P0", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    // Every term homogeneous: π has no dimension.
    let dims = torseur::units::Dimensions::of(&m);
    let d = torseur::units::dimension(&scalar(&m, "Ec(1/0)"), &dims).unwrap();
    assert_eq!(d, Some(torseur::units::Dimension::ENERGY));
    // `eval` gives π its value: Ec at θ̇ = 3 is π ρ e R⁴ · 9/4.
    let values: torseur::output::Values = serde_json::from_str(
        r#"{"parameters": {"rho": 7800, "R": 0.1, "e": 0.02, "N": 10, "P0": 500},
            "coordinates": {"theta": [0.3, 3, 0]}}"#,
    )
    .unwrap();
    let ec = scalar(&m, "Ec(1/0)");
    let point = torseur::output::numeric_point_for(&m, &values, &[&ec]).unwrap();
    let want = std::f64::consts::PI * 7800.0 * 0.02 * 1e-4 * 9.0 / 4.0;
    assert!(
        (ec.eval(&point) - want).abs() < 1e-12 * want,
        "{}",
        ec.eval(&point)
    );
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn screw_jack_by_hand() {
    // S1 the screw turns by θ about z0 on the frame (pivot at O), S2 the carriage slides by λ
    // along z0 (OG2 = λ z0), a right-hand helical link of pitch p between them, axis (O, z0).
    // Motion 2/1: Ω(2/1) = Ω(2/0) − Ω(1/0) = −θ̇ z0, V(O ∈ 2/1) = V(O ∈ 2/0) − V(O ∈ 1/0) =
    // λ̇ z0 − 0 (every point of S2 moves by λ̇ z0; O is on the pivot's axis). The screw motion
    // λ̇ = p/(2π) (−θ̇) gives θ̇ = −2π λ̇/p, θ̈ = −2π λ̈/p (λ free, θ determined).
    // Ec(E/0) = ½ J θ̇² + ½ M λ̇² = ½ (M + 4π² J/p²) λ̇², so J_eq(λ) = M + 4π² J/p².
    // Isolate S2, resultant on z0: M λ̈ = Z_H − M g (the slider transmits no axial force), so
    // Z_H = M (λ̈ + g). The torsor of 1 on 2 at O: resultant X_H x0 + Y_H y0 + Z_H z0, moment
    // L_H x0 + M_H y0 + N_H z0 with N_H = −p Z_H/(2π) (zero power: Z_H λ̇ + N_H (2π λ̇/p) = 0).
    // Isolate S1, moment at O on z0: δ(O,1/0)·z0 = J θ̈ (O fixed, on the axis); actions: the
    // motor C_m, the pivot none along z0, the nut −N_H = p Z_H/(2π), the weight none (G1 = O).
    // C_m = J θ̈ − p Z_H/(2π) = −2π J λ̈/p − p M (λ̈ + g)/(2π).
    // At constant speed λ̇ = V (H1): C_m = −M g p/(2π).
    // Powers: P(ext→E/0) = C_m θ̇ − M g λ̇ = −2π C_m λ̇/p − M g λ̇; Pint(E) = 0.
    let m = library("verin_a_vis");
    torseur::assert_equivalent!(m, "Omega(1/0)", "-2*pi*dot(lambda)/p*z0");
    torseur::assert_equivalent!(m, "V(G2,2/0)", "dot(lambda)*z0");
    torseur::assert_equivalent!(m, "{V(2/1)}_O", "[2*pi/p*dot(lambda)*z0, dot(lambda)*z0]");
    torseur::assert_equivalent!(m, "Ec(E/0)", "1/2*(M + 4*pi^2*J/p^2)*dot(lambda)^2");
    torseur::assert_equivalent!(m, "J_eq(lambda)", "M + J*(2*pi/p)^2");
    torseur::assert_equivalent!(m, "Z_H", "M*(ddot(lambda) + g)");
    torseur::assert_equivalent!(
        m,
        "{T(1->2)}_O",
        "[X_H*x0 + Y_H*y0 + Z_H*z0, L_H*x0 + M_H*y0 - p*Z_H/(2*pi)*z0]"
    );
    torseur::assert_equivalent!(
        m,
        "C_m",
        "-(p/(2*pi))*((M + J*(2*pi/p)^2)*ddot(lambda) + M*g)"
    );
    torseur::assert_equivalent!(m, "C_m", under "H1", "-M*g*p/(2*pi)");
    torseur::assert_equivalent!(
        m,
        "P(ext->E/0)",
        "-2*pi*C_m*dot(lambda)/p - M*g*dot(lambda)"
    );
    torseur::assert_equivalent!(m, "Pint(E)", "0");
    // The key's formulas are proven by `printed/mod.rs`; the float backend agrees with all of it.
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn screw_turning_in_a_fixed_nut_by_hand() {
    // The nut is the frame: S1 turns by θ and its centre rises by p θ/(2π) (OG = p θ/(2π) z0),
    // the positions following the screw motion, so the link determines no coordinate.
    // V(G,1/0) = p θ̇/(2π) z0; at O (fixed, on the axis), V(O ∈ 1/0) = V(G) + θ̇ z0 ∧ GO =
    // p θ̇/(2π) z0, the kinematic torsor {θ̇ z0 ; p θ̇/(2π) z0}_O of a screw motion.
    // Resultant on z0: m p θ̈/(2π) = Z_H − m g, Z_H = m (g + p θ̈/(2π)). Moment at O on z0:
    // δ(O,1/0)·z0 = C θ̈ (G on the axis), actions C_m + N_H, N_H = −p Z_H/(2π):
    // (C + m p²/(4π²)) θ̈ + m g p/(2π) − C_m = 0.
    // Ec = ½ C θ̇² + ½ m p² θ̇²/(4π²); P(ext→1/0) = C_m θ̇ − m g p θ̇/(2π) (the link's power is
    // zero: Z_H p θ̇/(2π) + N_H θ̇ = 0).
    let m = test_spec("vis_ecrou_fixe");
    torseur::assert_equivalent!(m, "V(G,1/0)", "p*dot(theta)/(2*pi)*z0");
    torseur::assert_equivalent!(m, "{V(1/0)}_O", "[dot(theta)*z0, p*dot(theta)/(2*pi)*z0]");
    torseur::assert_equivalent!(m, "Z_H", "m*(g + p*ddot(theta)/(2*pi))");
    torseur::assert_equivalent!(
        m,
        "eom(theta)",
        "(C + m*p^2/(4*pi^2))*ddot(theta) + m*g*p/(2*pi) - C_m = 0"
    );
    torseur::assert_equivalent!(m, "Ec(1/0)", "1/2*(C + m*p^2/(4*pi^2))*dot(theta)^2");
    torseur::assert_equivalent!(m, "P(ext->1/0)", "C_m*dot(theta) - m*g*p*dot(theta)/(2*pi)");
    let report = torseur::check::check(&m, 10, 1).unwrap();
    assert!(report.passed(), "{report}");
}

#[test]
fn a_helical_link_transmits_five_unknowns_on_both_sides() {
    // The resultant and the moment normal to the axis; the axial moment is no unknown.
    let text = std::fs::read_to_string(format!(
        "{}/derivations/verin_a_vis.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let m = torseur::spec::from_str(&text).unwrap();
    let want = [
        "X01", "Y01", "Z01", "L01", "M01", "X02", "Y02", "L02", "M02", "N02", "X_H", "Y_H", "Z_H",
        "L_H", "M_H", "C_m",
    ];
    assert_eq!(m.reg().unknowns(), want);
    let wire: torseur::spec::wire::SpecFile = serde_json::from_str(&text).unwrap();
    let float = torseur::numeric::NumericModel::new(&wire).unwrap();
    assert_eq!(float.unknown_names().collect::<Vec<_>>(), want);
}

/// The screw jack with `edit` applied: the exact side's refusal, and whether the float
/// backend refuses it too.
fn refused(edit: &dyn Fn(&mut serde_json::Value)) -> (String, bool) {
    let text = std::fs::read_to_string(format!(
        "{}/derivations/verin_a_vis.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    let e = torseur::spec::from_str(&v.to_string()).expect_err("refused");
    let wire: torseur::spec::wire::SpecFile = serde_json::from_value(v).unwrap();
    (
        e.to_string(),
        torseur::numeric::NumericModel::new(&wire).is_err(),
    )
}

type Edit = dyn Fn(&mut serde_json::Value);

/// Removes a field of the helical link of the screw jack.
fn remove(v: &mut serde_json::Value, field: &str) {
    v["links"][2].as_object_mut().unwrap().remove(field);
}

#[test]
fn a_helical_link_written_wrong_is_refused_with_its_place() {
    use serde_json::json;
    // (the edit, the exact side's message, whether the float backend refuses it too: it
    // reads no units, so it takes a pitch of the wrong dimension)
    let cases: [(&'static Edit, &str, bool); 11] = [
        (
            &|v| remove(v, "pitch"),
            "links[2].pitch: a helical link needs its pitch",
            true,
        ),
        (
            &|v| v["links"][0]["pitch"] = json!("p"),
            "links[0].pitch: only a helical link (`helical`) has a pitch",
            true,
        ),
        (
            &|v| v["links"][0]["dependent"] = json!("theta"),
            "links[0].dependent: only a helical link",
            true,
        ),
        (
            &|v| v["links"][2]["dependent"] = json!("phi"),
            "links[2].dependent: unknown coordinate `phi`",
            true,
        ),
        (
            &|v| v["links"][2]["pitch"] = json!("M"),
            "links[2].pitch: the pitch `M` is in kg, not a length",
            false,
        ),
        // A bare number has no unit: both sides refuse it (π too), and say what to type.
        (
            &|v| v["links"][2]["pitch"] = json!("2"),
            "links[2].pitch: the pitch `2` is a pure number, not a length (m per turn): name a \
             parameter of unit m",
            true,
        ),
        (
            &|v| v["links"][2]["pitch"] = json!("2*pi"),
            "links[2].pitch: the pitch `2*pi` is a pure number, not a length (m per turn)",
            true,
        ),
        (
            &|v| v["links"][2]["pitch"] = json!("p*lambda"),
            "links[2].pitch: the pitch `p*lambda` is not a constant of the parameters",
            true,
        ),
        (
            &|v| v["links"][2]["pitch"] = json!("p*C_m"),
            "links[2].pitch: the pitch `p*C_m` is not a constant of the parameters",
            true,
        ),
        (
            &|v| remove(v, "dependent"),
            "links[2].dependent: the positions do not follow the screw motion",
            true,
        ),
        (
            &|v| v["coordinates"][0]["rate"] = json!("V"),
            "coordinates[0].rate: a mechanism with a helical link that determines a coordinate \
             takes free rates only",
            true,
        ),
    ];
    for (edit, want, float) in cases {
        let (e, float_refused) = refused(edit);
        let (path, why) = want.split_once(": ").unwrap();
        assert!(
            e.starts_with(&format!("at {path} (line ")) || e.starts_with(&format!("at {path}: ")),
            "want {want}\ngot {e}"
        );
        assert!(e.contains(why), "want {want}\ngot {e}");
        assert_eq!(float_refused, float, "float backend on: {want}");
    }
}

#[test]
fn a_pitch_without_unit_is_refused_by_the_float_backend_in_the_same_words() {
    let text = std::fs::read_to_string(format!(
        "{}/derivations/verin_a_vis.json",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["links"][2]["pitch"] = serde_json::json!("3/2");
    let wire: torseur::spec::wire::SpecFile = serde_json::from_value(v).unwrap();
    let e = torseur::numeric::NumericModel::new(&wire)
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("links[2].pitch"), "{e}");
    assert!(
        e.contains(
            "the pitch `3/2` is a pure number, not a length (m per turn): name a parameter of \
             unit m"
        ),
        "{e}"
    );
}

#[test]
fn a_screw_in_a_fixed_nut_runs_up_as_its_closed_form_and_pi_reads_everywhere() {
    // Under a constant torque the equation of motion (C + m p²/(4π²)) θ̈ = C_m − m g p/(2π)
    // gives a constant θ̈ = a, so θ(T) = a T²/2 from rest: `simulate` evaluates π in the
    // compiled equations.
    let path = format!(
        "{}/tests/specs/vis_ecrou_fixe.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    v["scenarios"] = serde_json::json!([{"name": "serrage", "duration": 1.0,
        "values": {"m": 2.0, "p": 0.01, "A": 0.01, "C": 0.002, "g": 9.81, "C_m": 0.5},
        "initial": {"theta": [0.0, 0.0]}}]);
    let m = torseur::spec::from_str(&v.to_string()).unwrap();
    let run = torseur::simulate::simulate(&m, "serrage").unwrap();
    let pi = std::f64::consts::PI;
    let a = (0.5 - 2.0 * 9.81 * 0.01 / (2.0 * pi)) / (0.002 + 2.0 * 1e-4 / (4.0 * pi * pi));
    let theta = run.column("theta").unwrap();
    let last = theta[theta.len() - 1];
    assert!(
        (last - a / 2.0).abs() < 1e-8 * a,
        "θ(1) = {last}, closed form {}",
        a / 2.0
    );
    // `verify` reads π on a spec that never writes it (the regulator).
    let reg = regulator();
    let v =
        torseur::verify::verify_equation(&reg, "2*pi*C_m = 2*pi*delta(O1,E/0).z0", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
    let v = torseur::verify::verify_equation(&reg, "C_m = pi*delta(O1,E/0).z0/pi", None).unwrap();
    assert!(v.is_equivalent(), "{v}");
}
