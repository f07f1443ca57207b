//! Motion through the frame chain with dual numbers, and the quantities as the course defines them.

use super::expr::{self, Env, Node};
use super::la::{mat_parts, parts, point_inertia, rows};
use super::model::{Context, Names};
use super::{NumValue, NumericError, NumericModel, Sample, cloud, dynamics};
use crate::quantity::{Motion, Quantity, QuantityKind};
use nalgebra::{Matrix3, Vector3};
use num_dual::{Dual2_64, DualNum};

type D2 = Dual2_64;

/// Relative tolerance for an imposed rate given again in a sample.
const RATE_TOL: f64 = 1e-9;

/// A sample resolved to the model's indices.
pub(super) struct Values {
    pub params: Vec<f64>,
    /// [q, q̇, q̈] per coordinate.
    pub coords: Vec<[f64; 3]>,
}

impl Values {
    /// An environment for constant expressions (parameters only).
    pub fn constants(&self) -> Env<'_, f64> {
        Env {
            params: &self.params,
            coords: &[],
            rates: &[],
            frames: &[],
        }
    }

    /// The coordinates' values and their (q̇, q̈), as an [`Env`] takes them.
    pub fn split(&self) -> (Vec<f64>, Vec<[f64; 2]>) {
        (
            self.coords.iter().map(|c| c[0]).collect(),
            self.coords.iter().map(|c| [c[1], c[2]]).collect(),
        )
    }
}

/// Resolves a sample: every name known, every value present and finite, imposed rates kept.
pub(super) fn values(m: &NumericModel, s: &Sample) -> Result<Values, NumericError> {
    let bad = |msg: String| NumericError::Sample(msg);
    for name in s.parameters.keys() {
        if !m.param_index.contains_key(name) {
            return Err(bad(format!("unknown parameter `{name}`")));
        }
    }
    for name in s.coordinates.keys() {
        if !m.coord_index.contains_key(name) {
            return Err(bad(format!("unknown coordinate `{name}`")));
        }
    }
    let mut params = Vec::with_capacity(m.params.len());
    for p in &m.params {
        let v = *s
            .parameters
            .get(&p.name)
            .ok_or_else(|| bad(format!("missing parameter `{}`", p.name)))?;
        if !v.is_finite() {
            return Err(bad(format!("parameter `{}` is not finite", p.name)));
        }
        params.push(v);
    }
    let mut vals = Values {
        params,
        coords: Vec::with_capacity(m.coords.len()),
    };
    for c in &m.coords {
        let v = *s
            .coordinates
            .get(&c.name)
            .ok_or_else(|| bad(format!("missing coordinate `{}`", c.name)))?;
        if v.iter().any(|x| !x.is_finite()) {
            return Err(bad(format!("coordinate `{}` is not finite", c.name)));
        }
        if let Some(rate) = &c.rate {
            let w = expr::eval_scalar(rate, &vals.constants()).map_err(|e| {
                NumericError::Evaluation {
                    what: format!("imposed rate of `{}`", c.name),
                    message: e,
                }
            })?;
            if (v[1] - w).abs() > RATE_TOL * w.abs().max(1.0) || v[2] != 0.0 {
                return Err(bad(format!(
                    "coordinate `{}` has the imposed rate `{}` = {w}, so its [q, q̇, q̈] must be \
                     [q, {w}, 0], not {v:?}",
                    c.name,
                    c.rate_text.as_deref().unwrap_or("")
                )));
            }
        }
        vals.coords.push(v);
    }
    Ok(vals)
}

/// Every frame's orientation and every point's position at t → 0, as dual numbers in t.
pub(super) struct State {
    /// Per frame: column k is its k-th basis vector in ground components.
    pub rot: Vec<Matrix3<D2>>,
    /// Per point: position from the ground origin, ground components.
    pub pos: Vec<Vector3<D2>>,
    /// Per frame: index of its origin point.
    origin: Vec<usize>,
}

impl State {
    /// Orientation of frame `f` at t = 0.
    pub fn rot0(&self, f: usize) -> Matrix3<f64> {
        self.rot[f].map(|x| x.re)
    }

    /// Position of point `p` at t = 0.
    pub fn pos0(&self, p: usize) -> Vector3<f64> {
        self.pos[p].map(|x| x.re)
    }

    /// Origin of frame `f` as a function of t.
    pub fn origin(&self, f: usize) -> Vector3<D2> {
        self.pos[self.origin[f]]
    }

    /// Components in frame `f`'s basis, from its origin, of the ground-component point `p`
    /// at t = 0.
    pub fn local0(&self, f: usize, p: &Vector3<f64>) -> Vector3<f64> {
        self.rot0(f).transpose() * (p - self.origin(f).map(|x| x.re))
    }

