//! JSON wire types of a problem spec: what a teacher writes, before validation.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

mod coulomb;
mod scenario;
pub mod source;
mod texts;
pub use coulomb::{ContactFrictionSpec, ContactUnknowns};
pub use scenario::{ImposedSpec, RatePiece, ScenarioSpec};
pub use source::action_sources;
pub(crate) use texts::free_texts;

/// A whole problem as written in `derivations/*.json`.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SpecFile {
    /// The JSON Schema the file follows (`"../spec.schema.json"`), so that an editor validates
    /// and completes the spec as it is typed; ignored by the engine.
    #[serde(rename = "$schema", default, skip_serializing_if = "Option::is_none")]
    pub schema: Option<String>,
    /// Title of the problem (answer-key heading).
    pub title: String,
    /// Optional statement or source.
    #[serde(default)]
    pub description: Option<String>,
    /// Constant parameters, in the order they should be listed (`"kind": "angle"` for a
    /// constant angle such as an incline).
    #[serde(default)]
    pub parameters: Vec<ParameterSpec>,
    /// Named expressions of the parameters, as a statement poses them (« on pose
    /// K = C ω »): written once, then used by name in every expression of the spec, in
    /// `verify` and in `eval`. Each may use the aliases before it. The answer key states them
    /// in the paramétrage; results are written with the parameters.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub aliases: Vec<AliasSpec>,
    /// Time coordinates q(t). Their names, like the parameters', cannot be those of basis
    /// vectors (`x0` while frame `0` exists).
    #[serde(default)]
    pub coordinates: Vec<CoordinateSpec>,
    /// Name of the fixed (Galilean) frame, `0` unless given.
    #[serde(default = "default_ground")]
    pub ground: String,
    /// Name of the origin point of the ground frame, `O0` unless given.
    #[serde(default)]
    pub ground_origin: Option<String>,
    /// The names of the ground's basis vectors as the statement writes them (`["x", "y",
    /// "z"]`, `["i", "j", "k"]`); see [`FrameSpec::basis`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ground_basis: Option<[String; 3]>,
    /// Frames other than the ground, each turned from its parent.
    #[serde(default)]
    pub frames: Vec<FrameSpec>,
    /// Points, each placed from another point.
    #[serde(default)]
    pub points: Vec<PointSpec>,
    /// Solids, each attached to a frame.
    #[serde(default)]
    pub solids: Vec<SolidSpec>,
    /// Named sets of solids.
    #[serde(default)]
    pub sets: BTreeMap<String, Vec<String>>,
    /// Hypotheses that give additional simplified forms.
    #[serde(default)]
    pub hypotheses: Vec<HypothesisSpec>,
    /// Basis used to express vectors when a quantity does not say `in B..`.
    #[serde(default)]
    pub default_basis: Option<String>,
    /// Requested quantities in course notation.
    #[serde(default)]
    pub quantities: Vec<String>,
    /// The questions of the statement, for the answer key (optional: without them the key
    /// lists the requested quantities).
    #[serde(default)]
    pub questions: Vec<QuestionSpec>,
    /// Acceleration of gravity as a vector expression in the ground's terms (`-g*z0`); none
    /// means gravity is neglected.
    #[serde(default)]
    pub gravity: Option<String>,
    /// Loop closures (« fermeture géométrique »): each a vector sum that is zero around a
    /// closed kinematic chain, and the coordinates it determines.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub closures: Vec<ClosureSpec>,
    /// Rolling without slipping (« roulement sans glissement »): each a velocity at a
    /// contact that is zero, and the coordinates whose rates it determines.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub rolling: Vec<RollingSpec>,
    /// Perfect links between solids (and the ground), with optional viscous friction and
    /// torsion spring. They form a tree, unless `closures` close the loops: a link between two
    /// solids already connected by other links (a crank–slider's slide) is refused without a
    /// closure; links in parallel between the same two solids (two bearings) are one
    /// connection.
    #[serde(default)]
    pub links: Vec<LinkSpec>,
    /// Other actions: given or unknown forces and torques (a motor torque).
    #[serde(default)]
    pub actions: Vec<ActionSpec>,
    /// The Fundamental Principle of Dynamics as applied: which system is isolated, which
    /// theorem, at which point, projected on which vector.
    #[serde(default)]
    pub pfd: Vec<TheoremSpec>,
    /// Numerical scenarios for `simulate`.
    #[serde(default)]
    pub scenarios: Vec<ScenarioSpec>,
    /// Coordinates declared small for `lin(...)` (small motions around an equilibrium).
    #[serde(default)]
    pub small: Vec<SmallSpec>,
}

