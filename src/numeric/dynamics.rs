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

use super::expr::{self, Env, Node};
use super::kin::{self, State, Values};
use super::model::{Context, Names, spec_err};
use super::{NumericError, NumericModel, cloud};
use crate::spec::wire::{LinkKind, SpecFile, TheoremKind};
use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use std::collections::{BTreeMap, BTreeSet};
use std::ops::{Add, Mul, Neg};

/// A coefficient of an unknown below this fraction of the size of the terms of its equation is
/// rounding noise: the unknown does not appear there.
const APPEARS: f64 = 1e-9;
/// A pivot of the row- and column-scaled system below this is a singular system.
const SINGULAR: f64 = 1e-10;

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
    point: usize,
    /// Frame whose basis holds the components.
    basis: usize,
    /// Axis (or normal) letter 0..3 in `basis`, when the kind has one.
    axis: Option<usize>,
    /// Transmitted components (0..3 resultant, 3..6 moment) and their unknowns' indices.
    components: Vec<(usize, usize)>,
    /// Viscous friction coefficient f.
    pub friction: Option<Node>,
    /// Spring.
    pub spring: Option<SpringInfo>,
}

/// A given action {T(from→on)} at a point.
#[derive(Debug, Clone)]
pub(super) struct ActionInfo {
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
pub(super) fn build(spec: &SpecFile, m: &NumericModel) -> Result<Dynamics, NumericError> {
    let names = Names {
        params: &m.param_index,
        coords: &m.coord_index,
        frames: &m.frame_index,
    };
    let mut d = Dynamics::default();

    let body = |name: &str, path: String| -> Result<Body, NumericError> {
        if let Some(s) = m.solid_index.get(name) {
            return Ok(Body::Solid(*s));
        }
        if let Some(f) = m.frame_index.get(name) {
            return Ok(Body::Frame(*f));
        }
        if m.sets.contains_key(name) {
            return Err(spec_err(
                path,
                format!("`{name}` is a set: an action is exerted by and on a solid"),
            ));
        }
        Err(spec_err(path, format!("unknown solid or frame `{name}`")))
    };
    let point = |name: &str, path: String| -> Result<usize, NumericError> {
        m.point_index
            .get(name)
            .copied()
            .ok_or_else(|| spec_err(path, format!("unknown point `{name}`")))
    };
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
        let mut chars = name.chars();
        if !chars.next().is_some_and(|c| c.is_ascii_alphabetic())
            || !chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
            || name.len() > 32
        {
            return Err(format!(
                "`{name}` is not a valid name: a letter, then letters, digits or `_` (at most 32 \
                 characters)"
            ));
        }
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
    let mut link_names = BTreeSet::new();
    for (i, l) in spec.links.iter().enumerate() {
        let path = format!("links[{i}]");
        if crate::quantity::check_name(&l.name).is_err() {
            return Err(spec_err(
                format!("{path}.name"),
                format!(
                    "link name `{}`: only ASCII letters, digits and `_` are allowed",
                    l.name
                ),
            ));
        }
        if !link_names.insert(l.name.clone()) {
            return Err(spec_err(
                format!("{path}.name"),
                format!("link `{}` is defined twice", l.name),
            ));
        }
        let between = [
            body(&l.between[0], format!("{path}.between[0]"))?,
            body(&l.between[1], format!("{path}.between[1]"))?,
        ];
        if between[0] == between[1] {
            return Err(spec_err(
                format!("{path}.between"),
                "a link joins two different solids",
            ));
        }
        let p = point(&l.point, format!("{path}.point"))?;
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
            let name = format!("{}{}", letters[k], l.name);
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
            point: p,
            basis,
            axis: axis.map(|x| x.1),
            components,
            friction,
            spring,
        });
    }

    // Given actions.
    for (i, a) in spec.actions.iter().enumerate() {
        let path = format!("actions[{i}]");
        let from = body(&a.from, format!("{path}.from"))?;
        let on = body(&a.on, format!("{path}.on"))?;
        if from == on {
            return Err(spec_err(
                format!("{path}.on"),
                "an action is exerted by one solid on another",
            ));
        }
        let p = point(&a.point, format!("{path}.point"))?;
        let mut local = BTreeMap::new();
        for (k, u) in a.unknowns.iter().enumerate() {
            free_name(u).map_err(|e| spec_err(format!("{path}.unknowns[{k}]"), e))?;
            let idx = match d.unknown_index.get(u) {
                Some(idx) => *idx,
                None => {
                    d.unknown_index.insert(u.clone(), d.unknowns.len());
                    d.unknowns.push(u.clone());
                    d.unknowns.len() - 1
                }
            };
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
            from,
            on,
            point: p,
            resultant,
            moment,
            unknowns: used.into_iter().collect(),
        });
    }

    // The declared equations.
    let mut eoms = BTreeMap::new();
    for (i, t) in spec.pfd.iter().enumerate() {
        let path = format!("pfd[{i}]");
        if t.isolate == spec.ground {
            return Err(spec_err(
                format!("{path}.isolate"),
                format!("`{}` is the ground: it is never isolated", t.isolate),
            ));
        }
        let solids = if let Some(s) = m.solid_index.get(&t.isolate) {
            vec![*s]
        } else if let Some(list) = m.sets.get(&t.isolate) {
            list.clone()
        } else {
            return Err(spec_err(
                format!("{path}.isolate"),
                format!("unknown solid or set `{}`", t.isolate),
            ));
        };
        let moment = t.theorem == TheoremKind::Moment;
        let point = match (&t.point, moment) {
            (Some(p), _) => point(p, format!("{path}.point"))?,
            (None, false) => 0,
            (None, true) => {
                return Err(spec_err(
                    format!("{path}.point"),
                    "the moment theorem is applied at a point",
                ));
            }
        };
        let on = vector(&t.on, format!("{path}.on"))?;
        let eom = match &t.eom {
            None => None,
            Some(q) => {
                let c = *m.coord_index.get(q).ok_or_else(|| {
                    spec_err(format!("{path}.eom"), format!("unknown coordinate `{q}`"))
                })?;
                if let Some(j) = eoms.insert(c, i) {
                    return Err(spec_err(
                        format!("{path}.eom"),
                        format!("pfd[{j}] is already the equation of motion of `{q}`"),
                    ));
                }
                Some(c)
            }
        };
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

/// c + Σ uₖ aₖ: a scalar or a vector affine in the unknowns u.
#[derive(Debug, Clone)]
struct Lin<T> {
    c: T,
    a: Vec<T>,
}

impl<T> Lin<T>
where
    T: Copy + Add<Output = T> + Neg<Output = T> + Mul<f64, Output = T>,
{
    fn constant(c: T, zero: T, n: usize) -> Lin<T> {
        Lin {
            c,
            a: vec![zero; n],
        }
    }

    fn add(&mut self, other: &Lin<T>) {
        self.c = self.c + other.c;
        for (x, y) in self.a.iter_mut().zip(&other.a) {
            *x = *x + *y;
        }
    }

    fn neg(&self) -> Lin<T> {
        self.map(|x| -*x)
    }

    /// Applies a linear map to the constant and every coefficient.
    fn map<U>(&self, f: impl Fn(&T) -> U) -> Lin<U> {
        Lin {
            c: f(&self.c),
            a: self.a.iter().map(&f).collect(),
        }
    }
}

impl Lin<Vector3<f64>> {
    /// The largest norm of its constant and coefficients.
    fn size(&self) -> f64 {
        self.a.iter().fold(self.c.norm(), |s, v| s.max(v.norm()))
    }
}

/// An action torsor {T(from→on)} at a point (ground components and position).
#[derive(Debug, Clone)]
struct Term {
    from: Body,
    on: Body,
    point: Vector3<f64>,
    resultant: Lin<Vector3<f64>>,
    moment: Lin<Vector3<f64>>,
}

impl Term {
    /// {T(on→from)} = −{T(from→on)}.
    fn reaction(&self) -> Term {
        Term {
            from: self.on,
            on: self.from,
            point: self.point,
            resultant: self.resultant.neg(),
            moment: self.moment.neg(),
        }
    }
}

fn eval_err(what: String) -> impl Fn(String) -> NumericError {
    move |message| NumericError::Evaluation {
        what: what.clone(),
        message,
    }
}

fn body_frame(m: &NumericModel, b: Body) -> usize {
    match b {
        Body::Solid(s) => m.solids[s].frame,
        Body::Frame(f) => f,
    }
}

/// Evaluates a constant scalar.
fn constant(node: &Node, vals: &Values, what: impl Fn() -> String) -> Result<f64, NumericError> {
    expr::eval_scalar(node, &vals.constants()).map_err(eval_err(what()))
}

/// g⃗ in ground components (zero when gravity is neglected).
fn gravity(m: &NumericModel, st: &State, vals: &Values) -> Result<Vector3<f64>, NumericError> {
    let Some(node) = &m.dynamics.gravity else {
        return Ok(Vector3::zeros());
    };
    let frames: Vec<Matrix3<f64>> = (0..m.frames.len()).map(|f| st.rot0(f)).collect();
    let env = Env {
        params: &vals.params,
        coords: &[],
        rates: &[],
        frames: &frames,
    };
    expr::eval_vector(node, &env).map_err(eval_err("gravity".into()))
}

/// Every declared action (links and given actions) at the sampled instant, each followed by
/// its reaction.
fn terms(m: &NumericModel, st: &State, vals: &Values) -> Result<Vec<Term>, NumericError> {
    let dy = &m.dynamics;
    let n = dy.unknowns.len();
    let zero = Lin::constant(Vector3::zeros(), Vector3::zeros(), n);
    let mut out = Vec::new();
    for (i, l) in dy.links.iter().enumerate() {
        let rb = st.rot0(l.basis);
        let mut resultant = zero.clone();
        let mut moment = zero.clone();
        for (k, idx) in &l.components {
            let e = rb.column(k % 3).into_owned();
            if *k < 3 {
                resultant.a[*idx] = e;
            } else {
                moment.a[*idx] = e;
            }
        }
        let [fa, fb] = l.between.map(|b| body_frame(m, b));
        let u = rb.column(l.axis.unwrap_or(0)).into_owned();
        let slider = l.kind == LinkKind::Slider;
        if let Some(f) = &l.friction {
            let f = constant(f, vals, || format!("friction of links[{i}]"))?;
            if slider {
                let [v, _] = kin::point_motion(st, l.point, fb, fa);
                resultant.c -= u * (f * v.dot(&u));
            } else {
                let w = kin::omega(st, fb, fa);
                moment.c -= u * (f * w.dot(&u));
            }
        }
        if let Some(s) = &l.spring {
            let k = constant(&s.stiffness, vals, || {
                format!("stiffness of the spring of links[{i}]")
            })?;
            let q0 = match &s.free {
                Some(q0) => constant(q0, vals, || {
                    format!("free value of the spring of links[{i}]")
                })?,
                None => 0.0,
            };
            let push = u * (-k * (vals.coords[s.coord][0] - q0));
            if slider {
                resultant.c += push;
            } else {
                moment.c += push;
            }
        }
        let t = Term {
            from: l.between[0],
            on: l.between[1],
            point: st.pos0(l.point),
            resultant,
            moment,
        };
        out.push(t.reaction());
        out.push(t);
    }
    // Given actions: the part free of unknowns, and each unknown's coefficient exactly (the
    // expressions are affine in the unknowns: checked when the model is built).
    let frames: Vec<Matrix3<f64>> = (0..m.frames.len()).map(|f| st.rot0(f)).collect();
    let coords: Vec<f64> = vals.coords.iter().map(|c| c[0]).collect();
    let rates: Vec<[f64; 2]> = vals.coords.iter().map(|c| [c[1], c[2]]).collect();
    let env = Env {
        params: &vals.params,
        coords: &coords,
        rates: &rates,
        frames: &frames,
    };
    for (i, a) in dy.actions.iter().enumerate() {
        let mut parts = [zero.clone(), zero.clone()];
        for (part, (node, field)) in parts
            .iter_mut()
            .zip([(&a.resultant, "resultant"), (&a.moment, "moment")])
        {
            let Some(node) = node else { continue };
            let run = |n: &Node| {
                expr::eval_vector(n, &env).map_err(eval_err(format!("{field} of actions[{i}]")))
            };
            part.c = run(&expr::without_unknowns(node))?;
            for k in &a.unknowns {
                part.a[*k] = run(&expr::unknown_coefficient(node, *k))?;
            }
        }
        let [resultant, moment] = parts;
        let t = Term {
            from: a.from,
            on: a.on,
            point: st.pos0(a.point),
            resultant,
            moment,
        };
        out.push(t.reaction());
        out.push(t);
    }
    Ok(out)
}

/// The residual of a declared equation, dynamic side minus actions, and the size of the terms
/// it sums (for the rounding noise).
fn residual(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    terms: &[Term],
    g: &Vector3<f64>,
    t: &TheoremInfo,
) -> Result<(Lin<f64>, f64), NumericError> {
    let n = m.dynamics.unknowns.len();
    let member = |b: Body| matches!(b, Body::Solid(s) if t.solids.contains(&s));
    let p = st.pos0(t.point);
    let u = st.rot0(t.on.0).column(t.on.1).into_owned();
    let [_, _, rd, delta] = kin::kinetic(m, st, vals, &t.solids, 0, t.point)?;
    let dynamic = if t.moment { delta } else { rd };
    let mut size = dynamic.norm();
    let mut sum = Lin::constant(Vector3::zeros(), Vector3::zeros(), n);
    for term in terms {
        if !member(term.on) || member(term.from) {
            continue;
        }
        let part = if t.moment {
            let arm = term.point - p;
            let mut at_p = term.moment.clone();
            at_p.add(&term.resultant.map(|r| arm.cross(r)));
            at_p
        } else {
            term.resultant.clone()
        };
        size = size.max(part.size());
        sum.add(&part);
    }
    // Gravity on every point mass of every member.
    if g.norm() > 0.0 {
        for s in &t.solids {
            let f = m.solids[*s].frame;
            let (rf, of) = (st.rot0(f), st.origin(f).map(|x| x.re));
            for (mk, local) in cloud::solid_cloud(m, st, vals, *s)? {
                let weight = g * mk;
                let part = if t.moment {
                    (of + rf * local - p).cross(&weight)
                } else {
                    weight
                };
                size = size.max(part.norm());
                sum.c += part;
            }
        }
    }
    let actions = sum.map(|v| v.dot(&u));
    let mut r = actions.neg();
    r.c += dynamic.dot(&u);
    Ok((r, size))
}

/// The solved PFD at one sample.
struct Solution {
    /// Value of each unknown that the equations without `eom` determine.
    values: Vec<Option<f64>>,
    /// Each declared equation's residual, coefficients of absent unknowns set to zero.
    residuals: Vec<Lin<f64>>,
}

/// The value of the unknown `name` at the sample, solved from the equations without `eom`.
pub(super) fn unknown(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    name: &str,
) -> Result<f64, NumericError> {
    let fail = |message: String| NumericError::Quantity {
        quantity: name.to_string(),
        message,
    };
    let dy = &m.dynamics;
    let Some(k) = dy.unknown_index.get(name) else {
        return Err(fail(format!(
            "`{name}` is not an unknown of the PFD (its unknowns: {})",
            if dy.unknowns.is_empty() {
                "none".to_string()
            } else {
                dy.unknowns.join(", ")
            }
        )));
    };
    let solution = solve(m, st, vals)?.map_err(fail)?;
    solution.values[*k].ok_or_else(|| {
        fail(format!(
            "the unknown `{name}` appears in no equation of the PFD without eom: nothing \
             determines it"
        ))
    })
}

/// The residual of the equation of motion of coordinate `q` at the sample (q̈ the sample's),
/// the unknowns solved from the equations without `eom` substituted.
pub(super) fn eom(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    q: &str,
) -> Result<f64, NumericError> {
    let fail = |message: String| NumericError::Quantity {
        quantity: format!("eom({q})"),
        message,
    };
    let dy = &m.dynamics;
    let Some(c) = m.coord_index.get(q) else {
        return Err(fail(format!("`{q}` is not a time coordinate")));
    };
    let Some(i) = dy.theorems.iter().position(|t| t.eom == Some(*c)) else {
        return Err(fail(format!("no equation of the PFD has eom `{q}`")));
    };
    let solution = solve(m, st, vals)?.map_err(fail)?;
    let r = &solution.residuals[i];
    let mut x = r.c;
    for (k, a) in r.a.iter().enumerate() {
        if *a == 0.0 {
            continue;
        }
        let v = solution.values[k].ok_or_else(|| {
            fail(format!(
                "its equation still holds the unknown `{}`, which the equations without eom \
                 do not determine",
                dy.unknowns[k]
            ))
        })?;
        x += a * v;
    }
    Ok(x)
}

/// Builds every declared equation at the sample and solves those without `eom`: the outer
/// error is an evaluation failure, the inner one a system that cannot be solved.
fn solve(
    m: &NumericModel,
    st: &State,
    vals: &Values,
) -> Result<Result<Solution, String>, NumericError> {
    let dy = &m.dynamics;
    let n = dy.unknowns.len();
    let terms = terms(m, st, vals)?;
    let g = gravity(m, st, vals)?;
    let mut residuals = Vec::with_capacity(dy.theorems.len());
    for t in &dy.theorems {
        let (mut r, size) = residual(m, st, vals, &terms, &g, t)?;
        for a in &mut r.a {
            if a.abs() <= APPEARS * size {
                *a = 0.0;
            }
        }
        residuals.push(r);
    }
    let rows: Vec<usize> = (0..dy.theorems.len())
        .filter(|i| dy.theorems[*i].eom.is_none())
        .collect();
    let cols: Vec<usize> = (0..n)
        .filter(|k| rows.iter().any(|i| residuals[*i].a[*k] != 0.0))
        .collect();
    let listed = |ks: &[usize]| -> String {
        if ks.is_empty() {
            return "none".into();
        }
        ks.iter()
            .map(|k| dy.unknowns[*k].as_str())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if rows.len() != cols.len() {
        return Ok(Err(format!(
            "the PFD's equations without eom must determine the unknowns that appear in them: \
             {} equation(s) for {} unknown(s) ({})",
            rows.len(),
            cols.len(),
            listed(&cols)
        )));
    }
    let mut values = vec![None; n];
    if !rows.is_empty() {
        let k = rows.len();
        let mut a = DMatrix::from_fn(k, k, |r, c| residuals[rows[r]].a[cols[c]]);
        let mut b = DVector::from_fn(k, |r, _| -residuals[rows[r]].c);
        // Scale rows then columns to unit largest entries, so that the pivot test is
        // independent of units.
        for r in 0..k {
            let s = a.row(r).amax();
            if s > 0.0 {
                a.row_mut(r).scale_mut(1.0 / s);
                b[r] /= s;
            }
        }
        let col_scale: Vec<f64> = (0..k).map(|c| a.column(c).amax()).collect();
        for (c, s) in col_scale.iter().enumerate() {
            a.column_mut(c).scale_mut(1.0 / s);
        }
        let lu = a.lu();
        let pivot = lu.u().diagonal().amin();
        let singular = || {
            format!(
                "the PFD's equations without eom are singular at this sample: they do not \
                 determine their unknowns ({})",
                listed(&cols)
            )
        };
        if pivot.is_nan() || pivot <= SINGULAR {
            return Ok(Err(singular()));
        }
        let Some(y) = lu.solve(&b) else {
            return Ok(Err(singular()));
        };
        for (c, col) in cols.iter().enumerate() {
            values[*col] = Some(y[c] / col_scale[c]);
        }
    }
    Ok(Ok(Solution { values, residuals }))
}
