//! One verdict for both sides (issue 14): the exact side ([`torseur::spec::build`]) and the
//! float backend ([`torseur::numeric::NumericModel::new`]) accept and refuse the same specs.
//! The float backend reads the spec on its own, so that a convention it gets wrong cannot hide
//! behind the exact side's; this test keeps the two readings from drifting apart on what a
//! valid spec is.
//!
//! The corpus: every spec of the library, of `tests/specs/` and of the fuzz seeds, and
//! mutations of each, made systematically in the sections both sides read (parameters,
//! coordinates, frames, points, solids, sets, links, actions, gravity, the PFD, hypotheses):
//! each name or expression replaced by an unknown name or by another name of the spec, each
//! element of a list removed or duplicated. The sections only the exact side reads
//! (quantities, questions, scenarios…) are emptied first, since the float backend has no
//! opinion on them.

use serde_json::Value;
use torseur::numeric::NumericModel;

/// The top-level keys the float backend does not read: what to derive and print, and the
/// small coordinates of a linearisation (the float backend evaluates the full equations).
const EXACT_ONLY: &[&str] = &[
    "quantities",
    "questions",
    "scenarios",
    "simulation",
    "default_basis",
    "small",
];

/// The verdicts of both sides on `spec` (`None` if it is not a spec's shape at all: both
/// sides share that parse).
pub(crate) fn verdicts(spec: &Value) -> Option<(Result<(), String>, Result<(), String>)> {
    let text = spec.to_string();
    let file = torseur::spec::parse_spec(&text).ok()?;
    let exact = torseur::spec::build(&file)
        .map(|_| ())
        .map_err(|e| e.to_string());
    let float = NumericModel::new(&file)
        .map(|_| ())
        .map_err(|e| e.to_string());
    Some((exact, float))
}

/// Every string leaf under `v`, as a JSON pointer.
fn string_leaves(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::String(_) => out.push(at),
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                string_leaves(x, format!("{at}/{i}"), out);
            }
        }
        Value::Object(o) => {
            for (k, x) in o {
                string_leaves(
                    x,
                    format!("{at}/{}", k.replace('~', "~0").replace('/', "~1")),
                    out,
                );
            }
        }
        _ => {}
    }
}

/// Every list under `v`, as a JSON pointer.
fn lists(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::Array(a) => {
            out.push(at.clone());
            for (i, x) in a.iter().enumerate() {
                lists(x, format!("{at}/{i}"), out);
            }
        }
        Value::Object(o) => {
            for (k, x) in o {
                lists(
                    x,
                    format!("{at}/{}", k.replace('~', "~0").replace('/', "~1")),
                    out,
                );
            }
        }
        _ => {}
    }
}

/// The mutations of a spec.
fn mutations(base: &Value) -> Vec<(String, Value)> {
    let mut out = vec![("as written".to_string(), base.clone())];
    let mut leaves = Vec::new();
    string_leaves(base, String::new(), &mut leaves);
    // The names of the spec, a few of which replace each leaf in turn.
    let mut names: Vec<String> = leaves
        .iter()
        .filter(|p| p.ends_with("/name"))
        .filter_map(|p| base.pointer(p)?.as_str().map(str::to_string))
        .collect();
    names.sort();
    names.dedup();
    for p in &leaves {
        // Free texts (an action's printed `source` among them), and the units: the exact side
        // reads the units for its dimension checks; the float backend computes with numbers
        // and has no use for them.
        if p == "/title"
            || p == "/$schema"
            || p.contains("label")
            || p.ends_with("/source")
            || p.contains("description")
            || p.ends_with("/text")
            || p.ends_with("/unit")
        {
            continue;
        }
        let current = base.pointer(p).and_then(Value::as_str).unwrap_or_default();
        let mut by: Vec<String> = vec!["zz".to_string()];
        by.extend(
            names
                .iter()
                .filter(|n| *n != current)
                .step_by(3)
                .take(3)
                .cloned(),
        );
        for b in by {
            let mut v = base.clone();
            *v.pointer_mut(p).unwrap() = Value::String(b.clone());
            out.push((format!("{p} = {b:?}"), v));
        }
    }
    let mut ls = Vec::new();
    lists(base, String::new(), &mut ls);
    for p in ls {
        let n = base
            .pointer(&p)
            .and_then(Value::as_array)
            .map_or(0, Vec::len);
        for i in 0..n {
            let mut v = base.clone();
            v.pointer_mut(&p).unwrap().as_array_mut().unwrap().remove(i);
            out.push((format!("{p}/{i} removed"), v));
            let mut v = base.clone();
            let a = v.pointer_mut(&p).unwrap().as_array_mut().unwrap();
            let x = a[i].clone();
            a.insert(i, x);
            out.push((format!("{p}/{i} duplicated"), v));
        }
    }
    out
}

