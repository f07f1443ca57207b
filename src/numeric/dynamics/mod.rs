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
//!   from the relative motion (Ω(b/a), V(P ∈ b/a)) and the coordinate's value;
//! - a given action is evaluated from its expressions; its unknowns enter linearly (checked on
//!   the expression's structure), and their coefficients are read exactly with dual numbers;
//! - every action {T(a→b)} comes with its reaction {T(b→a)} = −{T(a→b)}; isolating S keeps the
//!   ones received by a member of S from a non-member, plus gravity on every member;
//! - each declared equation is a residual, dynamic side minus actions, affine in the unknowns.
//!
//! The equations without `eom` are solved with nalgebra's LU for the unknowns that appear in
//! them; an `eom` equation's residual, with those values substituted, is the equation of
//! motion's value at the sample (q̈ is the sample's).

use super::checks::identifier;
use super::expr::{self, Env, Node};
use super::kin::{self, State, Values};
use super::model::{Context, spec_err};
use super::{NumericError, NumericModel, cloud};
use crate::resolve::{Resolved, Side};
use crate::wire::{LinkKind, SpecFile, TheoremKind};
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
    /// Axis (or normal) letter 0..3 in `basis`, when the kind has one.
    axis: Option<usize>,
    /// Transmitted components (0..3 resultant, 3..6 moment) and their unknowns' indices.
    components: Vec<(usize, usize)>,
    /// Viscous friction coefficient f.
    pub friction: Option<Node>,
    /// Dry friction: its magnitude C and the index of the parameter ε that the samples set
    /// to the sign of the relative rate.
    pub coulomb: Option<(Node, usize)>,
    /// Spring.
    pub spring: Option<SpringInfo>,
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
    /// Moment theorem (else resultant theorem).
    moment: bool,
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
/// `d` the line direction.
fn transmitted(kind: LinkKind, a: usize, d: usize) -> [bool; 6] {
    let mut t = [false; 6];
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    match kind {
        LinkKind::Fixed => t = [true; 6],
        LinkKind::Pivot => {
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

fn kind_name(kind: LinkKind) -> &'static str {
    match kind {
        LinkKind::Fixed => "fixed",
        LinkKind::Pivot => "pivot",
        LinkKind::Slider => "slider",
        LinkKind::PivotSlider => "pivot_slider",
        LinkKind::Ball => "ball",
        LinkKind::Plane => "plane",
        LinkKind::Annular => "annular",
        LinkKind::Line => "line",
        LinkKind::Point => "point",
    }
}

/// Resolves the spec's `gravity`, `links`, `actions` and `pfd` against a model whose other
/// parts are built. Errors name the JSON path.
pub(super) fn build(
    spec: &SpecFile,
    m: &NumericModel,
    trees: &Resolved,
) -> Result<Dynamics, NumericError> {
    let names = m.names();
    let mut d = Dynamics::default();

    let vector = |name: &str, path: String| -> Result<(usize, usize), NumericError> {
        names
            .basis_vector(name.trim())
            .ok_or_else(|| spec_err(path, format!("`{name}` is not a basis vector such as z0")))
    };
    let constant = |text: &str, path: String| -> Result<Node, NumericError> {
        names
            .parse(text, Context::Constant)
            .map_err(|e| spec_err(path, e))
    };
    // A name may become an unknown only if it means nothing else in expressions.
    let free_name = |name: &str| -> Result<(), String> {
        identifier(name)?;
        if name == expr::PI_NAME {
            return Err(format!("`{name}` is π"));
        }
        if m.param_index.contains_key(name) {
            return Err(format!(
                "`{name}` is a parameter: an unknown is solved for, not given"
            ));
        }
        if m.coord_index.contains_key(name) {
            return Err(format!("`{name}` is a time coordinate"));
        }
        if names.basis_vector(name).is_some() {
            return Err(format!("`{name}` is a basis vector"));
        }
        Ok(())
    };

    // Gravity: a vector constant in the ground frame.
    if let Some(g) = &spec.gravity {
        let node = names
            .parse(g, Context::ConstantVector)
            .map_err(|e| spec_err("gravity", e))?;
        let mut used = BTreeSet::new();
        expr::frames_in(&node, &mut used);
        for f in used {
            let mut k = f;
            while k != 0 {
                if let Some((_, _, angle)) = &m.frames[k].rotation
                    && expr::depends_on_time(angle)
                {
                    return Err(spec_err(
                        "gravity",
                        format!(
                            "gravity is constant in the ground frame: the basis of frame {} \
                             turns with time",
                            m.frames[f].name
                        ),
                    ));
                }
                k = m.frames[k].parent;
            }
        }
        d.gravity = Some(node);
    }

    // Links.
    let letters = ['X', 'Y', 'Z', 'L', 'M', 'N'];
    let mut joined: Vec<(Body, Body)> = Vec::new();
    for ((i, l), link) in spec.links.iter().enumerate().zip(&trees.links) {
        let path = format!("links[{i}]");
        // Named, between two different solids (or the ground and a solid), as resolved.
        let between = link.between.map(|s| match s {
            Side::Ground => Body::Frame(0),
            Side::Solid(k) => Body::Solid(k),
        });
        // A closed kinematic loop needs its closure; links in parallel between the same two
        // solids (two bearings) are one connection.
        let parallel = joined
            .iter()
            .any(|&(a, b)| [a, b] == between || [b, a] == between);
        if spec.closures.is_empty() && !parallel && connected(&joined, between[0], between[1]) {
            return Err(spec_err(
                format!("{path}.between"),
                format!(
                    "the link {} closes a kinematic loop: declare its closure (`closures`)",
                    l.name
                ),
            ));
        }
        joined.push((between[0], between[1]));
        let p = link.point;
        let axis = l
            .axis
            .as_deref()
            .map(|a| vector(a, format!("{path}.axis")))
            .transpose()?;
        let kind = l.kind;
        if axis.is_none() && !matches!(kind, LinkKind::Fixed | LinkKind::Ball) {
            return Err(spec_err(
                format!("{path}.axis"),
                format!(
                    "a {} link needs its axis (or normal), a basis vector such as z0",
                    kind_name(kind)
                ),
            ));
        }
        let basis = axis.map_or(0, |a| a.0);
        let a = axis.map_or(0, |a| a.1);
        let mut dir = 0;
        match (&l.direction, kind) {
            (Some(text), LinkKind::Line) => {
                let (f, k) = vector(text, format!("{path}.direction"))?;
                if f != basis || k == a {
                    return Err(spec_err(
                        format!("{path}.direction"),
                        format!(
                            "the line direction is another basis vector of the normal's basis \
                             B{}",
                            m.frames[basis].name
                        ),
                    ));
                }
                dir = k;
            }
            (None, LinkKind::Line) => {
                return Err(spec_err(
                    format!("{path}.direction"),
                    "a line link needs its line direction, a basis vector of its normal's basis",
                ));
            }
            (Some(_), _) => {
                return Err(spec_err(
                    format!("{path}.direction"),
                    "only a line link has a direction",
                ));
            }
            (None, _) => {}
        }
        let turns_or_slides = matches!(kind, LinkKind::Pivot | LinkKind::Slider);
        let friction = match &l.friction {
            None => None,
            Some(_) if !turns_or_slides => {
                return Err(spec_err(
                    format!("{path}.friction"),
                    "viscous friction is given for a pivot or a slider",
                ));
            }
            Some(f) => Some(constant(f, format!("{path}.friction"))?),
        };
        let coulomb = match (&l.coulomb, l.sign_parameter()) {
            (Some(_), _) if !turns_or_slides => {
                return Err(spec_err(
                    format!("{path}.coulomb"),
                    "dry friction is given for a pivot or a slider",
                ));
            }
            (Some(c), Some(sign)) => {
                let eps = *m.param_index.get(&sign).ok_or_else(|| {
                    spec_err(format!("{path}.coulomb"), format!("no parameter `{sign}`"))
                })?;
                Some((constant(c, format!("{path}.coulomb"))?, eps))
            }
            _ => None,
        };
        let spring = match &l.spring {
            None => None,
            Some(_) if !turns_or_slides => {
                return Err(spec_err(
                    format!("{path}.spring"),
                    "a spring is given for a pivot or a slider",
                ));
            }
            Some(s) => {
                let coord = *m.coord_index.get(&s.coordinate).ok_or_else(|| {
                    spec_err(
                        format!("{path}.spring.coordinate"),
                        format!("unknown coordinate `{}`", s.coordinate),
                    )
                })?;
                Some(SpringInfo {
                    coord,
                    stiffness: constant(&s.stiffness, format!("{path}.spring.stiffness"))?,
                    free: s
                        .free
                        .as_deref()
                        .map(|q0| constant(q0, format!("{path}.spring.free")))
                        .transpose()?,
                })
            }
        };
        let mut components = Vec::new();
        for (k, t) in transmitted(kind, a, dir).into_iter().enumerate() {
            if !t {
                continue;
            }
            // X01 for the link 01, X_A for the link named after its centre A.
            let sep = if l
                .name
                .chars()
                .next()
                .is_some_and(|c| c.is_ascii_alphabetic())
            {
                "_"
            } else {
                ""
            };
            let name = format!("{}{sep}{}", letters[k], l.name);
            free_name(&name).map_err(|e| {
                spec_err(
                    format!("{path}.name"),
                    format!("the link's unknown {name}: {e}"),
                )
            })?;
            if d.unknown_index.contains_key(&name) {
                return Err(spec_err(
                    format!("{path}.name"),
                    format!("the link's unknown {name} is already an unknown of another link"),
                ));
            }
            d.unknown_index.insert(name.clone(), d.unknowns.len());
            components.push((k, d.unknowns.len()));
            d.unknowns.push(name);
        }
        d.links.push(LinkInfo {
            kind,
            between,
            names: l.between.clone(),
            point: p,
            basis,
            axis: axis.map(|x| x.1),
            components,
            friction,
            coulomb,
            spring,
        });
    }

    // Given actions.
    for ((i, a), action) in spec.actions.iter().enumerate().zip(&trees.actions) {
        let path = format!("actions[{i}]");
        // Named, exerted by a solid (or the ground) on another solid, as resolved.
        let from = match action.from {
            Side::Ground => Body::Frame(0),
            Side::Solid(k) => Body::Solid(k),
        };
        let on = Body::Solid(action.on);
        let p = action.point;
        let mut local = BTreeMap::new();
        for (k, u) in a.unknowns.iter().enumerate() {
            free_name(u).map_err(|e| spec_err(format!("{path}.unknowns[{k}]"), e))?;
            // One name, one unknown: an action's unknown named like a link's component (X01)
            // or like another action's would silently merge two different forces.
            if d.unknown_index.contains_key(u) {
                return Err(spec_err(
                    format!("{path}.unknowns[{k}]"),
                    format!("the unknown `{u}` is declared twice"),
                ));
            }
            d.unknown_index.insert(u.clone(), d.unknowns.len());
            d.unknowns.push(u.clone());
            let idx = d.unknowns.len() - 1;
            local.insert(u.clone(), idx);
        }
        let parse = |text: &Option<String>, field: &str| -> Result<Option<Node>, NumericError> {
            let Some(text) = text else { return Ok(None) };
            let at = format!("{path}.{field}");
            let node = names
                .parse_with(text, Context::Action, &local)
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
        d.actions.push(ActionInfo {
            names: [a.name.clone(), a.on.clone(), a.from.clone()],
            from,
            on,
            point: p,
            resultant,
            moment,
            unknowns: used.into_iter().collect(),
        });
    }

    // The declared equations: what each isolates, its point, its vector and its coordinate,
    // as resolved.
    for (t, node) in spec.pfd.iter().zip(&trees.theorems) {
        let solids = node.isolate.clone();
        let moment = t.theorem == TheoremKind::Moment;
        let point = node.point.unwrap_or(0);
        let (on, eom) = (node.on, node.eom);
        d.theorems.push(TheoremInfo {
            solids,
            moment,
            point,
            on,
            eom,
        });
    }
    Ok(d)
}

/// Whether `a` and `b` are already connected through the links `joined` (breadth-first).
fn connected(joined: &[(Body, Body)], a: Body, b: Body) -> bool {
    let mut reached = vec![a];
    let mut k = 0;
    while k < reached.len() {
        let n = reached[k];
        for &(x, y) in joined {
            let other = if x == n {
                y
            } else if y == n {
                x
            } else {
                continue;
            };
            if !reached.contains(&other) {
                reached.push(other);
            }
        }
        k += 1;
    }
    reached.contains(&b)
}