    /// Path of the material point of frame `i` with local coordinates `u`, seen from frame
    /// `j`: components in j's basis from j's origin, r(t) = R_jᵀ (O_i + R_i u − O_j).
    pub fn track(&self, i: usize, u: &Vector3<f64>, j: usize) -> Vector3<D2> {
        let p = self.origin(i) + self.rot[i] * u.map(D2::from);
        self.rot[j].transpose() * (p - self.origin(j))
    }
}

/// Rotation matrix of an elementary rotation about `axis` of the parent by `a`: its columns are
/// the new basis vectors in the parent's components.
///
/// Written out rather than `Rotation3::from_axis_angle`, which returns the identity when
/// `a == 0`: a dual number compares by its real part, so q = 0 would drop q̇ and q̈.
fn elementary(axis: usize, a: D2) -> Matrix3<D2> {
    let (s, c) = (a.sin(), a.cos());
    let mut m = Matrix3::identity();
    let (b, d) = ((axis + 1) % 3, (axis + 2) % 3);
    m[(b, b)] = c;
    m[(d, b)] = s;
    m[(b, d)] = -s;
    m[(d, d)] = c;
    m
}

/// Places every frame and point of the model at the sampled instant.
pub(super) fn state(m: &NumericModel, v: &Values) -> Result<State, NumericError> {
    let coords: Vec<D2> = v.coords.iter().map(|c| D2::new(c[0], c[1], c[2])).collect();
    let rates: Vec<[D2; 2]> = v
        .coords
        .iter()
        .map(|c| [D2::from(c[1]), D2::from(c[2])])
        .collect();
    let mut rot = vec![Matrix3::<D2>::identity(); m.frames.len()];
    for (k, f) in m.frames.iter().enumerate().skip(1) {
        let parent = rot[f.parent];
        rot[k] = match &f.rotation {
            None => parent,
            Some((axis, sign, angle)) => {
                let env = Env {
                    params: &v.params,
                    coords: &coords,
                    rates: &rates,
                    frames: &[],
                };
                let a = expr::eval_scalar(angle, &env).map_err(|e| NumericError::Evaluation {
                    what: format!("rotation angle of frame {}", f.name),
                    message: e,
                })?;
                parent * elementary(*axis, a * *sign)
            }
        };
    }
    let env = Env {
        params: &v.params,
        coords: &coords,
        rates: &rates,
        frames: &rot,
    };
    let mut pos = vec![Vector3::<D2>::zeros(); m.points.len()];
    for (k, p) in m.points.iter().enumerate().skip(1) {
        let d = expr::eval_vector(&p.position, &env).map_err(|e| NumericError::Evaluation {
            what: format!("position of point {}", p.name),
            message: e,
        })?;
        pos[k] = pos[p.from] + d;
    }
    Ok(State {
        rot,
        pos,
        origin: m.frames.iter().map(|f| f.origin).collect(),
    })
}

impl NumericModel {
    fn frame(&self, name: &str) -> Result<usize, NumericError> {
        self.frame_index
            .get(name)
            .copied()
            .ok_or_else(|| NumericError::Unknown {
                what: "frame".into(),
                name: name.into(),
            })
    }

    fn point(&self, name: &str) -> Result<usize, NumericError> {
        self.point_index
            .get(name)
            .copied()
            .ok_or_else(|| NumericError::Unknown {
                what: "point".into(),
                name: name.into(),
            })
    }

    /// The frame carried by a solid, or a frame by name.
    fn body_frame(&self, name: &str, q: &Quantity) -> Result<usize, NumericError> {
        if let Some(s) = self.solid_index.get(name) {
            return Ok(self.solids[*s].frame);
        }
        if let Some(f) = self.frame_index.get(name) {
            return Ok(*f);
        }
        if self.sets.contains_key(name) {
            return Err(NumericError::Quantity {
                quantity: q.to_string(),
                message: format!("`{name}` is a set: this quantity takes a solid or a frame"),
            });
        }
        Err(NumericError::Unknown {
            what: "solid or frame".into(),
            name: name.into(),
        })
    }

    /// The solids of a solid or set name.
    fn solids_of(&self, name: &str) -> Result<Vec<usize>, NumericError> {
        if let Some(s) = self.solid_index.get(name) {
            return Ok(vec![*s]);
        }
        if let Some(list) = self.sets.get(name) {
            return Ok(list.clone());
        }
        Err(NumericError::Unknown {
            what: "solid or set".into(),
            name: name.into(),
        })
    }
}

