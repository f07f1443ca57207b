//! What exerts a given action, as its torsor prints it ({T(poussée → 1)}): the spec's
//! `source`, else a word its label gives, else its name; two actions never print the same.

use super::SpecFile;

/// The articles a label may open with (« le moteur », « l'excitateur »).
const ARTICLES: &[&str] = &["le ", "la ", "les ", "l'", "l’", "un ", "une "];

/// The most characters a source may hold: it prints inside {T(… → 1)}, in a formula.
pub const MAX_SOURCE_CHARS: usize = 40;

/// What a label says exerts the action, when it says it in one word: the label without its
/// article when one word is left (« le moteur » → moteur, « l'excitateur » → excitateur),
/// else its word that is the action's name once accents and case are set aside (`resistant`
/// and « le couple résistant » → résistant). None when neither holds (`denture` and
/// « l'engrènement en $I$ »).
///
/// ```
/// use torseur::wire::source::from_label;
/// assert_eq!(from_label("poussee", "la poussée").as_deref(), Some("poussée"));
/// assert_eq!(from_label("exc", "L'excitateur").as_deref(), Some("excitateur"));
/// assert_eq!(from_label("resistant", "le couple résistant").as_deref(), Some("résistant"));
/// assert_eq!(from_label("moteur1", "le moteur $M_1$"), None);
/// ```
pub fn from_label(name: &str, label: &str) -> Option<String> {
    let l = label.trim();
    let rest = ARTICLES
        .iter()
        .find_map(|a| strip_article(l, a))
        .unwrap_or(l)
        .trim();
    if is_word(rest) {
        return Some(rest.to_string());
    }
    let key = fold(name);
    l.split(|c: char| c.is_whitespace() || c == '\'' || c == '’')
        .map(|w| w.trim_end_matches(|c: char| ",.;:!?)»".contains(c)))
        .find(|w| is_word(w) && fold(w) == key)
        .map(str::to_string)
}

/// `l` without the article `a` it opens with, whatever its case (« Le moteur »).
fn strip_article<'a>(l: &'a str, a: &str) -> Option<&'a str> {
    let head = l.get(..a.len())?;
    (head.to_lowercase() == a).then(|| &l[a.len()..])
}

/// One word: letters (accented or Greek), digits and hyphens, at least one letter.
fn is_word(w: &str) -> bool {
    w.chars()
        .all(|c| c.is_alphabetic() || c.is_ascii_digit() || c == '-')
        && w.chars().any(char::is_alphabetic)
}

/// A word with its case, its French accents and everything but letters and digits set
/// aside: `résistant` and `resistant` are both `resistant`.
fn fold(w: &str) -> String {
    let mut out = String::new();
    for c in w.chars().flat_map(char::to_lowercase) {
        match c {
            'à' | 'â' | 'ä' => out.push('a'),
            'é' | 'è' | 'ê' | 'ë' => out.push('e'),
            'î' | 'ï' => out.push('i'),
            'ô' | 'ö' => out.push('o'),
            'ù' | 'û' | 'ü' => out.push('u'),
            'ÿ' => out.push('y'),
            'ç' => out.push('c'),
            'œ' => out.push_str("oe"),
            'æ' => out.push_str("ae"),
            c if c.is_alphanumeric() => out.push(c),
            _ => {}
        }
    }
    out
}

/// Whether `s` already prints as the source of another torsor: a solid's or the ground's
/// name ({T(0 → 1)}), or gravity's `pes`.
pub(crate) fn taken(spec: &SpecFile, s: &str) -> bool {
    s == "pes" || s == spec.ground || spec.solids.iter().any(|b| b.name == s)
}

/// The source each given action prints, in the spec's order ([`super::ActionSpec::source`]):
/// one read from a label that another action, a solid or gravity already prints is left for
/// the action's name, so that two torsors never print the same source. (Sources the spec
/// gives are checked when it is validated.)
///
/// ```
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json").unwrap();
/// assert_eq!(torseur::wire::action_sources(m.spec()), ["poussée"]);
/// ```
pub fn action_sources(spec: &SpecFile) -> Vec<String> {
    let read: Vec<String> = spec.actions.iter().map(super::ActionSpec::source).collect();
    let clash = |i: usize| {
        taken(spec, &read[i]) || (read.iter().enumerate()).any(|(j, o)| j != i && *o == read[i])
    };
    (spec.actions.iter().enumerate())
        .map(|(i, a)| match a.source.is_none() && clash(i) {
            true => a.name.clone(),
            false => read[i].clone(),
        })
        .collect()
}
