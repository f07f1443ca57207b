//! Validation of a spec's PFD sections (`gravity`, `links`, `actions`, `pfd`) into
//! [`Dynamics`], on the references and unknowns the shared resolution found, and of the
//! exact side's own `small` section, every error naming the JSON path.

use super::SpecError;
use super::refusal::{at, expr_err};
use super::sides::{constant, frame_of_side, source};
use crate::expr::{Expr, Registry};
use crate::frame::{Axis, FrameId};
use crate::kinematics::{omega, velocity};
use crate::mechanism::{BodyId, DryFriction, Mark, Mechanism};
use crate::pfd::{Action, Dynamics, Small, SpringPart, Theorem};
use crate::point::PointId;
use crate::resolve::{LinkNode, Resolved, Unknowns};
use crate::vector::Vector;
use crate::wire::{CoordinateKind, LinkKind, LinkSpec, SpecFile};
use std::rc::Rc;

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

/// Builds the actions and theorems of the spec on the validated mechanism.
pub(super) fn build(
    m: &Mechanism,
    spec: &SpecFile,
    (resolved, unknowns): (&Resolved, &Unknowns),
) -> Result<Dynamics, SpecError> {
    let mut d = Dynamics {
        gravity: gravity(m, spec)?,
        ..Default::default()
    };
    for (i, node) in resolved.links.iter().enumerate() {
        let path = format!("links[{i}]");
        // Its unknowns: the components this side's own transmissibility gave, as named.
        let comps = (unknowns.links[i].iter()).map(|&(k, u)| (k, unknowns.names[u].as_str()));
        let action = link(m, (&spec.links[i], &path), node, comps, &mut d.dry)?;
        if let Some(c) = node.contact {
            let law = super::coulomb::law(m, (spec, i), node, c, &unknowns.links[i], unknowns)?;
            d.dry.push(DryFriction {
                sign: spec.links[i]
                    .sign_parameter()
                    .expect("a link with friction"),
                rate: law.rate.clone(),
                magnitude: &law.coefficient * &law.values[1],
            });
            d.laws.push(law);
        }
        d.actions.push(action);
    }
    marks(&mut d.actions, &spec.links);
    for (i, node) in resolved.actions.iter().enumerate() {
        d.actions.push(action(m, spec, i, node)?);
    }
    d.action_unknowns = (unknowns.actions.iter().flatten())
        .map(|&u| unknowns.names[u].clone())
        .collect();
    // What each theorem isolates, its point, its vector and its coordinate, as resolved.
    for (t, node) in spec.pfd.iter().zip(&resolved.theorems) {
        let eom = (t.eom.as_ref()).map(|c| m.reg.coord(c).expect("a coordinate, as resolved"));
        // A carrier is isolated with the solids it carries (`1+2`).
        let own: Vec<BodyId> = node.isolate.iter().map(|&b| BodyId(b)).collect();
        let (isolate, solids) = m.isolated(&t.isolate, &own);
        d.theorems.push(Theorem {
            isolate,
            solids,
            kind: t.theorem,
            point: node.point.map_or(m.points.origin(), PointId),
            on: (FrameId(node.on.0), Axis::ALL[node.on.1]),
            eom,
        });
    }
    d.small = small(m, spec)?;
    Ok(d)
}

/// Gravity: a constant vector of the ground's basis.
fn gravity(m: &Mechanism, spec: &SpecFile) -> Result<Option<Vector>, SpecError> {
    let Some(g) = &spec.gravity else {
        return Ok(None);
    };
    let (v, _) = vector(m, "gravity", g)?;
    for (f, c) in v.parts() {
        if f != m.frames.ground() || c.iter().any(|e| !e.is_time_independent()) {
            let why = "gravity is a constant vector of the ground's basis (z0, …)";
            return Err(at("gravity", why));
        }
    }
    Ok(Some(v))
}

