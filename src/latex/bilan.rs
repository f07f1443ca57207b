//! The closing « Bilan » of an answer key: the results short enough for a table row, each with
//! its value, its unit and its question; the long ones named where they are boxed.

use super::page::{Doc, Inline};
use super::{basis, escape_text, name};
use crate::derivation::Value;
use crate::quantity::{Quantity, QuantityKind};
use std::fmt::Write;

/// The closing « Bilan »: each result of the key (in the order of the questions) whose value
/// holds on a table's row, with its value, its unit from the parameters' units and the
/// question it is derived in; a long list is set in two tables side by side. A result too long
/// for a row is not repeated: one sentence under the tables names it with its question. A key
/// none of whose results is short has no bilan (a table of references says nothing).
pub(super) fn bilan(doc: &mut Doc) {
    let (entries, inline) = bilan_entries(doc);
    let (short, long): (Vec<Entry>, Vec<Entry>) =
        entries.into_iter().partition(|e| e.value.is_some());
    if short.is_empty() {
        return;
    }
    doc.inline.extend(inline);
    let with_questions = short.iter().chain(&long).all(|e| e.question.is_some());
    let rows: Vec<Row> = short.into_iter().map(|e| e.row(with_questions)).collect();
    // The sentence on the long results follows in the table's small type, not centred.
    let others = elsewhere(&long)
        .map(|s| format!("\n{{\\small\\smallskip\\noindent {s}\\par}}"))
        .unwrap_or_default();
    let _ = writeln!(
        doc.o,
        "\\section*{{Bilan}}\n{{\\small\\renewcommand{{\\arraystretch}}{{1.15}}\\noindent\n{}\\par}}{others}",
        tables(&rows, with_questions)
    );
}

/// A result of the bilan: the same result shown in general and under hypotheses, both
/// boxed in one question, is one entry (a long one boxed in two questions is two).
struct Entry {
    /// The grandeur, in math.
    title: String,
    /// The grandeur in a sentence: « l'équation du mouvement en $\theta$ », or the math.
    said: String,
    /// The hypotheses it holds under, none for the general case.
    unders: Vec<Option<String>>,
    /// The résultat, in math, when it holds on a row.
    value: Option<String>,
    unit: String,
    /// The printed width of the résultat.
    width: usize,
    /// The quantity id.
    what: String,
    /// The number of the question it is derived in, for a key with questions.
    question: Option<String>,
}

/// A row of the bilan's table: grandeur, résultat, unité, question, and its printed width.
struct Row {
    grandeur: String,
    value: String,
    unit: String,
    question: String,
    width: usize,
}

/// The entries of the bilan, one per result of the key (in the order of the questions),
/// and the short values it repeats, recorded to be proven like every formula.
fn bilan_entries(doc: &Doc) -> (Vec<Entry>, Vec<Inline>) {
    let m = doc.m;
    let dims = crate::units::Dimensions::of(m);
    let mut inline = Vec::new();
    let mut merged: Vec<Entry> = Vec::new();
    // A short list is one table, with room for a one-line result; a long one may be split
    // into tables side by side, where only short results fit.
    let longest = if doc.results.len() <= 6 { 60 } else { 34 };
    for (q, hyp, v, place) in &doc.results {
        let what = &q.to_string();
        let unit = unit_of(m, &dims, q);
        let shown = short_value(doc, q, v, longest);
        let width = shown.as_ref().map_or(0, |(t, _)| super::width(t));
        if let Some((t, value)) = &shown {
            inline.push(Inline {
                what: format!("bilan {what}"),
                latex: t.clone(),
                value: value.clone(),
            });
        }
        let value = shown.map(|(t, _)| format!("${t}$"));
        let question = place.strip_prefix("la question ").map(str::to_string);
        let under = hyp.as_deref().map(escape_text);
        match merged.iter_mut().find(|r| {
            r.what == *what && r.value == value && r.unit == unit && r.question == question
        }) {
            Some(r) => r.unders.push(under),
            None => merged.push(Entry {
                title: bilan_title(&doc.names, q),
                said: said_title(&doc.names, q),
                unders: vec![under],
                value,
                unit,
                width,
                what: what.clone(),
                question,
            }),
        }
    }
    (merged, inline)
}

