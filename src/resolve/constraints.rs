//! The loop closures' and rolling conditions' references, resolved once for both sides: the
//! coordinates each determines (each once, none with a rate of its own, every other rate
//! free), a rolling condition's velocity V(I,2/0) read as a point and two frames, and the
//! directions it is zero along.

use super::pfd::Known;
use super::{Refusal, at, find};
use crate::quantity::{Quantity, QuantityKind};

/// A loop closure's references, in the order of the spec's `closures`.
#[derive(Debug, Clone)]
pub struct ClosureNode {
    /// The coordinates it determines (indices in `coordinates`).
    pub dependent: Vec<usize>,
}

/// A rolling condition's references, in the order of the spec's `rolling`.
#[derive(Debug, Clone)]
pub struct RollingNode {
    /// The velocity that is zero, as the course writes it: V(I,2/0).
    pub velocity: Quantity,
    /// The position of the contact point I.
    pub point: usize,
    /// The positions of the moving frame (a solid's) and of the reference frame.
    pub motion: [usize; 2],
    /// The basis vectors it is zero along, (the position of its frame, its axis); empty: all
    /// of it.
    pub on: Vec<(usize, usize)>,
    /// The coordinates whose rates it determines (indices in `coordinates`).
    pub dependent: Vec<usize>,
}

/// The coordinates a closure or a rolling condition at `at` determines: at least one, each
/// known, without a rate of its own, and not already `taken` (which they join).
fn dependents(
    known: &Known,
    (at_path, what): (&str, &str),
    list: &[String],
    taken: &mut Vec<usize>,
) -> Result<Vec<usize>, Refusal> {
    if list.is_empty() {
        let why = format!("name the coordinates the {what} determines");
        return Err(at(format!("{at_path}.dependent"), why));
    }
    let spec = known.spec;
    let mut out = Vec::with_capacity(list.len());
    for (j, d) in list.iter().enumerate() {
        let path = format!("{at_path}.dependent[{j}]");
        let k = find(known.coords, "coordinate", path.clone(), d)?;
        if spec.coordinates[k].rate.is_some() {
            let why = format!(
                "`{d}` has a rate of its own (coordinates[{k}].rate): the {what} determines it"
            );
            return Err(at(path, why));
        }
        if taken.contains(&k) {
            return Err(at(path, format!("`{d}` is determined twice")));
        }
        taken.push(k);
        out.push(k);
    }
    Ok(out)
}

/// A rolling condition's velocity, point and frames, and the directions it is zero along, as
/// many as its dependent coordinates when given.
fn rolling(known: &Known, i: usize, taken: &mut Vec<usize>) -> Result<RollingNode, Refusal> {
    let r = &known.spec.rolling[i];
    let dependent = dependents(
        known,
        (&format!("rolling[{i}]"), "rolling condition"),
        &r.dependent,
        taken,
    )?;
    let path = format!("rolling[{i}].velocity");
    let velocity = Quantity::parse(&r.velocity).map_err(|e| at(&path, e.to_string()))?;
    let QuantityKind::Velocity { point, motion } = &velocity.kind else {
        let why = format!(
            "`{}` is not a velocity: write the velocity that is zero at the contact, V(I,2/0)",
            crate::excerpt::excerpt(&r.velocity)
        );
        return Err(at(path, why));
    };
    let point = find(known.points, "point", path.clone(), point)?;
    let frame = |n: &str| {
        let solid = known.solids.iter().find(|s| s.name == n).map(|s| s.frame);
        (solid.or_else(|| known.frames.get(n).copied()))
            .ok_or_else(|| at(&path, format!("unknown solid or frame `{n}`")))
    };
    let motion = [frame(&motion.moving)?, frame(&motion.reference)?];
    let mut on = Vec::with_capacity(r.on.len());
    for (k, u) in r.on.iter().enumerate() {
        let why = || format!("unknown basis vector `{u}`");
        let v = known.basis_vector(u);
        on.push(v.ok_or_else(|| at(format!("rolling[{i}].on[{k}]"), why()))?);
    }
    if !on.is_empty() && on.len() != dependent.len() {
        let n = dependent.len();
        let why = format!(
            "{} directions for {n} dependent coordinate{}: as many as the coordinates it \
             determines",
            on.len(),
            if n == 1 { "" } else { "s" }
        );
        return Err(at(format!("rolling[{i}].on"), why));
    }
    Ok(RollingNode {
        velocity,
        point,
        motion,
        on,
        dependent,
    })
}

/// The closures and the rolling conditions, and the coordinates' rates: with either, no
/// coordinate has a given rate (the ones they determine get theirs from them, the others are
/// free).
pub(super) fn constraints(known: &Known) -> Result<(Vec<ClosureNode>, Vec<RollingNode>), Refusal> {
    let spec = known.spec;
    let mut taken = Vec::new();
    let mut closures = Vec::with_capacity(spec.closures.len());
    for (i, c) in spec.closures.iter().enumerate() {
        let path = format!("closures[{i}]");
        let dependent = dependents(known, (&path, "closure"), &c.dependent, &mut taken)?;
        closures.push(ClosureNode { dependent });
    }
    let rolling = (0..spec.rolling.len())
        .map(|i| rolling(known, i, &mut taken))
        .collect::<Result<Vec<_>, _>>()?;
    // The loop's derivative is solved for the dependent rates in terms of free rates.
    if !taken.is_empty()
        && let Some(i) = spec.coordinates.iter().position(|c| c.rate.is_some())
    {
        return Err(at(
            format!("coordinates[{i}].rate"),
            "a mechanism with a loop closure or a rolling condition takes free rates only for \
             now (drive the crank by a torque rather than impose its rate)",
        ));
    }
    Ok((closures, rolling))
}
