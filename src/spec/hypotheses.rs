//! The motions and relations a hypothesis imposes besides symmetries: coordinates held fixed,
//! a relative equilibrium, rates given as parameters, relations between parameters. Each
//! becomes substitutions applied to the general results (after every derivative is taken).

use super::SpecError;
use super::refusal::at;
use crate::expr::{CoordId, CoordinateKind, Expr, Registry, VarId, VarRole};
use crate::mechanism::{Cause, Effect, Stated};
use crate::wire::HypothesisSpec;
use std::rc::Rc;

/// An expression of the parameters only (no coordinate, rate or unknown), read at `path`.
fn constant(reg: &Rc<Registry>, path: &str, text: &str) -> Result<Expr, SpecError> {
    let e = reg.parse(text).map_err(|e| at(path, e.to_string()))?;
    for v in reg.var_ids().filter(|v| e.contains_var(*v)) {
        let ok = match reg.role(v) {
            VarRole::Parameter(p) => !reg.is_unknown(p),
            VarRole::Inverse(_) => true,
            VarRole::Cos(q) | VarRole::Sin(q) => reg.coord_info(q).is_constant(),
            _ => false,
        };
        if !ok {
            return Err(at(
                path,
                format!("`{text}` must be written with parameters only"),
            ));
        }
    }
    Ok(e)
}

/// The variable of the parameter `p` (not an unknown of the PFD), read at `field`.
fn parameter(reg: &Rc<Registry>, field: &str, p: &str) -> Result<VarId, SpecError> {
    reg.param_id(p)
        .filter(|id| !reg.is_unknown(*id))
        .and_then(|id| reg.index_of(VarRole::Parameter(id)))
        .ok_or_else(|| {
            at(
                field,
                format!("unknown parameter `{p}`{}", reg.parameter_hint(p)),
            )
        })
}

/// q̇, q̈ and the third derivative of `q` set to `first`, 0 and 0.
fn rates(reg: &Rc<Registry>, q: CoordId, first: &Expr, subs: &mut Vec<(VarId, Expr)>) {
    for order in 1..=3u8 {
        if let Some(v) = reg.rate(q, order).single_variable() {
            subs.push((
                v,
                if order == 1 {
                    first.clone()
                } else {
                    reg.zero()
                },
            ));
        }
    }
}

/// q̇ = 0 and q̈ = 0, stated.
fn at_rest(reg: &Rc<Registry>, q: CoordId, effects: &mut Vec<Effect>) {
    effects.push(Effect::posed(reg.dot(q), reg.zero()));
    effects.push(Effect::posed(reg.ddot(q), reg.zero()));
}

/// The substitutions and their statements (`dot(alpha) = 0`, `theta2 = beta0`) of a
/// hypothesis' fixed coordinates, equilibrium, rates and relations, in that order.
pub(super) fn motions(
    reg: &Rc<Registry>,
    h: &HypothesisSpec,
    path: &str,
    subs: &mut Vec<(VarId, Expr)>,
    effects: &mut Vec<Effect>,
) -> Result<(), SpecError> {
    let mut seen: Vec<String> = Vec::new();
    let mut coord = |field: String, c: &str| -> Result<CoordId, SpecError> {
        let q = reg.coord(c).ok_or_else(|| {
            at(
                &field,
                format!("unknown coordinate `{c}`{}", reg.coordinate_hint(c)),
            )
        })?;
        if reg.coord_info(q).has_imposed_rate() {
            return Err(at(&field, format!("`{c}` already has an imposed rate")));
        }
        if seen.iter().any(|x| x == c) {
            return Err(at(&field, format!("the motion of `{c}` is given twice")));
        }
        seen.push(c.to_string());
        Ok(q)
    };
    let zero = reg.zero();
    for (k, c) in h.fixed_coordinates.iter().enumerate() {
        let q = coord(format!("{path}.fixed_coordinates[{k}]"), c)?;
        rates(reg, q, &zero, subs);
        at_rest(reg, q, effects);
    }
    for (c, text) in &h.equilibrium {
        let field = format!("{path}.equilibrium.{c}");
        let q = coord(field.clone(), c)?;
        let info = reg.coord_info(q);
        match info.kind {
            CoordinateKind::Angle => held_angle(reg, q, (c, text), &field, subs)?,
            CoordinateKind::Length => {
                let e = constant(reg, &field, text)?;
                if let Some(v) = reg.value(q).and_then(|e| e.single_variable()) {
                    subs.push((v, e));
                }
            }
        }
        rates(reg, q, &zero, subs);
        effects.push(Effect {
            cause: Cause::Posed,
            lhs: Stated::read(reg, c),
            rhs: Stated::read(reg, text),
        });
        at_rest(reg, q, effects);
    }
    for (c, text) in &h.rates {
        let field = format!("{path}.rates.{c}");
        let q = coord(field.clone(), c)?;
        let e = constant(reg, &field, text)?;
        rates(reg, q, &e, subs);
        effects.push(Effect {
            cause: Cause::Posed,
            lhs: Stated::Expr(reg.dot(q)),
            rhs: Stated::read(reg, text),
        });
        effects.push(Effect::posed(reg.ddot(q), reg.zero()));
    }
    for (p, text) in &h.relations {
        let field = format!("{path}.relations.{p}");
        let v = parameter(reg, &field, p)?;
        let e = constant(reg, &field, text)?;
        if e.contains_var(v) {
            return Err(at(&field, format!("`{p}` is written with itself")));
        }
        // Earlier substitutions hold the parameter too.
        for (_, val) in subs.iter_mut() {
            *val = val.substitute(v, &e);
        }
        subs.push((v, e));
        effects.push(Effect {
            cause: Cause::Posed,
            lhs: Stated::read(reg, p),
            rhs: Stated::read(reg, text),
        });
    }
    Ok(())
}

