//! Random physically valid samples: inertia parameters read off random clouds of point masses.

use super::cloud::{cloud_inertia, solid_cloud};
use super::expr::{self, Node};
use super::kin::{State, Values, state};
use super::{Hypothesis, InertiaInfo, NumericError, NumericModel, Sample, SolidInfo};
use crate::wire::CoordinateKind;
use nalgebra::{Matrix3, Vector3};
use rand::Rng;
use std::collections::{BTreeMap, BTreeSet};

/// Base points of a random cloud, before symmetry operations.
const CLOUD_POINTS: usize = 6;

/// `P` or `-P`: the parameter and the sign.
fn bare_param(node: &Node) -> Option<(usize, f64)> {
    match node {
        Node::Param(p) => Some((*p, 1.0)),
        Node::Neg(inner) => match **inner {
            Node::Param(p) => Some((p, -1.0)),
            _ => None,
        },
        _ => None,
    }
}

/// A symmetry operation on a cloud centred at the origin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Op {
    /// Mirror across the plane normal to an axis (doubles the points).
    Mirror(usize),
    /// Quarter turns about an axis (quadruples the points): the inertia becomes that of a
    /// solid of revolution about it.
    Turn(usize),
    /// Projection on the plane normal to an axis (a flat body).
    Flatten(usize),
}

const OPS: [Op; 9] = [
    Op::Mirror(0),
    Op::Mirror(1),
    Op::Mirror(2),
    Op::Turn(0),
    Op::Turn(1),
    Op::Turn(2),
    Op::Flatten(0),
    Op::Flatten(1),
    Op::Flatten(2),
];

fn cost(op: Op) -> u32 {
    match op {
        Op::Mirror(_) => 1,
        Op::Turn(_) => 2,
        Op::Flatten(_) => 10,
    }
}

/// Applies the operations of `mask` (bits over [`OPS`]): flattenings, then mirrors, then turns.
fn symmetrize(base: &[(f64, Vector3<f64>)], mask: usize) -> Vec<(f64, Vector3<f64>)> {
    let mut cloud = base.to_vec();
    let chosen: Vec<Op> = (0..OPS.len())
        .filter(|k| mask & (1 << k) != 0)
        .map(|k| OPS[k])
        .collect();
    let rank = |op: &Op| match op {
        Op::Flatten(_) => 0,
        Op::Mirror(_) => 1,
        Op::Turn(_) => 2,
    };
    let mut ordered = chosen.clone();
    ordered.sort_by_key(rank);
    for op in ordered {
        cloud = match op {
            Op::Flatten(a) => cloud
                .into_iter()
                .map(|(m, mut r)| {
                    r[a] = 0.0;
                    (m, r)
                })
                .collect(),
            Op::Mirror(a) => cloud
                .into_iter()
                .flat_map(|(m, r)| {
                    let mut s = r;
                    s[a] = -s[a];
                    [(m / 2.0, r), (m / 2.0, s)]
                })
                .collect(),
            Op::Turn(a) => {
                let (b, c) = ((a + 1) % 3, (a + 2) % 3);
                cloud
                    .into_iter()
                    .flat_map(|(m, r)| {
                        let mut out = [(m / 4.0, r); 4];
                        let mut cur = r;
                        for slot in out.iter_mut().skip(1) {
                            let mut next = cur;
                            next[b] = -cur[c];
                            next[c] = cur[b];
                            *slot = (m / 4.0, next);
                            cur = next;
                        }
                        out
                    })
                    .collect()
            }
        };
    }
    // Axes of revolution about two different axes: the body has the symmetries of a cube
    // (quarter turns about two axes generate them), so its inertia is isotropic. Averaging
    // over the 24 rotations of the cube gives exactly that.
    let turned: std::collections::BTreeSet<usize> = chosen
        .iter()
        .filter_map(|op| match op {
            Op::Turn(a) => Some(*a),
            _ => None,
        })
        .collect();
    if turned.len() >= 2 {
        let rotations = cube_rotations();
        let n = rotations.len() as f64;
        cloud = cloud
            .into_iter()
            .flat_map(|(m, r)| {
                rotations
                    .iter()
                    .map(move |q| (m / n, q * r))
                    .collect::<Vec<_>>()
            })
            .collect();
    }
    cloud
}