#[test]
fn both_sides_accept_and_refuse_the_same_specs() {
    let files = crate::specs_in(&["derivations", "tests/specs", "fuzz/seeds/spec"]);
    let mut disagreements = Vec::new();
    let (mut tried, mut refused) = (0, 0);
    for f in &files {
        let mut base: Value = serde_json::from_str(&std::fs::read_to_string(f).unwrap()).unwrap();
        let Some(o) = base.as_object_mut() else {
            continue;
        };
        for k in EXACT_ONLY {
            o.remove(*k);
        }
        for (what, spec) in mutations(&base) {
            let Some((exact, float)) = verdicts(&spec) else {
                continue;
            };
            tried += 1;
            if exact.is_err() {
                refused += 1;
            }
            if exact.is_ok() != float.is_ok() {
                disagreements.push(format!(
                    "{} with {what}: exact {exact:?}, float {float:?}",
                    f.file_name().unwrap().to_string_lossy()
                ));
            }
        }
    }
    eprintln!("parity: {tried} specs, {refused} refused by both");
    assert!(
        tried > 1000 && refused > 100,
        "{tried} tried, {refused} refused"
    );
    assert!(
        disagreements.is_empty(),
        "{} disagreements:\n{}",
        disagreements.len(),
        disagreements.join("\n")
    );
}

/// The two cases issue 14 found: an action's unknown named like a link's component, and two
/// actions sharing an unknown, were merged silently by the float backend. Both sides refuse
/// them now, naming the unknown.
#[test]
fn an_unknown_declared_twice_is_refused_by_both_sides() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("derivations/regulateur_centrifuge.json"),
    )
    .unwrap();
    let base: Value = serde_json::from_str(&text).unwrap();
    let mut like_a_link = base.clone();
    like_a_link["actions"][0]["unknowns"][0] = Value::String("X01".into());
    let mut shared = base.clone();
    let mut twin = shared["actions"][0].clone();
    twin["name"] = Value::String("moteur2".into());
    shared["actions"].as_array_mut().unwrap().push(twin);
    for (what, spec) in [("X01", like_a_link), ("C_m twice", shared)] {
        let (exact, float) = verdicts(&spec).expect("a spec's shape");
        for (side, v) in [("exact", exact), ("float", float)] {
            let e = v.expect_err(what);
            assert!(e.contains("declared twice"), "{what}, {side}: {e}");
        }
    }
}

/// A rotation angle: both sides accept ±q plus an integer combination of angle parameters
/// and a multiple of π/2, and refuse anything else, each by its own reading.
#[test]
fn both_sides_read_a_rotation_angle_alike() {
    let spec = |angle: &str| -> Value {
        serde_json::json!({
            "title": "angle",
            "parameters": [{"name": "m"}, {"name": "alpha", "kind": "angle"}],
            "coordinates": [{"name": "q", "kind": "angle"}, {"name": "x", "kind": "length"}],
            "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": angle}}]
        })
    };
    let accepted = [
        "q",
        "-q + pi/2",
        "q - 2*alpha",
        "3*pi/2 - q + alpha",
        "(q + alpha)*2 - q",
    ];
    let refused = [
        "q/2", "2*q - pi", "q + 1", "q + 1/0", "q/0", "m*q", "sin(q)", "q*q", "x", "m", "q + pi/3",
    ];
    for (angles, ok) in [(&accepted[..], true), (&refused[..], false)] {
        for a in angles {
            let (exact, float) = verdicts(&spec(a)).expect("a spec's shape");
            assert_eq!(exact.is_ok(), ok, "exact, {a}: {exact:?}");
            assert_eq!(float.is_ok(), ok, "float, {a}: {float:?}");
        }
    }
}

