//! The independent float backend: mechanics recomputed numerically from the course's definitions.
//!
//! Nothing here shares formula code with the exact side (`expr`, `frame`, `kinematics`,
//! `torsor`, symbolica): the spec's expressions are parsed again by a hand-written parser,
//! frames are rotation matrices, and every time derivative is exact through second-order dual
//! numbers in t — each coordinate is q(t) = q + q̇ t + q̈ t²/2 around t = 0, so a position's
//! dual parts are its velocity and acceleration, never a finite difference. Vectors and
//! matrices are nalgebra's `Vector3` and `Matrix3`, over `f64` and over num-dual's `Dual2_64`.
//!
//! Each solid is realised as a cloud of point masses with the solid's mass, centre of inertia
//! and inertia operator at G, and the kinetic and dynamic elements are the course's sums:
//!
//! - Rc(S/R0) = Σ mₖ V(Pₖ/R0), σ(A, S/R0) = Σ mₖ APₖ ∧ V(Pₖ/R0);
//! - Rd(S/R0) = Σ mₖ Γ(Pₖ/R0), δ(A, S/R0) = Σ mₖ APₖ ∧ Γ(Pₖ/R0);
//! - I(A, S) = Σ mₖ (|APₖ|² Id − APₖ APₖᵀ);
//! - Ec(S/R0) = Σ ½ mₖ |V(Pₖ/R0)|².
//!
//! The PFD (`dynamics`) is recomputed the same way: gravity acts on every point mass, the
//! links' unknowns, friction, springs and given actions are torsors at their points with their
//! reactions, each declared theorem is a residual affine in the unknowns, and the equations
//! without `eom` are solved with nalgebra's LU.
//!
//! ```
//! use torseur::numeric::{NumericModel, NumValue, Sample};
//! use torseur::quantity::Quantity;
//! let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
//! let spec: torseur::spec::wire::SpecFile = serde_json::from_str(&text).unwrap();
//! let model = NumericModel::new(&spec).unwrap();
//! let sample = model.sample(&mut rand::rng()).unwrap();
//! let q = Quantity::parse("{D(E/0)}_O2 in B1").unwrap();
//! assert!(matches!(model.evaluate(&q, &sample, "0").unwrap(), NumValue::Torsor { .. }));
//! ```

mod closure;
mod cloud;
mod dynamics;
pub(crate) mod expr;
mod kin;
mod la;
mod model;
mod quantities;
mod sample;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_pfd;
#[cfg(test)]
mod tests_regulator;
mod validate;

use crate::quantity::Quantity;
use crate::wire::{CoordinateKind, SpecFile};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Values of the parameters and of the time coordinates at one instant.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Sample {
    /// Value of every parameter of the spec.
    #[serde(default)]
    pub parameters: BTreeMap<String, f64>,
    /// `[q, q̇, q̈]` of every time coordinate of the spec.
    #[serde(default)]
    pub coordinates: BTreeMap<String, [f64; 3]>,
    /// The time t, for a spec that writes it (a forcing F0 cos(Ω t)).
    #[serde(default)]
    pub time: f64,
}

/// A numeric value of a quantity. Bases are frame names (`"2"` for B2).
#[derive(Debug, Clone, PartialEq)]
pub enum NumValue {
    /// A projection such as `delta(O2,2/0).x2`.
    Scalar(f64),
    /// A vector: its components in the basis of frame `basis`.
    Vector {
        /// Frame whose basis holds the components.
        basis: String,
        /// Components.
        value: [f64; 3],
    },
    /// An inertia operator: its matrix in the basis of frame `basis` (rows).
    Matrix {
        /// Frame whose basis holds the matrix.
        basis: String,
        /// Rows of the matrix.
        value: [[f64; 3]; 3],
    },
    /// A torsor at `point`, its resultant and moment in the basis of frame `basis`.
    Torsor {
        /// Point of reduction.
        point: String,
        /// Frame whose basis holds the components.
        basis: String,
        /// Resultant.
        resultant: [f64; 3],
        /// Moment at `point`.
        moment: [f64; 3],
    },
}

