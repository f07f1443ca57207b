//! Motion through the frame chain with dual numbers: positions, velocities and accelerations
//! of points, and Ω, in every frame (the quantities are evaluated from them in `quantities.rs`).

use super::expr::{self, Env};
use super::la::{mat_parts, parts};
use super::{NumericError, NumericModel, Sample};
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
    /// The time t.
    pub time: f64,
}

impl Values {
    /// An environment for constant expressions (parameters only).
    pub fn constants(&self) -> Env<'_, f64> {
        Env {
            params: &self.params,
            coords: &[],
            rates: &[],
            frames: &[],
            time: 0.0,
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
        time: s.time,
    };
    if !s.time.is_finite() {
        return Err(bad("the time `t` is not finite".to_string()));
    }
    for c in &m.coords {
        let v = *s
            .coordinates
            .get(&c.name)
            .ok_or_else(|| bad(format!("missing coordinate `{}`", c.name)))?;
        if v.iter().any(|x| !x.is_finite()) {
            return Err(bad(format!("coordinate `{}` is not finite", c.name)));
        }
        if let (Some(rate), true) = (&c.rate, c.driven) {
            let w =
                driven(rate, &vals_with(&vals, s, m)?).map_err(|e| NumericError::Evaluation {
                    what: format!("the rate of `{}`", c.name),
                    message: e,
                })?;
            if (v[1] - w[0]).abs() > RATE_TOL * w[0].abs().max(1.0)
                || (v[2] - w[1]).abs() > RATE_TOL * w[1].abs().max(1.0)
            {
                return Err(bad(format!(
                    "coordinate `{}` is driven by `{}` = [{}, {}] here, not {v:?}",
                    c.name,
                    c.rate_text.as_deref().unwrap_or(""),
                    w[0],
                    w[1]
                )));
            }
        } else if let Some(rate) = &c.rate {
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

/// The sample's coordinates as given, for a driven rate that reads them (before they are
/// checked).
fn vals_with(vals: &Values, s: &Sample, m: &NumericModel) -> Result<Values, NumericError> {
    let mut coords = Vec::with_capacity(m.coords.len());
    for c in &m.coords {
        coords.push(s.coordinates.get(&c.name).copied().unwrap_or([f64::NAN; 3]));
    }
    Ok(Values {
        params: vals.params.clone(),
        coords,
        time: vals.time,
    })
}

/// [q̇, q̈] of a coordinate whose rate is driven by the others' (linear in their rates,
/// see `expr::rate_degree`, with coefficients that may hold the coordinates, ẋ = R θ̇ cos ψ):
/// the form evaluated along the motion with dual numbers in t, each coordinate
/// q + q̇ t + ½ q̈ t² and each rate q̇ + q̈ t; its value and its first derivative.
pub(super) fn driven(rate: &expr::Node, vals: &Values) -> Result<[f64; 2], String> {
    let qs: Vec<D2> = vals
        .coords
        .iter()
        .map(|c| D2::new(c[0], c[1], c[2]))
        .collect();
    let rates: Vec<[D2; 2]> = vals
        .coords
        .iter()
        .map(|c| [D2::new(c[1], c[2], 0.0), D2::new(c[2], 0.0, 0.0)])
        .collect();
    let params: Vec<f64> = vals.params.clone();
    let env = Env {
        params: &params,
        coords: &qs,
        rates: &rates,
        frames: &[],
        time: D2::new(vals.time, 1.0, 0.0),
    };
    let v = expr::eval_scalar(rate, &env)?;
    Ok([v.re, v.v1])
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
    // The time, followed like a coordinate of rate 1.
    let time = D2::new(v.time, 1.0, 0.0);
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
                    time,
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
        time,
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

/// V(P ∈ i/j) in ground components, P given by its ground position at t = 0: the material
/// point of i there, moved with i and differentiated in j.
pub(super) fn velocity_at(st: &State, i: usize, p: &Vector3<f64>, j: usize) -> Vector3<f64> {
    let [_, v, _] = parts(&st.track(i, &st.local0(i, p), j));
    st.rot0(j) * v
}

/// V(P, i/j) and Γ(P, i/j) in ground components: the point of i that coincides with P at
/// t = 0, moved with i and differentiated in j.
pub(super) fn point_motion(st: &State, p: usize, i: usize, j: usize) -> [Vector3<f64>; 2] {
    let u = st.local0(i, &st.pos0(p));
    let [_, v, g] = parts(&st.track(i, &u, j));
    let rj = st.rot0(j);
    [rj * v, rj * g]
}
