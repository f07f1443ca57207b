//! The spec's names and trees resolved once, for the exact side ([`crate::spec`]) and the
//! float backend ([`crate::numeric`]) alike: parameters, coordinates and aliases in one
//! namespace, the names a statement gives basis vectors, each frame after its parent and each
//! point after the point it is placed from, every frame, point and solid named once, every
//! reference to one of them turned into a position, every error naming its JSON path.
//!
//! What is resolved here is names, structure and the spec's own conventions: the links' axes
//! (the ground's z for a ball or a fixed link, which need none), which kinds take friction and
//! springs, the unknowns' names (X01, X_A), the dry friction signs' parameters. Each side still
//! reads the expressions (rotation angles, positions, masses, inertia entries) with its own
//! parser and applies the physical conventions (which components a link transmits, rotation
//! sense, inertia signs) with its own code: a mistake in one cannot hide behind the other.
//!
//! ```
//! let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
//! let spec = torseur::spec::parse_spec(&text).unwrap();
//! let trees = torseur::resolve::resolve(&spec).unwrap();
//! // The ground first, then each frame after its parent.
//! assert_eq!(trees.frames[0].name, "0");
//! let f2 = trees.frame("2").unwrap();
//! assert!(trees.frames[f2].parent < f2);
//! ```

use crate::expr::{RESERVED, validate_identifier};
use crate::quantity::validate_name;
use crate::wire::SpecFile;
use carried::{carriers, isolations, solid_frame};
pub use constraints::{ClosureNode, HelixNode, RollingNode};
pub use pfd::{ActionNode, Contact, LinkNode, Side, TheoremNode, Unknowns, unknowns, with_signs};
use pfd::{Known, actions, links, theorems};
use std::collections::{BTreeMap, HashSet};

mod carried;
mod constraints;
mod pfd;

/// A structural error: the JSON path of the faulty value and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Refusal {
    /// JSON path (`frames[2].parent`).
    pub path: String,
    /// The message.
    pub message: String,
}

fn at(path: impl Into<String>, message: impl Into<String>) -> Refusal {
    Refusal {
        path: path.into(),
        message: message.into(),
    }
}

/// A frame: the ground (position 0) or one of the spec's.
#[derive(Debug, Clone)]
pub struct FrameNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// Its index in `frames` of the spec (None for the ground).
    pub spec: Option<usize>,
    /// The position of its parent (0 for the ground itself).
    pub parent: usize,
    /// The position of its origin among the points (0, the ground origin, unless given).
    pub origin: usize,
}

/// A point: the ground origin (position 0) or one of the spec's.
#[derive(Debug, Clone)]
pub struct PointNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// Its index in `points` of the spec (None for the ground origin).
    pub spec: Option<usize>,
    /// The position of the point it is placed from (0 for the ground origin itself).
    pub from: usize,
}

/// A solid's references, in the order of the spec's `solids`.
#[derive(Debug, Clone)]
pub struct SolidNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// The position of its frame.
    pub frame: usize,
    /// The position of its centre of mass, when the spec gives one (a body of negligible
    /// mass may have none).
    pub centre: Option<usize>,
    /// The positions of its inertia operator's point and basis, when it has one.
    pub inertia: Option<(usize, usize)>,
    /// The position of the solid that carries it (`carried_by`), if one does.
    pub carried_by: Option<usize>,
}

/// The names expressions read: parameters, coordinates and aliases (one namespace, each
/// name to its index in the spec), and the basis vectors a statement names (`u`).
#[derive(Debug, Clone, Default)]
pub struct Names<'a> {
    /// Parameter → index in `parameters`.
    pub params: BTreeMap<&'a str, usize>,
    /// Coordinate → index in `coordinates`.
    pub coords: BTreeMap<&'a str, usize>,
    /// Alias → index in `aliases`.
    pub aliases: BTreeMap<&'a str, usize>,
    /// A named basis vector → (the position of its frame, its axis: 0 for x, 1 for y, 2 for z).
    pub vectors: BTreeMap<&'a str, (usize, usize)>,
}

