//! The PFD recomputed numerically: action torsors at the sampled instant, isolation, the
//! resultant and moment theorems, the linear solve for the unknowns, the equations of motion.
//!
//! Everything comes from the course's definitions, independently of the exact side:
//!
//! - gravity acts on every point mass mₖ of a solid's cloud as mₖ g⃗ at Pₖ, so its moment at P
//!   is Σ PPₖ ∧ mₖ g⃗ summed over the cloud;
//! - a perfect link is the torsor of its first solid on its second at its point, with one
//!   unknown per component it transmits (X, Y, Z, L, M, N followed by its name) along the
//!   basis vectors of its axis' basis; viscous friction and a spring add a known part computed
//!   from the relative motion (Ω(b/a), V(P ∈ b/a)) and the coordinate's value; a helical
//!   link of pitch p, perfect, has zero power X V·u + L Ω·u = 0 along the screw motion
//!   V·u = p/(2π) Ω·u, so its axial moment is L = −p X/(2π);
//! - a given action is evaluated from its expressions; its unknowns enter linearly (checked on
//!   the expression's structure), and their coefficients are read exactly with dual numbers;
//! - every action {T(a→b)} comes with its reaction {T(b→a)} = −{T(a→b)}; isolating S keeps the
//!   ones received by a member of S from a non-member, plus gravity on every member;
//! - each declared equation is a residual, dynamic side minus actions, affine in the unknowns;
//!   the kinetic energy theorem's is Σ mₖ vₖ·Γₖ over the clouds minus the power of every
//!   action on a member (each at its point, in its receiver's motion relative to the ground;
//!   an action between two members and its reaction make the inter-efforts' power), the
//!   weight of every point mass included; as an equation of motion it is divided by q̇.
//!
//! The equations without `eom` are solved with nalgebra's LU for the unknowns that appear in
//! them; an `eom` equation's residual, with those values substituted, is the equation of
//! motion's value at the sample (q̈ is the sample's).

use super::expr::{self, Env, Node};
use super::kin::{self, State, Values};
use super::model::{Context, spec_err};
use super::{NumericError, NumericModel, cloud};
use crate::resolve::{ActionNode, LinkNode, Resolved, Side, Unknowns};
use crate::wire::{ActionSpec, LinkKind, LinkSpec, SpecFile, TheoremKind};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use std::collections::{BTreeMap, BTreeSet};

/// A coefficient of an unknown below this fraction of the size of the terms of its equation is
/// rounding noise: the unknown does not appear there.
const APPEARS: f64 = 1e-9;
/// A pivot of the row- and column-scaled system below this is a singular system.
const SINGULAR: f64 = 1e-10;

mod linear;
mod solve;
use solve::body_frame;
pub(super) use solve::{action, eom, internal_power, power, set_signs, unknown};

/// What exerts or receives an action: a solid, or a frame that is not a solid (the ground).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Body {
    /// A solid, by index.
    Solid(usize),
    /// A frame by index (never a member of an isolated system).
    Frame(usize),
}

/// A spring in a pivot or a slider.
#[derive(Debug, Clone)]
pub(super) struct SpringInfo {
    /// The coordinate q it measures.
    coord: usize,
    /// Stiffness k.
    pub stiffness: Node,
    /// Free value q0 (0 unless given).
    pub free: Option<Node>,
}

/// A perfect link, with its optional friction and spring.
#[derive(Debug, Clone)]
pub(super) struct LinkInfo {
    kind: LinkKind,
    /// The action is that of `between[0]` on `between[1]`.
    between: [Body; 2],
    /// Their names as the spec writes them.
    names: [String; 2],
    point: usize,
    /// Frame whose basis holds the components.
    basis: usize,
    /// Axis (or normal) 0..3 in `basis` (z of the ground for a ball or a fixed link).
    axis: usize,
    /// Transmitted components (0..3 resultant, 3..6 moment) and their unknowns' indices.
    components: Vec<(usize, usize)>,
    /// Viscous friction coefficient f.
    pub friction: Option<Node>,
    /// Dry friction: its magnitude C and the index of the parameter ε that the samples set
    /// to the sign of the relative rate.
    pub coulomb: Option<(Node, usize)>,
    /// Spring.
    pub spring: Option<SpringInfo>,
    /// A helical link's pitch p: its axial moment is −p/(2π) times its axial resultant.
    pub pitch: Option<Node>,
    /// Coulomb's law on its own unknowns.
    pub law: Option<LawInfo>,
}

