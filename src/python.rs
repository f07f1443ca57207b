//! The Python extension module `torseur._torseur` (feature `python`, built by maturin from
//! `pyproject.toml`). It is thin on purpose: each method runs the library as the command line
//! does and returns the command line's JSON as text; the Python package (`python/torseur/`)
//! turns it into objects with `_repr_latex_`, `to_sympy()` and the verdict's truth value.
//!
//! symbolica's restricted mode allows one process per user and one thread per process: the
//! first load takes the user's lock at once or raises `BusyError` (never waits, never lets
//! symbolica abort the interpreter), and keeps it for the life of the interpreter; a
//! mechanism is `unsendable` (used from another Python thread, pyo3 raises), and a second
//! thread that loads gets the library's thread error as `TorseurError`.

use crate::derivation::{Derivation, Value, derive};
use crate::lock::{LockError, ProcessLock};
use crate::mechanism::Mechanism;
use crate::output;
use crate::quantity::Quantity;
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use serde_json::{Value as Json, json};
use std::path::Path;
use std::sync::Mutex;

create_exception!(
    _torseur,
    TorseurError,
    PyException,
    "A spec, a quantity, an expression or values that torseur refuses; the message names the \
     JSON path or the argument."
);
create_exception!(
    _torseur,
    BusyError,
    TorseurError,
    "Another process of this user is using torseur (unlicensed symbolica allows one at a time)."
);

/// The user's lock, held from the first load until the interpreter exits.
static LOCK: Mutex<Option<ProcessLock>> = Mutex::new(None);

fn error(e: impl std::fmt::Display) -> PyErr {
    let text = e.to_string();
    TorseurError::new_err(crate::excerpt::bounded(&text).to_string())
}

/// Takes the lock on the first call; `BusyError` when another process holds it.
fn hold_lock() -> PyResult<()> {
    let mut held = LOCK.lock().unwrap_or_else(|p| p.into_inner());
    if held.is_none() {
        match ProcessLock::try_acquire() {
            Ok(l) => *held = Some(l),
            Err(e @ LockError::Held { .. }) => return Err(BusyError::new_err(e.to_string())),
            Err(e) => return Err(error(e)),
        }
    }
    Ok(())
}

/// Runs `f` (the first symbolica work of the process) with file descriptor 1 pointed at 2:
/// symbolica prints its licence notice on stdout, and it must stay visible without mixing
/// into what a notebook or a pipe reads on stdout (as in the command line).
fn with_stdout_on_stderr<T>(f: impl FnOnce() -> T) -> T {
    // SAFETY: dup and dup2 on the process's own standard descriptors; the saved one is
    // restored and closed before returning.
    let saved = unsafe { libc::dup(1) };
    if saved < 0 {
        return f();
    }
    let _ = std::io::Write::flush(&mut std::io::stdout());
    unsafe { libc::dup2(2, 1) };
    let r = f();
    let _ = std::io::Write::flush(&mut std::io::stdout());
    unsafe {
        libc::dup2(saved, 1);
        libc::close(saved);
    }
    r
}

/// An answer key's figures: file name and PNG bytes.
type Figures = Vec<(String, Vec<u8>)>;

fn to_text(j: &Json) -> PyResult<String> {
    serde_json::to_string(j).map_err(error)
}

/// A mechanism loaded from a spec (the Python package wraps it as `torseur.Mechanism`).
#[pyclass(unsendable, module = "torseur._torseur")]
pub struct Loaded {
    m: Mechanism,
}

/// Loads a spec from its JSON text; `origin` names it in messages.
#[pyfunction]
fn load_text(text: &str) -> PyResult<Loaded> {
    hold_lock()?;
    let m = with_stdout_on_stderr(|| crate::spec::from_str(text)).map_err(error)?;
    Ok(Loaded { m })
}

/// Loads a spec file (read with the command line's bound and checks).
#[pyfunction]
fn load_path(path: &str) -> PyResult<Loaded> {
    let text = crate::spec::read(Path::new(path)).map_err(error)?;
    load_text(&text)
}