/// A hypothesis' references, in the order of the spec's `hypotheses`.
#[derive(Debug, Clone)]
pub struct HypothesisNode<'a> {
    /// Its name.
    pub name: &'a str,
    /// The coordinates whose rates it holds constant (indices in `coordinates`).
    pub constant_rates: Vec<usize>,
    /// The solids whose symmetries it uses (positions among the solids).
    pub symmetric_solids: Vec<usize>,
}

impl Names<'_> {
    /// Whether `n` is a parameter, a coordinate or an alias.
    pub fn contains(&self, n: &str) -> bool {
        self.params.contains_key(n) || self.coords.contains_key(n) || self.aliases.contains_key(n)
    }
}

/// The spec's names, frames, points and solids, resolved (see the module documentation).
#[derive(Debug, Clone)]
pub struct Resolved<'a> {
    /// The names expressions read.
    pub names: Names<'a>,
    /// The ground first, then each frame after its parent.
    pub frames: Vec<FrameNode<'a>>,
    /// The ground origin first, then each point after the point it is placed from.
    pub points: Vec<PointNode<'a>>,
    /// The solids, in the spec's order.
    pub solids: Vec<SolidNode<'a>>,
    /// The sets of solids (`sets`): name → the positions of its solids, as listed.
    pub sets: BTreeMap<&'a str, Vec<usize>>,
    /// The hypotheses' references.
    pub hypotheses: Vec<HypothesisNode<'a>>,
    /// The links' references.
    pub links: Vec<LinkNode<'a>>,
    /// The given actions' references.
    pub actions: Vec<ActionNode<'a>>,
    /// The theorems' references (`pfd`).
    pub theorems: Vec<TheoremNode>,
    /// The loop closures' references.
    pub closures: Vec<ClosureNode>,
    /// The rolling conditions' references.
    pub rolling: Vec<RollingNode>,
    /// The helical links' references.
    pub helices: Vec<HelixNode>,
    frame_by_name: BTreeMap<&'a str, usize>,
    point_by_name: BTreeMap<&'a str, usize>,
}

impl<'a> Resolved<'a> {
    /// The position of a frame.
    pub fn frame(&self, name: &str) -> Option<usize> {
        self.frame_by_name.get(name).copied()
    }

    /// Frame name → position, for a reader that keeps its own table.
    pub fn frame_positions(&self) -> BTreeMap<String, usize> {
        self.frame_by_name
            .iter()
            .map(|(n, i)| (n.to_string(), *i))
            .collect()
    }

    /// Point name → position, for a reader that keeps its own table.
    pub fn point_positions(&self) -> BTreeMap<String, usize> {
        self.point_by_name
            .iter()
            .map(|(n, i)| (n.to_string(), *i))
            .collect()
    }
}

/// The name of the ground origin: `O0` unless the spec gives one.
fn ground_origin(spec: &SpecFile) -> &str {
    spec.ground_origin.as_deref().unwrap_or("O0")
}

/// Names unique among `taken`, each a valid name, at `{list}[i].name`.
fn distinct<'a>(
    what: &str,
    list: &str,
    names: impl Iterator<Item = &'a str>,
    taken: &mut HashSet<&'a str>,
) -> Result<(), Refusal> {
    for (i, n) in names.enumerate() {
        let path = format!("{list}[{i}].name");
        validate_name(n).map_err(|m| at(&path, m))?;
        if !taken.insert(n) {
            return Err(at(path, format!("duplicate {what} `{n}`")));
        }
    }
    Ok(())
}

