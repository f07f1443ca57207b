//! Numeric evaluation of derived values at given parameters and coordinates.

use crate::derivation::Value;
use crate::expr::{Expr, Registry, Trig, VarId, VarRole};
use crate::mechanism::Mechanism;
use serde::Deserialize;
use serde_json::{Value as Json, json};
use std::collections::BTreeMap;

/// A values file: `{"parameters": {"m2": 0.35}, "coordinates": {"theta1": [q, qdot, qddot]}}`,
/// and optionally `"unknowns": {"X01": 2.5}`: values for the unknowns of the PFD that an
/// action of the bilan holds (those not given are solved for).
#[derive(Debug, Clone, Deserialize, serde::Serialize, Default)]
#[serde(deny_unknown_fields)]
pub struct Values {
    /// Parameter values.
    #[serde(default)]
    pub parameters: BTreeMap<String, f64>,
    /// Coordinate values [q, q̇, q̈].
    #[serde(default)]
    pub coordinates: BTreeMap<String, [f64; 3]>,
    /// Values of unknowns of the PFD.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub unknowns: BTreeMap<String, f64>,
    /// The time t, for a spec that writes it (`cos(Omega*t)`): each phase Ω t is then Ω
    /// times it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time: Option<f64>,
}

/// A values file that does not fit the mechanism.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("values: {0}")]
pub struct ValuesError(pub String);

/// A number of the values file, or an expression of the others (`"atan(omega^2*a/g)"`).
#[derive(Debug, Clone, Deserialize)]
#[serde(untagged)]
enum Entry {
    Number(f64),
    Text(String),
}

/// The values file as written, before its expressions are evaluated.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawValues {
    #[serde(default)]
    parameters: BTreeMap<String, Entry>,
    #[serde(default)]
    coordinates: BTreeMap<String, [Entry; 3]>,
    #[serde(default)]
    unknowns: BTreeMap<String, f64>,
    #[serde(default)]
    time: Option<f64>,
}

impl Values {
    /// Parses a values file, naming the JSON path of a wrong entry. A parameter or a
    /// coordinate's value may be an expression of the other parameters and coordinates
    /// (`"beta": "atan(omega^2*a/g)"`, `"x": "l0 - m*g/k"`; see
    /// [`crate::expr::evaluate_number`]), evaluated once those are known.
    ///
    /// ```
    /// use torseur::output::Values;
    /// let v = Values::parse(r#"{"parameters": {"g": 9.81, "omega": 3, "a": 0.1,
    ///     "beta": "atan(omega^2*a/g)"}, "coordinates": {"theta": ["beta", 0, 0]}}"#).unwrap();
    /// assert_eq!(v.coordinates["theta"][0], (0.9_f64 / 9.81).atan());
    /// let e = Values::parse(r#"{"parameters": {"a": "b", "b": "a"}}"#).unwrap_err();
    /// assert!(e.to_string().contains("parameters.a"), "{e}");
    /// ```
    pub fn parse(text: &str) -> Result<Values, ValuesError> {
        let mut de = serde_json::Deserializer::from_str(text);
        let raw: RawValues = serde_path_to_error::deserialize(&mut de).map_err(|e| {
            let path = e.path().to_string();
            let inner = e.into_inner();
            let suffix = format!(" at line {} column {}", inner.line(), inner.column());
            let text = inner.to_string();
            let mut message = text.strip_suffix(&suffix).unwrap_or(&text).to_string();
            // serde_json's words for an array longer than its fixed length; the one such
            // array is a coordinate's [q, q̇, q̈].
            if message == "trailing characters" && path.starts_with("coordinates.") {
                message = "more than the 3 values [q, dot(q), ddot(q)] of a coordinate".into();
            }
            ValuesError(format!(
                "at {path} (line {}, column {}): {message}",
                inner.line(),
                inner.column()
            ))
        })?;
        de.end().map_err(|e| ValuesError(e.to_string()))?;
        raw.evaluated()
    }
}

