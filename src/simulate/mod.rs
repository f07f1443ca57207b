//! `simulate`: the equations of motion of the PFD integrated for a scenario of the spec (an
//! imposed rate law, initial conditions, parameter values), with the unknowns (a motor torque)
//! recorded along the way; CSV and plots.
//!
//! The right-hand side comes from the engine's exact results: each `eom(q)` is linear in the
//! accelerations, M(q, q̇) q̈ + h(q, q̇, t) = 0, with M and h compiled once; at every call the
//! free accelerations are solved for (LU), then the recorded unknowns are evaluated.
//!
//! ```no_run
//! let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
//! let run = torseur::simulate::simulate(&m, "sans_frottement").unwrap();
//! let cm = run.column("C_m").unwrap();
//! println!("max |C_m| = {}", cm.iter().fold(0.0f64, |a, v| a.max(v.abs())));
//! ```

mod error;
mod law;
mod ode;
mod plot;
mod raster;
mod scenario;
mod table;
#[cfg(test)]
mod tests;

pub use error::SimError;
pub use law::{LawError, TimeLaw};
pub use ode::{MAX_OUTPUT_POINTS, Options, Output, Stats, Trajectory, integrate};
pub use plot::{Figure, Panel, Series, plot};
pub use raster::FONT_DEJAVU_SANS;
pub use table::{NumberFormat, Table, write_atomic};

use crate::expr::Expr;
use crate::mechanism::Mechanism;
use crate::wire::{CoordinateKind, ScenarioSpec};
use scenario::Plan;

/// Why a simulation could not run.
#[derive(Debug, thiserror::Error)]
pub enum SimulateError {
    /// The scenario does not fit the spec.
    #[error("{0}")]
    Scenario(String),
    /// The integrator, the output or the plot failed.
    #[error(transparent)]
    Sim(#[from] SimError),
}

/// A column of a run: its id, its unit, its values at the output instants.
#[derive(Debug, Clone)]
pub struct Column {
    /// `theta2`, `dot(theta1)`, `C_m`.
    pub id: String,
    /// SI unit (`rad`, `rad/s`, `N m`).
    pub unit: String,
    /// One value per output instant.
    pub values: Vec<f64>,
}

/// The result of a simulation.
#[derive(Debug, Clone)]
pub struct Run {
    /// Scenario name.
    pub scenario: String,
    /// The scenario's display label (« sans frottement »), for legends.
    pub label: String,
    /// Output instants (s).
    pub times: Vec<f64>,
    /// Columns: each coordinate and its rate, then the recorded unknowns and integrals.
    pub columns: Vec<Column>,
    /// Right-hand side evaluations and accepted steps.
    pub stats: Stats,
    /// The largest component of the loop closures over the output instants (0 on the
    /// loop): how far the integration of the dependent coordinates drifted from it. None
    /// without a closure.
    pub drift: Option<f64>,
}

impl Run {
    /// The values of a column by id.
    pub fn column(&self, id: &str) -> Option<&[f64]> {
        self.columns
            .iter()
            .find(|c| c.id == id)
            .map(|c| c.values.as_slice())
    }

    /// Largest absolute value of a column and when it occurs.
    pub fn max_abs(&self, id: &str) -> Option<(f64, f64)> {
        let v = self.column(id)?;
        v.iter()
            .zip(&self.times)
            .fold(None, |best: Option<(f64, f64)>, (x, t)| match best {
                Some((b, _)) if b >= x.abs() => best,
                _ => Some((x.abs(), *t)),
            })
    }

