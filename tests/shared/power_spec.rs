//! A hostile spec shared by the engine's and the binary's tests of the derivation's budget
//! (each test crate includes this file with `#[path]`).

/// Four solids turned by q1 (z), q2 (x), q3 (z), q4 (x), and G4 = O0 + L sⁿ y4 where
/// s = cos q1 + sin q2 + cos q3 + sin q4: a 1.4 kB spec whose position is read at once
/// (C(n + 3, 3) monomials) and whose dynamic moment multiplies expressions of thousands of
/// terms by thousands. Without the budget, n = 16 derives for 28 s to a result of 809,547
/// terms, and n = 32 runs for over five minutes.
pub fn power(n: u32) -> String {
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
