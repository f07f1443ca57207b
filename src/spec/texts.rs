//! The texts of a spec, with their JSON paths: the expressions (checked for size and
//! degree) and the free texts (checked against the formula whitelist).

use crate::wire::{LinkKind, SpecFile};

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
        if let Some(mass) = &s.mass {
            out.push((format!("solids[{i}].mass"), mass));
        }
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
        if let Some(p) = &l.pitch {
            out.push((format!("links[{i}].pitch"), p));
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

/// The most characters the free text at `path` may hold, and what it is (for the message):
/// a title or a label is a line of the key, the rest is prose.
pub(super) fn free_text_limit(path: &str) -> (usize, &'static str) {
    if path == "title" || path.ends_with(".title") || path.ends_with(".label") {
        (crate::latex::MAX_LABEL_CHARS, "a title or a label")
    } else {
        (crate::latex::MAX_PROSE_CHARS, "a text")
    }
}

pub(crate) use crate::wire::free_texts;

/// The parameters the spec divides by (`l0 - m*g*sin(beta)/k`, a rate `V/R`), and π
/// (`p/(2*pi)`, a helical link's torsor), in every expression it gives: the texts of
/// [`expression_texts`], the aliases and the hypotheses.
/// A divisor that is an alias brings the parameters of its value, and a hypothesis relation
/// that sets a divisor brings those of the value it gives (k = k2 divides by k2 too).
/// `solved` gives, per coordinate whose rate a loop closure determines, the names its rate
/// divides by.
pub(super) fn divisors(
    spec: &SpecFile,
    params: &[String],
    solved: &[(usize, Vec<String>)],
) -> Vec<String> {
    let mut found = solved_in_place(spec, solved);
    let mut texts: Vec<&str> = spec.aliases.iter().map(|a| a.value.as_str()).collect();
    for h in &spec.hypotheses {
        texts.extend(h.equilibrium.values().map(String::as_str));
        texts.extend(h.rates.values().map(String::as_str));
        texts.extend(h.relations.values().map(String::as_str));
    }
    found.extend(texts.iter().flat_map(|t| crate::expr::divisors_in(t)));
    // Aliases and relations bring the names of their values, until nothing new comes.
    let mut k = 0;
    while k < found.len() {
        let n = found[k].clone();
        let values = spec
            .aliases
            .iter()
            .filter(|a| a.name == n)
            .map(|a| a.value.as_str())
            .chain(
                spec.hypotheses
                    .iter()
                    .filter_map(|h| h.relations.get(&n).map(String::as_str)),
            );
        for v in values.collect::<Vec<_>>() {
            for x in crate::expr::bare_names(v) {
                if !found.contains(&x) {
                    found.push(x);
                }
            }
        }
        k += 1;
    }
    // A helical link's torsor ties its axial moment to its axial resultant by p/(2π).
    if spec.links.iter().any(|l| l.kind == LinkKind::Helical) {
        found.push(crate::expr::PI.to_string());
    }
    let mut out: Vec<String> = Vec::new();
    for n in found {
        if (params.contains(&n) || n == crate::expr::PI) && !out.contains(&n) {
            out.push(n);
        }
    }
    out
}

/// The names below a division line in the expression texts, in their order, with those of
/// each solved rate (`solved`: coordinate index, its divisors) where that coordinate's rate
/// stands: after the points' and the rates of the coordinates before it.
fn solved_in_place(spec: &SpecFile, solved: &[(usize, Vec<String>)]) -> Vec<String> {
    let mut found: Vec<String> = Vec::new();
    let mut placed = 0;
    let mut place = |upto: usize, found: &mut Vec<String>| {
        for (_, names) in solved.iter().filter(|(k, _)| (placed..upto).contains(k)) {
            found.extend(names.iter().cloned());
        }
        placed = placed.max(upto);
    };
    for (path, text) in expression_texts(spec) {
        let coordinate = (path.strip_prefix("coordinates["))
            .and_then(|r| r.split(']').next()?.parse::<usize>().ok());
        let upto = match coordinate {
            Some(k) => k,
            None if path.starts_with("points[") => 0,
            None => spec.coordinates.len(),
        };
        place(upto, &mut found);
        found.extend(crate::expr::divisors_in(text));
    }
    place(spec.coordinates.len(), &mut found);
    found
}

/// A registry that could not be built, placed at the text at fault: the first alias whose
/// value it cannot read, else the coordinate whose rate it cannot read, else `coordinates`.
pub(super) fn registry_error(
    spec: &SpecFile,
    builder: &crate::expr::RegistryBuilder,
    aliases: &[(String, String)],
    e: crate::expr::ExprError,
) -> super::SpecError {
    use super::refusal::at;
    let alias_at_fault = builder.clone().build().ok().and_then(|_| {
        (0..aliases.len()).find_map(|k| {
            builder
                .clone()
                .aliases(&aliases[..=k])
                .build()
                .err()
                .map(|e| (k, e))
        })
    });
    let rate_at_fault = match &e {
        crate::expr::ExprError::Unsupported { input, .. }
        | crate::expr::ExprError::Parse { input, .. }
        | crate::expr::ExprError::UnknownName { input, .. } => spec
            .coordinates
            .iter()
            .position(|c| c.rate.as_deref() == Some(input.as_str())),
        _ => None,
    };
    match (alias_at_fault, rate_at_fault) {
        (Some((k, e)), _) => at(format!("aliases[{k}].value"), e.to_string()),
        (None, Some(i)) => at(format!("coordinates[{i}].rate"), e.to_string()),
        (None, None) => at("coordinates", e.to_string()),
    }
}
