//! Validation of the PFD sections of a spec (`gravity`, `links`, `actions`, `pfd`) into
//! [`Dynamics`], every error naming the JSON path.

use super::SpecError;
use super::validate::{at, expr_err};
use crate::expr::{Expr, Registry};
use crate::frame::{Axis, FrameId};
use crate::kinematics::{omega, velocity};
use crate::mechanism::{BodyId, Mechanism};
use crate::pfd::{Action, Dynamics, Source, SpringPart, Theorem, link_unknowns, transmitted};
use crate::point::PointId;
use crate::resolve::{Resolved, Side};
use crate::vector::Vector;
use crate::wire::{CoordinateKind, LinkKind, SpecFile};
use std::collections::HashSet;
use std::rc::Rc;

/// The axis letter of a basis vector text (`z0` → z), before frames exist.
fn axis_letter(s: &str) -> Option<Axis> {
    Axis::parse(&s.chars().next()?.to_string())
}

/// Names the PFD adds to the registry: the unknowns (links' components, then the actions'),
/// and the angles that enter as themselves (torsion springs).
pub(super) fn pfd_names(
    spec: &SpecFile,
    taken: &crate::resolve::Names,
) -> Result<(Vec<String>, Vec<String>), SpecError> {
    let mut unknowns: Vec<String> = Vec::new();
    let mut seen: HashSet<String> = HashSet::new();
    let mut add = |path: String, n: String, unknowns: &mut Vec<String>| {
        crate::expr::check_identifier(&n).map_err(|m| at(&path, m))?;
        if let Some(m) = crate::resolve::basis_vector_clash(spec, "unknown", &n) {
            return Err(at(path, m));
        }
        if taken.contains(&n) {
            return Err(at(
                path,
                format!("the unknown `{n}` is already a parameter or coordinate"),
            ));
        }
        if !seen.insert(n.clone()) {
            return Err(at(path, format!("the unknown `{n}` is declared twice")));
        }
        unknowns.push(n);
        Ok(())
    };
    for (i, l) in spec.links.iter().enumerate() {
        let path = format!("links[{i}]");
        let axis = match (&l.axis, l.kind) {
            (Some(a), _) => axis_letter(a).ok_or_else(|| {
                at(
                    format!("{path}.axis"),
                    format!("`{a}` is not a basis vector such as z0"),
                )
            })?,
            (None, LinkKind::Ball | LinkKind::Fixed) => Axis::Z,
            (None, _) => {
                return Err(at(
                    format!("{path}.axis"),
                    format!("a {} needs its axis (or normal)", l.kind.course_name()),
                ));
            }
        };
        let direction = match (&l.direction, l.kind) {
            (Some(d), LinkKind::Line) => {
                let d = axis_letter(d).ok_or_else(|| {
                    at(
                        format!("{path}.direction"),
                        format!("`{d}` is not a basis vector"),
                    )
                })?;
                if d == axis {
                    return Err(at(
                        format!("{path}.direction"),
                        "the line's direction must differ from the normal",
                    ));
                }
                Some(d)
            }
            (Some(_), _) => {
                return Err(at(
                    format!("{path}.direction"),
                    "only a line contact (`line`) has a direction",
                ));
            }
            (None, LinkKind::Line) => {
                return Err(at(
                    format!("{path}.direction"),
                    "a line contact needs the direction of its line",
                ));
            }
            (None, _) => None,
        };
        for n in link_unknowns(&l.name, transmitted(l.kind, axis, direction)) {
            add(format!("{path}.name"), n, &mut unknowns)?;
        }
    }
    for (i, a) in spec.actions.iter().enumerate() {
        for (k, n) in a.unknowns.iter().enumerate() {
            add(
                format!("actions[{i}].unknowns[{k}]"),
                n.clone(),
                &mut unknowns,
            )?;
        }
    }
    let mut raw = Vec::new();
    for s in &spec.small {
        if spec
            .coordinates
            .iter()
            .any(|c| c.name == s.coordinate && c.kind == CoordinateKind::Angle)
            && !raw.contains(&s.coordinate)
        {
            raw.push(s.coordinate.clone());
        }
    }
    for l in &spec.links {
        if let Some(s) = &l.spring
            && spec
                .coordinates
                .iter()
                .any(|c| c.name == s.coordinate && c.kind == CoordinateKind::Angle)
            && !raw.contains(&s.coordinate)
        {
            raw.push(s.coordinate.clone());
        }
    }
    Ok((unknowns, raw))
}

fn basis_vector(m: &Mechanism, path: &str, s: &str) -> Result<(FrameId, Axis), SpecError> {
    m.frames.basis_vector(s).ok_or_else(|| {
        at(
            path,
            format!("`{s}` is not a basis vector (x, y or z followed by a frame name)"),
        )
    })
}

