//! The PFD sections' and the constraints' refusals, resolved once (`torseur::resolve`): the
//! exact side and the float backend must refuse each spec below at the same place with the
//! same words. The expected messages are written by hand, from what the spec does wrong.

use super::parity::verdicts;
use serde_json::{Value, json};

/// Each spec refused by both sides, at the expected place with the expected words.
fn refused_alike(cases: Vec<(Value, &str)>) {
    for (s, expected) in cases {
        let (exact, float) = verdicts(&s).expect("a spec's shape");
        for (side, v) in [("exact", exact), ("float", float)] {
            let e = v.expect_err(expected);
            assert!(e.contains(expected), "{side}: {e}\n  expected: {expected}");
        }
    }
}

/// A solid S turning by q about z0 and a solid T in frame 2 (turned by p from 1), joined to
/// the ground by the link `01` (fields `link` added) and S to T by a pivot `12`.
fn linked(link: Value) -> Value {
    let mut l01 = json!({"name": "01", "kind": "pivot", "between": ["0", "S"],
        "point": "O0", "axis": "z0"});
    for (k, x) in link.as_object().expect("fields") {
        l01[k] = x.clone();
    }
    json!({
        "title": "links",
        "parameters": [{"name": "m"}, {"name": "k"}],
        "coordinates": [{"name": "q", "kind": "angle"}, {"name": "p", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}},
                   {"name": "2", "parent": "1", "rotation": {"axis": "z", "angle": "p"},
                    "basis": ["u", "v", "w"]}],
        "solids": [{"name": "S", "frame": "1", "mass": "m", "centre": "O0"},
                   {"name": "T", "frame": "2", "mass": "m", "centre": "O0"}],
        "links": [l01, {"name": "12", "kind": "pivot", "between": ["S", "T"], "point": "O0",
                        "axis": "z1"}]
    })
}

#[test]
fn both_sides_refuse_a_links_axis_friction_and_spring_alike() {
    let without_axis = {
        let mut v = linked(json!({}));
        v["links"][0].as_object_mut().expect("link").remove("axis");
        v
    };
    let looped = {
        let mut v = linked(json!({}));
        let closing = json!({"name": "02", "kind": "pivot", "between": ["0", "T"],
            "point": "O0", "axis": "z0"});
        v["links"].as_array_mut().expect("links").push(closing);
        v
    };
    refused_alike(vec![
        (
            without_axis,
            "links[0].axis: a liaison pivot needs its axis (or normal)",
        ),
        (
            linked(json!({"axis": "w0"})),
            "links[0].axis: `w0` is not a basis vector such as z0",
        ),
        (
            linked(json!({"kind": "line", "axis": "z1"})),
            "links[0].direction: a line contact needs the direction of its line",
        ),
        (
            linked(json!({"direction": "x1"})),
            "links[0].direction: only a line contact (`line`) has a direction",
        ),
        (
            linked(json!({"kind": "line", "axis": "z1", "direction": "x0"})),
            "links[0].direction: the line's direction is another basis vector of its normal's basis",
        ),
        (
            linked(json!({"kind": "line", "axis": "z1", "direction": "z1"})),
            "links[0].direction: the line's direction is another basis vector of its normal's basis",
        ),
        (
            linked(json!({"kind": "ball", "friction": "k"})),
            "links[0].friction: viscous friction is declared on a pivot or a slider",
        ),
        (
            linked(json!({"kind": "plane", "coulomb": "k"})),
            "links[0].coulomb: dry friction is declared on a pivot or a slider",
        ),
        (
            linked(json!({"kind": "annular", "spring": {"coordinate": "q", "stiffness": "k"}})),
            "links[0].spring: a spring is declared on a pivot or a slider",
        ),
        (
            linked(json!({"spring": {"coordinate": "r", "stiffness": "k"}})),
            "links[0].spring.coordinate: unknown coordinate `r`",
        ),
        (
            looped,
            "links[2].between: the link 02 closes a kinematic loop: 0 and T are already \
             connected by the links 01, 12",
        ),
    ]);
    // A line contact whose direction is another vector of its normal's basis, a spring and
    // friction on a pivot: accepted by both.
    for ok in [
        linked(json!({"kind": "line", "axis": "z1", "direction": "x1"})),
        linked(json!({"kind": "line", "axis": "w", "direction": "u"})),
        linked(json!({"friction": "k", "spring": {"coordinate": "q", "stiffness": "k"}})),
    ] {
        let (exact, float) = verdicts(&ok).expect("a spec's shape");
        assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    }
}

