//! The derivation's budget of terms, through the binary: a blow-up ends within seconds with
//! exit 2 and a message naming what grew, on every command that derives.

use super::{run, stderr, stdout, tmp};
use std::time::{Duration, Instant};

#[path = "../shared/power_spec.rs"]
mod power_spec;
use power_spec::power;

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
