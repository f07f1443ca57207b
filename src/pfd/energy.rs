//! The kinetic energy theorem's objects: the kinetic energy, the power of the actions
//! (exterior and between the solids of a set), the two sides of the theorem as a theorem of
//! the PFD, and, as a second route, the potential energy and Lagrange's equations.

use super::{Action, Source, Theorem, actions_of, external_actions};
use crate::expr::{CoordId, Expr};
use crate::kinematics::{omega, position, velocity};
use crate::mechanism::{BodyId, Mechanism};
use crate::torsor;
use crate::vector::Vector;

/// Kinetic energy Ec(S/R0) = Σ ½ (m V(G/R0)² + Ω(S/R0)·I_G(S) Ω(S/R0)).
pub fn kinetic_energy(m: &Mechanism, solids: &[BodyId]) -> Expr {
    let g0 = m.frames.ground();
    let half = m.reg.rational(1, 2);
    let mut acc = m.reg.zero();
    for &s in solids {
        let b = m.body(s);
        let v = velocity(m, b.centre, b.frame, g0);
        let mut twice = &b.mass * &v.dot(&m.frames, &v);
        if let Some(i) = torsor::inertia_at_centre(m, s) {
            let w = omega(m, b.frame, g0);
            twice = &twice + &w.dot(&m.frames, &i.apply(&m.frames, &w));
        }
        acc = &acc + &(&half * &twice);
    }
    acc
}

/// The power of one action in the motion of the solid that receives it relative to the
/// frame `reference`: {T} ⊗ {V(S/R)} = R·V(A∈S/R) + M(A)·Ω(S/R), at the action's point A.
pub fn action_power(m: &Mechanism, a: &Action, reference: crate::frame::FrameId) -> Expr {
    let f = m.body(a.on).frame;
    let v = velocity(m, a.point, f, reference);
    let w = omega(m, f, reference);
    &a.resultant.dot(&m.frames, &v) + &a.moment.dot(&m.frames, &w)
}

/// P(from→on/R): the power of the actions `from` exerts on the solids `on` (named
/// `on_name`, as [`actions_of`] reads them) in their motion relative to `reference`, each
/// action at its own point: Σ R·V(A∈S/R) + M(A)·Ω(S/R).
///
/// ```
/// use torseur::pfd::power;
/// let m = torseur::spec::load("derivations/pendule_inverse_ressort.json").unwrap();
/// let one = m.solids_of("1").unwrap();
/// let p = power(&m, "pes", &one, "1", m.frames().ground()).unwrap();
/// // The weight's power is the opposite of d/dt of its potential: m g l sin θ θ̇.
/// assert_eq!(p, m.reg().parse("m*g*l*sin(theta)*dot(theta)").unwrap());
/// ```
pub fn power(
    m: &Mechanism,
    from: &str,
    on: &[BodyId],
    on_name: &str,
    reference: crate::frame::FrameId,
) -> Result<Expr, String> {
    let mut acc = m.reg.zero();
    for a in actions_of(m, from, on, on_name)? {
        acc = &acc + &action_power(m, &a, reference);
    }
    Ok(acc)
}

/// The actions between two solids of `set` (the links inside it, their friction and springs,
/// and the given actions between its solids), each as the action of one on the other.
pub fn internal_actions<'m>(m: &'m Mechanism, set: &[BodyId]) -> Vec<&'m Action> {
    m.dynamics
        .actions
        .iter()
        .filter(|a| set.contains(&a.on) && matches!(a.from, Source::Body(b) if set.contains(&b)))
        .collect()
}

/// P_int(E): the power of the actions between the solids of `set`,
/// Σ {T(i→j)} ⊗ {V(j/i)} = R·V(A∈j/i) + M(A)·Ω(j/i): zero for perfect links, the friction's
/// and the springs' otherwise. It depends on no reference frame.
///
/// ```
/// use torseur::pfd::internal_power;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let e = m.solids_of("E").unwrap();
/// // The viscous friction f of the pivot 1–2: −f θ̇2².
/// assert_eq!(internal_power(&m, &e), m.reg().parse("-f*dot(theta2)^2").unwrap());
/// ```
pub fn internal_power(m: &Mechanism, set: &[BodyId]) -> Expr {
    let mut acc = m.reg.zero();
    for a in internal_actions(m, set) {
        let Source::Body(i) = a.from else { continue };
        acc = &acc + &action_power(m, a, m.body(i).frame);
    }
    acc
}

/// J_eq(q): Ec(all/0) = ½ J_eq q̇², the inertia (or the mass, for a length) of the whole
/// mechanism brought back to q: ∂²Ec/∂q̇², kept only when Ec is exactly ½ J_eq q̇² (every
/// other rate driven by q̇, as a gear ratio drives it; no constant imposed rate).
///
/// ```
/// let m = torseur::spec::load("derivations/treuil.json").unwrap();
/// let q = m.reg().coord("theta").unwrap();
/// // The drum and the load raised by R θ: J + m R².
/// assert_eq!(torseur::pfd::equivalent_inertia(&m, q).unwrap(), m.reg().parse("J + m*R^2").unwrap());
/// ```
pub fn equivalent_inertia(m: &Mechanism, q: CoordId) -> Result<Expr, String> {
    let all: Vec<BodyId> = (0..m.bodies.len()).map(BodyId).collect();
    let ec = kinetic_energy(m, &all);
    let j = ec.partial_rate(q, 1).partial_rate(q, 1);
    let qd = m.reg.dot(q);
    if &(&m.reg.rational(1, 2) * &j) * &(&qd * &qd) != ec {
        return Err(format!(
            "the kinetic energy is not ½ J q̇² in `{}` alone: another rate is free, or a rate is \
             imposed (drive the other coordinates by it, `\"rate\": \"k*dot({})\"`)",
            m.reg.coord_info(q).name,
            m.reg.coord_info(q).name
        ));
    }
    Ok(j)
}

