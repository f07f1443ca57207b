//! Loop closures, moved numerically: the dependent coordinates found by Newton's method on
//! the loop's vector (its own frames, its own parser), their rates and accelerations from
//! the loop's first and second time derivatives (dual numbers), by least squares. Nothing
//! here reads the exact side's solution.

use super::NumericError;
use super::NumericModel;
use super::expr::{self, Env, Node};
use super::kin::{State, Values, state};
use super::model::Context;
use crate::resolve::Resolved;
use crate::wire::SpecFile;
use nalgebra::{DMatrix, DVector, Vector3};

/// A closure: the vector that is zero, and the coordinates it determines.
#[derive(Debug, Clone)]
pub(super) struct Closure {
    vector: Node,
    dependent: Vec<usize>,
}

/// A rolling condition, as resolved: the velocity V(P, i/j) at a contact that is zero (or
/// its components along `on`), and the coordinates whose rates it determines.
pub(super) type Rolling = crate::resolve::RollingNode;

/// A helical link: the screw motion of its second solid's frame `b` on its first's `a`,
/// V(P ∈ b/a)·u = p/(2π) Ω(b/a)·u, and the coordinate whose rate it determines.
#[derive(Debug, Clone)]
pub(super) struct Helix {
    /// Its index in the spec's `links`.
    link: usize,
    point: usize,
    /// Frames a and b.
    motion: [usize; 2],
    /// The axis u: (frame, axis).
    axis: (usize, usize),
    /// The pitch p, read with this backend's parser.
    pitch: Node,
    dependent: Option<usize>,
}

/// Reads the spec's helical links, their pitches with the float backend's own parser, on
/// their resolved references.
pub(super) fn helices(
    spec: &SpecFile,
    m: &NumericModel,
    trees: &Resolved,
) -> Result<Vec<Helix>, NumericError> {
    let names = m.names();
    let mut out = Vec::with_capacity(trees.helices.len());
    for h in &trees.helices {
        let path = format!("links[{}].pitch", h.link);
        let text = spec.links[h.link].pitch.as_deref().unwrap_or("");
        let pitch =
            (names.parse(text, Context::Constant)).map_err(|e| super::model::spec_err(&path, e))?;
        if !holds_parameter(&pitch) {
            return Err(super::model::spec_err(path, pure_pitch(text)));
        }
        out.push(Helix {
            link: h.link,
            point: h.point,
            motion: h.motion,
            axis: h.axis,
            pitch,
            dependent: h.dependent,
        });
    }
    Ok(out)
}

/// Whether `node` holds a parameter: a pitch is a length per turn, and a bare number (π
/// included) has no unit.
fn holds_parameter(node: &Node) -> bool {
    match node {
        Node::Param(_) => true,
        Node::Num(_) | Node::Coord(_) | Node::Rate(..) | Node::Basis(..) | Node::Unknown(_) => {
            false
        }
        Node::Time => false,
        Node::Neg(a) | Node::Pow(a, _) | Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => {
            holds_parameter(a)
        }
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            holds_parameter(a) || holds_parameter(b)
        }
    }
}

/// The refusal of a pitch written as a bare number, worded as the exact side's.
fn pure_pitch(text: &str) -> String {
    let shown: String = text.chars().take(40).collect();
    format!(
        "the pitch `{shown}` is a pure number, not a length (m per turn): name a parameter \
         of unit m"
    )
}

/// The helical links that determine a coordinate (their relations join the loop's rows).
fn determining(m: &NumericModel) -> impl Iterator<Item = &Helix> {
    m.helices.iter().filter(|h| h.dependent.is_some())
}

/// The axial part of a skew matrix (ω of W = [ω]×), from its antisymmetric part.
fn vee(w: &nalgebra::Matrix3<f64>) -> Vector3<f64> {
    0.5 * Vector3::new(
        w[(2, 1)] - w[(1, 2)],
        w[(0, 2)] - w[(2, 0)],
        w[(1, 0)] - w[(0, 1)],
    )
}

/// Ω(f/0) and its time derivative in ground components: W = Ṙ Rᵀ = [Ω]×, Ẇ = R̈ Rᵀ + Ṙ Ṙᵀ.
fn spin(st: &State, f: usize) -> [Vector3<f64>; 2] {
    let r = st.rot[f];
    let (r0, r1, r2) = (r.map(|x| x.re), r.map(|x| x.v1), r.map(|x| x.v2));
    [
        vee(&(r1 * r0.transpose())),
        vee(&(r2 * r0.transpose() + r1 * r1.transpose())),
    ]
}

