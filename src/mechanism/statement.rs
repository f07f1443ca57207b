//! What the statement (« l'énoncé ») says besides the mechanics, typed once when the spec is
//! validated: the links as the course describes them, the loop closures and the coordinates
//! they determine, the descriptions of the paramétrage, the questions and the scenarios of
//! the simulations. The outputs read these, not the spec as written.

use crate::expr::{CoordId, Expr};
use crate::quantity::Quantity;
use crate::vector::Vector;
use crate::wire::{LinkKind, ScenarioSpec, SimulationSpec};

/// A link (« liaison ») as the statement describes it: its kind and geometry by the names
/// the statement gives, and what it adds to a perfect link (friction, spring), read.
#[doc(alias = "liaison")]
#[derive(Debug, Clone)]
pub struct Link {
    /// Its name (`01`).
    pub name: String,
    /// Pivot, glissière, …
    pub kind: LinkKind,
    /// Its two solids (or the ground) by name: the link's action is the first's on the second.
    pub between: [String; 2],
    /// Its point, by name.
    pub point: String,
    /// Its axis or normal, a basis vector by name (`z0`).
    pub axis: Option<String>,
    /// A linear rectilinear contact's line direction, a basis vector by name.
    pub direction: Option<String>,
    /// A helical link's pitch p (« pas »).
    pub pitch: Option<Expr>,
    /// The pitch's name, when the statement gives it as one parameter (`p`).
    pub pitch_name: Option<String>,
    /// The coordinate a helical link determines (« paramètre dépendant »).
    pub dependent: Option<CoordId>,
    /// The coefficient of viscous friction (« frottement visqueux »).
    pub viscous: Option<Expr>,
    /// The intensity of dry friction (« frottement sec »), C.
    pub dry: Option<Expr>,
    /// A contact's coefficient of friction f (« loi de Coulomb »).
    pub coefficient: Option<Expr>,
    /// The sign ε of the relative rate, under dry friction or Coulomb's law.
    pub sign: Option<Expr>,
    /// The spring in the link (« ressort »).
    pub spring: Option<LinkSpring>,
    /// How a sentence names it (« la liaison pivot entre 0 et 1 »).
    pub label: String,
}

/// A spring mounted in a link: its stiffness, and whether it is a torsion spring (it
/// measures an angle).
#[derive(Debug, Clone)]
pub struct LinkSpring {
    /// Stiffness k (« raideur »).
    pub stiffness: Expr,
    /// A torsion spring (« ressort de torsion »).
    pub torsion: bool,
}

/// A loop closure (« fermeture géométrique ») OA + AB + BO = 0⃗.
#[derive(Debug, Clone)]
pub struct Closure {
    /// The vector as the statement writes it, to name the relation.
    pub written: String,
    /// The vector, read with the mechanism's bases.
    pub vector: Vector,
    /// The coordinates it determines.
    pub dependent: Vec<CoordId>,
}

/// What determines a dependent coordinate's rate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DeterminedBy {
    /// A loop closure (« la loi entrée-sortie »).
    Closure,
    /// A rolling condition: of the whole velocity (« roulement sans glissement ») or along
    /// some directions (« condition de non-glissement »).
    Rolling {
        /// The whole velocity is zero.
        whole: bool,
    },
    /// A helical link, by its position among the links.
    Helical(usize),
}

impl DeterminedBy {
    /// How the answer key names a rolling condition: « le roulement sans glissement » for the
    /// whole velocity, « la condition de non-glissement » for some directions; None for the
    /// others.
    pub fn rolling_name(self) -> Option<&'static str> {
        match self {
            DeterminedBy::Rolling { whole: true } => Some("le roulement sans glissement"),
            DeterminedBy::Rolling { whole: false } => Some("la condition de non-glissement"),
            _ => None,
        }
    }
}

/// A dependent coordinate (« paramètre dépendant ») and what determines its rate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Dependent {
    /// The coordinate.
    pub coord: CoordId,
    /// What gives its rate.
    pub by: DeterminedBy,
}

/// A coordinate as the paramétrage states it.
#[derive(Debug, Clone)]
pub struct Coordinate {
    /// Its name.
    pub name: String,
    /// The coordinate, when the registry has it as one.
    pub coord: Option<CoordId>,
    /// Its description.
    pub description: Option<String>,
    /// Held constant (rate 0): a constant, not a function of t.
    pub constant: bool,
}

/// A question of the statement.
#[derive(Debug, Clone)]
pub struct Question {
    /// Its title (`Question 1`).
    pub title: String,
    /// Its statement.
    pub statement: Option<String>,
    /// The teacher's answer text.
    pub answer: Option<String>,
    /// The hypotheses it states, by position among the mechanism's.
    pub hypotheses: Vec<usize>,
    /// The hypothesis it works under, by position.
    pub under: Option<usize>,
    /// The quantities it asks for.
    pub quantities: Vec<Quantity>,
    /// The equations it writes out.
    pub equations: Vec<Equation>,
    /// The simulation it shows.
    pub simulation: Option<SimulationSpec>,
}

/// An equation a question writes out: `C_m = δ(O1,E/0)·z0`.
#[derive(Debug, Clone)]
pub struct Equation {
    /// The name on the left.
    pub lhs: String,
    /// The quantity on the right.
    pub quantity: Quantity,
    /// Why it holds.
    pub reason: Option<String>,
}

/// The statement's words and questions.
#[derive(Debug, Clone, Default)]
pub struct Statement {
    /// The coordinates, in the statement's order.
    pub coordinates: Vec<Coordinate>,
    /// Each alias' description, in the statement's order.
    pub aliases: Vec<Option<String>>,
    /// The questions.
    pub questions: Vec<Question>,
    /// The scenarios of the simulations.
    pub scenarios: Vec<ScenarioSpec>,
    /// Every free text with its JSON path, to name the text a LaTeX error comes from.
    pub free_texts: Vec<(String, String)>,
}