impl NumValue {
    /// All the numbers of the value, in a fixed order (a torsor: resultant then moment).
    ///
    /// ```
    /// use torseur::numeric::NumValue;
    /// let v = NumValue::Vector { basis: "0".into(), value: [1.0, 2.0, 3.0] };
    /// assert_eq!(v.numbers(), vec![1.0, 2.0, 3.0]);
    /// ```
    pub fn numbers(&self) -> Vec<f64> {
        match self {
            NumValue::Scalar(x) => vec![*x],
            NumValue::Vector { value, .. } => value.to_vec(),
            NumValue::Matrix { value, .. } => value.iter().flatten().copied().collect(),
            NumValue::Torsor {
                resultant, moment, ..
            } => resultant.iter().chain(moment).copied().collect(),
        }
    }
}

/// Why a numeric evaluation or a sample failed. Messages name the spec's objects.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NumericError {
    /// The spec cannot be realised numerically (unknown name, cycle, bad expression...).
    #[error(
        "spec, at {}: {}",
        crate::excerpt::excerpt(.path),
        crate::excerpt::bounded(.message)
    )]
    Spec {
        /// JSON path of the faulty value (`points[2].position`).
        path: String,
        /// What is wrong.
        message: String,
    },
    /// A name in a quantity or argument that the spec does not define.
    #[error("unknown {what} `{}`", crate::excerpt::excerpt(.name))]
    Unknown {
        /// What kind of object was expected (`point`, `frame`, `solid or set`...).
        what: String,
        /// The name given.
        name: String,
    },
    /// The sample does not fit the spec (missing, unknown or non-finite value).
    #[error("sample: {0}")]
    Sample(String),
    /// A solid whose mass or inertia no material body can have.
    #[error("solid {solid}: {message}")]
    NotPhysical {
        /// Solid name.
        solid: String,
        /// What is wrong.
        message: String,
    },
    /// A quantity that cannot be evaluated as asked.
    #[error("{quantity}: {message}")]
    Quantity {
        /// The quantity, in course notation.
        quantity: String,
        /// Why.
        message: String,
    },
    /// An expression that fails at these values (division by zero, overflow).
    #[error(
        "{}: {}",
        crate::excerpt::bounded(.what),
        crate::excerpt::bounded(.message)
    )]
    Evaluation {
        /// Where the expression comes from (`position of point G2`).
        what: String,
        /// What went wrong.
        message: String,
    },
    /// No sample can be drawn for this spec.
    #[error("cannot draw a sample: {0}")]
    Sampling(String),
}

/// A parameter and how it is drawn.
#[derive(Debug, Clone)]
struct ParamInfo {
    name: String,
    /// Drawn in [0.5, 2] (lengths, masses) rather than [−1, 1].
    positive: bool,
}

/// A time coordinate.
#[derive(Debug, Clone)]
struct CoordInfo {
    name: String,
    kind: CoordinateKind,
    /// Imposed rate: q̇ is its value and q̈ = 0 for parameters only; driven by the rates of
    /// other coordinates (`driven`), q̇ is its value at their rates and q̈ its value at their
    /// accelerations less its value at rest (it is affine in them).
    rate: Option<expr::Node>,
    rate_text: Option<String>,
    driven: bool,
}

/// A frame: orientation from its parent, and origin point.
#[derive(Debug, Clone)]
struct FrameInfo {
    name: String,
    /// Parent index (the ground is its own parent, index 0).
    parent: usize,
    /// (axis 0..3, sign, angle) of the elementary rotation from the parent.
    rotation: Option<(usize, f64, expr::Node)>,
    /// Origin point index.
    origin: usize,
}

/// A point placed from another one.
#[derive(Debug, Clone)]
struct PointInfo {
    name: String,
    from: usize,
    position: expr::Node,
}

/// Inertia operator as the spec gives it.
#[derive(Debug, Clone)]
struct InertiaInfo {
    point: usize,
    basis: usize,
    matrix: [[expr::Node; 3]; 3],
    text: [[String; 3]; 3],
}

/// A declared symmetry: plane normal to, or revolution about, a basis vector through G.
#[derive(Debug, Clone)]
struct Symmetry {
    frame: usize,
    axis: usize,
    revolution: bool,
}

/// A solid.
#[derive(Debug, Clone)]
struct SolidInfo {
    name: String,
    frame: usize,
    mass: expr::Node,
    centre: usize,
    inertia: Option<InertiaInfo>,
    symmetries: Vec<Symmetry>,
}