fn vector(m: &Mechanism, path: &str, text: &str) -> Result<(Vector, FrameId), SpecError> {
    let bv = |s: &str| m.frames.basis_vector(s).map(|(f, a)| (f, a.index()));
    let parts = m
        .reg
        .parse_vector(text, &bv)
        .map_err(|e| expr_err(path, e))?;
    let mut v = Vector::zero();
    let mut basis = None;
    for (f, c) in parts {
        basis.get_or_insert(f);
        v.add_part(f, c);
    }
    Ok((v, basis.unwrap_or(m.frames.ground())))
}

fn constant(reg: &Rc<Registry>, path: &str, text: &str) -> Result<Expr, SpecError> {
    let e = reg.parse(text).map_err(|e| expr_err(path, e))?;
    if !e.is_time_independent() {
        return Err(at(path, "a constant is expected (parameters only)"));
    }
    Ok(e)
}

fn frame_of_side(m: &Mechanism, s: &Source) -> FrameId {
    match s {
        Source::Body(b) => m.body(*b).frame,
        Source::Outside => m.frames.ground(),
    }
}

/// The links (indices) of a path from `a` to `b` in the graph of links, when a new link
/// between them would close a loop. Links in parallel between the same two solids (two
/// bearings of one shaft) make one connection, not a loop.
fn closes_loop(graph: &[(usize, usize, usize)], a: usize, b: usize) -> Option<Vec<usize>> {
    if graph
        .iter()
        .any(|&(x, y, _)| (x, y) == (a, b) || (x, y) == (b, a))
    {
        return None;
    }
    // Breadth-first search from a, remembering the link that reached each node.
    let mut reached: std::collections::BTreeMap<usize, Option<(usize, usize)>> = [(a, None)].into();
    let mut queue = std::collections::VecDeque::from([a]);
    while let Some(n) = queue.pop_front() {
        for &(x, y, k) in graph {
            let other = if x == n {
                y
            } else if y == n {
                x
            } else {
                continue;
            };
            if reached.contains_key(&other) {
                continue;
            }
            reached.insert(other, Some((n, k)));
            if other == b {
                let mut chain = Vec::new();
                let mut cur = b;
                while let Some(Some((prev, k))) = reached.get(&cur) {
                    chain.push(*k);
                    cur = *prev;
                }
                chain.reverse();
                return Some(chain);
            }
            queue.push_back(other);
        }
    }
    None
}

