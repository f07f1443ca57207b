//! The quantities of the course evaluated at a sample, from their definitions: sums over the
//! clouds of points of each solid ([`super::cloud`]), the motion of the frames
//! ([`super::kin`]) and the float PFD ([`super::dynamics`]).

use super::cloud::{kinetic, kinetic_energy};
use super::expr::{self, Env, Node};
use super::kin::{State, Values, omega, point_motion, state, values};
use super::la::{parts, point_inertia, rows};
use super::model::Context;
use super::{NumValue, NumericError, NumericModel, Sample, cloud, dynamics};
use crate::quantity::{ActionRef, Motion, Quantity, QuantityKind};
use nalgebra::{Matrix3, Vector3};
use num_dual::Dual2_64;
use std::collections::BTreeMap;

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
    unknowns: &BTreeMap<String, f64>,
    default_basis: &str,
) -> Result<NumValue, NumericError> {
    let vals = values(m, sample)?;
    let st = state(m, &vals)?;
    let at = At {
        m,
        q,
        st,
        vals,
        unknowns,
    };
    let raw = at.raw()?;
    at.written(raw, q.basis.as_deref().unwrap_or(default_basis))
}

/// A quantity at a placed sample.
struct At<'a> {
    m: &'a NumericModel,
    q: &'a Quantity,
    st: State,
    vals: Values,
    unknowns: &'a BTreeMap<String, f64>,
}

/// The resultant and the moment of an action, each evaluated on its own.
type Parts = [Result<Vector3<f64>, NumericError>; 2];

