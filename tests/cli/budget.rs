//! The derivation's budget of terms, through the binary: a blow-up ends within seconds with
//! exit 2 and a message naming what grew, on every command that derives.

use super::{run, stderr, stdout, tmp};
use std::time::{Duration, Instant};

/// Four solids turned by q1 (z), q2 (x), q3 (z), q4 (x), and G4 = O0 + L sⁿ y4 where
/// s = cos q1 + sin q2 + cos q3 + sin q4: a 1.4 kB spec whose position is read at once
/// (C(n + 3, 3) monomials) and whose dynamic moment multiplies expressions of thousands of
/// terms by thousands. Without the budget, n = 16 derives for 28 s to a result of 809,547
/// terms, and n = 32 runs for over five minutes.
fn power(n: u32) -> String {
    let solid = |k: u32| {
        format!(
            r#"{{"name": "{k}", "frame": "{k}", "mass": "m", "centre": "G{k}", "inertia": {{"point": "G{k}", "basis": "{k}", "matrix": [["A", "0", "0"], ["0", "A", "0"], ["0", "0", "A"]]}}}}"#
        )
    };
    format!(
        r#"{{"title": "hostile",
 "parameters": [{{"name": "m", "unit": "kg"}}, {{"name": "L", "unit": "m"}}, {{"name": "A", "unit": "kg m^2"}}],
 "coordinates": [{{"name": "q1", "kind": "angle"}}, {{"name": "q2", "kind": "angle"}}, {{"name": "q3", "kind": "angle"}}, {{"name": "q4", "kind": "angle"}}],
 "frames": [{{"name": "1", "parent": "0", "rotation": {{"axis": "z", "angle": "q1"}}}},
            {{"name": "2", "parent": "1", "rotation": {{"axis": "x", "angle": "q2"}}}},
            {{"name": "3", "parent": "2", "rotation": {{"axis": "z", "angle": "q3"}}}},
            {{"name": "4", "parent": "3", "rotation": {{"axis": "x", "angle": "q4"}}}}],
 "points": [{{"name": "G1", "from": "O0", "position": "L*y1"}},
            {{"name": "G2", "from": "O0", "position": "L*y2"}},
            {{"name": "G3", "from": "O0", "position": "L*y3"}},
            {{"name": "G4", "from": "O0", "position": "L*(cos(q1)+sin(q2)+cos(q3)+sin(q4))^{n}*y4"}}],
 "solids": [{}, {}, {}, {}],
 "quantities": ["delta(O0,4/0).z0"]}}"#,
        solid(1),
        solid(2),
        solid(3),
        solid(4)
    )
}

#[test]
fn a_blow_up_ends_within_seconds_with_exit_2_naming_what_grew() {
    let d = tmp();
    let (p32, p16) = (d.path().join("p32.json"), d.path().join("p16.json"));
    std::fs::write(&p32, power(32)).unwrap();
    std::fs::write(&p16, power(16)).unwrap();
    let (p32, p16) = (p32.to_str().unwrap(), p16.to_str().unwrap());
    let key = d.path().join("key.tex");
    let json = d.path().join("out.json");
    for args in [
        vec!["derive", p32],
        vec!["derive", p16, "--json", json.to_str().unwrap()],
        vec!["check", p16],
        vec!["verify", p16, "-q", "delta(O0,4/0).z0", "-e", "0"],
        vec!["answer-key", p16, "-o", key.to_str().unwrap()],
    ] {
        let start = Instant::now();
        let o = run(&args);
        assert!(
            start.elapsed() < Duration::from_secs(30),
            "{args:?}: {:?}",
            start.elapsed()
        );
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        let err = stderr(&o);
        assert!(
            err.contains(
                "torseur: error: the derivation of delta(O0,4/0).z0 grew past 5,000,000 terms ("
            ),
            "{args:?}: {err}"
        );
        assert!(
            err.contains("--max-terms raises this budget"),
            "{args:?}: {err}"
        );
        assert_eq!(stdout(&o), "", "{args:?}");
    }
    assert!(!key.exists() && !json.exists(), "nothing is written");
}

/// `--max-terms` moves the budget both ways and never changes a result: the regulator's
/// derivation holds a few hundred terms at once, so a budget of 50 stops it (exit 2, the
/// figure named), and any budget it fits in prints the default's output byte for byte.
#[test]
fn max_terms_moves_the_budget_and_never_the_result() {
    let spec = "derivations/regulateur_centrifuge.json";
    let default = run(&["derive", spec]);
    assert_eq!(default.status.code(), Some(0), "{}", stderr(&default));
    let small = run(&["--max-terms", "50", "derive", spec]);
    assert_eq!(small.status.code(), Some(2), "{}", stderr(&small));
    assert!(
        stderr(&small).contains("grew past 50 terms ("),
        "{}",
        stderr(&small)
    );
    assert_eq!(stdout(&small), "");
    for budget in ["100000", "18446744073709551615"] {
        let o = run(&["derive", spec, "--max-terms", budget]);
        assert_eq!(o.status.code(), Some(0), "{budget}: {}", stderr(&o));
        assert_eq!(stdout(&o), stdout(&default), "--max-terms {budget}");
    }
    for bad in ["0", "-3", "1e6", "many", ""] {
        let o = run(&[&format!("--max-terms={bad}"), "derive", spec]);
        assert_eq!(o.status.code(), Some(2), "--max-terms {bad:?}");
        assert!(
            stderr(&o).contains("--max-terms"),
            "{bad:?}: {}",
            stderr(&o)
        );
    }
}