/// The 24 rotations of the cube: signed permutation matrices of determinant 1.
fn cube_rotations() -> Vec<nalgebra::Matrix3<f64>> {
    let perms = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut out = Vec::new();
    for p in perms {
        for signs in 0..8u8 {
            let mut q = nalgebra::Matrix3::zeros();
            for (row, &col) in p.iter().enumerate() {
                q[(row, col)] = if signs & (1 << row) != 0 { -1.0 } else { 1.0 };
            }
            if q.determinant() > 0.0 {
                out.push(q);
            }
        }
    }
    out
}

/// Random point masses of total `mass`, centroid at the origin.
fn random_cloud(rng: &mut impl Rng, mass: f64) -> Vec<(f64, Vector3<f64>)> {
    let size: f64 = rng.random_range(0.3..=1.0);
    let mut pts: Vec<(f64, Vector3<f64>)> = (0..CLOUD_POINTS)
        .map(|_| {
            let w: f64 = rng.random_range(0.2..=1.0);
            let r = Vector3::from_fn(|_, _| size * rng.random_range(-1.0..=1.0));
            (w, r)
        })
        .collect();
    let total: f64 = pts.iter().map(|p| p.0).sum();
    let mut centroid = Vector3::zeros();
    for (w, r) in &pts {
        for k in 0..3 {
            centroid[k] += w * r[k] / total;
        }
    }
    for p in &mut pts {
        p.0 *= mass / total;
        p.1 -= centroid;
    }
    pts
}

/// Matches a cloud's matrix against the written entries: the values of the parameters read
/// off the body (`cloud`), or `None` when an entry does not fit. An entry holding one such
/// parameter not yet known is solved for it, linearly (`A2 + m*l^2`, `-E2`, `J - m*a^2`
/// through an alias); one holding none must equal the cloud's; one holding several waits for
/// the others to fix all but one.
fn fit(
    entries: &[[Node; 3]; 3],
    cloud: &BTreeSet<usize>,
    params: &[f64],
    mat: &Matrix3<f64>,
) -> Option<BTreeMap<usize, f64>> {
    let size = mat.amax();
    let tol = 1e-9 * size.max(f64::MIN_POSITIVE);
    let mut scratch = params.to_vec();
    let mut out: BTreeMap<usize, f64> = BTreeMap::new();
    let mut pending: Vec<(usize, usize)> =
        (0..3).flat_map(|r| (0..3).map(move |c| (r, c))).collect();
    while !pending.is_empty() {
        let before = pending.len();
        let mut left = Vec::new();
        for (r, c) in pending {
            let node = &entries[r][c];
            let mut used = BTreeSet::new();
            expr::params_in(node, &mut used);
            let unknown: Vec<usize> = used
                .into_iter()
                .filter(|p| cloud.contains(p) && !out.contains_key(p))
                .collect();
            let target = mat[(r, c)];
            match unknown.as_slice() {
                [] => {
                    let v = value(node, &scratch)?;
                    if (v - target).abs() > tol {
                        return None;
                    }
                }
                [p] => {
                    let v = solve_linear(node, *p, &mut scratch, target, size)?;
                    scratch[*p] = v;
                    out.insert(*p, v);
                }
                _ => left.push((r, c)),
            }
        }
        if left.len() == before {
            return None;
        }
        pending = left;
    }
    Some(out)
}

/// The value of a constant node at `params`, `None` if it has none.
fn value(node: &Node, params: &[f64]) -> Option<f64> {
    super::validate::at(node, params, &[])
        .ok()
        .filter(|v| v.is_finite())
}

/// The value of parameter `p` that makes `node` equal `target`, when `node` is affine in `p`
/// (read at p = 0, 1, 2; `None` if it is not, or does not depend on it).
fn solve_linear(node: &Node, p: usize, params: &mut [f64], target: f64, size: f64) -> Option<f64> {
    let mut at = |x: f64| {
        params[p] = x;
        value(node, params)
    };
    let (f0, f1, f2) = (at(0.0)?, at(1.0)?, at(2.0)?);
    let slope = f1 - f0;
    let scale = f0
        .abs()
        .max(f1.abs())
        .max(f2.abs())
        .max(size)
        .max(f64::MIN_POSITIVE);
    if slope.abs() <= 1e-12 * scale || (f2 - f0 - 2.0 * slope).abs() > 1e-9 * scale {
        return None;
    }
    Some((target - f0) / slope)
}

