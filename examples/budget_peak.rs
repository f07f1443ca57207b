//! Measures the budget's figures of a spec: `cargo run --release --example budget_peak -- SPEC
//! [MAX_TERMS]` derives every requested quantity as `torseur derive` does (values, then the
//! presentation text; with STEPS=1 also every derivation with its steps) and prints the
//! figures the budget bounds after each stage (`torseur::expr::budget::peaks`): the most terms
//! held at once and formed by one product, and the largest expression.
use torseur::expr::budget;

fn main() {
    let mut args = std::env::args().skip(1);
    let path = args.next().expect("a spec");
    if let Some(n) = args.next() {
        budget::set_max_terms(n.parse().expect("a number of terms"));
    }
    let t = std::time::Instant::now();
    let m = torseur::spec::load(&path).unwrap();
    let qs = m.quantities().to_vec();
    let figures = |what: &str| {
        println!(
            "{path}: {what}: {:?}, {:.2} s",
            budget::peaks(),
            t.elapsed().as_secs_f64()
        )
    };
    let ds = match torseur::derivation::derive_values(&m, &qs) {
        Ok(ds) => ds,
        Err(e) => {
            println!("{path}: {e} ({:.2} s)", t.elapsed().as_secs_f64());
            return;
        }
    };
    figures("values");
    let text = torseur::output::derive_text_in(&m, &ds, torseur::output::TextForm::Presentation);
    figures(&format!("text of {} bytes", text.len()));
    if std::env::var_os("STEPS").is_some() {
        for q in &qs {
            torseur::derivation::derive(&m, q).unwrap();
        }
        figures("with steps");
    }
}
