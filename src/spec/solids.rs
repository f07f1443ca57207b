//! The solids of a spec: each one's mass (or none: a body of negligible mass), its centre of
//! inertia and its inertia operator, read as resolved, every refusal at its JSON path.

use super::SpecError;
use super::refusal::{at, bounded, expr_err};
use crate::expr::Registry;
use crate::frame::{Axis, FrameId, Frames};
use crate::inertia::{Inertia, Symmetry};
use crate::mechanism::{Body, BodyId};
use crate::point::PointId;
use crate::resolve::Resolved;
use crate::wire::{SpecFile, SymmetrySpec};
use std::rc::Rc;

/// The solids: mass, centre, inertia operator and symmetries, named and referenced as
/// resolved.
pub(super) fn bodies(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    frames: &Frames,
    resolved: &Resolved,
) -> Result<Vec<Body>, SpecError> {
    // Solids: named and referenced in the trees.
    let mut bodies = Vec::new();
    for ((i, s), node) in spec.solids.iter().enumerate().zip(&resolved.solids) {
        let path = format!("solids[{i}]");
        let frame = FrameId(node.frame);
        let (mass, massless) = solid_mass(reg, s, &path)?;
        if massless {
            massless_has_nothing_else(s, &path)?;
        }
        // A body of negligible mass needs no centre: its frame's origin stands for it (every
        // term it enters is multiplied by its zero mass).
        let centre = match node.centre {
            Some(c) => PointId(c),
            None if massless => PointId(resolved.frames[node.frame].origin),
            None => {
                return Err(at(
                    format!("{path}.centre"),
                    "missing: a solid with a mass has a centre of inertia (a point)",
                ));
            }
        };
        let inertia = match (&s.inertia, node.inertia) {
            (Some(given), Some((point, basis))) => Some(inertia(
                reg,
                frames,
                (frame, PointId(point), FrameId(basis)),
                given,
                &format!("{path}.inertia"),
            )?),
            _ => None,
        };
        let mut symmetries = Vec::new();
        for (k, sym) in s.symmetries.iter().enumerate() {
            let sp = format!("{path}.symmetries[{k}]");
            let (txt, ctor): (&str, fn(Axis) -> Symmetry) = match sym {
                SymmetrySpec::Plane { normal } => (normal, Symmetry::Plane),
                SymmetrySpec::Revolution { axis } => (axis, Symmetry::Revolution),
            };
            let (f, axis) = frames
                .basis_vector(txt)
                .ok_or_else(|| at(&sp, format!("`{txt}` is not a basis vector")))?;
            let Some(ine) = &inertia else {
                return Err(at(&sp, "a point mass has no symmetry to declare"));
            };
            if f != ine.basis {
                return Err(at(
                    &sp,
                    format!(
                        "`{txt}` is not a vector of B{}, the basis the inertia matrix is written in",
                        frames.get(ine.basis).name
                    ),
                ));
            }
            symmetries.push(ctor(axis));
        }
        bodies.push(Body {
            name: s.name.clone(),
            frame,
            mass,
            massless,
            centre,
            inertia,
            symmetries,
            carried_by: node.carried_by.map(BodyId),
        });
    }

    Ok(bodies)
}

/// A solid's mass, and whether it is negligible: declared `"massless": true` (no mass, or a
/// mass of 0), or a mass that is zero. A solid that is not massless gives its mass.
fn solid_mass(
    reg: &Rc<Registry>,
    s: &crate::wire::SolidSpec,
    path: &str,
) -> Result<(crate::expr::Expr, bool), SpecError> {
    let mp = format!("{path}.mass");
    let Some(text) = &s.mass else {
        if s.massless {
            return Ok((reg.zero(), true));
        }
        return Err(at(
            mp,
            "missing: give the solid's mass, or declare a body of negligible mass with \
             `\"massless\": true`",
        ));
    };
    let mass = reg
        .parse(text)
        .map_err(|e| expr_err(&mp, e))
        .and_then(|e| bounded(&mp, e))?;
    if !mass.is_time_independent() {
        return Err(at(mp, "a mass is constant (parameters only)"));
    }
    if s.massless && !mass.is_zero() {
        return Err(at(
            mp,
            format!(
                "the solid is declared `\"massless\": true` but its mass is `{text}`: remove \
                 `mass`, or `massless` if the solid has this mass"
            ),
        ));
    }
    let massless = mass.is_zero();
    Ok((mass, massless))
}

