//! The spec's free texts (title, statements, labels, descriptions) listed with their JSON
//! paths, for the checks every text passes before anything is printed.

use super::SpecFile;

/// Every free text of the spec with its JSON path: what the answer key prints as text, where
/// `$…$` formulas are allowed (see [`crate::latex::rich_text`]).
pub(crate) fn free_texts(spec: &SpecFile) -> Vec<(String, &str)> {
    let mut out: Vec<(String, &str)> = vec![("title".to_string(), &spec.title)];
    if let Some(d) = &spec.description {
        out.push(("description".to_string(), d));
    }
    for (i, p) in spec.parameters.iter().enumerate() {
        if let Some(d) = &p.description {
            out.push((format!("parameters[{i}].description"), d));
        }
    }
    for (i, a) in spec.aliases.iter().enumerate() {
        if let Some(d) = &a.description {
            out.push((format!("aliases[{i}].description"), d));
        }
    }
    for (i, c) in spec.coordinates.iter().enumerate() {
        if let Some(d) = &c.description {
            out.push((format!("coordinates[{i}].description"), d));
        }
    }
    for (i, h) in spec.hypotheses.iter().enumerate() {
        if let Some(t) = &h.text {
            out.push((format!("hypotheses[{i}].text"), t));
        }
    }
    for (i, l) in spec.links.iter().enumerate() {
        if let Some(t) = &l.label {
            out.push((format!("links[{i}].label"), t));
        }
    }
    for (i, a) in spec.actions.iter().enumerate() {
        if let Some(t) = &a.label {
            out.push((format!("actions[{i}].label"), t));
        }
        if let Some(t) = &a.source {
            out.push((format!("actions[{i}].source"), t));
        }
    }
    for (i, sc) in spec.scenarios.iter().enumerate() {
        if let Some(t) = &sc.label {
            out.push((format!("scenarios[{i}].label"), t));
        }
        if let Some(d) = &sc.description {
            out.push((format!("scenarios[{i}].description"), d));
        }
    }
    for (i, q) in spec.questions.iter().enumerate() {
        out.push((format!("questions[{i}].title"), &q.title));
        if let Some(t) = &q.statement {
            out.push((format!("questions[{i}].statement"), t));
        }
        if let Some(t) = &q.answer {
            out.push((format!("questions[{i}].answer"), t));
        }
        for (k, e) in q.equations.iter().enumerate() {
            if let Some(r) = &e.reason {
                out.push((format!("questions[{i}].equations[{k}].reason"), r));
            }
        }
    }
    out
}
