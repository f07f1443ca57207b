//! The checks an expression's text passes before symbolica reads it (its characters, its
//! functions, its number literals and powers, bounded), decimal literals turned into exact
//! fractions, and symbolica's warnings caught while it reads, to be said in torseur's words; then symbolica's reading of the checked text into its tree.

use super::ExprError;
use symbolica::atom::Atom;

/// Longest expression text accepted (see [`super::MAX_INPUT_LEN`]).
pub(super) const MAX_INPUT: usize = super::MAX_INPUT_LEN;
pub(super) const MAX_POWER: i64 = 255;

/// Most digits a number literal may have (integer and decimal digits together): symbolica
/// reads a literal in a time quadratic in its length (10⁶ digits took minutes), and no
/// expression of a spec, a typed result or a values file needs more than a few dozen.
pub(super) const MAX_NUMBER_DIGITS: usize = 100;

/// Only these characters can appear in an expression of the spec syntax.
pub(super) fn validate_chars(s: &str) -> Result<(), String> {
    validate_chars_with(s, FUNCTIONS)
}

/// [`validate_chars`] with another list of functions (those of a number in a values file).
pub(super) fn validate_chars_with(s: &str, functions: &[&str]) -> Result<(), String> {
    if s.len() > MAX_INPUT {
        return Err(format!(
            "{} characters, longer than the {MAX_INPUT} a typed expression may have",
            s.len()
        ));
    }
    if s.trim().is_empty() {
        return Err("empty expression".to_string());
    }
    if let Some(fix) = primed(s) {
        return Err(fix);
    }
    for c in s.chars() {
        if !(c.is_ascii_alphanumeric() || " \t\n+-*/^()._,[]".contains(c)) {
            let hint = super::words::char_hint(c);
            return Err(format!("character `{c}` is not allowed{hint}"));
        }
    }
    let mut depth: i32 = 0;
    for c in s.chars() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            _ => {}
        }
        if depth < 0 {
            return Err("unbalanced parentheses".to_string());
        }
        if depth > 64 {
            return Err("parentheses nested deeper than 64".to_string());
        }
    }
    if depth != 0 {
        return Err("unbalanced parentheses".to_string());
    }
    // Only the syntax's functions may be called, never with empty arguments: the text must
    // not reach symbolica's own function evaluation (cot(), exp(...)).
    for (start, end, called) in names_in(s) {
        let word = &s[start..end];
        if called && !functions.contains(&word) {
            return Err(format!(
                "`{word}(...)`: {}the functions are {}",
                function_hint(word),
                listed(functions)
            ));
        }
    }
    if s.split_whitespace().collect::<String>().contains("()") {
        return Err("empty parentheses".to_string());
    }
    validate_powers(s)
}

/// Each number literal has at most [`MAX_NUMBER_DIGITS`] digits. A number starts with a digit
/// or a `.` before a digit that does not continue a name (`theta12` is a name).
pub(super) fn validate_numbers(s: &str) -> Result<(), String> {
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let starts = (b[i].is_ascii_digit()
            || (b[i] == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit)))
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
        if !starts {
            // Skip a whole name, digits included.
            if b[i].is_ascii_alphabetic() || b[i] == b'_' {
                while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
            } else {
                i += 1;
            }
            continue;
        }
        let mut digits = 0usize;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
            digits += usize::from(b[i] != b'.');
            i += 1;
        }
        if digits > MAX_NUMBER_DIGITS {
            return Err(format!(
                "a number of {digits} digits: a number has at most {MAX_NUMBER_DIGITS}"
            ));
        }
    }
    Ok(())
}