fn fail(msg: String) -> NumericError {
    NumericError::Sampling(msg)
}

/// What a hypothesis imposes on a sample: nothing without one.
struct Imposed<'a> {
    /// Solids given their declared symmetries.
    symmetric: &'a [usize],
    /// Coordinates with q̈ = 0.
    constant_rates: &'a [usize],
    /// Coordinates whose motion is given.
    motions: &'a [(usize, Option<Node>, Option<Node>)],
    /// Parameters set from the others.
    relations: &'a [(usize, Node)],
}

impl<'a> Imposed<'a> {
    fn of(hypothesis: Option<&'a Hypothesis>) -> Imposed<'a> {
        match hypothesis {
            Some(h) => Imposed {
                symmetric: &h.symmetric_solids,
                constant_rates: &h.constant_rates,
                motions: &h.motions,
                relations: &h.relations,
            },
            None => Imposed {
                symmetric: &[],
                constant_rates: &[],
                motions: &[],
                relations: &[],
            },
        }
    }
}

/// Draws a sample; `symmetric` solids get their declared symmetries, `constant_rates`
/// coordinates get q̈ = 0.
pub(super) fn draw(
    m: &NumericModel,
    rng: &mut impl Rng,
    hypothesis: Option<&Hypothesis>,
) -> Result<Sample, NumericError> {
    let imposed = Imposed::of(hypothesis);
    let from_cloud = cloud_parameters(m)?;
    let mut vals = Values {
        params: draw_parameters(m, rng, &from_cloud),
        coords: Vec::with_capacity(m.coords.len()),
        time: 0.0,
    };
    impose_relations(m, imposed.relations, &from_cloud, &mut vals)?;
    draw_coordinates(m, rng, &imposed, &mut vals)?;
    drive_rates(m, &mut vals)?;
    if m.uses_time {
        vals.time = rng.random_range(0.0..=10.0);
    }
    if let Some((i, motion)) = hypothesis.and_then(|h| h.trial.as_ref()) {
        vals.coords[*i] = trial_motion(motion, &vals.params, vals.time)
            .map_err(|e| fail(format!("the trial motion of `{}`: {e}", m.coords[*i].name)))?;
    }
    // Coordinates a loop closure determines: moved onto the loop (after any rate a gear
    // drives, and the time, which the loop may read).
    super::closure::settle(m, &mut vals).map_err(|e| fail(format!("closures: {e}")))?;
    // Dry friction's signs, from the relative rates now drawn, but for a sign the hypothesis
    // sets (« the block slides down »: `epsilon02 = 1`, or the limit of sliding), which the exact side reads as given.
    let set_by_hypothesis = |p: usize| imposed.relations.iter().any(|(q, _)| *q == p);
    super::dynamics::set_signs(m, &mut vals, &set_by_hypothesis)?;

    // Inertia parameters: the geometry does not depend on them, so place it once.
    let st = state(m, &vals)?;
    for s in 0..m.solids.len() {
        fit_inertia(
            m,
            &st,
            rng,
            (s, &from_cloud),
            imposed.symmetric.contains(&s),
            &mut vals,
        )?;
    }
    // Every solid must now be realisable.
    for s in 0..m.solids.len() {
        solid_cloud(m, &st, &vals, s)?;
    }
    Ok(Sample {
        parameters: m
            .params
            .iter()
            .zip(&vals.params)
            .map(|(p, v)| (p.name.clone(), *v))
            .collect(),
        coordinates: m
            .coords
            .iter()
            .zip(&vals.coords)
            .map(|(c, v)| (c.name.clone(), *v))
            .collect(),
        time: vals.time,
    })
}

/// Where each parameter is first used, to name it when an inertia entry read off a random
/// body also appears there.
#[derive(Default)]
struct FirstUse(BTreeMap<usize, String>);

impl FirstUse {
    fn note(&mut self, node: &Node, place: &dyn Fn() -> String) {
        let mut used = BTreeSet::new();
        expr::params_in(node, &mut used);
        for p in used {
            self.0.entry(p).or_insert_with(place);
        }
    }