/// Places the items whose parent is placed, pass after pass in the spec's order (so the
/// order of the positions is the same for every reader), from `placed` (name → position)
/// holding the root. `parent(i)` is the item's parent's name and the path naming it.
fn place<'a>(
    what: &str,
    names: &[&'a str],
    parent: &dyn Fn(usize) -> (&'a str, String),
    placed: &mut BTreeMap<&'a str, usize>,
) -> Result<Vec<(usize, usize)>, Refusal> {
    let known: HashSet<&str> = names
        .iter()
        .copied()
        .chain(placed.keys().copied())
        .collect();
    let mut order = Vec::with_capacity(names.len());
    let mut done = vec![false; names.len()];
    while order.len() < names.len() {
        let before = order.len();
        for (i, name) in names.iter().enumerate() {
            if done[i] {
                continue;
            }
            let (p, path) = parent(i);
            match placed.get(p) {
                Some(&k) => {
                    placed.insert(name, placed.len());
                    order.push((i, k));
                    done[i] = true;
                }
                None if !known.contains(p) => {
                    let mut declared: Vec<&str> = known.iter().copied().collect();
                    declared.sort_unstable();
                    let hint = crate::hint::suggestion(p, &declared);
                    return Err(at(path, format!("unknown {what} `{p}`{hint}")));
                }
                None => {}
            }
        }
        if order.len() == before {
            let i = done.iter().position(|d| !d).unwrap_or(0);
            return Err(at(
                parent(i).1,
                format!("the {what}s form a cycle through `{}`", names[i]),
            ));
        }
    }
    Ok(order)
}

/// A name read as the course writes a basis vector: x, y or z, then a frame's name (`z1` →
/// ('z', "1")), whether or not that frame exists.
fn course_vector(n: &str) -> Option<(char, &str)> {
    let mut c = n.chars();
    let axis = c.next().filter(|a| matches!(a, 'x' | 'y' | 'z'))?;
    Some((axis, c.as_str()))
}

/// The message refusing a name `n` of a scalar (`what`: parameter, coordinate, alias,
/// unknown) that is the name of a basis vector (`x0` when frame `0` exists), if it is one: in
/// a vector expression the name could only be read as the basis vector.
fn basis_vector_clash(spec: &SpecFile, what: &str, n: &str) -> Option<String> {
    let (axis, frame) = course_vector(n)?;
    let exists = frame == spec.ground || spec.frames.iter().any(|f| f.name == frame);
    exists.then(|| {
        format!(
            "the {what} `{n}` has the name of the basis vector {axis} of frame {frame}: rename it \
             (a position such as `{n}*{n}` could not tell them apart)"
        )
    })
}

/// A word expressions may use as a name, at `path`: an identifier, not a word of the syntax.
fn word(path: &str, n: &str) -> Result<(), Refusal> {
    validate_identifier(n).map_err(|m| at(path, m))?;
    if RESERVED.contains(&n) {
        return Err(at(path, crate::expr::reserved_word(n)));
    }
    Ok(())
}

/// A name expressions read, declared at `path`: an identifier, not a word of the syntax, not
/// a basis vector's name.
fn readable(spec: &SpecFile, what: &str, path: &str, n: &str) -> Result<(), Refusal> {
    word(path, n)?;
    match basis_vector_clash(spec, what, n) {
        Some(m) => Err(at(path, m)),
        None => Ok(()),
    }
}

/// Names declared in `{list}[i].name` (`what`: parameter, coordinate, alias), readable and
/// not `taken` yet (`also` completes the message of a duplicate): name → index.
fn declare<'a>(
    spec: &SpecFile,
    taken: &mut HashSet<&'a str>,
    (what, list, also): (&str, &str, &str),
    names: impl Iterator<Item = &'a str>,
) -> Result<BTreeMap<&'a str, usize>, Refusal> {
    let mut index = BTreeMap::new();
    for (i, n) in names.enumerate() {
        let path = format!("{list}[{i}].name");
        readable(spec, what, &path, n)?;
        if !taken.insert(n) {
            return Err(at(path, format!("duplicate name `{n}`{also}")));
        }
        index.insert(n, i);
    }
    Ok(index)
}