/// What a hypothesis imposes on samples.
#[derive(Debug, Clone)]
struct Hypothesis {
    symmetric_solids: Vec<usize>,
    constant_rates: Vec<usize>,
    /// Coordinates whose motion is given: (coordinate, its value if held at one, q̇ if given
    /// as an expression, else 0), and q̈ = 0.
    motions: Vec<(usize, Option<expr::Node>, Option<expr::Node>)>,
    /// Parameters set from the others.
    relations: Vec<(usize, expr::Node)>,
    /// A trial motion: (coordinate, its motion, a function of the time).
    trial: Option<(usize, expr::Node)>,
}

/// A spec made numeric: built once, then evaluated at any number of samples.
///
/// Frames and points are stored in tree order (each after its parent); index 0 is the ground
/// frame and the ground origin.
#[derive(Debug, Clone)]
pub struct NumericModel {
    params: Vec<ParamInfo>,
    /// Named expressions of the parameters, (name, value).
    aliases: Vec<(String, expr::Node)>,
    /// Basis vectors named as the statement does: (frame index, axis).
    vectors: BTreeMap<String, (usize, usize)>,
    /// Whether the spec writes the time t (its samples then draw it).
    uses_time: bool,
    coords: Vec<CoordInfo>,
    frames: Vec<FrameInfo>,
    points: Vec<PointInfo>,
    solids: Vec<SolidInfo>,
    sets: BTreeMap<String, Vec<usize>>,
    hypotheses: BTreeMap<String, Hypothesis>,
    param_index: BTreeMap<String, usize>,
    coord_index: BTreeMap<String, usize>,
    frame_index: BTreeMap<String, usize>,
    point_index: BTreeMap<String, usize>,
    solid_index: BTreeMap<String, usize>,
    /// Gravity, links, actions and the declared equations of the PFD.
    dynamics: dynamics::Dynamics,
    /// Loop closures, solved numerically at each sample.
    closures: Vec<closure::Closure>,
    /// Rolling conditions, solved numerically at each sample.
    rolling: Vec<closure::Rolling>,
    /// Helical links: the screw motions that determine coordinates, solved with the loops.
    helices: Vec<closure::Helix>,
}

impl NumericModel {
    /// The names the spec's expressions read, resolved to this model's indices.
    fn names(&self) -> model::Names<'_> {
        model::Names {
            params: &self.param_index,
            coords: &self.coord_index,
            frames: &self.frame_index,
            aliases: &self.aliases,
            vectors: &self.vectors,
        }
    }
}

impl NumericModel {
    /// Builds the numeric model of a spec: resolves every name and parses every expression.
    ///
    /// ```
    /// use torseur::numeric::NumericModel;
    /// let spec: torseur::spec::wire::SpecFile = serde_json::from_str(
    ///     r#"{"title": "t", "frames": [{"name": "1", "parent": "7"}]}"#).unwrap();
    /// let e = NumericModel::new(&spec).unwrap_err();
    /// assert_eq!(e.to_string(), "spec, at frames[0].parent: unknown frame `7` (declared: `0`, `1`)");
    /// ```
    pub fn new(spec: &SpecFile) -> Result<NumericModel, NumericError> {
        let refused = |e: crate::resolve::Refusal| NumericError::Spec {
            path: e.path,
            message: e.message,
        };
        // The signs of dry friction (parameters the samples set), then the names, trees and
        // references, resolved once for both sides (`crate::resolve`).
        let signed = crate::resolve::with_signs(spec).map_err(refused)?;
        let spec = signed.as_ref();
        let trees = crate::resolve::resolve(spec).map_err(refused)?;
        // The PFD's unknowns, named by the resolution from this backend's own reading of which
        // components each link transmits.
        let unknowns =
            crate::resolve::unknowns(spec, &trees, &dynamics::transmitted).map_err(refused)?;
        let mut model = model::build(spec, &trees)?;
        model.closures = closure::build(spec, &model, &trees)?;
        model.rolling = trees.rolling.clone();
        model.helices = closure::helices(spec, &model, &trees)?;
        closure::validate_shape(&model)?;
        model.dynamics = dynamics::build(spec, &model, &trees, unknowns)?;
        model::mark_positive(&mut model);
        model.uses_time = model.writes_time();
        model.validate_laws()?;
        Ok(model)
    }

