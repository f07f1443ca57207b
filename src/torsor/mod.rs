//! Torsors {R, M(A)}: change of point, sums, and the kinetic and dynamic torsors of the course.

use crate::expr::Expr;
use crate::frame::FrameId;
use crate::inertia::Inertia;
use crate::kinematics::{acceleration, omega, point_velocity, position, velocity};
use crate::mechanism::{BodyId, Mechanism};
use crate::point::PointId;
use crate::vector::Vector;

/// A torsor at a point: resultant R and moment M(A).
#[doc(alias = "torseur")]
#[derive(Debug, Clone)]
pub struct Torsor {
    /// Point of reduction A.
    pub point: PointId,
    /// Resultant.
    pub resultant: Vector,
    /// Moment at A.
    pub moment: Vector,
}

/// Adding torsors taken at different points.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("cannot add torsors at {0} and {1}: move one of them first")]
pub struct PointMismatch(pub String, pub String);

impl Torsor {
    /// Change of point: M(B) = M(A) + BA ∧ R.
    pub fn at(&self, m: &Mechanism, b: PointId) -> Torsor {
        if b == self.point {
            return self.clone();
        }
        let ba = position(m, b, self.point);
        Torsor {
            point: b,
            resultant: self.resultant.clone(),
            moment: self.moment.add(&ba.cross(&m.frames, &self.resultant)),
        }
    }

    /// Sum of two torsors at the same point.
    pub fn plus(&self, m: &Mechanism, other: &Torsor) -> Result<Torsor, PointMismatch> {
        if self.point != other.point {
            return Err(PointMismatch(
                m.point_name(self.point).to_string(),
                m.point_name(other.point).to_string(),
            ));
        }
        Ok(Torsor {
            point: self.point,
            resultant: self.resultant.add(&other.resultant),
            moment: self.moment.add(&other.moment),
        })
    }
}

/// The operator I_G(S) at the centre of inertia, in the basis the statement gives it in.
/// Given at another point P: I_G = I_P − m ⟦PG⟧ (Huygens backwards). None for a point mass.
pub fn inertia_at_centre(m: &Mechanism, s: BodyId) -> Option<Inertia> {
    let b = m.body(s);
    let given = b.inertia.as_ref()?;
    if given.point == b.centre {
        return Some(given.clone());
    }
    let pg = position(m, given.point, b.centre);
    let term = Inertia::point_mass(&m.frames, given.point, given.basis, &b.mass, &pg);
    let mut ig = given.minus(&term);
    ig.point = b.centre;
    Some(ig)
}

/// The basis a solid's inertia is worked in: that of its matrix, else the solid's own.
pub fn inertia_basis(m: &Mechanism, s: BodyId) -> FrameId {
    m.body(s)
        .inertia
        .as_ref()
        .map_or(m.body(s).frame, |i| i.basis)
}

/// I_A(S) by Huygens' theorem: I_A(S) = I_G(S) + m [ (AG·AG) Id − AG ⊗ AG ].
#[doc(alias = "Huygens")]
pub fn inertia_at(m: &Mechanism, s: BodyId, a: PointId) -> Inertia {
    let b = m.body(s);
    let basis = inertia_basis(m, s);
    let ag = position(m, a, b.centre);
    let huygens = Inertia::point_mass(&m.frames, a, basis, &b.mass, &ag);
    match inertia_at_centre(m, s) {
        Some(ig) if a == b.centre => ig,
        Some(ig) => {
            let mut r = ig.plus(&Inertia {
                point: ig.point,
                ..huygens
            });
            r.point = a;
            r
        }
        None => huygens,
    }
}

/// Rc(S/R) = m V(G, S/R), summed over the solids.
pub fn kinetic_resultant(m: &Mechanism, solids: &[BodyId], r: FrameId) -> Vector {
    Vector::sum(
        &m.reg,
        solids.iter().map(|&s| {
            let b = m.body(s);
            velocity(m, b.centre, b.frame, r).scale(&b.mass)
        }),
    )
}

