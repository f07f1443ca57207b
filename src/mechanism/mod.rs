//! The store that owns a problem's registry, frames, points, solids, sets and hypotheses.

use crate::expr::{Expr, Registry, VarId};
use crate::frame::{FrameId, Frames};
use crate::inertia::{Inertia, Symmetry};
use crate::point::{PointId, Points};
use crate::quantity::Quantity;
use crate::wire::SpecFile;
use std::collections::BTreeMap;
use std::rc::Rc;

mod dynamics;
mod statement;
pub use dynamics::{
    Action, CoulombLaw, DryFriction, Dynamics, Mark, Small, Source, SpringPart, Theorem,
};
pub use statement::{
    Closure, Coordinate, Dependent, DeterminedBy, Equation, Link, LinkSpring, Question, Statement,
};

/// Typed index of a solid.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct BodyId(pub(crate) usize);

/// A solid: mass, centre of inertia, attached frame, inertia operator.
#[doc(alias = "solide")]
#[derive(Debug, Clone)]
pub struct Body {
    /// Name: its number in the course (`1`, `2`).
    pub name: String,
    /// Frame attached to the solid.
    pub frame: FrameId,
    /// Mass (zero for a body of negligible mass).
    pub mass: Expr,
    /// Whether the body is of negligible mass (« de masse négligeable »): its kinetic and
    /// dynamic torsors and its kinetic energy are zero, and the answer key says so instead of
    /// deriving them.
    pub massless: bool,
    /// Centre of inertia G (for a body of negligible mass, the origin of its frame unless the
    /// spec names one: a zero mass makes the choice immaterial).
    pub centre: PointId,
    /// Inertia operator as given (at some point, in some basis); none for a point mass.
    pub inertia: Option<Inertia>,
    /// Declared symmetries, in the basis of the inertia matrix.
    pub symmetries: Vec<Symmetry>,
    /// The solid that carries it (`carried_by`, « le rotor porte une masse ponctuelle »),
    /// rigidly fixed to it with no link: isolating the carrier isolates it too.
    pub carried_by: Option<BodyId>,
}

/// A hypothesis: a named set of substitutions that gives additional simplified forms.
#[derive(Debug, Clone)]
pub struct Hypothesis {
    /// Short name (`Q2`).
    pub name: String,
    /// Statement as written in the spec.
    pub text: Option<String>,
    /// The solids it declares symmetric (« symétries »).
    pub symmetric_solids: Vec<BodyId>,
    /// The variable and the value it takes.
    pub substitutions: Vec<(VarId, Expr)>,
    /// What it sets, as the answer key states it (`D2 = 0`, `ddot(theta1) = 0`).
    pub effects: Vec<Effect>,
    /// Small parameters: the results are kept to first order in them (after the
    /// substitutions).
    pub first_order: Vec<VarId>,
    /// A trial motion (« régime forcé »), whose substitutions are among `substitutions`.
    pub trial: Option<Trial>,
}

/// One thing a hypothesis sets, `lhs = rhs`: a product of inertia its symmetries make zero
/// (`D2 = 0`), a rate or an acceleration (`ddot(theta1) = 0`), a coordinate held at a value
/// (`theta2 = beta0`), a relation between parameters, a trial motion.
///
/// ```
/// let m = torseur::spec::load(std::path::Path::new(concat!(
///     env!("CARGO_MANIFEST_DIR"),
///     "/derivations/regulateur_centrifuge.json"
/// )))
/// .unwrap();
/// let h2 = m.hypotheses().iter().find(|h| h.name == "H2").unwrap();
/// assert!(h2.effects.iter().any(|e| e.to_string() == "ddot(theta1) = 0"));
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Effect {
    /// Why it holds.
    pub cause: Cause,
    /// The side set.
    pub lhs: Stated,
    /// Its value.
    pub rhs: Stated,
}