/// A coordinate that stays close to an equilibrium value.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SmallSpec {
    /// The coordinate.
    pub coordinate: String,
    /// Its equilibrium value: `0` for an angle (write the angle from the equilibrium), a
    /// constant expression for a length (`l0`).
    #[serde(default)]
    pub around: Option<String>,
}

/// Kind of a perfect link, with the course's names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum LinkKind {
    /// Encastrement: the six components.
    Fixed,
    /// Pivot of axis (P, u): no moment along u.
    Pivot,
    /// Glissière of direction u: no resultant along u.
    Slider,
    /// Pivot glissant of axis (P, u): no resultant and no moment along u.
    PivotSlider,
    /// Rotule (sphérique) at P: no moment.
    Ball,
    /// Appui plan of normal n: resultant along n, moment in the plane.
    Plane,
    /// Linéaire annulaire (sphère-cylindre) of axis (P, u): resultant normal to u, no moment.
    Annular,
    /// Linéaire rectiligne of normal n and line direction u: resultant along n, moment along
    /// n ∧ u.
    Line,
    /// Ponctuelle (sphère-plan) of normal n at P: resultant along n.
    Point,
    /// Hélicoïdale (vis–écrou) of axis (P, u) and pitch p (`pitch`, a length per turn; p > 0
    /// for a right-hand thread, « pas à droite », p < 0 for a left-hand one): the relative
    /// motion of the second solid with respect to the first is a screw motion,
    /// V(P ∈ 2/1)·u = p/(2π) Ω(2/1)·u, which gives the rate of the coordinate `dependent`.
    /// Perfect, it transmits the resultant and the moment normal to u, and along u the moment
    /// −p/(2π) times the axial resultant (its power, X V·u + L Ω·u, is zero).
    Helical,
}

impl LinkKind {
    /// The course's name of the link (« liaison pivot », « encastrement »...).
    ///
    /// ```
    /// use torseur::wire::LinkKind;
    /// assert_eq!(LinkKind::Pivot.course_name(), "liaison pivot");
    /// ```
    pub fn course_name(self) -> &'static str {
        match self {
            LinkKind::Fixed => "encastrement",
            LinkKind::Pivot => "liaison pivot",
            LinkKind::Slider => "liaison glissière",
            LinkKind::PivotSlider => "liaison pivot glissant",
            LinkKind::Ball => "liaison sphérique (rotule)",
            LinkKind::Plane => "liaison appui plan",
            LinkKind::Annular => "liaison sphère-cylindre (linéaire annulaire)",
            LinkKind::Line => "liaison cylindre-plan (linéaire rectiligne)",
            LinkKind::Point => "liaison sphère-plan (ponctuelle)",
            LinkKind::Helical => "liaison hélicoïdale",
        }
    }
}

