//! The JSON Schema of the spec (`spec.schema.json`, generated from the wire types): committed
//! up to date, named by every spec's `$schema`, accepting every spec of the repository and
//! refusing the structural errors the loader refuses. Re-approve a reviewed change of the wire
//! types with `TORSEUR_BLESS=1 cargo test --release --test engine spec_schema`.
//!
//! The schema is checked by a small validator written here for the keywords schemars emits
//! (any other keyword fails the test, so a new one cannot pass unchecked). The `jsonschema`
//! crate would pull about thirty crates into the dev-dependencies and, through the feature
//! resolver 1 that lets `cargo run` and `cargo test` share one build, change the features of
//! crates symbolica is built with (a second, 8-minute build of it).

use serde_json::{Value, json};
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn schema() -> Value {
    let text = std::fs::read_to_string(root().join("spec.schema.json"))
        .expect("spec.schema.json missing: run with TORSEUR_BLESS=1");
    serde_json::from_str(&text).unwrap()
}

/// The errors of `v` against `s` (a schema of `root`'s), each with the JSON path of the value.
fn validate(root: &Value, s: &Value, v: &Value, path: &str, out: &mut Vec<String>) {
    let Some(obj) = s.as_object() else {
        assert_eq!(s, &Value::Bool(true), "a schema is an object or `true`");
        return;
    };
    let at = |what: String| format!("{path}: {what}");
    for (k, x) in obj {
        match k.as_str() {
            "$ref" => {
                let target = x.as_str().unwrap().strip_prefix('#').unwrap();
                let def = root.pointer(target).expect("a $ref within the schema");
                validate(root, def, v, path, out);
            }
            "type" => {
                let types: Vec<&str> = match x {
                    Value::String(t) => vec![t],
                    Value::Array(ts) => ts.iter().map(|t| t.as_str().unwrap()).collect(),
                    _ => panic!("type {x}"),
                };
                let is = |t: &str| match t {
                    "object" => v.is_object(),
                    "array" => v.is_array(),
                    "string" => v.is_string(),
                    "number" => v.is_number(),
                    "integer" => v.is_i64() || v.is_u64(),
                    "boolean" => v.is_boolean(),
                    "null" => v.is_null(),
                    _ => panic!("type {t}"),
                };
                if !types.iter().any(|t| is(t)) {
                    out.push(at(format!("{v} is not of type {x}")));
                }
            }
            "const" if v != x => out.push(at(format!("{v} is not {x}"))),
            "enum" if !x.as_array().unwrap().contains(v) => out.push(at(format!("{v} not in {x}"))),
            "properties" => {
                if let Some(o) = v.as_object() {
                    for (name, sub) in x.as_object().unwrap() {
                        if let Some(y) = o.get(name) {
                            validate(root, sub, y, &format!("{path}.{name}"), out);
                        }
                    }
                }
            }
            "required" => {
                if let Some(o) = v.as_object() {
                    for r in x.as_array().unwrap() {
                        if !o.contains_key(r.as_str().unwrap()) {
                            out.push(at(format!("missing required {r}")));
                        }
                    }
                }
            }
            "additionalProperties" => {
                if let Some(o) = v.as_object() {
                    let known = obj.get("properties").and_then(Value::as_object);
                    for (name, y) in o {
                        if known.is_some_and(|p| p.contains_key(name)) {
                            continue;
                        }
                        match x {
                            Value::Bool(false) => {
                                out.push(at(format!("unknown property `{name}`")))
                            }
                            sub => validate(root, sub, y, &format!("{path}.{name}"), out),
                        }
                    }
                }
            }
            "items" => {
                if let Some(a) = v.as_array() {
                    for (i, y) in a.iter().enumerate() {
                        validate(root, x, y, &format!("{path}[{i}]"), out);
                    }
                }
            }
            "minItems" | "maxItems" => {
                if let Some(a) = v.as_array() {
                    let n = x.as_u64().unwrap() as usize;
                    if (k == "minItems" && a.len() < n) || (k == "maxItems" && a.len() > n) {
                        out.push(at(format!("{} items, {k} {n}", a.len())));
                    }
                }
            }
            "oneOf" | "anyOf" => {
                let matching = x
                    .as_array()
                    .unwrap()
                    .iter()
                    .filter(|sub| {
                        let mut e = Vec::new();
                        validate(root, sub, v, path, &mut e);
                        e.is_empty()
                    })
                    .count();
                if matching == 0 || (k == "oneOf" && matching > 1) {
                    out.push(at(format!("{v} matches {matching} of the {k} schemas")));
                }
            }
            // Annotations: they constrain nothing (`format` is an annotation in 2020-12).
            "$schema" | "$defs" | "title" | "description" | "default" | "format" => {}
            "const" | "enum" => {}
            other => panic!("keyword `{other}` is not implemented by this validator"),
        }
    }
}

