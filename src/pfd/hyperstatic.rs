//! Hyperstatic mechanisms (« hyperstatique de degré h »): declared equations that fix some
//! unknowns of the links only through a relation between them (two bearings that both hold the
//! shaft axially: X_A + X_B = …).
//!
//! The declared system is solved for what it determines. Before an unknown is called
//! undetermined, the whole PFD is written as the course counts it, the six scalar equations of
//! every solid isolated alone (resultant and moment at the ground's origin on the ground's
//! basis, and the Coulomb laws): an unknown that system determines means an equation is
//! missing from the spec, and is refused; otherwise the mechanism is hyperstatic and its
//! degree h is the number of the link unknowns that system leaves free, Ns − rs.

use super::{PfdError, torsor, unknown_vars};
use crate::expr::{Expr, VarId};
use crate::frame::Axis;
use crate::mechanism::{BodyId, Mechanism, Theorem};
use crate::wire::TheoremKind;

/// What the declared equations leave undetermined, in a hyperstatic mechanism.
#[derive(Debug, Clone, PartialEq)]
pub struct Hyperstatic {
    /// The degree of hyperstatism h: how many link unknowns the PFD of every solid leaves
    /// free.
    pub degree: usize,
    /// The unknowns the declared equations do not determine, in the order they occur.
    pub undetermined: Vec<String>,
    /// Each relation the declared equations give between them, as a residual (= 0):
    /// X_A + X_B − F for two bearings that share an axial load F.
    pub relations: Vec<Expr>,
}

/// The scalar equations of the whole PFD as the course counts them: for every solid isolated
/// alone (with the solids it carries), the resultant and the moment at the ground's origin on the ground's three vectors;
/// then the Coulomb laws.
fn every_equation(m: &Mechanism, cache: &mut torsor::Cache) -> Vec<Expr> {
    let ground = m.frames.ground();
    let origin = m.frame_origins[ground.0];
    let mut rows = Vec::new();
    // A carried solid is counted with its carrier: one solid for the course.
    for (b, body) in m.bodies.iter().enumerate() {
        if body.carried_by.is_some() {
            continue;
        }
        let (isolate, solids) = m.isolated(&body.name, &[BodyId(b)]);
        for kind in [TheoremKind::Resultant, TheoremKind::Moment] {
            for axis in Axis::ALL {
                let th = Theorem {
                    isolate: isolate.clone(),
                    solids: solids.clone(),
                    kind,
                    point: origin,
                    on: (ground, axis),
                    eom: None,
                };
                let r = super::residual(m, &th, cache);
                if !r.is_zero() {
                    rows.push(r);
                }
            }
        }
    }
    rows.extend(m.dynamics.laws.iter().map(|l| l.residual()));
    rows
}

/// Gauss–Jordan elimination, fraction-free, of `rows` (linear in `vars`): the variables it
/// leaves free, and for each pivot its variable and its row (c x + Σ cₖ free_k + rest).
/// A pivot is a number when one exists, else the shortest nonzero coefficient: the rank is
/// the generic one, where no pivot vanishes.
fn reduced(rows: Vec<Expr>, vars: &[VarId]) -> (Vec<VarId>, Vec<(VarId, Expr)>) {
    let mut pending = rows;
    let mut pivots: Vec<(VarId, Expr)> = Vec::new();
    let mut free = Vec::new();
    for &v in vars {
        let pos = (pending
            .iter()
            .position(|r| r.derivative(v).is_nonzero_constant()))
        .or_else(|| {
            (pending.iter().enumerate())
                .map(|(i, r)| (i, r.derivative(v)))
                .filter(|(_, c)| !c.is_zero())
                .min_by_key(|(_, c)| c.nterms())
                .map(|(i, _)| i)
        });
        let Some(pos) = pos else {
            free.push(v);
            continue;
        };
        let row = pending.remove(pos);
        let p = row.derivative(v);
        let clear = |r: &mut Expr| {
            let c = r.derivative(v);
            if !c.is_zero() {
                *r = &(&*r * &p) - &(&c * &row);
            }
        };
        pending.iter_mut().for_each(clear);
        pivots.iter_mut().for_each(|(_, r)| clear(r));
        pivots.push((v, row));
    }
    (free, pivots)
}

/// The unknowns of `undetermined` (by the declared equations) that the whole PFD determines:
/// the equations the spec is missing. Empty when the mechanism is hyperstatic, with its
/// degree.
fn whole(m: &Mechanism, cache: &mut torsor::Cache, undetermined: &[VarId]) -> (usize, Vec<VarId>) {
    let vars: Vec<VarId> = unknown_vars(m).into_iter().map(|(_, v)| v).collect();
    let (free, pivots) = reduced(every_equation(m, cache), &vars);
    let determined = |v: VarId| {
        (pivots.iter().find(|(p, _)| *p == v))
            .is_some_and(|(_, r)| free.iter().all(|&f| r.derivative(f).is_zero()))
    };
    let missing = undetermined
        .iter()
        .copied()
        .filter(|&v| determined(v))
        .collect();
    (free.len(), missing)
}

/// The hyperstatic part of a solution whose declared equations left `free` unknowns without
/// a pivot; `solved` holds every other unknown's value, which may hold the free ones.
/// Refused when the whole PFD would determine one of them: an equation is missing.
pub(super) fn undetermined(
    m: &Mechanism,
    cache: &mut torsor::Cache,
    free: &[VarId],
    solved: &[(VarId, crate::expr::Fraction)],
    name: &dyn Fn(VarId) -> String,
) -> Result<Hyperstatic, PfdError> {
    let x = |v: VarId| m.reg.variable(v);
    let mut vars: Vec<VarId> = Vec::new();
    let mut relations = Vec::new();
    for (v, value) in solved {
        if free.iter().any(|&f| !value.num.derivative(f).is_zero()) {
            vars.push(*v);
            // x = n/d, kept as d x − n = 0.
            relations.push(&(&value.den * &x(*v)) - &value.num);
        }
    }
    vars.extend_from_slice(free);
    let (degree, missing) = whole(m, cache, &vars);
    if !missing.is_empty() || degree == 0 {
        let unknowns = if missing.is_empty() { &vars } else { &missing };
        return Err(PfdError::MissingEquation {
            unknowns: unknowns.iter().map(|&v| name(v)).collect(),
        });
    }
    Ok(Hyperstatic {
        degree,
        undetermined: vars.into_iter().map(name).collect(),
        relations,
    })
}