/// Coulomb's law on a contact's unknowns, T + f ε N = 0 while it slides along `tangent`.
#[derive(Debug, Clone)]
pub(super) struct LawInfo {
    /// The friction coefficient f.
    pub coefficient: Node,
    /// The index of the parameter ε, set at each sample to the sign of the sliding velocity.
    pub sign: usize,
    /// The indices of the unknowns T and N.
    pub unknowns: [usize; 2],
    /// The sliding direction: an axis 0..3 of the link's basis.
    pub tangent: usize,
    /// The normal: another axis of the link's basis.
    pub normal: usize,
}

/// A given action {T(from→on)} at a point.
#[derive(Debug, Clone)]
pub(super) struct ActionInfo {
    /// Its name (`moteur`), the solid it acts on and the one that exerts it.
    names: [String; 3],
    from: Body,
    on: Body,
    point: usize,
    /// Resultant (a vector expression, possibly with unknowns).
    pub resultant: Option<Node>,
    /// Moment at `point`.
    pub moment: Option<Node>,
    /// The unknowns its expressions use.
    unknowns: Vec<usize>,
}

/// One declared scalar equation.
#[derive(Debug, Clone)]
struct TheoremInfo {
    /// The isolated solids.
    solids: Vec<usize>,
    /// Moment theorem (else resultant theorem, or the energy theorem).
    moment: bool,
    /// The kinetic energy theorem: dEc/dt − P(ext) − P_int, no point and no vector.
    energy: bool,
    /// Point of the moment theorem (the ground origin for a resultant theorem).
    point: usize,
    /// Basis vector projected on: frame, axis.
    on: (usize, usize),
    /// The coordinate whose equation of motion this is.
    eom: Option<usize>,
}

/// The `gravity`, `links`, `actions` and `pfd` sections of a spec, resolved.
#[derive(Debug, Clone, Default)]
pub(super) struct Dynamics {
    /// g⃗, a constant vector.
    pub gravity: Option<Node>,
    /// Links.
    pub links: Vec<LinkInfo>,
    /// Given actions.
    pub actions: Vec<ActionInfo>,
    theorems: Vec<TheoremInfo>,
    /// Names of the unknowns: the links' components in order, then the actions' unknowns.
    pub unknowns: Vec<String>,
    unknown_index: BTreeMap<String, usize>,
    /// The given actions' unknowns (a motor torque), by index: one that no equation without
    /// `eom` holds is an input of the equations of motion.
    given_unknowns: Vec<usize>,
}

/// Components a link transmits (0..3 resultant, 3..6 moment, in its basis), `a` the axis,
/// `d` a line contact's direction, and `sliding` the direction of the tangential force that
/// Coulomb's law ties to the normal one (a contact's or a slider's friction).
pub(super) fn transmitted(
    kind: LinkKind,
    a: usize,
    d: Option<usize>,
    sliding: Option<usize>,
) -> [bool; 6] {
    let mut t = perfect(kind, a, d);
    if let Some(k) = sliding {
        t[k] = true;
    }
    t
}

