//! The structured form of the dynamic quantities of nested sets and of the equations of motion:
//! each set's dynamic resultant and moment named once, from its own solids and the named
//! torsors of the sets it contains, moved by the course's change of point,
//! δ(A, E) = δ(B, E) + AB ∧ Rd(E).
//!
//! The sets come from the request: the theorems that give an equation of motion and the
//! dynamic quantities asked of a set. A set holding another (E2 = {2} ∪ E3) is its own solids
//! plus that set's torsor: Rd(E2) = m2 Γ(G2) + Rd(E3), δ(P1, E2) = δ(P1, 2) + δ(P2, E3) +
//! P1P2 ∧ Rd(E3). Each set's components are named in one basis (that of its first request's
//! projection, else its first solid's), so a chain of n links is n short definitions where the
//! expanded form repeats every downstream sum in every equation. The equations of motion then
//! split, over the same names, into M(q) q̈ + h(q, q̇) = Q(q) ([`NamedMotion`]).
//!
//! ```
//! use torseur::pfd::structured::Structured;
//! use torseur::quantity::Quantity;
//! let m = torseur::spec::load("derivations/chain/planar_3.json").unwrap();
//! let qs: Vec<Quantity> = m.quantities().to_vec();
//! let s = Structured::of(&m, &qs).unwrap();
//! // Every equation, expanded back, is the engine's.
//! let solved = torseur::pfd::solve(&m).unwrap();
//! let mut memo = Vec::new();
//! for (q, v) in &s.values {
//!     if let torseur::quantity::QuantityKind::Eom(c) = &q.kind {
//!         assert_eq!(s.program.expand(v, &mut memo), solved.eom[c]);
//!     }
//! }
//! ```

use super::named::{Lin, Program};
use super::{Action, external_actions, unknowns_in};
use crate::expr::{CoordId, Expr, VarRole};
use crate::frame::{Axis, FrameId};
use crate::mechanism::{BodyId, Mechanism, Theorem};
use crate::point::PointId;
use crate::quantity::{Quantity, QuantityKind};
use crate::torsor;
use crate::vector::Vector;
use crate::wire::TheoremKind;

/// Three components over names.
type LinVector = [Lin; 3];

/// The structured values of a request.
#[derive(Debug, Clone)]
pub struct Structured {
    /// The named subexpressions.
    pub program: Program,
    /// Each quantity of the request this form holds, with its value over the names (the
    /// others, which are not dynamic quantities of a set projected on a vector nor equations
    /// of motion from a resultant or moment theorem, are the engine's alone).
    pub values: Vec<(Quantity, Lin)>,
    /// The equations of motion over the names, when the request holds every one of them.
    pub motion: Option<NamedMotion>,
}

/// M(q) q̈ + h(q, q̇) = Q(q) over the names of a [`Structured`] form: the same split as
/// [`super::EquationsOfMotion`] (Mᵢⱼ the coefficient of q̈ⱼ in eom(qᵢ), Q minus the value at
/// rest, h the rest), each entry over the names.
#[derive(Debug, Clone)]
pub struct NamedMotion {
    /// The coordinates, rows and columns.
    pub coordinates: Vec<CoordId>,
    /// M, row by row.
    pub mass: Vec<Vec<Lin>>,
    /// h, the terms that vanish at rest.
    pub velocity_terms: Vec<Lin>,
    /// Q, the generalised forces.
    pub forces: Vec<Lin>,
}

impl NamedMotion {
    /// M and Q − h compiled over the names of `program` (the program the form was built
    /// with): the accelerations at a registry point without expanding anything.
    pub fn compile(&self, program: &Program) -> Result<CompiledMotion, crate::expr::ExprError> {
        let n = self.coordinates.len();
        let rhs: Vec<Lin> = (0..n)
            .map(|i| self.forces[i].sub(&self.velocity_terms[i]))
            .collect();
        let mut vs: Vec<&Lin> = self.mass.iter().flatten().collect();
        vs.extend(rhs.iter());
        Ok(CompiledMotion {
            program: program.compile(&vs)?,
            n,
        })
    }
}

/// [`NamedMotion::compile`]: M and Q − h at a registry point.
pub struct CompiledMotion {
    program: super::named::CompiledProgram,
    n: usize,
}