/// A link's action on its second solid: one unknown per component it transmits, in the basis
/// of its axis, and what its viscous friction, dry friction and spring add along the axis
/// (a torque for a pivot, a force for a slider: the resolution allows them on no other kind).
fn link<'u>(
    m: &Mechanism,
    (l, path): (&LinkSpec, &str),
    node: &LinkNode,
    unknowns: impl Iterator<Item = (usize, &'u str)>,
    dry: &mut Vec<DryFriction>,
) -> Result<Action, SpecError> {
    let reg = &m.reg;
    let (from, on) = (source(node.from), BodyId(node.on));
    let (point, basis) = (PointId(node.point), FrameId(node.axis.0));
    let axis = Axis::ALL[node.axis.1];
    let mut comps: [Expr; 6] = std::array::from_fn(|_| reg.zero());
    for (k, n) in unknowns {
        comps[k] = reg.param(n).expect("unknown registered");
    }
    let [x, y, z, ll, mm, nn] = comps;
    let (mut resultant, mut moment) = (
        Vector::new(basis, [x, y, z]),
        Vector::new(basis, [ll, mm, nn]),
    );
    let u = Vector::along(basis, axis, reg.one());
    // The relative rate along the axis: Ω(b/a)·u for a pivot, V(P ∈ b/a)·u for a slider.
    let pivot = l.kind == LinkKind::Pivot;
    let (fa, fb) = (frame_of_side(m, &from), m.body(on).frame);
    if let Some(text) = &l.pitch {
        let p = pitch(m, (l, path), text, ([fa, fb], point, &u))?;
        // Perfect: zero power, X V·u + L Ω·u = 0 with V·u = p/(2π) Ω·u, so L = −p X/(2π).
        let axial = resultant.express_in(&m.frames, basis)[axis.index()].clone();
        let tied = &(&p * &reg.parse("-1/(2*pi)").map_err(|e| expr_err(path, e))?) * &axial;
        moment = moment.add(&u.scale(&tied));
    }
    let rate = || match pivot {
        true => omega(m, fb, fa).dot(&m.frames, &u),
        false => velocity(m, point, fb, fa).dot(&m.frames, &u),
    };
    let mut along = |v: Vector| match pivot {
        true => moment = moment.add(&v),
        false => resultant = resultant.add(&v),
    };
    let mut description = description(l);
    if let Some(f) = &l.friction {
        let f = constant(reg, &format!("{path}.friction"), f)?;
        along(u.scale(&(&f * &rate())).neg());
        description.push_str(", avec frottement visqueux");
    }
    if let Some(c) = &l.coulomb {
        let (push, friction) = coulomb(m, (l, path), c, rate())?;
        along(u.scale(&push).neg());
        dry.push(friction);
        description.push_str(", avec frottement sec");
    }
    if l.contact_friction.is_some() {
        description.push_str(", avec frottement sec");
    }
    let spring = match &l.spring {
        Some(s) => {
            let (force, potential) = spring(reg, s, &format!("{path}.spring"))?;
            let force = u.scale(&force).neg();
            along(force.clone());
            description.push_str(", avec ressort");
            let (resultant, moment) = match pivot {
                true => (Vector::zero(), force),
                false => (force, Vector::zero()),
            };
            Some(SpringPart {
                potential,
                resultant,
                moment,
            })
        }
        None => None,
    };
    Ok(Action {
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
        source: l.between[0].clone(),
        mark: None,
        spring,
    })
}

/// Each link's mark among the links joining the same two solids (`actions[i]` is
/// `links[i]`'s action): its point when theirs differ, else its name.
fn marks(actions: &mut [Action], links: &[LinkSpec]) {
    let pair = |l: &LinkSpec| {
        let mut p = l.between.clone();
        p.sort();
        p
    };
    for (i, l) in links.iter().enumerate() {
        let same: Vec<&LinkSpec> = links.iter().filter(|o| pair(o) == pair(l)).collect();
        if same.len() < 2 {
            continue;
        }
        let shared = same.iter().filter(|o| o.point == l.point).count() > 1;
        actions[i].mark = Some(match shared {
            true => Mark::Link(l.name.clone()),
            false => Mark::Point(l.point.clone()),
        });
    }
}