/// Builds the actions and theorems of the spec on the validated mechanism.
pub(super) fn build(
    m: &Mechanism,
    spec: &SpecFile,
    resolved: &Resolved,
) -> Result<Dynamics, SpecError> {
    let reg = &m.reg;
    let mut d = Dynamics::default();
    if let Some(g) = &spec.gravity {
        let (v, _) = vector(m, "gravity", g)?;
        for (f, c) in v.parts() {
            if f != m.frames.ground() || c.iter().any(|e| !e.is_time_independent()) {
                return Err(at(
                    "gravity",
                    format!(
                        "gravity is a constant vector of the ground's basis ({}0, …)",
                        'z'
                    ),
                ));
            }
        }
        d.gravity = Some(v);
    }
    let mut unknown_iter = reg.unknowns().iter();
    // The graph of links so far: (node, node, link index), the ground being node 0.
    let mut graph: Vec<(usize, usize, usize)> = Vec::new();
    for ((i, l), link) in spec.links.iter().enumerate().zip(&resolved.links) {
        let path = format!("links[{i}]");
        // Named, between two different solids (or the ground and a solid), as resolved.
        let source = |s: Side| match s {
            Side::Ground => Source::Outside,
            Side::Solid(b) => Source::Body(BodyId(b)),
        };
        let from = source(link.between[0]);
        let Source::Body(on) = source(link.between[1]) else {
            unreachable!("the ground never receives a link's action, as resolved")
        };
        let node = |s: &Source| match s {
            Source::Outside => 0,
            Source::Body(b) => b.0 + 1,
        };
        let (na, nb) = (node(&from), node(&Source::Body(on)));
        // A loop closed by a closure (a crank–slider's slide) is a loop of the mechanism.
        if let Some(chain) = closes_loop(&graph, na, nb).filter(|_| spec.closures.is_empty()) {
            let names: Vec<&str> = chain.iter().map(|&k| spec.links[k].name.as_str()).collect();
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
        graph.push((na, nb, i));
        let point = PointId(link.point);
        let (basis, axis) = match &l.axis {
            Some(a) => basis_vector(m, &format!("{path}.axis"), a)?,
            None => (m.frames.ground(), Axis::Z),
        };
        let direction = l.direction.as_ref().and_then(|s| axis_letter(s));
        let t = transmitted(l.kind, axis, direction);
        let mut comps: [Expr; 6] = std::array::from_fn(|_| reg.zero());
        for (k, on_k) in t.iter().enumerate() {
            if *on_k {
                let n = unknown_iter.next().expect("unknowns declared in order");
                comps[k] = reg.param(n).expect("unknown registered");
            }
        }
        let [x, y, z, ll, mm, nn] = comps;
        let mut resultant = Vector::new(basis, [x, y, z]);
        let mut moment = Vector::new(basis, [ll, mm, nn]);
        let u = Vector::along(basis, axis, reg.one());
        let (fa, fb) = (frame_of_side(m, &from), m.body(on).frame);
        let mut description = format!("{} ", l.kind.course_name());
        description.push_str(&match (l.kind, &l.axis) {
            (LinkKind::Ball, _) | (_, None) => format!("de centre {}", l.point),
            (LinkKind::Plane | LinkKind::Point | LinkKind::Line, Some(a)) => {
                format!("de normale ({}, {a})", l.point)
            }
            (_, Some(a)) => format!("d'axe ({}, {a})", l.point),
        });
        if let Some(f) = &l.friction {
            let fpath = format!("{path}.friction");
            let f = constant(reg, &fpath, f)?;
            match l.kind {
                LinkKind::Pivot => {
                    let rate = omega(m, fb, fa).dot(&m.frames, &u);
                    moment = moment.sub(&u.scale(&(&f * &rate)));
                }
                LinkKind::Slider => {
                    let rate = velocity(m, point, fb, fa).dot(&m.frames, &u);
                    resultant = resultant.sub(&u.scale(&(&f * &rate)));
                }
                _ => {
                    return Err(at(
                        fpath,
                        "viscous friction is declared on a pivot or a slider",
                    ));
                }
            }
            description.push_str(", avec frottement visqueux");
        }
        if let (Some(c), Some(sign)) = (&l.coulomb, l.sign_parameter()) {
            let cpath = format!("{path}.coulomb");
            let c = constant(reg, &cpath, c)?;
            if let Some(n) = reg.unknowns().iter().find(|n| {
                reg.param(n)
                    .and_then(|u| u.single_variable())
                    .is_some_and(|v| c.contains_var(v))
            }) {
                return Err(at(
                    cpath,
                    format!(
                        "the magnitude holds the unknown `{n}`: dry friction takes a magnitude \
                         of the parameters (write the normal force the statement knows, \
                         f*m*g*cos(alpha))"
                    ),
                ));
            }
            let eps = reg.parse(&sign).map_err(|e| expr_err(&cpath, e))?;
            let push = u.scale(&(&c * &eps));
            let rate = match l.kind {
                LinkKind::Pivot => {
                    moment = moment.sub(&push);
                    omega(m, fb, fa).dot(&m.frames, &u)
                }
                LinkKind::Slider => {
                    resultant = resultant.sub(&push);
                    velocity(m, point, fb, fa).dot(&m.frames, &u)
                }
                _ => {
                    return Err(at(cpath, "dry friction is declared on a pivot or a slider"));
                }
            };
            if rate.is_zero() {
                return Err(at(
                    cpath,
                    "the link's relative rate along its axis is zero whatever the motion: \
                     nothing slides",
                ));
            }
            d.dry.push(crate::mechanism::DryFriction {
                sign,
                rate,
                magnitude: c,
            });
            description.push_str(", avec frottement sec");
        }
        let mut spring = None;
        if let Some(s) = &l.spring {
            let spath = format!("{path}.spring");
            let q = reg.coord(&s.coordinate).ok_or_else(|| {
                at(
                    format!("{spath}.coordinate"),
                    format!("unknown coordinate `{}`", s.coordinate),
                )
            })?;
            let k = constant(reg, &format!("{spath}.stiffness"), &s.stiffness)?;
            let q0 = match &s.free {
                Some(t) => constant(reg, &format!("{spath}.free"), t)?,
                None => reg.zero(),
            };
            let value = reg.value(q).ok_or_else(|| {
                at(
                    format!("{spath}.coordinate"),
                    "the coordinate has no value variable",
                )
            })?;
            let stretch = &value - &q0;
            let force = u.scale(&(&k * &stretch)).neg();
            let potential = &(&reg.rational(1, 2) * &k) * &(&stretch * &stretch);
            let (sr, sm) = match l.kind {
                LinkKind::Pivot => (Vector::zero(), force),
                LinkKind::Slider => (force, Vector::zero()),
                _ => {
                    return Err(at(spath, "a spring is declared on a pivot or a slider"));
                }
            };
            resultant = resultant.add(&sr);
            moment = moment.add(&sm);
            spring = Some(SpringPart {
                potential,
                resultant: sr,
                moment: sm,
            });
            description.push_str(", avec ressort");
        }
        d.actions.push(Action {
            from_label: l.between[0].clone(),
            on_label: l.between[1].clone(),
            exerted_by: l.between[0].clone(),
            from,
            on,
            point,
            resultant,
            moment,
            basis,
            description,
            label: l.label(),
            spring,
        });
    }
    for ((i, a), action) in spec.actions.iter().enumerate().zip(&resolved.actions) {
        let path = format!("actions[{i}]");
        // Named, exerted by a solid (or the ground) on another solid, as resolved.
        let from = match action.from {
            Side::Ground => Source::Outside,
            Side::Solid(b) => Source::Body(BodyId(b)),
        };
        let on = BodyId(action.on);
        let point = PointId(action.point);
        let (resultant, b1) = match &a.resultant {
            Some(t) => vector(m, &format!("{path}.resultant"), t)?,
            None => (Vector::zero(), m.frames.ground()),
        };
        let (moment, b2) = match &a.moment {
            Some(t) => vector(m, &format!("{path}.moment"), t)?,
            None => (Vector::zero(), b1),
        };
        let basis = if a.resultant.is_some() { b1 } else { b2 };
        d.actions.push(Action {
            from_label: a.name.clone(),
            on_label: a.on.clone(),
            exerted_by: a.from.clone(),
            from,
            on,
            point,
            resultant,
            moment,
            basis,
            description: format!("action {} de {} sur {}", a.name, a.from, a.on),
            label: a.label(),
            spring: None,
        });
    }
    // What each theorem isolates, its point, its vector and its coordinate, as resolved.
    for (t, node) in spec.pfd.iter().zip(&resolved.theorems) {
        let solids = node.isolate.iter().map(|&b| BodyId(b)).collect();
        let point = node.point.map_or(m.points.origin(), PointId);
        let on = (FrameId(node.on.0), [Axis::X, Axis::Y, Axis::Z][node.on.1]);
        let eom = (t.eom.as_ref()).map(|c| reg.coord(c).expect("a coordinate, as resolved"));
        d.theorems.push(Theorem {
            isolate: t.isolate.clone(),
            solids,
            kind: t.theorem,
            point,
            on,
            eom,
        });
    }
    for (i, s) in spec.small.iter().enumerate() {
        let path = format!("small[{i}]");
        // lin(…) sets cos q to 1 and sin q to 0 coordinate by coordinate: it would neither
        // follow the coordinates a loop closure ties to q nor know 1/cos q.
        if !spec.closures.is_empty() {
            return Err(at(
                path,
                "lin(…) is not available with loop closures yet (the dependent coordinates \
                 would not follow the small one)",
            ));
        }
        let q = reg.coord(&s.coordinate).ok_or_else(|| {
            at(
                format!("{path}.coordinate"),
                format!("unknown coordinate `{}`", s.coordinate),
            )
        })?;
        if d.small.iter().any(|x| x.coord == q) {
            return Err(at(format!("{path}.coordinate"), "declared small twice"));
        }
        let around = match &s.around {
            Some(t) => constant(reg, &format!("{path}.around"), t)?,
            None => reg.zero(),
        };
        if reg.coord_info(q).kind == CoordinateKind::Angle && !around.is_zero() {
            return Err(at(
                format!("{path}.around"),
                "a small angle moves around 0: write the angle from the equilibrium position",
            ));
        }
        d.small.push(crate::pfd::Small { coord: q, around });
    }
    Ok(d)
}

/// The spec with a parameter ε (value ±1, the sign of the relative rate) for each link with
/// dry friction, named by [`crate::wire::LinkSpec::sign_parameter`].
pub(super) fn with_signs(spec: &SpecFile) -> Result<std::borrow::Cow<'_, SpecFile>, SpecError> {
    if spec.links.iter().all(|l| l.coulomb.is_none()) {
        return Ok(std::borrow::Cow::Borrowed(spec));
    }
    let mut out = spec.clone();
    for (i, l) in spec.links.iter().enumerate() {
        let Some(name) = l.sign_parameter() else {
            continue;
        };
        let taken = spec
            .parameters
            .iter()
            .map(|p| &p.name)
            .chain(spec.coordinates.iter().map(|c| &c.name))
            .chain(spec.aliases.iter().map(|a| &a.name))
            .any(|n| *n == name);
        if taken {
            return Err(at(
                format!("links[{i}].coulomb"),
                format!(
                    "`{name}` is the sign of this link's relative rate under dry friction: \
                     give the parameter of that name another name"
                ),
            ));
        }
        out.parameters.push(crate::wire::ParameterSpec {
            name,
            description: Some(format!(
                "signe de la vitesse relative de la liaison {} ($\\pm 1$)",
                l.name
            )),
            unit: Some("1".into()),
            kind: Default::default(),
        });
    }
    Ok(std::borrow::Cow::Owned(out))
}