/// A helical link's relation V(P ∈ b/a)·u − p/(2π) Ω(b/a)·u and its time derivative.
fn helix_row(st: &State, v: &Values, h: &Helix) -> Result<[f64; 2], NumericError> {
    let p = expr::eval_scalar(&h.pitch, &v.constants()).map_err(|e| NumericError::Evaluation {
        what: format!("the pitch of links[{}]", h.link),
        message: e,
    })?;
    let k = p / (2.0 * std::f64::consts::PI);
    let [a, b] = h.motion;
    let ([va, aa], [vb, ab]) = (carried(st, h.point, a), carried(st, h.point, b));
    let ([wa, dwa], [wb, dwb]) = (spin(st, a), spin(st, b));
    let u = st.rot[h.axis.0].column(h.axis.1).map(|x| x.re);
    let du = st.rot[h.axis.0].column(h.axis.1).map(|x| x.v1);
    let (vr, ar, wr, dwr) = (vb - va, ab - aa, wb - wa, dwb - dwa);
    Ok([
        vr.dot(&u) - k * wr.dot(&u),
        ar.dot(&u) + vr.dot(&du) - k * (dwr.dot(&u) + wr.dot(&du)),
    ])
}

/// Newton iterations before a loop is declared open.
const NEWTON_STEPS: usize = 60;
/// Largest residual of a closed loop, relative to its lengths.
const CLOSED_TOL: f64 = 1e-12;

/// Reads the spec's closures with the float backend's own parser, on their resolved
/// references.
pub(super) fn build(
    spec: &SpecFile,
    m: &NumericModel,
    trees: &Resolved,
) -> Result<Vec<Closure>, NumericError> {
    let names = m.names();
    let mut out = Vec::with_capacity(spec.closures.len());
    for (i, (c, node)) in spec.closures.iter().zip(&trees.closures).enumerate() {
        let vector = names
            .parse(&c.vector, Context::Position)
            .map_err(|e| super::model::spec_err(format!("closures[{i}].vector"), e))?;
        let dependent = node.dependent.clone();
        out.push(Closure { vector, dependent });
    }
    Ok(out)
}

/// V(P ∈ f/0) and its time derivative in ground components, from the frame's motion:
/// V = Ȯ + W (P − O) with W = Ṙ Rᵀ, and dV/dt = Ö + Ẇ (P − O) + W (Ṗ − Ȯ),
/// Ẇ = R̈ Rᵀ + Ṙ Ṙᵀ.
fn carried(st: &State, p: usize, f: usize) -> [Vector3<f64>; 2] {
    let r = st.rot[f];
    let (r0, r1, r2) = (r.map(|x| x.re), r.map(|x| x.v1), r.map(|x| x.v2));
    let w = r1 * r0.transpose();
    let dw = r2 * r0.transpose() + r1 * r1.transpose();
    let [o, od, odd] = super::la::parts(&st.origin(f));
    let [pp, pd, _] = super::la::parts(&st.pos[p]);
    let rel = pp - o;
    [od + w * rel, odd + dw * rel + w * (pd - od)]
}

/// Each rolling condition's scalar relations and their time derivatives, then each helical
/// link's that determines a coordinate.
fn rolling_rows(m: &NumericModel, v: &Values) -> Result<[Vec<f64>; 2], NumericError> {
    let st = state(m, v)?;
    let mut rows = [Vec::new(), Vec::new()];
    for r in &m.rolling {
        let [vi, ai] = carried(&st, r.point, r.motion[0]);
        let [vj, aj] = carried(&st, r.point, r.motion[1]);
        let (c, dc) = (vi - vj, ai - aj);
        if r.on.is_empty() {
            rows[0].extend(c.iter());
            rows[1].extend(dc.iter());
        } else {
            for &(f, a) in &r.on {
                let u = st.rot[f].column(a).map(|x| x.re);
                let du = st.rot[f].column(a).map(|x| x.v1);
                rows[0].push(u.dot(&c));
                rows[1].push(du.dot(&c) + u.dot(&dc));
            }
        }
    }
    for h in determining(m) {
        let [c, dc] = helix_row(&st, v, h)?;
        rows[0].push(c);
        rows[1].push(dc);
    }
    Ok(rows)
}

