//! The references of the PFD's sections, resolved once for both sides: the links' and the
//! given actions' sides and points, the theorems' isolated solids, points, vectors and
//! coordinates.

use super::{Refusal, SolidNode, at, distinct, find};
use crate::expr::check_identifier;
use crate::wire::{SpecFile, TheoremKind};
use std::collections::{BTreeMap, HashSet};

/// One side of a link: the ground or a solid.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The ground frame.
    Ground,
    /// A solid (its position among the solids).
    Solid(usize),
}

/// A link's references, in the order of the spec's `links`.
#[derive(Debug, Clone)]
pub struct LinkNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// The solid (or the ground) exerting the action, then the solid receiving it.
    pub between: [Side; 2],
    /// The position of its point.
    pub point: usize,
}

/// A given action's references, in the order of the spec's `actions`.
#[derive(Debug, Clone)]
pub struct ActionNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// The solid (or the ground) exerting it.
    pub from: Side,
    /// The solid receiving it (its position among the solids).
    pub on: usize,
    /// The position of its point.
    pub point: usize,
}

/// A theorem's references, in the order of the spec's `pfd`.
#[derive(Debug, Clone)]
pub struct TheoremNode {
    /// The solids isolated (positions among the solids): one solid, or a set's.
    pub isolate: Vec<usize>,
    /// The position of its point (None for a resultant theorem written at none).
    pub point: Option<usize>,
    /// The basis vector it is projected on: (the position of its frame, its axis 0, 1 or 2).
    pub on: (usize, usize),
    /// The coordinate whose equation of motion it is (index in `coordinates`).
    pub eom: Option<usize>,
}

/// What a link or an action may name: the solids, the ground, and the points (the frames
/// and sets only to say why they may not stand for a solid).
pub(super) struct Known<'s, 'a> {
    pub(super) spec: &'a SpecFile,
    pub(super) solids: &'s [SolidNode<'a>],
    pub(super) frames: &'s BTreeMap<&'a str, usize>,
    pub(super) points: &'s BTreeMap<&'a str, usize>,
    pub(super) sets: &'s BTreeMap<&'a str, Vec<usize>>,
    pub(super) vectors: &'s BTreeMap<&'a str, (usize, usize)>,
    pub(super) coords: &'s BTreeMap<&'a str, usize>,
}

impl Known<'_, '_> {
    /// A side of a link or an action: a solid, or the ground (which acts without being a
    /// solid); another frame, a set or an unknown name is refused at `path`.
    fn side(&self, path: String, n: &str) -> Result<Side, Refusal> {
        if let Some(s) = self.solids.iter().position(|s| s.name == n) {
            return Ok(Side::Solid(s));
        }
        let ground = &self.spec.ground;
        if n == ground {
            return Ok(Side::Ground);
        }
        let why = if self.frames.contains_key(n) {
            format!("`{n}` is a frame, not a solid: only the ground `{ground}` acts without one")
        } else if self.sets.contains_key(n) {
            format!("`{n}` is a set: a link or an action joins two solids")
        } else {
            format!("`{n}` is neither a solid nor the ground `{ground}`")
        };
        Err(at(path, why))
    }

    /// A basis vector: a name the statement gives one (`u`), or x, y or z followed by a
    /// frame's name: (the position of its frame, its axis).
    fn basis_vector(&self, s: &str) -> Option<(usize, usize)> {
        if let Some(&v) = self.vectors.get(s) {
            return Some(v);
        }
        let mut c = s.chars();
        let first = c.next()?;
        let axis = ['x', 'y', 'z'].iter().position(|&a| a == first)?;
        Some((*self.frames.get(c.as_str())?, axis))
    }

    /// The position of the point `n`, refused at `path` if there is none.
    fn point(&self, path: String, n: &str) -> Result<usize, Refusal> {
        find(self.points, "point", path, n)
    }
}