/// A perfect link between two solids: its action torsor {T(first→second)} at `point` carries
/// the unknowns X, Y, Z (resultant) and L, M, N (moment) suffixed by the link's name, as
/// components in the basis of its axis vector; those it cannot transmit are zero.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LinkSpec {
    /// Suffix of the unknowns (`01` gives X01, Y01, ...), usually the two solids' numbers.
    pub name: String,
    /// Kind of link.
    pub kind: LinkKind,
    /// The two solids (a solid or the ground frame): the torsor is the action of the first on
    /// the second.
    pub between: [String; 2],
    /// Centre of the link (a point on its axis).
    pub point: String,
    /// Axis direction (pivot, slider, pivot slider, annular) or normal (plane, line, point):
    /// a basis vector such as `z0`, whose basis the components are written in.
    #[serde(default)]
    pub axis: Option<String>,
    /// Line direction of a line contact (a basis vector of the axis' basis).
    #[serde(default)]
    pub direction: Option<String>,
    /// Pitch p of a helical link, a length per turn (a constant expression of the parameters,
    /// `p`, `2*a`): positive for a right-hand thread (« pas à droite »), negative for a
    /// left-hand one. V(P ∈ 2/1)·u = p/(2π) Ω(2/1)·u along the axis u.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pitch: Option<String>,
    /// The coordinate whose rate a helical link determines (its relation solved for it, like
    /// a rolling condition's): the load's `lambda` when the screw's angle is free, or the
    /// screw's angle. None when the positions already satisfy the relation (the nut placed
    /// at `p*theta/(2*pi)`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dependent: Option<String>,
    /// Viscous friction coefficient of a pivot or slider: the action on the second solid
    /// opposes the relative rate, -f q̇ along the axis.
    #[serde(default)]
    pub friction: Option<String>,
    /// Dry (Coulomb) friction of a pivot or slider: the magnitude of the torque or force that
    /// opposes the relative motion (a constant expression of the parameters, `mu*m*g*cos(alpha)`
    /// for a block on an incline). The action on the second solid is −C ε along the axis, with
    /// ε the sign of the relative rate, a parameter named by [`LinkSpec::sign_parameter`]
    /// (`epsilon01`) of value ±1: `eval` takes it as given, `check` and `simulate` set it from
    /// the relative rate (`simulate` holds the link stuck while the friction needed to stop it
    /// stays below C).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coulomb: Option<String>,
    /// Coulomb's law on the link's own unknowns, for a contact (point, plane, line) or a
    /// slider: the link also transmits the tangential component T along the sliding
    /// direction, tied to its normal unknown N by T = −f N ε while it slides, ε the sign of
    /// the sliding velocity V(P ∈ second/first)·t, a parameter named by
    /// [`LinkSpec::sign_parameter`] (`epsilonA`) of value ±1, as for `coulomb`. A hypothesis
    /// that sets ε (`"relations": {"epsilonA": "1"}`), with an equilibrium, states the limit
    /// of sliding, the impending motion's sign given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_friction: Option<ContactFrictionSpec>,
    /// Torsion (pivot) or linear (slider) spring: -k (q - q0) along the axis.
    #[serde(default)]
    pub spring: Option<SpringSpec>,
    /// How the answer key names it in a sentence (« la liaison pivot en O1 »); see
    /// [`LinkSpec::label`] for the default.
    #[serde(default)]
    pub label: Option<String>,
}

impl LinkSpec {
    /// The display label: the spec's `label`, or « la liaison pivot entre 0 et 1 » built
    /// from the kind and the two solids. Free text: it may hold `$…$` formulas.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert_eq!(m.spec().links[0].label(), "la liaison pivot entre 0 et 1");
    /// ```
    pub fn label(&self) -> String {
        if let Some(l) = &self.label {
            return l.clone();
        }
        let kind = self.kind.course_name();
        let article = if kind.starts_with('e') { "l'" } else { "la " };
        format!(
            "{article}{kind} entre {} et {}",
            self.between[0], self.between[1]
        )
    }

    /// The parameter that stands for the sign of the relative rate of a link with dry
    /// friction (`coulomb`): `epsilon` followed by the link's name.
    ///
    /// ```
    /// let link: torseur::wire::LinkSpec = serde_json::from_str(
    ///     r#"{"name": "01", "kind": "slider", "between": ["0", "1"], "point": "G",
    ///         "axis": "x1", "coulomb": "mu*m*g"}"#).unwrap();
    /// assert_eq!(link.sign_parameter().as_deref(), Some("epsilon01"));
    /// ```
    pub fn sign_parameter(&self) -> Option<String> {
        (self.coulomb.is_some() || self.contact_friction.is_some())
            .then(|| format!("epsilon{}", self.name))
    }
}

/// A spring in a pivot or a slider: the action on the link's second solid is
/// -k (q - q0) along the axis (a torque for a pivot, a force for a slider).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SpringSpec {
    /// The coordinate the spring measures: the relative angle (or length) of the link.
    pub coordinate: String,
    /// Stiffness k.
    pub stiffness: String,
    /// Value of the link's coordinate where the spring is free (q0), `0` unless given.
    #[serde(default)]
    pub free: Option<String>,
}