fn quantity(q: &str) -> PyResult<Quantity> {
    Quantity::parse(q).map_err(error)
}

fn hypothesis<'a>(
    m: &'a Mechanism,
    name: Option<&str>,
) -> PyResult<Option<&'a crate::mechanism::Hypothesis>> {
    crate::verify::hypothesis(m, name).map_err(error)
}

/// One derivation as the JSON of `derive --json`, with the value under `under` when given,
/// and the LaTeX of the quantity and of its value.
fn derivation_json(
    m: &Mechanism,
    d: &Derivation,
    under: Option<&crate::mechanism::Hypothesis>,
) -> Json {
    let mut j = output::derive_json(m, std::slice::from_ref(d))["quantities"][0].take();
    let value: Value = match under {
        Some(h) => d.value_under(m, h),
        None => d.value.clone(),
    };
    if let Some(h) = under {
        j["value"] = output::value_json(m, &value);
        j["hypothesis"] = json!(h.name);
    }
    let title = crate::latex::quantity_title_in(m, &d.quantity);
    j["latex"] = json!({"quantity": title, "value": crate::latex::value(m, &title, &value)});
    j
}

#[pymethods]
impl Loaded {
    /// The spec's title, parameters, coordinates, hypotheses, questions and scenarios.
    fn summary(&self) -> PyResult<String> {
        let m = &self.m;
        let reg = m.reg();
        let coords: Vec<&str> = reg.coordinates().iter().map(|c| c.name.as_str()).collect();
        let hyps: Vec<&str> = m.hypotheses().iter().map(|h| h.name.as_str()).collect();
        let qs: Vec<String> = m.quantities().iter().map(|q| q.to_string()).collect();
        let scenarios: Vec<&str> = (m.statement.scenarios.iter())
            .map(|s| s.name.as_str())
            .collect();
        to_text(&json!({"title": m.title(), "parameters": reg.parameters(),
            "coordinates": coords, "hypotheses": hyps, "quantities": qs,
            "scenarios": scenarios}))
    }

    /// `derive`: the quantity with its steps, as JSON text.
    #[pyo3(signature = (quantity, hypothesis=None))]
    fn derive(&self, quantity: &str, hypothesis: Option<&str>) -> PyResult<String> {
        let q = self::quantity(quantity)?;
        let h = self::hypothesis(&self.m, hypothesis)?;
        let d = derive(&self.m, &q).map_err(error)?;
        to_text(&derivation_json(&self.m, &d, h))
    }

    /// The equations of motion as M(q) q̈ + h = Q: coordinates, then each entry's canonical
    /// and presentation texts, as JSON.
    fn equations_of_motion(&self) -> PyResult<String> {
        let eq = crate::pfd::EquationsOfMotion::of(&self.m).map_err(error)?;
        let texts = |e: &crate::expr::Expr| json!({"canonical": e.to_string(), "presentation": e.presentation().to_string()});
        let mass: Vec<Vec<Json>> = eq
            .mass
            .iter()
            .map(|r| r.iter().map(texts).collect())
            .collect();
        to_text(&json!({
            "coordinates": eq.coordinates(),
            "mass": mass,
            "velocity_terms": eq.velocity_terms.iter().map(texts).collect::<Vec<_>>(),
            "forces": eq.forces.iter().map(texts).collect::<Vec<_>>(),
        }))
    }

    /// `verify`: the verdict on a hand-written value (`quantity` given) or equation, as JSON.
    #[pyo3(signature = (quantity, expr, hypothesis=None))]
    fn verify(
        &self,
        quantity: Option<&str>,
        expr: &str,
        hypothesis: Option<&str>,
    ) -> PyResult<String> {
        let v = match quantity {
            Some(q) => crate::verify::verify(&self.m, q, expr, hypothesis),
            None => crate::verify::verify_equation(&self.m, expr, hypothesis),
        }
        .map_err(error)?;
        let difference: Vec<Json> = v
            .difference
            .iter()
            .map(|d| {
                json!({"canonical": d.to_string(), "presentation": output::present(d),
                            "latex": crate::latex::expr(d)})
            })
            .collect();
        to_text(
            &json!({"equivalent": v.is_equivalent(), "message": v.to_string(),
            "quantity": v.quantity, "equation": v.equation, "hypothesis": v.hypothesis,
            "factor": v.factor.as_ref().map(|f| f.to_string()),
            "substituted": v.substituted, "difference": difference}),
        )
    }