/// Rd(S/R) = m Γ(G, S/R), summed over the solids.
pub fn dynamic_resultant(m: &Mechanism, solids: &[BodyId], r: FrameId) -> Vector {
    Vector::sum(
        &m.reg,
        solids.iter().map(|&s| {
            let b = m.body(s);
            acceleration(m, b.centre, b.frame, r).scale(&b.mass)
        }),
    )
}

/// σ(A, S/R) = I_A(S)·Ω(S/R) + m AG ∧ V(A, S/R) for one solid (with its two special cases:
/// A = G gives I_G(S)·Ω(S/R); A fixed in S and R gives I_A(S)·Ω(S/R)).
#[doc(alias = "moment cinétique")]
pub fn kinetic_moment_solid(m: &Mechanism, s: BodyId, a: PointId, r: FrameId) -> Vector {
    let b = m.body(s);
    let om = omega(m, b.frame, r);
    let ia = inertia_at(m, s, a);
    let mut sigma = ia.apply(&m.frames, &om);
    if a != b.centre {
        let v_a = velocity(m, a, b.frame, r);
        let ag = position(m, a, b.centre);
        sigma = sigma.add(&ag.cross(&m.frames, &v_a).scale(&b.mass));
    }
    sigma
}

/// σ(A, S/R), summed over the solids of a set.
pub fn kinetic_moment(m: &Mechanism, solids: &[BodyId], a: PointId, r: FrameId) -> Vector {
    Vector::sum(
        &m.reg,
        solids.iter().map(|&s| kinetic_moment_solid(m, s, a, r)),
    )
}

/// δ(A, S/R) = d/dt|R σ(A, S/R) + V(A/R) ∧ m V(G/R), where V(A/R) is the velocity of the
/// geometric point A.
#[doc(alias = "moment dynamique")]
pub fn dynamic_moment_solid(m: &Mechanism, s: BodyId, a: PointId, r: FrameId) -> Vector {
    let b = m.body(s);
    let sigma = kinetic_moment_solid(m, s, a, r);
    let d_sigma = sigma.derivative_in(&m.frames, r);
    let v_a = point_velocity(m, a, r);
    if v_a.is_zero(&m.frames) {
        return d_sigma;
    }
    let mv_g = velocity(m, b.centre, b.frame, r).scale(&b.mass);
    d_sigma.add(&v_a.cross(&m.frames, &mv_g))
}

/// δ(A, S/R), summed over the solids of a set.
pub fn dynamic_moment(m: &Mechanism, solids: &[BodyId], a: PointId, r: FrameId) -> Vector {
    Vector::sum(
        &m.reg,
        solids.iter().map(|&s| dynamic_moment_solid(m, s, a, r)),
    )
}

/// δ(A, S/R) by a second route: δ(G) = d/dt|R σ(G) = d/dt|R (I_G·Ω), then the change of point
/// δ(A) = δ(G) + AG ∧ m Γ(G, S/R).
pub fn dynamic_moment_via_centre(m: &Mechanism, s: BodyId, a: PointId, r: FrameId) -> Vector {
    let b = m.body(s);
    let sigma_g = kinetic_moment_solid(m, s, b.centre, r);
    let delta_g = sigma_g.derivative_in(&m.frames, r);
    let rd = acceleration(m, b.centre, b.frame, r).scale(&b.mass);
    let ag = position(m, a, b.centre);
    delta_g.add(&ag.cross(&m.frames, &rd))
}

/// σ(A, S/R) by the change of point from G: σ(A) = σ(G) + AG ∧ m V(G, S/R).
pub fn kinetic_moment_via_centre(m: &Mechanism, s: BodyId, a: PointId, r: FrameId) -> Vector {
    let b = m.body(s);
    let sigma_g = kinetic_moment_solid(m, s, b.centre, r);
    let rc = velocity(m, b.centre, b.frame, r).scale(&b.mass);
    sigma_g.add(&position(m, a, b.centre).cross(&m.frames, &rc))
}

