//! Messages that keep the contract, seen from the terminal (issue 32, item 6): one line of
//! torseur's, the JSON path or the argument named, nothing printed by symbolica but its licence
//! notice, exit 2. Expected messages written by hand.

use super::{run, spec, stderr, stdout, tmp};
use std::path::PathBuf;

/// The regulator's spec changed by `edit`, in a temporary directory.
fn edited(edit: impl Fn(&mut serde_json::Value)) -> (tempfile::TempDir, PathBuf) {
    let d = tmp();
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(spec()).unwrap()).unwrap();
    edit(&mut v);
    let p = d.path().join("spec.json");
    std::fs::write(&p, v.to_string()).unwrap();
    (d, p)
}

/// The error line of a run that exits 2, after checking that nothing else of torseur's or
/// symbolica's (a log line, colours, a panic) reached stderr or stdout.
fn refused(o: &std::process::Output) -> String {
    let e = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{e}");
    assert!(stdout(o).is_empty(), "{}", stdout(o));
    for bad in ["WARN", "\x1b[", "symbolica::", "panicked"] {
        assert!(!e.contains(bad), "`{bad}` on stderr: {e}");
    }
    let lines: Vec<&str> = e.lines().filter(|l| l.starts_with("torseur:")).collect();
    assert_eq!(lines.len(), 1, "{e}");
    lines[0].to_string()
}

#[test]
fn a_division_by_zero_in_a_spec_prints_no_log_line_of_symbolica() {
    let (_d, p) = edited(|v| v["points"][2]["position"] = "d1/(L1 - L1)*z0 + L1*y1".into());
    let line = refused(&run(&["derive", p.to_str().unwrap(), "-q", "Omega(1/0)"]));
    assert!(
        line.starts_with("torseur: error: at points[2].position (line "),
        "{line}"
    );
    assert!(
        line.ends_with("`d1/(L1 - L1)*z0 + L1*y1`: division by zero: a divisor is equal to 0"),
        "{line}"
    );
}

#[test]
fn a_division_by_zero_in_a_typed_result_prints_no_log_line_of_symbolica() {
    let line = refused(&run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "Omega(2/0).x2",
        "-e",
        "dot(theta2)/(L1 - L1)",
    ]));
    assert_eq!(
        line,
        "torseur: error: `dot(theta2)/(L1 - L1)`: division by zero: a divisor is equal to 0"
    );
}

#[test]
fn a_list_given_for_a_scalar_quantity_says_it_is_a_scalar() {
    let line = refused(&run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "Omega(2/0).x2",
        "-e",
        "[1,2,3]",
    ]));
    assert_eq!(
        line,
        "torseur: error: `Omega(2/0).x2` is a scalar: give one expression, not a list [x, y, z]"
    );
}

#[test]
fn eval_refuses_a_result_that_overflows() {
    let d = tmp();
    let at = d.path().join("values.json");
    std::fs::write(
        &at,
        r#"{"parameters": {"L1": 1e300, "L2": 1, "d1": 1, "h1": 1},
            "coordinates": {"theta1": [0, 1e300, 0], "theta2": [0, 1, 0]}}"#,
    )
    .unwrap();
    let line = refused(&run(&[
        "eval",
        spec().to_str().unwrap(),
        "--at",
        at.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
    ]));
    assert_eq!(
        line,
        "torseur: error: values: `V(G2,2/0) in B2` is not a finite number at these values (a \
         result overflows the floating-point range, or is undefined there)"
    );
}

#[test]
fn simulate_refuses_a_rate_law_that_divides_by_zero_at_its_start_naming_its_path() {
    let (d, p) = edited(|v| v["scenarios"][0]["imposed"][0]["rate"][0]["value"] = "1/t".into());
    let csv = d.path().join("run.csv");
    let o = run(&[
        "simulate",
        p.to_str().unwrap(),
        "--scenario",
        "sans_frottement",
        "-o",
        csv.to_str().unwrap(),
    ]);
    let line = refused(&o);
    assert!(
        line.starts_with("torseur: error: at scenarios[0].imposed[0].rate[0].value (line "),
        "{line}"
    );
    assert!(
        line.ends_with("the rate at t = 0 s, where this piece starts: division by zero"),
        "{line}"
    );
    assert!(!csv.exists());
}

#[test]
fn a_coulomb_law_on_a_link_without_a_contact_exits_2_naming_its_path() {
    // The ladder's floor contact turned into a ball joint, which transmits no tangential force
    // tied to a normal one: refused by derive, check and answer-key alike.
    let d = tmp();
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("derivations/echelle_frottement.json"),
    )
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    v["links"][0]["kind"] = "ball".into();
    let p = d.path().join("spec.json");
    std::fs::write(&p, v.to_string()).unwrap();
    let tex = d.path().join("k.tex");
    let p = p.to_str().unwrap();
    for args in [
        vec!["derive", p, "-q", "N_A"],
        vec!["check", p],
        vec!["answer-key", p, "-o", tex.to_str().unwrap()],
    ] {
        let line = refused(&run(&args));
        assert!(
            line.starts_with("torseur: error: at links[0].contact_friction (line "),
            "{args:?}: {line}"
        );
        assert!(
            line.ends_with(
                "a liaison sphérique (rotule) transmits no tangential force tied to a normal \
                 one: Coulomb's law on a link's unknowns is declared on a contact (point, plane, \
                 line) or a slider"
            ),
            "{args:?}: {line}"
        );
    }
    assert!(!tex.exists());
}

