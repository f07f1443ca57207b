//! Solids carried by another (`carried_by`): each one's carrier, the frame it shares with it,
//! and the isolations the PFD may declare. A carried solid is isolated only with its carrier
//! (the action that holds it is not modelled); two solids that share a frame with no link
//! between them are isolated together, or one is declared carried by the other. Each side
//! (exact and float) adds the carried solids to an isolated carrier with its own code: only
//! the references are resolved here.

use super::pfd::{Known, LinkNode, Side, TheoremNode};
use super::{Refusal, at, find};
use crate::wire::SpecFile;
use std::collections::BTreeMap;

/// Each solid's carrier (`carried_by`), a position among the solids: another solid, not the
/// ground, and no solid carried by itself through others.
pub(super) fn carriers(spec: &SpecFile) -> Result<Vec<Option<usize>>, Refusal> {
    let names: Vec<&str> = spec.solids.iter().map(|s| s.name.as_str()).collect();
    let mut out = Vec::with_capacity(names.len());
    for (i, s) in spec.solids.iter().enumerate() {
        let Some(c) = &s.carried_by else {
            out.push(None);
            continue;
        };
        let path = format!("solids[{i}].carried_by");
        if *c == spec.ground {
            let why = format!(
                "`{c}` is the ground: a solid fixed to the ground is part of it (leave it out, or \
                 link it to the ground with a `fixed` link)"
            );
            return Err(at(path, why));
        }
        let k = names.iter().position(|n| n == c).ok_or_else(|| {
            let hint = crate::hint::suggestion(c, &names);
            at(&path, format!("unknown solid `{c}`{hint}"))
        })?;
        out.push(Some(k));
    }
    for i in 0..out.len() {
        let (mut k, mut steps) = (i, 0);
        while let Some(c) = out[k] {
            (k, steps) = (c, steps + 1);
            if k == i || steps > out.len() {
                let why = format!(
                    "the solid `{}` is carried by itself, through `carried_by`",
                    names[i]
                );
                return Err(at(format!("solids[{i}].carried_by"), why));
            }
        }
    }
    Ok(out)
}

/// The position of the frame of the solid `i`: its `frame`, or for a carried solid its
/// carrier's, which a frame it names must be (a carried solid moves with its carrier).
pub(super) fn solid_frame(
    spec: &SpecFile,
    frames: &BTreeMap<&str, usize>,
    carried_by: &[Option<usize>],
    i: usize,
) -> Result<usize, Refusal> {
    let path = format!("solids[{i}].frame");
    let own = match &spec.solids[i].frame {
        Some(f) => Some(find(frames, "frame", path.clone(), f)?),
        None => None,
    };
    // No cycle of carriers (see `carriers`): the chain ends.
    let Some(c) = carried_by[i] else {
        let why = "missing: the frame attached to the solid (`\"frame\": \"1\"`), or the solid \
                   that carries it (`\"carried_by\": \"1\"`)";
        return own.ok_or_else(|| at(path, why));
    };
    let carrier = solid_frame(spec, frames, carried_by, c)?;
    match (own, &spec.solids[i].frame) {
        (Some(f), Some(name)) if f != carrier => {
            let why = format!(
                "the solid is carried by `{}`, attached to frame `{}`: a carried solid is attached \
                 to its carrier's frame, not to `{name}` (leave `frame` out)",
                spec.solids[c].name,
                spec.frames
                    .iter()
                    .find(|fr| frames.get(fr.name.as_str()) == Some(&carrier))
                    .map_or(spec.ground.as_str(), |fr| fr.name.as_str()),
            );
            Err(at(path, why))
        }
        _ => Ok(carrier),
    }
}

/// The solids of `isolate` with every solid they carry, in turn (the system a theorem
/// isolates, as this module checks it).
fn with_carried(solids: &[super::SolidNode], isolate: &[usize]) -> Vec<usize> {
    let mut out = isolate.to_vec();
    let mut k = 0;
    while k < out.len() {
        let carrier = out[k];
        for (s, node) in solids.iter().enumerate() {
            if node.carried_by == Some(carrier) && !out.contains(&s) {
                out.push(s);
            }
        }
        k += 1;
    }
    out
}

/// Every theorem isolates each carried solid with its carrier, and two solids that share a
/// frame, with no link between them, together or not at all: the action that holds one on
/// the other is not modelled, so the PFD on one alone would silently leave it out.
pub(super) fn isolations(
    known: &Known,
    links: &[LinkNode],
    theorems: &[TheoremNode],
) -> Result<(), Refusal> {
    let solids = known.solids;
    let linked = |a: usize, b: usize| {
        links.iter().any(|l| {
            let sides = l.sides();
            sides.contains(&Side::Solid(a)) && sides.contains(&Side::Solid(b))
        })
    };
    for (i, th) in theorems.iter().enumerate() {
        let path = format!("pfd[{i}].isolate");
        let system = with_carried(solids, &th.isolate);
        for &s in &system {
            if let Some(c) = solids[s].carried_by
                && !system.contains(&c)
            {
                let (s, c) = (solids[s].name, solids[c].name);
                let why = format!(
                    "the solid `{s}` is carried by `{c}` (`carried_by`): the action of `{c}` on \
                     it is not modelled, so it is isolated only with its carrier (isolate `{c}`, \
                     which includes it, or a set that holds both)"
                );
                return Err(at(path, why));
            }
        }
        for &a in &system {
            let apart = (0..solids.len()).find(|&b| {
                !system.contains(&b) && solids[b].frame == solids[a].frame && !linked(a, b)
            });
            if let Some(b) = apart {
                let (a, b) = (solids[a].name, solids[b].name);
                let why = format!(
                    "the solids `{a}` and `{b}` share a frame with no link between them, and `{b}` \
                     is not isolated with `{a}`: the action that holds them together is not \
                     modelled. If `{b}` is fixed on `{a}`, declare it `\"carried_by\": \"{a}\"` \
                     (isolating `{a}` then includes it), or isolate a set that holds both"
                );
                return Err(at(path, why));
            }
        }
    }
    Ok(())
}