impl RawValues {
    /// Every entry a number: the expressions evaluated in rounds, each with the numbers known
    /// so far, until none is left (or none can be, which names the first and its reason).
    fn evaluated(self) -> Result<Values, ValuesError> {
        let mut out = Values {
            unknowns: self.unknowns,
            time: self.time,
            ..Values::default()
        };
        // (path, where the number goes, text).
        let mut pending: Vec<(String, Slot, String)> = Vec::new();
        for (n, e) in self.parameters {
            match e {
                Entry::Number(x) => {
                    out.parameters.insert(n, x);
                }
                Entry::Text(t) => pending.push((format!("parameters.{n}"), Slot::Parameter(n), t)),
            }
        }
        for (n, es) in self.coordinates {
            let mut v = [f64::NAN; 3];
            for (k, e) in es.into_iter().enumerate() {
                match e {
                    Entry::Number(x) => v[k] = x,
                    Entry::Text(t) => pending.push((
                        format!("coordinates.{n}[{k}]"),
                        Slot::Coordinate(n.clone(), k),
                        t,
                    )),
                }
            }
            out.coordinates.insert(n, v);
        }
        while !pending.is_empty() {
            let mut progress = false;
            let mut first_error = None;
            let mut left = Vec::new();
            for (path, slot, text) in pending {
                let known = |name: &str| {
                    out.parameters.get(name).copied().or_else(|| {
                        out.coordinates
                            .get(name)
                            .map(|c| c[0])
                            .filter(|x| !x.is_nan())
                    })
                };
                match crate::expr::evaluate_number(&text, &known) {
                    Ok(x) => {
                        match &slot {
                            Slot::Parameter(n) => {
                                out.parameters.insert(n.clone(), x);
                            }
                            Slot::Coordinate(n, k) => {
                                out.coordinates.get_mut(n).expect("declared")[*k] = x;
                            }
                        }
                        progress = true;
                    }
                    Err(e) => {
                        first_error.get_or_insert_with(|| format!("at {path}: {e}"));
                        left.push((path, slot, text));
                    }
                }
            }
            if !progress {
                return Err(ValuesError(first_error.unwrap_or_default()));
            }
            pending = left;
        }
        Ok(out)
    }
}

/// Where an evaluated entry of the values file goes.
#[derive(Debug, Clone)]
enum Slot {
    Parameter(String),
    Coordinate(String, usize),
}

/// `v` with each unknown of the PFD it holds (an action of the bilan holds its links') that
/// `values` gives no value for replaced by its solved value ([`crate::pfd::solve`]). A solved
/// value that is a quotient (a pivot was a length) stays a symbol: its number at the
/// parameters of `values` is added to `values.unknowns`.
///
/// ```
/// use torseur::output::{Values, solve_unknowns};
/// use torseur::quantity::Quantity;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let q = Quantity::parse("M(O1,ext->E).z0").unwrap();
/// let v = torseur::derivation::derive(&m, &q).unwrap().value;
/// let solved = solve_unknowns(&m, &v, &mut Values::default()).unwrap();
/// let c_m = torseur::derivation::derive(&m, &Quantity::parse("C_m").unwrap()).unwrap().value;
/// assert_eq!(solved.exprs(), c_m.exprs());
/// // A value given is kept for evaluation.
/// let mut given = Values::parse(r#"{"unknowns": {"C_m": 2}}"#).unwrap();
/// assert_eq!(solve_unknowns(&m, &v, &mut given).unwrap().exprs(), v.exprs());
/// ```
pub fn solve_unknowns(m: &Mechanism, v: &Value, values: &mut Values) -> Result<Value, ValuesError> {
    let held: Vec<(String, crate::expr::VarId)> = crate::pfd::unknown_vars(m)
        .into_iter()
        .filter(|(n, x)| {
            !values.unknowns.contains_key(n) && v.exprs().iter().any(|e| e.contains_var(*x))
        })
        .collect();
    if held.is_empty() {
        return Ok(v.clone());
    }
    let names = || held.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
    let solution = crate::pfd::solve(m).map_err(|e| {
        ValuesError(format!(
            "no value for {} (give it in \"unknowns\"): the PFD cannot be solved: {e}",
            listed(&names())
        ))
    })?;
    let mut out = v.clone();
    for (n, x) in &held {
        let value = solution.unknowns.get(n).ok_or_else(|| {
            ValuesError(format!(
                "no value for `{n}` (give it in \"unknowns\"): {}",
                (solution.why_undetermined(n))
                    .unwrap_or_else(|| "no equation of the spec's pfd determines it".into())
            ))
        })?;
        if value.is_whole() {
            out = out.map(&|e| e.substitute(*x, &value.num));
        } else {
            // A quotient stays a symbol of the value, its number given at the parameters.
            let point = numeric_point_for(m, values, &[&value.num, &value.den])?;
            let number = value.num.eval(&point) / value.den.eval(&point);
            values.unknowns.insert(n.clone(), number);
        }
    }
    Ok(out)
}