#[test]
fn both_sides_refuse_the_same_motions_in_a_hypothesis() {
    let text = std::fs::read_to_string("derivations/pendule_arbre_tournant.json").unwrap();
    let base: Value = serde_json::from_str(&text).unwrap();
    let with = |field: &str, v: Value| {
        let mut s = base.clone();
        for k in EXACT_ONLY {
            s.as_object_mut().unwrap().remove(*k);
        }
        s["hypotheses"][0]
            .as_object_mut()
            .unwrap()
            .remove("equilibrium");
        s["hypotheses"][0][field] = v;
        s
    };
    use serde_json::json;
    let refused = [
        ("equilibrium", json!({"phi": "beta"}), "equilibrium.phi"),
        ("equilibrium", json!({"theta": "a"}), "equilibrium.theta"),
        ("equilibrium", json!({"psi": "0"}), "equilibrium.psi"),
        ("rates", json!({"theta": "dot(theta)"}), "rates.theta"),
        ("rates", json!({"theta": "nope"}), "rates.theta"),
        ("relations", json!({"q": "a"}), "relations.q"),
        ("relations", json!({"a": "2*a"}), "relations.a"),
        (
            "fixed_coordinates",
            json!(["theta", "theta"]),
            "fixed_coordinates[1]",
        ),
        ("fixed_coordinates", json!(["psi"]), "fixed_coordinates[0]"),
    ];
    for (field, v, path) in refused {
        let (exact, float) = verdicts(&with(field, v.clone())).expect("a spec's shape");
        let (e, f) = (exact.unwrap_err(), float.unwrap_err());
        assert!(
            e.contains(&format!("hypotheses[0].{path}")),
            "{field} {v}: {e}"
        );
        assert!(
            f.contains(&format!("hypotheses[0].{path}")),
            "{field} {v}: {f}"
        );
    }
    for (field, v) in [
        ("equilibrium", json!({"theta": "beta"})),
        ("equilibrium", json!({"theta": "0"})),
        ("rates", json!({"theta": "2*omega"})),
        ("relations", json!({"A": "C + m*a^2"})),
        ("fixed_coordinates", json!(["theta"])),
    ] {
        let (exact, float) = verdicts(&with(field, v.clone())).expect("a spec's shape");
        assert!(
            exact.is_ok() && float.is_ok(),
            "{field} {v}: {exact:?} {float:?}"
        );
    }
}

#[test]
fn both_sides_read_the_time_alike() {
    // The exciter's force, and a frame turned by a phase: the time enters only as k Ω t.
    let text = std::fs::read_to_string("derivations/masse_ressort_forcee.json").unwrap();
    let base: Value = serde_json::from_str(&text).unwrap();
    let force = |f: &str| {
        let mut s = base.clone();
        s["actions"][0]["resultant"] = f.into();
        s
    };
    let turned = |a: &str| {
        let mut s = base.clone();
        s["frames"][0]["rotation"] = serde_json::json!({"axis": "z", "angle": a});
        s
    };
    let accepted = [
        force("F0*cos(Omega*t)*x0"),
        force("F0*sin(2*Omega*t)*x0 + F0*cos(Omega*t)^2*y0"),
        force("F0*cos(-Omega*t + pi/2)*x0"),
        force("F0*cos(t*Omega*3)*x0"),
        turned("Omega*t"),
        turned("-Omega*t + pi/2"),
    ];
    let refused = [
        force("F0*t*x0"),
        force("F0*cos(t)*x0"),
        force("F0*cos(x*t)*x0"),
        force("F0*cos(Omega*t/2)*x0"),
        force("F0*cos(0.5*Omega*t)*x0"),
        force("F0*cos(Omega*t^2)*x0"),
        force("F0*cos(Omega*k*t)*x0"),
        force("F0*cos(Omega*(t + 1))*x0"),
        force("F0*exp(t)*x0"),
        turned("t"),
        turned("Omega*t*t"),
        turned("2*Omega*t"),
        turned("Omega*t + x"),
    ];
    for (specs, ok) in [(&accepted[..], true), (&refused[..], false)] {
        for s in specs {
            let (exact, float) = verdicts(s).expect("a spec's shape");
            let what = (&s["actions"][0]["resultant"], &s["frames"][0]["rotation"]);
            assert_eq!(exact.is_ok(), ok, "exact, {what:?}: {exact:?}");
            assert_eq!(float.is_ok(), ok, "float, {what:?}: {float:?}");
        }
    }
}

