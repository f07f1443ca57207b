//! The wire types of a simulation scenario: values, initial state, imposed motions.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A numerical scenario: parameter values, initial state, imposed motions.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ScenarioSpec {
    /// Name given to `simulate --scenario`.
    pub name: String,
    /// What it shows.
    #[serde(default)]
    pub description: Option<String>,
    /// How the answer key and the plots' legends name it (« sans frottement »); see
    /// [`ScenarioSpec::label`] for the default.
    #[serde(default)]
    pub label: Option<String>,
    /// Duration in seconds.
    pub duration: f64,
    /// Value of every parameter (SI units).
    pub values: BTreeMap<String, f64>,
    /// Initial value and rate of the free coordinates: `[q, q̇]`; for a coordinate driven by
    /// the others (a gear ratio, a loop closure), its value (its rate follows), which must
    /// close the loop.
    #[serde(default)]
    pub initial: BTreeMap<String, [f64; 2]>,
    /// Coordinates whose motion is imposed: their rate as a function of `t`, piece by piece.
    #[serde(default)]
    pub imposed: Vec<ImposedSpec>,
    /// Unknowns and coordinates to record (`C_m`, `theta2`), in output order.
    #[serde(default)]
    pub record: Vec<String>,
}

impl ScenarioSpec {
    /// The display label: the spec's `label`, or the name with its underscores as spaces
    /// (`sans_frottement` → « sans frottement »). Free text: it may hold `$…$` formulas.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// assert_eq!(m.spec().scenarios[0].label(), "sans frottement");
    /// ```
    pub fn label(&self) -> String {
        self.label
            .clone()
            .unwrap_or_else(|| self.name.replace('_', " "))
    }
}

/// An imposed motion: the rate of a coordinate as pieces `until` successive times.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ImposedSpec {
    /// The coordinate.
    pub coordinate: String,
    /// Initial value of the coordinate.
    #[serde(default)]
    pub initial: f64,
    /// Successive pieces of the rate law; the last one holds until the end.
    pub rate: Vec<RatePiece>,
}

/// One piece of an imposed rate law.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RatePiece {
    /// End of the piece in seconds (none for the last one).
    #[serde(default)]
    pub until: Option<f64>,
    /// The rate, an expression of `t` and the parameters (`2000*2*pi/60*t/0.5`).
    pub value: String,
}