/// Ω(i/j) in ground components, from its definition: with R = R_jᵀ R_i the orientation of i
/// in j, dR/dt Rᵀ is the skew matrix of Ω(i/j) in j's basis.
pub(super) fn omega(st: &State, i: usize, j: usize) -> Vector3<f64> {
    let [r0, dr] = mat_parts(&(st.rot[j].transpose() * st.rot[i]));
    let w = dr * r0.transpose();
    let in_j = Vector3::new(
        0.5 * (w[(2, 1)] - w[(1, 2)]),
        0.5 * (w[(0, 2)] - w[(2, 0)]),
        0.5 * (w[(1, 0)] - w[(0, 1)]),
    );
    st.rot0(j) * in_j
}

/// V(P, i/j) and Γ(P, i/j) in ground components: the point of i that coincides with P at
/// t = 0, moved with i and differentiated in j.
pub(super) fn point_motion(st: &State, p: usize, i: usize, j: usize) -> [Vector3<f64>; 2] {
    let u = st.local0(i, &st.pos0(p));
    let [_, v, g] = parts(&st.track(i, &u, j));
    let rj = st.rot0(j);
    [rj * v, rj * g]
}

/// Σ mₖ V, Σ mₖ APₖ ∧ V, Σ mₖ Γ, Σ mₖ APₖ ∧ Γ over the clouds of `solids`, motion relative
/// to frame `j`, A = point `a`; ground components.
pub(super) fn kinetic(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    solids: &[usize],
    j: usize,
    a: usize,
) -> Result<[Vector3<f64>; 4], NumericError> {
    let a_j = st.local0(j, &st.pos0(a));
    let mut acc = [Vector3::zeros(); 4];
    for s in solids {
        let f = m.solids[*s].frame;
        for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
            let [r, v, g] = parts(&st.track(f, &u, j));
            let ap = r - a_j;
            acc[0] += v * mk;
            acc[1] += ap.cross(&v) * mk;
            acc[2] += g * mk;
            acc[3] += ap.cross(&g) * mk;
        }
    }
    let rj = st.rot0(j);
    Ok(acc.map(|x| rj * x))
}

/// Ec = Σ ½ mₖ |V(Pₖ/Rj)|² over the clouds of `solids`, motion relative to frame `j`.
fn kinetic_energy(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    solids: &[usize],
    j: usize,
) -> Result<f64, NumericError> {
    let mut e = 0.0;
    for s in solids {
        let f = m.solids[*s].frame;
        for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
            let [_, v, _] = parts(&st.track(f, &u, j));
            e += 0.5 * mk * v.norm_squared();
        }
    }
    Ok(e)
}

/// I(P, S) = Σ mₖ (|PPₖ|² Id − PPₖ PPₖᵀ), ground components.
fn inertia(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    solids: &[usize],
    p: usize,
) -> Result<Matrix3<f64>, NumericError> {
    let p0 = st.pos0(p);
    let mut acc = Matrix3::zeros();
    for s in solids {
        let f = m.solids[*s].frame;
        let (rf, of) = (st.rot0(f), st.origin(f).map(|x| x.re));
        for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
            acc += point_inertia(&(of + rf * u - p0)) * mk;
        }
    }
    Ok(acc)
}

enum Raw {
    Scalar(f64),
    Vector(Vector3<f64>),
    Matrix(Matrix3<f64>),
    Torsor(String, Vector3<f64>, Vector3<f64>),
}

