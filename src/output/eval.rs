//! Numeric evaluation of derived values at given parameters and coordinates.

use crate::derivation::Value;
use crate::expr::VarRole;
use crate::mechanism::Mechanism;
use serde::Deserialize;
use serde_json::{Value as Json, json};
use std::collections::BTreeMap;

/// A values file: `{"parameters": {"m2": 0.35}, "coordinates": {"theta1": [q, qdot, qddot]}}`.
#[derive(Debug, Clone, Deserialize, serde::Serialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Values {
    /// Parameter values.
    #[serde(default)]
    pub parameters: BTreeMap<String, f64>,
    /// Coordinate values [q, q̇, q̈].
    #[serde(default)]
    pub coordinates: BTreeMap<String, [f64; 3]>,
}

/// A values file that does not fit the mechanism.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("values: {0}")]
pub struct ValuesError(pub String);

impl Values {
    /// Parses a values file, naming the JSON path of a wrong entry.
    pub fn parse(text: &str) -> Result<Values, ValuesError> {
        let mut de = serde_json::Deserializer::from_str(text);
        let v: Values = serde_path_to_error::deserialize(&mut de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            ValuesError(format!(
                "at {path} (line {}, column {}): {inner}",
                inner.line(),
                inner.column()
            ))
        })?;
        de.end().map_err(|e| ValuesError(e.to_string()))?;
        Ok(v)
    }
}

/// The value of every polynomial variable of the mechanism at `values`.
pub fn numeric_point(m: &Mechanism, values: &Values) -> Result<Vec<f64>, ValuesError> {
    let reg = &m.reg;
    for p in values.parameters.keys() {
        if !reg.parameters().contains(p) {
            return Err(ValuesError(format!("unknown parameter `{p}`")));
        }
    }
    for q in values.coordinates.keys() {
        if reg.coord(q).is_none() {
            return Err(ValuesError(format!("unknown coordinate `{q}`")));
        }
    }
    let mut point = Vec::with_capacity(reg.nvars());
    for i in 0..reg.nvars() {
        let v = match reg.role(i) {
            // Solved values never contain an unknown.
            VarRole::Parameter(k) if reg.is_unknown(k) => f64::NAN,
            VarRole::Parameter(k) => {
                let name = &reg.parameters()[k];
                *values
                    .parameters
                    .get(name)
                    .ok_or_else(|| ValuesError(format!("missing parameter `{name}`")))?
            }
            // A constant angle parameter: its value is among the parameters.
            VarRole::Cos(q) | VarRole::Sin(q) if reg.coord_info(q).is_constant() => {
                let name = &reg.coord_info(q).name;
                let a = *values
                    .parameters
                    .get(name)
                    .ok_or_else(|| ValuesError(format!("missing parameter `{name}`")))?;
                if matches!(reg.role(i), VarRole::Cos(_)) {
                    a.cos()
                } else {
                    a.sin()
                }
            }
            VarRole::Cos(q) | VarRole::Sin(q) | VarRole::Value(q) | VarRole::Rate(q, _) => {
                let name = &reg.coord_info(q).name;
                let c = values
                    .coordinates
                    .get(name)
                    .ok_or_else(|| ValuesError(format!("missing coordinate `{name}`")))?;
                match reg.role(i) {
                    VarRole::Cos(_) => c[0].cos(),
                    VarRole::Sin(_) => c[0].sin(),
                    VarRole::Value(_) => c[0],
                    VarRole::Rate(_, 1) => c[1],
                    VarRole::Rate(_, 2) => c[2],
                    _ => f64::NAN,
                }
            }
        };
        let exempt = match reg.role(i) {
            VarRole::Rate(_, 3) => true,
            VarRole::Parameter(k) => reg.is_unknown(k),
            _ => false,
        };
        if !v.is_finite() && !exempt {
            return Err(ValuesError(format!("non-finite value for variable {i}")));
        }
        point.push(v);
    }
    Ok(point)
}

/// A derived value evaluated at a point, as the JSON of the CLI contract.
pub fn eval_value(m: &Mechanism, id: &str, v: &Value, point: &[f64]) -> Json {
    let ev = |c: &[crate::expr::Expr; 3]| -> Vec<f64> { c.iter().map(|e| e.eval(point)).collect() };
    match v {
        Value::Scalar(e) => json!({"id": id, "kind": "scalar", "value": e.eval(point)}),
        Value::Vector { basis, components } => json!({
            "id": id, "kind": "vector", "basis": format!("B{}", m.frame_name(*basis)), "value": ev(components)}),
        Value::Matrix(i) => json!({
            "id": id, "kind": "matrix", "point": m.point_name(i.point),
            "basis": format!("B{}", m.frame_name(i.basis)),
            "value": i.matrix.iter().map(ev).collect::<Vec<_>>()}),
        Value::Torsor {
            point: p,
            basis,
            resultant,
            moment,
        } => json!({
            "id": id, "kind": "torsor", "point": m.point_name(*p),
            "basis": format!("B{}", m.frame_name(*basis)),
            "resultant": ev(resultant), "moment": ev(moment)}),
    }
}