/// Why an [`Effect`] holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// A symmetry of a solid makes a product of inertia zero (or two moments equal).
    Symmetry,
    /// The hypothesis poses it: a motion, a rate, a relation, a trial.
    Posed,
}

/// A side of an [`Effect`]: an expression of the registry, or a name the registry has no
/// variable for (an angle held at a value, which then enters only through its cos and sin).
#[derive(Debug, Clone, PartialEq)]
pub enum Stated {
    /// An expression.
    Expr(Expr),
    /// A name as the spec writes it.
    Name(String),
}

impl Stated {
    /// `text` read with `reg`, else kept as a name.
    pub(crate) fn read(reg: &Rc<Registry>, text: &str) -> Stated {
        let text = text.trim();
        reg.parse(text)
            .map_or_else(|_| Stated::Name(text.to_string()), Stated::Expr)
    }
}

impl std::fmt::Display for Stated {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Stated::Expr(e) => write!(f, "{e}"),
            Stated::Name(n) => f.write_str(n),
        }
    }
}

impl Effect {
    /// A posed effect `lhs = rhs`.
    pub(crate) fn posed(lhs: Expr, rhs: Expr) -> Effect {
        Effect {
            cause: Cause::Posed,
            lhs: Stated::Expr(lhs),
            rhs: Stated::Expr(rhs),
        }
    }
}

impl std::fmt::Display for Effect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {}", self.lhs, self.rhs)
    }
}

/// A trial motion q(t) = motion of a hypothesis: its unknowns are solved so that eom(q) holds
/// at every t.
#[derive(Debug, Clone)]
pub struct Trial {
    /// The coordinate whose motion is posed.
    pub coord: crate::expr::CoordId,
    /// The motion, an expression of the phases Ω t, the parameters and the unknowns.
    pub motion: Expr,
    /// The unknowns (name, variable), in the spec's order.
    pub unknowns: Vec<(String, VarId)>,
}

impl Hypothesis {
    /// Applies the substitutions to an expression, then keeps it to first order in the small
    /// parameters: e(0) + Σ εᵢ ∂e/∂εᵢ(0), every small parameter at 0.
    pub fn apply(&self, e: &Expr) -> Expr {
        let mut r = e.clone();
        for (v, val) in &self.substitutions {
            r = r.substitute(*v, val);
        }
        if self.first_order.is_empty() {
            return r;
        }
        let zero = r.registry().zero();
        let at_zero = |x: &Expr| {
            self.first_order
                .iter()
                .fold(x.clone(), |acc, v| acc.substitute(*v, &zero))
        };
        let mut out = at_zero(&r);
        for v in &self.first_order {
            let slope = at_zero(&r.derivative(*v));
            out = &out + &(&slope * &r.registry().variable(*v));
        }
        out
    }
}

/// A validated problem: everything the derivations need, behind typed ids. Only the spec's
/// validation builds one ([`crate::spec::build`]); callers outside the crate read it through
/// its accessors and cannot change what was validated.
#[derive(Debug, Clone)]
pub struct Mechanism {
    /// Title.
    pub(crate) title: String,
    /// Statement.
    pub(crate) description: Option<String>,
    /// Parameters and coordinates.
    pub(crate) reg: Rc<Registry>,
    /// Frames (the ground is the root).
    pub(crate) frames: Frames,
    /// Origin point of each frame, indexed by frame.
    pub(crate) frame_origins: Vec<PointId>,
    /// Points (the ground origin is the root).
    pub(crate) points: Points,
    /// Solids.
    pub(crate) bodies: Vec<Body>,
    /// Named sets of solids.
    pub(crate) sets: BTreeMap<String, Vec<BodyId>>,
    /// Hypotheses.
    pub(crate) hypotheses: Vec<Hypothesis>,
    /// Basis for results that do not name one.
    pub(crate) default_basis: FrameId,
    /// Requested quantities.
    pub(crate) quantities: Vec<Quantity>,
    /// Actions, links and the declared equations of the PFD.
    pub(crate) dynamics: Dynamics,
    /// The links, as the statement describes them.
    pub(crate) links: Vec<Link>,
    /// The loop closures.
    pub(crate) closures: Vec<Closure>,
    /// The dependent coordinates: the closures', then the rolling conditions', then the
    /// helical links'.
    pub(crate) dependent: Vec<Dependent>,
    /// The statement's words and questions.
    pub(crate) statement: Statement,
    /// The spec it was built from (the float backend works from it).
    pub(crate) spec: SpecFile,
    /// How the loop closures were solved, for the answer key (None without closures).
    pub(crate) loop_law: Option<LoopLaw>,
}

