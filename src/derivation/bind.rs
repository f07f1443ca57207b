//! A quantity bound to the mechanism: the ids of the points, solids, frames and actions its
//! names name, checked once before any derivation.

use super::*;

/// A quantity bound to the mechanism: the ids of what its names name.
#[derive(Debug, Clone)]
pub struct Bound {
    /// Point involved (if any).
    pub point: Option<PointId>,
    /// Frame of the moving solid or frame (for Ω, V, Γ, {V}).
    pub moving_frame: Option<FrameId>,
    /// Solids of the moving solid or set (for kinetic and dynamic quantities, I).
    pub solids: Vec<BodyId>,
    /// Reference frame.
    pub reference: Option<FrameId>,
    /// Basis the result is written in.
    pub basis: FrameId,
    /// Projection vector (basis, axis).
    pub projection: Option<(FrameId, Axis)>,
}

/// Binds the names of a quantity to the mechanism's ids (its point, solids, frames, basis);
/// why not, for a name the mechanism does not have.
pub fn bind(m: &Mechanism, q: &Quantity) -> Result<Bound, DeriveError> {
    let mut r = Bound {
        point: None,
        moving_frame: None,
        solids: vec![],
        reference: None,
        basis: m.default_basis,
        projection: None,
    };
    bind_kind(m, q, &mut r)?;
    // The action must be in the bilan of what it acts on.
    if let Some(a) = q.kind.action() {
        crate::pfd::actions_of(m, &a.from, &r.solids, &a.on).map_err(|e| DeriveError::new(q, e))?;
    }
    bind_basis(m, q, &mut r)?;
    Ok(r)
}

/// The objects the quantity's kind names (its point, solids, frames), into `r`; a set's
/// inertia in the basis of its first solid's operator.
fn bind_kind(m: &Mechanism, q: &Quantity, r: &mut Bound) -> Result<(), DeriveError> {
    let unknown = |what: &'static str, n: &str| DeriveError::unknown(m, q, what, n);
    let frame = |n: &str| m.frame_of(n).ok_or_else(|| unknown("solid or frame", n));
    let point = |n: &str| m.point(n).ok_or_else(|| unknown("point", n));
    let solids = |n: &str| m.solids_of(n).ok_or_else(|| unknown("solid or set", n));
    let kinetic = |mo: &Motion, r: &mut Bound| -> Result<(), DeriveError> {
        r.solids = solids(&mo.moving)?;
        r.reference = Some(frame(&mo.reference)?);
        Ok(())
    };
    let kinematic = |mo: &Motion, r: &mut Bound| -> Result<(), DeriveError> {
        r.moving_frame = Some(frame(&mo.moving)?);
        r.reference = Some(frame(&mo.reference)?);
        Ok(())
    };
    use QuantityKind::*;
    match &q.kind {
        Omega(mo) => kinematic(mo, r)?,
        Velocity { point: p, motion } | Acceleration { point: p, motion } => {
            r.point = Some(point(p)?);
            kinematic(motion, r)?;
        }
        KinematicTorsor { motion, point: p } => {
            r.point = Some(point(p)?);
            kinematic(motion, r)?;
        }
        // I(P,S) of a solid, or I(P,E) = Σ I(P,Si) of a set, in the basis of its first
        // solid's operator.
        Inertia { point: p, solid } => {
            r.point = Some(point(p)?);
            r.solids = solids(solid)?;
            r.basis = torsor::inertia_basis(m, r.solids[0]);
        }
        KineticResultant(mo) | DynamicResultant(mo) | KineticEnergy(mo) => kinetic(mo, r)?,
        // Named objects checked here, before the PFD is solved: a spec's `quantities` are
        // resolved when it is loaded.
        Unknown(name) => {
            if m.reg.coord(name).is_some() {
                return Err(DeriveError::new(q, dynamics::a_coordinate(name)));
            }
            if !m.reg.unknowns().contains(name) && trial::trial_of(m, name).is_none() {
                return Err(DeriveError::new(q, dynamics::not_an_unknown(name)));
            }
        }
        Eom(c) => {
            let coord = m.reg.coord(c).ok_or_else(|| unknown("coordinate", c))?;
            if !m.dynamics.theorems.iter().any(|t| t.eom == Some(coord)) {
                return Err(DeriveError::new(q, dynamics::no_eom_marked(c)));
            }
        }
        ActionResultant(a) => r.solids = solids(&a.on)?,
        Power { action, reference } => {
            r.solids = solids(&action.on)?;
            r.reference = Some(frame(reference)?);
        }
        InternalPower(set) => r.solids = solids(set)?,
        EquivalentInertia(c) | Rate { coordinate: c, .. } => {
            m.reg.coord(c).ok_or_else(|| unknown("coordinate", c))?;
        }
        ActionMoment { point: p, action } | ActionTorsor { action, point: p } => {
            r.point = Some(point(p)?);
            r.solids = solids(&action.on)?;
        }
        // The inner quantity's names, then the frame of the derivative.
        Derivative { of, frame: f } => {
            let inner = bind(m, of)?;
            r.basis = inner.basis;
            r.reference = f
                .as_deref()
                .map(|f| derivative::frame(m, q, f))
                .transpose()?;
        }
        KineticMoment { point: p, motion }
        | DynamicMoment { point: p, motion }
        | KineticTorsor { motion, point: p }
        | DynamicTorsor { motion, point: p } => {
            r.point = Some(point(p)?);
            kinetic(motion, r)?;
        }
    }
    Ok(())
}

/// The basis the quantity asks for (`in B2`) and its projection vector (`.x2`), into `r`;
/// without a basis, the projection's is used.
fn bind_basis(m: &Mechanism, q: &Quantity, r: &mut Bound) -> Result<(), DeriveError> {
    let unknown = |what: &'static str, n: &str| DeriveError::unknown(m, q, what, n);
    if let Some(b) = &q.basis {
        r.basis = m
            .frames
            .find(b)
            .ok_or_else(|| unknown("basis", &format!("B{b}")))?;
    }
    if let Some((f, axis)) = &q.projection {
        // Intermediate steps are written in the basis of the projection vector.
        let fid = m
            .frames
            .find(f)
            .ok_or_else(|| unknown("basis vector", &format!("{axis}{f}")))?;
        if q.basis.is_none() {
            r.basis = fid;
        }
        r.projection = Some((
            fid,
            Axis::parse(&axis.to_string()).ok_or_else(|| unknown("axis", &axis.to_string()))?,
        ));
    }
    Ok(())
}