/// The value of every polynomial variable of the mechanism at `values`, which must give
/// every parameter and every coordinate (a sample of the whole mechanism).
pub fn numeric_point(m: &Mechanism, values: &Values) -> Result<Vec<f64>, ValuesError> {
    point_where(m, values, &|_| true, "")
}

/// The value at `values` of the variables that `exprs` contain: only the parameters and
/// coordinates they hold are demanded, and when some are missing, the error names exactly
/// those. The other variables are NaN, which [`crate::expr::Expr::eval`] of these
/// expressions never reads (a variable of exponent 0 is not multiplied).
///
/// ```
/// use torseur::output::{Values, numeric_point_for};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let omega = m.reg().parse("dot(theta1)*L1").unwrap();
/// let v = Values::parse(r#"{"parameters": {"L1": 2}, "coordinates": {"theta1": [0, 3, 0]}}"#)
///     .unwrap();
/// let point = numeric_point_for(&m, &v, &[&omega]).unwrap();
/// assert_eq!(omega.eval(&point), 6.0);
/// let v = Values::parse(r#"{"parameters": {}}"#).unwrap();
/// let e = numeric_point_for(&m, &v, &[&omega]).unwrap_err();
/// assert_eq!(e.to_string(),
///     "values: missing parameter `L1` and coordinate `theta1` (the requested quantities hold them)");
/// ```
pub fn numeric_point_for(
    m: &Mechanism,
    values: &Values,
    exprs: &[&Expr],
) -> Result<Vec<f64>, ValuesError> {
    // A root is computed from its radicand's variables: they are needed with it.
    let radicands: Vec<Expr> = (exprs.iter())
        .flat_map(|e| e.roots_held())
        .map(|r| m.reg.radicand(r))
        .collect();
    let needed: Vec<bool> = m
        .reg
        .var_ids()
        .map(|i| {
            exprs.iter().any(|e| e.contains_var(i)) || radicands.iter().any(|e| e.contains_var(i))
        })
        .collect();
    point_where(
        m,
        values,
        &|i| needed[i],
        " (the requested quantities hold them)",
    )
}

/// `names` as `` `a`, `b` ``.
fn listed(names: &[String]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    quoted.join(", ")
}

/// The point where variable `i` takes its value when `needed(i)`, NaN otherwise; every missing
/// parameter and coordinate named at once.
fn point_where(
    m: &Mechanism,
    values: &Values,
    needed: &dyn Fn(usize) -> bool,
    why: &str,
) -> Result<Vec<f64>, ValuesError> {
    let reg = &m.reg;
    validate_names(reg, values)?;
    let mut missing = Missing::default();
    let mut point = Vec::with_capacity(reg.nvars());
    for i in reg.var_ids() {
        let v = if needed(i.index()) {
            variable_value(reg, values, i, &mut missing)?
        } else {
            f64::NAN
        };
        let exempt = !needed(i.index())
            || match reg.role(i) {
                VarRole::Rate(_, 3) | VarRole::Root(_) => true,
                VarRole::Parameter(k) => reg.is_unknown(k),
                _ => false,
            };
        if !v.is_finite() && !exempt && missing.is_empty() {
            return Err(ValuesError(format!(
                "`{}` is not a finite number at these values",
                reg.variable(i)
            )));
        }
        point.push(v);
    }
    missing.refuse(why)?;
    reg.fill_roots(&mut point);
    Ok(point)
}

