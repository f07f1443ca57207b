//! The free text at fault when pdflatex rejects an answer key: every free text of a validated
//! spec should compile, and if one still does not, the message names it by its JSON path.

use super::text::lowercase_text;
use crate::mechanism::Mechanism;

/// How many lines above the reported one a free text is looked for: TeX reports some errors
/// (a runaway argument, a paragraph ended too soon) a few lines after the text at fault.
const LOOK_BACK: usize = 20;

/// The JSON path (`questions[2].statement`) of the spec's free text whose LaTeX stands on the
/// 1-based line `line` of the answer key `tex`, or else on the nearest line above it (up to
/// 20 lines above); `None` if no free text stands there. Where several do, the longest wins
/// (a statement before a label it quotes). Meant for the line pdflatex reports (`l.123`)
/// when it rejects the key of a validated spec.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let tex = torseur::latex::answer_key(&m, &torseur::simulate::question_runs(&m)).unwrap();
/// // The line of question 3's statement, and the line after it.
/// let line = 1 + tex.lines().position(|l| l.contains("Déterminer le torseur dynamique de $S_1$")).unwrap();
/// assert_eq!(
///     torseur::latex::text_at_fault(&m, &tex, line).as_deref(),
///     Some("questions[2].statement")
/// );
/// assert_eq!(
///     torseur::latex::text_at_fault(&m, &tex, line + 1).as_deref(),
///     Some("questions[2].statement")
/// );
/// // The preamble holds no free text.
/// assert_eq!(torseur::latex::text_at_fault(&m, &tex, 1), None);
/// ```
pub fn text_at_fault(m: &Mechanism, tex: &str, line: usize) -> Option<String> {
    // Each free text as the key prints it (a question's title also lowercased, as a sentence
    // cites it), lowercased again: a label may start a sentence with a capital.
    let mut printed: Vec<(String, String)> = Vec::new();
    for (path, text) in &m.statement.free_texts {
        let mut forms = vec![super::rich_text_or_escaped(text)];
        if path.ends_with(".title") {
            forms.push(super::rich_text_or_escaped(&lowercase_text(text)));
        }
        for f in forms {
            let f = f.trim().to_lowercase();
            if !f.is_empty() {
                printed.push((path.clone(), f));
            }
        }
    }
    let lines: Vec<&str> = tex.lines().collect();
    let last = line.checked_sub(1).filter(|&k| k < lines.len())?;
    (last.saturating_sub(LOOK_BACK)..=last).rev().find_map(|k| {
        let l = lines[k].to_lowercase();
        printed
            .iter()
            .filter(|(_, f)| l.contains(f.as_str()))
            .max_by_key(|(_, f)| f.len())
            .map(|(p, _)| p.clone())
    })
}
