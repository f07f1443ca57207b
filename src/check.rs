//! `check`: the symbolic results against the independent float backend, on random physically
//! valid samples (bodies realised as random point clouds, random angles, rates, accelerations),
//! and every result homogeneous, of its quantity's dimension ([`crate::units`]).

use crate::derivation::{DeriveError, Value, bind, derive_values};
use crate::mechanism::{Hypothesis, Mechanism};
use crate::numeric::{NumericError, NumericModel, Sample};
use crate::output::{Values, ValuesError, numeric_point};
use crate::quantity::{Quantity, QuantityKind};
use crate::units::{DimensionError, Dimensions, homogeneous_value};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use std::fmt;

/// Agreement demanded between the two sides (relative).
pub const TOLERANCE: f64 = 1e-9;

/// Why a check could not run.
#[derive(Debug, thiserror::Error)]
pub enum CheckError {
    /// The float backend refused the spec or a sample.
    #[error("float backend: {0}")]
    Numeric(#[from] NumericError),
    /// A quantity does not resolve.
    #[error(transparent)]
    Resolve(#[from] DeriveError),
    /// A sample does not fit the mechanism.
    #[error(transparent)]
    Values(#[from] ValuesError),
}

/// The worst disagreement found for one quantity (under one hypothesis).
#[derive(Debug, Clone)]
pub struct CheckRow {
    /// Quantity id.
    pub quantity: String,
    /// Hypothesis the forms were taken under, if any.
    pub hypothesis: Option<String>,
    /// Worst relative error over the samples: ‖sym − num‖∞ / max(‖sym‖∞, ‖num‖∞, 1e-3): values of the problems are O(1), so a quantity
    /// that is zero is compared absolutely.
    pub worst: f64,
    /// Index of the sample where it occurred.
    pub sample: usize,
}

/// The dimension check of one quantity under one hypothesis (or none).
#[derive(Debug, Clone)]
pub struct DimensionRow {
    /// Quantity id.
    pub quantity: String,
    /// Hypothesis the value was taken under, if any.
    pub hypothesis: Option<String>,
    /// Why the value is inhomogeneous or not of its quantity's dimension; none when it is
    /// right.
    pub error: Option<DimensionError>,
}

/// The result of a check run.
#[derive(Debug, Clone)]
pub struct CheckReport {
    /// Number of samples per quantity.
    pub samples: usize,
    /// Seed of the random generator.
    pub seed: u64,
    /// One row per quantity and hypothesis (the linearisations `lin(...)` are not compared
    /// with the float backend).
    pub rows: Vec<CheckRow>,
    /// One row per quantity and hypothesis, `lin(...)` included: the dimension check.
    pub dimensions: Vec<DimensionRow>,
    /// Hypotheses whose results are not compared with the float backend, and why (kept to
    /// first order in small parameters; a relation no sample can satisfy).
    pub not_compared: Vec<(String, String)>,
}

impl CheckReport {
    /// Rows beyond the tolerance.
    pub fn failures(&self) -> Vec<&CheckRow> {
        self.rows
            .iter()
            .filter(|r| r.worst.is_nan() || r.worst > TOLERANCE)
            .collect()
    }

    /// Values that are inhomogeneous or not of their quantity's dimension.
    pub fn dimension_failures(&self) -> Vec<&DimensionRow> {
        self.dimensions
            .iter()
            .filter(|r| r.error.is_some())
            .collect()
    }

    /// The report of `torseur check --json`: each quantity's worst relative error against
    /// the float backend and whether it is within [`TOLERANCE`], each dimension.
    pub fn to_json(&self) -> serde_json::Value {
        let rows: Vec<serde_json::Value> = self
            .rows
            .iter()
            .map(|x| {
                serde_json::json!({"id": x.quantity, "hypothesis": x.hypothesis,
                    "worst_relative_error": x.worst, "sample": x.sample,
                    "ok": x.worst <= TOLERANCE})
            })
            .collect();
        let dims: Vec<serde_json::Value> = self
            .dimensions
            .iter()
            .map(|x| {
                serde_json::json!({"id": x.quantity, "hypothesis": x.hypothesis,
                    "ok": x.error.is_none(),
                    "error": x.error.as_ref().map(|e| e.to_string())})
            })
            .collect();
        serde_json::json!({"samples": self.samples, "seed": self.seed, "tolerance": TOLERANCE,
            "passed": self.passed(), "quantities": rows, "dimensions": dims})
    }

    /// Whether every quantity agrees within [`TOLERANCE`] and has its dimension.
    pub fn passed(&self) -> bool {
        self.failures().is_empty() && self.dimension_failures().is_empty()
    }
}

impl fmt::Display for CheckReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let w = self
            .rows
            .iter()
            .map(|r| r.quantity.len())
            .max()
            .unwrap_or(8)
            .max(8);
        writeln!(
            f,
            "{:<w$}  {:<10}  {:>12}  {:>6}  verdict",
            "quantity", "hypothesis", "worst rel.", "sample"
        )?;
        for r in &self.rows {
            writeln!(
                f,
                "{:<w$}  {:<10}  {:>12.3e}  {:>6}  {}",
                r.quantity,
                r.hypothesis.as_deref().unwrap_or("-"),
                r.worst,
                r.sample,
                if r.worst <= TOLERANCE {
                    "ok"
                } else {
                    "MISMATCH"
                }
            )?;
        }
        for (h, why) in &self.not_compared {
            writeln!(f, "{h}: not compared with the float backend ({why})")?;
        }
        for r in self.dimension_failures() {
            if let Some(e) = &r.error {
                match &r.hypothesis {
                    Some(h) => writeln!(f, "DIMENSION under {h}: {e}")?,
                    None => writeln!(f, "DIMENSION: {e}")?,
                }
            }
        }
        let wrong = self.dimension_failures().len();
        write!(
            f,
            "{} quantities x {} samples (seed {}), tolerance {TOLERANCE:e}: {}; dimensions: {}",
            self.rows.len(),
            self.samples,
            self.seed,
            if self.failures().is_empty() {
                "all agree"
            } else {
                "MISMATCH"
            },
            if wrong == 0 {
                format!("{} values homogeneous", self.dimensions.len())
            } else {
                format!("{wrong} of {} values WRONG", self.dimensions.len())
            }
        )
    }
}

fn relative_error(sym: &[f64], num: &[f64]) -> f64 {
    if sym.len() != num.len() {
        return f64::INFINITY;
    }
    let norm = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    let diff = sym
        .iter()
        .zip(num)
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    let scale = norm(sym).max(norm(num)).max(1e-3);
    if diff.is_nan() {
        f64::INFINITY
    } else {
        diff / scale
    }
}

/// The quantity as the float backend must evaluate it: in the basis the symbolic side used.
fn as_evaluated(m: &Mechanism, q: &Quantity) -> Result<Quantity, DeriveError> {
    if q.projection.is_some() {
        return Ok(q.clone());
    }
    let r = bind(m, q)?;
    Ok(q.with_basis(m.frame_name(r.basis)))
}

/// Compares one symbolic value of `q` with the float backend on `samples` random samples
/// (drawn under `hypothesis` if given). The symbolic value may come from anywhere: tests use
/// this to prove that a wrong formula is caught.
pub fn compare(
    m: &Mechanism,
    model: &NumericModel,
    q: &Quantity,
    symbolic: &Value,
    hypothesis: Option<&Hypothesis>,
    samples: usize,
    rng: &mut ChaCha8Rng,
) -> Result<CheckRow, CheckError> {
    let evaluated = as_evaluated(m, q)?;
    // An action of the bilan holds the unknowns of its links: each sample gives every unknown
    // of the PFD a random value, the same on both sides (a component the projection drops
    // may hold one that the value does not).
    // An equation of motion holds its inputs (a motor torque): given a value the same way.
    let held: Vec<String> = match (&q.kind, q.kind.action()) {
        (_, Some(_)) => m.reg.unknowns().to_vec(),
        (QuantityKind::Eom(_), None) => m.dynamics().action_unknowns.clone(),
        _ => Vec::new(),
    };
    let default = m.frame_name(m.default_basis).to_string();
    let mut row = CheckRow {
        quantity: q.to_string(),
        hypothesis: hypothesis.map(|h| h.name.clone()),
        worst: 0.0,
        sample: 0,
    };
    for k in 0..samples {
        let s: Sample = match hypothesis {
            Some(h) => model.sample_under(rng, &h.name)?,
            None => model.sample(rng)?,
        };
        let unknowns: BTreeMap<String, f64> = held
            .iter()
            .map(|n| (n.clone(), rng.random_range(-2.0..2.0)))
            .collect();
        let values = Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            unknowns,
            time: Some(s.time),
        };
        let point = numeric_point(m, &values)?;
        let sym = symbolic.numbers(&point);
        let num = model
            .evaluate_with(&evaluated, &s, &values.unknowns, &default)?
            .numbers();
        let err = relative_error(&sym, &num);
        if err.is_nan() || err > row.worst {
            row.worst = err;
            row.sample = k;
        }
    }
    Ok(row)
}

