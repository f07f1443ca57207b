//! User expressions (`m2*L2^2*cos(theta2)*dot(theta1)^2`, `sin(2*theta1)`) into canonical form.
//!
//! symbolica parses the text; the tree is then walked into the polynomial of the registry.
//! sin and cos of a sum or of a multiple angle expand first (angle-addition formulas), so
//! `sin(2*theta)` and `2*sin(theta)*cos(theta)` have the same canonical form.

use super::{CoordId, Expr, ExprError, LinearAngle, Registry};
use std::rc::Rc;
use symbolica::atom::{Atom, AtomCore, AtomView, Symbol};
use symbolica::domains::rational::{Q, Rational, RationalField};
use symbolica::poly::polynomial::MultivariatePolynomial;

/// Longest expression text accepted (see [`super::MAX_INPUT_LEN`]).
const MAX_INPUT: usize = super::MAX_INPUT_LEN;
const MAX_POWER: i64 = 255;

/// Only these characters can appear in an expression of the spec syntax.
fn check_chars(s: &str) -> Result<(), String> {
    if s.len() > MAX_INPUT {
        return Err(format!(
            "{} characters, longer than the {MAX_INPUT} a typed expression may have",
            s.len()
        ));
    }
    if s.trim().is_empty() {
        return Err("empty expression".to_string());
    }
    for c in s.chars() {
        if !(c.is_ascii_alphanumeric() || " \t\n+-*/^()._,[]".contains(c)) {
            return Err(format!("character `{c}` is not allowed"));
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
    let b = s.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_alphabetic() || b[i] == b'_' {
            let start = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            let word = &s[start..i];
            if i < b.len() && (b[i] == b'(' || b[i] == b'[') && !FUNCTIONS.contains(&word) {
                return Err(format!(
                    "`{word}(...)`: the functions are sin, cos, dot and ddot"
                ));
            }
        } else {
            i += 1;
        }
    }
    if s.split_whitespace().collect::<String>().contains("()") {
        return Err("empty parentheses".to_string());
    }
    check_powers(s)
}

/// Exponents are integer literals, nested powers multiply to at most [`MAX_POWER`], and
/// `a^b^c` is refused: symbolica would otherwise compute `4444^444442` before any check of ours.
fn check_powers(s: &str) -> Result<(), String> {
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
const FUNCTIONS: &[&str] = &["sin", "cos", "dot", "ddot"];

fn parse_atom(s: &str) -> Result<Atom, ExprError> {
    check_chars(s).map_err(|reason| ExprError::Parse {
        input: s.to_string(),
        reason,
    })?;
    let exact = exact_decimals(s).map_err(|reason| ExprError::Parse {
        input: s.to_string(),
        reason,
    })?;
    symbolica::try_parse!(&exact).map_err(|e| ExprError::Parse {
        input: s.to_string(),
        reason: e.to_string(),
    })
}

/// Decimal literals as exact fractions (`0.25` → `(25/100)`), so symbolica never reads a
/// float (a float zero divisor made its parser panic), then refuses a literal zero divisor.
fn exact_decimals(s: &str) -> Result<String, String> {
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

pub(super) fn parse_scalar(reg: &Rc<Registry>, s: &str) -> Result<Expr, ExprError> {
    parse_scalar_with(reg, s, &|_| None)
}

/// [`parse_scalar`], where `names` gives the value of names the registry does not know.
pub(super) fn parse_scalar_with(
    reg: &Rc<Registry>,
    s: &str,
    names: &dyn Fn(&str) -> Option<Expr>,
) -> Result<Expr, ExprError> {
    let a = parse_atom(s)?;
    Walker {
        reg,
        input: s,
        names,
    }
    .scalar(a.as_view())
}

pub(super) fn parse_vector<K: Ord + Copy>(
    reg: &Rc<Registry>,
    s: &str,
    basis_vector: &dyn Fn(&str) -> Option<(K, usize)>,
    names: &dyn Fn(&str) -> Option<Expr>,
) -> Result<Vec<(K, [Expr; 3])>, ExprError> {
    let a = parse_atom(s)?;
    let w = Walker {
        reg,
        input: s,
        names,
    };
    let expanded = a.expand();
    let mut out: Vec<(K, [Expr; 3])> = Vec::new();
    let mut add = |k: K, axis: usize, e: Expr| {
        if let Some(slot) = out.iter_mut().find(|(kk, _)| *kk == k) {
            slot.1[axis] = &slot.1[axis] + &e;
        } else {
            let z = reg.zero();
            let mut c = [z.clone(), z.clone(), z];
            c[axis] = e;
            out.push((k, c));
        }
    };
    let view = expanded.as_view();
    if let AtomView::Num(n) = view
        && n.is_zero()
    {
        return Ok(out);
    }
    let terms: Vec<AtomView> = match view {
        AtomView::Add(a) => a.iter().collect(),
        other => vec![other],
    };
    for term in terms {
        let factors: Vec<AtomView> = match term {
            AtomView::Mul(m) => m.iter().collect(),
            other => vec![other],
        };
        let mut found: Option<(K, usize)> = None;
        let mut coef = reg.one();
        for f in factors {
            if let AtomView::Var(v) = f
                && let Some(bv) = basis_vector(v.get_symbol().get_stripped_name())
            {
                if found.is_some() {
                    return Err(w.unsupported("a term holds two basis vectors"));
                }
                found = Some(bv);
                continue;
            }
            if let AtomView::Pow(p) = f
                && let AtomView::Var(v) = p.get_base()
                && basis_vector(v.get_symbol().get_stripped_name()).is_some()
            {
                return Err(w.unsupported("a basis vector cannot be raised to a power"));
            }
            coef = &coef * &w.scalar(f)?;
        }
        match found {
            Some((k, axis)) => add(k, axis, coef),
            None => {
                return Err(w.unsupported(
                    "every term of a vector must hold one basis vector (x0, y1, z2, …)",
                ));
            }
        }
    }
    Ok(out)
}

struct Walker<'a> {
    reg: &'a Rc<Registry>,
    input: &'a str,
    /// Values of names the registry does not know (none but in [`parse_scalar_with`]).
    names: &'a dyn Fn(&str) -> Option<Expr>,
}

impl Walker<'_> {
    fn unsupported(&self, reason: &str) -> ExprError {
        ExprError::Unsupported {
            input: self.input.to_string(),
            reason: reason.to_string(),
        }
    }

    fn degree_too_high(&self) -> ExprError {
        self.unsupported(&format!(
            "the expanded expression would have a degree over {} in one variable",
            super::MAX_INPUT_DEGREE
        ))
    }

    fn number(&self, v: AtomView) -> Result<Rational, ExprError> {
        let p: MultivariatePolynomial<RationalField, u8> = v
            .try_to_polynomial(&Q, None)
            .map_err(|_| self.unsupported("only rational numbers are allowed"))?;
        if !p.is_constant() {
            return Err(self.unsupported("only rational numbers are allowed"));
        }
        Ok(p.get_constant())
    }

    fn scalar(&self, v: AtomView) -> Result<Expr, ExprError> {
        let reg = self.reg;
        match v {
            AtomView::Num(_) => Ok(reg.constant(self.number(v)?)),
            AtomView::Var(var) => {
                let name = var.get_symbol().get_stripped_name().to_string();
                if let Some(p) = reg.param(&name) {
                    return Ok(p);
                }
                if let Some(q) = reg.coord(&name) {
                    return reg.value(q).ok_or_else(|| {
                        self.unsupported(&format!(
                            "the angle `{name}` is written as itself in no expression of the \
                             spec, so no result holds it: here it enters only through \
                             sin({name}) and cos({name})"
                        ))
                    });
                }
                if let Some(e) = (self.names)(&name) {
                    return Ok(e);
                }
                Err(ExprError::UnknownName {
                    name,
                    input: self.input.to_string(),
                })
            }
            AtomView::Add(a) => {
                // Summed pairwise: adding n terms one by one to a growing sum is quadratic
                // (a chain's equation of motion holds 10^5 terms).
                let mut parts = Vec::new();
                for t in a.iter() {
                    parts.push(self.scalar(t)?);
                }
                while parts.len() > 1 {
                    let mut next = Vec::with_capacity(parts.len().div_ceil(2));
                    let mut it = parts.into_iter();
                    while let Some(x) = it.next() {
                        next.push(match it.next() {
                            Some(y) => x + &y,
                            None => x,
                        });
                    }
                    parts = next;
                }
                Ok(parts.pop().unwrap_or_else(|| reg.zero()))
            }
            AtomView::Mul(m) => {
                let mut acc = reg.one();
                for t in m.iter() {
                    let f = self.scalar(t)?;
                    if !acc.product_fits(&f, 1) {
                        return Err(self.degree_too_high());
                    }
                    acc = &acc * &f;
                }
                Ok(acc)
            }
            AtomView::Pow(p) => {
                let (base, exp) = p.get_base_exp();
                let e = self.number(exp)?;
                if !e.is_integer() {
                    return Err(self.unsupported("only integer powers are allowed"));
                }
                let n = e.to_f64() as i64;
                if n.abs() > MAX_POWER {
                    return Err(self.unsupported(&format!("powers are limited to ±{MAX_POWER}")));
                }
                if n >= 0 {
                    let b = self.scalar(base)?;
                    if !reg.zero().product_fits(&b, 0) || !b.product_fits(&reg.zero(), n as u32) {
                        return Err(self.degree_too_high());
                    }
                    return Ok(b.pow(n as u32));
                }
                // A negative power is allowed of a number only: the canonical form is a
                // polynomial.
                let b = self.scalar(base)?;
                match b.as_rational() {
                    Some(r) if !r.is_zero() => Ok(reg.constant(r.inv().pow((-n) as u64))),
                    Some(_) => Err(self.unsupported("division by zero")),
                    None => Err(self.unsupported(
                        "division by a parameter or a coordinate is not supported: the exact \
                         form is a polynomial (write 1/12*m*L^2, not m*L^2/(12*k))",
                    )),
                }
            }
            AtomView::Fun(f) => {
                let s = f.get_symbol();
                let name = s.get_stripped_name();
                if f.get_nargs() != 1 {
                    return Err(self.unsupported(&format!("`{name}` takes one argument")));
                }
                let arg = f.get(0);
                if s == Symbol::SIN || s == Symbol::COS {
                    let (c, sn) = self.trig(arg)?;
                    return Ok(if s == Symbol::SIN { sn } else { c });
                }
                let order = match name {
                    "dot" => 1,
                    "ddot" => 2,
                    _ => {
                        return Err(self.unsupported(&format!(
                            "unknown function `{name}` (known: sin, cos, dot, ddot)"
                        )));
                    }
                };
                let AtomView::Var(qv) = arg else {
                    return Err(self.unsupported(&format!("{name}() takes a coordinate name")));
                };
                let qsym = qv.get_symbol();
                let qn = qsym.get_stripped_name();
                let q = reg.coord(qn).ok_or_else(|| {
                    self.unsupported(&format!("{name}({qn}): `{qn}` is not a coordinate"))
                })?;
                Ok(reg.rate(q, order))
            }
        }
    }

    /// (cos a, sin a) of an angle a = Σ nᵢ qᵢ + k π/2, by the angle-addition formulas.
    fn trig(&self, arg: AtomView) -> Result<(Expr, Expr), ExprError> {
        let (terms, quarter_turns) = self.linear_angle(arg)?;
        Ok(cos_sin(self.reg, &terms, quarter_turns))
    }

    /// An angle as Σ nᵢ aᵢ (angle coordinates and constant angle parameters, integer nᵢ, like
    /// terms combined) and k π/2.
    fn linear_angle(&self, arg: AtomView) -> Result<(Vec<(CoordId, i64)>, i64), ExprError> {
        let expanded = arg.expand();
        let terms: Vec<AtomView> = match expanded.as_view() {
            AtomView::Add(a) => a.iter().collect(),
            AtomView::Num(n) if n.is_zero() => vec![],
            other => vec![other],
        };
        let mut out: Vec<(CoordId, i64)> = Vec::new();
        let mut pi_multiple = Rational::zero();
        for t in terms {
            let (coef, q) = self.angle_term(t)?;
            match q {
                AngleTerm::Pi => pi_multiple = &pi_multiple + &coef,
                AngleTerm::Coord(q) => {
                    if !coef.is_integer() {
                        return Err(self.unsupported(
                            "an angle takes integer multiples of the angle coordinates and \
                             angle parameters",
                        ));
                    }
                    let n = coef.to_f64() as i64;
                    if n.abs() > MAX_POWER {
                        return Err(self.unsupported("multiple angle too large"));
                    }
                    match out.iter_mut().find(|(x, _)| *x == q) {
                        Some(slot) => slot.1 += n,
                        None => out.push((q, n)),
                    }
                }
            }
        }
        out.retain(|(_, n)| *n != 0);
        if out.iter().any(|(_, n)| n.abs() > MAX_POWER) {
            return Err(self.unsupported("multiple angle too large"));
        }
        // Exact values for multiples of π/2 only.
        let twice = &pi_multiple * &Rational::new(2, 1);
        if !twice.is_integer() || twice.to_f64().abs() > 1e15 {
            return Err(self.unsupported(NOT_QUARTER_TURNS));
        }
        Ok((out, twice.to_f64() as i64))
    }

    fn angle_term(&self, t: AtomView) -> Result<(Rational, AngleTerm), ExprError> {
        let factors: Vec<AtomView> = match t {
            AtomView::Mul(m) => m.iter().collect(),
            other => vec![other],
        };
        let mut coef = Rational::one();
        let mut what: Option<AngleTerm> = None;
        for f in factors {
            match f {
                AtomView::Num(_) => coef = &coef * &self.number(f)?,
                AtomView::Var(v) => {
                    let sym = v.get_symbol();
                    let name = sym.get_stripped_name();
                    let this = if sym == Symbol::PI || name == "pi" {
                        AngleTerm::Pi
                    } else {
                        match self.reg.angle(name) {
                            Some(q) => AngleTerm::Coord(q),
                            None if self.reg.param(name).is_none()
                                && self.reg.coord(name).is_none() =>
                            {
                                return Err(ExprError::UnknownName {
                                    name: name.to_string(),
                                    input: self.input.to_string(),
                                });
                            }
                            None => {
                                return Err(self.unsupported(&format!(
                                    "`{name}` is not an angle: an angle is an angle coordinate \
                                     or a parameter declared with \"kind\": \"angle\""
                                )));
                            }
                        }
                    };
                    if what.is_some() {
                        return Err(self.unsupported("sin and cos take a linear angle"));
                    }
                    what = Some(this);
                }
                _ => return Err(self.unsupported("sin and cos take a linear angle")),
            }
        }
        match what {
            Some(w) => Ok((coef, w)),
            None => Err(self.unsupported(NOT_QUARTER_TURNS)),
        }
    }
}

/// Why a constant angle is refused.
const NOT_QUARTER_TURNS: &str = "a constant angle written with numbers must be a multiple of \
     pi/2 (the only ones whose cos and sin are exact rationals): declare any other constant \
     angle as a parameter with \"kind\": \"angle\"";

/// (cos a, sin a) of a = Σ nᵢ aᵢ + k π/2.
pub(super) fn cos_sin(
    reg: &Rc<Registry>,
    terms: &[(CoordId, i64)],
    quarter_turns: i64,
) -> (Expr, Expr) {
    let (mut c, mut s) = (reg.one(), reg.zero());
    for &(q, n) in terms {
        let (cn, sn) = multiple_angle(reg, q, n);
        let nc = &(&c * &cn) - &(&s * &sn);
        let ns = &(&s * &cn) + &(&c * &sn);
        c = nc;
        s = ns;
    }
    match quarter_turns.rem_euclid(4) {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    }
}

/// Reads an angle `Σ nᵢ aᵢ + k π/2` (see [`Registry::parse_angle`]).
pub(super) fn parse_angle(reg: &Rc<Registry>, s: &str) -> Result<LinearAngle, ExprError> {
    let a = parse_atom(s)?;
    let w = Walker {
        reg,
        input: s,
        names: &|_| None,
    };
    let (terms, quarter_turns) = w.linear_angle(a.as_view())?;
    let (cos, sin) = cos_sin(reg, &terms, quarter_turns);
    Ok(LinearAngle {
        terms,
        quarter_turns,
        cos,
        sin,
    })
}

enum AngleTerm {
    Pi,
    Coord(CoordId),
}

/// (cos nq, sin nq) by repeated angle addition (de Moivre), for any integer n.
fn multiple_angle(reg: &Rc<Registry>, q: CoordId, n: i64) -> (Expr, Expr) {
    let (c1, s1) = (reg.cos(q), reg.sin(q));
    let (mut c, mut s) = (reg.one(), reg.zero());
    for _ in 0..n.unsigned_abs() {
        let nc = &(&c * &c1) - &(&s * &s1);
        let ns = &(&s * &c1) + &(&c * &s1);
        c = nc;
        s = ns;
    }
    if n < 0 { (c, -s) } else { (c, s) }
}