/// The links: each named once, between two different solids (or the ground and a solid,
/// which receives the action), at a point.
pub(super) fn links<'a>(known: &Known<'_, 'a>) -> Result<Vec<LinkNode<'a>>, Refusal> {
    let spec = known.spec;
    let mut taken = HashSet::new();
    distinct(
        "link",
        "links",
        spec.links.iter().map(|l| l.name.as_str()),
        &mut taken,
    )?;
    let mut out = Vec::with_capacity(spec.links.len());
    for (i, l) in spec.links.iter().enumerate() {
        let path = format!("links[{i}]");
        let from = known.side(format!("{path}.between[0]"), &l.between[0])?;
        let on = known.side(format!("{path}.between[1]"), &l.between[1])?;
        if on == Side::Ground {
            return Err(at(
                format!("{path}.between[1]"),
                "the second solid of a link receives its action: it cannot be the ground",
            ));
        }
        if from == on {
            return Err(at(
                format!("{path}.between"),
                "a link joins two different solids",
            ));
        }
        out.push(LinkNode {
            name: &l.name,
            between: [from, on],
            point: known.point(format!("{path}.point"), &l.point)?,
        });
    }
    Ok(out)
}

/// The given actions: each named by an identifier, exerted by a solid (or the ground) on
/// another solid, at a point.
pub(super) fn actions<'a>(known: &Known<'_, 'a>) -> Result<Vec<ActionNode<'a>>, Refusal> {
    let spec = known.spec;
    let mut out = Vec::with_capacity(spec.actions.len());
    for (i, a) in spec.actions.iter().enumerate() {
        let path = format!("actions[{i}]");
        check_identifier(&a.name).map_err(|m| at(format!("{path}.name"), m))?;
        let from = known.side(format!("{path}.from"), &a.from)?;
        let Side::Solid(on) = known.side(format!("{path}.on"), &a.on)? else {
            return Err(at(format!("{path}.on"), "an action is received by a solid"));
        };
        if from == Side::Solid(on) {
            return Err(at(
                format!("{path}.on"),
                "an action is exerted by one solid on another",
            ));
        }
        out.push(ActionNode {
            name: &a.name,
            from,
            on,
            point: known.point(format!("{path}.point"), &a.point)?,
        });
    }
    Ok(out)
}

/// The theorems of the `pfd` section: each isolates a solid or a set (never the ground), is
/// written at a point (a moment theorem must name one), projected on a basis vector, and is
/// the equation of motion of at most one coordinate, which no other theorem is.
pub(super) fn theorems(known: &Known) -> Result<Vec<TheoremNode>, Refusal> {
    let spec = known.spec;
    let mut out: Vec<TheoremNode> = Vec::with_capacity(spec.pfd.len());
    for (i, t) in spec.pfd.iter().enumerate() {
        let path = format!("pfd[{i}]");
        let isolate = match known.solids.iter().position(|s| s.name == t.isolate) {
            Some(s) => vec![s],
            None if t.isolate == spec.ground => {
                let why = format!("`{}` is the ground: it is never isolated", t.isolate);
                return Err(at(format!("{path}.isolate"), why));
            }
            None => (known.sets.get(t.isolate.as_str()).cloned()).ok_or_else(|| {
                let why = format!("unknown solid or set `{}`", t.isolate);
                at(format!("{path}.isolate"), why)
            })?,
        };
        let point = match (&t.point, t.theorem) {
            (Some(p), _) => Some(known.point(format!("{path}.point"), p)?),
            (None, TheoremKind::Resultant) => None,
            (None, TheoremKind::Moment) => {
                let why = "the moment theorem is written at a point";
                return Err(at(format!("{path}.point"), why));
            }
        };
        let on = known.basis_vector(&t.on).ok_or_else(|| {
            let why = format!("`{}` is not a basis vector such as z0", t.on);
            at(format!("{path}.on"), why)
        })?;
        let eom = match &t.eom {
            None => None,
            Some(q) => {
                let c = find(known.coords, "coordinate", format!("{path}.eom"), q)?;
                if let Some(j) = out.iter().position(|o| o.eom == Some(c)) {
                    let why = format!("pfd[{j}] is already the equation of motion of `{q}`");
                    return Err(at(format!("{path}.eom"), why));
                }
                Some(c)
            }
        };
        out.push(TheoremNode {
            isolate,
            point,
            on,
            eom,
        });
    }
    Ok(out)
}