/// An angle coordinate `q` (named `c`) held at equilibrium at `text`, 0 or an angle
/// parameter: cos q and sin q become those of the parameter (or 1 and 0), and q its value.
fn held_angle(
    reg: &Rc<Registry>,
    q: CoordId,
    (c, text): (&str, &str),
    field: &str,
    subs: &mut Vec<(VarId, Expr)>,
) -> Result<(), SpecError> {
    let (cos, sin, value) = if text.trim() == "0" {
        (reg.one(), reg.zero(), reg.zero())
    } else {
        let b = reg
            .angle(text.trim())
            .filter(|b| reg.coord_info(*b).is_constant())
            .ok_or_else(|| {
                at(
                    field,
                    format!(
                        "the angle `{c}` is held at 0 or at an angle parameter (a parameter of \
                         kind angle), not at `{text}`"
                    ),
                )
            })?;
        let value = reg.param(text.trim()).unwrap_or_else(|| reg.zero());
        (reg.cos(b), reg.sin(b), value)
    };
    for (from, to) in [(reg.cos(q), cos), (reg.sin(q), sin)] {
        if let Some(v) = from.single_variable() {
            subs.push((v, to));
        }
    }
    if let Some(v) = reg.value(q).and_then(|e| e.single_variable()) {
        subs.push((v, value));
    }
    Ok(())
}

/// The variables of a hypothesis' small parameters, read at `path` (one that a substitution
/// of the hypothesis replaces is gone before the truncation: listing it has no effect).
pub(super) fn small_parameters(
    reg: &Rc<Registry>,
    h: &HypothesisSpec,
    path: &str,
) -> Result<Vec<VarId>, SpecError> {
    let mut out = Vec::new();
    for (k, p) in h.small_parameters.iter().enumerate() {
        let field = format!("{path}.small_parameters[{k}]");
        let v = parameter(reg, &field, p)?;
        if out.contains(&v) {
            return Err(at(&field, format!("`{p}` is listed twice")));
        }
        out.push(v);
    }
    Ok(out)
}

/// The substitutions of a hypothesis with, after each one that sets a parameter the spec
/// divides by, the value of its inverse: k = k2 brings 1/k = 1/k2. A parameter the spec
/// divides by may be set to a product of parameters only, and may not be small: refused at
/// `path` otherwise (D = 0 would divide by zero).
pub(super) fn with_inverses(
    reg: &Rc<Registry>,
    subs: Vec<(VarId, Expr)>,
    first_order: &[VarId],
    path: &str,
) -> Result<Vec<(VarId, Expr)>, SpecError> {
    let inverse = |v: VarId| match reg.role(v) {
        VarRole::Parameter(p) => reg.index_of(VarRole::Inverse(p)).map(|w| (p, w)),
        _ => None,
    };
    for v in first_order {
        if let Some((p, _)) = inverse(*v) {
            return Err(at(
                path,
                format!(
                    "`{}` is a small parameter, and the spec divides by it: a first-order \
                     result would hold 1/{}",
                    reg.scalar_name(p),
                    reg.scalar_name(p)
                ),
            ));
        }
    }
    let mut out = Vec::with_capacity(subs.len());
    for (v, val) in subs {
        let Some((p, w)) = inverse(v) else {
            out.push((v, val));
            continue;
        };
        let name = reg.scalar_name(p);
        if val.is_zero() {
            return Err(at(
                path,
                format!("the hypothesis sets `{name}` to 0, and the spec divides by it"),
            ));
        }
        let inv = val.monomial_inverse().map_err(|why| {
            at(
                path,
                format!(
                    "the hypothesis sets `{name}`, which the spec divides by, to `{val}`: {why}"
                ),
            )
        })?;
        out.push((v, val));
        out.push((w, inv));
    }
    Ok(out)
}