impl CompiledMotion {
    /// M (row-major) and Q − h at a registry point.
    pub fn evaluate(&mut self, point: &[f64]) -> (nalgebra::DMatrix<f64>, nalgebra::DVector<f64>) {
        let n = self.n;
        let out = self.program.evaluate(point);
        (
            nalgebra::DMatrix::from_row_slice(n, n, &out[..n * n]),
            nalgebra::DVector::from_column_slice(&out[n * n..]),
        )
    }

    /// q̈ = M⁻¹ (Q − h) at a registry point, or None where M is singular.
    pub fn accelerations(&mut self, point: &[f64]) -> Option<nalgebra::DVector<f64>> {
        let (mass, rhs) = self.evaluate(point);
        mass.lu().solve(&rhs)
    }
}

/// A set the request names, its place in the nesting, and its named torsor once built.
struct Node {
    solids: Vec<BodyId>,
    label: String,
    basis: FrameId,
    point: PointId,
    children: Vec<usize>,
    own: Vec<BodyId>,
    torsor: Option<(LinVector, LinVector)>,
}

/// One structured request: a dynamic side on a set, at a point, projected on a vector.
struct Request {
    node: usize,
    moment_at: Option<PointId>,
    on: (FrameId, Axis),
}

impl Structured {
    /// The structured form of the quantities `qs` that have one. `Err` names a set or point
    /// the mechanism does not know (the engine's own derivation reports it better).
    pub fn of(m: &Mechanism, qs: &[Quantity]) -> Result<Structured, String> {
        let mut nodes: Vec<Node> = Vec::new();
        let mut requests: Vec<(usize, Request)> = Vec::new();
        for (i, q) in qs.iter().enumerate() {
            if let Some(r) = request(m, q, &mut nodes)? {
                requests.push((i, r));
            }
        }
        nest(&mut nodes);
        let mut program = Program::new(&m.reg);
        let mut cache = torsor::Cache::default();
        let mut order: Vec<usize> = (0..nodes.len()).collect();
        order.sort_by_key(|&k| nodes[k].solids.len());
        for k in order {
            let t = build(m, &nodes, k, &mut cache, &mut program);
            nodes[k].torsor = Some(t);
        }
        let mut values = Vec::new();
        for (i, r) in &requests {
            let dynamic = side(m, &nodes[r.node], r);
            let v = match &qs[*i].kind {
                QuantityKind::Eom(_) => match eom_actions(m, &nodes[r.node], r) {
                    Some(actions) => dynamic.sub(&Lin::of(actions)),
                    None => continue,
                },
                _ => dynamic,
            };
            values.push((qs[*i].clone(), v));
        }
        let motion = named_motion(m, &mut program, &values);
        Ok(Structured {
            program,
            values,
            motion,
        })
    }

    /// The value of a quantity of the request, if this form holds it.
    pub fn value(&self, q: &Quantity) -> Option<&Lin> {
        self.values.iter().find(|(p, _)| p == q).map(|(_, v)| v)
    }
}

/// The request of one quantity, its set added to `nodes`; None for a quantity this form does
/// not hold.
fn request(m: &Mechanism, q: &Quantity, nodes: &mut Vec<Node>) -> Result<Option<Request>, String> {
    if q.linear || q.basis.is_some() {
        return Ok(None);
    }
    let (label, solids, moment_at, on) = match &q.kind {
        QuantityKind::Eom(c) => {
            let Some(th) = eom_theorem(m, c) else {
                return Ok(None);
            };
            let at = (th.kind == TheoremKind::Moment).then_some(th.point);
            (th.isolate.clone(), th.solids.clone(), at, th.on)
        }
        QuantityKind::DynamicResultant(motion) | QuantityKind::DynamicMoment { motion, .. } => {
            let ground = m.frame_name(m.frames.ground());
            let Some((f, a)) = &q.projection else {
                return Ok(None);
            };
            if motion.reference != ground {
                return Ok(None);
            }
            let solids = m
                .solids_of(&motion.moving)
                .ok_or_else(|| format!("no solid or set `{}`", motion.moving))?;
            let frame = m.frames.find(f).ok_or_else(|| format!("no frame `{f}`"))?;
            let axis = Axis::parse(&a.to_string()).ok_or_else(|| format!("no axis `{a}`"))?;
            let at = match &q.kind {
                QuantityKind::DynamicMoment { point, .. } => Some(
                    m.point(point)
                        .ok_or_else(|| format!("no point `{point}`"))?,
                ),
                _ => None,
            };
            (motion.moving.clone(), solids, at, (frame, axis))
        }
        _ => return Ok(None),
    };
    let mut key = solids.clone();
    key.sort();
    let node = match nodes.iter().position(|n| n.solids == key) {
        Some(k) => k,
        None => {
            let point = moment_at.unwrap_or_else(|| m.body(solids[0]).centre);
            nodes.push(Node {
                solids: key,
                label,
                basis: on.0,
                point,
                children: Vec::new(),
                own: Vec::new(),
                torsor: None,
            });
            nodes.len() - 1
        }
    };
    Ok(Some(Request {
        node,
        moment_at,
        on,
    }))
}