/// The screw jack of the library changed by `edit`, in a temporary directory.
fn jack(edit: impl Fn(&mut serde_json::Value)) -> (tempfile::TempDir, PathBuf) {
    let d = tmp();
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/derivations/verin_a_vis.json");
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    edit(&mut v);
    let p = d.path().join("spec.json");
    std::fs::write(&p, v.to_string()).unwrap();
    (d, p)
}

#[test]
fn a_helical_link_without_its_pitch_or_with_a_mass_for_one_exits_2_at_its_place() {
    let (_d, p) = jack(|v| {
        v["links"][2].as_object_mut().unwrap().remove("pitch");
    });
    let line = refused(&run(&["derive", p.to_str().unwrap(), "-q", "C_m"]));
    // The field is missing: the message names its path, with no line to point at.
    assert!(
        line.starts_with("torseur: error: at links[2].pitch"),
        "{line}"
    );
    assert!(
        line.ends_with(
            "a helical link needs its pitch `pitch`, a length per turn (`p`; negative for a \
             left-hand thread)"
        ),
        "{line}"
    );
    let (_d, p) = jack(|v| v["links"][2]["pitch"] = "M".into());
    let line = refused(&run(&["check", p.to_str().unwrap()]));
    assert!(
        line.starts_with("torseur: error: at links[2].pitch (line "),
        "{line}"
    );
    assert!(
        line.ends_with(
            "the pitch `M` is in kg, not a length (m per turn): name a parameter of unit m"
        ),
        "{line}"
    );
}

#[test]
fn verify_reads_pi_in_a_typed_result() {
    // The carriage rises by p/(2π) per radian the screw turns back: θ̇ = −2π λ̇/p.
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/derivations/verin_a_vis.json");
    let o = run(&[
        "verify",
        path,
        "-q",
        "Omega(1/0).z0",
        "-e",
        "-2*pi*dot(lambda)/p",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(stdout(&o).trim(), "Omega(1/0).z0: equivalent");
    let o = run(&[
        "verify",
        path,
        "-q",
        "Omega(1/0).z0",
        "-e",
        "-pi*dot(lambda)/p",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
}

/// The typos of a first hour (issue 35, item 4), each refused with the fix: the declared name
/// it most likely misspells, the rate to write for a prime, the solid a frame should be. The
/// regulator declares the points O0, O1, G1, O2, G2, the solids 1, 2 and the set E, the
/// coordinates theta1, theta2 and the parameter L1 (among others).
#[test]
fn a_first_hours_typos_are_refused_with_the_name_meant() {
    let s = spec();
    let s = s.to_str().unwrap();
    let said = |args: &[&str]| refused(&run(args));
    assert_eq!(
        said(&["derive", s, "-q", "V(g2,2/0)"]),
        "torseur: error: V(g2,2/0): unknown point `g2` (did you mean `G2`?)"
    );
    assert_eq!(
        said(&["derive", s, "-q", "Omega(2/O)"]),
        "torseur: error: Omega(2/O): unknown solid or frame `O` (did you mean `0`?)"
    );
    let omega = said(&["derive", s, "-q", "omega(2/0)"]);
    assert!(
        omega.starts_with(
            "torseur: error: quantity `omega(2/0)`: unknown quantity `omega` (did you mean \
             `Omega`? known: Omega, V,"
        ),
        "{omega}"
    );
    assert_eq!(
        said(&["verify", s, "-q", "Omega(2/0).x2", "-e", "dot(thta2)"]),
        "torseur: error: unknown name `thta2` in `dot(thta2)`: neither a parameter, a \
         coordinate nor an unknown of the PFD of the spec (did you mean `theta2`?)"
    );
    assert_eq!(
        said(&["verify", s, "-q", "Omega(2/0).x2", "-e", "theta2'"]),
        "torseur: error: cannot parse `theta2'`: `theta2'`: a time derivative is written \
         dot(theta2)"
    );
    // In the spec, at the place: a parameter's case, a point, a solid to isolate.
    let (_d, p) = edited(|v| v["points"][2]["position"] = "d1*z0 + l1*y1".into());
    let line = said(&["check", p.to_str().unwrap()]);
    assert!(
        line.ends_with("unknown name `l1` in `d1*z0 + l1*y1` (did you mean `L1`?)"),
        "{line}"
    );
    let (_d, p) = edited(|v| v["pfd"][0]["isolate"] = "S2".into());
    let line = said(&["check", p.to_str().unwrap()]);
    assert!(
        line.starts_with("torseur: error: at pfd[0].isolate (line "),
        "{line}"
    );
    assert!(
        line.ends_with("unknown solid or set `S2` (did you mean `2`?)"),
        "{line}"
    );
}

/// Issue 37: the rotor isolated alone while the balourd shares its frame with no link gave
/// X01 = 0 without a word; now one line names both solids and the fix, exit 2.
#[test]
fn a_solid_isolated_without_the_mass_on_its_frame_exits_2_naming_the_fix() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("derivations/rotor_balourd.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    for t in v["pfd"].as_array_mut().unwrap() {
        t["isolate"] = "1".into();
    }
    let d = tmp();
    let p = d.path().join("rotor.json");
    std::fs::write(&p, v.to_string()).unwrap();
    for command in ["derive", "check"] {
        let line = refused(&run(&[command, p.to_str().unwrap()]));
        assert!(
            line.starts_with("torseur: error: at pfd[0].isolate (line 1, column "),
            "{line}"
        );
        assert!(
            line.contains("the solids `1` and `2` share a frame with no link between them")
                && line.contains("declare it `\"carried_by\": \"1\"`"),
            "{line}"
        );
    }
}