#[test]
fn both_sides_refuse_an_unknowns_name_alike() {
    let acting = |unknown: &str| {
        let mut v = linked(json!({}));
        v["actions"] = json!([{"name": "moteur", "from": "0", "on": "S", "point": "O0",
            "moment": format!("{unknown}*z0"), "unknowns": [unknown]}]);
        v
    };
    // Two faults: each side reports the unknown's first, before reading the point's position.
    let multiple = {
        let mut v = acting("X01");
        v["points"] = json!([{"name": "P", "position": "L*(x0"}]);
        v
    };
    let signed = {
        let mut v = linked(json!({"coulomb": "m"}));
        v["parameters"][1]["name"] = json!("epsilon01");
        v
    };
    refused_alike(vec![
        (
            acting("X01"),
            "actions[0].unknowns[0]: the unknown `X01` is declared twice",
        ),
        (
            acting("m"),
            "actions[0].unknowns[0]: the unknown `m` is already a parameter",
        ),
        (
            acting("q"),
            "actions[0].unknowns[0]: the unknown `q` is already a coordinate or an alias",
        ),
        (
            acting("y1"),
            "actions[0].unknowns[0]: the unknown `y1` has the name of the basis vector y of frame 1",
        ),
        (
            acting("u"),
            "actions[0].unknowns[0]: the unknown `u` is the name of a basis vector",
        ),
        (
            acting("pi"),
            "actions[0].unknowns[0]: `pi` is reserved by the expression syntax: it is the constant π",
        ),
        (
            multiple,
            "actions[0].unknowns[0]: the unknown `X01` is declared twice",
        ),
        (
            signed,
            "links[0].coulomb: `epsilon01` is the sign of this link's relative rate under dry \
             friction",
        ),
    ]);
}

/// A crank–slider: crank 1 (θ), rod 2 (φ from the ground), slider 3 (x), closed by
/// OA + AB − x x0 = 0; `change` edits it.
fn crank(change: &dyn Fn(&mut Value)) -> Value {
    let mut v = json!({
        "title": "crank",
        "parameters": [{"name": "R"}, {"name": "L"}, {"name": "m"}],
        "coordinates": [{"name": "theta", "kind": "angle"}, {"name": "phi", "kind": "angle"},
                        {"name": "x", "kind": "length"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}},
                   {"name": "2", "parent": "0", "rotation": {"axis": "z", "angle": "phi"}}],
        "points": [{"name": "A", "position": "R*x1"}, {"name": "B", "position": "x*x0"}],
        "solids": [{"name": "S1", "frame": "1", "mass": "m", "centre": "O0"},
                   {"name": "S2", "frame": "2", "mass": "m", "centre": "A"}],
        "closures": [{"vector": "R*x1 + L*x2 - x*x0", "dependent": ["phi", "x"]}]
    });
    change(&mut v);
    v
}

/// A disc of radius R rolling on the line (O0, x0): its centre C at x x0 + R y0, turned by θ.
fn disc(change: &dyn Fn(&mut Value)) -> Value {
    let mut v = json!({
        "title": "disc",
        "parameters": [{"name": "R"}, {"name": "m"}],
        "coordinates": [{"name": "x", "kind": "length"}, {"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "origin": "C",
                    "rotation": {"axis": "z", "angle": "theta"}}],
        "points": [{"name": "C", "position": "x*x0 + R*y0"}, {"name": "I", "position": "x*x0"}],
        "solids": [{"name": "S", "frame": "1", "mass": "m", "centre": "C"}],
        "rolling": [{"velocity": "V(I,S/0)", "dependent": ["x"]}]
    });
    change(&mut v);
    v
}