/// The theorem that gives the equation of motion of `c`, when it is a resultant or moment one.
fn eom_theorem<'a>(m: &'a Mechanism, c: &str) -> Option<&'a Theorem> {
    let q = m.reg.coord(c)?;
    m.dynamics
        .theorems
        .iter()
        .find(|th| th.eom == Some(q) && th.kind != TheoremKind::Energy)
}

/// Each set's children: the largest requested sets inside it, disjoint, taken greedily; its
/// own solids are the rest.
fn nest(nodes: &mut [Node]) {
    let mut by_size: Vec<usize> = (0..nodes.len()).collect();
    by_size.sort_by_key(|&k| std::cmp::Reverse(nodes[k].solids.len()));
    for &k in &by_size {
        let mut rest = nodes[k].solids.clone();
        let mut children = Vec::new();
        for &c in &by_size {
            let inner = &nodes[c].solids;
            if c != k
                && inner.len() < nodes[k].solids.len()
                && inner.iter().all(|s| rest.contains(s))
            {
                rest.retain(|s| !inner.contains(s));
                children.push(c);
            }
        }
        nodes[k].children = children;
        nodes[k].own = rest;
    }
}

/// The named Rd(E/R0) and δ(P, E/R0) of a node, in its basis, its children built.
fn build(
    m: &Mechanism,
    nodes: &[Node],
    k: usize,
    cache: &mut torsor::Cache,
    program: &mut Program,
) -> (LinVector, LinVector) {
    let n = &nodes[k];
    let (g0, b, p) = (m.frames.ground(), n.basis, n.point);
    let mut res: [Vec<Expr>; 3] = Default::default();
    let mut mom: [Vec<Expr>; 3] = Default::default();
    for &s in &n.own {
        let pg = m.points.vector(p, m.body(s).centre);
        let (dg, rd) = cache.at_centre(m, s, g0, true);
        let transport = pg.cross(&m.frames, rd);
        let (r, d, t) = (
            rd.express_in(&m.frames, b),
            dg.express_in(&m.frames, b),
            transport.express_in(&m.frames, b),
        );
        for i in 0..3 {
            res[i].push(r[i].clone());
            mom[i].push(d[i].clone());
            mom[i].push(t[i].clone());
        }
    }
    let mut r: LinVector = res.map(|v| Lin::of(Expr::sum(&m.reg, v)));
    let mut d: LinVector = mom.map(|v| Lin::of(Expr::sum(&m.reg, v)));
    for &c in &n.children {
        let child = &nodes[c];
        let (rc, dc) = child.torsor.as_ref().expect("children are built first");
        let rc = convert(m, child.basis, b, rc);
        let dc = convert(m, child.basis, b, dc);
        let arm = m.points.vector(p, child.point).express_in(&m.frames, b);
        let moved = cross(&arm, &rc);
        for i in 0..3 {
            r[i] = r[i].add(&rc[i]);
            d[i] = d[i].add(&dc[i]).add(&moved[i]);
        }
    }
    let ground = m.frame_name(g0);
    let names = |what: &str| -> [String; 3] {
        Axis::ALL.map(|a| format!("{what}.{}", m.frames.vector_name(b, a)))
    };
    let rn = names(&format!("Rd({}/{ground})", n.label));
    let dn = names(&format!("delta({},{}/{ground})", m.point_name(p), n.label));
    let r = name_all(program, rn, r);
    let d = name_all(program, dn, d);
    (r, d)
}

fn name_all(program: &mut Program, names: [String; 3], v: LinVector) -> LinVector {
    let [a, b, c] = v;
    let [na, nb, nc] = names;
    [
        program.named(na, a),
        program.named(nb, b),
        program.named(nc, c),
    ]
}