/// Compares a trial motion's unknown `q` with the float backend by the backend's own route:
/// at each sample drawn under the trial's hypothesis `h`, the exact values of the trial's
/// unknowns (as numbers) put in the motion, the backend's own eom(q) along it must vanish at
/// several random times, relative to its value with the unknowns at zero (the forcing).
pub fn compare_trial(
    m: &Mechanism,
    model: &NumericModel,
    q: &Quantity,
    h: &Hypothesis,
    samples: usize,
    rng: &mut ChaCha8Rng,
) -> Result<CheckRow, CheckError> {
    let Some(t) = &h.trial else {
        return Err(DeriveError::new(q, format!("`{}` poses no trial motion", h.name)).into());
    };
    let names: Vec<Quantity> = (t.unknowns.iter())
        .map(|(n, _)| Quantity::parse(n))
        .collect::<Result<_, _>>()
        .map_err(|e| DeriveError::new(q, e.to_string()))?;
    let exact: Vec<Value> = (derive_values(m, &names)?.into_iter())
        .map(|d| d.value)
        .collect();
    compare_trial_values(m, model, q, h, &exact, samples, rng)
}

/// [`compare_trial`] with the values of the trial's unknowns given, in the trial's order:
/// they may come from anywhere, and tests use this to prove that a wrong amplitude is caught.
pub fn compare_trial_values(
    m: &Mechanism,
    model: &NumericModel,
    q: &Quantity,
    h: &Hypothesis,
    exact: &[Value],
    samples: usize,
    rng: &mut ChaCha8Rng,
) -> Result<CheckRow, CheckError> {
    let Some(t) = &h.trial else {
        return Err(DeriveError::new(q, format!("`{}` poses no trial motion", h.name)).into());
    };
    let eom = Quantity::parse(&format!("eom({})", m.reg.coord_info(t.coord).name))
        .map_err(|e| DeriveError::new(q, e.to_string()))?;
    let default = m.frame_name(m.default_basis).to_string();
    let none = BTreeMap::new();
    let mut row = CheckRow {
        quantity: q.to_string(),
        hypothesis: Some(h.name.clone()),
        worst: 0.0,
        sample: 0,
    };
    for k in 0..samples {
        let mut s = model.sample_under(rng, &h.name)?;
        let values = Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            unknowns: BTreeMap::new(),
            time: Some(s.time),
        };
        let point = numeric_point(m, &values)?;
        let mut zero = s.clone();
        for ((n, _), d) in t.unknowns.iter().zip(exact) {
            s.parameters.insert(n.clone(), d.numbers(&point)[0]);
            zero.parameters.insert(n.clone(), 0.0);
        }
        let (mut worst, mut scale) = (0.0f64, 1e-3f64);
        for _ in 0..4 {
            let time = rng.random_range(0.0..=10.0);
            let residual = |s: &Sample| -> Result<f64, CheckError> {
                let on = model.along_trial(&h.name, s, time)?;
                let v = model.evaluate_with(&eom, &on, &none, &default)?.numbers();
                Ok(v.first().copied().unwrap_or(f64::NAN))
            };
            let r = residual(&s)?.abs();
            worst = if r.is_nan() { r } else { worst.max(r) };
            scale = scale.max(residual(&zero)?.abs());
        }
        let err = if worst.is_nan() || !worst.is_finite() {
            f64::INFINITY
        } else {
            worst / scale
        };
        if err > row.worst {
            row.worst = err;
            row.sample = k;
        }
    }
    Ok(row)
}

