//! The references of the PFD's sections, resolved once for both sides: the links' sides,
//! points, axes, directions and springs' coordinates, the tree they form, the given actions'
//! sides and points, the unknowns' names, the theorems' isolated solids, points, vectors and
//! coordinates, and the parameters standing for dry friction's signs.

use super::{Refusal, Resolved, SolidNode, at, course_vector, distinct, find, readable};
use crate::expr::validate_identifier;
use crate::wire::{LinkKind, LinkSpec, ParameterSpec, SpecFile, TheoremKind};
use std::borrow::Cow;
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
    /// The solid (or the ground) exerting the action.
    pub from: Side,
    /// The solid receiving it (its position among the solids).
    pub on: usize,
    /// The position of its point.
    pub point: usize,
    /// The basis vector of its axis (or normal): (the position of its frame, its axis 0, 1
    /// or 2); the ground's z for a ball or a fixed link, which need none.
    pub axis: (usize, usize),
    /// A line contact's direction: another axis of its normal's basis.
    pub direction: Option<usize>,
    /// The coordinate its spring measures (index in `coordinates`).
    pub spring: Option<usize>,
    /// The coordinate whose rate a helical link determines (index in `coordinates`).
    pub dependent: Option<usize>,
    /// Coulomb's law on its unknowns (`contact_friction`): the axes of its sliding direction
    /// and of its normal in the basis of its axis.
    pub contact: Option<Contact>,
}

/// The directions of Coulomb's law on a link's unknowns, as axes 0, 1, 2 of the basis of the
/// link's axis: a contact's normal is its axis, a slider's sliding direction is its axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Contact {
    /// The sliding direction t, along which the tangential unknown T lies.
    pub tangent: usize,
    /// The normal n, along which the normal unknown N lies.
    pub normal: usize,
}

impl LinkNode<'_> {
    /// The solid (or the ground) exerting the action, then the solid receiving it.
    pub fn sides(&self) -> [Side; 2] {
        [self.from, Side::Solid(self.on)]
    }
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
    /// The basis vector it is projected on: (the position of its frame, its axis 0, 1 or 2);
    /// the ground's first vector, unused, for the energy theorem.
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
            format!(
                "`{n}` is a frame, not a solid: only the ground `{ground}` acts without one; a \
                 body of negligible mass is a solid too, declared in `solids` as \
                 `{{\"name\": \"{n}\", \"frame\": \"{n}\", \"massless\": true}}`"
            )
        } else if self.sets.contains_key(n) {
            format!("`{n}` is a set: a link or an action joins two solids")
        } else {
            let hint = self.solid_hint(n, true, false);
            format!("`{n}` is neither a solid nor the ground `{ground}`{hint}")
        };
        Err(at(path, why))
    }

    /// A basis vector: a name the statement gives one (`u`), or x, y or z followed by a
    /// frame's name: (the position of its frame, its axis).
    pub(super) fn basis_vector(&self, s: &str) -> Option<(usize, usize)> {
        if let Some(&v) = self.vectors.get(s) {
            return Some(v);
        }
        let (axis, frame) = course_vector(s)?;
        Some((
            *self.frames.get(frame)?,
            ['x', 'y', 'z'].iter().position(|&a| a == axis)?,
        ))
    }

    /// What a refusal of the basis vector `text` suggests: a close name among the named
    /// vectors and x, y, z of every frame.
    pub(super) fn vector_hint(&self, text: &str) -> String {
        let course: Vec<String> = (self.frames.keys())
            .flat_map(|f| ['x', 'y', 'z'].map(|a| format!("{a}{f}")))
            .collect();
        let declared: Vec<&str> = (self.vectors.keys().copied())
            .chain(course.iter().map(String::as_str))
            .collect();
        crate::hint::suggestion(text, &declared)
    }

    /// What a refusal of the solid `n` suggests among the solids' names (and the ground's and
    /// the sets', when `ground` and `sets`).
    pub(super) fn solid_hint(&self, n: &str, ground: bool, sets: bool) -> String {
        let mut declared: Vec<&str> = self.solids.iter().map(|s| s.name).collect();
        if ground {
            declared.push(&self.spec.ground);
        }
        if sets {
            declared.extend(self.sets.keys().copied());
        }
        crate::hint::suggestion(n, &declared)
    }

    /// The position of the point `n`, refused at `path` if there is none.
    pub(super) fn point(&self, path: String, n: &str) -> Result<usize, Refusal> {
        find(self.points, "point", path, n)
    }
}

