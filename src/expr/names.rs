//! Lexical scans of an expression's names, before (or without) parsing it.

use super::parse::FUNCTIONS;

/// The names an expression writes as themselves, outside the arguments of sin, cos, dot and
/// ddot (`R*theta*x1 + L*sin(theta)*y1` gives `R`, `theta`, `x1`, `L`, `y1`), in order, each
/// once. A lexical scan: the text need not be valid.
///
/// ```
/// assert_eq!(
///     torseur::expr::bare_names("R*theta*x1 + L*sin(2*theta)*y1 - dot(q)*z0"),
///     ["R", "theta", "x1", "L", "y1", "z0"]
/// );
/// ```
pub fn bare_names(s: &str) -> Vec<String> {
    let b = s.as_bytes();
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c.is_ascii_digit() {
            // A number, and a name glued to it (`2x` is refused by the parser anyway).
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'.') {
                i += 1;
            }
            continue;
        }
        if !(c.is_ascii_alphabetic() || c == b'_') {
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
            i += 1;
        }
        let word = &s[start..i];
        let mut j = i;
        while j < b.len() && b[j].is_ascii_whitespace() {
            j += 1;
        }
        if FUNCTIONS.contains(&word) && j < b.len() && (b[j] == b'(' || b[j] == b'[') {
            // Skip the whole argument.
            let mut depth = 0usize;
            while j < b.len() {
                match b[j] {
                    b'(' | b'[' => depth += 1,
                    b')' | b']' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    _ => {}
                }
                j += 1;
            }
            i = j + 1;
            continue;
        }
        if !out.iter().any(|w| w == word) {
            out.push(word.to_string());
        }
    }
    out
}

/// The functions of the expression syntax.
/// Each name of `s` as (start, end, called), called when `(` or `[` follows it at once.
pub(super) fn names_in(s: &str) -> Vec<(usize, usize, bool)> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_alphabetic() || b[i] == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push((start, i, i < b.len() && (b[i] == b'(' || b[i] == b'[')));
        } else {
            i += 1;
        }
    }
    out
}