/// A given or unknown action {T(from→on)} written at a point.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ActionSpec {
    /// Name (`moteur`), for the answer key.
    pub name: String,
    /// The solid (or ground frame) that exerts it.
    pub from: String,
    /// The solid that receives it.
    pub on: String,
    /// Point where the moment is given.
    pub point: String,
    /// Resultant, a vector expression (`0` unless given).
    #[serde(default)]
    pub resultant: Option<String>,
    /// Moment at `point`, a vector expression (`C_m*z0`).
    #[serde(default)]
    pub moment: Option<String>,
    /// Scalars of these expressions that are unknowns to solve for (`C_m`), not parameters.
    #[serde(default)]
    pub unknowns: Vec<String>,
    /// How the answer key names it in a sentence (« le moteur », « la poussée »); see
    /// [`ActionSpec::label`] for the default.
    #[serde(default)]
    pub label: Option<String>,
    /// What exerts it, as its torsor {T(source→on)} prints it (« poussée », « moteur 1 »,
    /// `$C_r$`): free text, which may hold `$…$` formulas; see [`ActionSpec::source`] for the
    /// default, read from the label.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<String>,
}

impl ActionSpec {
    /// The display label: the spec's `label`, or « l'action moteur » built from the name.
    /// Free text: it may hold `$…$` formulas.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert_eq!(m.spec().actions[0].label(), "le moteur");
    /// let mut a = m.spec().actions[0].clone();
    /// a.label = None;
    /// assert_eq!(a.label(), "l'action moteur");
    /// ```
    pub fn label(&self) -> String {
        self.label
            .clone()
            .unwrap_or_else(|| format!("l'action {}", self.name.replace('_', " ")))
    }

    /// What exerts it, as {T(source→on)} prints it: the spec's `source`, else read from the
    /// label (see [`source::from_label`]), else the name. [`action_sources`] settles two
    /// actions that would print the same.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/train_engrenages.json").unwrap();
    /// let a = &m.spec().actions;
    /// // « le moteur » → moteur; « le couple résistant » → résistant, the name's word with
    /// // the label's accents; « l'engrènement en $I$ » → the name, `denture`.
    /// assert_eq!(a[0].source(), "moteur");
    /// assert_eq!(a[1].source(), "résistant");
    /// assert_eq!(a[2].source(), "denture");
    /// ```
    pub fn source(&self) -> String {
        if let Some(s) = &self.source {
            return s.clone();
        }
        self.label
            .as_deref()
            .and_then(|l| source::from_label(&self.name, l))
            .unwrap_or_else(|| self.name.clone())
    }
}

/// The display label of gravity in the answer key's sentences.
pub const GRAVITY_LABEL: &str = "la pesanteur";

/// Which theorem of the PFD.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TheoremKind {
    /// Théorème de la résultante dynamique: Rd(S/R0)·u = R(S̄→S)·u.
    Resultant,
    /// Théorème du moment dynamique: δ(P,S/R0)·u = M(P,S̄→S)·u.
    Moment,
    /// Théorème de l'énergie cinétique: dEc(E/R0)/dt = P(Ē→E/R0) + P_int(E), E in its motion
    /// relative to the ground (galilean); a scalar equation, at no point and on no vector.
    /// As the equation of motion of q (`eom`), it is q̇ times that equation once the unknowns
    /// the other equations determine are replaced: divided by q̇.
    Energy,
}

/// One scalar equation of the PFD.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TheoremSpec {
    /// The isolated solid or set.
    pub isolate: String,
    /// Resultant or moment theorem.
    pub theorem: TheoremKind,
    /// Point of the moment theorem.
    #[serde(default)]
    pub point: Option<String>,
    /// Basis vector a resultant or moment theorem is projected on (none for the energy
    /// theorem, a scalar equation).
    #[serde(default)]
    pub on: Option<String>,
    /// When this equation is the equation of motion of a coordinate (`theta2`): it is then
    /// `eom(theta2)`; otherwise it determines unknowns.
    #[serde(default)]
    pub eom: Option<String>,
}

/// One question of the statement and what its answer shows.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct QuestionSpec {
    /// Heading (`Question 3`).
    pub title: String,
    /// The question as the subject asks it.
    #[serde(default)]
    pub statement: Option<String>,
    /// The teacher's discussion of the results, printed after them (the method, what is
    /// isolated and which theorem, is written by the tool); alone for a question without
    /// quantities.
    #[serde(default)]
    pub answer: Option<String>,
    /// Hypotheses whose consequences the answer shows (particular inertia matrices, what is
    /// set to zero).
    #[serde(default)]
    pub hypotheses: Vec<String>,
    /// The hypothesis the question works under: every step and result of the answer is then
    /// written under it (« on se place sous l'hypothèse H2 »), and only under it.
    #[serde(default)]
    pub under: Option<String>,
    /// Quantities derived step by step in the answer.
    #[serde(default)]
    pub quantities: Vec<String>,
    /// Equations `lhs = quantity` written out (a theorem applied, e.g. the motor torque).
    #[serde(default)]
    pub equations: Vec<EquationSpec>,
    /// Simulations whose curves and maxima the answer shows.
    #[serde(default)]
    pub simulation: Option<SimulationSpec>,
}

