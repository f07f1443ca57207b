//! Reading what the user typed: the expression syntax with quantities in the course's
//! notation and unknowns of the PFD inside it.

use super::*;
use crate::expr::Registry;

/// Reads what the user typed: quantities written in the course's notation inside it are
/// replaced by their derived values, unknowns of the PFD by their solved values, everything
/// under the hypothesis.
pub(super) struct Reader<'a> {
    pub(super) m: &'a Mechanism,
    pub(super) hypothesis: Option<&'a Hypothesis>,
    pub(super) solution: Option<Solution>,
    /// Quantities met, with their value (under the hypothesis).
    pub(super) quantities: Vec<(Quantity, Expr)>,
    /// Quantities and unknowns replaced, in the order met.
    pub(super) substituted: Vec<String>,
    /// Bare names met (outside quantities), for `-q Q` with Q an unknown.
    pub(super) names: Vec<String>,
    /// Unknowns kept as they are (an action of the bilan is compared as declared, its links'
    /// unknowns unsolved).
    pub(super) keep_unknowns: bool,
}

/// The functions of the expression syntax; any other `name(` starts a quantity.
const SYNTAX_FUNCTIONS: &[&str] = &["sin", "cos", "sqrt", "dot", "ddot"];

impl<'a> Reader<'a> {
    pub(super) fn new(m: &'a Mechanism, hypothesis: Option<&'a Hypothesis>) -> Reader<'a> {
        Reader {
            m,
            hypothesis,
            solution: None,
            quantities: Vec::new(),
            substituted: Vec::new(),
            names: Vec::new(),
            keep_unknowns: false,
        }
    }

    pub(super) fn under(&self, e: Expr) -> Expr {
        match self.hypothesis {
            Some(h) => h.apply(&e),
            None => e,
        }
    }

    pub(super) fn solution(&mut self) -> Result<&Solution, VerifyError> {
        if self.solution.is_none() {
            self.solution = Some(crate::pfd::solve(self.m)?);
        }
        Ok(self.solution.as_ref().expect("solved"))
    }

    pub(super) fn note(&mut self, what: String) {
        if !self.substituted.contains(&what) {
            self.substituted.push(what);
        }
    }

    /// One scalar text, which may divide by a nonzero polynomial in the parameters: quantities
    /// replaced by placeholder names, unknown names refused (all named at once), parsed; the
    /// numerator with the unknowns replaced by their solved values, both under the hypothesis.
    pub(super) fn read_fraction(&mut self, text: &str) -> Result<(Expr, Expr), VerifyError> {
        let (out, placeholders) = self.prepare(text, &|_| false)?;
        let lookup = |n: &str| placeholder(&placeholders, n);
        let (n, d) = self
            .m
            .reg
            .parse_fraction_with(&out, &lookup)
            .map_err(|err| users_text(err, text, &placeholders))?;
        if !d.is_one() && self.hypothesis.is_some_and(|h| !h.first_order.is_empty()) {
            return Err(VerifyError::Shape(format!(
                "`{text}` divides by `{d}`: a fraction is not compared at first order in small \
                 parameters (multiply it out)"
            )));
        }
        let d = self.under(d);
        if d.is_zero() {
            return Err(VerifyError::Shape(format!(
                "`{text}`: its denominator is zero under the hypothesis"
            )));
        }
        let (n, solved) = self.finish(n, text)?;
        Ok((n, &d * &solved))
    }

    /// lhs − rhs over a common denominator: (numerator, denominator).
    pub(super) fn read_difference(
        &mut self,
        l: &str,
        r: &str,
    ) -> Result<(Expr, Expr), VerifyError> {
        let (n1, d1) = self.read_fraction(l)?;
        let (n2, d2) = self.read_fraction(r)?;
        if d1 == d2 {
            return Ok((&n1 - &n2, d1));
        }
        Ok((&(&n1 * &d2) - &(&n2 * &d1), &d1 * &d2))
    }

    /// A vector typed over any bases (`a*x1 + b*y2 - c*z0`, quantities and unknowns inside
    /// its coefficients), its components in basis `b`.
    pub(super) fn read_vector(
        &mut self,
        text: &str,
        b: crate::frame::FrameId,
    ) -> Result<[Expr; 3], VerifyError> {
        let m = self.m;
        let bv = |s: &str| m.frames.basis_vector(s).map(|(f, a)| (f, a.index()));
        let (out, placeholders) = self.prepare(text, &|n| bv(n).is_some())?;
        let lookup = |n: &str| placeholder(&placeholders, n);
        let parts = self
            .m
            .reg
            .parse_vector_with(&out, &bv, &lookup)
            .map_err(|err| users_text(err, text, &placeholders))?;
        let mut v = crate::vector::Vector::zero();
        for (f, c) in parts {
            let mut done = Vec::with_capacity(3);
            for e in c {
                let (n, d) = self.finish(e, text)?;
                if !d.is_one() {
                    return Err(VerifyError::Shape(format!(
                        "`{text}`: an unknown inside it is a quotient ({d} below the line): \
                         write the components one by one"
                    )));
                }
                done.push(n);
            }
            let c: [Expr; 3] = done.try_into().expect("three components");
            v.add_part(f, c);
        }
        // The change of basis holds the angles too: under the hypothesis as well.
        Ok(v.express_in(&m.frames, b).map(|e| self.under(e)))
    }

    /// The text with every quantity replaced by a placeholder name, and the placeholders'
    /// values; names that are neither the spec's nor `allowed` are refused, all at once.
    fn prepare(
        &mut self,
        text: &str,
        allowed: &dyn Fn(&str) -> bool,
    ) -> Result<(String, Vec<Placeholder>), VerifyError> {
        let reg = self.m.reg.clone();
        // The time is known where the spec writes it: a phase Ω t then exists.
        let timed = reg.coordinates().iter().any(|c| c.phase().is_some());
        let known = |n: &str| {
            reg.param(n).is_some()
                || reg.alias(n).is_some()
                || reg.coord(n).is_some()
                || n == "pi"
                || (n == "t" && timed)
                || allowed(n)
        };
        let prefix = placeholder_prefix(&reg, text);
        let b = text.as_bytes();
        let mut out = String::with_capacity(text.len());
        let mut placeholders: Vec<Placeholder> = Vec::new();
        let mut unknown: Vec<String> = Vec::new();
        let mut i = 0;
        while i < b.len() {
            let c = b[i];
            if c.is_ascii_digit() {
                // A number, and a name glued to it (the parser refuses `2x`).
                while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'.')
                {
                    out.push(b[i] as char);
                    i += 1;
                }
                continue;
            }
            if !(c.is_ascii_alphabetic() || c == b'_') {
                // Only ASCII is allowed; the parser names any other character.
                let ch = text[i..].chars().next().unwrap_or(' ');
                out.push(ch);
                i += ch.len_utf8();
                continue;
            }
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            let word = &text[start..i];
            let mut j = i;
            while j < b.len() && b[j].is_ascii_whitespace() {
                j += 1;
            }
            // d/dt(Q), d/dt(Q)|R.x0: the time derivative of a quantity.
            if let Some(end) = derivative_end(text, start, i)? {
                let notation = &text[start..end];
                let q = Quantity::parse(notation)?;
                let value = self.quantity_value(&q, notation)?;
                let name = format!("{prefix}{}", placeholders.len());
                out.push_str(&name);
                placeholders.push(Placeholder::new(name, notation, value));
                i = end;
                continue;
            }
            let call = j < b.len() && b[j] == b'(';
            if call && matches!(word, "dot" | "ddot") {
                rate_of_a_coordinate(text, start, j)?;
            }
            if !call || SYNTAX_FUNCTIONS.contains(&word) {
                if !call && !known(word) && !unknown.iter().any(|u| u == word) {
                    unknown.push(word.to_string());
                }
                if !call && !self.names.iter().any(|n| n == word) {
                    self.names.push(word.to_string());
                }
                out.push_str(word);
                continue;
            }
            let end = quantity_end(text, j)?;
            let notation = &text[start..end];
            let q = Quantity::parse(notation)?;
            let value = self.quantity_value(&q, notation)?;
            let name = format!("{prefix}{}", placeholders.len());
            out.push_str(&name);
            placeholders.push(Placeholder::new(name, notation, value));
            i = end;
        }
        if !unknown.is_empty() {
            let hint = names_hint(&reg, &unknown);
            return Err(VerifyError::UnknownNames {
                names: unknown,
                input: text.to_string(),
                hint,
            });
        }
        Ok((out, placeholders))
    }

    /// A value read from `text`: the unknowns of the PFD replaced by their solved values,
    /// under the hypothesis; as n / d, d ≠ 1 when a solved value is a quotient (Y_B = −D ω²/L).
    fn finish(&mut self, mut e: Expr, text: &str) -> Result<(Expr, Expr), VerifyError> {
        let reg = self.m.reg.clone();
        let mut den = reg.one();
        // Unknowns of the PFD: their solved values.
        for v in reg.var_ids() {
            if self.keep_unknowns {
                break;
            }
            let VarRole::Parameter(k) = reg.role(v) else {
                continue;
            };
            if !reg.is_unknown(k) || !e.contains_var(v) {
                continue;
            }
            let name = reg.scalar_name(k).to_string();
            let value = self
                .solution()?
                .unknowns
                .get(&name)
                .cloned()
                .ok_or_else(|| {
                    VerifyError::Shape(format!(
                        "`{name}` in `{text}`: no equation of the spec's pfd determines it"
                    ))
                })?;
            if value.is_whole() {
                e = e.substitute(v, &value.num);
            } else {
                // e = c x + rest with x = n / d: (c n + d rest) / d.
                let c = e.derivative(v);
                let rest = &e - &(&c * &reg.variable(v));
                e = &(&c * &value.num) + &(&rest * &value.den);
                den = &den * &value.den;
            }
            self.note(name);
        }
        Ok((self.under(e), self.under(den)))
    }

    /// The derived value of a scalar quantity written inside an expression.
    pub(super) fn quantity_value(
        &mut self,
        q: &Quantity,
        notation: &str,
    ) -> Result<Expr, VerifyError> {
        if let Some((_, v)) = self.quantities.iter().find(|(x, _)| x == q) {
            return Ok(v.clone());
        }
        let value = derive_values(self.m, std::slice::from_ref(q))?
            .pop()
            .map(|d| d.value)
            .ok_or_else(|| VerifyError::Shape("nothing derived".into()))?;
        let Value::Scalar(e) = value else {
            return Err(VerifyError::Shape(format!(
                "`{notation}` is not a scalar: inside an expression, write a projection \
                 (`.x2`), an unknown, an energy or an equation of motion"
            )));
        };
        let e = self.under(e);
        self.quantities.push((q.clone(), e.clone()));
        self.note(q.to_string());
        Ok(e)
    }
}