/// The links: each named once, between two different solids (or the ground and a solid,
/// which receives the action), at a point, with the axis its kind needs, a line contact's
/// direction, friction and springs only on a pivot or a slider; without loop closures, the
/// links form a tree.
pub(super) fn links<'a>(known: &Known<'_, 'a>) -> Result<Vec<LinkNode<'a>>, Refusal> {
    let spec = known.spec;
    let mut taken = HashSet::new();
    distinct(
        "link",
        "links",
        spec.links.iter().map(|l| l.name.as_str()),
        &mut taken,
    )?;
    let mut out: Vec<LinkNode> = Vec::with_capacity(spec.links.len());
    for (i, l) in spec.links.iter().enumerate() {
        let path = format!("links[{i}]");
        let from = known.side(format!("{path}.between[0]"), &l.between[0])?;
        let Side::Solid(on) = known.side(format!("{path}.between[1]"), &l.between[1])? else {
            return Err(at(
                format!("{path}.between[1]"),
                "the second solid of a link receives its action: it cannot be the ground",
            ));
        };
        if from == Side::Solid(on) {
            return Err(at(
                format!("{path}.between"),
                "a link joins two different solids",
            ));
        }
        // A loop closed by a closure (a crank–slider's slide), or by a helical link, which
        // ties its two relative motions itself (a screw turning on the frame, its nut sliding
        // on it), is a loop of the mechanism.
        let sides = [from, Side::Solid(on)];
        let closed = !spec.closures.is_empty() || l.kind == LinkKind::Helical;
        if let Some(chain) = closes_loop(&out, sides).filter(|_| !closed) {
            let names: Vec<&str> = chain.iter().map(|&k| out[k].name).collect();
            return Err(at(
                format!("{path}.between"),
                format!(
                    "the link {} closes a kinematic loop: {} and {} are already connected by the \
                     links {}. Closed kinematic loops are not supported yet (they need \
                     constraint equations between the coordinates); keep the links of a tree, \
                     from the ground to every solid",
                    l.name,
                    l.between[0],
                    l.between[1],
                    names.join(", ")
                ),
            ));
        }
        let (axis, direction) = axis(known, &path, l)?;
        let turns_or_slides = matches!(l.kind, LinkKind::Pivot | LinkKind::Slider);
        let extras = [
            ("friction", l.friction.is_some(), "viscous friction is"),
            ("coulomb", l.coulomb.is_some(), "dry friction is"),
            ("spring", l.spring.is_some(), "a spring is"),
        ];
        if let Some((field, _, what)) = extras.iter().find(|e| e.1 && !turns_or_slides) {
            let why = format!("{what} declared on a pivot or a slider");
            return Err(at(format!("{path}.{field}"), why));
        }
        let spring = (l.spring.as_ref())
            .map(|s| {
                let path = format!("{path}.spring.coordinate");
                find(known.coords, "coordinate", path, &s.coordinate)
            })
            .transpose()?;
        let contact = contact(known, &path, l, axis)?;
        let dependent = helical(known, &path, l)?;
        out.push(LinkNode {
            name: &l.name,
            from,
            on,
            point: known.point(format!("{path}.point"), &l.point)?,
            axis,
            direction,
            spring,
            contact,
            dependent,
        });
    }
    Ok(out)
}