/// A body of negligible mass has no inertia operator and no symmetries to declare.
fn massless_has_nothing_else(s: &crate::wire::SolidSpec, path: &str) -> Result<(), SpecError> {
    let why = if s.massless {
        "the solid is declared `\"massless\": true`"
    } else {
        "a mass of 0 makes the solid a body of negligible mass"
    };
    if s.inertia.is_some() {
        return Err(at(
            format!("{path}.inertia"),
            format!("{why}: it has no inertia operator (remove `inertia`, or give its mass)"),
        ));
    }
    if !s.symmetries.is_empty() {
        return Err(at(
            format!("{path}.symmetries[0]"),
            format!("{why}: it has no symmetry to declare (remove `symmetries`)"),
        ));
    }
    Ok(())
}

/// A solid's inertia operator at `point` in `basis` (`frame` the solid's): constant
/// entries, a symmetric matrix, a basis in which the operator does not turn.
fn inertia(
    reg: &Rc<Registry>,
    frames: &Frames,
    (frame, point, basis): (FrameId, PointId, FrameId),
    given: &crate::wire::InertiaSpec,
    ip: &str,
) -> Result<Inertia, SpecError> {
    let mut m: Vec<Vec<crate::expr::Expr>> = Vec::new();
    for (r, row) in given.matrix.iter().enumerate() {
        let mut out = Vec::new();
        for (c, cell) in row.iter().enumerate() {
            let e = reg
                .parse(cell)
                .map_err(|e| expr_err(&format!("{ip}.matrix[{r}][{c}]"), e))
                .and_then(|e| bounded(&format!("{ip}.matrix[{r}][{c}]"), e))?;
            if !e.is_time_independent() {
                return Err(at(
                    format!("{ip}.matrix[{r}][{c}]"),
                    "an inertia entry is constant in the solid's basis",
                ));
            }
            out.push(e);
        }
        m.push(out);
    }
    for r in 0..3 {
        for c in r + 1..3 {
            if m[r][c] != m[c][r] {
                return Err(at(
                    format!("{ip}.matrix[{c}][{r}]"),
                    format!(
                        "the inertia matrix is not symmetric: entry [{r}][{c}] is \
                             `{}` but entry [{c}][{r}] is `{}`",
                        m[r][c], m[c][r]
                    ),
                ));
            }
        }
    }
    invariant_in_solid(frames, frame, basis, &m).map_err(|msg| at(format!("{ip}.basis"), msg))?;
    let matrix = std::array::from_fn(|r| std::array::from_fn(|c| m[r][c].clone()));
    Ok(Inertia {
        point,
        basis,
        matrix,
    })
}

/// An inertia matrix is constant in the solid's basis. Given in another basis, that basis
/// must be fixed in the solid, or turn relative to it about one of its own axes around which
/// the matrix is of revolution (then it is the same in every such basis); anything else would
/// be a matrix the engine takes as constant while it is not.
fn invariant_in_solid(
    frames: &Frames,
    solid: FrameId,
    basis: FrameId,
    m: &[Vec<crate::expr::Expr>],
) -> Result<(), String> {
    let w = crate::vector::omega(frames, solid, basis).express_in(frames, basis);
    let turning: Vec<usize> = (0..3).filter(|&k| !w[k].is_zero()).collect();
    let ok = match turning.as_slice() {
        [] => true,
        [k] => {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            m[i][*k].is_zero() && m[j][*k].is_zero() && m[i][j].is_zero() && m[i][i] == m[j][j]
        }
        _ => false,
    };
    if ok {
        Ok(())
    } else {
        Err(format!(
            "the inertia matrix is given in basis {} which turns relative to the solid's frame \
             {}: give it in the solid's basis (or in a basis where it is of revolution about \
             the relative rotation axis)",
            frames.get(basis).name,
            frames.get(solid).name
        ))
    }
}