/// Parameters, coordinates and aliases: one namespace.
fn namespace(spec: &SpecFile) -> Result<Names<'_>, Refusal> {
    let mut taken = HashSet::new();
    let params = spec.parameters.iter().map(|p| p.name.as_str());
    let coords = spec.coordinates.iter().map(|c| c.name.as_str());
    let aliases = spec.aliases.iter().map(|a| a.name.as_str());
    let also = ": already a parameter, a coordinate or an alias";
    Ok(Names {
        params: declare(spec, &mut taken, ("parameter", "parameters", ""), params)?,
        coords: declare(spec, &mut taken, ("coordinate", "coordinates", ""), coords)?,
        aliases: declare(spec, &mut taken, ("alias", "aliases", also), aliases)?,
        vectors: BTreeMap::new(),
    })
}

/// The basis vectors the spec names (`ground_basis`, a frame's `basis`), each an identifier,
/// not a word of the syntax, taken by no parameter, coordinate, alias or other basis vector
/// (`x1` while frame 1 exists).
fn named_vectors<'a>(
    spec: &'a SpecFile,
    names: &Names<'a>,
    frames: &BTreeMap<&'a str, usize>,
) -> Result<BTreeMap<&'a str, (usize, usize)>, Refusal> {
    let declared = std::iter::once(("ground_basis".to_string(), &spec.ground, &spec.ground_basis))
        .chain(
            spec.frames
                .iter()
                .enumerate()
                .map(|(i, f)| (format!("frames[{i}].basis"), &f.name, &f.basis)),
        );
    let mut vectors = BTreeMap::new();
    for (path, frame, given) in declared {
        let Some(given) = given else { continue };
        for (k, n) in given.iter().enumerate() {
            let path = format!("{path}[{k}]");
            word(&path, n)?;
            if names.contains(n)
                || vectors
                    .insert(n.as_str(), (frames[frame.as_str()], k))
                    .is_some()
            {
                return Err(at(
                    path,
                    format!(
                        "`{n}` is already the name of a parameter, a coordinate, an alias or \
                         another basis vector: rename one of them"
                    ),
                ));
            }
            if let Some((axis, frame)) = course_vector(n)
                && frames.contains_key(frame)
            {
                let why = format!("`{n}` is already the basis vector {axis} of frame {frame}");
                return Err(at(path, why));
            }
        }
    }
    Ok(vectors)
}

/// The sets of solids: each named apart from the solids, listing at least one solid, each once.
fn sets<'a>(
    spec: &'a SpecFile,
    solids: &[SolidNode<'a>],
) -> Result<BTreeMap<&'a str, Vec<usize>>, Refusal> {
    let mut sets = BTreeMap::new();
    for (name, members) in &spec.sets {
        let path = format!("sets.{name}");
        validate_name(name).map_err(|m| at(&path, m))?;
        if solids.iter().any(|s| s.name == name) {
            return Err(at(path, format!("`{name}` is already a solid")));
        }
        let mut list = Vec::new();
        for (k, m) in members.iter().enumerate() {
            let s = solids.iter().position(|s| s.name == m).ok_or_else(|| {
                let hint = crate::hint::suggestion(m, &solid_names(solids));
                at(format!("{path}[{k}]"), format!("unknown solid `{m}`{hint}"))
            })?;
            if list.contains(&s) {
                return Err(at(
                    format!("{path}[{k}]"),
                    format!("solid `{m}` listed twice"),
                ));
            }
            list.push(s);
        }
        if list.is_empty() {
            return Err(at(path, "a set holds at least one solid"));
        }
        sets.insert(name.as_str(), list);
    }
    Ok(sets)
}