/// {C(S/R)}_A.
pub fn kinetic_torsor(m: &Mechanism, solids: &[BodyId], a: PointId, r: FrameId) -> Torsor {
    Torsor {
        point: a,
        resultant: kinetic_resultant(m, solids, r),
        moment: kinetic_moment(m, solids, a, r),
    }
}

/// {D(S/R)}_A.
#[doc(alias = "torseur dynamique")]
pub fn dynamic_torsor(m: &Mechanism, solids: &[BodyId], a: PointId, r: FrameId) -> Torsor {
    Torsor {
        point: a,
        resultant: dynamic_resultant(m, solids, r),
        moment: dynamic_moment(m, solids, a, r),
    }
}

/// {V(i/j)}_A = {Ω(i/j), V(A, i/j)}.
pub fn kinematic_torsor(m: &Mechanism, i: FrameId, j: FrameId, a: PointId) -> Torsor {
    Torsor {
        point: a,
        resultant: omega(m, i, j),
        moment: velocity(m, a, i, j),
    }
}

/// Per-solid results shared by the quantities of one run: the moment at the centre of inertia
/// (σ(G) or δ(G)) and the resultant (m V(G) or m Γ(G)), by solid, reference frame and kind.
#[derive(Debug, Default)]
pub struct Cache {
    centre: std::collections::HashMap<(BodyId, FrameId, bool), (Vector, Vector)>,
}

impl Cache {
    /// (σ(G, S/R), m V(G, S/R)), or (δ(G, S/R), m Γ(G, S/R)) when `dynamic`.
    ///
    /// δ(G) = d/dt|R σ(G) with σ(G) = I_G(S)·Ω(S/R) written in the solid's basis, where I_G is
    /// constant: the Bour formula there is Euler's I_G Ω̇ + Ω ∧ I_G Ω.
    pub fn at_centre(
        &mut self,
        m: &Mechanism,
        s: BodyId,
        r: FrameId,
        dynamic: bool,
    ) -> &(Vector, Vector) {
        self.centre.entry((s, r, dynamic)).or_insert_with(|| {
            let b = m.body(s);
            let sigma_g = kinetic_moment_solid(m, s, b.centre, r);
            if dynamic {
                let rd = acceleration(m, b.centre, b.frame, r).scale(&b.mass);
                (sigma_g.derivative_in(&m.frames, r), rd)
            } else {
                (sigma_g, velocity(m, b.centre, b.frame, r).scale(&b.mass))
            }
        })
    }
}

/// The moment at A by transport from each centre of inertia: M(A) = Σ M(G_i) + AG_i ∧ R_i
/// (σ(A) = σ(G) + AG ∧ m V(G); δ(A) = δ(G) + AG ∧ m Γ(G)); projected on `u` when given, as
/// M(G)·u + R·(u ∧ AG), which never builds the full vector.
pub fn moment_by_transport(
    m: &Mechanism,
    cache: &mut Cache,
    solids: &[BodyId],
    a: PointId,
    r: FrameId,
    dynamic: bool,
    u: Option<&Vector>,
) -> (Vector, Option<Expr>) {
    let mut total = Vec::new();
    let mut scalars = Vec::new();
    for &s in solids {
        let ag = m.points.vector(a, m.body(s).centre);
        let (mg, res) = cache.at_centre(m, s, r, dynamic);
        match u {
            Some(u) => {
                scalars.push(mg.dot(&m.frames, u));
                scalars.push(res.dot(&m.frames, &u.cross(&m.frames, &ag)));
            }
            None => {
                total.push(mg.clone());
                total.push(ag.cross(&m.frames, res));
            }
        }
    }
    (
        Vector::sum(&m.reg, total),
        u.map(|_| Expr::sum(&m.reg, scalars)),
    )
}