/// Simulations shown in an answer: scenarios run, curves plotted, a maximum compared with the
/// statement's figures.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SimulationSpec {
    /// Scenario names (the spec's `scenarios`), one curve each.
    pub scenarios: Vec<String>,
    /// Columns plotted against time, one panel each (`theta2`, `C_m`).
    pub plot: Vec<String>,
    /// Column whose largest absolute value is compared with the statement's.
    #[serde(default)]
    pub maximum: Option<String>,
    /// The statement's value of that maximum for each scenario.
    #[serde(default)]
    pub reference: BTreeMap<String, f64>,
}

/// An equation of an answer: a named unknown equal to a derived quantity.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EquationSpec {
    /// Name of the left-hand side (`Cm`), written C_{m}.
    pub lhs: String,
    /// The quantity it equals, in course notation (`delta(O1,E/0).z0`).
    pub quantity: String,
    /// Why, in the course's words (which theorem, which actions vanish).
    #[serde(default)]
    pub reason: Option<String>,
}

fn default_ground() -> String {
    "0".to_string()
}

/// An empty problem with the ground `0`: start here to build a spec in code
/// (`SpecFile { title: ..., ..SpecFile::default() }`).
impl Default for SpecFile {
    fn default() -> Self {
        SpecFile {
            schema: None,
            title: String::new(),
            description: None,
            parameters: vec![],
            aliases: vec![],
            coordinates: vec![],
            ground: default_ground(),
            ground_origin: None,
            ground_basis: None,
            frames: vec![],
            points: vec![],
            solids: vec![],
            sets: BTreeMap::new(),
            hypotheses: vec![],
            default_basis: None,
            quantities: vec![],
            questions: vec![],
            gravity: None,
            closures: vec![],
            rolling: vec![],
            links: vec![],
            actions: vec![],
            pfd: vec![],
            scenarios: vec![],
            small: vec![],
        }
    }
}

/// A constant parameter.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ParameterSpec {
    /// Identifier (`m2`, `L1`, `A2`).
    pub name: String,
    /// What it is, in the course's words.
    #[serde(default)]
    pub description: Option<String>,
    /// SI unit (`kg m^2`, `N m s/rad`; see [`crate::units::Dimension::parse`]): the answer
    /// key's units and the homogeneity checks. Without it the parameter's dimension is
    /// unknown and the terms holding it are not checked.
    #[serde(default)]
    pub unit: Option<String>,
    /// `angle` for a constant angle (an incline α): it may then turn a frame (`"angle":
    /// "alpha"`, `"theta - alpha"`) and appear in sin and cos; results hold cos α and sin α,
    /// reduced like a coordinate's, with a zero rate. A plain scalar unless given.
    #[serde(default, skip_serializing_if = "ParameterKind::is_scalar")]
    pub kind: ParameterKind,
}

/// A named expression of the parameters (`{"name": "K", "value": "C*omega"}`).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct AliasSpec {
    /// Identifier, in the namespace of the parameters and coordinates.
    pub name: String,
    /// Its value: an expression of the parameters and the aliases before it.
    pub value: String,
    /// What it is, in the course's words.
    #[serde(default)]
    pub description: Option<String>,
}

/// Kind of a constant parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum ParameterKind {
    /// Enters polynomially (a mass, a length, an inertia).
    #[default]
    Scalar,
    /// A constant angle: enters polynomially as itself, and through its exact cos and sin.
    Angle,
}

impl ParameterKind {
    /// Whether this is the default kind (a plain scalar).
    pub fn is_scalar(&self) -> bool {
        *self == ParameterKind::Scalar
    }
}

/// Kind of a time coordinate (defined with the expressions, which need it; the spec reads it).
pub use crate::expr::CoordinateKind;