/// Every closure's vector in ground components, as dual numbers in t.
fn loops(m: &NumericModel, v: &Values) -> Result<Vec<Vector3<num_dual::Dual2_64>>, NumericError> {
    let st = state(m, v)?;
    let coords: Vec<num_dual::Dual2_64> = v
        .coords
        .iter()
        .map(|c| num_dual::Dual2_64::new(c[0], c[1], c[2]))
        .collect();
    let rates: Vec<[num_dual::Dual2_64; 2]> = v
        .coords
        .iter()
        .map(|c| [c[1].into(), c[2].into()])
        .collect();
    let env = Env {
        params: &v.params,
        coords: &coords,
        rates: &rates,
        frames: &st.rot,
        time: num_dual::Dual2_64::new(v.time, 1.0, 0.0),
    };
    m.closures
        .iter()
        .map(|c| {
            expr::eval_vector(&c.vector, &env).map_err(|e| NumericError::Evaluation {
                what: "a loop closure".to_string(),
                message: e,
            })
        })
        .collect()
}

/// The stacked components of every loop, order `k` of the time derivative (0, 1, 2); at
/// orders 1 and 2, the rolling conditions' relations and their derivatives follow.
fn stacked(m: &NumericModel, v: &Values, k: usize) -> Result<DVector<f64>, NumericError> {
    let l = loops(m, v)?;
    let mut out: Vec<f64> = l
        .iter()
        .flat_map(|x| {
            x.iter()
                .map(|d| match k {
                    0 => d.re,
                    1 => d.v1,
                    _ => d.v2,
                })
                .collect::<Vec<_>>()
        })
        .collect();
    if k > 0 && (!m.rolling.is_empty() || determining(m).next().is_some()) {
        let [r1, r2] = rolling_rows(m, v)?;
        out.extend(if k == 1 { r1 } else { r2 });
    }
    Ok(DVector::from_vec(out))
}

/// The coordinates the closures, the rolling conditions and the helical links determine, in
/// the order of their rows.
fn dependents(m: &NumericModel) -> Vec<usize> {
    (m.closures.iter().flat_map(|c| c.dependent.clone()))
        .chain(m.rolling.iter().flat_map(|r| r.dependent.clone()))
        .chain(determining(m).filter_map(|h| h.dependent))
        .collect()
}

/// ∂(loop)/∂q_d for each dependent coordinate: the first derivative in t when only q_d moves,
/// at unit rate.
fn jacobian(m: &NumericModel, v: &Values, dep: &[usize]) -> Result<DMatrix<f64>, NumericError> {
    let mut cols = Vec::new();
    for &d in dep {
        let mut w = Values {
            params: v.params.clone(),
            coords: v.coords.iter().map(|c| [c[0], 0.0, 0.0]).collect(),
            time: v.time,
        };
        w.coords[d][1] = 1.0;
        cols.push(stacked(m, &w, 1)?);
    }
    Ok(DMatrix::from_columns(&cols))
}

fn least_squares(j: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    j.clone().svd(true, true).solve(b, 1e-14).ok()
}