    /// `eval`: the quantities (the spec's when empty) at the values (the `--at` file's JSON).
    fn eval(&self, values: &str, quantities: Vec<String>) -> PyResult<String> {
        let mut v = output::Values::parse(values).map_err(error)?;
        let qs: Vec<Quantity> = if quantities.is_empty() {
            self.m.quantities().to_vec()
        } else {
            quantities
                .iter()
                .map(|q| self::quantity(q))
                .collect::<PyResult<_>>()?
        };
        let ds = crate::derivation::derive_values(&self.m, &qs).map_err(error)?;
        to_text(&output::eval_json(&self.m, &mut v, &ds).map_err(error)?)
    }

    /// `check`: the exact results against the float backend, as the JSON of `check --json`.
    fn check(&self, samples: usize, seed: u64) -> PyResult<String> {
        let r = crate::check::check(&self.m, samples.clamp(1, 100_000), seed).map_err(error)?;
        to_text(&r.to_json())
    }

    /// The answer key: its LaTeX, and its figures (PNG) named with `prefix`.
    #[pyo3(signature = (prefix, column=false))]
    fn answer_key(&self, prefix: &str, column: bool) -> PyResult<(String, Figures)> {
        let style = if column {
            crate::latex::VectorStyle::Column
        } else {
            crate::latex::VectorStyle::Sum
        };
        let runs = crate::simulate::question_runs(&self.m);
        let key = crate::latex::answer_key_named(&self.m, style, prefix, &runs).map_err(error)?;
        let figures = key
            .figures
            .iter()
            .map(|(name, fig)| Ok((name.clone(), fig.to_png(2).map_err(error)?)))
            .collect::<PyResult<Vec<_>>>()?;
        Ok((key.tex, figures))
    }

    /// `simulate`: the scenario's instants and columns (id, unit, values), as JSON text.
    fn simulate(&self, scenario: &str) -> PyResult<String> {
        let run = crate::simulate::simulate(&self.m, scenario).map_err(error)?;
        let columns: Vec<Json> = run
            .columns
            .iter()
            .map(|c| json!({"id": c.id, "unit": c.unit, "values": c.values}))
            .collect();
        to_text(
            &json!({"scenario": run.scenario, "label": run.label, "times": run.times,
            "columns": columns, "drift": run.drift}),
        )
    }
}

/// Writes files as the command line does (`output::target` refuses devices and what is not
/// a regular file; all or nothing).
#[pyfunction]
fn write_files(files: Vec<(String, Vec<u8>)>) -> PyResult<()> {
    let targets = files
        .iter()
        .map(|(p, _)| output::target(Path::new(p)).map_err(|e| error(format!("{p}: {e}"))))
        .collect::<PyResult<Vec<_>>>()?;
    let items: Vec<(&output::Target, &[u8])> = targets
        .iter()
        .zip(&files)
        .map(|(t, (_, b))| (t, b.as_slice()))
        .collect();
    // No item names standard output ("-" is refused above by the Python package): the sink
    // only satisfies the signature.
    output::write_outputs(&items, &mut std::io::sink()).map_err(error)
}

/// The extension module.
#[pymodule]
#[pyo3(name = "_torseur")]
fn extension(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("TorseurError", m.py().get_type::<TorseurError>())?;
    m.add("BusyError", m.py().get_type::<BusyError>())?;
    m.add_class::<Loaded>()?;
    m.add_function(wrap_pyfunction!(load_text, m)?)?;
    m.add_function(wrap_pyfunction!(load_path, m)?)?;
    m.add_function(wrap_pyfunction!(write_files, m)?)?;
    Ok(())
}