/// The hypotheses: each named once, its constant rates coordinates, its symmetric solids
/// solids.
fn hypotheses<'a>(
    spec: &'a SpecFile,
    names: &Names<'a>,
    solids: &[SolidNode<'a>],
) -> Result<Vec<HypothesisNode<'a>>, Refusal> {
    let mut out: Vec<HypothesisNode> = Vec::with_capacity(spec.hypotheses.len());
    for (i, h) in spec.hypotheses.iter().enumerate() {
        let path = format!("hypotheses[{i}]");
        validate_name(&h.name).map_err(|m| at(format!("{path}.name"), m))?;
        if out.iter().any(|o| o.name == h.name) {
            return Err(at(
                format!("{path}.name"),
                format!("the hypothesis `{}` is defined twice", h.name),
            ));
        }
        let constant_rates = (h.constant_rates.iter().enumerate())
            .map(|(k, c)| {
                names.coords.get(c.as_str()).copied().ok_or_else(|| {
                    let declared: Vec<&str> = names.coords.keys().copied().collect();
                    let hint = crate::hint::suggestion(c, &declared);
                    at(
                        format!("{path}.constant_rates[{k}]"),
                        format!("unknown coordinate `{c}`{hint}"),
                    )
                })
            })
            .collect::<Result<_, _>>()?;
        let symmetric_solids = (h.symmetric_solids.iter().enumerate())
            .map(|(k, n)| {
                solids.iter().position(|s| s.name == n).ok_or_else(|| {
                    let hint = crate::hint::suggestion(n, &solid_names(solids));
                    at(
                        format!("{path}.symmetric_solids[{k}]"),
                        format!("unknown solid `{n}`{hint}"),
                    )
                })
            })
            .collect::<Result<_, _>>()?;
        out.push(HypothesisNode {
            name: &h.name,
            constant_rates,
            symmetric_solids,
        });
    }
    Ok(out)
}

/// Resolves the spec's names, frames, points, solids, sets, hypotheses, links, actions,
/// theorems, loop closures and rolling conditions.
pub fn resolve(spec: &SpecFile) -> Result<Resolved<'_>, Refusal> {
    let namespace = namespace(spec)?;
    let (frame_order, frame_by_name) = frame_tree(spec)?;
    let (points, point_by_name) = point_tree(spec)?;
    let frames = frames(spec, &frame_order, &point_by_name)?;
    let solids = solids(spec, &frame_by_name, &point_by_name)?;
    let vectors = named_vectors(spec, &namespace, &frame_by_name)?;
    let sets = sets(spec, &solids)?;
    let hypotheses = hypotheses(spec, &namespace, &solids)?;
    let known = Known {
        spec,
        solids: &solids,
        frames: &frame_by_name,
        points: &point_by_name,
        sets: &sets,
        vectors: &vectors,
        coords: &namespace.coords,
    };
    let (links, actions) = (links(&known)?, actions(&known)?);
    let theorems = theorems(&known)?;
    isolations(&known, &links, &theorems)?;
    let (closures, rolling, helices) = constraints::constraints(&known, &links)?;
    Ok(Resolved {
        names: Names {
            vectors,
            ..namespace
        },
        frames,
        points,
        solids,
        sets,
        hypotheses,
        links,
        actions,
        theorems,
        closures,
        rolling,
        helices,
        frame_by_name,
        point_by_name,
    })
}

/// The solids' names, in the spec's order: what a refusal of an unknown solid suggests.
fn solid_names<'a>(solids: &[SolidNode<'a>]) -> Vec<&'a str> {
    solids.iter().map(|s| s.name).collect()
}

/// The position of `n` in `index`, or an « unknown `what` » refusal at `path`.
fn find(
    index: &BTreeMap<&str, usize>,
    what: &str,
    path: String,
    n: &str,
) -> Result<usize, Refusal> {
    (index.get(n).copied()).ok_or_else(|| {
        let declared: Vec<&str> = index.keys().copied().collect();
        let hint = crate::hint::suggestion(n, &declared);
        at(path, format!("unknown {what} `{n}`{hint}"))
    })
}

/// The frames' order (each after its parent: (index in the spec, position of the parent))
/// and their positions by name, the ground at 0.
type Tree<'a> = (Vec<(usize, usize)>, BTreeMap<&'a str, usize>);