/// Components a perfect link transmits (see [`transmitted`]).
fn perfect(kind: LinkKind, a: usize, d: Option<usize>) -> [bool; 6] {
    let d = d.unwrap_or((a + 1) % 3);
    let mut t = [false; 6];
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    match kind {
        LinkKind::Fixed => t = [true; 6],
        // The axial moment of a helical link follows its axial resultant (`link_term`).
        LinkKind::Pivot | LinkKind::Helical => {
            t = [true; 6];
            t[3 + a] = false;
        }
        LinkKind::Slider => {
            t = [true; 6];
            t[a] = false;
        }
        LinkKind::PivotSlider => {
            t = [true; 6];
            t[a] = false;
            t[3 + a] = false;
        }
        LinkKind::Ball => {
            t[0] = true;
            t[1] = true;
            t[2] = true;
        }
        LinkKind::Plane => {
            t[a] = true;
            t[3 + b] = true;
            t[3 + c] = true;
        }
        LinkKind::Annular => {
            t[b] = true;
            t[c] = true;
        }
        LinkKind::Line => {
            t[a] = true;
            t[3 + (3 - a - d)] = true;
        }
        LinkKind::Point => t[a] = true,
    }
    t
}

/// Resolves the spec's `gravity`, `links`, `actions` and `pfd` against a model whose other
/// parts are built, on the references the shared resolution found. Errors name the JSON path.
pub(super) fn build(
    spec: &SpecFile,
    m: &NumericModel,
    trees: &Resolved,
    unknowns: Unknowns,
) -> Result<Dynamics, NumericError> {
    let mut d = Dynamics {
        gravity: gravity(spec, m)?,
        ..Default::default()
    };
    for (i, (l, node)) in spec.links.iter().zip(&trees.links).enumerate() {
        let path = format!("links[{i}]");
        d.links.push(link(
            (spec, m),
            (l, &path),
            node,
            unknowns.links[i].clone(),
        )?);
    }
    for (i, (a, node)) in spec.actions.iter().zip(&trees.actions).enumerate() {
        // Its own unknowns, the only ones its expressions may name.
        let own = (a.unknowns.iter().cloned()).zip(unknowns.actions[i].iter().copied());
        let path = format!("actions[{i}]");
        d.actions.push(given(m, (a, &path), node, own.collect())?);
    }
    d.given_unknowns = unknowns.actions.iter().flatten().copied().collect();
    d.unknown_index = (unknowns.names.iter().enumerate())
        .map(|(k, n)| (n.clone(), k))
        .collect();
    d.unknowns = unknowns.names;
    // The declared equations: what each isolates, its point, its vector and its coordinate,
    // as resolved.
    for (t, node) in spec.pfd.iter().zip(&trees.theorems) {
        d.theorems.push(TheoremInfo {
            solids: with_carried(trees, &node.isolate),
            moment: t.theorem == TheoremKind::Moment,
            energy: t.theorem == TheoremKind::Energy,
            point: node.point.unwrap_or(0),
            on: node.on,
            eom: node.eom,
        });
    }
    Ok(d)
}

/// The solids a theorem on `isolate` isolates: these, and each solid whose chain of carriers
/// (`carried_by`) reaches one of them (a balourd rides on its rotor).
fn with_carried(trees: &Resolved, isolate: &[usize]) -> Vec<usize> {
    let mut out = isolate.to_vec();
    for s in 0..trees.solids.len() {
        let mut up = trees.solids[s].carried_by;
        // A chain of carriers ends (resolve refuses a cycle): at most one step per solid.
        for _ in 0..trees.solids.len() {
            match up {
                Some(c) if isolate.contains(&c) => {
                    if !out.contains(&s) {
                        out.push(s);
                    }
                    break;
                }
                Some(c) => up = trees.solids[c].carried_by,
                None => break,
            }
        }
    }
    out
}

