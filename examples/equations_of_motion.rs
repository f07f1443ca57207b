//! The equations of motion as M(q) q̈ + h(q, q̇, t) = Q(q, t), exact, and compiled: the double
//! pendulum's mass matrix, its velocity terms and its generalised forces, then the
//! accelerations at a state, as a tool that integrates the motion itself would use them.
//!
//! Run: `cargo run --release --example equations_of_motion`

use torseur::output::{Values, numeric_point};
use torseur::pfd::EquationsOfMotion;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/double_pendule.json"
    ))?;
    let eq = EquationsOfMotion::of(&m)?;
    print!("{eq}");
    for (i, q) in eq.coordinates().iter().enumerate() {
        for (j, p) in eq.coordinates().iter().enumerate() {
            println!("M[{q}][{p}] = {}", eq.mass[i][j].presentation());
        }
        println!("h[{q}] = {}", eq.velocity_terms[i].presentation());
        println!("Q[{q}] = {}", eq.forces[i].presentation());
    }
    // The accelerations at a state: parameters, then [q, q̇, q̈] of each coordinate.
    let mut compiled = eq.compile()?;
    let state = Values::parse(
        r#"{"parameters": {"m1": 1, "m2": 0.5, "L1": 0.4, "L2": 0.3, "g": 9.81},
            "coordinates": {"theta1": [0.5, 0, 0], "theta2": [-0.2, 1, 0]}}"#,
    )?;
    let point = numeric_point(&m, &state)?;
    let acc = compiled
        .accelerations(&point)
        .ok_or("singular mass matrix")?;
    println!("accelerations: {:?}", acc.as_slice());
    Ok(())
}