/// A result's value as a row shows it, with the value the page records for it: a scalar, a
/// quotient (an unknown divided by a length), or a vector as its sum over the basis vectors,
/// when it holds in `longest` characters. An equation of motion, a torsor or an operator is
/// found where it is boxed.
fn short_value(doc: &Doc, q: &Quantity, v: &Value, longest: usize) -> Option<(String, Value)> {
    let m = doc.m;
    match (v, &q.kind) {
        (_, QuantityKind::Eom(_)) => None,
        (Value::Scalar(e), _) => {
            let t = super::expr(e);
            (super::width(&t) <= longest).then(|| (t, v.clone()))
        }
        (Value::Quotient(f), _) => {
            let t = super::fraction(f);
            (super::width(&t) <= longest).then(|| (t, v.clone()))
        }
        (Value::Vector { basis, components }, _) => {
            let frame = m.frame_name(*basis);
            let t = super::values::vector_line(&doc.names, frame, components, longest)?;
            // The reader reads a sum over any bases and compares in the ground basis.
            let g = m.frames.ground();
            let value = Value::Vector {
                basis: g,
                components: crate::vector::Vector::new(*basis, components.clone())
                    .express_in(&m.frames, g),
            };
            Some((t, value))
        }
        _ => None,
    }
}

/// The unit of a result from the parameters' units (`--` when it has none), both elements'
/// for a torsor.
fn unit_of(
    m: &crate::mechanism::Mechanism,
    dims: &crate::units::Dimensions,
    q: &Quantity,
) -> String {
    let style = crate::units::unit_style(&q.kind);
    let expected = crate::units::expected_dimension(m, dims, q);
    let unit = |k: usize| {
        expected
            .component(k)
            .map(|u| u.si_latex(style))
            .filter(|u| !u.is_empty())
            .map(|u| format!("${u}$"))
            .unwrap_or_else(|| "--".to_string())
    };
    if q.kind.is_torsor() {
        format!("{} ; {}", unit(0), unit(3))
    } else {
        unit(0)
    }
}

/// The grandeur of a result: « Éq. du mouvement en θ », or the quantity with the basis
/// asked (the same vector asked in two bases reads apart).
fn bilan_title(names: &super::VectorNames, q: &Quantity) -> String {
    match &q.kind {
        QuantityKind::Eom(c) if q.linear => {
            format!(
                "\\text{{Éq. du mouvement en }} {} \\text{{ (linéarisée)}}",
                name(c)
            )
        }
        QuantityKind::Eom(c) => format!("\\text{{Éq. du mouvement en }} {}", name(c)),
        _ => match &q.basis {
            Some(b) => format!("{} \\text{{ dans }} {}", names.quantity_title(q), basis(b)),
            None => names.quantity_title(q),
        },
    }
}

/// The grandeur as a sentence names it: the quantity in math, an equation of motion in words.
fn said_title(names: &super::VectorNames, q: &Quantity) -> String {
    match &q.kind {
        QuantityKind::Eom(c) if q.linear => {
            format!("l'équation du mouvement linéarisée en ${}$", name(c))
        }
        QuantityKind::Eom(c) => format!("l'équation du mouvement en ${}$", name(c)),
        _ => format!("${}$", bilan_title(names, q)),
    }
}

impl Entry {
    /// The hypotheses after the grandeur: « (h) », or « (général ; h) ».
    fn under(&self) -> String {
        match self.unders.as_slice() {
            [None] => String::new(),
            [Some(h)] => format!(" ({h})"),
            hs => {
                let names: Vec<String> = hs
                    .iter()
                    .map(|h| h.clone().unwrap_or_else(|| "général".to_string()))
                    .collect();
                format!(" ({})", names.join(" ; "))
            }
        }
    }

