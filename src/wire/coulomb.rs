//! The wire types of Coulomb's law on a contact's unknowns (`contact_friction`).

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Coulomb's law on a contact's unknowns: the friction coefficient, the sliding direction t
/// and the normal n (one of them is the link's axis), and the names of T and N.
///
/// ```
/// let link: torseur::wire::LinkSpec = serde_json::from_str(
///     r#"{"name": "A", "kind": "point", "between": ["0", "1"], "point": "A", "axis": "y0",
///         "contact_friction": {"coefficient": "f", "tangent": "x0",
///                              "unknowns": {"T": "T_A", "N": "N_A"}}}"#).unwrap();
/// assert_eq!(link.sign_parameter().as_deref(), Some("epsilonA"));
/// ```
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ContactFrictionSpec {
    /// The friction coefficient f, a pure number: a constant expression of dimensionless
    /// parameters (`f`, `f1`, `0.3`).
    pub coefficient: String,
    /// The sliding direction t of a contact (point, plane, line): another basis vector of its
    /// normal's basis. A slider slides along its axis and omits it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangent: Option<String>,
    /// The normal n of a slider (the block's contact): another basis vector of its axis'
    /// basis, N ≥ 0 pressing the second solid along it. A contact's normal is its axis.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal: Option<String>,
    /// The names of T and N (`T_A`, `N_A`); the link's component names (X_A, Y_A) otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unknowns: Option<ContactUnknowns>,
}

/// The names of a contact's tangential and normal unknowns.
#[derive(Debug, Clone, Deserialize, Serialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ContactUnknowns {
    /// The tangential unknown T.
    #[serde(rename = "T")]
    pub tangential: String,
    /// The normal unknown N.
    #[serde(rename = "N")]
    pub normal: String,
}