/// Components in basis `to` of a named vector given in basis `from`.
fn convert(m: &Mechanism, from: FrameId, to: FrameId, v: &LinVector) -> LinVector {
    if from == to {
        return v.clone();
    }
    let p = m.frames.dcm(to, from);
    std::array::from_fn(|i| Lin::combination(&m.reg, (0..3).map(|j| (&p[i][j], &v[j]))))
}

/// a ∧ v of a known vector and a named one, in one basis.
fn cross(a: &[Expr; 3], v: &LinVector) -> LinVector {
    std::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        v[k].scale(&a[j]).sub(&v[j].scale(&a[k]))
    })
}

/// The dynamic side of a request: Rd(E)·u, or δ(A, E)·u = (δ(P, E) + AP ∧ Rd(E))·u.
fn side(m: &Mechanism, n: &Node, r: &Request) -> Lin {
    let (res, mom) = n.torsor.as_ref().expect("built");
    let u = Vector::along(r.on.0, r.on.1, m.reg.one()).express_in(&m.frames, n.basis);
    let v: LinVector = match r.moment_at {
        None => res.clone(),
        Some(a) if a == n.point => mom.clone(),
        Some(a) => {
            let arm = m.points.vector(a, n.point).express_in(&m.frames, n.basis);
            let moved = cross(&arm, res);
            std::array::from_fn(|i| mom[i].add(&moved[i]))
        }
    };
    Lin::combination(&m.reg, (0..3).map(|i| (&u[i], &v[i])))
}

/// The actions' side of an equation of motion, when it holds no unknown of the links (the
/// engine's route solves those; this form then leaves the equation to it).
fn eom_actions(m: &Mechanism, n: &Node, r: &Request) -> Option<Expr> {
    let u = Vector::along(r.on.0, r.on.1, m.reg.one());
    // The request's point is the moment theorem's; none for the resultant theorem.
    let parts: Vec<Expr> = external_actions(m, &n.solids)
        .into_iter()
        .map(|a: Action| match r.moment_at {
            Some(p) => a.torsor().at(m, p).moment.dot(&m.frames, &u),
            None => a.resultant.dot(&m.frames, &u),
        })
        .collect();
    let actions = Expr::sum(&m.reg, parts);
    unknowns_in(m, &actions).is_empty().then_some(actions)
}

/// M, h and Q over the names, when every coordinate with an equation of motion has its
/// equation in `values`.
fn named_motion(
    m: &Mechanism,
    program: &mut Program,
    values: &[(Quantity, Lin)],
) -> Option<NamedMotion> {
    // In the order of the spec's coordinates, as [`super::EquationsOfMotion`].
    let mut eoms: Vec<(CoordId, Lin)> = Vec::new();
    for (q, v) in values {
        if let QuantityKind::Eom(c) = &q.kind {
            eoms.push((m.reg.coord(c)?, v.clone()));
        }
    }
    eoms.sort_by_key(|(c, _)| *c);
    let (coordinates, rows): (Vec<CoordId>, Vec<Lin>) = eoms.into_iter().unzip();
    let with_eom = m
        .dynamics
        .theorems
        .iter()
        .filter(|t| t.eom.is_some())
        .count();
    if rows.is_empty() || rows.len() != with_eom {
        return None;
    }
    let mut mass = Vec::new();
    let mut velocity_terms = Vec::new();
    let mut forces = Vec::new();
    // The rows' accelerations (another coordinate's, imposed, stays in h), and every rate.
    let accelerations: Vec<_> = coordinates
        .iter()
        .filter_map(|&q| m.reg.index_of(VarRole::Rate(q, 2)))
        .collect();
    let rates = program.rate_vars((0..m.reg.coordinates().len()).map(CoordId), 1);
    for row in &rows {
        // The row is affine in the accelerations: Σ Mᵢⱼ q̈ⱼ plus its value without them.
        let mrow = coordinates
            .iter()
            .map(|&qj| program.partial(row, qj))
            .collect();
        let moving = program.without(row, &accelerations, "without accelerations");
        let at_rest = program.without(row, &rates, "at rest");
        velocity_terms.push(moving.sub(&at_rest));
        forces.push(at_rest.scale(&-&m.reg.one()));
        mass.push(mrow);
    }
    Some(NamedMotion {
        coordinates,
        mass,
        velocity_terms,
        forces,
    })
}