    /// The run as a CSV table, headers with units.
    pub fn table(&self) -> Result<Table, SimError> {
        let mut headers = vec!["t (s)".to_string()];
        headers.extend(
            self.columns
                .iter()
                .map(|c| format!("{} ({})", c.id, c.unit)),
        );
        let refs: Vec<&str> = headers.iter().map(String::as_str).collect();
        let mut t = Table::new(&refs);
        for (k, time) in self.times.iter().enumerate() {
            let mut row = vec![*time];
            row.extend(self.columns.iter().map(|c| c.values[k]));
            t.push_row(&row)?;
        }
        Ok(t)
    }
}

/// Unit of a recorded unknown: N m when it enters an action's moment, else N.
fn unknown_unit(m: &Mechanism, id: &str) -> String {
    let moment = m
        .reg
        .param(id)
        .and_then(|x| x.single_variable())
        .is_some_and(|v| {
            m.dynamics.actions.iter().any(|a| {
                a.moment
                    .parts()
                    .any(|(_, c)| c.iter().any(|e| !e.derivative(v).is_zero()))
            })
        });
    if moment { "N m" } else { "N" }.to_string()
}

/// Runs the scenario `name` of the spec.
pub fn simulate(m: &Mechanism, name: &str) -> Result<Run, SimulateError> {
    let sc = m
        .statement
        .scenarios
        .iter()
        .find(|s| s.name == name)
        .ok_or_else(|| {
            let known: Vec<&str> = (m.statement.scenarios.iter())
                .map(|s| s.name.as_str())
                .collect();
            SimulateError::Scenario(format!(
                "no scenario `{name}` in the spec (scenarios: {})",
                if known.is_empty() {
                    "none".to_string()
                } else {
                    known.join(", ")
                }
            ))
        })?;
    simulate_with(m, sc, &[])
}

/// The runs of one question's simulation, its scenarios in order, with the figure the
/// answer key includes; or the first scenario that failed, with its error (the scenarios
/// after it are not run).
pub type QuestionRuns = Result<Simulated, (String, SimulateError)>;

/// One question's simulation, run: its runs and the figure drawn from them.
#[derive(Debug, Clone)]
pub struct Simulated {
    /// The runs, one per scenario, in order.
    pub runs: Vec<Run>,
    /// The curves the question plots ([`question_figure`]).
    pub figure: Figure,
}

/// The runs of the simulation each question of the spec shows (`questions[k].simulation`),
/// one entry per question, in order (no run for a question without one), and their figure:
/// what the answer key draws and tabulates, run and plotted here so that the key's writer
/// only writes.
pub fn question_runs(m: &Mechanism) -> Vec<QuestionRuns> {
    m.statement
        .questions
        .iter()
        .map(|q| {
            let names = q.simulation.iter().flat_map(|s| &s.scenarios);
            let runs = names
                .map(|n| simulate(m, n).map_err(|e| (n.clone(), e)))
                .collect::<Result<Vec<Run>, _>>()?;
            let plot = q.simulation.as_ref().map_or(&[][..], |s| &s.plot[..]);
            let figure = question_figure(plot, &runs);
            Ok(Simulated { runs, figure })
        })
        .collect()
}

/// The figure of a question's runs, as the answer key includes it: one wide and short
/// panel per column of `plot` (the curves are read across time, and the page is the limit),
/// the legend naming each run by its scenario's label (« sans frottement »), in the course's
/// units. The document's title is above; the figure needs none of its own.
pub fn question_figure(plot: &[String], runs: &[Run]) -> Figure {
    let pairs: Vec<(&str, &Run)> = runs.iter().map(|r| (r.label.as_str(), r)).collect();
    let ids: Vec<&str> = plot.iter().map(String::as_str).collect();
    let figure = figure("", &pairs, &ids, true);
    let panels = u32::try_from(figure.panels.len()).unwrap_or(1);
    figure.size(1100, 60 + 160 * panels)
}

/// Longest scenario, in seconds: the run is output every millisecond (every thousandth of
/// the duration below 1 s), so it holds at most 10⁶ instants.
pub const MAX_DURATION: f64 = 1000.0;

/// Why a scenario's duration is refused, if it is: it must be more than 0 s and at most
/// [`MAX_DURATION`].
///
/// ```
/// use torseur::simulate::duration_refusal;
/// assert_eq!(duration_refusal(1.5), None);
/// assert_eq!(duration_refusal(1e12).unwrap(),
///     "1000000000000 s: a duration is more than 0 s and at most 1000 s");
/// ```
pub fn duration_refusal(duration: f64) -> Option<String> {
    (!(duration.is_finite() && duration > 0.0 && duration <= MAX_DURATION))
        .then(|| format!("{duration} s: a duration is more than 0 s and at most {MAX_DURATION} s"))
}

/// Runs a scenario, also integrating each expression of `integrals` over time (a power, to
/// get a work): its integral is recorded as a column named after it.
pub fn simulate_with(
    m: &Mechanism,
    sc: &ScenarioSpec,
    integrals: &[(String, Expr)],
) -> Result<Run, SimulateError> {
    if let Some(why) = duration_refusal(sc.duration) {
        return Err(SimulateError::Scenario(format!(
            "scenario `{}`: duration {why}",
            sc.name
        )));
    }
    let mut plan = Plan::new(m, sc, &sc.record, integrals)?;
    let opts = Options {
        rtol: 1e-10,
        atol: 1e-12,
        output: Output::Interval((sc.duration / 1000.0).min(1e-3)),
        breakpoints: plan.breakpoints.clone(),
        ..Options::default()
    };
    let y0 = plan.initial_state();
    validate_loop_start(m, sc, &mut plan, &y0)?;
    let traj = integrate(|t, y, dy| plan.rhs(m, t, y, dy), &y0, sc.duration, &opts)?;
    let (mut columns, shown) = empty_columns(m, sc, &plan, integrals, traj.len());
    let drift = fill_columns(m, sc, &mut plan, &traj, &shown, &mut columns)?;
    Ok(Run {
        scenario: sc.name.clone(),
        label: sc.label(),
        times: traj.times().to_vec(),
        columns,
        stats: traj.stats(),
        drift,
    })
}

/// The dependent coordinates start on the loop: their initial values are given.
fn validate_loop_start(
    m: &Mechanism,
    sc: &ScenarioSpec,
    plan: &mut Plan,
    y0: &[f64],
) -> Result<(), SimulateError> {
    let scale = sc.values.values().fold(1.0_f64, |a, v| a.max(v.abs()));
    if let Some(r) = plan.closure_residual(m, 0.0, y0)
        && r > 1e-9 * scale
    {
        let names: Vec<&str> = plan
            .driven
            .iter()
            .map(|&q| m.reg.coord_info(q).name.as_str())
            .collect();
        return Err(SimulateError::Scenario(format!(
            "scenario `{}`: the initial values do not close the loop (a component of the \
             closure is {r:e}): give {} values on it in `initial`",
            sc.name,
            names.join(", ")
        )));
    }
    Ok(())
}

/// The run's columns, with room for `len` instants: each shown coordinate and its rate
/// (imposed, free, driven), the recorded unknowns, the integrals. Also which imposed
/// coordinates are shown (a phase Ω t is the time itself, scaled: not a column of its own).
fn empty_columns(
    m: &Mechanism,
    sc: &ScenarioSpec,
    plan: &Plan,
    integrals: &[(String, Expr)],
    len: usize,
) -> (Vec<Column>, Vec<bool>) {
    let reg = &m.reg;
    let unit = |q: crate::expr::CoordId, rate: bool| {
        let base = match reg.coord_info(q).kind {
            CoordinateKind::Angle => "rad",
            CoordinateKind::Length => "m",
        };
        if rate {
            format!("{base}/s")
        } else {
            base.to_string()
        }
    };
    let mut columns: Vec<Column> = Vec::new();
    let mut push = |id: String, unit: String| {
        columns.push(Column {
            id,
            unit,
            values: Vec::with_capacity(len),
        })
    };
    let shown: Vec<bool> = plan
        .imposed
        .iter()
        .map(|im| reg.coord_info(im.coord).phase().is_none())
        .collect();
    for (im, _) in plan.imposed.iter().zip(&shown).filter(|(_, s)| **s) {
        let n = &reg.coord_info(im.coord).name;
        push(n.clone(), unit(im.coord, false));
        push(format!("dot({n})"), unit(im.coord, true));
    }
    for &q in plan.free.iter().chain(&plan.driven) {
        let n = &reg.coord_info(q).name;
        push(n.clone(), unit(q, false));
        push(format!("dot({n})"), unit(q, true));
    }
    for id in &sc.record {
        push(id.clone(), unknown_unit(m, id));
    }
    for (name, _) in integrals {
        push(format!("int({name})"), "SI".to_string());
    }
    (columns, shown)
}

/// Fills the columns at every instant of the trajectory; returns the largest drift of the
/// loop closures, if any.
fn fill_columns(
    m: &Mechanism,
    sc: &ScenarioSpec,
    plan: &mut Plan,
    traj: &Trajectory,
    shown: &[bool],
    columns: &mut [Column],
) -> Result<Option<f64>, SimulateError> {
    let ni = plan.imposed.len();
    let nf = plan.free.len();
    let at = ni + 2 * nf + plan.integrals;
    let mut drift: Option<f64> = None;
    for (k, y) in traj.states().enumerate() {
        let t = traj.times()[k];
        let e = plan
            .evaluate(m, t, y)
            .map_err(|e| SimulateError::Scenario(format!("at t = {t}: {e}")))?;
        let mut c = 0;
        let mut put = |v: f64, c: &mut usize| {
            columns[*c].values.push(v);
            *c += 1;
        };
        for (i, w) in e.rates.iter().enumerate().filter(|(i, _)| shown[*i]) {
            put(y[i], &mut c);
            put(*w, &mut c);
        }
        for i in 0..nf {
            put(y[ni + i], &mut c);
            put(y[ni + nf + i], &mut c);
        }
        for (i, w) in e.driven_rates.iter().enumerate() {
            put(y[at + i], &mut c);
            put(*w, &mut c);
        }
        if let Some(r) = plan.closure_residual(m, t, y) {
            drift = Some(drift.map_or(r, |d| d.max(r)));
        }
        for v in e.recorded.iter().take(sc.record.len()) {
            put(*v, &mut c);
        }
        for i in 0..plan.integrals {
            put(y[ni + 2 * nf + i], &mut c);
        }
    }
    Ok(drift)
}

/// A figure comparing runs: one panel per column id, one curve per run, named by the legend
/// given with it (a run's [`Run::label`]). Axes are labelled in the course's notation
/// ([`column_label`], units with `·`); angles are drawn in degrees and rates in tr/min when
/// `course_units` is set, as the seed's curves are.
pub fn figure(title: &str, runs: &[(&str, &Run)], ids: &[&str], course_units: bool) -> Figure {
    let mut fig = Figure::new(title, "t (s)");
    for id in ids {
        let mut label = None;
        let mut panel_series = Vec::new();
        for (name, run) in runs {
            let Some(col) = run.columns.iter().find(|c| c.id == *id) else {
                continue;
            };
            let (scale, unit) = match (course_units, col.unit.as_str()) {
                (true, "rad") => (180.0 / std::f64::consts::PI, "°".to_string()),
                (true, "rad/s") => (30.0 / std::f64::consts::PI, "tr/min".to_string()),
                (_, u) => (1.0, u.replace(' ', "·")),
            };
            label.get_or_insert(format!("{} ({unit})", column_label(id)));
            let pts = run
                .times
                .iter()
                .zip(&col.values)
                .map(|(t, v)| (*t, v * scale))
                .collect();
            panel_series.push(Series::new(*name, pts));
        }
        if let Some(l) = label {
            let mut p = Panel::new(l);
            for s in panel_series {
                p = p.series(s);
            }
            fig = fig.panel(p);
        }
    }
    fig
}

/// A column id in the course's notation, in Unicode for the plots: `dot(theta1)` → θ̇₁,
/// `C_m` → Cₘ, `X01` → X₀₁; an index without a Unicode subscript stays after `_`.
///
/// ```
/// use torseur::simulate::column_label;
/// assert_eq!(column_label("dot(theta1)"), "θ\u{307}₁");
/// assert_eq!(column_label("ddot(x)"), "x\u{308}");
/// assert_eq!(column_label("C_m"), "Cₘ");
/// assert_eq!(column_label("F_b"), "F_b");
/// assert_eq!(column_label("omega"), "ω");
/// ```
pub fn column_label(id: &str) -> String {
    let (inner, accent) =
        if let Some(n) = id.strip_prefix("ddot(").and_then(|r| r.strip_suffix(')')) {
            (n, "\u{308}")
        } else if let Some(n) = id.strip_prefix("dot(").and_then(|r| r.strip_suffix(')')) {
            (n, "\u{307}")
        } else {
            (id, "")
        };
    let (head, sub) = match inner.split_once('_') {
        Some((h, s)) => (h, s.replace('_', "")),
        None => {
            let cut = inner
                .char_indices()
                .find(|(i, c)| *i > 0 && c.is_ascii_digit())
                .map_or(inner.len(), |(i, _)| i);
            (&inner[..cut], inner[cut..].to_string())
        }
    };
    let head = greek_letter(head).map_or_else(|| head.to_string(), String::from);
    let sub = match sub.chars().map(subscript).collect::<Option<String>>() {
        Some(s) => s,
        None => format!("_{sub}"),
    };
    format!("{head}{accent}{sub}")
}

/// The Greek letter a name spells (`theta` → θ).
fn greek_letter(n: &str) -> Option<char> {
    const NAMES: [(&str, char); 33] = [
        ("alpha", 'α'),
        ("beta", 'β'),
        ("gamma", 'γ'),
        ("delta", 'δ'),
        ("epsilon", 'ε'),
        ("zeta", 'ζ'),
        ("eta", 'η'),
        ("theta", 'θ'),
        ("iota", 'ι'),
        ("kappa", 'κ'),
        ("lambda", 'λ'),
        ("mu", 'μ'),
        ("nu", 'ν'),
        ("xi", 'ξ'),
        ("pi", 'π'),
        ("rho", 'ρ'),
        ("sigma", 'σ'),
        ("tau", 'τ'),
        ("upsilon", 'υ'),
        ("phi", 'φ'),
        ("chi", 'χ'),
        ("psi", 'ψ'),
        ("omega", 'ω'),
        ("Gamma", 'Γ'),
        ("Delta", 'Δ'),
        ("Theta", 'Θ'),
        ("Lambda", 'Λ'),
        ("Xi", 'Ξ'),
        ("Pi", 'Π'),
        ("Sigma", 'Σ'),
        ("Phi", 'Φ'),
        ("Psi", 'Ψ'),
        ("Omega", 'Ω'),
    ];
    NAMES.iter().find(|(s, _)| *s == n).map(|(_, c)| *c)
}

/// The Unicode subscript of a digit or of one of the letters that have one (in the plots'
/// font, DejaVu Sans).
fn subscript(c: char) -> Option<char> {
    match c {
        '0'..='9' => char::from_u32(0x2080 + (c as u32 - '0' as u32)),
        'a' => Some('ₐ'),
        'e' => Some('ₑ'),
        'o' => Some('ₒ'),
        'x' => Some('ₓ'),
        'h' => Some('ₕ'),
        'k' => Some('ₖ'),
        'l' => Some('ₗ'),
        'm' => Some('ₘ'),
        'n' => Some('ₙ'),
        'p' => Some('ₚ'),
        's' => Some('ₛ'),
        't' => Some('ₜ'),
        _ => None,
    }
}