#[test]
fn both_sides_divide_by_the_same_things() {
    // Issue 15, item 6: a spec divides by a product of parameters, in every expression it
    // gives; a sum, a coordinate, a rate or a sin below the line is refused by both sides.
    let text = std::fs::read_to_string("derivations/systeme_masse_ressort.json").unwrap();
    let base: Value = serde_json::from_str(&text).unwrap();
    let at_rest = |x: &str| {
        let mut s = base.clone();
        s["hypotheses"][0]["equilibrium"]["x"] = x.into();
        s
    };
    let weight = |g: &str| {
        let mut s = base.clone();
        s["gravity"] = g.into();
        s
    };
    let accepted = [
        at_rest("l0 - m*g*sin(beta)/k"),
        at_rest("l0 - m*g/(2*k)"),
        at_rest("l0 - m*g*k^-1"),
        at_rest("l0 - c^2/(k*m)"),
        at_rest("l0 - g/(k/m)"),
        weight("-k*l0/m*y0"),
        weight("-g*(m/k)^2*k^2/m^2*y0"),
    ];
    let refused = [
        at_rest("l0 - m*g/(k + c)"),
        at_rest("l0 - m*g/cos(beta)"),
        at_rest("l0 - m*g/k^2/(1 - m)"),
        weight("-g/x*l0*y0"),
        weight("-g/dot(x)*l0*y0"),
        weight("-g*l0/(k - c)*y0"),
    ];
    for (specs, ok) in [(&accepted[..], true), (&refused[..], false)] {
        for s in specs {
            let (exact, float) = verdicts(s).expect("a spec's shape");
            let what = (&s["hypotheses"][0]["equilibrium"], &s["gravity"]);
            assert_eq!(exact.is_ok(), ok, "exact, {what:?}: {exact:?}");
            assert_eq!(float.is_ok(), ok, "float, {what:?}: {float:?}");
        }
    }
}

#[test]
fn both_sides_read_a_driven_rate_alike() {
    // Issue 16: a coordinate whose rate is driven by the others' (a gear ratio): affine in the
    // first derivatives of coordinates with free rates, coefficients of parameters.
    let text = std::fs::read_to_string("derivations/train_engrenages.json").unwrap();
    let base: Value = serde_json::from_str(&text).unwrap();
    let rate = |r: &str| {
        let mut s = base.clone();
        s["coordinates"][1]["rate"] = r.into();
        s
    };
    let accepted = [
        rate("-r1/r2*dot(theta1)"),
        rate("-r1*dot(theta1)/r2"),
        rate("2*dot(theta1) + r1/r2"),
        rate("(r1 + r2)/r2*dot(theta1)"),
        rate("r1/r2"),
        // Coefficients may hold coordinates (a nonholonomic rolling, ẋ = R θ̇ cos ψ).
        rate("theta1*dot(theta1)"),
        rate("cos(theta1)*dot(theta1)"),
    ];
    let refused = [
        rate("dot(theta1)^2"),
        rate("ddot(theta1)"),
        rate("dot(theta2)"),
        rate("sin(dot(theta1))"),
        rate("r1/dot(theta1)"),
        rate("dot(theta1)/(r1 + r2)"),
    ];
    // A hypothesis holding a driven coordinate's rate constant: its q̈ follows θ̈1.
    let mut held = rate("-r1/r2*dot(theta1)");
    held["hypotheses"] = serde_json::json!([{"name": "C", "constant_rates": ["theta2"]}]);
    let refused: Vec<Value> = refused.into_iter().chain([held]).collect();
    for (specs, ok) in [(&accepted[..], true), (&refused[..], false)] {
        for s in specs {
            let (exact, float) = verdicts(s).expect("a spec's shape");
            let what = &s["coordinates"][1]["rate"];
            assert_eq!(exact.is_ok(), ok, "exact, {what:?}: {exact:?}");
            assert_eq!(float.is_ok(), ok, "float, {what:?}: {float:?}");
        }
    }
}

