//! Small motions: the linearisation of a result around the equilibrium of the `small`
//! coordinates, and one combined first order with a hypothesis' small parameters.

use crate::expr::Expr;
use crate::mechanism::Mechanism;

/// The small-motion linearisation of `e` around the equilibrium of the `small` coordinates
/// (their rates and accelerations small too): f(x0) + Σ ∂f/∂xᵢ(x0)·(xᵢ − xᵢ0), exactly, with
/// sin q ≈ q and cos q ≈ 1 for a small angle. The other coordinates keep their full form.
pub fn linearise(m: &Mechanism, e: &Expr) -> Expr {
    let reg = &m.reg;
    let small = &m.dynamics.small;
    let at_equilibrium = |f: &Expr| at_equilibrium(m, f);
    let mut out = at_equilibrium(e);
    for s in small {
        let q = s.coord;
        if let Some(value) = reg.value(q) {
            let deviation = &value - &s.around;
            out = &out + &(&at_equilibrium(&e.partial_coordinate(q)) * &deviation);
        }
        for order in 1..=2u8 {
            let d = e.partial_rate(q, order);
            if !d.is_zero() {
                out = &out + &(&at_equilibrium(&d) * &reg.rate(q, order));
            }
        }
    }
    out
}

/// `e` with every small coordinate at its equilibrium and its rates zero (sin θ = 0 and
/// cos θ = 1 for an angle around 0).
fn at_equilibrium(m: &Mechanism, e: &Expr) -> Expr {
    let reg = &m.reg;
    let mut r = e.clone();
    for s in &m.dynamics.small {
        let q = s.coord;
        if let Some(si) = reg.index_of(crate::expr::VarRole::Sin(q)) {
            r = r.substitute(si, &reg.zero());
        }
        if let Some(c) = reg.index_of(crate::expr::VarRole::Cos(q)) {
            r = r.substitute(c, &reg.one());
        }
        if let Some(v) = reg.coordinates()[q.0].value_var() {
            r = r.substitute(v, &s.around);
        }
        for order in 1..=3u8 {
            if let Some(i) = reg.index_of(crate::expr::VarRole::Rate(q, order)) {
                r = r.substitute(i, &reg.zero());
            }
        }
    }
    r
}

/// A linearisation [`linearise`] under the hypothesis `h` that keeps results to first order
/// in small parameters, kept to one combined first order: with ε the small parameters and δ
/// the small coordinates' deviations and rates, the terms in ε δ are second order and go,
/// e|ε=0 + e|δ=0 − e|ε=0,δ=0 of e = h(lin(…)) (D = ε(A) and α, β = ε(1) give D α no place).
pub fn first_order_jointly(m: &Mechanism, e: &Expr, h: &crate::mechanism::Hypothesis) -> Expr {
    let r = h.apply(e);
    if h.first_order.is_empty() {
        return r;
    }
    let zero = m.reg.zero();
    let no_small =
        |x: &Expr| (h.first_order.iter()).fold(x.clone(), |acc, v| acc.substitute(*v, &zero));
    let coordinates_only = no_small(&r);
    let parameters_only = at_equilibrium(m, &r);
    let neither = no_small(&parameters_only);
    &(&coordinates_only + &parameters_only) - &neither
}
