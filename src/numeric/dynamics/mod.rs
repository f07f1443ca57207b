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

mod solve;
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
}

/// Components a link transmits (0..3 resultant, 3..6 moment, in its basis), `a` the axis and
/// `d` a line contact's direction.
pub(super) fn transmitted(kind: LinkKind, a: usize, d: Option<usize>) -> [bool; 6] {
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
        d.links
            .push(link(m, (l, &path), node, unknowns.links[i].clone())?);
    }
    for (i, (a, node)) in spec.actions.iter().zip(&trees.actions).enumerate() {
        // Its own unknowns, the only ones its expressions may name.
        let own = (a.unknowns.iter().cloned()).zip(unknowns.actions[i].iter().copied());
        let path = format!("actions[{i}]");
        d.actions.push(given(m, (a, &path), node, own.collect())?);
    }
    d.unknown_index = (unknowns.names.iter().enumerate())
        .map(|(k, n)| (n.clone(), k))
        .collect();
    d.unknowns = unknowns.names;
    // The declared equations: what each isolates, its point, its vector and its coordinate,
    // as resolved.
    for (t, node) in spec.pfd.iter().zip(&trees.theorems) {
        d.theorems.push(TheoremInfo {
            solids: node.isolate.clone(),
            moment: t.theorem == TheoremKind::Moment,
            energy: t.theorem == TheoremKind::Energy,
            point: node.point.unwrap_or(0),
            on: node.on,
            eom: node.eom,
        });
    }
    Ok(d)
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
    m: &NumericModel,
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