/// Every name of the values file is a parameter, a coordinate or an unknown of the PFD.
fn validate_names(reg: &Registry, values: &Values) -> Result<(), ValuesError> {
    for p in values.parameters.keys() {
        if p == crate::expr::PI {
            return Err(ValuesError(
                "`pi` is the constant π, which the values do not give".to_string(),
            ));
        }
        if !reg.parameters().contains(p) {
            let hint = reg.parameter_hint(p);
            return Err(ValuesError(format!("unknown parameter `{p}`{hint}")));
        }
    }
    for q in values.coordinates.keys() {
        if reg.coord(q).is_none() {
            let hint = reg.coordinate_hint(q);
            return Err(ValuesError(format!("unknown coordinate `{q}`{hint}")));
        }
    }
    for u in values.unknowns.keys() {
        if !reg.unknowns().contains(u) {
            return Err(ValuesError(format!("`{u}` is not an unknown of the PFD")));
        }
    }
    Ok(())
}

/// What the values file lacks, in the order met.
#[derive(Default)]
struct Missing {
    parameters: Vec<String>,
    coordinates: Vec<String>,
    time: bool,
}

impl Missing {
    fn is_empty(&self) -> bool {
        self.parameters.is_empty() && self.coordinates.is_empty() && !self.time
    }

    /// Notes a missing parameter; its value is NaN.
    fn parameter(&mut self, name: &str) -> f64 {
        Missing::note(&mut self.parameters, name)
    }

    /// Notes a missing coordinate; its value is NaN.
    fn coordinate(&mut self, name: &str) -> f64 {
        Missing::note(&mut self.coordinates, name)
    }

    fn note(list: &mut Vec<String>, name: &str) -> f64 {
        if !list.iter().any(|x| x == name) {
            list.push(name.to_string());
        }
        f64::NAN
    }

    /// The error that names everything missing, if anything is.
    fn refuse(&self, why: &str) -> Result<(), ValuesError> {
        let plural = |n: usize, word: &str| {
            if n > 1 {
                format!("{word}s")
            } else {
                word.to_string()
            }
        };
        let mut parts = Vec::new();
        if !self.parameters.is_empty() {
            parts.push(format!(
                "{} {}",
                plural(self.parameters.len(), "parameter"),
                listed(&self.parameters)
            ));
        }
        if !self.coordinates.is_empty() {
            parts.push(format!(
                "{} {}",
                plural(self.coordinates.len(), "coordinate"),
                listed(&self.coordinates)
            ));
        }
        if self.time {
            parts.push("the time `t` (\"time\": a number)".to_string());
        }
        if parts.is_empty() {
            return Ok(());
        }
        // The time alone is one thing missing.
        let why = match parts.len() == 1 && self.time {
            true => why.replace("hold them", "hold it"),
            false => why.to_string(),
        };
        Err(ValuesError(format!("missing {}{why}", parts.join(" and "))))
    }
}