    /// The uses outside the solids: rotations, positions, imposed rates, gravity, links and
    /// actions.
    fn outside_solids(m: &NumericModel) -> FirstUse {
        let mut uses = FirstUse::default();
        for f in &m.frames {
            if let Some((_, _, a)) = &f.rotation {
                uses.note(a, &|| format!("the rotation angle of frame {}", f.name));
            }
        }
        for p in &m.points {
            uses.note(&p.position, &|| format!("the position of point {}", p.name));
        }
        for c in &m.coords {
            if let Some(r) = &c.rate {
                uses.note(r, &|| format!("the imposed rate of {}", c.name));
            }
        }
        let dy = &m.dynamics;
        if let Some(g) = &dy.gravity {
            uses.note(g, &|| "gravity".to_string());
        }
        for (i, l) in dy.links.iter().enumerate() {
            if let Some(f) = &l.friction {
                uses.note(f, &|| format!("the friction of links[{i}]"));
            }
            if let Some(sp) = &l.spring {
                uses.note(&sp.stiffness, &|| format!("the spring of links[{i}]"));
                if let Some(q0) = &sp.free {
                    uses.note(q0, &|| format!("the spring of links[{i}]"));
                }
            }
        }
        for (i, a) in dy.actions.iter().enumerate() {
            for node in a.resultant.iter().chain(&a.moment) {
                uses.note(node, &|| format!("actions[{i}]"));
            }
        }
        uses
    }
}

/// The parameters read off a random body, each with its solid: those its inertia entries
/// hold and nothing else does (no other solid, no mass, no position, no action...). An entry
/// written `P` or `-P` must be one of them.
fn cloud_parameters(m: &NumericModel) -> Result<BTreeMap<usize, usize>, NumericError> {
    let mut elsewhere = FirstUse::outside_solids(m);
    for solid in &m.solids {
        elsewhere.note(&solid.mass, &|| format!("the mass of solid {}", solid.name));
    }
    // The solids whose inertia entries hold each parameter, and where, for the messages.
    let mut holders: BTreeMap<usize, BTreeMap<usize, String>> = BTreeMap::new();
    let mut bare: BTreeMap<usize, usize> = BTreeMap::new();
    for (s, solid) in m.solids.iter().enumerate() {
        let Some(inr) = &solid.inertia else { continue };
        for r in 0..3 {
            for c in 0..3 {
                let node = &inr.matrix[r][c];
                let mut used = BTreeSet::new();
                expr::params_in(node, &mut used);
                for p in used {
                    holders.entry(p).or_default().entry(s).or_insert_with(|| {
                        format!(
                            "the inertia entry [{r}][{c}] `{}` of solid {}",
                            inr.text[r][c], solid.name
                        )
                    });
                }
                if let Some((p, _)) = bare_param(node)
                    && let Some(other) = bare.insert(p, s)
                    && other != s
                {
                    return Err(fail(format!(
                        "parameter `{}` is an inertia entry of solids {} and {}",
                        m.params[p].name, m.solids[other].name, solid.name
                    )));
                }
            }
        }
    }
    // A parameter written alone in an entry must be read off its body: used nowhere else.
    for (p, s) in &bare {
        let other_solid = holders[p]
            .iter()
            .find(|(t, _)| *t != s)
            .map(|(_, w)| w.clone());
        if let Some(place) = elsewhere.0.get(p).cloned().or(other_solid) {
            return Err(fail(format!(
                "parameter `{}` is an inertia entry of solid {}, read off a random body, but \
                 it also appears in {place}",
                m.params[*p].name, m.solids[*s].name
            )));
        }
    }
    Ok(holders
        .into_iter()
        .filter(|(p, solids)| solids.len() == 1 && !elsewhere.0.contains_key(p))
        .map(|(p, solids)| (p, *solids.keys().next().unwrap_or(&0)))
        .collect())
}

/// Random values of the parameters not read off a random body (0 for those).
fn draw_parameters(
    m: &NumericModel,
    rng: &mut impl Rng,
    from_cloud: &BTreeMap<usize, usize>,
) -> Vec<f64> {
    let mut params = vec![0.0; m.params.len()];
    for (i, p) in m.params.iter().enumerate() {
        if !from_cloud.contains_key(&i) {
            params[i] = if p.positive {
                rng.random_range(0.5..=2.0)
            } else {
                rng.random_range(-1.0..=1.0)
            };
        }
    }
    params
}

/// Relations: a parameter set from the others (repeated, for a chain A = B, B = C). An
/// inertia entry read off a random body cannot be set so.
fn impose_relations(
    m: &NumericModel,
    relations: &[(usize, Node)],
    from_cloud: &BTreeMap<usize, usize>,
    vals: &mut Values,
) -> Result<(), NumericError> {
    for (p, node) in relations {
        let mut used = BTreeSet::new();
        expr::params_in(node, &mut used);
        if let Some(q) = std::iter::once(p)
            .chain(&used)
            .find(|q| from_cloud.contains_key(q))
        {
            let what = if q == p {
                format!("sets `{}`", m.params[*p].name)
            } else {
                format!("on `{}` reads `{}`", m.params[*p].name, m.params[*q].name)
            };
            return Err(fail(format!(
                "the relation {what}, an inertia entry that the float backend reads off a \
                 random body (a point cloud): it cannot be imposed on a sample"
            )));
        }
    }
    for _ in 0..relations.len() {
        for (p, node) in relations {
            vals.params[*p] = expr::eval_scalar(node, &vals.constants())
                .map_err(|e| fail(format!("relation on `{}`: {e}", m.params[*p].name)))?;
        }
    }
    Ok(())
}

/// Random [q, q̇, q̈] of every coordinate, then what the spec and the hypothesis impose: an
/// imposed rate, a constant rate, a given motion.
fn draw_coordinates(
    m: &NumericModel,
    rng: &mut impl Rng,
    imposed: &Imposed,
    vals: &mut Values,
) -> Result<(), NumericError> {
    for (i, c) in m.coords.iter().enumerate() {
        let q = match c.kind {
            CoordinateKind::Angle => rng.random_range(-std::f64::consts::PI..=std::f64::consts::PI),
            CoordinateKind::Length => rng.random_range(0.5..=2.0),
        };
        let mut qd = rng.random_range(-2.0..=2.0);
        let mut qdd = rng.random_range(-2.0..=2.0);
        if let Some(rate) = &c.rate
            && !c.driven
        {
            qd = expr::eval_scalar(rate, &vals.constants())
                .map_err(|e| fail(format!("imposed rate of `{}`: {e}", c.name)))?;
            qdd = 0.0;
        }
        if imposed.constant_rates.contains(&i) {
            qdd = 0.0;
        }
        let mut q = q;
        if let Some((_, value, rate)) = imposed.motions.iter().find(|(j, _, _)| *j == i) {
            let at = |node: &Node| {
                expr::eval_scalar(node, &vals.constants())
                    .map_err(|e| fail(format!("the motion of `{}`: {e}", c.name)))
            };
            if let Some(v) = value {
                q = at(v)?;
            }
            qd = match rate {
                Some(r) => at(r)?,
                None => 0.0,
            };
            qdd = 0.0;
        }
        vals.coords.push([q, qd, qdd]);
    }
    Ok(())
}

/// [q, q̇, q̈] of a trial motion q(t) at the time `t`: the motion evaluated on a dual number
/// of the time (t, 1, 0), whose parts are the value and its first two derivatives.
pub(super) fn trial_motion(motion: &Node, params: &[f64], t: f64) -> Result<[f64; 3], String> {
    let env = expr::Env {
        params,
        coords: &[],
        rates: &[],
        frames: &[],
        time: num_dual::Dual2_64::new(t, 1.0, 0.0),
    };
    let v = expr::eval_scalar(motion, &env)?;
    Ok([v.re, v.v1, v.v2])
}

/// Rates driven by the others' (a gear ratio), once those are drawn; a coefficient may
/// hold a driven coordinate's value, whose rates are then settled by the passes before.
fn drive_rates(m: &NumericModel, vals: &mut Values) -> Result<(), NumericError> {
    for _ in 0..m.coords.len() {
        for (i, c) in m.coords.iter().enumerate() {
            if let (Some(rate), true) = (&c.rate, c.driven) {
                let [qd, qdd] = super::kin::driven(rate, vals)
                    .map_err(|e| fail(format!("the rate of `{}`: {e}", c.name)))?;
                vals.coords[i][1] = qd;
                vals.coords[i][2] = qdd;
            }
        }
    }
    Ok(())
}

/// The symmetry operations (bits over [`OPS`]) a solid's declared symmetries force.
fn forced_ops(
    m: &NumericModel,
    solid: &SolidInfo,
    inr: &InertiaInfo,
) -> Result<usize, NumericError> {
    let mut forced = 0usize;
    for sym in &solid.symmetries {
        if sym.frame != inr.basis {
            return Err(fail(format!(
                "a symmetry of solid {} is written in the basis of frame {}, its \
                 inertia in that of frame {}",
                solid.name, m.frames[sym.frame].name, m.frames[inr.basis].name
            )));
        }
        let op = if sym.revolution {
            Op::Turn(sym.axis)
        } else {
            Op::Mirror(sym.axis)
        };
        forced |= 1 << OPS.iter().position(|o| *o == op).unwrap_or(0);
    }
    Ok(forced)
}

/// Sets the inertia parameters of solid `s` (`symmetric`: with its declared symmetries) from
/// the cheapest symmetrised random cloud whose matrix fits the written one.
fn fit_inertia(
    m: &NumericModel,
    st: &State,
    rng: &mut impl Rng,
    (s, from_cloud): (usize, &BTreeMap<usize, usize>),
    symmetric: bool,
    vals: &mut Values,
) -> Result<(), NumericError> {
    let solid = &m.solids[s];
    let Some(inr) = &solid.inertia else {
        return Ok(());
    };
    let mass = expr::eval_scalar(&solid.mass, &vals.constants())
        .map_err(|e| fail(format!("mass of solid {}: {e}", solid.name)))?;
    if !(mass.is_finite() && mass > 0.0) {
        return Err(fail(format!(
            "solid {} has mass {mass} at the drawn parameters; give its mass parameters \
             the unit kg",
            solid.name
        )));
    }
    let cloud: BTreeSet<usize> = from_cloud
        .iter()
        .filter(|(_, t)| **t == s)
        .map(|(p, _)| *p)
        .collect();
    if cloud.is_empty() {
        // Fully written in terms of other parameters: checked like any body.
        return Ok(());
    }
    let forced = if symmetric {
        forced_ops(m, solid, inr)?
    } else {
        0
    };
    // QG in the inertia basis.
    let qg = st.rot0(inr.basis).transpose() * (st.pos0(solid.centre) - st.pos0(inr.point));
    let base = random_cloud(rng, mass);
    // Flattened along all three axes, the body is its centre: every entry 0, which fits any
    // linear relation between them and tests nothing. Never drawn.
    let point = (6..9).fold(0usize, |acc, k| acc | 1 << k);
    debug_assert!((6..9).all(|k| matches!(OPS[k], Op::Flatten(_))));
    let mut masks: Vec<usize> = (0..1usize << OPS.len())
        .filter(|mk| mk & forced == forced && mk & point != point)
        .collect();
    masks.sort_by_key(|mk| {
        let c: u32 = (0..OPS.len())
            .filter(|k| mk & (1 << k) != 0)
            .map(|k| cost(OPS[k]))
            .sum();
        (c, *mk)
    });
    let found = masks.iter().find_map(|mk| {
        let body = symmetrize(&base, *mk);
        fit(
            &inr.matrix,
            &cloud,
            &vals.params,
            &cloud_inertia(&body, &qg),
        )
    });
    let Some(assigned) = found else {
        return Err(fail(format!(
            "no random body fits the inertia matrix {:?} of solid {} (an entry is a \
             parameter of its own, or linear in one such as `A + m*a^2`; numbers and \
             repeated parameters must follow from mirror planes, axes of revolution or \
             flatness)",
            inr.text, solid.name
        )));
    };
    for (p, v) in assigned {
        vals.params[p] = v;
    }
    Ok(())
}
