//! `torseur verify`, run as a user would: equivalent or not, up to a factor, relations
//! between unknowns, quantities and expressions.

use super::*;

#[test]
fn verify_answers_equivalent_or_shows_the_difference() {
    let s = spec();
    let ok = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(O2,2/0).x2",
        "--hypothesis",
        "H1",
        "-e",
        "(A2 + m2*L2^2)*ddot(theta2) + (m2*L1*L2*sin(theta2) + 1/2*(C2 - B2 + m2*L2^2)*sin(2*theta2) + D2*cos(2*theta2))*dot(theta1)^2",
    ]);
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    assert!(stdout(&ok).contains("equivalent"));
    let bad = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "delta(O2,2/0).x2",
        "--hypothesis",
        "H1",
        "-e",
        "(A2 + m2*L2^2)*ddot(theta2)",
    ]);
    assert_eq!(bad.status.code(), Some(1));
    assert!(stdout(&bad).contains("NOT equivalent"));
    assert!(stdout(&bad).contains("dot(theta1)^2"), "{}", stdout(&bad));
    let vector = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-e",
        "[-(L1 + L2*cos(theta2))*dot(theta1), 0, L2*dot(theta2)]",
    ]);
    assert_eq!(vector.status.code(), Some(0), "{}", stderr(&vector));
    let malformed = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "V(G2,2/0) in B2",
        "-e",
        "[1, 2",
    ]);
    assert_eq!(malformed.status.code(), Some(2));
}

#[test]
fn verify_accepts_an_equation_of_motion_up_to_a_factor() {
    let eq = "A2*ddot(theta2) + m2*L2^2*ddot(theta2) \
              + (C2 - B2)*sin(theta2)*cos(theta2)*dot(theta1)^2 + D2*cos(2*theta2)*dot(theta1)^2 \
              + m2*L1*L2*sin(theta2)*dot(theta1)^2 + m2*L2^2*sin(theta2)*cos(theta2)*dot(theta1)^2 \
              = -m2*g*L2*cos(theta2) - f*dot(theta2)";
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        eq,
    ]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
    // Twice the equation, sides swapped: the same equation.
    let (lhs, rhs) = eq.split_once('=').unwrap();
    let doubled = format!("2*({rhs}) = 2*({lhs})");
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        &doubled,
    ]);
    assert!(
        o.status.success(),
        "{doubled}: {}{}",
        stdout(&o),
        stderr(&o)
    );
    // Without friction it is another equation.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "eom(theta2)",
        "--hypothesis",
        "H1",
        "-e",
        &eq.replace(" - f*dot(theta2)", ""),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
}

#[test]
fn verify_takes_an_expression_that_starts_with_a_minus() {
    // Found while writing the library: `-e "-m..."` was read as an option.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-q",
        "Omega(2/1) in B1",
        "-e",
        "[-(-dot(theta2)), 0, 0]",
    ]);
    assert!(o.status.success(), "{}{}", stdout(&o), stderr(&o));
}

/// A corrigé writes the pendulum's equation divided by m l (hand derivation in
/// tests/engine/verify.rs: eom(θ) = m l (ẍ cos θ + l θ̈ + g sin θ) for a point mass).
#[test]
fn verify_accepts_an_equation_up_to_a_factor_of_parameters_and_reports_it() {
    let s = fixture("pendule_simple_sur_chariot.json");
    let divided = "ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta) = 0";
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        divided,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("equivalent, up to the factor m*l"),
        "{}",
        stdout(&o)
    );
    // Without -q: found to be the equation of motion of theta, with the same factor.
    let o = run(&["verify", s.to_str().unwrap(), "-e", divided]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("up to the factor m*l"), "{out}");
    assert!(out.contains("equation of motion eom(theta)"), "{out}");
    // Multiplied by dot(theta): another equation (exit 1).
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        "dot(theta)*(ddot(x)*cos(theta) + l*ddot(theta) + g*sin(theta)) = 0",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(stdout(&o).contains("NOT equivalent"), "{}", stdout(&o));
    // The weight's sign wrong (exit 1): the difference is that term alone, −2 m g l sin θ.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "eom(theta)",
        "-e",
        "ddot(x)*cos(theta) + l*ddot(theta) - g*sin(theta) = 0",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("difference: -2*m*g*l*sin(theta)\n"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn verify_decides_relations_between_unknowns_quantities_and_expressions() {
    let s = fixture("pendule_simple_sur_chariot.json");
    // Resultant theorem on the pendulum along y0: Y12 − m g = m Γ(G,2/0)·y0 (hand form in
    // tests/engine/verify.rs), written with the unknown and the quantity Rd(2/0).y0.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-e",
        "Y12 - m*g = Rd(2/0).y0",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("relation: lhs − rhs = 0"), "{out}");
    assert!(
        out.contains("Rd(2/0).y0 replaced by its derived value and Y12 by its solved value"),
        "{out}"
    );
    // A wrong relation (exit 1), with --quantity naming the unknown it is about.
    let o = run(&[
        "verify",
        s.to_str().unwrap(),
        "-q",
        "Y12",
        "-e",
        "Y12 = m*g",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    assert!(stdout(&o).contains("NOT equivalent"), "{}", stdout(&o));
    // The regulator's Q6: C_m = δ(O1,E/0)·z0, under H2.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-e",
        "C_m = delta(O1,E/0).z0",
        "--hypothesis",
        "H2",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    // Undeclared names: exit 2, all of them named; an unknown no equation determines: exit 2.
    let o = run(&[
        "verify",
        spec().to_str().unwrap(),
        "-e",
        "C_m = foo + bar*sin(baz)",
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("unknown names `foo`, `bar`, `baz` in `foo + bar*sin(baz)`"),
        "{}",
        stderr(&o)
    );
    assert!(stdout(&o).is_empty());
    let o = run(&["verify", spec().to_str().unwrap(), "-e", "X01 = 0"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("`X01`"), "{}", stderr(&o));
    // Without -q, the text must be an equation.
    let o = run(&["verify", spec().to_str().unwrap(), "-e", "C_m"]);
    assert_eq!(o.status.code(), Some(2));
}