#[test]
fn both_sides_refuse_a_closures_and_a_rolling_conditions_references_alike() {
    refused_alike(vec![
        (
            crank(&|v| v["closures"][0]["dependent"] = json!(["phi", "y"])),
            "closures[0].dependent[1]: unknown coordinate `y`",
        ),
        (
            crank(&|v| v["closures"][0]["dependent"] = json!([])),
            "closures[0].dependent: name the coordinates the closure determines",
        ),
        (
            crank(&|v| v["closures"][0]["dependent"] = json!(["phi", "phi"])),
            "closures[0].dependent[1]: `phi` is determined twice",
        ),
        (
            crank(&|v| v["coordinates"][1]["rate"] = json!("0")),
            "closures[0].dependent[0]: `phi` has a rate of its own (coordinates[1].rate)",
        ),
        (
            crank(&|v| v["coordinates"][0]["rate"] = json!("1")),
            "coordinates[0].rate: a mechanism with a loop closure or a rolling condition takes \
             free rates only",
        ),
        (
            disc(&|v| v["rolling"][0]["velocity"] = json!("Omega(S/0)")),
            "rolling[0].velocity: `Omega(S/0)` is not a velocity",
        ),
        (
            disc(&|v| v["rolling"][0]["velocity"] = json!("V(J,S/0)")),
            "rolling[0].velocity: unknown point `J`",
        ),
        (
            disc(&|v| v["rolling"][0]["velocity"] = json!("V(I,S/9)")),
            "rolling[0].velocity: unknown solid or frame `9`",
        ),
        (
            disc(&|v| v["rolling"][0]["on"] = json!(["w0"])),
            "rolling[0].on[0]: unknown basis vector `w0`",
        ),
        (
            disc(&|v| v["rolling"][0]["on"] = json!(["x0", "y0"])),
            "rolling[0].on: 2 directions for 1 dependent coordinate",
        ),
        (
            disc(&|v| v["rolling"][0]["dependent"] = json!(["x", "x"])),
            "rolling[0].dependent[1]: `x` is determined twice",
        ),
        (
            disc(&|v| v["rolling"][0]["dependent"] = json!([])),
            "rolling[0].dependent: name the coordinates the rolling condition determines",
        ),
        (
            crank(&|v| {
                v["rolling"] = json!([{"velocity": "V(B,S2/0)", "dependent": ["x"]}]);
            }),
            "rolling[0].dependent[0]: `x` is determined twice",
        ),
    ]);
    for ok in [crank(&|_| {}), disc(&|_| {})] {
        let (exact, float) = verdicts(&ok).expect("a spec's shape");
        assert!(exact.is_ok() && float.is_ok(), "{exact:?} {float:?}");
    }
}

/// Each side names the PFD's unknowns from its own reading of which components a link
/// transmits: for every link kind, on a course basis and on the statement's names for one,
/// both must give the same unknowns (their values are held against each other by `check`).
#[test]
fn both_sides_read_the_same_unknowns_from_every_link_kind() {
    let kinds = [
        ("fixed", None, None, 6),
        ("pivot", Some("z1"), None, 5),
        ("slider", Some("x1"), None, 5),
        ("pivot_slider", Some("z1"), None, 4),
        ("ball", None, None, 3),
        ("plane", Some("z1"), None, 3),
        ("annular", Some("x1"), None, 2),
        ("line", Some("z1"), Some("x1"), 2),
        ("line", Some("w"), Some("u"), 2),
        ("point", Some("v"), None, 1),
    ];
    for (kind, axis, direction, count) in kinds {
        let mut v = linked(json!({"kind": kind, "between": ["S", "T"], "name": "A"}));
        let l = v["links"][0].as_object_mut().expect("link");
        l.remove("axis");
        if let Some(a) = axis {
            l.insert("axis".into(), json!(a));
        }
        if let Some(d) = direction {
            l.insert("direction".into(), json!(d));
        }
        // S on the ground by a pivot, T on S by the link under test.
        v["links"][1] = json!({"name": "01", "kind": "pivot", "between": ["0", "S"],
            "point": "O0", "axis": "z0"});
        let file = torseur::spec::parse_spec(&v.to_string()).expect("a spec");
        let exact = torseur::spec::build(&file).expect("the exact side builds it");
        let float = torseur::numeric::NumericModel::new(&file).expect("the float side too");
        let float: Vec<&str> = float.unknown_names().collect();
        let exact: Vec<&str> = exact.reg().unknowns().iter().map(String::as_str).collect();
        assert_eq!(exact, float, "{kind} {axis:?} {direction:?}");
        assert_eq!(exact.len(), count + 5, "{kind}: {exact:?}");
        assert!(exact[0].ends_with("_A"), "{exact:?}");
    }
}