    /// Coulomb's laws: each contact slides along its tangent and never across it, at three
    /// samples of its own (not checked when the mechanism cannot be sampled: `check` says so).
    fn validate_laws(&self) -> Result<(), NumericError> {
        use rand::SeedableRng;
        if self.dynamics.links.iter().all(|l| l.law.is_none()) {
            return Ok(());
        }
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(37);
        let mut vals = Vec::new();
        for _ in 0..3 {
            let Ok(s) = self.sample(&mut rng) else {
                return Ok(());
            };
            vals.push(kin::values(self, &s)?);
        }
        dynamics::validate_sliding(self, &vals)
    }

    /// Whether the spec writes the time t (a forcing F0 cos(Ω t), a frame turned by Ω t):
    /// its samples then draw t too. Read once, when the model is built.
    fn writes_time(&self) -> bool {
        let frames = self
            .frames
            .iter()
            .filter_map(|f| f.rotation.as_ref().map(|r| &r.2));
        let points = self.points.iter().map(|p| &p.position);
        let actions = self
            .dynamics
            .actions
            .iter()
            .flat_map(|a| [a.resultant.as_ref(), a.moment.as_ref()])
            .flatten();
        let trials = self
            .hypotheses
            .values()
            .filter_map(|h| h.trial.as_ref().map(|t| &t.1));
        (frames.chain(points).chain(actions).chain(trials)).any(expr::holds_time)
    }

    /// Evaluates a quantity in course notation at `sample`.
    ///
    /// A vector is given in the basis `q.basis`, else in `default_basis` (a frame name); a
    /// projection `.x2` gives the scalar product with x2. Velocities and accelerations are those
    /// of the point of the moving solid that coincides with P at the sample's instant; the
    /// moving and reference bodies are solids (their frames) or frames, and kinetic and
    /// dynamic elements take a solid or a set (`sets` of the spec) and sum over its solids.
    /// A coordinate with an imposed rate must be given q̇ equal to that rate and q̈ = 0.
    ///
    /// Scalars by themselves: `Ec(S/R)` is Σ ½ mₖ |V(Pₖ/R)|² over the clouds of S; an unknown
    /// (`C_m`, `X01`) is its value solved from the spec's `pfd` equations without `eom`
    /// (square, nonsingular, nalgebra's LU); `eom(q)` is the residual (dynamic side minus
    /// actions) of the equation whose `eom` is q, those unknowns substituted and q̈ the
    /// sample's. Actions are gravity on every point mass of the clouds, the links (one unknown
    /// per transmitted component, with viscous friction and springs), the given actions, and
    /// the reaction of each; isolating S keeps those a member receives from a non-member.
    ///
    /// ```
    /// use torseur::numeric::{NumericModel, NumValue, Sample};
    /// use torseur::quantity::Quantity;
    /// let spec: torseur::spec::wire::SpecFile = serde_json::from_str(r#"{
    ///   "title": "arm", "parameters": [{"name": "L"}],
    ///   "coordinates": [{"name": "q", "kind": "angle"}],
    ///   "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}}],
    ///   "points": [{"name": "P", "position": "L*x1"}]}"#).unwrap();
    /// let model = NumericModel::new(&spec).unwrap();
    /// let s = Sample {
    ///     parameters: [("L".to_string(), 2.0)].into(),
    ///     coordinates: [("q".to_string(), [0.3, 5.0, 0.0])].into(),
    ///     time: 0.0,
    /// };
    /// let v = model.evaluate(&Quantity::parse("V(P,1/0).y1").unwrap(), &s, "0").unwrap();
    /// assert!(matches!(v, NumValue::Scalar(x) if (x - 10.0).abs() < 1e-12));
    /// ```
    pub fn evaluate(
        &self,
        q: &Quantity,
        sample: &Sample,
        default_basis: &str,
    ) -> Result<NumValue, NumericError> {
        self.evaluate_with(q, sample, &BTreeMap::new(), default_basis)
    }