/// A quantity of the user's text replaced by a name for the parser: the name, the notation
/// typed, its value.
struct Placeholder {
    name: String,
    notation: String,
    value: Expr,
}

impl Placeholder {
    fn new(name: String, notation: &str, value: Expr) -> Placeholder {
        Placeholder {
            name,
            notation: notation.to_string(),
            value,
        }
    }
}

/// The value a placeholder name stands for.
fn placeholder(placeholders: &[Placeholder], n: &str) -> Option<Expr> {
    placeholders
        .iter()
        .find(|p| p.name == n)
        .map(|p| p.value.clone())
}

/// `dot(Q)` or `ddot(Q)` (the word from byte `start`, its parenthesis at byte `open`) whose
/// argument is a quantity, not a coordinate: refused with the notation of a quantity's
/// derivative, before the parser would name the placeholder that stands for Q.
fn rate_of_a_coordinate(text: &str, start: usize, open: usize) -> Result<(), VerifyError> {
    let mut depth = 0usize;
    let Some(close) = text[open..].char_indices().find_map(|(k, c)| {
        match c {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + k);
                }
            }
            _ => {}
        }
        None
    }) else {
        // Unbalanced: the parser says so.
        return Ok(());
    };
    let inner = text[open + 1..close].trim();
    if !inner.contains('(') {
        return Ok(());
    }
    let word = &text[start..open].trim_end();
    let what = match *word {
        "dot" => "the rate of a coordinate",
        _ => "the second derivative of a coordinate",
    };
    let vector = !inner.starts_with("Ec(") && !inner.contains(").");
    let written = if vector {
        format!("d/dt({inner})|0 for its derivative in R0 (the frame after the bar)")
    } else {
        format!("d/dt({inner})")
    };
    let once = if *word == "dot" {
        ""
    } else {
        ", a first derivative only"
    };
    Err(VerifyError::Shape(format!(
        "`{}`: {word}(q) is {what}; the time derivative of a quantity is written \
         {written}{once}",
        &text[start..=close]
    )))
}

