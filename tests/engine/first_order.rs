//! One combined first order (issue 37): a linearisation `lin(...)` under a hypothesis with
//! small parameters keeps one first order in the small parameters and the small coordinates
//! together, as a course writes D = ε(A) with α, β = ε(1): a product of a small parameter and
//! a small coordinate (or its rate) is second order and goes.
//!
//! The pendulum, by hand: the bar 1 turns by θ about (O, z0) on a pivot with viscous friction
//! c; its centre G is off the bar's line, OG = l x1 + e y1; inertia J about (G, z0), mass m;
//! the weight m g x0 (x0 downwards, so θ = 0 hangs). The moment of the weight at O on z0 is
//! (l x1 + e y1) ∧ m g x0 · z0 = −m g (l sin θ + e cos θ), the friction's −c θ̇, and J_O =
//! J + m (l² + e²), so eom(θ) = (J + m l² + m e²) θ̈ + c θ̇ + m g (l sin θ + e cos θ).
//! Linearised around θ = 0 (sin θ → θ, cos θ → 1): (J + m l² + m e²) θ̈ + c θ̇ + m g l θ + m g e.
//! With e and c small and θ small together: (J + m l²) θ̈ + m g l θ + m g e (m e² θ̈ and c θ̇ are
//! second order).

use torseur::derivation::derive;
use torseur::quantity::Quantity;

fn pendulum() -> torseur::mechanism::Mechanism {
    let v = serde_json::json!({
        "title": "Pendule excentré",
        "ground_origin": "O",
        "parameters": [{"name": "m"}, {"name": "l"}, {"name": "e"}, {"name": "J"},
                       {"name": "g"}, {"name": "c"}],
        "coordinates": [{"name": "theta", "kind": "angle"}],
        "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "theta"}}],
        "points": [{"name": "G", "from": "O", "position": "l*x1 + e*y1"}],
        "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G",
                    "inertia": {"point": "G", "basis": "1",
                                "matrix": [["J", "0", "0"], ["0", "J", "0"], ["0", "0", "J"]]}}],
        "gravity": "g*x0",
        "links": [{"name": "01", "kind": "pivot", "between": ["0", "1"], "point": "O",
                   "axis": "z0", "friction": "c"}],
        "small": [{"coordinate": "theta"}],
        "hypotheses": [{"name": "P", "text": "e et c petits", "small_parameters": ["e", "c"]}],
        "quantities": ["lin(eom(theta))"],
        "pfd": [{"isolate": "1", "theorem": "moment", "point": "O", "on": "z0",
                 "eom": "theta"}]
    });
    torseur::spec::from_str(&v.to_string()).unwrap()
}

#[test]
fn a_linearisation_under_small_parameters_keeps_one_combined_first_order() {
    let m = pendulum();
    let e = |s: &str| m.reg().parse(s).unwrap();
    let d = derive(&m, &Quantity::parse("lin(eom(theta))").unwrap()).unwrap();
    assert_eq!(
        d.value.exprs()[0],
        &e("(J + m*l^2 + m*e^2)*ddot(theta) + c*dot(theta) + m*g*l*theta + m*g*e")
    );
    let h = &m.hypotheses()[0];
    let joint = d.value_under(&m, h);
    assert_eq!(
        joint.exprs()[0],
        &e("(J + m*l^2)*ddot(theta) + m*g*l*theta + m*g*e")
    );
    // The first order in e and c alone (the value outside `lin`) keeps c θ̇ and the sines:
    // only the linearisation joins the two orders.
    let full = derive(&m, &Quantity::parse("eom(theta)").unwrap()).unwrap();
    assert_eq!(
        full.value_under(&m, h).exprs()[0],
        &e("(J + m*l^2)*ddot(theta) + c*dot(theta) + m*g*(l*sin(theta) + e*cos(theta))")
    );
}

#[test]
fn verify_reads_a_linearisation_to_the_same_combined_order() {
    let m = pendulum();
    let v = |text: &str| {
        torseur::verify::verify(&m, "lin(eom(theta))", text, Some("P"))
            .unwrap()
            .is_equivalent()
    };
    assert!(v("(J + m*l^2)*ddot(theta) + m*g*l*theta + m*g*e"));
    // A term of second order written anyway is within the order kept.
    assert!(v(
        "(J + m*l^2)*ddot(theta) + c*dot(theta) + m*g*l*theta + m*g*e"
    ));
    // A wrong first-order term is not.
    assert!(!v("(J + m*l^2)*ddot(theta) + m*g*l*theta - m*g*e"));
    assert!(!v("(J + m*l^2)*ddot(theta) + m*g*l*theta"));
}