/// The names and trees (parameters, coordinates, aliases, named basis vectors, frames,
/// points, solids, the references of the hypotheses, links, actions and theorems) are resolved once for both sides (`torseur::resolve`): an error there is
/// reported at the same path in the same words by each, and a tree given in any order is
/// accepted by both.
#[test]
fn both_sides_report_the_names_and_trees_errors_alike() {
    let spec = |frames: Value, points: Value, solids: Value| -> Value {
        serde_json::json!({
            "title": "trees",
            "parameters": [{"name": "m"}, {"name": "L"}],
            "coordinates": [{"name": "q", "kind": "angle"}],
            "frames": frames, "points": points, "solids": solids
        })
    };
    let f = |name: &str, parent: &str| serde_json::json!({"name": name, "parent": parent});
    let p = |name: &str, from: &str| serde_json::json!({"name": name, "from": from, "position": "L*x0"});
    let solid = |frame: &str, centre: &str| serde_json::json!([{"name": "S", "frame": frame, "mass": "m", "centre": centre}]);
    // Children before parents: accepted by both.
    let (exact, float) = verdicts(&spec(
        serde_json::json!([f("2", "1"), f("1", "0")]),
        serde_json::json!([p("B", "A"), p("A", "O0")]),
        solid("2", "B"),
    ))
    .unwrap();
    assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    let cases = [
        (
            spec(
                serde_json::json!([f("1", "2"), f("2", "1")]),
                serde_json::json!([]),
                serde_json::json!([]),
            ),
            "frames[0].parent: the frames form a cycle through `1`",
        ),
        (
            spec(
                serde_json::json!([f("1", "3")]),
                serde_json::json!([]),
                serde_json::json!([]),
            ),
            "frames[0].parent: unknown frame `3`",
        ),
        (
            spec(
                serde_json::json!([f("0", "0")]),
                serde_json::json!([]),
                serde_json::json!([]),
            ),
            "frames[0].name: duplicate frame `0`",
        ),
        (
            spec(
                serde_json::json!([]),
                serde_json::json!([p("A", "B"), p("B", "A")]),
                serde_json::json!([]),
            ),
            "points[0].from: the points form a cycle through `A`",
        ),
        (
            spec(
                serde_json::json!([]),
                serde_json::json!([p("O0", "O0")]),
                serde_json::json!([]),
            ),
            "points[0].name: duplicate point `O0`",
        ),
        (
            spec(
                serde_json::json!([f("1", "0")]),
                serde_json::json!([]),
                solid("1", "G"),
            ),
            "solids[0].centre: unknown point `G`",
        ),
        (
            spec(
                serde_json::json!([]),
                serde_json::json!([]),
                serde_json::json!([{"name": "0", "frame": "0", "mass": "m", "centre": "O0"}]),
            ),
            "solids[0].name: duplicate solid `0`",
        ),
    ];
    let named = |params: Value, basis: Value| -> Value {
        serde_json::json!({
            "title": "names",
            "parameters": params,
            "coordinates": [{"name": "q", "kind": "angle"}],
            "aliases": [{"name": "M", "value": "2*m"}],
            "ground_basis": basis
        })
    };
    let m = serde_json::json!({"name": "m"});
    let names = [
        (
            named(serde_json::json!([m, {"name": "sin"}]), Value::Null),
            "parameters[1].name: `sin` is reserved by the expression syntax",
        ),
        (
            named(serde_json::json!([m, {"name": "x0"}]), Value::Null),
            "parameters[1].name: the parameter `x0` has the name of the basis vector x of frame 0",
        ),
        (
            named(serde_json::json!([m, {"name": "q"}]), Value::Null),
            "coordinates[0].name: duplicate name `q`",
        ),
        (
            named(serde_json::json!([m]), serde_json::json!(["i", "M", "k"])),
            "ground_basis[1]: `M` is already the name of a parameter",
        ),
        (
            named(serde_json::json!([m]), serde_json::json!(["i", "j", "y0"])),
            "ground_basis[2]: `y0` is already the basis vector y of frame 0",
        ),
    ];
    let held = |hypotheses: Value| -> Value {
        serde_json::json!({
            "title": "hypotheses",
            "parameters": [{"name": "m"}],
            "coordinates": [{"name": "q", "kind": "angle"}],
            "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}}],
            "solids": [{"name": "S", "frame": "1", "mass": "m", "centre": "O0"}],
            "hypotheses": hypotheses
        })
    };
    let hypotheses = [
        (
            held(serde_json::json!([{"name": "H", "constant_rates": ["q"]}, {"name": "H"}])),
            "hypotheses[1].name: the hypothesis `H` is defined twice",
        ),
        (
            held(serde_json::json!([{"name": "H", "constant_rates": ["p"]}])),
            "hypotheses[0].constant_rates[0]: unknown coordinate `p`",
        ),
        (
            held(serde_json::json!([{"name": "H", "symmetric_solids": ["T"]}])),
            "hypotheses[0].symmetric_solids[0]: unknown solid `T`",
        ),
    ];
    let linked = |between: [&str; 2], point: &str, twice: bool| -> Value {
        let link = serde_json::json!({"name": "01", "kind": "pivot", "between": between,
            "point": point, "axis": "z0"});
        let links = if twice {
            vec![link.clone(), link]
        } else {
            vec![link]
        };
        serde_json::json!({
            "title": "links",
            "parameters": [{"name": "m"}],
            "coordinates": [{"name": "q", "kind": "angle"}],
            "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}},
                       {"name": "2", "parent": "1"}],
            "solids": [{"name": "S", "frame": "1", "mass": "m", "centre": "O0"}],
            "sets": {"E": ["S"]},
            "links": links
        })
    };
    let links = [
        (
            linked(["0", "S"], "O0", true),
            "links[1].name: duplicate link `01`",
        ),
        (
            linked(["2", "S"], "O0", false),
            "links[0].between[0]: `2` is a frame, not a solid",
        ),
        (
            linked(["E", "S"], "O0", false),
            "links[0].between[0]: `E` is a set: a link or an action joins two solids",
        ),
        (
            linked(["S", "0"], "O0", false),
            "links[0].between[1]: the second solid of a link receives its action",
        ),
        (
            linked(["S", "S"], "O0", false),
            "links[0].between: a link joins two different solids",
        ),
        (
            linked(["0", "S"], "P", false),
            "links[0].point: unknown point `P`",
        ),
    ];
    let acting = |name: &str, from: &str, on: &str, point: &str| -> Value {
        let mut v = linked(["0", "S"], "O0", false);
        v["actions"] = serde_json::json!([{"name": name, "from": from, "on": on,
            "point": point, "moment": "C*z0", "unknowns": ["C"]}]);
        v
    };
    let actions = [
        (
            acting("moteur", "S", "0", "O0"),
            "actions[0].on: an action is received by a solid",
        ),
        (
            acting("moteur", "S", "S", "O0"),
            "actions[0].on: an action is exerted by one solid on another",
        ),
        (
            acting("moteur", "0", "S", "P"),
            "actions[0].point: unknown point `P`",
        ),
        (
            acting("2moteur", "0", "S", "O0"),
            "actions[0].name: `2moteur` is not a valid name",
        ),
    ];
    let theorem = |t: Value| -> Value {
        let mut v = linked(["0", "S"], "O0", false);
        v["pfd"] = t;
        v
    };
    let moment = |isolate: &str, on: &str, eom: &str| {
        serde_json::json!({"isolate": isolate, "theorem": "moment", "point": "O0", "on": on,
            "eom": eom})
    };
    let theorems = [
        (
            theorem(serde_json::json!([moment("0", "z0", "q")])),
            "pfd[0].isolate: `0` is the ground: it is never isolated",
        ),
        (
            theorem(serde_json::json!([moment("T", "z0", "q")])),
            "pfd[0].isolate: unknown solid or set `T`",
        ),
        (
            theorem(serde_json::json!([{"isolate": "S", "theorem": "moment", "on": "z0"}])),
            "pfd[0].point: the moment theorem is written at a point",
        ),
        (
            theorem(serde_json::json!([moment("S", "w0", "q")])),
            "pfd[0].on: `w0` is not a basis vector such as z0",
        ),
        (
            theorem(serde_json::json!([moment("S", "z0", "p")])),
            "pfd[0].eom: unknown coordinate `p`",
        ),
        (
            theorem(serde_json::json!([
                moment("S", "z0", "q"),
                moment("E", "z1", "q")
            ])),
            "pfd[1].eom: pfd[0] is already the equation of motion of `q`",
        ),
    ];
    let (exact, float) = verdicts(&theorem(serde_json::json!([moment("E", "z1", "q")]))).unwrap();
    assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    let (exact, float) = verdicts(&acting("moteur", "0", "S", "O0")).unwrap();
    assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    let (exact, float) = verdicts(&linked(["0", "S"], "O0", false)).unwrap();
    assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    for (s, expected) in cases
        .into_iter()
        .chain(names)
        .chain(hypotheses)
        .chain(links)
        .chain(actions)
        .chain(theorems)
    {
        let (exact, float) = verdicts(&s).expect("a spec's shape");
        for (side, v) in [("exact", exact), ("float", float)] {
            let e = v.expect_err(expected);
            assert!(e.contains(expected), "{side}: {e}\n  expected: {expected}");
        }
    }
}
