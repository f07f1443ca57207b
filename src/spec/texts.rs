//! The texts of a spec, with their JSON paths: the expressions (checked for size and
//! degree) and the free texts (checked against the formula whitelist).

use crate::wire::SpecFile;

/// Every expression text of the spec with its JSON path (what may write an angle as itself).
pub(super) fn expression_texts(spec: &SpecFile) -> Vec<(String, &str)> {
    let mut out: Vec<(String, &str)> = Vec::new();
    for (i, p) in spec.points.iter().enumerate() {
        out.push((format!("points[{i}].position"), &p.position));
    }
    for (i, c) in spec.coordinates.iter().enumerate() {
        if let Some(r) = &c.rate {
            out.push((format!("coordinates[{i}].rate"), r));
        }
    }
    for (i, s) in spec.solids.iter().enumerate() {
        out.push((format!("solids[{i}].mass"), &s.mass));
        if let Some(inr) = &s.inertia {
            for (r, row) in inr.matrix.iter().enumerate() {
                for (c, cell) in row.iter().enumerate() {
                    out.push((format!("solids[{i}].inertia.matrix[{r}][{c}]"), cell));
                }
            }
        }
    }
    if let Some(g) = &spec.gravity {
        out.push(("gravity".to_string(), g));
    }
    for (i, l) in spec.links.iter().enumerate() {
        if let Some(f) = &l.friction {
            out.push((format!("links[{i}].friction"), f));
        }
        if let Some(sp) = &l.spring {
            out.push((format!("links[{i}].spring.stiffness"), &sp.stiffness));
            if let Some(f) = &sp.free {
                out.push((format!("links[{i}].spring.free"), f));
            }
        }
    }
    for (i, a) in spec.actions.iter().enumerate() {
        if let Some(r) = &a.resultant {
            out.push((format!("actions[{i}].resultant"), r));
        }
        if let Some(m) = &a.moment {
            out.push((format!("actions[{i}].moment"), m));
        }
    }
    for (i, s) in spec.small.iter().enumerate() {
        if let Some(a) = &s.around {
            out.push((format!("small[{i}].around"), a));
        }
    }
    out
}

/// Every free text of the spec with its JSON path: what the answer key prints as text, where
/// `$…$` formulas are allowed (see [`crate::latex::rich_text`]).
pub(super) fn free_texts(spec: &SpecFile) -> Vec<(String, &str)> {
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