/// The directions of Coulomb's law on a link's unknowns: a contact (point, plane, line) names
/// its sliding direction, another basis vector of its normal's basis; a slider names its
/// normal, another basis vector of its axis' basis. Refused on any other link, beside dry
/// friction given by its magnitude, or with a direction that is not such a vector.
fn contact(
    known: &Known,
    path: &str,
    l: &LinkSpec,
    axis: (usize, usize),
) -> Result<Option<Contact>, Refusal> {
    let Some(c) = &l.contact_friction else {
        return Ok(None);
    };
    let path = format!("{path}.contact_friction");
    if !matches!(
        l.kind,
        LinkKind::Point | LinkKind::Plane | LinkKind::Line | LinkKind::Slider
    ) {
        let why = format!(
            "a {} transmits no tangential force tied to a normal one: Coulomb's law on a \
             link's unknowns is declared on a contact (point, plane, line) or a slider",
            l.kind.course_name()
        );
        return Err(at(path, why));
    }
    if l.coulomb.is_some() {
        let why = "the link already has dry friction given by its magnitude (`coulomb`): \
                   declare one or the other";
        return Err(at(path, why));
    }
    let slider = l.kind == LinkKind::Slider;
    let (wanted, other) = if slider {
        ("normal", "tangent")
    } else {
        ("tangent", "normal")
    };
    let given = if slider { &c.normal } else { &c.tangent };
    let stray = if slider { &c.tangent } else { &c.normal };
    if stray.is_some() {
        let why = if slider {
            "a slider slides along its axis: give its `normal` only"
        } else {
            "a contact's normal is its axis: give its sliding direction `tangent` only"
        };
        return Err(at(format!("{path}.{other}"), why));
    }
    let Some(text) = given else {
        let why = if slider {
            "a slider with Coulomb's law needs its `normal`, the direction of the normal \
             unknown N: another basis vector of its axis' basis"
        } else {
            "a contact with Coulomb's law needs its sliding direction `tangent`, another basis \
             vector of its normal's basis"
        };
        return Err(at(path, why));
    };
    let field = format!("{path}.{wanted}");
    let Some((f, k)) = known.basis_vector(text) else {
        return Err(at(
            field,
            format!(
                "`{text}` is not a basis vector such as x0{}",
                known.vector_hint(text)
            ),
        ));
    };
    if f != axis.0 || k == axis.1 {
        let why = format!(
            "`{text}` is not another basis vector of the basis of the link's axis `{}`",
            l.axis.as_deref().unwrap_or_default()
        );
        return Err(at(field, why));
    }
    Ok(Some(if slider {
        Contact {
            tangent: axis.1,
            normal: k,
        }
    } else {
        Contact {
            tangent: k,
            normal: axis.1,
        }
    }))
}

/// A helical link's pitch, which it needs and no other kind takes, and the coordinate whose
/// rate it determines (index in `coordinates`), if it names one.
fn helical(known: &Known, path: &str, l: &LinkSpec) -> Result<Option<usize>, Refusal> {
    let helical = l.kind == LinkKind::Helical;
    match (&l.pitch, helical) {
        (None, true) => {
            let why = "a helical link needs its pitch `pitch`, a length per turn (`p`; negative \
                       for a left-hand thread)";
            return Err(at(format!("{path}.pitch"), why));
        }
        (Some(_), false) => {
            let why = "only a helical link (`helical`) has a pitch";
            return Err(at(format!("{path}.pitch"), why));
        }
        _ => {}
    }
    let Some(d) = &l.dependent else {
        return Ok(None);
    };
    if !helical {
        let why = "only a helical link (`helical`) determines a coordinate's rate";
        return Err(at(format!("{path}.dependent"), why));
    }
    find(known.coords, "coordinate", format!("{path}.dependent"), d).map(Some)
}

