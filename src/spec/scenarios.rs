//! The scenarios of a spec and the simulations its questions show, checked when the spec is
//! loaded: what `simulate` and the answer key would otherwise refuse only once they run, and
//! without the place in the file.

use super::SpecError;
use super::refusal::at;
use crate::mechanism::Mechanism;
use crate::simulate::{TimeLaw, duration_refusal};

/// Checks every scenario (duration, the names of its values and initial state, imposed laws
/// evaluated where each piece starts, recorded unknowns) and every question's simulation (scenarios, plotted
/// columns, the column of the maximum).
pub(super) fn validate(m: &Mechanism) -> Result<(), SpecError> {
    let reg = &m.reg;
    let sign = |p: &str| m.dynamics.dry.iter().any(|d| d.sign == p);
    for (i, sc) in m.statement.scenarios.iter().enumerate() {
        let path = format!("scenarios[{i}]");
        if m.statement.scenarios[..i].iter().any(|s| s.name == sc.name) {
            return Err(at(
                format!("{path}.name"),
                format!("a second scenario named `{}`", sc.name),
            ));
        }
        if let Some(why) = duration_refusal(sc.duration) {
            return Err(at(format!("{path}.duration"), why));
        }
        for k in sc.values.keys() {
            let here = format!("{path}.values.{k}");
            if sign(k) {
                return Err(at(
                    here,
                    format!(
                        "`{k}` is the sign of a link's relative rate under dry friction: the \
                         simulation sets it"
                    ),
                ));
            }
            // An action's unknown may be given: an input of the equations of motion (a
            // motor torque), which `simulate` checks against the solved PFD.
            if !reg.parameters().contains(k) && !m.dynamics.action_unknowns.contains(k) {
                return Err(at(here, format!("`{k}` is not a parameter")));
            }
        }
        // A parameter without a value is refused when the scenario runs (a spec may gain a
        // parameter that its scenarios do not need); the laws are then not evaluated here.
        let complete = (reg.parameters().iter()).all(|p| sc.values.contains_key(p) || sign(p));
        for name in sc.initial.keys() {
            if reg.coord(name).is_none() {
                return Err(at(
                    format!("{path}.initial.{name}"),
                    format!("`{name}` is not a coordinate"),
                ));
            }
        }
        let params: Vec<f64> = (reg.parameters().iter())
            .map(|p| sc.values.get(p).copied().unwrap_or(0.0))
            .collect();
        for (k, im) in sc.imposed.iter().enumerate() {
            let here = format!("{path}.imposed[{k}]");
            let q = reg.coord(&im.coordinate).ok_or_else(|| {
                at(
                    format!("{here}.coordinate"),
                    format!("`{}` is not a coordinate", im.coordinate),
                )
            })?;
            if reg.coord_info(q).is_driven() {
                return Err(at(
                    format!("{here}.coordinate"),
                    format!(
                        "`{}` is driven by other coordinates' rates: its motion cannot be imposed",
                        im.coordinate
                    ),
                ));
            }
            TimeLaw::new(&im.rate, reg.parameters(), &params)
                .and_then(|law| match complete {
                    true => law.validate_starts(sc.duration),
                    false => Ok(()),
                })
                .map_err(|e| at(e.path_under(&format!("{here}.rate")), e.message))?;
        }
        for (k, id) in sc.record.iter().enumerate() {
            if !reg.unknowns().contains(id) {
                return Err(at(
                    format!("{path}.record[{k}]"),
                    format!(
                        "`{id}` is not an unknown of the PFD (links' components, actions' unknowns)"
                    ),
                ));
            }
        }
    }
    for (i, q) in m.statement.questions.iter().enumerate() {
        if let Some(sim) = &q.simulation {
            simulation(m, sim, &format!("questions[{i}].simulation"))?;
        }
    }
    Ok(())
}

/// A question's simulation: its scenarios exist, each plotted column is one of theirs, the
/// maximum is taken on a column every one of them has.
fn simulation(
    m: &Mechanism,
    sim: &crate::wire::SimulationSpec,
    path: &str,
) -> Result<(), SpecError> {
    let mut runs = Vec::new();
    for (k, name) in sim.scenarios.iter().enumerate() {
        let sc = (m.statement.scenarios.iter())
            .find(|s| &s.name == name)
            .ok_or_else(|| {
                at(
                    format!("{path}.scenarios[{k}]"),
                    format!("no scenario `{name}` in the spec's `scenarios`"),
                )
            })?;
        runs.push(sc);
    }
    // The columns of a run: each coordinate (but a phase Ω t) and its rate, then what the
    // scenario records.
    let coordinates: Vec<String> = (m.reg.coordinates().iter())
        .filter(|c| c.phase().is_none())
        .flat_map(|c| [c.name.clone(), format!("dot({})", c.name)])
        .collect();
    let has = |sc: &crate::wire::ScenarioSpec, id: &str| {
        coordinates.iter().any(|c| c == id) || sc.record.iter().any(|r| r == id)
    };
    let columns = || {
        let mut all: Vec<&str> = coordinates.iter().map(String::as_str).collect();
        for r in runs.iter().flat_map(|sc| &sc.record) {
            if !all.contains(&r.as_str()) {
                all.push(r);
            }
        }
        all.join(", ")
    };
    for (k, id) in sim.plot.iter().enumerate() {
        if !runs.iter().any(|sc| has(sc, id)) {
            return Err(at(
                format!("{path}.plot[{k}]"),
                format!(
                    "`{id}` is not a column of the simulation (its columns: {})",
                    columns()
                ),
            ));
        }
    }
    if let Some(id) = &sim.maximum
        && let Some(sc) = runs.iter().find(|sc| !has(sc, id))
    {
        return Err(at(
            format!("{path}.maximum"),
            format!(
                "`{id}` is not a column of the scenario `{}` (record it in its `record`)",
                sc.name
            ),
        ));
    }
    for name in sim.reference.keys() {
        if !sim.scenarios.contains(name) {
            return Err(at(
                format!("{path}.reference.{name}"),
                format!("`{name}` is not one of this simulation's `scenarios`"),
            ));
        }
    }
    Ok(())
}