/// The loop law (« loi entrée–sortie ») as the closures gave it: each scalar relation's time
/// derivative written with the dependent rates (which the mechanism's registry no longer has
/// as variables: there they are the solved forms, and each derivative reads 0), and the
/// determinant the solution divides by.
#[derive(Debug, Clone)]
pub struct LoopLaw {
    /// The time derivative of each scalar relation, the dependent rates as symbols (the
    /// expressions belong to the geometry's registry, where those rates are variables).
    pub derivatives: Vec<Expr>,
    /// The determinant of the dependent rates' columns (`L*cos(phi)`), over the mechanism's
    /// variables; None when it names a helical link's lead, which only the geometry has.
    pub determinant: Option<Expr>,
    /// Each rolling condition of the spec, in its order.
    pub rolling: Vec<RollingLaw>,
    /// Each helical link that determines a coordinate, in the order of the links.
    pub helical: Vec<HelicalLaw>,
    /// The dependent lengths a closure gives in explicit form (see [`ExplicitLaw`]).
    pub explicit: Vec<ExplicitLaw>,
}

/// A dependent length of a loop closure in explicit form, x = m ± √P (« loi entrée–sortie
/// explicite »): the closure with one term's direction eliminated is quadratic in x. The sign
/// is the branch of the closure solver's configurations ([`crate::derivation::explicit_law`]).
#[derive(Debug, Clone)]
pub struct ExplicitLaw {
    /// x.
    pub coordinate: crate::expr::CoordId,
    /// The closure's index in the spec.
    pub closure: usize,
    /// The name of the frame whose term's direction is eliminated (`2` for L x⃗2).
    pub eliminated: String,
    /// m, free of x.
    pub center: Expr,
    /// √P, a root of the registry.
    pub root: Expr,
}

/// A helical link's relation V(P ∈ b/a)·u = p/(2π) Ω(b/a)·u as the answer key writes it:
/// the link, its point, frames and axis, the two factors and the right side p/(2π) Ω(b/a)·u,
/// the dependent rate as a symbol (in the mechanism, where it reads its
/// solved rate, the right side is the velocity V(P ∈ b/a)·u).
#[derive(Debug, Clone)]
pub struct HelicalLaw {
    /// Its index in the spec's `links`.
    pub link: usize,
    /// Its point, on the axis.
    pub point: PointId,
    /// The frames of its first solid (a) and of its second (b): the motion b/a.
    pub motion: [FrameId; 2],
    /// Its axis u.
    pub axis: (FrameId, crate::frame::Axis),
    /// V(P ∈ b/a)·u.
    pub velocity: Expr,
    /// Ω(b/a)·u.
    pub rotation: Expr,
    /// p/(2π) Ω(b/a)·u.
    pub screw: Expr,
}

/// A rolling condition V(I,2/0) = 0⃗ as the answer key writes it: the velocity, its point and
/// frames, the directions it is zero along, the basis it was projected on (None when the spec
/// names the directions, `on`) and each scalar relation, the dependent rates as symbols (each
/// reads 0 in the mechanism).
#[derive(Debug, Clone)]
pub struct RollingLaw {
    /// The velocity that is zero, as the course writes it.
    pub velocity: Quantity,
    /// The velocity as the statement writes it, to name the condition.
    pub written: String,
    /// The contact point.
    pub point: PointId,
    /// The moving frame and the reference frame.
    pub motion: [FrameId; 2],
    /// The basis vectors it is zero along (empty: all of it).
    pub on: Vec<(FrameId, crate::frame::Axis)>,
    /// The frame whose basis the velocity was projected on, by name.
    pub basis: Option<String>,
    /// The scalar relations, linear in the rates.
    pub rows: Vec<Expr>,
}

