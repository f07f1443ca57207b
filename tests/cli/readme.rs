//! The README's first spec is the file it names, and what the README shows of it is what the
//! binary prints; its results are also checked against a derivation by hand.

use super::*;

/// The fenced block of `lang` that follows `heading` in the README.
fn block_after(readme: &str, heading: &str, lang: &str) -> String {
    let at = readme.find(heading).expect("the README has the section");
    let rest = &readme[at..];
    let open = format!("```{lang}\n");
    let start = rest.find(&open).expect("a fenced block") + open.len();
    let len = rest[start..].find("```").expect("closed");
    rest[start..start + len].to_string()
}

/// `a 'b c' d` → [a, "b c", d]: the quoting the README's commands use.
fn words(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    for c in line.chars() {
        match c {
            '\'' => quoted = !quoted,
            ' ' if !quoted => {
                if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
            }
            _ => cur.push(c),
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn the_first_spec_of_the_readme_is_the_example_file() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let shown: serde_json::Value =
        serde_json::from_str(&block_after(&readme, "## Your first spec", "json")).unwrap();
    let file: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("examples/pendule_simple.json")).unwrap(),
    )
    .unwrap();
    assert_eq!(shown, file);
}

/// Every command of the section's console block that writes nothing runs, exits 0 and prints
/// exactly the lines shown under it.
#[test]
fn the_first_spec_prints_what_the_readme_shows() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let console = block_after(&readme, "## Your first spec", "console");
    let mut runs: Vec<(Vec<String>, String)> = Vec::new();
    for line in console.lines() {
        if let Some(cmd) = line.strip_prefix("$ torseur ") {
            let cmd = cmd.split("  #").next().unwrap_or(cmd);
            runs.push((words(cmd), String::new()));
        } else if let Some((_, out)) = runs.last_mut() {
            out.push_str(line);
            out.push('\n');
        }
    }
    assert!(runs.len() >= 3, "{console}");
    let mut ran = 0;
    for (args, shown) in runs {
        if args.iter().any(|a| a == "-o") {
            continue; // writes a file: the answer key is tested elsewhere
        }
        let o = bin().current_dir(root()).args(&args).output().unwrap();
        assert!(o.status.success(), "{args:?}: {}", stderr(&o));
        if !shown.is_empty() {
            assert_eq!(stdout(&o), shown, "{args:?}");
        }
        ran += 1;
    }
    assert!(ran >= 3);
}

/// The pendulum by hand: G = l (sin θ, −cos θ) in B0, so V(G,1/0) = l θ̇ (cos θ, sin θ) and
/// Γ(G,1/0) = l (θ̈ cos θ − θ̇² sin θ, θ̈ sin θ + θ̇² cos θ). A point mass about the fixed O0:
/// δ(O0,1/0)·z0 = m l² θ̈. The moment theorem at O0 on z0: m l² θ̈ = −m g l sin θ. The
/// resultant theorem: X01 = m ẍ_G, Y01 − m g = m ÿ_G.
#[test]
fn the_first_spec_agrees_with_the_pendulum_by_hand() {
    let spec = root().join("examples/pendule_simple.json");
    for (q, hand) in [
        (
            "V(G,1/0)",
            "[l*cos(theta)*dot(theta), l*sin(theta)*dot(theta), 0]",
        ),
        ("delta(O0,1/0).z0", "m*l^2*ddot(theta)"),
        ("eom(theta)", "m*l^2*ddot(theta) + m*g*l*sin(theta)"),
        (
            "X01",
            "m*l*cos(theta)*ddot(theta) - m*l*sin(theta)*dot(theta)^2",
        ),
        (
            "Y01",
            "m*g + m*l*sin(theta)*ddot(theta) + m*l*cos(theta)*dot(theta)^2",
        ),
    ] {
        let o = run(&["verify", spec.to_str().unwrap(), "-q", q, "-e", hand]);
        assert!(o.status.success(), "{q}: {}{}", stdout(&o), stderr(&o));
    }
    // And a sign error is caught (exit 1).
    let o = run(&[
        "verify",
        spec.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        "m*l^2*ddot(theta) - m*g*l*sin(theta)",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}

/// The modelling rules' snippets are what the spec reads: the solid with its inertia and the
/// motor are a `solids` and an `actions` entry (unknown fields are refused by the spec's types).
#[test]
fn the_modelling_rules_snippets_are_spec_entries() {
    let readme = std::fs::read_to_string(root().join("README.md")).unwrap();
    let solid = block_after(&readme, "- **Solids.**", "json");
    let solid: torseur::wire::SolidSpec = serde_json::from_str(&solid).unwrap();
    assert_eq!(solid.name, "1");
    let action = block_after(&readme, "- **Actions**", "json");
    let action: torseur::wire::ActionSpec = serde_json::from_str(&action).unwrap();
    assert_eq!(action.name, "moteur");
}