impl At<'_> {
    /// The frames of a motion i/j.
    fn frames(&self, mo: &Motion) -> Result<(usize, usize), NumericError> {
        Ok((
            self.m.body_frame(&mo.moving, self.q)?,
            self.m.body_frame(&mo.reference, self.q)?,
        ))
    }

    /// The kinetic and dynamic resultants and moments at point `a` of a motion.
    fn kin(&self, mo: &Motion, a: usize) -> Result<[Vector3<f64>; 4], NumericError> {
        let solids = self.m.solids_of(&mo.moving)?;
        let j = self.m.body_frame(&mo.reference, self.q)?;
        kinetic(self.m, &self.st, &self.vals, &solids, j, a)
    }

    /// The actions of `a.from` on `a.on`, at point p (the ground origin for a resultant).
    fn action(&self, a: &ActionRef, p: usize) -> Result<Parts, NumericError> {
        let solids = self.m.solids_of(&a.on)?;
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        dynamics::action(m, st, vals, &a.from, &solids, &a.on, p, self.unknowns)
    }

    /// The quantity's value in ground components, before any basis or projection.
    fn raw(&self) -> Result<Raw, NumericError> {
        let (m, st, vals, q) = (self.m, &self.st, &self.vals, self.q);
        use QuantityKind as K;
        Ok(match &q.kind {
            K::Omega(mo) => {
                let (i, j) = self.frames(mo)?;
                Raw::Vector(omega(st, i, j))
            }
            K::Velocity { point, motion } | K::Acceleration { point, motion } => {
                let (i, j) = self.frames(motion)?;
                let [v, g] = point_motion(st, m.point(point)?, i, j);
                Raw::Vector(if matches!(q.kind, K::Velocity { .. }) {
                    v
                } else {
                    g
                })
            }
            K::Inertia { point, solid } => {
                let solids = m.solids_of(solid)?;
                Raw::Matrix(inertia(m, st, vals, &solids, m.point(point)?)?)
            }
            K::KineticResultant(mo) => Raw::Vector(self.kin(mo, 0)?[0]),
            K::DynamicResultant(mo) => Raw::Vector(self.kin(mo, 0)?[2]),
            K::KineticMoment { point, motion } => {
                Raw::Vector(self.kin(motion, m.point(point)?)?[1])
            }
            K::DynamicMoment { point, motion } => {
                Raw::Vector(self.kin(motion, m.point(point)?)?[3])
            }
            K::KinematicTorsor { motion, point } => {
                let (i, j) = self.frames(motion)?;
                let [v, _] = point_motion(st, m.point(point)?, i, j);
                Raw::Torsor(point.clone(), omega(st, i, j), v)
            }
            K::KineticTorsor { motion, point } => {
                let k = self.kin(motion, m.point(point)?)?;
                Raw::Torsor(point.clone(), k[0], k[1])
            }
            K::DynamicTorsor { motion, point } => {
                let k = self.kin(motion, m.point(point)?)?;
                Raw::Torsor(point.clone(), k[2], k[3])
            }
            K::KineticEnergy(mo) => {
                let solids = m.solids_of(&mo.moving)?;
                let j = m.body_frame(&mo.reference, q)?;
                Raw::Scalar(kinetic_energy(m, st, vals, &solids, j)?)
            }
            K::Unknown(name) => Raw::Scalar(dynamics::unknown(m, st, vals, name)?),
            K::Eom(c) => Raw::Scalar(dynamics::eom(m, st, vals, c, self.unknowns)?),
            K::ActionResultant(a) => {
                let [r, _] = self.action(a, 0)?;
                Raw::Vector(r?)
            }
            K::ActionMoment { point, action: a } => {
                let [_, mo] = self.action(a, m.point(point)?)?;
                Raw::Vector(mo?)
            }
            K::ActionTorsor { action: a, point } => {
                let [r, mo] = self.action(a, m.point(point)?)?;
                Raw::Torsor(point.clone(), r?, mo?)
            }
            K::Power {
                action: a,
                reference,
            } => Raw::Scalar(self.power(a, reference)?),
            K::EquivalentInertia(c) => Raw::Scalar(self.equivalent_inertia(c)?),
            // The sample's own rates: a dependent coordinate's come from this backend's
            // solution of the loops, not from the exact side's loop law.
            K::Rate { coordinate, order } => {
                Raw::Scalar(vals.coords[self.coordinate(coordinate)?][usize::from(*order)])
            }
            K::InternalPower(set) => Raw::Scalar(self.internal_power(set)?),
            K::Derivative { of, frame } => self.derivative(of, frame.as_deref())?,
        })
    }

    /// P(from->on/reference).
    fn power(&self, a: &ActionRef, reference: &str) -> Result<f64, NumericError> {
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        let solids = m.solids_of(&a.on)?;
        let j = m.body_frame(reference, self.q)?;
        let (from, on) = (&a.from, &a.on);
        dynamics::power(m, st, vals, from, &solids, on, j, self.unknowns)
    }

    /// P_int(set).
    fn internal_power(&self, set: &str) -> Result<f64, NumericError> {
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        let solids = m.solids_of(set)?;
        dynamics::internal_power(m, st, vals, &solids, self.unknowns)
    }

    /// J_eq(c) = 2 Ec(all/0)/q̇², from the clouds: the rate q̇ is the sample's.
    fn equivalent_inertia(&self, c: &str) -> Result<f64, NumericError> {
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        let all: Vec<usize> = (0..m.solids.len()).collect();
        let i = self.coordinate(c)?;
        let qd = vals.coords[i][1];
        Ok(2.0 * kinetic_energy(m, st, vals, &all, 0)? / (qd * qd))
    }

    /// The index of the coordinate named `c`.
    fn coordinate(&self, c: &str) -> Result<usize, NumericError> {
        (self.m.coords.iter().position(|x| x.name == c)).ok_or_else(|| NumericError::Quantity {
            quantity: self.q.to_string(),
            message: format!("unknown coordinate `{c}`"),
        })
    }

    /// The raw value written as asked: in basis `basis_name`, or projected; refused when a
    /// number of it is not finite.
    fn written(&self, raw: Raw, basis_name: &str) -> Result<NumValue, NumericError> {
        let q = self.q;
        let not_finite = || NumericError::Quantity {
            quantity: q.to_string(),
            message: "the value is not finite at this sample".into(),
        };
        // The basis is only looked up when the result is written in it (not for a projection).
        let rb = if q.projection.is_none() && !matches!(raw, Raw::Scalar(_)) {
            self.st.rot0(self.m.frame(basis_name)?)
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
                let x = self.projected(v, frame, *axis)?;
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
                let (resultant, moment): ([f64; 3], [f64; 3]) =
                    ((rbt * r).into(), (rbt * mo).into());
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

    /// v · the basis vector `axis` of `frame`.
    fn projected(&self, v: Vector3<f64>, frame: &str, axis: char) -> Result<f64, NumericError> {
        let k = match axis {
            'x' => 0,
            'y' => 1,
            'z' => 2,
            _ => {
                return Err(NumericError::Quantity {
                    quantity: self.q.to_string(),
                    message: format!("`{axis}` is not an axis"),
                });
            }
        };
        Ok(v.dot(&self.st.rot0(self.m.frame(frame)?).column(k)))
    }
}

pub(super) fn evaluate_expression(
    m: &NumericModel,
    text: &str,
    sample: &Sample,
) -> Result<f64, NumericError> {
    let names = m.names();
    let node: Node = names
        .parse(text, Context::Instant)
        .map_err(|e| NumericError::Evaluation {
            what: format!("expression `{}`", crate::excerpt::excerpt(text)),
            message: e,
        })?;
    let vals = values(m, sample)?;
    let (coords, rates) = vals.split();
    let env = Env {
        params: &vals.params,
        coords: &coords,
        rates: &rates,
        frames: &[],
        time: vals.time,
    };
    let x = expr::eval_scalar(&node, &env).map_err(|e| NumericError::Evaluation {
        what: format!("expression `{}`", crate::excerpt::excerpt(text)),
        message: e,
    })?;
    if !x.is_finite() {
        return Err(NumericError::Evaluation {
            what: format!("expression `{}`", crate::excerpt::excerpt(text)),
            message: "the value is not finite".into(),
        });
    }
    Ok(x)
}

/// A vector as a function of time at the sample: its value and its time derivative in the
/// ground frame, both in ground components.
type Moving = [Vector3<f64>; 2];

/// Value, first and second time derivatives of a dual matrix.
fn mat3(m: &Matrix3<Dual2_64>) -> [Matrix3<f64>; 3] {
    [m.map(|x| x.re), m.map(|x| x.v1), m.map(|x| x.v2)]
}

/// The vector of a skew matrix W (W x = w ∧ x).
fn vee(w: &Matrix3<f64>) -> Vector3<f64> {
    Vector3::new(
        0.5 * (w[(2, 1)] - w[(1, 2)]),
        0.5 * (w[(0, 2)] - w[(2, 0)]),
        0.5 * (w[(1, 0)] - w[(0, 1)]),
    )
}

/// The time derivatives of the quantities, from the dual parts of the motion (positions to
/// their second derivatives): d/dt of a scalar, and of a vector the derivative of its
/// components in the frame asked, nothing of the exact side's rules (no Bour formula).
impl At<'_> {
    /// d/dt(Q) of a scalar, or [d/dt Q]_r of a vector (ground components): with c = R_rᵀ u
    /// the components in r, ċ = Ṙ_rᵀ u + R_rᵀ u̇, written back in the ground's basis.
    fn derivative(&self, of: &Quantity, frame: Option<&str>) -> Result<Raw, NumericError> {
        let Some(r) = frame else {
            return Ok(Raw::Scalar(self.scalar_rate(of)?));
        };
        let f = self.m.body_frame(r, self.q)?;
        let [u, du] = self.moving(&of.kind)?;
        let [rr, dr, _] = mat3(&self.st.rot[f]);
        let dc = dr.transpose() * u + rr.transpose() * du;
        Ok(Raw::Vector(rr * dc))
    }

    /// d/dt of a scalar: Ec = Σ ½ mₖ |vₖ|² gives Σ mₖ vₖ·Γₖ; a projection u·e gives
    /// u̇·e + u·ė, e the basis vector turning with its frame.
    fn scalar_rate(&self, of: &Quantity) -> Result<f64, NumericError> {
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        match (&of.kind, &of.projection) {
            (QuantityKind::KineticEnergy(mo), None) => {
                let solids = m.solids_of(&mo.moving)?;
                let j = m.body_frame(&mo.reference, self.q)?;
                let mut rate = 0.0;
                for s in &solids {
                    let f = m.solids[*s].frame;
                    for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
                        let [_, v, g] = parts(&st.track(f, &u, j));
                        rate += mk * v.dot(&g);
                    }
                }
                Ok(rate)
            }
            (k, Some((frame, axis))) => {
                let [u, du] = self.moving(k)?;
                let [rr, dr, _] = mat3(&st.rot[m.frame(frame)?]);
                let a = ['x', 'y', 'z'].iter().position(|c| c == axis).unwrap_or(0);
                Ok(du.dot(&rr.column(a)) + u.dot(&dr.column(a)))
            }
            _ => Err(self.not_derivable(of)),
        }
    }

    fn not_derivable(&self, of: &Quantity) -> NumericError {
        NumericError::Quantity {
            quantity: self.q.to_string(),
            message: format!("the float backend has no derivative of `{of}`"),
        }
    }

    /// A vector given in j's components (x, its derivative dx of those components), in the
    /// ground's: R_j x and Ṙ_j x + R_j dx.
    fn in_ground(&self, j: usize, x: Vector3<f64>, dx: Vector3<f64>) -> Moving {
        let [rj, drj, _] = mat3(&self.st.rot[j]);
        [rj * x, drj * x + rj * dx]
    }

    /// Ω(i/j), V(P, i/j), Rc(S/j), σ(A, S/j) as functions of time, each from its definition.
    fn moving(&self, k: &QuantityKind) -> Result<Moving, NumericError> {
        let (m, st, vals) = (self.m, &self.st, &self.vals);
        match k {
            // R = R_jᵀ R_i: Ω(i/j) in j is the vector of W = Ṙ Rᵀ, and Ẇ = R̈ Rᵀ + Ṙ Ṙᵀ.
            QuantityKind::Omega(mo) => {
                let (i, j) = self.frames(mo)?;
                let [r, dr, ddr] = mat3(&(st.rot[j].transpose() * st.rot[i]));
                let w = dr * r.transpose();
                let dw = ddr * r.transpose() + dr * dr.transpose();
                Ok(self.in_ground(j, vee(&w), vee(&dw)))
            }
            // The point P(t) has local coordinates u(t) in i; the material point of i there
            // moves in j as B + A u (A = R_jᵀ R_i, B = R_jᵀ (O_i − O_j)): V = Ḃ + Ȧ u, whose
            // derivative, P moving on, is B̈ + Ä u + Ȧ u̇.
            QuantityKind::Velocity { point, motion } => {
                let (i, j) = self.frames(motion)?;
                let p = st.pos[m.point(point)?];
                let u = parts(&(st.rot[i].transpose() * (p - st.origin(i))));
                let [_, da, dda] = mat3(&(st.rot[j].transpose() * st.rot[i]));
                let b = parts(&(st.rot[j].transpose() * (st.origin(i) - st.origin(j))));
                let v = b[1] + da * u[0];
                let dv = b[2] + dda * u[0] + da * u[1];
                Ok(self.in_ground(j, v, dv))
            }
            QuantityKind::KineticResultant(mo) => {
                let j = m.body_frame(&mo.reference, self.q)?;
                let (mut x, mut dx) = (Vector3::zeros(), Vector3::zeros());
                for s in &m.solids_of(&mo.moving)? {
                    let f = m.solids[*s].frame;
                    for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
                        let [_, v, g] = parts(&st.track(f, &u, j));
                        x += v * mk;
                        dx += g * mk;
                    }
                }
                Ok(self.in_ground(j, x, dx))
            }
            // σ(A) = Σ mₖ (rₖ − a) ∧ vₖ in j, A(t) at a: its derivative is
            // Σ mₖ [(vₖ − ȧ) ∧ vₖ + (rₖ − a) ∧ Γₖ].
            QuantityKind::KineticMoment { point, motion } => {
                let j = m.body_frame(&motion.reference, self.q)?;
                let a = parts(&(st.rot[j].transpose() * (st.pos[m.point(point)?] - st.origin(j))));
                let (mut x, mut dx) = (Vector3::zeros(), Vector3::zeros());
                for s in &m.solids_of(&motion.moving)? {
                    let f = m.solids[*s].frame;
                    for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
                        let [r, v, g] = parts(&st.track(f, &u, j));
                        x += (r - a[0]).cross(&v) * mk;
                        dx += ((v - a[1]).cross(&v) + (r - a[0]).cross(&g)) * mk;
                    }
                }
                Ok(self.in_ground(j, x, dx))
            }
            _ => Err(NumericError::Quantity {
                quantity: self.q.to_string(),
                message: format!("the float backend has no derivative of `{k}`"),
            }),
        }
    }
}

/// Names of the spec, looked up for a quantity.
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
        // Solids and sets moving together, `1+2`: their union.
        if name.contains('+') {
            let mut all: Vec<usize> = Vec::new();
            for part in name.split('+') {
                let one = self.solid_index.get(part).map(|s| vec![*s]);
                let list = one.or_else(|| self.sets.get(part).cloned());
                let list = list.ok_or_else(|| NumericError::Unknown {
                    what: "solid or set".into(),
                    name: part.into(),
                })?;
                all.extend(
                    list.into_iter()
                        .filter(|s| !all.contains(s))
                        .collect::<Vec<_>>(),
                );
            }
            return Ok(all);
        }
        Err(NumericError::Unknown {
            what: "solid or set".into(),
            name: name.into(),
        })
    }
}