    /// The entry as a row, its hypotheses after the grandeur, its question when the key has
    /// questions.
    fn row(self, with_questions: bool) -> Row {
        let under = self.under();
        let question = match (&self.question, with_questions) {
            (Some(n), true) => format!("Q{n}"),
            _ => String::new(),
        };
        // The row's printed width: the grandeur, the résultat, the unit (the question's
        // column, « Q4 », is narrower than the rough estimate's slack).
        let title_w = super::width(&self.title) + under.chars().count();
        let unit_w = super::width(&self.unit).min(12);
        Row {
            grandeur: format!("${}${under}", self.title),
            value: self.value.unwrap_or_default(),
            width: title_w + self.width + unit_w,
            unit: self.unit,
            question,
        }
    }
}

/// The sentence naming the results too long for the table, grouped by their question
/// (« $X_{23}$ et l'équation du mouvement en θ (Q4) »), or none.
fn elsewhere(long: &[Entry]) -> Option<String> {
    if long.is_empty() {
        return None;
    }
    let mut groups: Vec<(Option<&String>, Vec<String>)> = Vec::new();
    for e in long {
        let item = format!("{}{}", e.said, e.under());
        match groups.iter_mut().find(|(q, _)| *q == e.question.as_ref()) {
            Some((_, items)) => items.push(item),
            None => groups.push((e.question.as_ref(), vec![item])),
        }
    }
    let parts: Vec<String> = groups
        .into_iter()
        .map(|(q, items)| {
            let list = super::words::french_list(&items);
            match q {
                Some(n) => format!("{list} (Q{n})"),
                None => list,
            }
        })
        .collect();
    let place = match long.iter().all(|e| e.question.is_some()) {
        true => "dans leur question",
        false => "ci-dessus",
    };
    Some(format!(
        "Trop longs pour ce tableau, encadrés {place} : {}.",
        parts.join(" ; ")
    ))
}

/// One table of the bilan.
fn table(rows: &[Row], with_questions: bool) -> String {
    let body: Vec<String> = rows
        .iter()
        .map(|r| match with_questions {
            true => format!(
                "{} & {} & {} & {} \\\\",
                r.grandeur, r.value, r.unit, r.question
            ),
            false => format!("{} & {} & {} \\\\", r.grandeur, r.value, r.unit),
        })
        .collect();
    let (spec, head) = match with_questions {
        true => ("llll", "Grandeur & Résultat & Unité & Question"),
        false => ("lll", "Grandeur & Résultat & Unité"),
    };
    format!(
        "\\begin{{tabular}}[t]{{@{{}}{spec}@{{}}}}\n\\hline\n{head} \\\\\n\\hline\n\\noalign{{\\vspace{{2pt}}}}\n{}\n\\hline\n\\end{{tabular}}",
        body.join("\n")
    )
}

/// The rows in one centred table, or in two or three tables side by side when the values
/// are short and the list long.
fn tables(rows: &[Row], with_questions: bool) -> String {
    // (in \small, a line holds about 1.2 × LINE characters)
    let widest = rows.iter().map(|r| r.width).max().unwrap_or(0);
    let narrow = widest + 6 <= super::LINE * 6 / 10;
    // Side by side, each table is scaled down to its share of the line if it is wider (the
    // width estimate is rough; the page's margin is not).
    let fit = |t: String, share: &str| {
        format!(
            "\\resizebox{{\\ifdim\\width>{share}\\linewidth {share}\\linewidth\\else\\width\\fi}}{{!}}{{{t}}}"
        )
    };
    match rows.len() {
        n if n > 9 && widest + 6 <= super::LINE * 4 / 10 => rows
            .chunks(n.div_ceil(3))
            .map(|c| fit(table(c, with_questions), "0.32"))
            .collect::<Vec<_>>()
            .join("\\hfill\n"),
        n if n > 6 && narrow => rows
            .chunks(n.div_ceil(2))
            .map(|c| fit(table(c, with_questions), "0.49"))
            .collect::<Vec<_>>()
            .join("\\hfill\n"),
        _ => format!("\\centering\n{}", table(rows, with_questions)),
    }
}
