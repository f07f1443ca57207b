//! Outputs: plain text and JSON of derived quantities, numeric evaluation, atomic files.

mod display;
mod eval;
mod structured;

pub use crate::atomic::{
    OutputError, Sink, Target, distinct, forget_pending, register_pending, remove_pending, target,
    write_atomic, write_outputs,
};
pub use display::Shown;
pub use eval::{
    Values, ValuesError, eval_json, eval_value, numeric_point, numeric_point_for, solve_unknowns,
    try_eval_value,
};
pub use structured::{structured_json, structured_text};

use crate::derivation::{Derivation, Value};
use crate::expr::{Expr, Fraction};
use crate::mechanism::Mechanism;
use serde_json::{Value as Json, json};

/// Presentation text of one expression.
pub fn present(e: &Expr) -> String {
    e.presentation().to_string()
}

fn triple(c: &[Expr; 3], f: &impl Fn(&Expr) -> String) -> Vec<String> {
    c.iter().map(f).collect()
}

/// Which written form the text output uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TextForm {
    /// The presentation form: as a teacher writes it (sin² θ, cos(θ2 − θ1), m2 (L1 + L2 cos θ2)²).
    #[default]
    Presentation,
    /// The canonical polynomial, expanded (for tools that compare texts).
    Canonical,
}

/// A value as one line of text, in the form asked.
///
/// ```
/// use torseur::output::{TextForm, value_text_in};
/// let m = torseur::spec::load(concat!(env!("CARGO_MANIFEST_DIR"),
///     "/derivations/double_pendule.json")).unwrap();
/// let q = torseur::quantity::Quantity::parse("V(G2,2/0).x2").unwrap();
/// let d = torseur::derivation::derive_values(&m, &[q]).unwrap();
/// assert_eq!(value_text_in(&m, &d[0].value, TextForm::Presentation),
///     "L1*dot(theta1)*cos(theta2 - theta1) + 1/2*L2*dot(theta2)");
/// assert_eq!(value_text_in(&m, &d[0].value, TextForm::Canonical),
///     "L1*cos(theta1)*cos(theta2)*dot(theta1) + L1*sin(theta1)*sin(theta2)*dot(theta1) + 1/2*L2*dot(theta2)");
/// ```
pub fn value_text_in(m: &Mechanism, v: &Value, form: TextForm) -> String {
    let present = |e: &Expr| match form {
        TextForm::Presentation => present(e),
        TextForm::Canonical => e.to_string(),
    };
    let f = |e: &Expr| present(e);
    match v {
        Value::Scalar(e) => present(e),
        Value::Quotient(q) => quotient_text(q, f),
        Value::Vector { basis, components } => {
            format!(
                "[{}] in B{}",
                triple(components, &f).join(", "),
                m.frame_name(*basis)
            )
        }
        Value::Matrix(i) => {
            let rows: Vec<String> = i
                .matrix
                .iter()
                .map(|r| format!("[{}]", triple(r, &f).join(", ")))
                .collect();
            format!(
                "[{}] at {} in B{}",
                rows.join(", "),
                m.point_name(i.point),
                m.frame_name(i.basis)
            )
        }
        Value::Torsor {
            point,
            basis,
            resultant,
            moment,
        } => format!(
            "{{ R = [{}], M({}) = [{}] }} in B{}",
            triple(resultant, &f).join(", "),
            m.point_name(*point),
            triple(moment, &f).join(", "),
            m.frame_name(*basis)
        ),
    }
}

/// The text report of `torseur derive`: each quantity, then its forms under each hypothesis.
pub fn derive_text(m: &Mechanism, ds: &[Derivation]) -> String {
    derive_text_in(m, ds, TextForm::Presentation)
}

/// [`derive_text`] in the form asked.
pub fn derive_text_in(m: &Mechanism, ds: &[Derivation], form: TextForm) -> String {
    let mut out = String::new();
    for d in ds {
        out.push_str(&format!(
            "{} = {}\n",
            d.quantity,
            value_text_in(m, &d.value, form)
        ));
        for h in &m.hypotheses {
            out.push_str(&format!(
                "  under {}: {}\n",
                h.name,
                value_text_in(m, &d.value_under(m, h), form)
            ));
        }
    }
    out
}