/// Checks every requested quantity of the spec, in general and under each hypothesis: against
/// the float backend, and for its dimension (every term of every component of the quantity's
/// dimension, [`crate::units::homogeneous_value`]; terms holding a parameter without a unit are not
/// checked).
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let report = torseur::check::check(&m, 5, 1).unwrap();
/// assert!(report.passed(), "{report}");
/// ```
pub fn check(m: &Mechanism, samples: usize, seed: u64) -> Result<CheckReport, CheckError> {
    let model = NumericModel::new(&m.spec)?;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut rows = Vec::new();
    let mut dimensions = Vec::new();
    let dims = Dimensions::of(m);
    let derived = derive_values(m, &m.quantities)?;
    // Hypotheses the float backend cannot sample, said once rather than failing the run.
    let mut not_compared: Vec<(String, String)> = Vec::new();
    for h in &m.hypotheses {
        if !h.first_order.is_empty() {
            not_compared.push((
                h.name.clone(),
                "results kept to first order in small parameters: no sample realises a \
                 truncation"
                    .into(),
            ));
        } else if let Err(NumericError::Sampling(why)) =
            model.sample_under(&mut ChaCha8Rng::seed_from_u64(seed), &h.name)
        {
            not_compared.push((h.name.clone(), why));
        }
    }
    let skipped =
        |h: Option<&Hypothesis>| h.is_some_and(|h| not_compared.iter().any(|(n, _)| *n == h.name));
    // An equation of motion the PFD's solve left multiplied by pivots (1 − f1 f2 εA εB):
    // compared as the residual the float backend computes, divided by them.
    let factors = match m
        .quantities
        .iter()
        .any(|q| matches!(q.kind, QuantityKind::Eom(_)))
    {
        true => crate::pfd::solve(m)
            .map(|s| s.eom_factors)
            .unwrap_or_default(),
        false => BTreeMap::new(),
    };
    for (q, d) in m.quantities.iter().zip(derived) {
        let v = match (&q.kind, d.value) {
            (QuantityKind::Eom(c), Value::Scalar(e)) if factors.contains_key(c) => {
                let f = crate::expr::Fraction::new(e.clone(), factors[c].clone());
                f.map_or(Value::Scalar(e), Value::Quotient)
            }
            (_, v) => v,
        };
        let under: Vec<(Option<&Hypothesis>, Value)> = std::iter::once((None, v.clone()))
            .chain(m.hypotheses.iter().map(|h| (Some(h), v.under(h))))
            .collect();
        for (h, value) in &under {
            dimensions.push(DimensionRow {
                quantity: q.to_string(),
                hypothesis: h.map(|h| h.name.clone()),
                error: homogeneous_value(m, &dims, q, value).err(),
            });
        }
        // A linearisation, or a result kept to first order in small parameters, is exact
        // algebra on a checked quantity, tested against hand derivations; the float backend
        // computes full motions only.
        if q.linear {
            continue;
        }
        // A trial's unknown is compared under its hypothesis only, by its own route.
        if let QuantityKind::Unknown(n) = &q.kind
            && let Some((h, _)) = crate::derivation::trial_of(m, n)
        {
            if !skipped(Some(h)) {
                rows.push(compare_trial(m, &model, q, h, samples, &mut rng)?);
            }
            continue;
        }
        for (h, value) in &under {
            if skipped(*h) {
                continue;
            }
            rows.push(compare(m, &model, q, value, *h, samples, &mut rng)?);
        }
    }
    Ok(CheckReport {
        samples,
        seed,
        rows,
        dimensions,
        not_compared,
    })
}
