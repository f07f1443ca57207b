//! Random physically valid samples: inertia parameters read off random clouds of point masses.

use super::cloud::{cloud_inertia, solid_cloud};
use super::expr::{self, Node};
use super::kin::{Values, state};
use super::{Hypothesis, NumericError, NumericModel, Sample};
use crate::wire::CoordinateKind;
use nalgebra::{Matrix3, Vector3};
use rand::Rng;
use std::collections::{BTreeMap, BTreeSet};

/// Base points of a random cloud, before symmetry operations.
const CLOUD_POINTS: usize = 6;

/// An entry of an inertia matrix as written: a number, or ± a parameter.
#[derive(Debug, Clone, Copy)]
enum Entry {
    Number(f64),
    Param(usize, f64),
}

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

/// Matches a cloud's matrix against the written entries: parameter values, or `None` when a
/// number or a repeated parameter does not fit.
fn fit(pattern: &[[Entry; 3]; 3], mat: &Matrix3<f64>) -> Option<BTreeMap<usize, f64>> {
    let size = mat.amax();
    let tol = 1e-9 * size.max(f64::MIN_POSITIVE);
    let mut out: BTreeMap<usize, f64> = BTreeMap::new();
    for r in 0..3 {
        for c in 0..3 {
            match pattern[r][c] {
                Entry::Number(x) => {
                    if (mat[(r, c)] - x).abs() > tol {
                        return None;
                    }
                }
                Entry::Param(p, sign) => {
                    let v = sign * mat[(r, c)];
                    if let Some(old) = out.get(&p) {
                        if (old - v).abs() > tol {
                            return None;
                        }
                    } else {
                        out.insert(p, v);
                    }
                }
            }
        }
    }
    Some(out)
}