/// How the course describes a link: « liaison pivot d'axe (O1, z0) », « de normale », « de
/// centre », « liaison hélicoïdale d'axe (O, z0) et de pas p ».
fn description(l: &LinkSpec) -> String {
    let place = match (l.kind, &l.axis) {
        (LinkKind::Ball, _) | (_, None) => format!("de centre {}", l.point),
        (LinkKind::Plane | LinkKind::Point | LinkKind::Line, Some(a)) => {
            format!("de normale ({}, {a})", l.point)
        }
        (_, Some(a)) => format!("d'axe ({}, {a})", l.point),
    };
    match &l.pitch {
        Some(p) => format!("{} {place} et de pas {p}", l.kind.course_name()),
        None => format!("{} {place}", l.kind.course_name()),
    }
}

/// A helical link's pitch p: a constant of the parameters (no unknown), a length when the
/// parameters' units say; and, when the link names no coordinate to determine, the positions
/// must satisfy its relation V(P ∈ b/a)·u = p/(2π) Ω(b/a)·u already.
fn pitch(
    m: &Mechanism,
    (l, path): (&LinkSpec, &str),
    text: &str,
    ([fa, fb], point, u): ([FrameId; 2], PointId, &Vector),
) -> Result<Expr, SpecError> {
    let reg = &m.reg;
    let at_pitch = format!("{path}.pitch");
    let p = constant(reg, &at_pitch, text)?;
    let occurs = p.occurring();
    if let Some((n, _)) = (crate::pfd::unknown_vars(m).into_iter()).find(|(_, v)| occurs[v.index()])
    {
        let why = format!("the pitch holds the unknown `{n}`: it is a length of the parameters");
        return Err(at(at_pitch, why));
    }
    if p.is_zero() {
        return Err(at(
            at_pitch,
            "a pitch of 0 makes no screw: the link would be a pivot",
        ));
    }
    let dims = crate::units::Dimensions::of(m);
    match crate::units::dimension(&p, &dims) {
        Ok(Some(d)) if d != crate::units::Dimension::LENGTH => {
            let unit = match d.si_text(crate::units::UnitStyle::Mechanics) {
                u if u.is_empty() => "a pure number".to_string(),
                u => format!("in {u}"),
            };
            let why = format!(
                "the pitch `{}` is {unit}, not a length (m per turn): name a parameter of unit m",
                crate::excerpt::excerpt(text)
            );
            return Err(at(at_pitch, why));
        }
        Err(_) => {
            let why = format!(
                "the pitch `{}` is not homogeneous: it is a length (m per turn)",
                crate::excerpt::excerpt(text)
            );
            return Err(at(at_pitch, why));
        }
        _ => {}
    }
    if l.dependent.is_none() {
        let two_pi = &reg.integer(2) * &reg.pi();
        let v = velocity(m, point, fb, fa).dot(&m.frames, u);
        let w = omega(m, fb, fa).dot(&m.frames, u);
        let row = &(&two_pi * &v) - &(&p * &w);
        if !row.is_zero() {
            let why = format!(
                "the positions do not follow the screw motion: 2π V({},{}/{})·u − p Ω·u = `{}`, \
                 not 0; name the coordinate whose rate the link determines (`dependent`)",
                l.point,
                l.between[1],
                l.between[0],
                crate::excerpt::excerpt(&row.to_string())
            );
            return Err(at(format!("{path}.dependent"), why));
        }
    }
    Ok(p)
}