/// A link's axis (or normal), which every kind but a ball and a fixed link needs, and a line
/// contact's direction, another basis vector of its normal's basis.
fn axis(
    known: &Known,
    path: &str,
    l: &LinkSpec,
) -> Result<((usize, usize), Option<usize>), Refusal> {
    let vector = |field: &str, text: &str| {
        let why = || {
            let hint = known.vector_hint(text);
            format!("`{text}` is not a basis vector such as z0{hint}")
        };
        (known.basis_vector(text)).ok_or_else(|| at(format!("{path}.{field}"), why()))
    };
    let axis = match &l.axis {
        Some(a) => vector("axis", a)?,
        None if matches!(l.kind, LinkKind::Ball | LinkKind::Fixed) => (0, 2),
        None => {
            let why = format!(
                "a {} needs its axis (or normal), a basis vector such as z0",
                l.kind.course_name()
            );
            return Err(at(format!("{path}.axis"), why));
        }
    };
    let path = format!("{path}.direction");
    let direction = match (&l.direction, l.kind) {
        (None, LinkKind::Line) => {
            let why = "a line contact needs the direction of its line, another basis vector of \
                       its normal's basis";
            return Err(at(path, why));
        }
        (None, _) => None,
        (Some(_), kind) if kind != LinkKind::Line => {
            return Err(at(path, "only a line contact (`line`) has a direction"));
        }
        (Some(d), _) => match vector("direction", d)? {
            (f, k) if f == axis.0 && k != axis.1 => Some(k),
            _ => {
                let why = "the line's direction is another basis vector of its normal's basis";
                return Err(at(path, why));
            }
        },
    };
    Ok((axis, direction))
}

/// The links (positions among `links`) of a path between the two sides of a new link, when
/// it would close a loop. Links in parallel between the same two solids (two bearings of one
/// shaft) make one connection, not a loop.
fn closes_loop(links: &[LinkNode], [a, b]: [Side; 2]) -> Option<Vec<usize>> {
    if links
        .iter()
        .any(|l| l.sides() == [a, b] || l.sides() == [b, a])
    {
        return None;
    }
    // Breadth-first from a: each side reached, with (where it was reached from, the link).
    let mut reached: Vec<(Side, Option<(usize, usize)>)> = vec![(a, None)];
    let mut k = 0;
    while k < reached.len() {
        let n = reached[k].0;
        for (j, l) in links.iter().enumerate() {
            let other = match l.sides() {
                [x, y] if x == n => y,
                [x, y] if y == n => x,
                _ => continue,
            };
            if reached.iter().any(|r| r.0 == other) {
                continue;
            }
            reached.push((other, Some((k, j))));
            if other == b {
                let mut chain = Vec::new();
                let mut cur = reached.len() - 1;
                while let Some((prev, j)) = reached[cur].1 {
                    chain.push(j);
                    cur = prev;
                }
                chain.reverse();
                return Some(chain);
            }
        }
        k += 1;
    }
    None
}

/// The PFD's unknowns: their names in order, each link's transmitted components, then each
/// given action's unknowns.
#[derive(Debug, Clone, Default)]
pub struct Unknowns {
    /// The names: X, Y, Z, L, M, N followed by a link's name where it transmits them (X01;
    /// X_A for a link named by a letter, its centre A), link after link, then each given
    /// action's unknowns.
    pub names: Vec<String>,
    /// For each link, its transmitted components (0..3 the resultant's, 3..6 the moment's, in
    /// the basis of its axis), each with the position of its unknown in `names`.
    pub links: Vec<Vec<(usize, usize)>>,
    /// For each given action, the positions of its unknowns in `names`.
    pub actions: Vec<Vec<usize>>,
}

