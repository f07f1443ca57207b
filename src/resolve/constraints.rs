//! The loop closures', rolling conditions' and helical links' references, resolved once for
//! both sides: the coordinates each determines (each once, none with a rate of its own, every
//! other rate free), a rolling condition's velocity V(I,2/0) read as a point and two frames,
//! and the directions it is zero along; a helical link's point, frames and axis.

use super::pfd::{Known, LinkNode, Side};
use super::{Refusal, at, find};
use crate::quantity::{Quantity, QuantityKind};
use crate::wire::LinkKind;

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

/// A helical link's references, in the order of the spec's `links` (helical ones only).
#[derive(Debug, Clone)]
pub struct HelixNode {
    /// Its index in `links`.
    pub link: usize,
    /// The position of its point, on its axis.
    pub point: usize,
    /// The positions of the frames of its first and second solids (the ground's for the
    /// ground): the relation holds in the motion of the second with respect to the first.
    pub motion: [usize; 2],
    /// Its axis: (the position of its frame, its axis 0, 1 or 2).
    pub axis: (usize, usize),
    /// The coordinate whose rate it determines (index in `coordinates`); none when the
    /// positions satisfy its relation already.
    pub dependent: Option<usize>,
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
        (solid.or_else(|| known.frames.get(n).copied())).ok_or_else(|| {
            let mut declared: Vec<&str> = known.frames.keys().copied().collect();
            declared.extend(known.solids.iter().map(|s| s.name));
            declared.sort_unstable();
            declared.dedup();
            let hint = crate::hint::suggestion(n, &declared);
            at(&path, format!("unknown solid or frame `{n}`{hint}"))
        })
    };
    let motion = [frame(&motion.moving)?, frame(&motion.reference)?];
    let mut on = Vec::with_capacity(r.on.len());
    for (k, u) in r.on.iter().enumerate() {
        let why = || format!("unknown basis vector `{u}`{}", known.vector_hint(u));
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

/// The helical links: their points, frames and axes as resolved with the links, and the
/// coordinate each determines, once and without a rate of its own.
fn helices(
    known: &Known,
    links: &[LinkNode],
    taken: &mut Vec<usize>,
) -> Result<Vec<HelixNode>, Refusal> {
    let spec = known.spec;
    let frame = |s: Side| match s {
        Side::Ground => 0,
        Side::Solid(k) => known.solids[k].frame,
    };
    let mut out = Vec::new();
    for (i, (l, node)) in spec.links.iter().zip(links).enumerate() {
        if l.kind != LinkKind::Helical {
            continue;
        }
        if let (Some(k), Some(d)) = (node.dependent, &l.dependent) {
            let path = format!("links[{i}].dependent");
            if spec.coordinates[k].rate.is_some() {
                let why = format!(
                    "`{d}` has a rate of its own (coordinates[{k}].rate): the helical link \
                     determines it"
                );
                return Err(at(path, why));
            }
            if taken.contains(&k) {
                return Err(at(path, format!("`{d}` is determined twice")));
            }
            taken.push(k);
        }
        out.push(HelixNode {
            link: i,
            point: node.point,
            motion: node.sides().map(frame),
            axis: node.axis,
            dependent: node.dependent,
        });
    }
    Ok(out)
}

/// What [`constraints`] resolves: the closures, the rolling conditions, the helical links.
pub(super) type Constraints = (Vec<ClosureNode>, Vec<RollingNode>, Vec<HelixNode>);

/// The closures, the rolling conditions and the helical links, and the coordinates' rates:
/// with any of them determining a rate, no coordinate has a given rate (the ones they
/// determine get theirs from them, the others are free).
pub(super) fn constraints(known: &Known, links: &[LinkNode]) -> Result<Constraints, Refusal> {
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
    let helices = helices(known, links, &mut taken)?;
    // The loop's derivative is solved for the dependent rates in terms of free rates.
    if !taken.is_empty()
        && let Some(i) = spec.coordinates.iter().position(|c| c.rate.is_some())
    {
        let why = if spec.closures.is_empty() && spec.rolling.is_empty() {
            "a mechanism with a helical link that determines a coordinate takes free rates only \
             for now (drive the screw by a torque rather than impose its rate)"
        } else {
            "a mechanism with a loop closure or a rolling condition takes free rates only for \
             now (drive the crank by a torque rather than impose its rate)"
        };
        return Err(at(format!("coordinates[{i}].rate"), why));
    }
    Ok((closures, rolling, helices))
}