/// Exponents are integer literals, nested powers multiply to at most [`MAX_POWER`], and
/// `a^b^c` is refused: symbolica would otherwise compute `4444^444442` before any check of ours.
fn validate_powers(s: &str) -> Result<(), String> {
    let b = s.as_bytes();
    let skip = |mut i: usize| {
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        i
    };
    // The exponent starting after the `^` at `i`: its value and the index after it.
    let exponent = |i: usize| -> Result<(u64, usize), String> {
        let mut j = skip(i + 1);
        let paren = j < b.len() && b[j] == b'(';
        if paren {
            j = skip(j + 1);
        }
        if j < b.len() && (b[j] == b'-' || b[j] == b'+') {
            j = skip(j + 1);
        }
        let start = j;
        while j < b.len() && b[j].is_ascii_digit() {
            j += 1;
        }
        if j == start || (j < b.len() && b[j] == b'.') {
            return Err("an exponent must be an integer literal".to_string());
        }
        let digits = &s[start..j];
        let value = if digits.len() > 4 {
            u64::MAX
        } else {
            digits.parse::<u64>().unwrap_or(u64::MAX)
        };
        if paren {
            j = skip(j);
            if j >= b.len() || b[j] != b')' {
                return Err("an exponent must be an integer literal".to_string());
            }
            j += 1;
        }
        let after = skip(j);
        if after < b.len() && b[after] == b'^' {
            return Err("`a^b^c` is ambiguous: write (a^b)^c".to_string());
        }
        Ok((value, j))
    };
    let too_high = || format!("powers are limited to ±{MAX_POWER}, nested powers included");
    // For each open group, the largest product of exponents inside it.
    let mut stack: Vec<u64> = vec![1];
    let mut i = 0;
    while i < b.len() {
        match b[i] {
            b'(' | b'[' => {
                stack.push(1);
                i += 1;
            }
            b')' | b']' => {
                let inner = stack.pop().unwrap_or(1);
                let k = skip(i + 1);
                let (power, next) = if k < b.len() && b[k] == b'^' {
                    exponent(k)?
                } else {
                    (1, i + 1)
                };
                let total = inner.saturating_mul(power);
                if total > MAX_POWER as u64 {
                    return Err(too_high());
                }
                if let Some(top) = stack.last_mut() {
                    *top = (*top).max(total);
                }
                i = next;
            }
            b'^' => {
                let (power, next) = exponent(i)?;
                if power > MAX_POWER as u64 {
                    return Err(too_high());
                }
                if let Some(top) = stack.last_mut() {
                    *top = (*top).max(power);
                }
                i = next;
            }
            _ => i += 1,
        }
    }
    Ok(())
}

pub(super) const FUNCTIONS: &[&str] = &["sin", "cos", "dot", "ddot", "sqrt"];

/// « sin, cos, dot and ddot ».
fn listed(names: &[&str]) -> String {
    match names.split_last() {
        Some((last, [])) => last.to_string(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
        None => String::new(),
    }
}

/// Whether a warning of symbolica's says that a value is undefined (an infinity made by a
/// division by zero, an indeterminate 0/0).
pub(super) fn undefined(warning: &str) -> bool {
    let w = warning.to_ascii_lowercase();
    [
        "infinity",
        "indeterminate",
        "division by zero",
        "divide by zero",
        "undefined",
    ]
    .iter()
    .any(|k| w.contains(k))
}

/// Runs `f` with symbolica's log events (`tracing`, WARN and ERROR) caught instead of printed:
/// it prints them with colours and timestamps on the terminal otherwise. Returns `f`'s value
/// and the messages, in order. Scoped to this thread and this call; symbolica runs on one
/// thread (see [`super::guard`]).
pub(super) fn caught<T>(f: impl FnOnce() -> T) -> (T, Vec<String>) {
    let catcher = Catcher::default();
    let messages = catcher.messages.clone();
    let value = tracing::subscriber::with_default(catcher, f);
    let messages = std::mem::take(&mut *messages.lock().unwrap_or_else(|p| p.into_inner()));
    (value, messages)
}

/// A `tracing` subscriber that keeps the messages of WARN and ERROR events and drops the rest.
#[derive(Default)]
struct Catcher {
    messages: std::sync::Arc<std::sync::Mutex<Vec<String>>>,
}

impl tracing::Subscriber for Catcher {
    fn enabled(&self, metadata: &tracing::Metadata<'_>) -> bool {
        metadata.is_event() && *metadata.level() <= tracing::Level::WARN
    }

    fn new_span(&self, _: &tracing::span::Attributes<'_>) -> tracing::span::Id {
        tracing::span::Id::from_u64(1)
    }

    fn record(&self, _: &tracing::span::Id, _: &tracing::span::Record<'_>) {}

    fn record_follows_from(&self, _: &tracing::span::Id, _: &tracing::span::Id) {}

    fn event(&self, event: &tracing::Event<'_>) {
        struct Message(String);
        impl tracing::field::Visit for Message {
            fn record_debug(&mut self, field: &tracing::field::Field, value: &dyn std::fmt::Debug) {
                if field.name() == "message" {
                    self.0 = format!("{value:?}");
                }
            }
        }
        let mut m = Message(String::new());
        event.record(&mut m);
        self.messages
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .push(m.0);
    }

    fn enter(&self, _: &tracing::span::Id) {}

    fn exit(&self, _: &tracing::span::Id) {}
}

/// Decimal literals as exact fractions (`0.25` → `(25/100)`), so symbolica never reads a
/// float (a float zero divisor made its parser panic), then refuses a literal zero divisor.
pub(super) fn exact_decimals(s: &str) -> Result<String, String> {
    let b = s.as_bytes();
    let mut out = String::with_capacity(s.len() + 8);
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let starts_number = (c.is_ascii_digit()
            || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit)))
            && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'));
        if !starts_number {
            if c == b'.' {
                return Err("a `.` outside a number".to_string());
            }
            out.push(c as char);
            i += 1;
            continue;
        }
        let start = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        let int = &s[start..i];
        if i < b.len() && b[i] == b'.' {
            i += 1;
            let fs = i;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
            let frac = &s[fs..i];
            if frac.len() > 64 {
                return Err("more than 64 decimals".to_string());
            }
            let digits = format!("{int}{frac}");
            let digits = digits.trim_start_matches('0');
            let digits = if digits.is_empty() { "0" } else { digits };
            out.push_str(&format!("({digits}/1{})", "0".repeat(frac.len())));
        } else {
            out.push_str(int);
        }
        // `2x` or `1e5`: symbolica would read a float in scientific notation.
        if i < b.len() && (b[i].is_ascii_alphabetic() || b[i] == b'_') {
            return Err(format!(
                "`{}` is a number followed by a name: write the product with `*`",
                &s[start..(i + 1).min(s.len())]
            ));
        }
    }
    // A literal zero divisor: `/0`, `/ 0.0`, `/(0)`.
    let compact: String = out.chars().filter(|c| !c.is_whitespace()).collect();
    let cb = compact.as_bytes();
    for (k, _) in compact.match_indices('/') {
        let mut j = k + 1;
        while j < cb.len() && cb[j] == b'(' {
            j += 1;
        }
        let n = cb[j..].iter().take_while(|d| d.is_ascii_digit()).count();
        if n > 0 && cb[j..j + n].iter().all(|&d| d == b'0') {
            return Err("division by zero".to_string());
        }
    }
    Ok(out)
}