/// A time coordinate q(t).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CoordinateSpec {
    /// Identifier (`theta1`, `lambda`).
    pub name: String,
    /// Angle or length.
    pub kind: CoordinateKind,
    /// What it is.
    #[serde(default)]
    pub description: Option<String>,
    /// Imposed constant rate: q̇ is this parameter expression and q̈ = 0 (a constant angle is
    /// better declared as a parameter of kind `angle`).
    #[serde(default)]
    pub rate: Option<String>,
}

/// A loop closure: OA + AB + BO = 0 around a closed chain (a crank–slider:
/// `R*x1 + L*x2 - x*x0`), projected on the ground's basis. Its derivative gives the rates of
/// the `dependent` coordinates as linear forms of the free ones (the loop law, « loi
/// entrée–sortie »); the relation itself stays implicit.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ClosureSpec {
    /// The vector that is zero, a sum over the basis vectors (`R*x1 + L*x2 - x*x0`).
    pub vector: String,
    /// The coordinates it determines, as many as it has independent scalar equations (two
    /// for a planar loop); each without a `rate` of its own.
    pub dependent: Vec<String>,
}

/// A velocity constraint at a contact: V(I,2/0) = 0⃗ (rolling without slipping), or only its
/// components along `on` (no sliding across a blade: `["y1"]`). Its components, linear in
/// the rates, give the rates of the `dependent` coordinates as linear forms of the others,
/// by Cramer's rule; they are holonomic when their coefficients are constant (a disc on a
/// line, ẋ = R θ̇), nonholonomic otherwise (a wheel on a plane, ẋ = R θ̇ cos ψ).
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RollingSpec {
    /// The velocity that is zero, in the course's notation: `V(I,2/0)`, the velocity of the
    /// point of solid 2 at the contact I in its motion relative to 0.
    pub velocity: String,
    /// The basis vectors it is zero along; all of it when absent (then it is projected on
    /// the first basis, ground first, where it has as many nonzero components as dependent
    /// coordinates).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub on: Vec<String>,
    /// The coordinates whose rates it determines; each without a `rate` of its own.
    pub dependent: Vec<String>,
}

impl RollingSpec {
    /// How the answer key names the condition: « le roulement sans glissement » for the whole
    /// velocity, « la condition de non-glissement » for some directions (`on`).
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/roue_sur_plan.json").unwrap();
    /// assert_eq!(m.spec().rolling[0].course_name(), "le roulement sans glissement");
    /// ```
    pub fn course_name(&self) -> &'static str {
        if self.on.is_empty() {
            "le roulement sans glissement"
        } else {
            "la condition de non-glissement"
        }
    }
}

/// A frame turned (and possibly moved) from its parent.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct FrameSpec {
    /// Frame name, also the subscript of its basis vectors (`1` gives x1, y1, z1, B1, R1).
    pub name: String,
    /// Parent frame.
    pub parent: String,
    /// Rotation from the parent basis; none means the bases coincide.
    #[serde(default)]
    pub rotation: Option<RotationSpec>,
    /// Origin point of the frame (a point of the spec), the ground origin unless given.
    #[serde(default)]
    pub origin: Option<String>,
    /// The names of its basis vectors as the statement writes them (`["u", "v", "w"]`),
    /// usable in every expression besides x1, y1, z1; the answer key prints them
    /// (\vec{u}). Quantity projections keep the x1 form.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub basis: Option<[String; 3]>,
}

/// Elementary rotation about a basis vector of the parent.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RotationSpec {
    /// `x`, `y` or `z` of the parent basis (`-z` for a negative orientation).
    pub axis: String,
    /// The angle: `±q + c`, one angle coordinate q (coefficient ±1) plus a constant c made of
    /// multiples of pi/2 and of angle parameters (`theta1`, `pi/2 - q1`, `theta - alpha`);
    /// or constants only, with at least one angle parameter (`alpha`, an incline).
    pub angle: String,
}

/// A point placed from another point by a vector expression.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PointSpec {
    /// Point name (`O2`, `G2`).
    pub name: String,
    /// The point it is placed from (the ground origin unless given).
    #[serde(default)]
    pub from: Option<String>,
    /// Vector from `from` to this point, e.g. `d1*z0 + L1*y1` (`0` for the same point).
    pub position: String,
}

/// Inertia operator of a solid as given by the statement.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct InertiaSpec {
    /// Point at which it is given (usually the centre of inertia).
    pub point: String,
    /// Basis in which the matrix is written (frame name).
    pub basis: String,
    /// 3x3 symmetric matrix of expressions.
    pub matrix: [[String; 3]; 3],
}