/// The value of the needed variable `i` at the values file, NaN (and noted in `missing`) when
/// the file lacks it.
fn variable_value(
    reg: &Registry,
    values: &Values,
    i: VarId,
    missing: &mut Missing,
) -> Result<f64, ValuesError> {
    Ok(match reg.role(i) {
        // Solved values never contain an unknown; an action of the bilan holds them as
        // they are, and takes the values given.
        VarRole::Parameter(k) if reg.is_unknown(k) => {
            let name = reg.scalar_name(k);
            values.unknowns.get(name).copied().unwrap_or(f64::NAN)
        }
        // π, which no values file gives, and 1/π.
        VarRole::Parameter(k) | VarRole::Inverse(k) if reg.constant_value(k).is_some() => {
            let c = reg.constant_value(k).unwrap_or(f64::NAN);
            if matches!(reg.role(i), VarRole::Inverse(_)) {
                1.0 / c
            } else {
                c
            }
        }
        VarRole::Parameter(k) => {
            let name = reg.scalar_name(k);
            match values.parameters.get(name) {
                Some(v) => *v,
                None => missing.parameter(name),
            }
        }
        // 1/k, for a parameter k the spec divides by.
        VarRole::Inverse(k) => {
            let name = reg.scalar_name(k);
            match values.parameters.get(name) {
                Some(v) if *v == 0.0 => {
                    return Err(ValuesError(format!(
                        "`{name}` = 0, and the results divide by it"
                    )));
                }
                Some(v) => 1.0 / v,
                None => missing.parameter(name),
            }
        }
        // A constant angle parameter: its value is among the parameters.
        VarRole::Cos(q) | VarRole::Sin(q) if reg.coord_info(q).is_constant() => {
            let name = &reg.coord_info(q).name;
            match values.parameters.get(name) {
                Some(a) if matches!(reg.role(i), VarRole::Cos(_)) => a.cos(),
                Some(a) => a.sin(),
                None => missing.parameter(name),
            }
        }
        // A phase Ω t: Ω among the parameters, t the values' time.
        VarRole::Cos(q) | VarRole::Sin(q) if reg.coord_info(q).phase().is_some() => {
            let w = reg.coord_info(q).phase().unwrap_or_default();
            let w = match values.parameters.get(w) {
                Some(w) => *w,
                None => missing.parameter(w),
            };
            match values.time {
                Some(t) if matches!(reg.role(i), VarRole::Cos(_)) => (w * t).cos(),
                Some(t) => (w * t).sin(),
                None => {
                    missing.time = true;
                    f64::NAN
                }
            }
        }
        // A square root: from its radicand's variables, once they are all set.
        VarRole::Root(_) => f64::NAN,
        VarRole::Cos(q)
        | VarRole::Sin(q)
        | VarRole::Value(q)
        | VarRole::Rate(q, _)
        | VarRole::Reciprocal(q, _) => {
            let name = &reg.coord_info(q).name;
            match values.coordinates.get(name) {
                Some(c) => coordinate_value(reg.role(i), name, c)?,
                None => missing.coordinate(name),
            }
        }
    })
}

/// A variable of coordinate `name` (cos, sin, value, rate, reciprocal) at its [q, q̇, q̈] `c`.
fn coordinate_value(role: VarRole, name: &str, c: &[f64; 3]) -> Result<f64, ValuesError> {
    Ok(match role {
        // 1/cos q or 1/sin q, for an angle a loop closure divides by.
        VarRole::Reciprocal(_, trig) => {
            let (f, v) = match trig {
                Trig::Sin => ("sin", c[0].sin()),
                _ => ("cos", c[0].cos()),
            };
            if v.abs() < 1e-12 {
                return Err(ValuesError(format!(
                    "{f}({name}) = 0 here, and the results divide by it (the loop \
                     closure is singular)"
                )));
            }
            1.0 / v
        }
        VarRole::Cos(_) => c[0].cos(),
        VarRole::Sin(_) => c[0].sin(),
        VarRole::Value(_) => c[0],
        VarRole::Rate(_, 1) => c[1],
        VarRole::Rate(_, 2) => c[2],
        _ => f64::NAN,
    })
}