/// Dry friction of magnitude C (the parameters' only, never an unknown) on a link whose
/// relative rate along its axis is `rate`, not zero whatever the motion: C ε, what the link
/// adds against the axis, and the friction the samples set ε's sign from.
fn coulomb(
    m: &Mechanism,
    (l, path): (&LinkSpec, &str),
    text: &str,
    rate: Expr,
) -> Result<(Expr, DryFriction), SpecError> {
    let (reg, path) = (&m.reg, format!("{path}.coulomb"));
    let err = |why: String| at(&path, why);
    let c = constant(reg, &path, text)?;
    let occurs = c.occurring();
    if let Some((n, _)) = (crate::pfd::unknown_vars(m).into_iter()).find(|(_, v)| occurs[v.index()])
    {
        return Err(err(format!(
            "the magnitude holds the unknown `{n}`: dry friction takes a magnitude of the \
             parameters (write the normal force the statement knows, f*m*g*cos(alpha))"
        )));
    }
    let sign = l.sign_parameter().expect("a link with dry friction");
    let eps = reg.parse(&sign).map_err(|e| err(e.to_string()))?;
    if rate.is_zero() {
        return Err(err(
            "the link's relative rate along its axis is zero whatever the motion: nothing slides"
                .into(),
        ));
    }
    let push = &c * &eps;
    Ok((
        push,
        DryFriction {
            sign,
            rate,
            magnitude: c,
        },
    ))
}

/// A spring of stiffness k and free value q0 on the coordinate q: k (q − q0), what it adds
/// against the axis, and its potential energy ½ k (q − q0)².
fn spring(
    reg: &Rc<Registry>,
    s: &crate::wire::SpringSpec,
    path: &str,
) -> Result<(Expr, Expr), SpecError> {
    let q = reg.coord(&s.coordinate).expect("a coordinate, as resolved");
    let k = constant(reg, &format!("{path}.stiffness"), &s.stiffness)?;
    let q0 = match &s.free {
        Some(t) => constant(reg, &format!("{path}.free"), t)?,
        None => reg.zero(),
    };
    let value = reg.value(q).ok_or_else(|| {
        at(
            format!("{path}.coordinate"),
            "the coordinate has no value variable",
        )
    })?;
    let stretch = &value - &q0;
    let potential = &(&reg.rational(1, 2) * &k) * &(&stretch * &stretch);
    Ok((&k * &stretch, potential))
}

/// A given action {T(from→on)} at its point, from its resultant and moment expressions.
fn action(
    m: &Mechanism,
    spec: &SpecFile,
    i: usize,
    node: &crate::resolve::ActionNode,
) -> Result<Action, SpecError> {
    let (a, path) = (&spec.actions[i], format!("actions[{i}]"));
    let (resultant, b1) = match &a.resultant {
        Some(t) => vector(m, &format!("{path}.resultant"), t)?,
        None => (Vector::zero(), m.frames.ground()),
    };
    let (moment, b2) = match &a.moment {
        Some(t) => vector(m, &format!("{path}.moment"), t)?,
        None => (Vector::zero(), b1),
    };
    Ok(Action {
        from_label: a.name.clone(),
        on_label: a.on.clone(),
        exerted_by: a.from.clone(),
        from: source(node.from),
        on: BodyId(node.on),
        point: PointId(node.point),
        resultant,
        moment,
        basis: if a.resultant.is_some() { b1 } else { b2 },
        description: format!("action {} de {} sur {}", a.name, a.from, a.on),
        label: a.label(),
        source: crate::wire::action_sources(spec).swap_remove(i),
        mark: None,
        spring: None,
    })
}

/// The coordinates declared small, for `lin(…)`: each once, an angle around 0.
fn small(m: &Mechanism, spec: &SpecFile) -> Result<Vec<Small>, SpecError> {
    let reg = &m.reg;
    let mut out: Vec<Small> = Vec::new();
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
            let why = format!("unknown coordinate `{}`", s.coordinate);
            at(format!("{path}.coordinate"), why)
        })?;
        if out.iter().any(|x| x.coord == q) {
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
        out.push(Small { coord: q, around });
    }
    Ok(out)
}
