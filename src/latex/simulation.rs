//! The simulations a question shows in the answer key: the assumed values, the curves, the
//! maxima against the statement's figures.

use super::{escape_text, name, rich_text_or_escaped};
use crate::mechanism::Mechanism;
use std::fmt::Write;

/// A number as the French text writes it: three significant digits, decimal comma.
fn french(v: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let digits = (2 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    format!("{v:.digits$}").replace('.', "{,}")
}

/// The simulations of a question from their runs and figure (run and drawn by the caller):
/// the assumed values, the curves, the maxima against the statement's; `line`, the width of
/// the page's line in characters (see [`super::LINE`]).
pub(super) fn simulation_block(
    o: &mut String,
    m: &Mechanism,
    sim: &crate::wire::SimulationSpec,
    runs: &crate::simulate::QuestionRuns,
    (file, line): (&str, usize),
) -> Result<crate::simulate::Figure, crate::derivation::DeriveError> {
    let simulated = runs
        .as_ref()
        .map_err(|(name, e)| fail(name, e.to_string()))?;
    assumed_values(o, m, sim, line);
    scenario_descriptions(o, m, sim);
    let _ = writeln!(
        o,
        "\\begin{{center}}\n\\includegraphics[width=0.9\\textwidth]{{{file}}}\n\\end{{center}}"
    );
    if let Some(col) = &sim.maximum {
        maxima_table(o, m, sim, &simulated.runs, col)?;
    }
    Ok(simulated.figure.clone())
}

/// The error of a simulation that fails, naming its scenario.
fn fail(what: &str, e: String) -> crate::derivation::DeriveError {
    crate::derivation::DeriveError::new(&what, e)
}

/// The values the simulations use (the statement may give some of them, or none), six to a
/// row of the full line ([`super::LINE`]), fewer on a narrower one (`line`); a value that
/// differs between the scenarios (the friction f) is given for each, in the order of the
/// scenarios.
fn assumed_values(o: &mut String, m: &Mechanism, sim: &crate::wire::SimulationSpec, line: usize) {
    let Some(first) = sim
        .scenarios
        .first()
        .and_then(|n| m.statement.scenarios.iter().find(|s| &s.name == n))
    else {
        return;
    };
    let per = (6 * line / super::LINE).clamp(2, 6);
    let _ = writeln!(
        o,
        "Les simulations utilisent les valeurs suivantes (unités SI).\n\n\\begin{{center}}\n\
         \\begin{{tabular}}{{{}}}",
        "l".repeat(per)
    );
    let others: Vec<&crate::wire::ScenarioSpec> = sim
        .scenarios
        .iter()
        .filter_map(|n| m.statement.scenarios.iter().find(|s| &s.name == n))
        .collect();
    let cells: Vec<String> = first
        .values
        .iter()
        .map(|(k, v)| {
            let mut vals: Vec<String> = Vec::new();
            for sc in &others {
                let x = sc.values.get(k).copied().unwrap_or(*v);
                let t = french_sci(x);
                if !vals.contains(&t) {
                    vals.push(t);
                }
            }
            format!("${} = {}$", name(k), vals.join(" \\text{ ou } "))
        })
        .collect();
    for row in cells.chunks(per) {
        let _ = writeln!(o, "{} \\\\", row.join(" & "));
    }
    o.push_str("\\end{tabular}\n\\end{center}\n");
}

/// Each scenario's description, under its label.
fn scenario_descriptions(o: &mut String, m: &Mechanism, sim: &crate::wire::SimulationSpec) {
    for (name, sc) in sim.scenarios.iter().filter_map(|n| {
        m.statement
            .scenarios
            .iter()
            .find(|s| &s.name == n)
            .map(|s| (n, s))
    }) {
        if let Some(d) = &sc.description {
            let _ = writeln!(
                o,
                "\\textbf{{{}}} : {}\n",
                rich_text_or_escaped(&m.scenario_label(name).unwrap_or_else(|| name.clone())),
                rich_text_or_escaped(d)
            );
        }
    }
}

/// The maximum of `col` in each run against the statement's.
fn maxima_table(
    o: &mut String,
    m: &Mechanism,
    sim: &crate::wire::SimulationSpec,
    runs: &[crate::simulate::Run],
    col: &str,
) -> Result<(), crate::derivation::DeriveError> {
    let unit = runs
        .first()
        .and_then(|r| r.columns.iter().find(|c| c.id == col))
        .map(|c| format!(" ({})", escape_text(&c.unit)))
        .unwrap_or_default();
    let _ = writeln!(
        o,
        "\\begin{{center}}\n\\begin{{tabular}}{{lcc}}\nCas & ${}$ maximal calculé{unit} & \
         ${}$ maximal du sujet{unit} \\\\\n\\hline",
        name(col),
        name(col)
    );
    for (scenario, run) in sim.scenarios.iter().zip(runs) {
        let (v, t) = run
            .max_abs(col)
            .ok_or_else(|| fail(scenario, format!("no column `{col}` in the run")))?;
        let reference = sim
            .reference
            .get(scenario)
            .map(|r| format!("${}$", french(*r)))
            .unwrap_or_else(|| "--".to_string());
        let _ = writeln!(
            o,
            "{} & ${}$ (à $t = {}$~s) & {} \\\\",
            rich_text_or_escaped(
                &m.scenario_label(scenario)
                    .unwrap_or_else(|| scenario.clone())
            ),
            french(v),
            french(t),
            reference
        );
    }
    o.push_str("\\end{tabular}\n\\end{center}\n");
    Ok(())
}

/// A value for the table of assumed values: plain when moderate, else a power of ten.
fn french_sci(v: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let e = v.abs().log10().floor() as i32;
    if (-2..=3).contains(&e) {
        return format!("{v}").replace('.', "{,}");
    }
    let mant = v / 10f64.powi(e);
    let mant = format!("{mant:.3}");
    let mant = mant
        .trim_end_matches('0')
        .trim_end_matches('.')
        .replace('.', "{,}");
    format!("{mant} \\cdot 10^{{{e}}}")
}