fn errors(v: &Value) -> Vec<String> {
    let s = schema();
    let mut out = Vec::new();
    validate(&s, &s, v, "", &mut out);
    out
}

/// Every spec of the repository.
fn specs() -> Vec<PathBuf> {
    let out = super::specs_in(&[
        "derivations",
        "derivations/chain",
        "tests/specs",
        "fuzz/seeds/spec",
    ]);
    assert!(out.len() > 25, "{} specs", out.len());
    out
}

#[test]
fn the_committed_schema_is_generated_from_the_wire_types() {
    // Stale when the wire types changed; the diff shows how.
    let actual = serde_json::to_string_pretty(&torseur::spec::json_schema()).unwrap() + "\n";
    super::golden::golden_in("", "spec.schema.json", &actual);
}

#[test]
fn every_spec_names_the_schema_first_and_validates_against_it() {
    let schema_file = root().join("spec.schema.json").canonicalize().unwrap();
    for p in specs() {
        let text = std::fs::read_to_string(&p).unwrap();
        let v: Value = serde_json::from_str(&text).unwrap();
        let (first, target) = v.as_object().unwrap().iter().next().unwrap();
        assert_eq!(
            first,
            "$schema",
            "{}: `$schema` is the first key",
            p.display()
        );
        let named = p.parent().unwrap().join(target.as_str().unwrap());
        assert_eq!(
            named.canonicalize().ok().as_ref(),
            Some(&schema_file),
            "{}: `$schema` names {target}",
            p.display()
        );
        let e = errors(&v);
        assert!(e.is_empty(), "{}: {e:#?}", p.display());
        // The loader ignores `$schema` (the wire types refuse unknown fields).
        torseur::spec::parse_spec(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    }
}

/// A change made to a valid spec.
type Mutation = fn(&mut Value);

/// Structural mistakes a teacher makes are refused by the schema (so the editor shows them)
/// and by the loader alike; the unchanged spec passes both.
#[test]
fn the_schema_refuses_what_the_loader_refuses() {
    let text = std::fs::read_to_string(root().join("derivations/regulateur_centrifuge.json"))
        .expect("the regulator");
    let base: Value = serde_json::from_str(&text).unwrap();
    let mutations: [(&str, Mutation); 11] = [
        ("unknown field", |v| v["oops"] = json!(1)),
        ("unknown nested field", |v| {
            v["links"][0]["axes"] = json!("z0")
        }),
        ("a number for a string", |v| {
            v["solids"][0]["mass"] = json!(3)
        }),
        ("a string for a list", |v| v["frames"] = json!("1")),
        ("a string for a number", |v| {
            v["scenarios"][0]["duration"] = json!("1 s")
        }),
        ("an unknown link kind", |v| {
            v["links"][0]["kind"] = json!("hinge")
        }),
        ("three solids in a link", |v| {
            v["links"][0]["between"] = json!(["0", "1", "2"])
        }),
        ("a missing required field", |v| {
            v["solids"][0].as_object_mut().unwrap().remove("name");
        }),
        ("a 2x3 inertia matrix", |v| {
            v["solids"][0]["inertia"]["matrix"]
                .as_array_mut()
                .unwrap()
                .pop();
        }),
        ("an unknown symmetry kind", |v| {
            v["solids"][1]["symmetries"][0]["kind"] = json!("mirror");
        }),
        ("a null title", |v| v["title"] = Value::Null),
    ];
    assert!(errors(&base).is_empty());
    for (what, mutate) in mutations {
        let mut v = base.clone();
        mutate(&mut v);
        assert!(!errors(&v).is_empty(), "the schema accepts {what}");
        assert!(
            torseur::spec::parse_spec(&v.to_string()).is_err(),
            "the loader accepts {what}"
        );
    }
}