/// Moves the dependent coordinates of `v` onto the loops: their values (Newton from those
/// drawn), rates and accelerations. Err with the reason when a loop does not close.
pub(super) fn settle(m: &NumericModel, v: &mut Values) -> Result<(), String> {
    if m.closures.is_empty() && m.rolling.is_empty() && determining(m).next().is_none() {
        return Ok(());
    }
    let looped: Vec<usize> = m
        .closures
        .iter()
        .flat_map(|c| c.dependent.clone())
        .collect();
    let dep = dependents(m);
    let scale = v.params.iter().map(|p| p.abs()).fold(1.0_f64, f64::max);
    let err = |e: NumericError| e.to_string();
    let at_rest = |v: &Values| Values {
        params: v.params.clone(),
        coords: v.coords.iter().map(|c| [c[0], 0.0, 0.0]).collect(),
        time: v.time,
    };
    let mut closed = false;
    for _ in 0..NEWTON_STEPS {
        let f = stacked(m, &at_rest(v), 0).map_err(err)?;
        if f.amax() <= CLOSED_TOL * scale {
            closed = true;
            break;
        }
        // The loops' rows only: a rolling condition ties no positions.
        let j = jacobian(m, v, &looped)
            .map_err(err)?
            .rows(0, f.len())
            .into_owned();
        let Some(dq) = least_squares(&j, &(-f)) else {
            break;
        };
        for (k, &d) in looped.iter().enumerate() {
            v.coords[d][0] += dq[k];
        }
    }
    if !closed {
        return Err("the loop does not close here (Newton's method found no position)".into());
    }
    let j = jacobian(m, v, &dep).map_err(err)?;
    // J_d q̇_d = −(the loop's rate with the dependent rates at 0).
    for &d in &dep {
        v.coords[d][1] = 0.0;
        v.coords[d][2] = 0.0;
    }
    let b = stacked(m, v, 1).map_err(err)?;
    let qd = least_squares(&j, &(-&b)).ok_or("the loop's rates are singular here")?;
    for (k, &d) in dep.iter().enumerate() {
        v.coords[d][1] = qd[k];
    }
    // J_d q̈_d = −(the loop's second derivative with the dependent q̈ at 0).
    let b = stacked(m, v, 2).map_err(err)?;
    let qdd = least_squares(&j, &(-&b)).ok_or("the loop's accelerations are singular here")?;
    for (k, &d) in dep.iter().enumerate() {
        v.coords[d][2] = qdd[k];
    }
    // The solution must close the loop at every order, not only in the least-squares sense.
    for k in 0..3 {
        let r = stacked(m, v, k).map_err(err)?;
        if r.amax() > 1e-9 * scale.max(1.0) {
            return Err(format!(
                "the loop does not close at order {k} of d/dt here (residual {:e}): the \
                 closure determines its coordinates only in part",
                r.amax()
            ));
        }
    }
    Ok(())
}

/// The closures' shape, checked at three configurations (parameters fixed, coordinates
/// varied): each closure's nonzero ground components as many as its dependent coordinates,
/// none without a coordinate, and their derivative invertible in the dependent rates.
pub(super) fn validate_shape(m: &NumericModel) -> Result<(), NumericError> {
    screw_motions_hold(m)?;
    if m.closures.is_empty() && m.rolling.is_empty() && determining(m).next().is_none() {
        return Ok(());
    }
    let configs: Vec<Values> = (0..3)
        .map(|c| Values {
            params: (0..m.params.len())
                .map(|i| 0.6 + 0.29 * (i % 5) as f64)
                .collect(),
            coords: (0..m.coords.len())
                .map(|j| [0.3 + 0.41 * j as f64 + 0.77 * c as f64, 0.0, 0.0])
                .collect(),
            time: 0.0,
        })
        .collect();
    let mut at = Vec::new();
    for v in &configs {
        at.push(loops(m, v)?);
    }
    let rank_needed = closure_relations(m, &at)?
        + rolling_relations(m, &configs)?
        + helix_relations(m, &configs)?;
    let dep = dependents(m);
    let full = configs.iter().any(|v| {
        jacobian(m, v, &dep).is_ok_and(|j| j.rank(1e-9 * j.amax().max(1e-300)) == rank_needed)
    });
    if !full {
        let place = match (m.closures.is_empty(), m.rolling.is_empty()) {
            (false, true) => "closures".to_string(),
            (true, false) => "rolling".to_string(),
            (true, true) => determining(m)
                .next()
                .map(|h| format!("links[{}].dependent", h.link))
                .unwrap_or_default(),
            _ => "closures and rolling".to_string(),
        };
        return Err(super::model::spec_err(
            place,
            "the closures, rolling conditions and helical links do not determine their \
             dependent coordinates: their relations are redundant",
        ));
    }
    Ok(())
}

/// Three configurations with every rate drawn (parameters fixed), where the relations are read.
fn moving_configs(m: &NumericModel) -> Vec<Values> {
    (0..3)
        .map(|c| Values {
            params: (0..m.params.len())
                .map(|i| 0.6 + 0.29 * (i % 5) as f64)
                .collect(),
            coords: (0..m.coords.len())
                .map(|j| {
                    let x = 0.3 + 0.41 * j as f64 + 0.77 * c as f64;
                    [x, 0.9 - 0.37 * x, 0.5 * x - 0.2]
                })
                .collect(),
            time: 0.0,
        })
        .collect()
}

