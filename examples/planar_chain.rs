//! Generates the planar benchmark family « planar N » (derivations/chain/planar_N.json):
//! sympy's `models.n_link_pendulum_on_cart(n)`, written as a torseur spec. A cart (point mass
//! m0 at P0, OP0 = q0 x0) pushed by F along x0 on a slider; n links turned by the absolute
//! angles qk about z0 (frame k from the ground), Pk = P(k−1) + l(k−1) yk, a point mass mk at
//! Pk; gravity −g y0. The equations: the resultant on x0 of the whole (q0), and for each k
//! the moment at P(k−1) on z0 of the links k..n (qk), unknowns eliminated.
//!
//! Run: `cargo run --example planar_chain` (writes N = 1..12), `cargo run --example
//! planar_chain -- 24` for one spec on stdout.

use serde_json::json;

fn planar(n: usize) -> serde_json::Value {
    let mut params = vec![json!({"name": "m0", "unit": "kg"})];
    for k in 1..=n {
        params.push(json!({"name": format!("m{k}"), "unit": "kg"}));
        params.push(json!({"name": format!("l{}", k - 1), "unit": "m"}));
    }
    params.push(json!({"name": "g", "unit": "m/s^2"}));
    params.push(json!({"name": "F", "unit": "N"}));
    let mut coords = vec![json!({"name": "q0", "kind": "length"})];
    let mut frames = vec![json!({"name": "c", "parent": "0", "origin": "P0"})];
    let mut points = vec![json!({"name": "P0", "from": "O", "position": "q0*x0"})];
    let mut solids = vec![json!({"name": "c", "frame": "c", "mass": "m0", "centre": "P0"})];
    let mut links = vec![
        json!({"name": "0c", "kind": "slider", "between": ["0", "c"], "point": "P0", "axis": "x0"}),
    ];
    let mut sets = serde_json::Map::new();
    let mut pfd = vec![json!({"isolate": "E0", "theorem": "resultant", "on": "x0", "eom": "q0"})];
    let mut quantities = vec!["eom(q0)".to_string()];
    let mut all = vec!["c".to_string()];
    for k in 1..=n {
        coords.push(json!({"name": format!("q{k}"), "kind": "angle"}));
        frames.push(json!({"name": format!("{k}"), "parent": "0",
            "rotation": {"axis": "z", "angle": format!("q{k}")}, "origin": format!("P{}", k - 1)}));
        points.push(
            json!({"name": format!("P{k}"), "from": format!("P{}", k - 1),
            "position": format!("l{}*y{k}", k - 1)}),
        );
        solids.push(json!({"name": format!("{k}"), "frame": format!("{k}"),
            "mass": format!("m{k}"), "centre": format!("P{k}")}));
        let before = if k == 1 {
            "c".to_string()
        } else {
            (k - 1).to_string()
        };
        links.push(json!({"name": format!("{before}{k}"), "kind": "pivot",
            "between": [before, k.to_string()], "point": format!("P{}", k - 1), "axis": "z0"}));
        sets.insert(
            format!("E{k}"),
            json!((k..=n).map(|j| j.to_string()).collect::<Vec<_>>()),
        );
        pfd.push(json!({"isolate": format!("E{k}"), "theorem": "moment",
            "point": format!("P{}", k - 1), "on": "z0", "eom": format!("q{k}")}));
        quantities.push(format!("eom(q{k})"));
        all.push(k.to_string());
    }
    sets.insert("E0".to_string(), json!(all));
    json!({
        "$schema": "../../spec.schema.json",
        "title": format!("Pendule à {n} barre{} sur chariot", if n == 1 { "" } else { "s" }),
        "description": "Famille de référence « planar N » : le n_link_pendulum_on_cart de sympy, angles absolus.",
        "ground_origin": "O",
        "parameters": params, "coordinates": coords, "frames": frames, "points": points,
        "solids": solids, "sets": sets, "quantities": quantities, "gravity": "-g*y0",
        "links": links,
        "actions": [{"name": "pousse", "from": "0", "on": "c", "point": "P0", "resultant": "F*x0"}],
        "pfd": pfd
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(n) = args.get(1).and_then(|s| s.parse::<usize>().ok()) {
        println!(
            "{}",
            serde_json::to_string_pretty(&planar(n.clamp(1, 64))).unwrap()
        );
        return;
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain");
    std::fs::create_dir_all(&dir).unwrap();
    for n in 1..=12 {
        let text = serde_json::to_string_pretty(&planar(n)).unwrap() + "\n";
        std::fs::write(dir.join(format!("planar_{n}.json")), text).unwrap();
    }
    eprintln!("wrote derivations/chain/planar_1.json .. planar_12.json");
}