    /// [`NumericModel::evaluate`], the unknowns of the PFD taking the values `unknowns` gives:
    /// an action of the bilan (`R(0->1)`, `M(A,ext->E).z0`, `{T(0->1)}_A`) holds the
    /// unknowns of its links as they are, before the PFD is solved.
    ///
    /// ```
    /// use torseur::numeric::{NumericModel, NumValue, Sample};
    /// use torseur::quantity::Quantity;
    /// let spec: torseur::spec::wire::SpecFile = serde_json::from_str(r#"{
    ///   "title": "arm", "ground_origin": "O",
    ///   "parameters": [{"name": "L"}, {"name": "m"}, {"name": "g"}],
    ///   "coordinates": [{"name": "q", "kind": "angle"}],
    ///   "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "q"}}],
    ///   "points": [{"name": "G", "position": "L*x1"}],
    ///   "solids": [{"name": "1", "frame": "1", "mass": "m", "centre": "G"}],
    ///   "gravity": "-g*y0"}"#).unwrap();
    /// let model = NumericModel::new(&spec).unwrap();
    /// let s = Sample {
    ///     parameters: [("L", 2.0), ("m", 3.0), ("g", 10.0)].map(|(n, v)| (n.to_string(), v)).into(),
    ///     coordinates: [("q".to_string(), [0.0, 0.0, 0.0])].into(),
    ///     time: 0.0,
    /// };
    /// // The weight's moment at O about z0: (2 x0) ∧ (−30 y0) = −60 z0.
    /// let q = Quantity::parse("M(O,pes->1).z0").unwrap();
    /// let v = model.evaluate_with(&q, &s, &Default::default(), "0").unwrap();
    /// assert!(matches!(v, NumValue::Scalar(x) if (x + 60.0).abs() < 1e-9));
    /// ```
    pub fn evaluate_with(
        &self,
        q: &Quantity,
        sample: &Sample,
        unknowns: &BTreeMap<String, f64>,
        default_basis: &str,
    ) -> Result<NumValue, NumericError> {
        if q.linear {
            return Err(NumericError::Quantity {
                quantity: q.to_string(),
                message: "the float backend computes full motions, not linearisations".into(),
            });
        }
        quantities::evaluate(self, q, sample, unknowns, default_basis)
    }

    /// Draws a random physically valid sample, reproducible from the generator's state.
    ///
    /// Lengths and masses (parameters with unit m or kg, or entering a mass) and the
    /// parameters of gravity, friction coefficients and stiffnesses are drawn in [0.5, 2], other
    /// parameters in [−1, 1] (the unknowns of the PFD are not parameters: they get no value); angles in [−π, π], length coordinates in
    /// [0.5, 2], rates and accelerations in [−2, 2] (an imposed rate is evaluated, with q̈ = 0).
    /// Inertia entries written `P` or `-P` are read off a random cloud of point masses with the
    /// solid's mass, so the matrix is always a real body's; the cloud gets the mirror planes,
    /// quarter-turn axes or flatness that the written zeros and repeated entries require.
    /// Entries written in terms of other parameters (`m*l^2/12`) are kept as written.
    ///
    /// ```
    /// use rand::SeedableRng;
    /// let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
    /// let spec = serde_json::from_str(&text).unwrap();
    /// let model = torseur::numeric::NumericModel::new(&spec).unwrap();
    /// let a = model.sample(&mut rand_chacha::ChaCha8Rng::seed_from_u64(1)).unwrap();
    /// let b = model.sample(&mut rand_chacha::ChaCha8Rng::seed_from_u64(1)).unwrap();
    /// assert_eq!(a, b);
    /// ```
    pub fn sample(&self, rng: &mut impl rand::Rng) -> Result<Sample, NumericError> {
        self.draw_closed(rng, None)
    }

    /// A sample whose loops close: drawn again (up to 100 times) while a loop closure cannot
    /// close at the drawn lengths and angles (a crank longer than its rod at that angle).
    fn draw_closed(
        &self,
        rng: &mut impl rand::Rng,
        h: Option<&Hypothesis>,
    ) -> Result<Sample, NumericError> {
        let mut last = None;
        for _ in 0..100 {
            match sample::draw(self, rng, h) {
                Err(NumericError::Sampling(m))
                    if !(self.closures.is_empty()
                        && self.rolling.is_empty()
                        && self.helices.is_empty())
                        && m.starts_with("closures:") =>
                {
                    last = Some(m);
                }
                r => return r,
            }
        }
        Err(NumericError::Sampling(last.unwrap_or_default()))
    }