/// A parse error about the user's text, not the one with placeholders: each placeholder
/// named in the reason is written back as the notation it stands for.
fn users_text(err: ExprError, text: &str, placeholders: &[Placeholder]) -> ExprError {
    let back = |mut reason: String| {
        // The longest names first (qty10 before qty1).
        for p in placeholders.iter().rev() {
            reason = reason.replace(&p.name, &p.notation);
        }
        reason
    };
    match err {
        ExprError::Parse { reason, .. } => ExprError::Parse {
            input: text.to_string(),
            reason: back(reason),
        },
        ExprError::Unsupported { reason, .. } => ExprError::Unsupported {
            input: text.to_string(),
            reason: back(reason),
        },
        other => other,
    }
}

/// Splits `[a, b, c]` (possibly nested) at its top-level commas.
pub(super) fn split_list(s: &str) -> Option<Vec<String>> {
    let t = s.trim();
    let inner = t.strip_prefix('[')?.strip_suffix(']')?;
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut cur = String::new();
    for c in inner.chars() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            _ => {}
        }
        if c == ',' && depth == 0 {
            out.push(std::mem::take(&mut cur));
        } else {
            cur.push(c);
        }
    }
    out.push(cur);
    Some(out)
}

/// A prefix for placeholder names that neither the text nor any name of the spec holds.
fn placeholder_prefix(reg: &Registry, text: &str) -> String {
    let mut prefix = String::from("qty");
    while text.contains(&prefix)
        || reg
            .parameters()
            .iter()
            .chain(reg.unknowns())
            .any(|n| n.starts_with(&prefix))
        || reg
            .coordinates()
            .iter()
            .any(|c| c.name.starts_with(&prefix))
    {
        prefix.push('_');
    }
    prefix
}