/// `num/den` as text that reads back: each side in parentheses unless it is one term (the
/// numerator) or one name (the denominator).
fn quotient_text(q: &Fraction, f: impl Fn(&Expr) -> String) -> String {
    let (minus, num) = if q.reads_negative() {
        ("-", -&q.num)
    } else {
        ("", q.num.clone())
    };
    let n = f(&num);
    let d = f(&q.den);
    let n = if num.nterms() == 1 {
        n
    } else {
        format!("({n})")
    };
    let d = if d.chars().all(|c| c.is_alphanumeric() || c == '_') {
        d
    } else {
        format!("({d})")
    };
    format!("{minus}{n}/{d}")
}

/// A value as JSON: canonical and presentation strings.
pub fn value_json(m: &Mechanism, v: &Value) -> Json {
    let canon = |c: &[Expr; 3]| -> Vec<String> { c.iter().map(|e| e.to_string()).collect() };
    let pres = |c: &[Expr; 3]| -> Vec<String> { c.iter().map(present).collect() };
    match v {
        Value::Scalar(e) => {
            json!({"kind": "scalar", "canonical": e.to_string(), "presentation": present(e), "terms": e.nterms()})
        }
        Value::Quotient(q) => json!({
            "kind": "scalar",
            "canonical": quotient_text(q, |e| e.to_string()),
            "presentation": quotient_text(q, present),
            "numerator": q.num.to_string(), "denominator": q.den.to_string(),
            "terms": v.nterms()}),
        Value::Vector { basis, components } => json!({
            "kind": "vector", "basis": format!("B{}", m.frame_name(*basis)),
            "canonical": canon(components), "presentation": pres(components), "terms": v.nterms()}),
        Value::Matrix(i) => json!({
            "kind": "matrix", "point": m.point_name(i.point), "basis": format!("B{}", m.frame_name(i.basis)),
            "canonical": i.matrix.iter().map(canon).collect::<Vec<_>>(),
            "presentation": i.matrix.iter().map(pres).collect::<Vec<_>>(), "terms": v.nterms()}),
        Value::Torsor {
            point,
            basis,
            resultant,
            moment,
        } => json!({
            "kind": "torsor", "point": m.point_name(*point), "basis": format!("B{}", m.frame_name(*basis)),
            "resultant": {"canonical": canon(resultant), "presentation": pres(resultant)},
            "moment": {"canonical": canon(moment), "presentation": pres(moment)}, "terms": v.nterms()}),
    }
}

/// The manifest of an answer key (`answer-key --manifest`): every displayed formula, what it
/// shows, under which hypothesis, its LaTeX exactly as printed and the engine's value, so that
/// a reader of the LaTeX can prove each line equal to the engine's result; then the formulas
/// of the text that carry a value (positions, in the ground basis; masses).
pub fn manifest_json(m: &Mechanism, key: &crate::latex::AnswerKey) -> Json {
    use crate::latex::DisplayRole;
    let displays: Vec<Json> = key
        .displays
        .iter()
        .map(|d| {
            let role = match d.role {
                DisplayRole::Inertia => "inertia",
                DisplayRole::Step => "step",
                DisplayRole::Result => "result",
                DisplayRole::Equation => "equation",
            };
            let mut j = json!({"role": role, "what": d.what, "hypothesis": d.hypothesis,
                   "latex": d.latex, "value": value_json(m, &d.value)});
            if let Some(r) = &d.rhs {
                j["rhs"] = value_json(m, r);
            }
            if let Some(s) = &d.solid {
                // Whose mass and centre the left side prints (a complementary term).
                j["solid"] = json!(s);
            }
            j
        })
        .collect();
    let inline: Vec<Json> = key
        .inline
        .iter()
        .map(|f| json!({"what": f.what, "latex": f.latex, "value": value_json(m, &f.value)}))
        .collect();
    json!({"title": m.title, "displays": displays, "inline": inline})
}

/// The JSON report of `torseur derive --json`.
pub fn derive_json(m: &Mechanism, ds: &[Derivation]) -> Json {
    let qs: Vec<Json> = ds
        .iter()
        .map(|d| {
            let mut o = json!({"id": d.quantity.to_string(), "value": value_json(m, &d.value)});
            let hs: serde_json::Map<String, Json> = m
                .hypotheses
                .iter()
                .map(|h| (h.name.clone(), value_json(m, &d.value_under(m, h))))
                .collect();
            if !hs.is_empty() {
                o["hypotheses"] = Json::Object(hs);
            }
            o["steps"] = Json::Array(
                d.steps
                    .iter()
                    .map(|s| json!({"label": s.label, "theorem": s.theorem, "value": value_json(m, &s.value)}))
                    .collect(),
            );
            o
        })
        .collect();
    json!({"title": m.title, "quantities": qs})
}
