//! The hostile-input corpus (`tests/hostile/corpus.json`): every case runs the binary and is
//! held to its exit code and to the shape of its message — one short error line that holds
//! the expected words, no panic, no abort, no output of symbolica's own besides its notice,
//! and nothing written beside the inputs.

use super::{bin, files_in, stderr, stdout, tmp};
use std::collections::BTreeMap;
use std::path::Path;

#[derive(serde::Deserialize)]
struct Corpus {
    #[allow(dead_code)]
    about: Vec<String>,
    cases: Vec<Case>,
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct Case {
    family: String,
    name: String,
    spec: String,
    args: Vec<String>,
    exit: i32,
    message: String,
    #[serde(default)]
    set: BTreeMap<String, serde_json::Value>,
    spec_text: Option<serde_json::Value>,
    values: Option<String>,
}

/// A value of the corpus: `{repeat, times, before, after}` is a long text, `{hex}` raw bytes,
/// anything else itself.
fn expand(v: &serde_json::Value) -> serde_json::Value {
    match v.get("repeat").and_then(|r| r.as_str()) {
        Some(r) => {
            let times = v["times"].as_u64().unwrap() as usize;
            let before = v["before"].as_str().unwrap_or("");
            let after = v["after"].as_str().unwrap_or("");
            serde_json::Value::String(format!("{before}{}{after}", r.repeat(times)))
        }
        None => v.clone(),
    }
}

fn bytes_of(v: &serde_json::Value) -> Vec<u8> {
    if let Some(h) = v.get("hex").and_then(|h| h.as_str()) {
        return (0..h.len())
            .step_by(2)
            .map(|i| u8::from_str_radix(&h[i..i + 2], 16).unwrap())
            .collect();
    }
    match expand(v) {
        serde_json::Value::String(s) => s.into_bytes(),
        other => other.to_string().into_bytes(),
    }
}

/// Sets the value at a JSON pointer, creating the last key of an object.
fn set(doc: &mut serde_json::Value, pointer: &str, value: serde_json::Value) {
    let (parent, key) = pointer.rsplit_once('/').unwrap();
    let p = doc
        .pointer_mut(parent)
        .unwrap_or_else(|| panic!("no {parent}"));
    match p {
        serde_json::Value::Object(o) => {
            o.insert(key.to_string(), value);
        }
        serde_json::Value::Array(a) => a[key.parse::<usize>().unwrap()] = value,
        _ => panic!("{pointer}: not a container"),
    }
}

fn spec_path(name: &str) -> std::path::PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    match name {
        "patin" => root.join("tests/specs/patin.json"),
        "regulateur" => root.join("derivations/regulateur_centrifuge.json"),
        other => panic!("unknown spec {other}"),
    }
}

/// Runs one case; `Err` says how it failed.
fn run_case(c: &Case) -> Result<(), String> {
    let d = tmp();
    let dir = d.path().join("work");
    std::fs::create_dir(&dir).unwrap();
    let spec = d.path().join("spec.json");
    let bytes = match &c.spec_text {
        Some(t) => bytes_of(t),
        None => {
            let mut doc: serde_json::Value =
                serde_json::from_str(&std::fs::read_to_string(spec_path(&c.spec)).unwrap())
                    .unwrap();
            for (p, v) in &c.set {
                set(&mut doc, p, expand(v));
            }
            doc.to_string().into_bytes()
        }
    };
    std::fs::write(&spec, &bytes).unwrap();
    let values = d.path().join("values.json");
    if let Some(v) = &c.values {
        std::fs::write(&values, v).unwrap();
    }
    let args: Vec<String> = c
        .args
        .iter()
        .map(|a| {
            a.replace("{spec}", spec.to_str().unwrap())
                .replace("{tmp}", dir.to_str().unwrap())
                .replace("{values}", values.to_str().unwrap())
        })
        .collect();
    let o = bin().args(&args).output().unwrap();
    let err = stderr(&o);
    let mut problems = Vec::new();
    if o.status.code() != Some(c.exit) {
        problems.push(format!("exit {:?}, expected {}", o.status.code(), c.exit));
    }
    if err.contains("panicked") || err.contains("RUST_BACKTRACE") {
        problems.push("a panic".to_string());
    }
    if err.contains("WARN") {
        problems.push("symbolica's warnings reached stderr".to_string());
    }
    if c.exit == 2 {
        // torseur's own line, or clap's for a usage error.
        let line = err
            .lines()
            .find(|l| l.starts_with("torseur: error:") || l.starts_with("error:"));
        match line {
            None if c.args.is_empty() && err.contains(&c.message) => {}
            None => problems.push("no error line".to_string()),
            Some(l) => {
                if !l.contains(&c.message) {
                    problems.push(format!("message without `{}`", c.message));
                }
                if l.len() > 600 {
                    problems.push(format!("message of {} bytes", l.len()));
                }
            }
        }
        if !stdout(&o).is_empty() {
            problems.push("output on stdout".to_string());
        }
    }
    let left = files_in(&dir);
    if !left.is_empty() {
        problems.push(format!("wrote {left:?}"));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        let first = err
            .lines()
            .find(|l| l.contains("error"))
            .unwrap_or("")
            .chars()
            .take(300)
            .collect::<String>();
        Err(format!(
            "[{}] {}: {} — stderr: {first}",
            c.family,
            c.name,
            problems.join("; ")
        ))
    }
}

#[test]
fn every_hostile_case_keeps_the_contract() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/hostile/corpus.json");
    let corpus: Corpus = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    let mut by_family: BTreeMap<&str, usize> = BTreeMap::new();
    let mut failures = Vec::new();
    for c in &corpus.cases {
        *by_family.entry(c.family.as_str()).or_default() += 1;
        if let Err(e) = run_case(c) {
            failures.push(e);
        }
    }
    eprintln!("hostile corpus: {} cases {by_family:?}", corpus.cases.len());
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        corpus.cases.len(),
        failures.join("\n")
    );
}