/// The PFD's unknowns, named and checked here: each an identifier, not a word of the syntax,
/// not a basis vector, a parameter, a coordinate or an alias, and declared once. Which
/// components a link transmits is the reader's own convention, `transmitted(kind, axis,
/// direction, sliding)` (axes 0, 1, 2; `sliding` the direction of Coulomb's law's tangential
/// unknown, which the link then transmits too), which each side applies with its own code.
///
/// ```
/// let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
/// let spec = torseur::spec::parse_spec(&text).unwrap();
/// let r = torseur::resolve::resolve(&spec).unwrap();
/// // A reader for which every link transmits only its resultant's component along x.
/// let x_only = |_, _, _, _| [true, false, false, false, false, false];
/// let unknowns = torseur::resolve::unknowns(&spec, &r, &x_only).unwrap();
/// assert_eq!(unknowns.names[0], "X01");
/// assert_eq!(unknowns.links[0], [(0, 0)]);
/// ```
pub fn unknowns(
    spec: &SpecFile,
    r: &Resolved,
    transmitted: &dyn Fn(LinkKind, usize, Option<usize>, Option<usize>) -> [bool; 6],
) -> Result<Unknowns, Refusal> {
    let mut out = Unknowns::default();
    let add = |path: String, n: String, names: &mut Vec<String>| -> Result<usize, Refusal> {
        readable(spec, "unknown", &path, &n)?;
        let why = if r.names.vectors.contains_key(n.as_str()) {
            format!("the unknown `{n}` is the name of a basis vector")
        } else if r.names.params.contains_key(n.as_str()) {
            format!("the unknown `{n}` is already a parameter: an unknown is solved for, not given")
        } else if r.names.contains(&n) {
            format!("the unknown `{n}` is already a coordinate or an alias")
        } else if names.contains(&n) {
            format!("the unknown `{n}` is declared twice")
        } else {
            names.push(n);
            return Ok(names.len() - 1);
        };
        Err(at(path, why))
    };
    for ((i, l), node) in spec.links.iter().enumerate().zip(&r.links) {
        let sliding = node.contact.map(|c| c.tangent);
        let t = transmitted(l.kind, node.axis.1, node.direction, sliding);
        // A link named by its centre (`A`) gives X_A, as the course writes it; `01` gives X01.
        let sep = if l.name.starts_with(|c: char| c.is_ascii_alphabetic()) {
            "_"
        } else {
            ""
        };
        // Coulomb's law names its T and N as the statement does (T_A, N_A), if it names them.
        let named = node
            .contact
            .zip((l.contact_friction.as_ref()).and_then(|c| c.unknowns.as_ref()));
        let mut components = Vec::new();
        for (k, letter) in ["X", "Y", "Z", "L", "M", "N"].iter().enumerate() {
            if t[k] {
                let (n, path) = match named {
                    Some((c, u)) if k == c.tangent => (
                        u.tangential.clone(),
                        format!("links[{i}].contact_friction.unknowns.T"),
                    ),
                    Some((c, u)) if k == c.normal => (
                        u.normal.clone(),
                        format!("links[{i}].contact_friction.unknowns.N"),
                    ),
                    _ => (
                        format!("{letter}{sep}{}", l.name),
                        format!("links[{i}].name"),
                    ),
                };
                components.push((k, add(path, n, &mut out.names)?));
            }
        }
        out.links.push(components);
    }
    for (i, a) in spec.actions.iter().enumerate() {
        let mut own = Vec::with_capacity(a.unknowns.len());
        for (k, n) in a.unknowns.iter().enumerate() {
            let path = format!("actions[{i}].unknowns[{k}]");
            own.push(add(path, n.clone(), &mut out.names)?);
        }
        out.actions.push(own);
    }
    Ok(out)
}

/// The spec with a parameter ε of value ±1, the sign of the relative rate, for each link with
/// dry friction, named by [`LinkSpec::sign_parameter`] (`epsilon01`); refused where the spec
/// already uses that name.
///
/// ```
/// let text = std::fs::read_to_string("derivations/bloc_frottement_sec.json").unwrap();
/// let spec = torseur::spec::parse_spec(&text).unwrap();
/// let signed = torseur::resolve::with_signs(&spec).unwrap();
/// assert_eq!(signed.parameters.len(), spec.parameters.len() + 1);
/// ```
pub fn with_signs(spec: &SpecFile) -> Result<Cow<'_, SpecFile>, Refusal> {
    if spec.links.iter().all(|l| l.sign_parameter().is_none()) {
        return Ok(Cow::Borrowed(spec));
    }
    let mut out = spec.clone();
    for (i, l) in spec.links.iter().enumerate() {
        let Some(name) = l.sign_parameter() else {
            continue;
        };
        let taken = (spec.parameters.iter().map(|p| &p.name))
            .chain(spec.coordinates.iter().map(|c| &c.name))
            .chain(spec.aliases.iter().map(|a| &a.name))
            .any(|n| *n == name);
        if taken {
            let why = format!(
                "`{name}` is the sign of this link's relative rate under dry friction: give the \
                 parameter of that name another name"
            );
            let field = if l.coulomb.is_some() {
                "coulomb"
            } else {
                "contact_friction"
            };
            return Err(at(format!("links[{i}].{field}"), why));
        }
        validate_identifier(&name).map_err(|m| {
            let why = format!("the sign of its relative rate under dry friction is named {m}");
            at(format!("links[{i}].name"), why)
        })?;
        out.parameters.push(ParameterSpec {
            name,
            description: Some(format!(
                "signe de la vitesse relative de la liaison {} ($\\pm 1$)",
                l.name
            )),
            unit: Some("1".into()),
            kind: Default::default(),
        });
    }
    Ok(Cow::Owned(out))
}