impl Mechanism {
    /// The problem's title.
    pub fn title(&self) -> &str {
        &self.title
    }

    /// The statement, if the spec gives one.
    pub fn description(&self) -> Option<&str> {
        self.description.as_deref()
    }

    /// The variables: parameters, coordinates, the PFD's unknowns.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert!(m.reg().coord("theta2").is_some());
    /// ```
    pub fn reg(&self) -> &Rc<Registry> {
        &self.reg
    }

    /// The frames, the ground at the root.
    pub fn frames(&self) -> &Frames {
        &self.frames
    }

    /// The points, the ground origin at the root.
    pub fn points(&self) -> &Points {
        &self.points
    }

    /// The solids, in the spec's order.
    pub fn bodies(&self) -> &[Body] {
        &self.bodies
    }

    /// The named sets of solids.
    pub fn sets(&self) -> &BTreeMap<String, Vec<BodyId>> {
        &self.sets
    }

    /// The hypotheses, in the spec's order.
    pub fn hypotheses(&self) -> &[Hypothesis] {
        &self.hypotheses
    }

    /// The basis of results that do not name one.
    pub fn default_basis(&self) -> FrameId {
        self.default_basis
    }

    /// The quantities the spec asks for.
    pub fn quantities(&self) -> &[Quantity] {
        &self.quantities
    }

    /// The actions, links and declared equations of the PFD.
    pub fn dynamics(&self) -> &Dynamics {
        &self.dynamics
    }

    /// The links, in the statement's order.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert_eq!(m.links()[0].name, "01");
    /// ```
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// The loop closures, in the statement's order.
    pub fn closures(&self) -> &[Closure] {
        &self.closures
    }

    /// The dependent coordinates and what determines each.
    pub fn dependent(&self) -> &[Dependent] {
        &self.dependent
    }

    /// What determines the rate of the coordinate `q`, if it is a dependent one.
    pub fn determined_by(&self, q: crate::expr::CoordId) -> Option<DeterminedBy> {
        self.dependent.iter().find(|d| d.coord == q).map(|d| d.by)
    }

    /// The statement's words and questions.
    pub fn statement(&self) -> &Statement {
        &self.statement
    }

    /// The spec as written.
    pub fn spec(&self) -> &SpecFile {
        &self.spec
    }

    /// How the loop closures were solved (None without closures).
    pub fn loop_law(&self) -> Option<&LoopLaw> {
        self.loop_law.as_ref()
    }

    /// The same problem asking for the quantities `qs` instead of the spec's. They are not
    /// checked here: derive each (or bind it, [`crate::derivation::bind`]) to know it
    /// names this mechanism's objects.
    pub fn asking(&self, qs: Vec<Quantity>) -> Mechanism {
        Mechanism {
            quantities: qs,
            ..self.clone()
        }
    }

    /// The vector of each loop closure of the spec (`closures`: OA + AB + BO, zero along
    /// the motion), read with the mechanism's bases; a closure the spec validated always
    /// reads.
    pub fn closure_vectors(&self) -> Vec<crate::vector::Vector> {
        self.closures.iter().map(|c| c.vector.clone()).collect()
    }

    /// Solid by id.
    pub fn body(&self, id: BodyId) -> &Body {
        &self.bodies[id.0]
    }

    /// Solid by name.
    pub fn find_body(&self, name: &str) -> Option<BodyId> {
        self.bodies.iter().position(|b| b.name == name).map(BodyId)
    }

    /// Origin of a frame.
    pub fn origin(&self, f: FrameId) -> PointId {
        self.frame_origins[f.0]
    }