/// The frames' tree: the ground and the frames named once, each after its parent.
fn frame_tree(spec: &SpecFile) -> Result<Tree<'_>, Refusal> {
    validate_name(&spec.ground).map_err(|m| at("ground", m))?;
    let mut taken = HashSet::from([spec.ground.as_str()]);
    let names: Vec<&str> = spec.frames.iter().map(|f| f.name.as_str()).collect();
    distinct("frame", "frames", names.iter().copied(), &mut taken)?;
    let mut by_name = BTreeMap::from([(spec.ground.as_str(), 0)]);
    let parent = |i: usize| {
        let f = &spec.frames[i];
        (f.parent.as_str(), format!("frames[{i}].parent"))
    };
    let order = place("frame", &names, &parent, &mut by_name)?;
    Ok((order, by_name))
}

/// The points, the ground origin first, each named once and after the point it is placed
/// from, and their positions by name.
fn point_tree(spec: &SpecFile) -> Result<(Vec<PointNode<'_>>, BTreeMap<&str, usize>), Refusal> {
    let origin = ground_origin(spec);
    validate_name(origin).map_err(|m| at("ground_origin", m))?;
    let mut taken = HashSet::from([origin]);
    let names: Vec<&str> = spec.points.iter().map(|p| p.name.as_str()).collect();
    distinct("point", "points", names.iter().copied(), &mut taken)?;
    let mut by_name = BTreeMap::from([(origin, 0)]);
    let from = |i: usize| {
        let p = &spec.points[i];
        (
            p.from.as_deref().unwrap_or(origin),
            format!("points[{i}].from"),
        )
    };
    let order = place("point", &names, &from, &mut by_name)?;
    let root = PointNode {
        name: origin,
        spec: None,
        from: 0,
    };
    let points = std::iter::once(root)
        .chain(order.iter().map(|&(i, from)| PointNode {
            name: &spec.points[i].name,
            spec: Some(i),
            from,
        }))
        .collect();
    Ok((points, by_name))
}

/// The frames in the tree's order, each with its origin.
fn frames<'a>(
    spec: &'a SpecFile,
    order: &[(usize, usize)],
    points: &BTreeMap<&str, usize>,
) -> Result<Vec<FrameNode<'a>>, Refusal> {
    let ground = FrameNode {
        name: &spec.ground,
        spec: None,
        parent: 0,
        origin: 0,
    };
    let mut frames = vec![ground];
    for &(i, parent) in order {
        let f = &spec.frames[i];
        let origin = match &f.origin {
            None => 0,
            Some(o) => find(points, "point", format!("frames[{i}].origin"), o)?,
        };
        frames.push(FrameNode {
            name: &f.name,
            spec: Some(i),
            parent,
            origin,
        });
    }
    Ok(frames)
}

/// The solids: named once and apart from the ground (a body too), their frame, centre and
/// inertia operator's point and basis found, each carrier a solid (see [`carriers`]).
fn solids<'a>(
    spec: &'a SpecFile,
    frames: &BTreeMap<&str, usize>,
    points: &BTreeMap<&str, usize>,
) -> Result<Vec<SolidNode<'a>>, Refusal> {
    let mut taken = HashSet::from([spec.ground.as_str()]);
    let names = spec.solids.iter().map(|s| s.name.as_str());
    distinct("solid", "solids", names, &mut taken)?;
    let carried_by = carriers(spec)?;
    let mut solids = Vec::with_capacity(spec.solids.len());
    for (i, s) in spec.solids.iter().enumerate() {
        let path = format!("solids[{i}]");
        let inertia = match &s.inertia {
            None => None,
            Some(j) => Some((
                find(points, "point", format!("{path}.inertia.point"), &j.point)?,
                find(frames, "frame", format!("{path}.inertia.basis"), &j.basis)?,
            )),
        };
        solids.push(SolidNode {
            name: &s.name,
            frame: solid_frame(spec, frames, &carried_by, i)?,
            centre: match &s.centre {
                Some(c) => Some(find(points, "point", format!("{path}.centre"), c)?),
                None => None,
            },
            inertia,
            carried_by: carried_by[i],
        });
    }
    Ok(solids)
}
