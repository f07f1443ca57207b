//! Imposed rates: a constant (ψ̇ = ω), or a form driven by the free rates of the other
//! coordinates (a gear ratio, rolling without slipping), read once when a registry is built.

use super::*;

/// Whether the rate `e` imposed on `q` is driven by other coordinates' rates (a gear ratio
/// θ̇2 = −(r1/r2) θ̇1, rolling without slipping ẋ = −R θ̇ on a line, ẋ = R θ̇ cos ψ on a
/// plane): a linear form in the first derivatives of coordinates whose rates are free, with
/// coefficients made of parameters and of the coordinates' values (cos ψ), plus a constant.
/// None for a constant (ψ̇ = ω), Some(holonomic) for a driven rate, holonomic when no
/// coefficient holds a coordinate; why not, for anything else.
pub(super) fn driven_by(reg: &Registry, q: CoordId, e: &Expr) -> Result<Option<bool>, String> {
    if e.is_time_independent() {
        return Ok(None);
    }
    let mut holonomic = true;
    let name = &reg.coords[q.0].name;
    let why = format!(
        "the rate of `{name}` is a constant (parameters only), or a linear form of the rates \
         of other coordinates whose rates are free, with coefficients of parameters and \
         coordinates (`-r1/r2*dot(theta1)`, `R*dot(theta)*cos(psi)`)"
    );
    let (with, without) = e.split_by_rates();
    if !without.is_time_independent() {
        return Err(why);
    }
    for (_, x) in with.terms() {
        let mut rate = None;
        for (i, &k) in x.iter().enumerate() {
            if k == 0 {
                continue;
            }
            match reg.roles[i] {
                VarRole::Parameter(p) if !reg.is_unknown(p) => {}
                VarRole::Inverse(_) => {}
                VarRole::Cos(c)
                | VarRole::Sin(c)
                | VarRole::Value(c)
                | VarRole::Reciprocal(c, _) => {
                    holonomic &= reg.coords[c.0].is_fixed();
                }
                VarRole::Rate(c, 1) if k == 1 && rate.is_none() && c != q => rate = Some(c),
                _ => return Err(why),
            }
        }
        if rate.is_none() {
            return Err(why);
        }
    }
    Ok(Some(holonomic))
}