/// A solid.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
// Its frame, or the solid that carries it (whose frame it takes): an editor asks for one.
#[schemars(extend("anyOf" = [{"required": ["frame"]}, {"required": ["carried_by"]}]))]
pub struct SolidSpec {
    /// Solid name: its number (`1`, `2`).
    pub name: String,
    /// Frame attached to the solid; for a solid `carried_by` another, its carrier's frame
    /// when left out (and no other).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frame: Option<String>,
    /// The solid that carries this one (« le rotor porte une masse ponctuelle m en P »): it
    /// is rigidly fixed to it, with no link between them. Isolating the carrier isolates it
    /// too (and every solid it carries in turn); it is never isolated without its carrier,
    /// whose action on it is not modelled.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub carried_by: Option<String>,
    /// Mass expression; absent for a body of negligible mass (`"massless": true`). A mass
    /// of `0` declares a body of negligible mass too.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<String>,
    /// A body of negligible mass (« de masse négligeable »): a nacelle, a gimbal, a support
    /// that carries links and actions but whose kinetic and dynamic torsors and kinetic
    /// energy are zero, so that the PFD applied to it is the balance of the actions on it.
    /// It has no `mass`, no `inertia` and no `symmetries`; its `centre` may be left out.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub massless: bool,
    /// Centre of inertia (a point); may be left out for a body of negligible mass.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub centre: Option<String>,
    /// Inertia operator; absent for a point mass.
    #[serde(default)]
    pub inertia: Option<InertiaSpec>,
    /// Geometric symmetries of the solid (they zero products of inertia).
    #[serde(default)]
    pub symmetries: Vec<SymmetrySpec>,
}

/// A symmetry declaration, in the solid's frame.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields, tag = "kind", rename_all = "snake_case")]
pub enum SymmetrySpec {
    /// Plane of material symmetry through the centre, normal to the given basis vector
    /// (`x1` for the plane (G, y1, z1)).
    Plane {
        /// Basis vector normal to the plane.
        normal: String,
    },
    /// Axis of revolution through the centre, along the given basis vector.
    Revolution {
        /// Basis vector along the axis.
        axis: String,
    },
}

/// A hypothesis that yields an additional simplified form.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HypothesisSpec {
    /// Short name (`H1`).
    pub name: String,
    /// Statement as the course writes it.
    #[serde(default)]
    pub text: Option<String>,
    /// Coordinates whose rate is held constant (q̈ = 0).
    #[serde(default)]
    pub constant_rates: Vec<String>,
    /// Solids whose declared symmetries are applied to their inertia.
    #[serde(default)]
    pub symmetric_solids: Vec<String>,
    /// Coordinates held fixed (an angle α constant): q̇ = q̈ = 0, q itself kept.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub fixed_coordinates: Vec<String>,
    /// A relative equilibrium: each coordinate at a constant value (an angle coordinate at
    /// `0` or at an angle parameter, `"theta2": "beta0"`; a length at an expression of the
    /// parameters), with q̇ = q̈ = 0.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub equilibrium: BTreeMap<String, String>,
    /// Rates given as parameters: q̇ = the expression (`"theta3": "omega3"`), q̈ = 0.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub rates: BTreeMap<String, String>,
    /// Relations between parameters: the parameter replaced by an expression of the others
    /// (`"A3": "C3"`).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub relations: BTreeMap<String, String>,
    /// Small parameters (an offset e ≪ R): results kept to first order in them, the terms of
    /// degree 2 or more in these parameters together dropped.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub small_parameters: Vec<String>,
    /// A trial motion (« régime forcé »): the coordinate follows the given motion of the time,
    /// whose new names (`unknowns`) are solved so that the equation of motion holds at every t.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trial: Option<TrialSpec>,
}

/// A trial motion q(t) = motion (`X*cos(Omega*t)`), its unknowns (`X`) to be determined.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TrialSpec {
    /// The coordinate whose motion is posed (`x`).
    pub coordinate: String,
    /// Its motion, an expression of the time through phases Ω t, the parameters and the
    /// unknowns (`X*cos(Omega*t) + Y*sin(Omega*t)`).
    pub motion: String,
    /// The new names the motion holds, solved so that the equation of motion holds at every
    /// t (`["X", "Y"]`).
    pub unknowns: Vec<String>,
}