/// The end of a derivative `d/dt(Q)`, `d/dt(Q)|R` or `d/dt(Q)|R.x2` whose word `d` spans
/// `start..word_end` of `text`; none when the word does not start one.
fn derivative_end(text: &str, start: usize, word_end: usize) -> Result<Option<usize>, VerifyError> {
    let rest = &text[word_end..];
    let trimmed = rest.trim_start();
    if &text[start..word_end] != "d" || !trimmed.starts_with('/') {
        return Ok(None);
    }
    let after_bar = trimmed[1..].trim_start();
    let Some(dt) = after_bar.strip_prefix("dt") else {
        return Ok(None);
    };
    let paren = dt.trim_start();
    if !paren.starts_with('(') {
        return Ok(None);
    }
    let open = text.len() - paren.len();
    let mut end = quantity_end(text, open)?;
    let b = text.as_bytes();
    if b.get(end) == Some(&b'|') {
        end += 1;
        while end < b.len() && (b[end].is_ascii_alphanumeric() || b[end] == b'_') {
            end += 1;
        }
        // A projection `.x2` after the frame.
        if b.get(end) == Some(&b'.')
            && b.get(end + 1)
                .is_some_and(|a| matches!(a, b'x' | b'y' | b'z'))
            && b.get(end + 2)
                .is_some_and(|a| a.is_ascii_alphanumeric() || *a == b'_')
        {
            end += 2;
            while end < b.len() && (b[end].is_ascii_alphanumeric() || b[end] == b'_') {
                end += 1;
            }
        }
    }
    Ok(Some(end))
}

/// The end of a quantity `name(...)` whose opening parenthesis is at byte `open` of `text`,
/// after an optional projection `.x2`.
fn quantity_end(text: &str, open: usize) -> Result<usize, VerifyError> {
    let b = text.as_bytes();
    let mut depth = 0usize;
    let mut end = open;
    while end < b.len() {
        match b[end] {
            b'(' => depth += 1,
            b')' => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            _ => {}
        }
        end += 1;
    }
    if end >= b.len() {
        return Err(ExprError::Parse {
            input: text.to_string(),
            reason: "unbalanced parentheses".to_string(),
        }
        .into());
    }
    end += 1;
    if end + 2 < b.len() + 1
        && b.get(end) == Some(&b'.')
        && b.get(end + 1)
            .is_some_and(|a| matches!(a, b'x' | b'y' | b'z'))
        && b.get(end + 2)
            .is_some_and(|a| a.is_ascii_alphanumeric() || *a == b'_')
    {
        end += 2;
        while end < b.len() && (b[end].is_ascii_alphanumeric() || b[end] == b'_') {
            end += 1;
        }
    }
    Ok(end)
}

/// ` (did you mean `theta` for `thta`?)`: for each of the `unknown` names, the parameter,
/// coordinate, alias or PFD unknown of `reg` it most likely misspells; empty when none is
/// close.
fn names_hint(reg: &std::rc::Rc<Registry>, unknown: &[String]) -> String {
    let aliases: Vec<&str> = reg.aliases().map(|(a, _)| a).collect();
    let declared: Vec<&str> = (reg.parameters().iter().map(String::as_str))
        .chain(reg.coordinates().iter().map(|c| c.name.as_str()))
        .chain(aliases)
        .collect();
    let guesses: Vec<String> = (unknown.iter())
        .filter_map(|u| crate::hint::closest(u, &declared).map(|d| (u, d)))
        .map(|(u, d)| match unknown.len() {
            1 => format!("`{d}`"),
            _ => format!("`{d}` for `{u}`"),
        })
        .collect();
    match guesses.is_empty() {
        true => String::new(),
        false => format!(" (did you mean {}?)", guesses.join(", ")),
    }
}