/// Gravity: a vector constant in the ground frame, written on bases that do not turn with
/// time.
fn gravity(spec: &SpecFile, m: &NumericModel) -> Result<Option<Node>, NumericError> {
    let Some(g) = &spec.gravity else {
        return Ok(None);
    };
    let node = (m.names().parse(g, Context::ConstantVector)).map_err(|e| spec_err("gravity", e))?;
    let mut used = BTreeSet::new();
    expr::frames_in(&node, &mut used);
    for f in used {
        let mut k = f;
        while k != 0 {
            if let Some((_, _, angle)) = &m.frames[k].rotation
                && expr::depends_on_time(angle)
            {
                let why = format!(
                    "gravity is constant in the ground frame: the basis of frame {} turns with \
                     time",
                    m.frames[f].name
                );
                return Err(spec_err("gravity", why));
            }
            k = m.frames[k].parent;
        }
    }
    Ok(Some(node))
}

/// A link: its sides, point and axis as resolved, its transmitted `components` (with their
/// unknowns' indices), its viscous friction, dry friction and spring read with this backend's
/// parser.
fn link(
    (spec, m): (&SpecFile, &NumericModel),
    (l, path): (&LinkSpec, &str),
    node: &LinkNode,
    components: Vec<(usize, usize)>,
) -> Result<LinkInfo, NumericError> {
    let names = m.names();
    let constant = |text: &str, field: &str| {
        (names.parse(text, Context::Constant)).map_err(|e| spec_err(format!("{path}.{field}"), e))
    };
    let friction = l
        .friction
        .as_deref()
        .map(|f| constant(f, "friction"))
        .transpose()?;
    let coulomb = match (&l.coulomb, l.sign_parameter()) {
        (Some(c), Some(sign)) => Some((constant(c, "coulomb")?, m.param_index[&sign])),
        _ => None,
    };
    let law = match (&l.contact_friction, node.contact) {
        (Some(_), Some(contact)) => Some(law((spec, m), (l, path), contact, &components)?),
        _ => None,
    };
    let spring = match &l.spring {
        Some(s) => Some(SpringInfo {
            coord: node.spring.expect("a spring's coordinate, as resolved"),
            stiffness: constant(&s.stiffness, "spring.stiffness")?,
            free: (s.free.as_deref())
                .map(|q0| constant(q0, "spring.free"))
                .transpose()?,
        }),
        None => None,
    };
    let pitch = (l.pitch.as_deref())
        .map(|p| constant(p, "pitch"))
        .transpose()?;
    let from = match node.from {
        Side::Ground => Body::Frame(0),
        Side::Solid(k) => Body::Solid(k),
    };
    Ok(LinkInfo {
        kind: l.kind,
        between: [from, Body::Solid(node.on)],
        names: l.between.clone(),
        point: node.point,
        basis: node.axis.0,
        axis: node.axis.1,
        components,
        friction,
        coulomb,
        spring,
        pitch,
        law,
    })
}

/// Coulomb's law of a contact, read with this backend's parser: the coefficient a constant of
/// pure numbers (each parameter an angle, of unit `1` or `rad`, or of no unit given), not a
/// negative number; T and N the unknowns of the components along the sliding direction and
/// the normal.
fn law(
    (spec, m): (&SpecFile, &NumericModel),
    (l, path): (&LinkSpec, &str),
    contact: crate::resolve::Contact,
    components: &[(usize, usize)],
) -> Result<LawInfo, NumericError> {
    let c = l
        .contact_friction
        .as_ref()
        .expect("a link with Coulomb's law");
    let field = format!("{path}.contact_friction.coefficient");
    let coefficient =
        (m.names().parse(&c.coefficient, Context::Constant)).map_err(|e| spec_err(&field, e))?;
    let mut used = BTreeSet::new();
    expr::params_in(&coefficient, &mut used);
    for p in &used {
        let name = &m.params[*p].name;
        let Some(given) = spec.parameters.iter().find(|q| &q.name == name) else {
            continue;
        };
        let pure = given.kind == crate::wire::ParameterKind::Angle
            || given
                .unit
                .as_deref()
                .is_none_or(|u| matches!(u.trim(), "1" | "rad"));
        if !pure {
            let why = format!("a friction coefficient is a pure number: `{name}` has a unit");
            return Err(spec_err(field, why));
        }
    }
    if used.is_empty() {
        let env = Env {
            params: &[],
            coords: &[],
            rates: &[],
            frames: &[],
            time: 0.0,
        };
        if expr::eval_scalar(&coefficient, &env).is_ok_and(|f: f64| f < 0.0) {
            return Err(spec_err(field, "a friction coefficient is not negative"));
        }
    }
    let unknown = |axis: usize| {
        let found = components.iter().find(|(k, _)| *k == axis);
        found.map(|(_, u)| *u).expect("the link transmits T and N")
    };
    let sign = l.sign_parameter().expect("a link with friction");
    Ok(LawInfo {
        coefficient,
        sign: m.param_index[&sign],
        unknowns: [unknown(contact.tangent), unknown(contact.normal)],
        tangent: contact.tangent,
        normal: contact.normal,
    })
}

