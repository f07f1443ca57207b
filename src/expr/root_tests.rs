//! Square roots in the canonical form, checked by routes that do not go through the reduction:
//! identities squared out by hand, float evaluation, and refusals of radicands that are
//! squares.

use super::*;

/// The slider–crank's loop law: R, L, θ, x, and the root √(L² − R² sin²θ).
fn crank() -> Rc<Registry> {
    Registry::builder()
        .parameters(&["R".into(), "L".into()])
        .coordinate("theta", CoordinateKind::Angle)
        .coordinate("x", CoordinateKind::Length)
        .roots(&["L^2 - R^2*sin(theta)^2".into()])
        .build()
        .unwrap()
}

#[test]
fn a_root_squared_is_its_radicand() {
    let reg = crank();
    let s = reg.parse("sqrt(L^2 - R^2*sin(theta)^2)").unwrap();
    // Written by hand: (a + b s)² = a² + b² (L² − R² sin²θ) + 2 a b s, a = R cos θ, b = 3.
    let e = reg
        .parse("(R*cos(theta) + 3*sqrt(L^2 - R^2*sin(theta)^2))^2")
        .unwrap();
    let by_hand = reg
        .parse("R^2*cos(theta)^2 + 9*L^2 - 9*R^2*sin(theta)^2 + 6*R*cos(theta)*sqrt(L^2 - R^2*sin(theta)^2)")
        .unwrap();
    assert_eq!(e, by_hand);
    assert_eq!(s.pow(3), &reg.parse("L^2 - R^2*sin(theta)^2").unwrap() * &s);
    assert!(s.pow(4) == reg.parse("(L^2 - R^2*sin(theta)^2)^2").unwrap());
}

#[test]
fn the_loop_law_times_its_conjugate_is_the_eliminated_closure() {
    let reg = crank();
    // (x − R cos θ − s)(x − R cos θ + s) = (x − R cos θ)² − L² + R² sin²θ
    // = x² − 2 R x cos θ + R² − L², the closure with the rod's direction eliminated.
    let d = reg
        .parse("x - R*cos(theta) - sqrt(L^2 - R^2*sin(theta)^2)")
        .unwrap();
    let c = reg
        .parse("x - R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)")
        .unwrap();
    assert_eq!(
        &d * &c,
        reg.parse("x^2 - 2*R*x*cos(theta) + R^2 - L^2").unwrap()
    );
    let (a, b) = d.split_root(RootId(0));
    assert_eq!(a, reg.parse("x - R*cos(theta)").unwrap());
    assert_eq!(b, reg.integer(-1));
}

#[test]
fn a_reduced_form_with_a_root_is_zero_only_when_both_parts_are() {
    let reg = crank();
    let s = reg.parse("sqrt(L^2 - R^2*sin(theta)^2)").unwrap();
    assert!(!(&s - &reg.parse("L").unwrap()).is_zero());
    assert!(!s.is_zero());
    assert!((&s - &s).is_zero());
    // c² P reads c s; the text prints back and parses to the same form.
    let two = reg.parse("sqrt(4*L^2 - 4*R^2*sin(theta)^2)").unwrap();
    assert_eq!(two, &reg.integer(2) * &s);
    let e = reg
        .parse("R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)")
        .unwrap();
    assert_eq!(reg.parse(&e.to_string()).unwrap(), e);
    assert_eq!(reg.parse(&e.presentation().to_string()).unwrap(), e);
}

#[test]
fn a_root_evaluates_to_the_float_square_root() {
    let reg = crank();
    let e = reg
        .parse("R*cos(theta) + sqrt(L^2 - R^2*sin(theta)^2)")
        .unwrap();
    let (r, l, th) = (0.05_f64, 0.2_f64, 0.7_f64);
    let mut point = vec![f64::NAN; reg.nvars()];
    let set = |role: VarRole, v: f64, point: &mut Vec<f64>| {
        point[reg.index_of(role).unwrap().index()] = v;
    };
    let q = reg.coord("theta").unwrap();
    set(
        VarRole::Parameter(reg.param_id("R").unwrap()),
        r,
        &mut point,
    );
    set(
        VarRole::Parameter(reg.param_id("L").unwrap()),
        l,
        &mut point,
    );
    set(VarRole::Cos(q), th.cos(), &mut point);
    set(VarRole::Sin(q), th.sin(), &mut point);
    reg.fill_roots(&mut point);
    let by_hand = r * th.cos() + (l * l - r * r * th.sin() * th.sin()).sqrt();
    assert!((e.eval(&point) - by_hand).abs() < 1e-15);
}

#[test]
fn radicands_that_are_squares_are_refused() {
    let build = |radicand: &str| {
        Registry::builder()
            .parameters(&["R".into(), "L".into()])
            .coordinate("theta", CoordinateKind::Angle)
            .roots(&[radicand.into()])
            .build()
    };
    for square in [
        "L^2",
        "4*R^2*L^2",
        "-L^2 - 2*L*R - R^2",
        // Squares only through sin² + cos² = 1: sin²θ, (2 + sin θ)² written out.
        "1 - cos(theta)^2",
        "5 + 4*sin(theta) - cos(theta)^2",
        // (R cos θ + L sin θ)², written out.
        "R^2 + (L^2 - R^2)*sin(theta)^2 + 2*R*L*sin(theta)*cos(theta)",
        "7",
    ] {
        assert!(build(square).is_err(), "{square}");
    }
    for fine in [
        "L^2 + R^2",
        "L^2 - R^2*sin(theta)^2",
        "1 - cos(theta)",
        "2*L*R",
    ] {
        assert!(build(fine).is_ok(), "{fine}");
    }
    let reg = crank();
    assert_eq!(reg.parse("sqrt(9/4)").unwrap(), reg.parse("3/2").unwrap());
    assert!(reg.parse("sqrt(2)").is_err());
    assert!(reg.parse("sqrt(L^2 + R^2)").is_err());
}