/// Draws a sample; `symmetric` solids get their declared symmetries, `constant_rates`
/// coordinates get q̈ = 0.
pub(super) fn draw(
    m: &NumericModel,
    rng: &mut impl Rng,
    hypothesis: Option<&Hypothesis>,
) -> Result<Sample, NumericError> {
    let fail = |msg: String| NumericError::Sampling(msg);
    let (symmetric, constant_rates, motions, relations) = match hypothesis {
        Some(h) => (
            &h.symmetric_solids[..],
            &h.constant_rates[..],
            &h.motions[..],
            &h.relations[..],
        ),
        None => (&[][..], &[][..], &[][..], &[][..]),
    };
    // Entries written `P` or `-P` are read off a random body; the parameter must then appear
    // nowhere else. `elsewhere` says where each other parameter is first used.
    let mut elsewhere: BTreeMap<usize, String> = BTreeMap::new();
    let mut note = |node: &Node, place: &dyn Fn() -> String| {
        let mut used = BTreeSet::new();
        expr::params_in(node, &mut used);
        for p in used {
            elsewhere.entry(p).or_insert_with(place);
        }
    };
    for f in &m.frames {
        if let Some((_, _, a)) = &f.rotation {
            note(a, &|| format!("the rotation angle of frame {}", f.name));
        }
    }
    for p in &m.points {
        note(&p.position, &|| format!("the position of point {}", p.name));
    }
    for c in &m.coords {
        if let Some(r) = &c.rate {
            note(r, &|| format!("the imposed rate of {}", c.name));
        }
    }
    let dy = &m.dynamics;
    if let Some(g) = &dy.gravity {
        note(g, &|| "gravity".to_string());
    }
    for (i, l) in dy.links.iter().enumerate() {
        if let Some(f) = &l.friction {
            note(f, &|| format!("the friction of links[{i}]"));
        }
        if let Some(sp) = &l.spring {
            note(&sp.stiffness, &|| format!("the spring of links[{i}]"));
            if let Some(q0) = &sp.free {
                note(q0, &|| format!("the spring of links[{i}]"));
            }
        }
    }
    for (i, a) in dy.actions.iter().enumerate() {
        for node in a.resultant.iter().chain(&a.moment) {
            note(node, &|| format!("actions[{i}]"));
        }
    }
    let mut from_cloud: BTreeMap<usize, usize> = BTreeMap::new();
    for (s, solid) in m.solids.iter().enumerate() {
        note(&solid.mass, &|| format!("the mass of solid {}", solid.name));
        let Some(inr) = &solid.inertia else { continue };
        for r in 0..3 {
            for c in 0..3 {
                match bare_param(&inr.matrix[r][c]) {
                    Some((p, _)) => {
                        if let Some(other) = from_cloud.insert(p, s)
                            && other != s
                        {
                            return Err(fail(format!(
                                "parameter `{}` is an inertia entry of solids {} and {}",
                                m.params[p].name, m.solids[other].name, solid.name
                            )));
                        }
                    }
                    None => note(&inr.matrix[r][c], &|| {
                        format!(
                            "the inertia entry [{r}][{c}] `{}` of solid {}",
                            inr.text[r][c], solid.name
                        )
                    }),
                }
            }
        }
    }
    for (p, s) in &from_cloud {
        if let Some(place) = elsewhere.get(p) {
            return Err(fail(format!(
                "parameter `{}` is an inertia entry of solid {}, read off a random body, but \
                 it also appears in {place}",
                m.params[*p].name, m.solids[*s].name
            )));
        }
    }

    let mut vals = Values {
        params: vec![0.0; m.params.len()],
        coords: Vec::with_capacity(m.coords.len()),
        time: 0.0,
    };
    for (i, p) in m.params.iter().enumerate() {
        if !from_cloud.contains_key(&i) {
            vals.params[i] = if p.positive {
                rng.random_range(0.5..=2.0)
            } else {
                rng.random_range(-1.0..=1.0)
            };
        }
    }
    // Relations: a parameter set from the others (repeated, for a chain A = B, B = C). An
    // inertia entry read off a random body cannot be set so.
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
        if constant_rates.contains(&i) {
            qdd = 0.0;
        }
        let mut q = q;
        if let Some((_, value, rate)) = motions.iter().find(|(j, _, _)| *j == i) {
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
    // Rates driven by the others' (a gear ratio), once those are drawn; a coefficient may
    // hold a driven coordinate's value, whose rates are then settled by the passes before.
    for _ in 0..m.coords.len() {
        for (i, c) in m.coords.iter().enumerate() {
            if let (Some(rate), true) = (&c.rate, c.driven) {
                let [qd, qdd] = super::kin::driven(rate, &vals)
                    .map_err(|e| fail(format!("the rate of `{}`: {e}", c.name)))?;
                vals.coords[i][1] = qd;
                vals.coords[i][2] = qdd;
            }
        }
    }
    if m.uses_time {
        vals.time = rng.random_range(0.0..=10.0);
    }
    // Coordinates a loop closure determines: moved onto the loop (after any rate a gear
    // drives, and the time, which the loop may read).
    super::closure::settle(m, &mut vals).map_err(|e| fail(format!("closures: {e}")))?;
    // Dry friction's signs, from the relative rates now drawn.
    super::dynamics::set_signs(m, &mut vals)?;

    // Inertia parameters: the geometry does not depend on them, so place it once.
    let st = state(m, &vals)?;
    for (s, solid) in m.solids.iter().enumerate() {
        let Some(inr) = &solid.inertia else { continue };
        let mass = expr::eval_scalar(&solid.mass, &vals.constants())
            .map_err(|e| fail(format!("mass of solid {}: {e}", solid.name)))?;
        if !(mass.is_finite() && mass > 0.0) {
            return Err(fail(format!(
                "solid {} has mass {mass} at the drawn parameters; give its mass parameters \
                 the unit kg",
                solid.name
            )));
        }
        let mut pattern = [[Entry::Number(0.0); 3]; 3];
        let mut free = false;
        for (r, row) in pattern.iter_mut().enumerate() {
            for (c, entry) in row.iter_mut().enumerate() {
                *entry = match bare_param(&inr.matrix[r][c]) {
                    Some((p, sign)) => {
                        free = true;
                        Entry::Param(p, sign)
                    }
                    None => Entry::Number(
                        expr::eval_scalar(&inr.matrix[r][c], &vals.constants()).map_err(|e| {
                            fail(format!(
                                "inertia entry [{r}][{c}] `{}` of solid {}: {e}",
                                inr.text[r][c], solid.name
                            ))
                        })?,
                    ),
                };
            }
        }
        if !free {
            // Fully written in terms of other parameters: checked below like any body.
            continue;
        }
        let mut forced = 0usize;
        if symmetric.contains(&s) {
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
        }
        // QG in the inertia basis.
        let qg = st.rot0(inr.basis).transpose() * (st.pos0(solid.centre) - st.pos0(inr.point));
        let base = random_cloud(rng, mass);
        let mut masks: Vec<usize> = (0..1usize << OPS.len())
            .filter(|mk| mk & forced == forced)
            .collect();
        masks.sort_by_key(|mk| {
            let c: u32 = (0..OPS.len())
                .filter(|k| mk & (1 << k) != 0)
                .map(|k| cost(OPS[k]))
                .sum();
            (c, *mk)
        });
        let found = masks.iter().find_map(|mk| {
            let cloud = symmetrize(&base, *mk);
            fit(&pattern, &cloud_inertia(&cloud, &qg))
        });
        let Some(assigned) = found else {
            return Err(fail(format!(
                "no random body fits the inertia matrix {:?} of solid {} (numbers and repeated \
                 parameters must follow from mirror planes, axes of revolution or flatness)",
                inr.text, solid.name
            )));
        };
        for (p, v) in assigned {
            vals.params[p] = v;
        }
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
