//! The closing « Bilan » of an answer key: its results, their values when short, their units.

use super::page::{Doc, Inline};
use super::{basis, escape_text, name};
use crate::derivation::Value;
use crate::quantity::{Quantity, QuantityKind};
use std::fmt::Write;

/// The closing « Bilan »: each result of the key (in the order of the questions), its value
/// when it is short or the question where it is boxed, and its unit from the parameters'
/// units. A long list is set in two tables side by side.
pub(super) fn bilan(doc: &mut Doc) {
    let (entries, inline) = bilan_entries(doc);
    doc.inline.extend(inline);
    let rows: Vec<Row> = entries.into_iter().map(Entry::row).collect();
    if rows.is_empty() {
        return;
    }
    let _ = writeln!(
        doc.o,
        "\\section*{{Bilan}}\n{{\\small\\renewcommand{{\\arraystretch}}{{1.15}}\\noindent\n{}\\par}}",
        tables(&rows)
    );
}

/// A result of the bilan: the same result shown in general and under hypotheses, both
/// boxed in one question, is one entry.
struct Entry {
    /// The grandeur, in math.
    title: String,
    /// The hypotheses it holds under, none for the general case.
    unders: Vec<Option<String>>,
    /// The résultat: the value, or where it is boxed.
    value: String,
    unit: String,
    /// The printed width of the résultat.
    width: usize,
    /// The quantity id.
    what: String,
}

/// A row of the bilan's table: grandeur, résultat, unité, and its printed width.
struct Row {
    grandeur: String,
    value: String,
    unit: String,
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
        // A short scalar is repeated (and recorded); a long result or an equation of motion
        // is found where it is boxed.
        let short = match (v, &q.kind) {
            (_, QuantityKind::Eom(_)) => None,
            (Value::Scalar(e), _) => {
                Some((e, super::expr(e))).filter(|(_, t)| super::width(t) <= longest)
            }
            _ => None,
        };
        let (value, w) = match short {
            Some((e, t)) => {
                inline.push(Inline {
                    what: format!("bilan {what}"),
                    latex: t.clone(),
                    value: Value::Scalar(e.clone()),
                });
                let w = super::width(&t);
                (format!("${t}$"), w)
            }
            // A key without questions shows every result once, above.
            None => match place.strip_prefix("la question ") {
                Some(n) => (format!("voir Q{n}"), 7),
                None => ("ci-dessus".to_string(), 9),
            },
        };
        let under = hyp.as_deref().map(escape_text);
        match merged
            .iter_mut()
            .find(|r| r.what == *what && r.value == value && r.unit == unit)
        {
            Some(r) => r.unders.push(under),
            None => merged.push(Entry {
                title: bilan_title(&doc.names, q),
                unders: vec![under],
                value,
                unit,
                width: w,
                what: what.clone(),
            }),
        }
    }
    (merged, inline)
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

impl Entry {
    /// The entry as a row, its hypotheses after the grandeur.
    fn row(self) -> Row {
        let under = match self.unders.as_slice() {
            [None] => String::new(),
            [Some(h)] => format!(" ({h})"),
            hs => {
                let names: Vec<String> = hs
                    .iter()
                    .map(|h| h.clone().unwrap_or_else(|| "général".to_string()))
                    .collect();
                format!(" ({})", names.join(" ; "))
            }
        };
        // The row's printed width: the grandeur, the résultat, the unit.
        let title_w = super::width(&self.title) + under.chars().count();
        let unit_w = super::width(&self.unit).min(12);
        Row {
            grandeur: format!("${}${under}", self.title),
            value: self.value,
            width: title_w + self.width + unit_w,
            unit: self.unit,
        }
    }
}

/// One table of the bilan.
fn table(rows: &[Row]) -> String {
    let body: Vec<String> = rows
        .iter()
        .map(|r| format!("{} & {} & {} \\\\", r.grandeur, r.value, r.unit))
        .collect();
    format!(
        "\\begin{{tabular}}[t]{{@{{}}lll@{{}}}}\n\\hline\nGrandeur & Résultat & Unité \\\\\n\\hline\n\\noalign{{\\vspace{{2pt}}}}\n{}\n\\hline\n\\end{{tabular}}",
        body.join("\n")
    )
}

/// The rows in one centred table, or in two or three tables side by side when the values
/// are short and the list long.
fn tables(rows: &[Row]) -> String {
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
            .map(|c| fit(table(c), "0.32"))
            .collect::<Vec<_>>()
            .join("\\hfill\n"),
        n if n > 6 && narrow => rows
            .chunks(n.div_ceil(2))
            .map(|c| fit(table(c), "0.49"))
            .collect::<Vec<_>>()
            .join("\\hfill\n"),
        _ => format!("\\centering\n{}", table(rows)),
    }
}
