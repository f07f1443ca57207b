//! Derived values shown in the spec's notation: `value.display(&m)` writes a scalar in the
//! presentation form, a vector as a sum along basis vectors, a torsor as its resultant and its
//! moment at a point, and a derivation step by step; each reads back as spec text.
//!
//! Run: `cargo run --release --example display`

use torseur::{Quantity, derive};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))?;
    for q in ["Omega(2/0)", "V(G2,2/0)", "{C(2/0)}_O2", "delta(O2,2/0).x2"] {
        let d = derive(&m, &Quantity::parse(q)?)?;
        println!("{q} = {}", d.value.display(&m));
    }
    // A derivation, with the theorem behind each step.
    let d = derive(&m, &Quantity::parse("sigma(O1,E/0).z0")?)?;
    println!("\n{}", d.display(&m));
    // What is shown reads back to the same vector (the spec's own reader).
    let d = derive(&m, &Quantity::parse("V(G2,2/0)")?)?;
    let text = d.value.display(&m).to_string();
    let axis = |n: &str| Some((m.frames().find(n.get(1..)?)?, "xyz".find(n.get(..1)?)?));
    let read = m.reg().parse_vector(&text, &axis)?;
    let torseur::Value::Vector { basis, components } = &d.value else {
        unreachable!()
    };
    assert_eq!(read, vec![(*basis, components.clone())]);
    Ok(())
}
