//! The mechanical actions and theorems a spec declares, as data of the store: what the PFD
//! ([`crate::pfd`]) isolates, sums and solves. Built by [`crate::spec`].

use super::BodyId;
use crate::expr::{CoordId, Expr};
use crate::frame::{Axis, FrameId};
use crate::point::PointId;
use crate::vector::Vector;
use crate::wire::TheoremKind;

/// What exerts an action.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    /// A solid of the spec.
    Body(BodyId),
    /// The ground, or anything outside the solids (gravity).
    Outside,
}

/// The part of a link's action due to its spring (kept apart for the potential energy).
#[derive(Debug, Clone)]
pub struct SpringPart {
    /// ½ k (q − q0)².
    pub potential: Expr,
    /// Its torsor at the link's point (on the second solid).
    pub resultant: Vector,
    /// Its moment at the link's point.
    pub moment: Vector,
}

/// An action {T(from→on)} at a point, as the course writes it in the « bilan des actions
/// mécaniques extérieures ».
#[derive(Debug, Clone)]
pub struct Action {
    /// What exerts it, as written in {T(from→on)}: a solid or frame name, `pes` for gravity,
    /// the action's name for a given action.
    pub from_label: String,
    /// The solid that receives it, as written.
    pub on_label: String,
    /// The solid or frame that exerts it, as the spec names it (`from_label` for a link;
    /// for a given action, the solid its reaction acts on).
    pub exerted_by: String,
    /// The solid that exerts it, if it is one.
    pub from: Source,
    /// The solid that receives it.
    pub on: BodyId,
    /// Point of reduction.
    pub point: PointId,
    /// Resultant.
    pub resultant: Vector,
    /// Moment at `point`.
    pub moment: Vector,
    /// Basis the torsor is written in.
    pub basis: FrameId,
    /// How the course describes it (« liaison pivot d'axe (O1, z0) »).
    pub description: String,
    /// How a sentence names it (« le moteur », « la pesanteur », « la liaison pivot entre 0
    /// et 1 »): free text that may hold `$…$` formulas, for [`crate::latex::rich_text`].
    pub label: String,
    /// What exerts it, as {T(source→on)} prints it: a solid or frame name for a link, `pes`
    /// for gravity, the action's source (« poussée », « moteur 1 ») for a given action, free
    /// text that may hold `$…$` formulas ([`crate::wire::ActionSpec::source`]).
    pub source: String,
    /// What tells a link's torsor from another link's between the same two solids (two
    /// bearings: {T_A(0→1)} and {T_B(0→1)}); None when no other link joins them.
    pub mark: Option<Mark>,
    /// The spring's part, when the link has one.
    pub spring: Option<SpringPart>,
}

/// The index of a link's torsor among the links joining the same two solids.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Mark {
    /// The link's point, when the others have other points (the bearing in A, the one in B).
    Point(String),
    /// The link's name, when another of them has the same point.
    Link(String),
}

/// Dry (Coulomb) friction in a link: its action holds −C ε along the axis (or, with Coulomb's
/// law on its unknowns, T = −f N ε), where the parameter `sign` stands for ε = sgn(`rate`),
/// ±1.
#[derive(Debug, Clone)]
pub struct DryFriction {
    /// The sign's parameter (`epsilon01`).
    pub sign: String,
    /// The relative rate whose sign it is: Ω(2/1)·u for a pivot, V(A,2/1)·u for a slider,
    /// V(P,2/1)·t for a contact sliding along t.
    pub rate: Expr,
    /// The friction's magnitude: C (a torque or a force), or f N with N the normal unknown.
    pub magnitude: Expr,
}

/// Coulomb's law on a contact's unknowns, one more equation of the PFD: while the contact
/// slides, its tangential unknown T = −f N ε, with N its normal unknown and ε the sign of the
/// sliding velocity V(P ∈ on/from)·t.
#[derive(Debug, Clone)]
pub struct CoulombLaw {
    /// The link's position in the spec's `links`.
    pub link: usize,
    /// The tangential unknown T and the normal unknown N, by name.
    pub unknowns: [String; 2],
    /// T and N as expressions.
    pub values: [Expr; 2],
    /// The friction coefficient f.
    pub coefficient: Expr,
    /// The sign ε (the parameter `epsilon` + the link's name).
    pub sign: Expr,
    /// The sliding direction t and the normal n, each a basis vector (frame, axis).
    pub directions: [(FrameId, Axis); 2],
    /// The sliding velocity along t, V(P ∈ on/from)·t, whose sign ε is.
    pub rate: Expr,
}

impl CoulombLaw {
    /// −f N ε, what T equals while the contact slides.
    pub fn friction(&self) -> Expr {
        -&(&(&self.coefficient * &self.values[1]) * &self.sign)
    }

    /// T + f N ε, the law as an equation of the PFD (= 0).
    pub fn residual(&self) -> Expr {
        &self.values[0] - &self.friction()
    }
}

/// One scalar equation of the PFD, as declared.
#[derive(Debug, Clone)]
pub struct Theorem {
    /// Name of the isolated solid or set.
    pub isolate: String,
    /// Its solids.
    pub solids: Vec<BodyId>,
    /// Resultant or moment theorem.
    pub kind: TheoremKind,
    /// Point of the moment theorem (unused for the resultant and the energy theorem).
    pub point: PointId,
    /// Projection vector (the ground's x, unused, for the energy theorem).
    pub on: (FrameId, Axis),
    /// The coordinate whose equation of motion this is, if any.
    pub eom: Option<CoordId>,
}

/// The actions and theorems of a mechanism.
#[derive(Debug, Clone, Default)]
pub struct Dynamics {
    /// Gravity g⃗ (constant in the ground frame), if not neglected.
    pub gravity: Option<Vector>,
    /// Links and given actions, each as the action of its first solid on its second.
    pub actions: Vec<Action>,
    /// The declared equations, in order.
    pub theorems: Vec<Theorem>,
    /// Coordinates declared small, for `lin(...)`.
    pub small: Vec<Small>,
    /// The links with dry friction, in the spec's order.
    pub dry: Vec<DryFriction>,
    /// Coulomb's laws on contacts' unknowns, in the spec's order of the links.
    pub laws: Vec<CoulombLaw>,
    /// The unknowns the given actions declare (a motor torque `C_m`), in the spec's order.
    /// One that no equation without `eom` holds is an input of the equations of motion: a
    /// known torque for the direct dynamics, and found from them for an imposed motion
    /// (the inverse dynamics).
    pub action_unknowns: Vec<String>,
}

/// A coordinate declared small, and the equilibrium value it moves around.
#[derive(Debug, Clone)]
pub struct Small {
    /// The coordinate.
    pub coord: CoordId,
    /// Its equilibrium value (0 for an angle).
    pub around: Expr,
}
