//! Lexical scans of an expression's names, before (or without) parsing it.

use super::lexical::{FUNCTIONS, parse_atom};

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

/// The names written below a division line in `s` (`l0 - m*g*sin(beta)/k` gives `k`;
/// `V/(2*R*r)` gives `R`, `r`), in order, each once: the parameters a registry's
/// [`super::RegistryBuilder::inverses`] declares for a spec. A text that does not parse has
/// none (its error comes when it is read).
///
/// ```
/// assert_eq!(torseur::expr::divisors_in("l0 - m*g*sin(beta)/k + V/(2*R*r)"), ["k", "R", "r"]);
/// assert_eq!(torseur::expr::divisors_in("p*dot(theta)/(2*pi)"), ["pi"]);
/// assert!(torseur::expr::divisors_in("m*L^2/12").is_empty());
/// ```
pub fn divisors_in(s: &str) -> Vec<String> {
    use symbolica::atom::AtomView;
    fn names(v: AtomView, out: &mut Vec<String>) {
        match v {
            AtomView::Var(x) => {
                // π, as typed (symbolica reads `pi` as its own constant).
                let n = super::words::typed_name(x.get_symbol());
                if !out.contains(&n) {
                    out.push(n);
                }
            }
            AtomView::Mul(m) => m.iter().for_each(|f| names(f, out)),
            AtomView::Add(a) => a.iter().for_each(|f| names(f, out)),
            AtomView::Pow(p) => names(p.get_base_exp().0, out),
            // The argument of sin or cos is an angle: never a divisor of the text.
            _ => {}
        }
    }
    fn walk(v: AtomView, out: &mut Vec<String>) {
        match v {
            AtomView::Pow(p) => {
                let (base, exp) = p.get_base_exp();
                if negative_number(exp) {
                    names(base, out);
                } else {
                    walk(base, out);
                }
            }
            AtomView::Mul(m) => m.iter().for_each(|f| walk(f, out)),
            AtomView::Add(a) => a.iter().for_each(|f| walk(f, out)),
            AtomView::Fun(f) => f.iter().for_each(|a| walk(a, out)),
            _ => {}
        }
    }
    let mut out = Vec::new();
    if (s.contains('/') || s.contains('^'))
        && let Ok(a) = parse_atom(s)
    {
        walk(a.as_view(), &mut out);
    }
    out
}

/// Whether an exponent is a negative number (a division: `k^-1`, `1/(m*l)`).
pub(super) fn negative_number(exp: symbolica::atom::AtomView) -> bool {
    use symbolica::atom::{AtomCore, AtomView};
    matches!(exp, AtomView::Num(_))
        && exp
            .try_to_polynomial::<_, u8>(&symbolica::domains::rational::Q, None)
            .is_ok_and(|e| e.is_constant() && e.get_constant().is_negative())
}