    /// Draws a random sample that satisfies the spec's hypothesis `name`: its symmetric solids
    /// get clouds with the declared symmetries, its constant rates get q̈ = 0, its fixed
    /// coordinates, equilibrium and given rates their values, its relations their parameters.
    ///
    /// ```
    /// use rand::SeedableRng;
    /// let text = std::fs::read_to_string("derivations/regulateur_centrifuge.json").unwrap();
    /// let spec = serde_json::from_str(&text).unwrap();
    /// let model = torseur::numeric::NumericModel::new(&spec).unwrap();
    /// let s = model.sample_under(&mut rand_chacha::ChaCha8Rng::seed_from_u64(1), "H2").unwrap();
    /// assert_eq!(s.coordinates["theta1"][2], 0.0);
    /// assert!(s.parameters["F2"].abs() < 1e-12);
    /// ```
    pub fn sample_under(
        &self,
        rng: &mut impl rand::Rng,
        hypothesis: &str,
    ) -> Result<Sample, NumericError> {
        let h = self
            .hypotheses
            .get(hypothesis)
            .ok_or_else(|| NumericError::Unknown {
                what: "hypothesis".into(),
                name: hypothesis.into(),
            })?;
        self.draw_closed(rng, Some(h))
    }

    /// The sample moved along the trial motion of hypothesis `name` at the time `t`: its
    /// coordinate and rates from the motion (with the sample's values of the trial's
    /// unknowns), the rest kept.
    pub fn along_trial(&self, name: &str, sample: &Sample, t: f64) -> Result<Sample, NumericError> {
        let h = (self.hypotheses.get(name)).ok_or_else(|| NumericError::Unknown {
            what: "hypothesis".into(),
            name: name.into(),
        })?;
        let Some((i, motion)) = &h.trial else {
            return Err(NumericError::Sampling(format!(
                "`{name}` poses no trial motion"
            )));
        };
        let params: Vec<f64> = (self.params.iter())
            .map(|p| sample.parameters.get(&p.name).copied().unwrap_or(0.0))
            .collect();
        let at = sample::trial_motion(motion, &params, t).map_err(NumericError::Sampling)?;
        let mut out = sample.clone();
        out.time = t;
        out.coordinates.insert(self.coords[*i].name.clone(), at);
        Ok(out)
    }

    /// Evaluates a scalar expression of the spec's syntax (parameters, coordinates, `dot(q)`,
    /// `ddot(q)`, `sin`, `cos`, `pi`) at the sample's instant.
    ///
    /// ```
    /// use torseur::numeric::{NumericModel, Sample};
    /// let spec = serde_json::from_str(r#"{"title": "t", "parameters": [{"name": "m"}],
    ///     "coordinates": [{"name": "q", "kind": "angle"}]}"#).unwrap();
    /// let model = NumericModel::new(&spec).unwrap();
    /// let s = Sample {
    ///     parameters: [("m".to_string(), 3.0)].into(),
    ///     coordinates: [("q".to_string(), [0.0, 2.0, 0.5])].into(),
    ///     time: 0.0,
    /// };
    /// let v = model.evaluate_expression("m*cos(q)*dot(q)^2 + ddot(q)", &s).unwrap();
    /// assert_eq!(v, 12.5);
    /// ```
    pub fn evaluate_expression(&self, text: &str, sample: &Sample) -> Result<f64, NumericError> {
        quantities::evaluate_expression(self, text, sample)
    }

    /// Names of the parameters, in the spec's order.
    pub fn parameter_names(&self) -> impl Iterator<Item = &str> {
        self.params.iter().map(|p| p.name.as_str())
    }

    /// Names of the unknowns of the PFD (never parameters, so never in a [`Sample`]): the
    /// transmitted components of the links in order (X, Y, Z, L, M, N followed by the link's
    /// name), then the actions' unknowns in order of first appearance.
    pub fn unknown_names(&self) -> impl Iterator<Item = &str> {
        self.dynamics.unknowns.iter().map(String::as_str)
    }
}