    /// The frame a motion name refers to: a solid's frame, or a frame by name.
    pub fn frame_of(&self, name: &str) -> Option<FrameId> {
        if let Some(b) = self.find_body(name) {
            return Some(self.bodies[b.0].frame);
        }
        self.frames.find(name)
    }

    /// The solids a name refers to: one solid, a set, or several of them joined by `+`
    /// (`1+2`, each solid once).
    pub fn solids_of(&self, name: &str) -> Option<Vec<BodyId>> {
        if let Some(b) = self.find_body(name) {
            return Some(vec![b]);
        }
        if name.contains('+') {
            let mut out: Vec<BodyId> = Vec::new();
            for part in name.split('+') {
                for b in self.solids_of(part)? {
                    if !out.contains(&b) {
                        out.push(b);
                    }
                }
            }
            return Some(out);
        }
        self.sets.get(name).cloned()
    }

    /// The system isolated by a theorem on `solids`: these, with every solid they carry
    /// (`carried_by`), in turn, each after its carrier.
    pub fn with_carried(&self, solids: &[BodyId]) -> Vec<BodyId> {
        let mut out = solids.to_vec();
        let mut k = 0;
        while k < out.len() {
            let carrier = out[k];
            for (i, b) in self.bodies.iter().enumerate() {
                if b.carried_by == Some(carrier) && !out.contains(&BodyId(i)) {
                    out.push(BodyId(i));
                }
            }
            k += 1;
        }
        out
    }

    /// The system a theorem on `name` (its `solids`) isolates: with the solids they carry,
    /// named `name+2+…` after them (`1+2`, the rotor with its balourd), or as it is.
    pub fn isolated(&self, name: &str, solids: &[BodyId]) -> (String, Vec<BodyId>) {
        let all = self.with_carried(solids);
        let mut named = name.to_string();
        for b in &all[solids.len()..] {
            named = format!("{named}+{}", self.body(*b).name);
        }
        (named, all)
    }

    /// Point by name.
    pub fn point(&self, name: &str) -> Option<PointId> {
        self.points.find(name)
    }

    /// Name of a point.
    pub fn point_name(&self, p: PointId) -> &str {
        &self.points.get(p).name
    }

    /// Name of a frame.
    pub fn frame_name(&self, f: FrameId) -> &str {
        &self.frames.get(f).name
    }

    /// How a sentence names the action `name` of the spec (« le moteur »): its `label`, or
    /// a default built from the name; `None` for an unknown action. Gravity's label is
    /// [`crate::wire::GRAVITY_LABEL`]. Free text that may hold `$…$` formulas, checked
    /// when the spec was loaded: print it with [`crate::latex::rich_text`].
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert_eq!(m.action_label("moteur").as_deref(), Some("le moteur"));
    /// assert_eq!(m.link_label("01").as_deref(), Some("la liaison pivot entre 0 et 1"));
    /// assert_eq!(m.scenario_label("sans_frottement").as_deref(), Some("sans frottement"));
    /// ```
    pub fn action_label(&self, name: &str) -> Option<String> {
        // The given actions follow the links' in the PFD's, each written {T(name→on)}.
        let given = self.dynamics.actions.get(self.links.len()..)?;
        let a = given.iter().find(|a| a.from_label == name)?;
        Some(a.label.clone())
    }

    /// How a sentence names the link `name` of the spec: its `label`, or « la liaison pivot
    /// entre 0 et 1 » (see [`Mechanism::action_label`]).
    pub fn link_label(&self, name: &str) -> Option<String> {
        let l = self.links.iter().find(|l| l.name == name)?;
        Some(l.label.clone())
    }

    /// How the answer key and the plots name the scenario `name`: its `label`, or its name
    /// with spaces for underscores (see [`Mechanism::action_label`]).
    pub fn scenario_label(&self, name: &str) -> Option<String> {
        let s = (self.statement.scenarios.iter()).find(|s| s.name == name)?;
        Some(s.label())
    }
}