/// A helical link that determines no coordinate: the positions must follow its screw motion,
/// its relation zero whatever the rates (checked at three moving configurations).
fn screw_motions_hold(m: &NumericModel) -> Result<(), NumericError> {
    let free: Vec<&Helix> = m.helices.iter().filter(|h| h.dependent.is_none()).collect();
    if free.is_empty() {
        return Ok(());
    }
    for v in moving_configs(m) {
        let st = state(m, &v)?;
        for h in &free {
            let [c, _] = helix_row(&st, &v, h)?;
            let scale = v.params.iter().fold(1.0_f64, |a, p| a.max(p.abs()));
            if c.abs() > 1e-9 * scale {
                return Err(super::model::spec_err(
                    format!("links[{}].dependent", h.link),
                    "the positions do not follow the screw motion V(P,2/1)·u = p/(2π) \
                     Ω(2/1)·u: name the coordinate whose rate the link determines",
                ));
            }
        }
    }
    Ok(())
}

/// Each helical link that determines a coordinate: its relation must hold a rate. Returns
/// their count (one relation each).
fn helix_relations(m: &NumericModel, configs: &[Values]) -> Result<usize, NumericError> {
    let all: Vec<usize> = (0..m.coords.len()).collect();
    let jacobians: Vec<DMatrix<f64>> = (configs.iter())
        .filter_map(|v| jacobian(m, v, &all).ok())
        .collect();
    let first = (jacobians.first().map_or(0, |j| j.nrows())).saturating_sub(determining(m).count());
    for (n, h) in determining(m).enumerate() {
        let holds = jacobians
            .iter()
            .any(|j| j.row(first + n).amax() > 1e-12 * j.amax().max(1e-300));
        if !holds {
            return Err(super::model::spec_err(
                format!("links[{}].dependent", h.link),
                "the link's relation holds whatever the rates: name no coordinate it determines",
            ));
        }
    }
    Ok(determining(m).count())
}

/// The closures' scalar relations, counted from their values `at` the configurations: each
/// nonzero ground component must vary, and they must be as many as the dependent
/// coordinates.
fn closure_relations(
    m: &NumericModel,
    at: &[Vec<Vector3<num_dual::Dual2_64>>],
) -> Result<usize, NumericError> {
    let axes = ["x", "y", "z"];
    let mut count = 0;
    for (i, c) in m.closures.iter().enumerate() {
        let path = format!("closures[{i}].vector");
        let mut n = 0;
        for k in 0..3 {
            let vals: Vec<f64> = at.iter().map(|l| l[i][k].re).collect();
            let size = vals.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
            if size <= 1e-12 {
                continue;
            }
            if vals.iter().all(|x| (x - vals[0]).abs() <= 1e-12 * size) {
                return Err(super::model::spec_err(
                    path,
                    format!(
                        "its component on the ground's {} axis holds no coordinate: the loop \
                         does not close",
                        axes[k]
                    ),
                ));
            }
            n += 1;
        }
        if n != c.dependent.len() {
            return Err(super::model::spec_err(
                path,
                format!(
                    "it gives {n} scalar relations on the ground's basis for {} dependent \
                     coordinates: as many relations as dependent coordinates",
                    c.dependent.len()
                ),
            ));
        }
        count += n;
    }
    Ok(count)
}

/// Each rolling condition: its relations, linear in the rates, of rank its dependent
/// coordinates' count over all the rates. Returns the sum of the ranks.
fn rolling_relations(m: &NumericModel, configs: &[Values]) -> Result<usize, NumericError> {
    let mut count = 0;
    let mut row = 3 * m.closures.len();
    for (i, r) in m.rolling.iter().enumerate() {
        let n = if r.on.is_empty() { 3 } else { r.on.len() };
        let all: Vec<usize> = (0..m.coords.len()).collect();
        let rank = configs
            .iter()
            .filter_map(|v| jacobian(m, v, &all).ok())
            .map(|j| {
                let part = j.rows(row, n).into_owned();
                part.rank(1e-9 * part.amax().max(1e-300))
            })
            .max()
            .unwrap_or(0);
        let path = format!("rolling[{i}].velocity");
        if rank == 0 {
            return Err(super::model::spec_err(
                path,
                "the velocity is zero whatever the rates: it imposes nothing",
            ));
        }
        if rank != r.dependent.len() {
            return Err(super::model::spec_err(
                path,
                format!(
                    "it gives {rank} independent relations for {} dependent coordinates",
                    r.dependent.len()
                ),
            ));
        }
        count += rank;
        row += n;
    }
    Ok(count)
}
