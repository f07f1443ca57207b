//! How another project's test suite checks hand-written results against torseur, exactly.
//!
//! Load a spec, derive a quantity, and assert that an expression string equals it: the test is
//! the canonical form's zero test (any grouping or order, sin 2θ = 2 sin θ cos θ,
//! sin² + cos² = 1), never a numeric sampling. On a mismatch the message gives the simplified
//! difference in the course's notation.
//!
//! Run: `cargo run --example verify_in_tests`.

use torseur::verify::verify;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let m = torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))?;

    // A student's answer to Q4, under the hypotheses H2 (symmetries, constant rates).
    let student = "m2*L2*sin(theta2)*(L1 + L2*cos(theta2))*dot(theta1)^2 \
                   + 1/2*(C2 - B2)*sin(2*theta2)*dot(theta1)^2 + D2*cos(2*theta2)*dot(theta1)^2";
    torseur::assert_equivalent!(m, "delta(O2,2/0).x2", under "H2", student);
    println!("Q4 (under H2): the student's answer is exactly right");

    // A vector, component by component in the quantity's basis.
    torseur::assert_equivalent!(
        m,
        "Omega(2/0) in B2",
        "[dot(theta2), sin(theta2)*dot(theta1), cos(theta2)*dot(theta1)]"
    );

    // A wrong answer: the verdict says what is missing, exactly.
    let wrong = verify(
        &m,
        "delta(O2,2/0).x2",
        "(A2 + m2*L2^2)*ddot(theta2)",
        Some("H1"),
    )?;
    assert!(!wrong.is_equivalent());
    println!("{wrong}");
    for d in wrong.difference.iter().filter(|d| !d.is_zero()) {
        println!("in LaTeX: {}", torseur::latex::expr(d));
    }
    Ok(())
}