/// The given actions: each named by an identifier, exerted by a solid (or the ground) on
/// another solid, at a point.
pub(super) fn actions<'a>(known: &Known<'_, 'a>) -> Result<Vec<ActionNode<'a>>, Refusal> {
    let spec = known.spec;
    let mut out = Vec::with_capacity(spec.actions.len());
    for (i, a) in spec.actions.iter().enumerate() {
        let path = format!("actions[{i}]");
        validate_identifier(&a.name).map_err(|m| at(format!("{path}.name"), m))?;
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
    sources(spec)?;
    Ok(out)
}

/// A source the spec gives an action ({T(poussée → 1)}) is no other torsor's: not another
/// action's, nor a solid's, the ground's or gravity's `pes`.
fn sources(spec: &SpecFile) -> Result<(), Refusal> {
    let printed = crate::wire::action_sources(spec);
    for (i, a) in spec.actions.iter().enumerate() {
        let Some(s) = a.source.as_deref().map(str::trim) else {
            continue;
        };
        let same = (printed.iter().enumerate()).find(|&(j, o)| j != i && o.trim() == s);
        let why = match same {
            Some((j, _)) => format!(
                "`{s}` is also the source of actions[{j}] (`{}`): their torsors would print \
                 the same {{T({s}→…)}}; give each its own `source`",
                spec.actions[j].name
            ),
            None if crate::wire::source::taken(spec, s) => format!(
                "`{s}` already prints as the source of another torsor (a solid's, the ground's \
                 or gravity's `pes`): give the action its own `source`"
            ),
            None => continue,
        };
        return Err(at(format!("actions[{i}].source"), why));
    }
    Ok(())
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
                let n = &t.isolate;
                let why = if known.frames.contains_key(n.as_str()) {
                    format!(
                        "`{n}` is a frame, not a solid or a set: a body of negligible mass is \
                         isolated as a solid, declared in `solids` as `{{\"name\": \"{n}\", \
                         \"frame\": \"{n}\", \"massless\": true}}`"
                    )
                } else {
                    let hint = known.solid_hint(n, false, true);
                    format!("unknown solid or set `{n}`{hint}")
                };
                at(format!("{path}.isolate"), why)
            })?,
        };
        let point = match (&t.point, t.theorem) {
            (Some(_), TheoremKind::Energy) => {
                let why = "the kinetic energy theorem is written at no point";
                return Err(at(format!("{path}.point"), why));
            }
            (Some(p), _) => Some(known.point(format!("{path}.point"), p)?),
            (None, TheoremKind::Resultant | TheoremKind::Energy) => None,
            (None, TheoremKind::Moment) => {
                let why = "the moment theorem is written at a point";
                return Err(at(format!("{path}.point"), why));
            }
        };
        let on = match (&t.on, t.theorem) {
            (Some(_), TheoremKind::Energy) => {
                let why = "the kinetic energy theorem is a scalar equation: it is projected on \
                           no vector (remove `on`)";
                return Err(at(format!("{path}.on"), why));
            }
            // Unused: the ground's first vector.
            (None, TheoremKind::Energy) => (0, 0),
            (None, _) => {
                let why = "a resultant or moment theorem is projected on a basis vector: \
                           `\"on\": \"z0\"`";
                return Err(at(format!("{path}.on"), why));
            }
            (Some(on), _) => known.basis_vector(on).ok_or_else(|| {
                let hint = known.vector_hint(on);
                let why = format!("`{on}` is not a basis vector such as z0{hint}");
                at(format!("{path}.on"), why)
            })?,
        };
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