/// A given action: its sides and point as resolved, its expressions read with this backend's
/// parser, its own unknowns entering linearly.
fn given(
    m: &NumericModel,
    (a, path): (&ActionSpec, &str),
    node: &ActionNode,
    local: BTreeMap<String, usize>,
) -> Result<ActionInfo, NumericError> {
    let parse = |text: &Option<String>, field: &str| -> Result<Option<Node>, NumericError> {
        let Some(text) = text else { return Ok(None) };
        let at = format!("{path}.{field}");
        let node = (m.names().parse_with(text, Context::Action, &local))
            .map_err(|e| spec_err(at.clone(), e))?;
        match expr::unknown_degree(&node) {
            Ok(deg) if deg <= 1 => Ok(Some(node)),
            Ok(_) => Err(spec_err(
                at,
                "the unknowns enter linearly: a term holds at most one unknown, once",
            )),
            Err(e) => Err(spec_err(at, format!("the unknowns enter linearly: {e}"))),
        }
    };
    let resultant = parse(&a.resultant, "resultant")?;
    let moment = parse(&a.moment, "moment")?;
    let mut used = BTreeSet::new();
    for n in resultant.iter().chain(&moment) {
        expr::unknowns_in(n, &mut used);
    }
    let from = match node.from {
        Side::Ground => Body::Frame(0),
        Side::Solid(k) => Body::Solid(k),
    };
    Ok(ActionInfo {
        names: [a.name.clone(), a.on.clone(), a.from.clone()],
        from,
        on: Body::Solid(node.on),
        point: node.point,
        resultant,
        moment,
        unknowns: used.into_iter().collect(),
    })
}

/// Each contact under Coulomb's law slides along its tangent at one of the states `vals` at
/// least, and never across it (along the normal's and the tangent's third axis): its sliding
/// velocity V(P,2/1), from this backend's kinematics, refused at the link's place otherwise.
pub(in crate::numeric) fn validate_sliding(
    m: &NumericModel,
    vals: &[Values],
) -> Result<(), NumericError> {
    for (i, l) in m.dynamics.links.iter().enumerate() {
        let Some(law) = &l.law else { continue };
        let [fa, fb] = l.between.map(|b| body_frame(m, b));
        let (mut along, mut across, mut size) = (0.0_f64, 0.0_f64, 0.0_f64);
        for v in vals {
            let st = kin::state(m, v)?;
            let rb = st.rot0(l.basis);
            let w = kin::point_motion(&st, l.point, fb, fa)[0];
            along = along.max(w.dot(&rb.column(law.tangent)).abs());
            across = across.max(w.dot(&rb.column(3 - law.tangent - law.normal)).abs());
            size = size.max(w.norm());
        }
        let path = format!("links[{i}].contact_friction");
        if along <= 1e-9 * size.max(1.0) {
            let why = "the sliding velocity along the tangent is zero: nothing slides";
            return Err(spec_err(path, why));
        }
        if across > 1e-9 * size.max(1.0) {
            let why = "the sliding velocity has a component across the tangent";
            return Err(spec_err(path, why));
        }
    }
    Ok(())
}
