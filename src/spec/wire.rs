//! JSON wire types of a problem spec: what a teacher writes, before validation.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A whole problem as written in `derivations/*.json`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SpecFile {
    /// Title of the problem (answer-key heading).
    pub title: String,
    /// Optional statement or source.
    #[serde(default)]
    pub description: Option<String>,
    /// Constant parameters, in the order they should be listed.
    #[serde(default)]
    pub parameters: Vec<ParameterSpec>,
    /// Time coordinates q(t).
    #[serde(default)]
    pub coordinates: Vec<CoordinateSpec>,
    /// Name of the fixed (Galilean) frame, `0` unless given.
    #[serde(default = "default_ground")]
    pub ground: String,
    /// Name of the origin point of the ground frame, `O0` unless given.
    #[serde(default)]
    pub ground_origin: Option<String>,
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
}

/// One question of the statement and what its answer shows.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct QuestionSpec {
    /// Heading (`Question 3`).
    pub title: String,
    /// The question as the subject asks it.
    #[serde(default)]
    pub statement: Option<String>,
    /// The teacher's text: a method, a discussion.
    #[serde(default)]
    pub answer: Option<String>,
    /// Hypotheses whose consequences the answer shows (particular inertia matrices, what is
    /// set to zero).
    #[serde(default)]
    pub hypotheses: Vec<String>,
    /// Quantities derived step by step in the answer.
    #[serde(default)]
    pub quantities: Vec<String>,
    /// Equations `lhs = quantity` written out (a theorem applied, e.g. the motor torque).
    #[serde(default)]
    pub equations: Vec<EquationSpec>,
}

/// An equation of an answer: a named unknown equal to a derived quantity.
#[derive(Debug, Clone, Deserialize, Serialize)]
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

/// A constant parameter.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ParameterSpec {
    /// Identifier (`m2`, `L1`, `A2`).
    pub name: String,
    /// What it is, in the course's words.
    #[serde(default)]
    pub description: Option<String>,
    /// Unit, for the answer key.
    #[serde(default)]
    pub unit: Option<String>,
}

/// Kind of a time coordinate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum CoordinateKind {
    /// Enters through cos q and sin q.
    Angle,
    /// Enters polynomially.
    Length,
}

/// A time coordinate q(t).
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CoordinateSpec {
    /// Identifier (`theta1`, `lambda`).
    pub name: String,
    /// Angle or length.
    pub kind: CoordinateKind,
    /// What it is.
    #[serde(default)]
    pub description: Option<String>,
    /// Imposed constant rate: q̇ is this parameter expression and q̈ = 0.
    #[serde(default)]
    pub rate: Option<String>,
}

/// A frame turned (and possibly moved) from its parent.
#[derive(Debug, Clone, Deserialize, Serialize)]
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
}

/// Elementary rotation about a basis vector of the parent.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RotationSpec {
    /// `x`, `y` or `z` of the parent basis (`-z` for a negative orientation).
    pub axis: String,
    /// A coordinate name or a constant angle expression.
    pub angle: String,
}

/// A point placed from another point by a vector expression.
#[derive(Debug, Clone, Deserialize, Serialize)]
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
#[derive(Debug, Clone, Deserialize, Serialize)]
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
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SolidSpec {
    /// Solid name: its number (`1`, `2`).
    pub name: String,
    /// Frame attached to the solid.
    pub frame: String,
    /// Mass expression.
    pub mass: String,
    /// Centre of inertia (a point).
    pub centre: String,
    /// Inertia operator; absent for a point mass.
    #[serde(default)]
    pub inertia: Option<InertiaSpec>,
    /// Geometric symmetries of the solid (they zero products of inertia).
    #[serde(default)]
    pub symmetries: Vec<SymmetrySpec>,
}

/// A symmetry declaration, in the solid's frame.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, Serialize)]
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
#[derive(Debug, Clone, Deserialize, Serialize)]
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
}
