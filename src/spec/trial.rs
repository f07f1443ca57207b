//! A hypothesis' trial motion (« régime forcé », `x(t) = X cos(Ω t)`): its unknowns are new
//! names of the registry, and the motion becomes substitutions of the coordinate and its rates.

use super::SpecError;
use super::refusal::{at, name_ok};
use crate::expr::{CoordinateKind, Expr, Registry, VarId, VarRole};
use crate::mechanism::{Cause, Effect, Stated, Trial};
use crate::wire::{HypothesisSpec, SpecFile};
use std::rc::Rc;

/// The unknowns of every trial motion of the spec, in order: new names, refused at their JSON
/// path when one is already a parameter, a coordinate, an alias, an unknown of the PFD, the
/// time or π, or another trial's.
pub(super) fn unknown_names(spec: &SpecFile, pfd: &[String]) -> Result<Vec<String>, SpecError> {
    let mut out: Vec<String> = Vec::new();
    for (i, h) in spec.hypotheses.iter().enumerate() {
        let Some(t) = &h.trial else { continue };
        for (k, u) in t.unknowns.iter().enumerate() {
            let path = format!("hypotheses[{i}].trial.unknowns[{k}]");
            name_ok(&path, u)?;
            let what = if spec.parameters.iter().any(|p| &p.name == u) {
                Some("a parameter")
            } else if spec.coordinates.iter().any(|c| &c.name == u) {
                Some("a coordinate")
            } else if spec.aliases.iter().any(|a| &a.name == u) {
                Some("an alias")
            } else if pfd.contains(u) {
                Some("an unknown of the PFD")
            } else if u == "t" || u == "pi" {
                Some("reserved (the time, π)")
            } else if out.contains(u) {
                Some("already an unknown of a trial motion")
            } else {
                None
            };
            if let Some(what) = what {
                return Err(at(
                    &path,
                    format!(
                        "`{u}` is {what}: the unknowns of a trial motion are new names (rename \
                         it, or drop it from `parameters`)"
                    ),
                ));
            }
            out.push(u.clone());
        }
    }
    Ok(out)
}

/// The trial motion of hypothesis `h` (at `path`), if it has one: q, q̇, q̈ and the third
/// derivative set to the motion and its time derivatives, after the hypothesis' other
/// substitutions (`subs`), which the motion's value goes through.
pub(super) fn trial(
    reg: &Rc<Registry>,
    h: &HypothesisSpec,
    path: &str,
    subs: &mut Vec<(VarId, Expr)>,
    effects: &mut Vec<Effect>,
) -> Result<Option<Trial>, SpecError> {
    let Some(t) = &h.trial else { return Ok(None) };
    let field = format!("{path}.trial.coordinate");
    let c = &t.coordinate;
    let q = reg.coord(c).ok_or_else(|| {
        at(
            &field,
            format!("unknown coordinate `{c}`{}", reg.coordinate_hint(c)),
        )
    })?;
    let info = reg.coord_info(q);
    if info.has_imposed_rate() {
        return Err(at(&field, format!("`{c}` already has an imposed rate")));
    }
    if info.kind != CoordinateKind::Length {
        return Err(at(
            &field,
            format!(
                "`{c}` is an angle: a trial motion is posed on a length coordinate (the \
                 equation of motion must be linear in it)"
            ),
        ));
    }
    let mut vars: Vec<Expr> = reg.value(q).into_iter().collect();
    vars.extend((1..=3).map(|o| reg.rate(q, o)));
    if subs
        .iter()
        .any(|(v, _)| vars.iter().any(|e| e.contains_var(*v)))
    {
        return Err(at(
            &field,
            format!("the hypothesis already gives the motion of `{c}`"),
        ));
    }
    let unknowns = unknown_vars(reg, &t.unknowns);
    let motion = motion(reg, &t.motion, &format!("{path}.trial.motion"), &unknowns)?;
    let motion = subs
        .iter()
        .fold(motion, |e, (v, val)| e.substitute(*v, val));
    let mut value = motion.clone();
    for e in &vars {
        if let Some(v) = e.single_variable() {
            subs.push((v, value.clone()));
        }
        value = value.dt();
    }
    effects.push(Effect {
        cause: Cause::Posed,
        lhs: Stated::read(reg, c),
        rhs: Stated::read(reg, &t.motion),
    });
    Ok(Some(Trial {
        coord: q,
        motion,
        unknowns,
    }))
}

/// The variables of the names `names`, registered as parameters by the registry.
fn unknown_vars(reg: &Rc<Registry>, names: &[String]) -> Vec<(String, VarId)> {
    names
        .iter()
        .filter_map(|n| {
            let p = reg.param_id(n)?;
            Some((n.clone(), reg.index_of(VarRole::Parameter(p))?))
        })
        .collect()
}

/// The motion's text read at `path`: the time through phases Ω t, the parameters and the
/// unknowns, each unknown present.
fn motion(
    reg: &Rc<Registry>,
    text: &str,
    path: &str,
    unknowns: &[(String, VarId)],
) -> Result<Expr, SpecError> {
    let e = reg.parse(text).map_err(|e| at(path, e.to_string()))?;
    for v in reg.var_ids().filter(|v| e.contains_var(*v)) {
        let ok = match reg.role(v) {
            VarRole::Parameter(p) => !reg.is_unknown(p),
            VarRole::Inverse(_) => true,
            VarRole::Cos(q) | VarRole::Sin(q) => {
                let i = reg.coord_info(q);
                i.is_constant() || i.phase().is_some()
            }
            _ => false,
        };
        if !ok {
            return Err(at(
                path,
                format!(
                    "`{text}` must be written with the time (as Omega*t inside cos and sin), \
                     the parameters and the trial's unknowns only"
                ),
            ));
        }
    }
    if let Some((u, _)) = unknowns.iter().find(|(_, v)| !e.contains_var(*v)) {
        return Err(at(path, format!("the motion `{text}` does not hold `{u}`")));
    }
    Ok(e)
}