/// Potential energy of gravity (−Σ m g⃗·O0G) and of the springs (½ k (q − q0)²).
pub fn potential_energy(m: &Mechanism) -> Expr {
    let mut acc = m.reg.zero();
    if let Some(g) = &m.dynamics.gravity {
        for b in &m.bodies {
            let og = position(m, m.points.origin(), b.centre);
            acc = &acc - &(&b.mass * &og.dot(&m.frames, g));
        }
    }
    for a in &m.dynamics.actions {
        if let Some(s) = &a.spring {
            acc = &acc + &s.potential;
        }
    }
    acc
}

/// ∂e/∂q through q and through the coordinates its rate drives: a driven coordinate d with
/// ḋ = Σ kⱼ q̇ⱼ + c, kⱼ constant, moves by k_q when q does (a gear ratio, rolling without
/// slipping on a line), so ∂e/∂q = ∂e/∂q|_d + k_q ∂e/∂d. (A nonholonomic relation, ẋ = R θ̇
/// cos ψ, has no such position-level meaning: Lagrange's equations without multipliers do not
/// hold for it, see [`lagrange`].)
fn total_partial(m: &Mechanism, e: &Expr, q: CoordId) -> Expr {
    let reg = &m.reg;
    let mut acc = e.partial_coordinate(q);
    for c in reg.coordinates() {
        // A nonholonomic relation (ẋ = R θ̇ cos ψ) ties no positions: nothing to follow.
        if !c.is_driven() || !c.is_holonomic() {
            continue;
        }
        let Some(d) = reg.coord(&c.name) else {
            continue;
        };
        let k = reg.dot(d).partial_rate(q, 1);
        if !k.is_zero() {
            acc = &acc + &(&k * &e.partial_coordinate(d));
        }
    }
    acc
}

/// Lagrange's equation of coordinate q as a residual (for holonomic mechanisms: a driven
/// rate with constant coefficients is followed, a nonholonomic one is not):
/// d/dt ∂Ec/∂q̇ − ∂Ec/∂q + ∂Ep/∂q − Q_q = 0, with Ec the kinetic energy of all the solids,
/// Ep the potential of gravity and springs, and Q_q the generalised force of every other
/// action (links' unknowns, friction, given actions) by virtual power:
/// Q_q = Σ R·∂V(A∈S/R0)/∂q̇ + M(A)·∂Ω(S/R0)/∂q̇ over the receiving solid and, with opposite
/// sign, the solid that exerts it.
pub fn lagrange(m: &Mechanism, q: CoordId) -> Expr {
    let all: Vec<BodyId> = (0..m.bodies.len()).map(BodyId).collect();
    let t = kinetic_energy(m, &all);
    let ep = potential_energy(m);
    let mut r =
        &(&t.partial_rate(q, 1).dt() - &total_partial(m, &t, q)) + &total_partial(m, &ep, q);
    let g0 = m.frames.ground();
    let coefficient = |body: BodyId, a: &Action, res: &Vector, mom: &Vector| -> Expr {
        let f = m.body(body).frame;
        let dv = velocity(m, a.point, f, g0).map(|e| e.partial_rate(q, 1));
        let dw = omega(m, f, g0).map(|e| e.partial_rate(q, 1));
        &res.dot(&m.frames, &dv) + &mom.dot(&m.frames, &dw)
    };
    for a in &m.dynamics.actions {
        let (res, mom) = match &a.spring {
            Some(s) => (a.resultant.sub(&s.resultant), a.moment.sub(&s.moment)),
            None => (a.resultant.clone(), a.moment.clone()),
        };
        r = &r - &coefficient(a.on, a, &res, &mom);
        if let Source::Body(b) = a.from {
            r = &r + &coefficient(b, a, &res, &mom);
        }
    }
    r
}

/// The two sides of the kinetic energy theorem applied to the isolated solids in their motion
/// relative to the ground R0 (galilean): dEc(E/R0)/dt, and each action's power, the exterior
/// actions' {T} ⊗ {V(S/R0)} at their points (the bilan's), then those between two solids of
/// E, {T(i→j)} ⊗ {V(j/i)} (P_int(E)).
pub(super) fn energy_sides(m: &Mechanism, th: &Theorem) -> (Expr, Vec<(Action, Expr)>) {
    let g0 = m.frames.ground();
    let dynamic = kinetic_energy(m, &th.solids).dt();
    let mut parts: Vec<(Action, Expr)> = external_actions(m, &th.solids)
        .into_iter()
        .map(|a| {
            let p = action_power(m, &a, g0);
            (a, p)
        })
        .collect();
    for a in internal_actions(m, &th.solids) {
        let Source::Body(i) = a.from else { continue };
        parts.push((a.clone(), action_power(m, a, m.body(i).frame)));
    }
    (dynamic, parts)
}

/// The kinetic energy theorem's residual r, marked as the equation of motion of q, divided
/// by q̇: r = q̇ eom(q) once the unknowns the other equations determine are replaced. None
/// when q̇ does not divide it exactly (another rate is free).
pub(super) fn per_rate(m: &Mechanism, r: &Expr, q: CoordId) -> Option<Expr> {
    if m.reg.coord_info(q).has_imposed_rate() {
        return None;
    }
    r.exact_div(&m.reg.dot(q))
}
