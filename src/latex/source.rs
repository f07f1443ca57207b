//! What exerts an action, as its torsor prints it: {𝒯(poussée → 1)} in the course's words,
//! and the index that tells two links between the same solids apart, {𝒯_A(0 → 1)}.

use super::{action_side, name};
use crate::mechanism::Mark;

/// The LaTeX (math) of what exerts an action, from its source as the spec gives it: a solid
/// number as is, letters and digits upright (`\mathrm{moteur}`; one letter italic, `F`), a
/// formula alone as the formula (`$C_r$` → `C_r`), any other text upright in the text
/// font, accents and spaces kept (`\textnormal{poussée}`), escaped as a free text is (a
/// text with `\overrightarrow`, which would nest too deep under the arrow of R(…), as plain
/// text).
///
/// ```
/// use torseur::latex::action_source;
/// assert_eq!(action_source("0"), "0");
/// assert_eq!(action_source("moteur"), "\\mathrm{moteur}");
/// assert_eq!(action_source("poussée"), "\\textnormal{poussée}");
/// assert_eq!(action_source("moteur 1"), "\\textnormal{moteur 1}");
/// assert_eq!(action_source("$C_r$"), "C_r");
/// assert_eq!(action_source("50% {x}"), "\\textnormal{50\\% \\{x\\}}");
/// ```
pub fn action_source(text: &str) -> String {
    let t = text.trim();
    if !t.is_empty() && t.chars().all(|c| c.is_ascii_alphanumeric()) {
        return action_side(t);
    }
    // Under the arrow of R(source → 1) an arrow of its own would nest too deep: such a text
    // (which validation refuses) prints escaped.
    let rich = match super::rich_text(t) {
        Ok(r) if !r.contains("\\overrightarrow") => r,
        _ => super::escape_text(t),
    };
    // One formula and nothing else: the formula itself, already in math.
    let alone = (rich.strip_prefix('$').and_then(|r| r.strip_suffix('$')))
        .filter(|f| !f.trim().is_empty() && !f.contains('$'));
    match alone {
        Some(f) => f.to_string(),
        None => format!("\\textnormal{{{rich}}}"),
    }
}

/// The index of a link's torsor among those joining the same solids: its point (`A`,
/// `O_{1}`), or its name (`01`, `\mathrm{pal}`).
fn mark(m: &Mark) -> String {
    match m {
        Mark::Point(p) => super::point(p),
        Mark::Link(n) if n.chars().all(|c| c.is_ascii_digit()) => n.clone(),
        Mark::Link(n) => name(n),
    }
}

/// `\mathcal{T}` with a link's index when it has one: `\mathcal{T}_{A}`.
pub(crate) fn torsor_letter(m: Option<&Mark>) -> String {
    match m {
        Some(m) => format!("\\mathcal{{T}}_{{{}}}", mark(m)),
        None => "\\mathcal{T}".to_string(),
    }
}
