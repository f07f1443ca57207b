//! Generates the benchmark family « chain N » (derivations/chain/chain_N.json, N = 1..10):
//! N solids in a spatial serial chain generalising the regulator. Rk is turned from R(k−1) by
//! qk about z(k−1) (k odd) or x(k−1) (k even); O1 = O0, Ok = O(k−1) + L(k−1) y(k−1);
//! Gk = Ok + lk yk; full inertia [[Ak,−Fk,−Ek],[−Fk,Bk,−Dk],[−Ek,−Dk,Ck]] at Gk in Bk;
//! sets Ek = {k..N}; quantities τk = δ(Ok, Ek/0)·ak with ak = z(k−1) (odd k) or x(k−1) (even k).
//!
//! Run: `cargo run --example chain` (writes the files), `cargo run --example chain -- 12` for
//! a longer chain printed on stdout.

use serde_json::json;

fn chain(n: usize) -> serde_json::Value {
    let mut params = Vec::new();
    for k in 1..=n {
        params.push(json!({"name": format!("m{k}"), "unit": "kg"}));
        if k < n {
            params.push(json!({"name": format!("L{k}"), "unit": "m"}));
        }
        params.push(json!({"name": format!("l{k}"), "unit": "m"}));
        for p in ["A", "B", "C", "D", "E", "F"] {
            params.push(json!({"name": format!("{p}{k}"), "unit": "kg m^2"}));
        }
    }
    let coords: Vec<_> = (1..=n)
        .map(|k| json!({"name": format!("q{k}"), "kind": "angle"}))
        .collect();
    let mut frames = Vec::new();
    let mut points = Vec::new();
    let mut solids = Vec::new();
    let mut quantities = Vec::new();
    let mut sets = serde_json::Map::new();
    for k in 1..=n {
        let axis = if k % 2 == 1 { "z" } else { "x" };
        frames.push(
            json!({"name": format!("{k}"), "parent": format!("{}", k - 1),
            "rotation": {"axis": axis, "angle": format!("q{k}")}, "origin": format!("O{k}")}),
        );
        if k == 1 {
            points.push(json!({"name": "O1", "from": "O0", "position": "0"}));
        } else {
            points.push(
                json!({"name": format!("O{k}"), "from": format!("O{}", k - 1),
                "position": format!("L{}*y{}", k - 1, k - 1)}),
            );
        }
        points.push(json!({"name": format!("G{k}"), "from": format!("O{k}"),
            "position": format!("l{k}*y{k}")}));
        let e = |p: &str| format!("{p}{k}");
        let ne = |p: &str| format!("-{p}{k}");
        solids.push(json!({"name": format!("{k}"), "frame": format!("{k}"), "mass": format!("m{k}"),
            "centre": format!("G{k}"), "inertia": {"point": format!("G{k}"), "basis": format!("{k}"),
            "matrix": [[e("A"), ne("F"), ne("E")], [ne("F"), e("B"), ne("D")], [ne("E"), ne("D"), e("C")]]}}));
        sets.insert(
            format!("E{k}"),
            json!((k..=n).map(|j| j.to_string()).collect::<Vec<_>>()),
        );
        quantities.push(format!("delta(O{k},E{k}/0).{axis}{}", k - 1));
    }
    json!({
        "$schema": "../../spec.schema.json",
        "title": format!("Chaîne spatiale de {n} solides"),
        "description": "Famille de référence « chain N » : rotations alternées autour de z et de x.",
        "parameters": params, "coordinates": coords, "ground": "0", "ground_origin": "O0",
        "frames": frames, "points": points, "solids": solids, "sets": sets, "quantities": quantities
    })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if let Some(n) = args.get(1).and_then(|s| s.parse::<usize>().ok()) {
        println!(
            "{}",
            serde_json::to_string_pretty(&chain(n.clamp(1, 64))).unwrap()
        );
        return;
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain");
    std::fs::create_dir_all(&dir).unwrap();
    for n in 1..=10 {
        let text = serde_json::to_string_pretty(&chain(n)).unwrap() + "\n";
        std::fs::write(dir.join(format!("chain_{n}.json")), text).unwrap();
    }
    eprintln!("wrote derivations/chain/chain_1.json .. chain_10.json");
}
