//! Kinematics: Ω(i/j), V(P, i/j), Γ(P, i/j), the velocity of a geometric point, and the
//! kinematic torsor {V(i/j)}_A.
//!
//! Every frame R_i has an origin O_i fixed in it. The velocity of the point P attached to
//! frame i, relative to frame j, is given by the field of velocities of the solid:
//! V(P, i/j) = V(O_i, i/j) + PO_i ∧ Ω(i/j), with V(O_i, i/j) = d/dt|R_j O_jO_i.

use crate::frame::FrameId;
use crate::mechanism::Mechanism;
use crate::point::PointId;
use crate::vector::{Vector, omega as frame_omega};

/// Ω(i/j): angular velocity of frame i relative to frame j, composed along the tree.
#[doc(alias = "vecteur rotation")]
pub fn omega(m: &Mechanism, i: FrameId, j: FrameId) -> Vector {
    frame_omega(&m.frames, i, j)
}

/// The vector AB.
pub fn position(m: &Mechanism, a: PointId, b: PointId) -> Vector {
    m.points.vector(a, b)
}

/// V(A/R_j): velocity of the geometric point A (as its position moves), d/dt|R_j O_jA.
pub fn point_velocity(m: &Mechanism, a: PointId, j: FrameId) -> Vector {
    position(m, m.origin(j), a).derivative_in(&m.frames, j)
}

/// Γ(A/R_j): acceleration of the geometric point A, d²/dt²|R_j O_jA.
pub fn point_acceleration(m: &Mechanism, a: PointId, j: FrameId) -> Vector {
    point_velocity(m, a, j).derivative_in(&m.frames, j)
}

/// V(P, i/j) by the field formula V(P, i/j) = V(O_i, i/j) + PO_i ∧ Ω(i/j).
#[doc(alias = "vitesse")]
pub fn velocity(m: &Mechanism, p: PointId, i: FrameId, j: FrameId) -> Vector {
    let oi = m.origin(i);
    let v_oi = point_velocity(m, oi, j);
    let p_oi = position(m, p, oi);
    v_oi.add(&p_oi.cross(&m.frames, &omega(m, i, j)))
}

/// Γ(P, i/j) by the field of accelerations:
/// Γ(P, i/j) = Γ(O_i, i/j) + d/dt|R_j Ω(i/j) ∧ O_iP + Ω(i/j) ∧ (Ω(i/j) ∧ O_iP).
#[doc(alias = "accélération")]
pub fn acceleration(m: &Mechanism, p: PointId, i: FrameId, j: FrameId) -> Vector {
    let f = &m.frames;
    let oi = m.origin(i);
    let om = omega(m, i, j);
    let dom = om.derivative_in(f, j);
    let oi_p = position(m, oi, p);
    let w_x_r = om.cross(f, &oi_p);
    point_acceleration(m, oi, j)
        .add(&dom.cross(f, &oi_p))
        .add(&om.cross(f, &w_x_r))
}

/// Whether point P is fixed in frame i (O_iP has constant components in B_i).
pub fn is_fixed_in(m: &Mechanism, p: PointId, i: FrameId) -> bool {
    position(m, m.origin(i), p)
        .derivative_in(&m.frames, i)
        .is_zero(&m.frames)
}

/// V(P, i/j) by derivation of the position, d/dt|R_j O_jP, valid when P is fixed in i.
/// Returns None when P is not fixed in i. A second route for tests.
pub fn velocity_by_derivation(m: &Mechanism, p: PointId, i: FrameId, j: FrameId) -> Option<Vector> {
    if !is_fixed_in(m, p, i) {
        return None;
    }
    Some(position(m, m.origin(j), p).derivative_by_components(&m.frames, j))
}

/// Γ(P, i/j) by derivation, d/dt|R_j V(P, i/j), valid when P is fixed in i.
pub fn acceleration_by_derivation(
    m: &Mechanism,
    p: PointId,
    i: FrameId,
    j: FrameId,
) -> Option<Vector> {
    velocity_by_derivation(m, p, i, j).map(|v| v.derivative_by_components(&m.frames, j))
}