/// A name followed by primes, `psi'` or `psi''` (also with ’ or ′), as the first one in `s`:
/// the rate to write instead, `dot(psi)` or `ddot(psi)`.
///
/// ```text
/// psi' + 1   →  `psi'`: a time derivative is written dot(psi)
/// ```
fn primed(s: &str) -> Option<String> {
    let is_prime = |c: char| matches!(c, '\'' | '’' | '′');
    let chars: Vec<(usize, char)> = s.char_indices().collect();
    let k = chars.iter().position(|&(_, c)| is_prime(c))?;
    let end = chars[k].0;
    // After the last character that is not part of a name (it may be several bytes long).
    let start = s[..end]
        .char_indices()
        .rfind(|&(_, c)| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |(i, c)| i + c.len_utf8());
    let name = &s[start..end];
    if name.is_empty() || !name.starts_with(|c: char| c.is_ascii_alphabetic()) {
        return None;
    }
    let primes = chars[k..].iter().take_while(|&&(_, c)| is_prime(c)).count();
    let rate = match primes {
        1 => format!("dot({name})"),
        2 => format!("ddot({name})"),
        _ => return None,
    };
    let typed: String = chars[k..k + primes].iter().map(|&(_, c)| c).collect();
    Some(format!(
        "`{name}{typed}`: a time derivative is written {rate}"
    ))
}

/// What to write instead of a function the syntax does not have, when there is an answer:
/// a time derivative is `dot(q)`, a square root or a tangent is not part of the syntax.
pub(crate) fn function_hint(word: &str) -> &'static str {
    match word {
        "diff" | "d" | "D" | "derivative" | "Derivative" | "deriv" => {
            "a time derivative is written dot(q) or ddot(q) for a coordinate q; "
        }
        "Sqrt" | "exp" | "log" | "ln" | "tan" | "atan" | "asin" | "acos" => {
            "a result of the spec syntax is a polynomial in parameters, coordinates, their rates, \
             and sin and cos of angles; "
        }
        _ => "",
    }
}

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

pub(super) fn parse_atom(s: &str) -> Result<Atom, ExprError> {
    validate_chars(s).map_err(|reason| ExprError::Parse {
        input: s.to_string(),
        reason,
    })?;
    parse_checked(s)
}

/// symbolica's parse of a text whose characters and functions are checked.
pub(super) fn parse_checked(s: &str) -> Result<Atom, ExprError> {
    // Every text symbolica reads passes here (lexical scans included): the bound on number
    // literals is checked first.
    let exact = validate_numbers(s)
        .and_then(|()| exact_decimals(s))
        .map_err(|reason| ExprError::Parse {
            input: s.to_string(),
            reason,
        })?;
    // symbolica's message draws a caret under the text on further lines: its first line
    // says what and where, which is what an error message of ours quotes.
    let (parsed, warnings) = caught(|| symbolica::try_parse!(&exact));
    let atom = parsed.map_err(|e| ExprError::Parse {
        input: s.to_string(),
        reason: e
            .to_string()
            .lines()
            .next()
            .unwrap_or_default()
            .trim_start_matches("Error at line 1, ")
            .to_string(),
    })?;
    // symbolica simplifies as it reads: `a/(b - b)` becomes 0^-1, which it reports as a
    // warning and turns into an infinity. Refused here, in our words.
    if warnings.iter().any(|w| undefined(w)) {
        return Err(ExprError::Unsupported {
            input: s.to_string(),
            reason: "division by zero: a divisor is equal to 0".to_string(),
        });
    }
    Ok(atom)
}