pub(super) fn evaluate(
    m: &NumericModel,
    q: &Quantity,
    sample: &Sample,
    default_basis: &str,
) -> Result<NumValue, NumericError> {
    let vals = values(m, sample)?;
    let st = state(m, &vals)?;
    let basis_name = q.basis.as_deref().unwrap_or(default_basis);
    let frames = |mo: &Motion| -> Result<(usize, usize), NumericError> {
        Ok((
            m.body_frame(&mo.moving, q)?,
            m.body_frame(&mo.reference, q)?,
        ))
    };
    let kin = |mo: &Motion, a: usize| -> Result<[Vector3<f64>; 4], NumericError> {
        let solids = m.solids_of(&mo.moving)?;
        let j = m.body_frame(&mo.reference, q)?;
        kinetic(m, &st, &vals, &solids, j, a)
    };
    use QuantityKind as K;
    let raw = match &q.kind {
        K::Omega(mo) => {
            let (i, j) = frames(mo)?;
            Raw::Vector(omega(&st, i, j))
        }
        K::Velocity { point, motion } | K::Acceleration { point, motion } => {
            let (i, j) = frames(motion)?;
            let [v, g] = point_motion(&st, m.point(point)?, i, j);
            Raw::Vector(if matches!(q.kind, K::Velocity { .. }) {
                v
            } else {
                g
            })
        }
        K::Inertia { point, solid } => {
            let solids = m.solids_of(solid)?;
            Raw::Matrix(inertia(m, &st, &vals, &solids, m.point(point)?)?)
        }
        K::KineticResultant(mo) => Raw::Vector(kin(mo, 0)?[0]),
        K::DynamicResultant(mo) => Raw::Vector(kin(mo, 0)?[2]),
        K::KineticMoment { point, motion } => Raw::Vector(kin(motion, m.point(point)?)?[1]),
        K::DynamicMoment { point, motion } => Raw::Vector(kin(motion, m.point(point)?)?[3]),
        K::KinematicTorsor { motion, point } => {
            let (i, j) = frames(motion)?;
            let [v, _] = point_motion(&st, m.point(point)?, i, j);
            Raw::Torsor(point.clone(), omega(&st, i, j), v)
        }
        K::KineticTorsor { motion, point } => {
            let k = kin(motion, m.point(point)?)?;
            Raw::Torsor(point.clone(), k[0], k[1])
        }
        K::DynamicTorsor { motion, point } => {
            let k = kin(motion, m.point(point)?)?;
            Raw::Torsor(point.clone(), k[2], k[3])
        }
        K::KineticEnergy(mo) => {
            let solids = m.solids_of(&mo.moving)?;
            let j = m.body_frame(&mo.reference, q)?;
            Raw::Scalar(kinetic_energy(m, &st, &vals, &solids, j)?)
        }
        K::Unknown(name) => Raw::Scalar(dynamics::unknown(m, &st, &vals, name)?),
        K::Eom(c) => Raw::Scalar(dynamics::eom(m, &st, &vals, c)?),
    };
    let not_finite = || NumericError::Quantity {
        quantity: q.to_string(),
        message: "the value is not finite at this sample".into(),
    };
    // The basis is only looked up when the result is written in it (not for a projection).
    let rb = if q.projection.is_none() && !matches!(raw, Raw::Scalar(_)) {
        st.rot0(m.frame(basis_name)?)
    } else {
        Matrix3::identity()
    };
    let rbt = rb.transpose();
    let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
    match (raw, &q.projection) {
        (Raw::Scalar(x), None) => {
            if !x.is_finite() {
                return Err(not_finite());
            }
            Ok(NumValue::Scalar(x))
        }
        (Raw::Vector(v), Some((frame, axis))) => {
            let k = match axis {
                'x' => 0,
                'y' => 1,
                'z' => 2,
                _ => {
                    return Err(NumericError::Quantity {
                        quantity: q.to_string(),
                        message: format!("`{axis}` is not an axis"),
                    });
                }
            };
            let x = v.dot(&st.rot0(m.frame(frame)?).column(k));
            if !x.is_finite() {
                return Err(not_finite());
            }
            Ok(NumValue::Scalar(x))
        }
        (Raw::Vector(v), None) => {
            let value: [f64; 3] = (rbt * v).into();
            if !finite(&value) {
                return Err(not_finite());
            }
            Ok(NumValue::Vector {
                basis: basis_name.to_string(),
                value,
            })
        }
        (Raw::Matrix(mat), None) => {
            let value = rows(&(rbt * mat * rb));
            if !finite(value.as_flattened()) {
                return Err(not_finite());
            }
            Ok(NumValue::Matrix {
                basis: basis_name.to_string(),
                value,
            })
        }
        (Raw::Torsor(point, r, mo), None) => {
            let (resultant, moment): ([f64; 3], [f64; 3]) = ((rbt * r).into(), (rbt * mo).into());
            if !finite(&resultant) || !finite(&moment) {
                return Err(not_finite());
            }
            Ok(NumValue::Torsor {
                point,
                basis: basis_name.to_string(),
                resultant,
                moment,
            })
        }
        (_, Some(_)) => Err(NumericError::Quantity {
            quantity: q.to_string(),
            message: "only a vector can be projected".into(),
        }),
    }
}

pub(super) fn evaluate_expression(
    m: &NumericModel,
    text: &str,
    sample: &Sample,
) -> Result<f64, NumericError> {
    let names = Names {
        params: &m.param_index,
        coords: &m.coord_index,
        frames: &m.frame_index,
    };
    let node: Node = names
        .parse(text, Context::Instant)
        .map_err(|e| NumericError::Evaluation {
            what: format!("expression `{text}`"),
            message: e,
        })?;
    let vals = values(m, sample)?;
    let (coords, rates) = vals.split();
    let env = Env {
        params: &vals.params,
        coords: &coords,
        rates: &rates,
        frames: &[],
    };
    let x = expr::eval_scalar(&node, &env).map_err(|e| NumericError::Evaluation {
        what: format!("expression `{text}`"),
        message: e,
    })?;
    if !x.is_finite() {
        return Err(NumericError::Evaluation {
            what: format!("expression `{text}`"),
            message: "the value is not finite".into(),
        });
    }
    Ok(x)
}