/// A derived value evaluated at a point, as the JSON of the CLI contract; refused when a
/// number of it is not finite (the values overflow: a parameter of 1e300 squared), naming the
/// quantity, where [`eval_value`] would print it as `null`.
///
/// ```
/// use torseur::output::{Values, numeric_point_for, try_eval_value};
/// use torseur::quantity::Quantity;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let q = Quantity::parse("V(G2,2/0) in B2").unwrap();
/// let v = torseur::derivation::derive(&m, &q).unwrap().value;
/// let at = |big: &str| {
///     let values = Values::parse(&format!(r#"{{"parameters": {{"L1": {big}, "L2": 1,
///         "d1": 1, "h1": 1}}, "coordinates": {{"theta1": [0, {big}, 0], "theta2": [0, 1, 0]}}}}"#))
///         .unwrap();
///     numeric_point_for(&m, &values, &v.exprs()).unwrap()
/// };
/// assert!(try_eval_value(&m, "V(G2,2/0) in B2", &v, &at("2")).is_ok());
/// // L1 θ̇1 = 1e600 overflows.
/// let e = try_eval_value(&m, "V(G2,2/0) in B2", &v, &at("1e300")).unwrap_err();
/// assert!(e.to_string().starts_with("values: `V(G2,2/0) in B2` is not a finite number"), "{e}");
/// ```
pub fn try_eval_value(
    m: &Mechanism,
    id: &str,
    v: &Value,
    point: &[f64],
) -> Result<Json, ValuesError> {
    let j = eval_value(m, id, v, point);
    if has_null(&j) {
        return Err(ValuesError(format!(
            "`{id}` is not a finite number at these values (a result overflows the \
             floating-point range, or is undefined there)"
        )));
    }
    Ok(j)
}

/// The report of `torseur eval`: each derived value at `values` (the `--at` file), the
/// unknowns the values do not give solved for, as `{"quantities": [...]}`.
///
/// ```
/// use torseur::{derivation::derive_values, output::{Values, eval_json}, quantity::Quantity};
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json")?;
/// let ds = derive_values(&m, &[Quantity::parse("Omega(2/0) in B1")?])?;
/// let mut v = Values::parse(r#"{"coordinates": {"theta1": [0, 2, 0], "theta2": [0, 3, 0]}}"#)?;
/// let j = eval_json(&m, &mut v, &ds)?;
/// // Ω(2/0) = θ̇2 x⃗1 + θ̇1 z⃗1 (by hand: the rotation θ2 about x⃗1 after θ1 about z⃗0).
/// assert_eq!(j["quantities"][0]["value"], serde_json::json!([3.0, 0.0, 2.0]));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn eval_json(
    m: &Mechanism,
    values: &mut Values,
    ds: &[crate::derivation::Derivation],
) -> Result<Json, ValuesError> {
    // An action holds its links' unknowns: those without a value are solved for.
    let solved = ds
        .iter()
        .map(|d| solve_unknowns(m, &d.value, values))
        .collect::<Result<Vec<_>, _>>()?;
    // Only the parameters and coordinates the results hold are demanded.
    let exprs: Vec<&Expr> = solved.iter().flat_map(|v| v.exprs()).collect();
    let point = numeric_point_for(m, values, &exprs)?;
    let items = ds
        .iter()
        .zip(&solved)
        .map(|(d, v)| try_eval_value(m, &d.quantity.to_string(), v, &point))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(json!({ "quantities": items }))
}

/// Whether a JSON value holds a `null` (serde_json's number for NaN and the infinities).
fn has_null(j: &Json) -> bool {
    match j {
        Json::Null => true,
        Json::Array(a) => a.iter().any(has_null),
        Json::Object(o) => o.values().any(has_null),
        _ => false,
    }
}

/// A derived value evaluated at a point, as the JSON of the CLI contract. A number that is
/// not finite is `null`: [`try_eval_value`] refuses it instead.
pub fn eval_value(m: &Mechanism, id: &str, v: &Value, point: &[f64]) -> Json {
    let ev = |c: &[crate::expr::Expr; 3]| -> Vec<f64> { c.iter().map(|e| e.eval(point)).collect() };
    match v {
        Value::Scalar(e) => json!({"id": id, "kind": "scalar", "value": e.eval(point)}),
        Value::Quotient(q) => {
            json!({"id": id, "kind": "scalar", "value": q.num.eval(point) / q.den.eval(point)})
        }
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
