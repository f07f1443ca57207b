//! What is printed is the engine's value. Every displayed formula of every answer key is read
//! back from its LaTeX by a reader written here, which shares no code with the printer
//! (`src/latex`): it tokenises the math, turns it into the engine's plain syntax, and the
//! engine's parser decides exact equality with the value the line claims to show. The values
//! of the results are themselves re-derived by the fast route (`derive_values`), not taken
//! from the document.

use std::collections::HashMap;
use torseur::derivation::Value;
use torseur::expr::Expr;
use torseur::mechanism::Mechanism;

#[derive(Debug, Clone, PartialEq)]
pub(super) enum Tok {
    /// `\name`, or `\,` `\\` `\{` (one non-letter character).
    Cmd(String),
    Letter(char),
    Digit(char),
    Sym(char),
}

/// The notation macros of the answer key, as the reader understands them: name, number of
/// arguments, and what they stand for in the course's LaTeX (the definitions the document's
/// preamble block gives; a teacher may redefine them, the reader reads the defaults).
const MACROS: &[(&str, usize, &str)] = &[
    ("TVec", 1, "\\vec{#1}"),
    ("TVecLong", 1, "\\overrightarrow{#1}"),
    ("TMvt", 2, "#1/#2"),
    ("TTorseur", 2, "\\left\\{#1\\right\\}_{#2}"),
    (
        "TElements",
        3,
        "\\left\\{ \\begin{array}{c|c} #1 \\end{array} \\right\\}_{#2,\\,#3}",
    ),
    (
        "TDeriv",
        2,
        "\\left[\\frac{\\mathrm{d}}{\\mathrm{d}t}#2\\right]_{#1}",
    ),
];

/// A document's text with the notation macros replaced by what they stand for (see
/// [`MACROS`]): the course's LaTeX, for the tests that look for a formula in a key.
pub(super) fn course(tex: &str) -> String {
    let mut out = String::with_capacity(tex.len());
    let mut rest = tex;
    while let Some(at) = rest.find('\\') {
        out.push_str(&rest[..at]);
        let after = &rest[at + 1..];
        let len = after
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(after.len());
        // A macro named without its arguments (where the preamble defines it) stays.
        let called = after[len..].starts_with('{');
        let found = MACROS.iter().find(|m| called && m.0 == &after[..len]);
        let Some((_, n, body)) = found else {
            let take = if len == 0 {
                after.chars().next().map_or(0, char::len_utf8)
            } else {
                len
            };
            out.push('\\');
            out.push_str(&after[..take]);
            rest = &after[take..];
            continue;
        };
        let mut tail = &after[len..];
        let mut with = body.to_string();
        for k in 1..=*n {
            let inner = tail
                .strip_prefix('{')
                .expect("a macro's argument is a group");
            let mut depth = 0;
            let end = inner
                .char_indices()
                .find(|&(_, c)| {
                    depth += match c {
                        '{' => 1,
                        '}' => -1,
                        _ => 0,
                    };
                    depth < 0
                })
                .map(|(i, _)| i)
                .expect("the group closes");
            with = with.replace(&format!("#{k}"), &inner[..end]);
            tail = &inner[end + 1..];
        }
        out.push_str(&course(&with));
        rest = tail;
    }
    out.push_str(rest);
    out
}

/// The tokens of LaTeX math, the notation macros expanded (see [`MACROS`]).
pub(super) fn tokenize(s: &str) -> Vec<Tok> {
    expand(&lex(s))
}

/// One argument of a macro from `t[*i]`: a `{…}` group without its braces, or one token.
fn argument(t: &[Tok], i: &mut usize) -> Vec<Tok> {
    let Some(first) = t.get(*i) else {
        return Vec::new();
    };
    *i += 1;
    if *first != Tok::Sym('{') {
        return vec![first.clone()];
    }
    let mut depth = 0;
    let mut out = Vec::new();
    while let Some(x) = t.get(*i) {
        *i += 1;
        match x {
            Tok::Sym('{') => depth += 1,
            Tok::Sym('}') if depth == 0 => break,
            Tok::Sym('}') => depth -= 1,
            _ => {}
        }
        out.push(x.clone());
    }
    out
}

/// `t` with every notation macro replaced by what it stands for, its arguments in place of
/// `#1`, `#2`…, and expanded again (an argument may hold a macro).
fn expand(t: &[Tok]) -> Vec<Tok> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < t.len() {
        let found = match &t[i] {
            Tok::Cmd(c) => MACROS.iter().find(|(n, _, _)| n == c),
            _ => None,
        };
        i += 1;
        let Some((_, n, body)) = found else {
            out.push(t[i - 1].clone());
            continue;
        };
        let args: Vec<Vec<Tok>> = (0..*n).map(|_| argument(t, &mut i)).collect();
        let body = lex(body);
        let mut with = Vec::new();
        let mut k = 0;
        while k < body.len() {
            match (&body[k], body.get(k + 1)) {
                (Tok::Sym('#'), Some(Tok::Digit(d))) => {
                    let a = d.to_digit(10).unwrap_or(1) as usize;
                    with.extend(args[a - 1].iter().cloned());
                    k += 2;
                }
                (x, _) => {
                    with.push(x.clone());
                    k += 1;
                }
            }
        }
        out.extend(expand(&with));
    }
    out
}

/// The tokens of LaTeX math as written.
fn lex(s: &str) -> Vec<Tok> {
    let cs: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cs.len() {
        let c = cs[i];
        if c == '\\' {
            let mut j = i + 1;
            while j < cs.len() && cs[j].is_ascii_alphabetic() {
                j += 1;
            }
            if j == i + 1 {
                j = (i + 2).min(cs.len());
            }
            out.push(Tok::Cmd(cs[i + 1..j].iter().collect()));
            i = j;
            continue;
        }
        if c.is_whitespace() {
        } else if c.is_ascii_alphabetic() {
            out.push(Tok::Letter(c));
        } else if c.is_ascii_digit() {
            out.push(Tok::Digit(c));
        } else {
            out.push(Tok::Sym(c));
        }
        i += 1;
    }
    out
}

/// The identifier a Greek letter command stands for: `\varphi` is `phi`, as `\phi`.
fn greek(c: &str) -> Option<String> {
    let plain = c
        .strip_prefix("var")
        .filter(|p| ["phi", "epsilon"].contains(p));
    let c = plain.unwrap_or(c);
    GREEK.contains(&c).then(|| c.to_string())
}

fn is_cmd(t: Option<&Tok>, name: &str) -> bool {
    matches!(t, Some(Tok::Cmd(c)) if c == name)
}

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
];

/// Reads LaTeX math into the engine's syntax. Basis vectors are replaced by what `basis`
/// says (`1` for the one whose component is wanted, `0` for the others): the printed vector
/// is linear in its basis vectors.
struct Reader<'a> {
    t: &'a [Tok],
    i: usize,
    names: &'a HashMap<String, String>,
    basis: &'a dyn Fn(char, &str) -> &'static str,
    seen: Vec<(char, String)>,
    /// Basis vectors the spec names as its statement does, as printed (`u`, `i1`): (axis,
    /// frame), read off the spec's `ground_basis` and `frames[].basis`.
    vectors: &'a HashMap<String, (char, String)>,
}

impl Reader<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }

    fn next(&mut self) -> Result<Tok, String> {
        let t = self.t.get(self.i).cloned().ok_or("unexpected end")?;
        self.i += 1;
        Ok(t)
    }

    fn expect(&mut self, t: Tok) -> Result<(), String> {
        let got = self.next()?;
        if got == t {
            Ok(())
        } else {
            Err(format!(
                "expected {t:?}, found {got:?} at token {}",
                self.i - 1
            ))
        }
    }

    /// Spacing that means nothing (or an implicit product).
    fn skip_space(&mut self) {
        while let Some(Tok::Cmd(c)) = self.peek() {
            if [",", ";", "!", "quad", "qquad", " "].contains(&c.as_str()) {
                self.i += 1;
            } else {
                break;
            }
        }
    }

    /// The raw text of a `{…}` group of letters and digits (a subscript, a \mathrm name).
    fn raw_group(&mut self) -> Result<String, String> {
        let mut s = String::new();
        match self.next()? {
            Tok::Sym('{') => loop {
                match self.next()? {
                    Tok::Sym('}') => break,
                    Tok::Letter(c) | Tok::Digit(c) => s.push(c),
                    Tok::Cmd(c) if greek(&c).is_some() => {
                        s.push_str(&greek(&c).unwrap_or_default())
                    }
                    t => return Err(format!("unexpected {t:?} in a name")),
                }
            },
            Tok::Letter(c) | Tok::Digit(c) => s.push(c),
            t => return Err(format!("unexpected {t:?} after `_`")),
        }
        Ok(s)
    }

    /// A subscript, if one follows.
    fn subscript(&mut self) -> Result<String, String> {
        if self.peek() == Some(&Tok::Sym('_')) {
            self.i += 1;
            self.raw_group()
        } else {
            Ok(String::new())
        }
    }

    fn identifier(&self, written: &str) -> Result<String, String> {
        self.names
            .get(written)
            .cloned()
            .ok_or_else(|| format!("`{written}` names nothing of the spec"))
    }

    /// A name's head: a Latin letter, a Greek letter, or `\mathrm{…}`.
    fn head(&mut self) -> Result<String, String> {
        match self.next()? {
            Tok::Letter(c) => Ok(c.to_string()),
            Tok::Cmd(c) if greek(&c).is_some() => Ok(greek(&c).unwrap_or_default()),
            Tok::Cmd(c) if c == "mathrm" => self.raw_group(),
            t => Err(format!("expected a name, found {t:?}")),
        }
    }

    fn name(&mut self) -> Result<String, String> {
        let h = self.head()?;
        let s = self.subscript()?;
        self.identifier(&format!("{h}{s}"))
    }

    fn is_end(&self) -> bool {
        match self.peek() {
            None => true,
            Some(Tok::Sym(c)) => matches!(c, '}' | ')' | ']' | '&' | '+' | '-' | '='),
            Some(Tok::Cmd(c)) if c == "Big" => matches!(
                self.t.get(self.i + 1),
                Some(&Tok::Sym(')')) | Some(&Tok::Sym(']'))
            ),
            Some(Tok::Cmd(c)) => matches!(c.as_str(), "right" | "\\" | "end"),
            _ => false,
        }
    }

    /// sum := [±] product (± product)*
    fn sum(&mut self) -> Result<String, String> {
        let mut out = String::new();
        loop {
            self.skip_space();
            let sign = match self.peek() {
                Some(Tok::Sym('+')) => {
                    self.i += 1;
                    "+"
                }
                Some(Tok::Sym('-')) => {
                    self.i += 1;
                    "-"
                }
                _ if out.is_empty() => "+",
                _ => break,
            };
            self.skip_space();
            let p = self.product()?;
            out.push_str(&format!(" {sign} ({p})"));
        }
        if out.is_empty() {
            return Err(format!("empty sum at token {}", self.i));
        }
        Ok(format!("({out})"))
    }

    fn product(&mut self) -> Result<String, String> {
        let mut fs = Vec::new();
        loop {
            self.skip_space();
            if self.is_end() {
                break;
            }
            fs.push(self.power()?);
        }
        if fs.is_empty() {
            return Err(format!("empty product at token {}", self.i));
        }
        Ok(fs.join("*"))
    }

    fn exponent(&mut self) -> Result<Option<String>, String> {
        if self.peek() != Some(&Tok::Sym('^')) {
            return Ok(None);
        }
        self.i += 1;
        Ok(Some(self.raw_group()?))
    }

    fn power(&mut self) -> Result<String, String> {
        let base = self.primary()?;
        Ok(match self.exponent()? {
            Some(k) => format!("({base})^{k}"),
            None => base,
        })
    }

    /// A group closed by the given closing tokens.
    fn closed(&mut self, close: &[Tok]) -> Result<String, String> {
        let s = self.sum()?;
        for t in close {
            self.expect(t.clone())?;
        }
        Ok(s)
    }

    fn primary(&mut self) -> Result<String, String> {
        match self.peek().cloned().ok_or("unexpected end")? {
            Tok::Digit(_) => {
                let mut n = String::new();
                while let Some(Tok::Digit(d)) = self.peek() {
                    n.push(*d);
                    self.i += 1;
                }
                Ok(n)
            }
            Tok::Letter(_) => self.name(),
            Tok::Sym('(') => {
                self.i += 1;
                self.closed(&[Tok::Sym(')')])
            }
            Tok::Sym('{') => {
                self.i += 1;
                self.closed(&[Tok::Sym('}')])
            }
            Tok::Cmd(c) => {
                self.i += 1;
                match c.as_str() {
                    // ( … ) or [ … ], closed by the same size.
                    "left" | "Big" => {
                        let close = match self.next()? {
                            Tok::Sym('(') => ')',
                            Tok::Sym('[') => ']',
                            t => return Err(format!("\\{c} followed by {t:?}")),
                        };
                        let size = if c == "left" { "right" } else { "Big" };
                        self.closed(&[Tok::Cmd(size.into()), Tok::Sym(close)])
                    }
                    "frac" => {
                        self.expect(Tok::Sym('{'))?;
                        let n = self.closed(&[Tok::Sym('}')])?;
                        self.expect(Tok::Sym('{'))?;
                        let d = self.closed(&[Tok::Sym('}')])?;
                        Ok(format!("({n}/{d})"))
                    }
                    "sin" | "cos" => {
                        let k = self.exponent()?;
                        self.skip_space();
                        let arg = match self.peek() {
                            Some(Tok::Sym('(')) | Some(Tok::Sym('{')) => self.primary()?,
                            Some(Tok::Cmd(c)) if c == "left" => self.primary()?,
                            // \sin 2\theta_{2}: a multiple of an angle.
                            Some(Tok::Digit(_)) => {
                                let mut n = String::new();
                                while let Some(Tok::Digit(d)) = self.peek() {
                                    n.push(*d);
                                    self.i += 1;
                                }
                                format!("{n}*{}", self.name()?)
                            }
                            _ => self.name()?,
                        };
                        let f = format!("{c}({arg})");
                        Ok(match k {
                            Some(k) => format!("{f}^{k}"),
                            None => f,
                        })
                    }
                    "dot" | "ddot" | "dddot" => {
                        let h = match self.next()? {
                            Tok::Sym('{') => {
                                let h = self.head()?;
                                self.expect(Tok::Sym('}'))?;
                                h
                            }
                            t => return Err(format!("\\{c} of {t:?}")),
                        };
                        let s = self.subscript()?;
                        let q = self.identifier(&format!("{h}{s}"))?;
                        Ok(format!("{c}({q})"))
                    }
                    "vec" => {
                        let axis = self.raw_group()?;
                        if axis == "0" {
                            return Ok("0".into());
                        }
                        let sub = self.subscript()?;
                        let (a, f) = match self.vectors.get(&format!("{axis}{sub}")) {
                            Some((a, f)) => (*a, f.clone()),
                            None => (axis.chars().next().ok_or("empty \\vec")?, sub),
                        };
                        self.seen.push((a, f.clone()));
                        Ok((self.basis)(a, &f).to_string())
                    }
                    g if greek(g).is_some() => {
                        self.i -= 1;
                        self.name()
                    }
                    "mathrm" => {
                        self.i -= 1;
                        self.name()
                    }
                    other => Err(format!("unknown command \\{other}")),
                }
            }
            t => Err(format!("unexpected {t:?} at token {}", self.i)),
        }
    }
}

/// The equations of an `align*` body: (left side, right side) as tokens; `&\phantom{=}`
/// rows continue the previous right side. Rows inside environments are kept whole.
pub(super) fn equations(body: &str) -> Vec<(Vec<Tok>, Vec<Tok>)> {
    let toks = tokenize(body);
    let mut rows: Vec<Vec<Tok>> = vec![vec![]];
    let mut env = 0;
    for t in toks {
        match &t {
            Tok::Cmd(c) if c == "begin" => env += 1,
            Tok::Cmd(c) if c == "end" => env -= 1,
            Tok::Cmd(c) if c == "\\" && env == 0 => {
                rows.push(vec![]);
                continue;
            }
            _ => {}
        }
        rows.last_mut().unwrap().push(t);
    }
    let mut eqs: Vec<(Vec<Tok>, Vec<Tok>)> = Vec::new();
    // A wide left side on a row of its own (`&lhs`), continued by rows `&\quad …` (an
    // equation of motion's dynamic side), its `&= …` on the next row.
    let mut alone: Option<Vec<Tok>> = None;
    for r in rows {
        let more = [Tok::Sym('&'), Tok::Cmd("quad".into())];
        if let (Some(lhs), true) = (alone.as_mut(), r.starts_with(&more)) {
            lhs.extend_from_slice(&r[1..]);
            continue;
        }
        if let Some(lhs) = alone.take() {
            assert!(
                r.starts_with(&[Tok::Sym('&'), Tok::Sym('=')]),
                "a left side alone is followed by its `&=`: {r:?}"
            );
            eqs.push((lhs, r[2..].to_vec()));
            continue;
        }
        if r.first() == Some(&Tok::Sym('&')) && !r.contains(&Tok::Sym('=')) {
            alone = Some(r[1..].to_vec());
            continue;
        }
        let phantom = [
            Tok::Sym('&'),
            Tok::Cmd("phantom".into()),
            Tok::Sym('{'),
            Tok::Sym('='),
            Tok::Sym('}'),
        ];
        if r.starts_with(&phantom) {
            eqs.last_mut()
                .expect("a continuation row follows an equation")
                .1
                .extend_from_slice(&r[phantom.len()..]);
            continue;
        }
        let at = (0..r.len().saturating_sub(1))
            .find(|&k| r[k] == Tok::Sym('&') && r[k + 1] == Tok::Sym('='))
            .unwrap_or_else(|| panic!("a row without `&=`: {r:?}"));
        eqs.push((r[..at].to_vec(), r[at + 2..].to_vec()));
    }
    eqs
}

pub(super) struct Ctx<'a> {
    pub(super) m: &'a Mechanism,
    names: HashMap<String, String>,
    vectors: HashMap<String, (char, String)>,
}

impl Ctx<'_> {
    pub(super) fn new(m: &Mechanism) -> Ctx<'_> {
        let mut names = HashMap::new();
        let ids = m
            .reg()
            .parameters()
            .iter()
            .chain(m.reg().unknowns())
            .cloned()
            .chain(m.spec().aliases.iter().map(|a| a.name.clone()))
            .chain(m.reg().coordinates().iter().map(|c| match c.phase() {
                // A phase is printed Ω t: the time is then a name of its own.
                Some(_) => "t".to_string(),
                None => c.name.clone(),
            }))
            // \pi is the constant π, `pi` in the engine's syntax (no spec may take the name).
            .chain(std::iter::once("pi".to_string()));
        for n in ids {
            let written: String = n.chars().filter(|&c| c != '_').collect();
            if let Some(other) = names.insert(written.clone(), n.clone())
                && other != n
            {
                panic!("`{n}` and `{other}` print alike ({written})");
            }
        }
        let mut vectors = HashMap::new();
        let spec = &m.spec();
        let given = std::iter::once((&spec.ground, &spec.ground_basis))
            .chain(spec.frames.iter().map(|f| (&f.name, &f.basis)));
        for (frame, names) in given {
            for (k, n) in names.iter().flatten().enumerate() {
                let written: String = n.chars().filter(|&c| c != '_').collect();
                vectors.insert(written, (['x', 'y', 'z'][k], frame.clone()));
            }
        }
        Ctx { m, names, vectors }
    }

    /// A scalar read from tokens, with basis vectors set by `basis`.
    fn read(
        &self,
        t: &[Tok],
        basis: &dyn Fn(char, &str) -> &'static str,
    ) -> Result<(Expr, Vec<(char, String)>), String> {
        let mut r = Reader {
            t,
            i: 0,
            names: &self.names,
            basis,
            seen: vec![],
            vectors: &self.vectors,
        };
        let text = r.sum()?;
        if r.i != t.len() {
            return Err(format!("trailing {:?}", &t[r.i..]));
        }
        let e = self
            .m
            .reg()
            .parse(&text)
            .map_err(|e| format!("{text}: {e}"))?;
        Ok((e, r.seen))
    }

    /// A scalar that may be a quotient, as (numerator, denominator) read by the engine's
    /// fraction parser.
    fn quotient(&self, t: &[Tok]) -> Result<(Expr, Expr), String> {
        let mut r = Reader {
            t,
            i: 0,
            names: &self.names,
            basis: &|_, _| "0",
            seen: vec![],
            vectors: &self.vectors,
        };
        let text = r.sum()?;
        if r.i != t.len() || !r.seen.is_empty() {
            return Err(format!("not a scalar: {text}"));
        }
        self.m
            .reg()
            .parse_fraction_with(&text, &|_| None)
            .map_err(|e| format!("{text}: {e}"))
    }

    pub(super) fn scalar(&self, t: &[Tok]) -> Result<Expr, String> {
        let (e, seen) = self.read(t, &|_, _| "0")?;
        if !seen.is_empty() {
            return Err(format!("a scalar printed with basis vectors {seen:?}"));
        }
        Ok(e)
    }

    /// The components of a vector printed as a sum over the basis vectors of `frame`.
    fn vector(&self, t: &[Tok], frame: &str) -> Result<[Expr; 3], String> {
        let axes = ['x', 'y', 'z'];
        let mut out: Vec<Expr> = Vec::new();
        for &a in &axes {
            let f = frame.to_string();
            let pick = move |ax: char, fr: &str| if ax == a && fr == f { "1" } else { "0" };
            let (e, seen) = self.read(t, &pick)?;
            if let Some(bad) = seen.iter().find(|(_, fr)| fr != frame) {
                return Err(format!("basis vector {bad:?} outside the basis {frame}"));
            }
            out.push(e);
        }
        Ok([out[0].clone(), out[1].clone(), out[2].clone()])
    }
}

impl Ctx<'_> {
    /// A vector printed over the basis vectors of any frames, expressed in the ground basis.
    fn any_basis(&self, t: &[Tok]) -> Result<[Expr; 3], String> {
        let (_, seen) = self.read(t, &|_, _| "0")?;
        let mut v = torseur::vector::Vector::zero();
        let mut done: Vec<(char, String)> = Vec::new();
        for (a, f) in seen {
            if done.contains(&(a, f.clone())) {
                continue;
            }
            let g = f.clone();
            let pick = move |ax: char, fr: &str| if ax == a && fr == g { "1" } else { "0" };
            let (c, _) = self.read(t, &pick)?;
            let frame = self.m.frames().find(&f).ok_or(format!("no frame {f}"))?;
            let axis = match a {
                'x' => torseur::frame::Axis::X,
                'y' => torseur::frame::Axis::Y,
                _ => torseur::frame::Axis::Z,
            };
            v = v.add(&torseur::vector::Vector::along(frame, axis, c));
            done.push((a, f));
        }
        Ok(v.express_in(self.m.frames(), self.m.frames().ground()))
    }
}

/// Splits an environment's content (`\begin{env}{spec}? … \end{env}`) starting at `t[0]`
/// into rows of cells, and returns what follows it.
fn environment(t: &[Tok]) -> (Vec<Vec<Vec<Tok>>>, &[Tok]) {
    assert!(is_cmd(t.first(), "begin"), "expected \\begin: {t:?}");
    // Skip `{name}` and, for an array, its column spec.
    let mut i = 1;
    let mut groups = 0;
    while groups < 2 {
        if t[i] == Tok::Sym('}') {
            groups += 1;
            if !matches!(t.get(i + 1), Some(Tok::Sym('{'))) {
                break;
            }
        }
        i += 1;
    }
    i += 1;
    let mut rows = vec![vec![vec![]]];
    let mut depth = 0;
    while !(depth == 0 && is_cmd(t.get(i), "end")) {
        match &t[i] {
            Tok::Cmd(c) if c == "begin" => depth += 1,
            Tok::Cmd(c) if c == "end" => depth -= 1,
            _ => {}
        }
        match &t[i] {
            Tok::Cmd(c) if c == "\\" && depth == 0 => rows.push(vec![vec![]]),
            Tok::Sym('&') if depth == 0 => rows.last_mut().unwrap().push(vec![]),
            tok => rows
                .last_mut()
                .unwrap()
                .last_mut()
                .unwrap()
                .push(tok.clone()),
        }
        i += 1;
    }
    // `\end{name}`
    i += 1;
    while t[i] != Tok::Sym('}') {
        i += 1;
    }
    (rows, &t[i + 1..])
}

/// The frame named by a `_{\mathcal{B}_{2}}` subscript.
fn basis_subscript(t: &[Tok]) -> String {
    // The frame of the last `\mathcal{B}_{…}` in the subscript (`_{O_{2},\,\mathcal{B}_{1}}`
    // names the point first); empty when there is none.
    let at = (0..t.len()).rev().find(|&k| {
        t[k] == Tok::Cmd("mathcal".into())
            && t.get(k + 2) == Some(&Tok::Letter('B'))
            && t.get(k + 4) == Some(&Tok::Sym('_'))
    });
    let Some(k) = at else {
        return String::new();
    };
    let mut out = String::new();
    let mut depth = 0;
    for x in &t[k + 5..] {
        match x {
            Tok::Sym('{') => depth += 1,
            Tok::Sym('}') => {
                depth -= 1;
                if depth <= 0 {
                    break;
                }
            }
            Tok::Letter(c) | Tok::Digit(c) => {
                out.push(*c);
                if depth == 0 {
                    break;
                }
            }
            _ => {}
        }
    }
    out
}

/// Proves that a displayed formula equals its value; returns what is wrong otherwise.
fn prove(ctx: &Ctx, latex: &str, v: &Value) -> Result<(), String> {
    let m = ctx.m;
    let eqs = equations(latex);
    let same = |what: &str, got: &Expr, want: &Expr| -> Result<(), String> {
        if got == want {
            Ok(())
        } else {
            Err(format!("{what}: printed {got}, engine {want}"))
        }
    };
    match v {
        Value::Scalar(e) => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a scalar", eqs.len()));
            };
            same("scalar", &ctx.scalar(rhs)?, e)
        }
        Value::Quotient(q) => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a quotient", eqs.len()));
            };
            // n / d = N / D, cross-multiplied.
            let (n, d) = ctx.quotient(rhs)?;
            same("quotient", &(&n * &q.den), &(&q.num * &d))
        }
        Value::Vector { basis, components } => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a vector", eqs.len()));
            };
            let f = m.frame_name(*basis);
            let got = if is_cmd(rhs.first(), "begin") {
                let (rows, rest) = environment(rhs);
                if basis_subscript(rest) != f {
                    return Err(format!("column in basis {rest:?}, engine {f}"));
                }
                let c: Result<Vec<Expr>, String> = rows.iter().map(|r| ctx.scalar(&r[0])).collect();
                c?
            } else {
                ctx.vector(rhs, f)?.to_vec()
            };
            for k in 0..3 {
                same(&format!("component {k}"), &got[k], &components[k])?;
            }
            Ok(())
        }
        Value::Matrix(i) => {
            let (_, rhs) = &eqs[0];
            let (rows, rest) = environment(rhs);
            let f = m.frame_name(i.basis);
            if basis_subscript(rest) != f {
                return Err(format!("matrix in basis {rest:?}, engine {f}"));
            }
            for r in 0..3 {
                for c in 0..3 {
                    let cell = &rows[r][c];
                    let def = eqs[1..].iter().find(|(l, _)| l == cell);
                    let got = ctx.scalar(def.map(|d| &d.1[..]).unwrap_or(cell))?;
                    same(&format!("entry ({r},{c})"), &got, &i.matrix[r][c])?;
                }
            }
            Ok(())
        }
        Value::Torsor {
            basis,
            resultant,
            moment,
            ..
        } => {
            let f = m.frame_name(*basis);
            let (res, mom) = if eqs.len() == 2 {
                (ctx.vector(&eqs[0].1, f)?, ctx.vector(&eqs[1].1, f)?)
            } else {
                let rhs = &eqs[0].1;
                // \left\{ \begin{array}{c|c} … \end{array} \right\}_{O,\,B}, or the zero
                // torsor \left\{ 0 \right\}.
                assert!(is_cmd(rhs.first(), "left"), "torsor opens with \\left\\{{");
                if rhs.get(2) == Some(&Tok::Digit('0')) && is_cmd(rhs.get(3), "right") {
                    let zero = || -> [Expr; 3] {
                        [0, 1, 2].map(|_| ctx.scalar(&[Tok::Digit('0')]).unwrap())
                    };
                    let z = zero();
                    for k in 0..3 {
                        same(&format!("resultant {k}"), &z[k], &resultant[k])?;
                        same(&format!("moment {k}"), &z[k], &moment[k])?;
                    }
                    return Ok(());
                }
                let (rows, rest) = environment(&rhs[2..]);
                let b = basis_subscript(rest);
                if b != f {
                    return Err(format!("torsor in basis {b}, engine {f}"));
                }
                let col = |k: usize| -> Result<[Expr; 3], String> {
                    Ok([
                        ctx.scalar(&rows[0][k])?,
                        ctx.scalar(&rows[1][k])?,
                        ctx.scalar(&rows[2][k])?,
                    ])
                };
                (col(0)?, col(1)?)
            };
            for k in 0..3 {
                same(&format!("resultant {k}"), &res[k], &resultant[k])?;
                same(&format!("moment {k}"), &mom[k], &moment[k])?;
            }
            Ok(())
        }
    }
}

/// The bodies of the `align*` displays of a document (boxed in `\\TResultat` or not), in order.
fn align_bodies(tex: &str) -> Vec<&str> {
    let kinds = [
        ("\\begin{align*}\n", "\n\\end{align*}"),
        ("\\TResultat{\n", "\n}\n"),
    ];
    let mut out = Vec::new();
    let mut rest = tex;
    loop {
        let next = kinds
            .iter()
            .filter_map(|(o, c)| rest.find(o).map(|a| (a, *o, *c)))
            .min_by_key(|x| x.0);
        let Some((a, open, close)) = next else { break };
        let from = &rest[a + open.len()..];
        let b = from.find(close).expect("display closes");
        out.push(&from[..b]);
        rest = &from[b..];
    }
    out
}

/// An equality display: its left side (first equation's right side, or the left side of a
/// single equation) and its right side.
fn prove_equality(ctx: &Ctx, latex: &str, l: &Value, r: &Value) -> Result<(), String> {
    let eqs = equations(latex);
    let (Value::Scalar(l), Value::Scalar(r)) = (l, r) else {
        return Err("an equality of non-scalars".into());
    };
    let (a, b) = match eqs.as_slice() {
        [(_, a), (_, b)] => (ctx.scalar(a)?, ctx.scalar(b)?),
        [(a, b)] => (ctx.scalar(a)?, ctx.scalar(b)?),
        _ => return Err(format!("{} equations in an equality", eqs.len())),
    };
    if &a != l {
        return Err(format!("left side printed {a}, engine {l}"));
    }
    if &b != r {
        return Err(format!("right side printed {b}, engine {r}"));
    }
    Ok(())
}

/// Each J_eq form of an equation of motion (three displays, each proven on its right side
/// as any other: J_eq(q), J_eq′(q), and the form J_eq q̈ + ½ J_eq′ q̇² = Q), proven to be that
/// equation: J_eq′ q̇ is the time derivative of J_eq, and J_eq q̈ + ½ J_eq′ q̇² − Q is the fast
/// route's eom(q) up to its sign. Returns how many were proven.
fn prove_jeq_forms(m: &Mechanism, displays: &[torseur::latex::Display]) -> usize {
    let value = |what: &str| -> Option<Expr> {
        let d = displays.iter().find(|d| d.what == what)?;
        match &d.value {
            Value::Scalar(e) => Some(e.clone()),
            _ => None,
        }
    };
    let mut n = 0;
    for d in displays {
        let Some(id) = d.what.strip_prefix("J_eq form of ") else {
            continue;
        };
        let (Some(j), Some(jp), Some(q_side)) = (
            value(&format!("J_eq of {id}")),
            value(&format!("J_eq' of {id}")),
            value(&d.what),
        ) else {
            panic!("{id}: a J_eq form without its J_eq and J_eq'");
        };
        let coordinate = id
            .strip_prefix("eom(")
            .and_then(|r| r.strip_suffix(')'))
            .expect("the J_eq form of an equation of motion");
        let reg = m.reg();
        let q = reg.coord(coordinate).unwrap();
        let (dq, ddq) = (reg.dot(q), reg.ddot(q));
        assert_eq!(
            &jp * &dq,
            j.dt(),
            "{id}: J_eq' is not the derivative of J_eq"
        );
        let half = reg.parse("1/2").unwrap();
        let written = &(&(&j * &ddq) + &(&(&half * &jp) * &(&dq * &dq))) - &q_side;
        let quantity = torseur::quantity::Quantity::parse(id).unwrap();
        let fast = torseur::derivation::derive_values(m, std::slice::from_ref(&quantity))
            .unwrap()
            .remove(0)
            .value;
        let Value::Scalar(eom) = fast else {
            panic!("{id}: an equation of motion is a scalar")
        };
        assert!(
            written == eom || written == -&eom,
            "{id}: the J_eq form is not the equation of motion"
        );
        n += 1;
    }
    n
}

fn spec_paths() -> Vec<std::path::PathBuf> {
    // The library, one chain, and the reusable specs (Latin and Greek names, the link kinds
    // no library spec uses).
    let mut v = super::specs_in(&["derivations"]);
    v.push(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("derivations/chain/chain_2.json"));
    v.extend(super::specs_in(&["tests/specs"]));
    v
}

/// Every displayed formula of every answer key in `derivations/`, proven equal to its value;
/// every `align*` of the document is one of them; every result is the fast route's value.
#[test]
fn every_printed_formula_is_the_engines_value() {
    let mut proven = 0;
    let mut jeq = 0;
    for path in spec_paths() {
        let m = torseur::spec::load(&path).unwrap();
        let key = torseur::latex::answer_key_document(
            &m,
            torseur::latex::VectorStyle::Sum,
            &torseur::simulate::question_runs(&m),
        )
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let ctx = Ctx::new(&m);
        let bodies = align_bodies(&key.tex);
        assert_eq!(
            bodies,
            key.displays
                .iter()
                .map(|d| d.latex.as_str())
                .collect::<Vec<_>>(),
            "{}: the document's displays are exactly the recorded ones",
            path.display()
        );
        for f in &key.inline {
            assert!(
                key.tex.contains(&format!("${}$", f.latex)),
                "{}: {} is not in the text as recorded",
                path.display(),
                f.what
            );
            let t = tokenize(&f.latex);
            let ok = match &f.value {
                // A scalar alone, or stated as `lhs = value` (an imposed rate ψ̇ = ω).
                // A condition `value \neq 0`: its left side is the value, its right side 0.
                Value::Scalar(e) if t.contains(&Tok::Cmd("neq".into())) => {
                    let ne = t.iter().position(|x| *x == Tok::Cmd("neq".into())).unwrap();
                    let zero = ctx.scalar(&t[ne + 1..]).map(|z| z.is_zero());
                    ctx.scalar(&t[..ne]).map(|g| &g == e && zero == Ok(true))
                }
                // A condition |a| ≤ |b| (Coulomb's |T| ≤ f |N|), recorded as a² − b² (≤ 0),
                // the same condition: each |…| is read as (…) and both sides squared.
                Value::Scalar(e) if t.contains(&Tok::Cmd("leq".into())) => {
                    let le = t.iter().position(|x| *x == Tok::Cmd("leq".into())).unwrap();
                    let bars = |s: &[Tok]| -> Vec<Tok> {
                        let mut out = s.to_vec();
                        for k in 1..out.len() {
                            if out[k] == Tok::Sym('|') {
                                out[k] = match &out[k - 1] {
                                    Tok::Cmd(c) if c == "left" => Tok::Sym('('),
                                    Tok::Cmd(c) if c == "right" => Tok::Sym(')'),
                                    _ => Tok::Sym('|'),
                                };
                            }
                        }
                        out
                    };
                    let sides = (ctx.scalar(&bars(&t[..le])), ctx.scalar(&bars(&t[le + 1..])));
                    match sides {
                        (Ok(a), Ok(b)) => Ok(&(&(&a * &a) - &(&b * &b)) == e),
                        (Err(x), _) | (_, Err(x)) => Err(x),
                    }
                }
                Value::Scalar(e) => {
                    let rhs = match t.iter().position(|x| *x == Tok::Sym('=')) {
                        Some(eq) => &t[eq + 1..],
                        None => &t[..],
                    };
                    ctx.scalar(rhs).map(|g| &g == e)
                }
                Value::Vector { components, .. } => {
                    let eq = t.iter().position(|x| *x == Tok::Sym('=')).unwrap();
                    ctx.any_basis(&t[eq + 1..]).map(|g| &g == components)
                }
                _ => unreachable!("inline formulas are scalars and positions"),
            };
            assert_eq!(
                ok,
                Ok(true),
                "{}: {} printed {}",
                path.display(),
                f.what,
                f.latex
            );
            proven += 1;
        }
        // Every displayed value is homogeneous: all its terms have one dimension, from the
        // parameters' units (torseur::units).
        let dims = torseur::units::Dimensions::of(&m);
        for d in &key.displays {
            for v in std::iter::once(&d.value).chain(d.rhs.iter()) {
                for e in v.exprs() {
                    if let Err(err) = torseur::units::dimension(e, &dims) {
                        panic!("{}: {} is not homogeneous: {err:?}", path.display(), d.what);
                    }
                }
            }
        }
        jeq += prove_jeq_forms(&m, &key.displays);
        let mut fast: HashMap<String, Value> = HashMap::new();
        for d in &key.displays {
            let proof = match &d.rhs {
                Some(r) => prove_equality(&ctx, &d.latex, &d.value, r),
                None => prove(&ctx, &d.latex, &d.value),
            };
            // The left side's own symbols (a solid's mass and centre), read back too.
            let proof = proof.and_then(|()| super::printed_names::check(&ctx, d));
            if let Err(e) = proof {
                panic!(
                    "{}: {} ({:?}, under {:?}) is printed wrong: {e}\n{}",
                    path.display(),
                    d.what,
                    d.role,
                    d.hypothesis,
                    d.latex
                );
            }
            if matches!(
                d.role,
                torseur::latex::DisplayRole::Result | torseur::latex::DisplayRole::Equation
            ) {
                let q = torseur::quantity::Quantity::parse(&d.what).unwrap();
                let v = fast.entry(d.what.clone()).or_insert_with(|| {
                    torseur::derivation::derive_values(&m, std::slice::from_ref(&q))
                        .unwrap()
                        .remove(0)
                        .value
                });
                let want = match &d.hypothesis {
                    Some(h) => as_asked(
                        &m,
                        &q,
                        v,
                        m.hypotheses().iter().find(|x| &x.name == h).unwrap(),
                    ),
                    None => v.clone(),
                };
                // An equation a = b shows the quantity a − b (up to its sign: either side may
                // stand on the left).
                let shown = match (&d.value, &d.rhs) {
                    (Value::Scalar(a), Some(Value::Scalar(b))) => {
                        let diff = a - b;
                        let Value::Scalar(w) = &want else {
                            panic!("an equation of a vector")
                        };
                        if &(-&diff) == w {
                            Value::Scalar(-&diff)
                        } else {
                            Value::Scalar(diff)
                        }
                    }
                    _ => d.value.clone(),
                };
                assert!(
                    want.exprs() == shown.exprs(),
                    "{}: {} under {:?}: the key's value is not the fast route's",
                    path.display(),
                    d.what,
                    d.hypothesis
                );
            }
            proven += 1;
        }
    }
    eprintln!("{proven} displayed formulas proven");
    eprintln!("{jeq} J_eq forms proven");
    assert!(proven > 300, "only {proven} formulas read back");
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]

    /// The LaTeX of the presentation form of random expressions (sums of angles, powers,
    /// products of sums) reads back, with this file's reader, to the same canonical form.
    #[test]
    fn the_latex_of_random_expressions_reads_back(e in super::properties::expression()) {
        let m = super::regulator();
        let ctx = Ctx::new(&m);
        let exact = m.reg().parse(&e).unwrap();
        let latex = format!("x &= {}", torseur::latex::expr(&exact));
        let v = Value::Scalar(exact);
        proptest::prop_assert!(prove(&ctx, &latex, &v).is_ok(), "{}: {:?}", latex, prove(&ctx, &latex, &v));
    }
}

/// The reader can fail: a sign flipped in the printed LaTeX, a dropped parenthesis, a wrong
/// basis are each caught.
#[test]
fn the_reader_catches_a_wrong_sign() {
    let m = super::regulator();
    let ctx = Ctx::new(&m);
    let e = m.reg().parse("-(A2 + L2^2*m2)*ddot(theta2) + g").unwrap();
    let v = Value::Scalar(e);
    assert!(
        prove(
            &ctx,
            "x &= -\\left(A_{2} + m_{2}\\,L_{2}^{2}\\right)\\,\\ddot{\\theta}_{2} + g",
            &v
        )
        .is_ok()
    );
    assert!(
        prove(
            &ctx,
            "x &= -A_{2} + m_{2}\\,L_{2}^{2}\\,\\ddot{\\theta}_{2} + g",
            &v
        )
        .is_err()
    );
    assert!(
        prove(
            &ctx,
            "x &= -A_{2}\\,\\ddot{\\theta}_{2} - m_{2}\\,L_{2}^{2}\\,\\ddot{\\theta}_{2} - g",
            &v
        )
        .is_err()
    );
    let f2 = m.frames().find("2").unwrap();
    let z = m.reg().zero();
    let vec = Value::Vector {
        basis: f2,
        components: [m.reg().parse("L1 + L2").unwrap(), z.clone(), z],
    };
    assert!(prove(&ctx, "v &= \\left(L_{1} + L_{2}\\right)\\vec{x}_{2}", &vec).is_ok());
    assert!(prove(&ctx, "v &= L_{1} + L_{2}\\,\\vec{x}_{2}", &vec).is_err());
    assert!(prove(&ctx, "v &= \\left(L_{1} + L_{2}\\right)\\vec{x}_{1}", &vec).is_err());
    let col = "\\begin{pmatrix} L_{1} + L_{2} \\\\ 0 \\\\ 0 \\end{pmatrix}_{\\mathcal{B}_{2}}";
    assert!(prove(&ctx, &format!("v &= {col}"), &vec).is_ok());
    assert!(
        prove(
            &ctx,
            &format!("v &= {}", col.replace("B}_{2}", "B}_{1}")),
            &vec
        )
        .is_err()
    );
}

/// An equation of motion written on several rows (the dynamic side on rows of its own, then
/// `&= actions`) reads back side by side; a sign flipped on either side is caught.
#[test]
fn the_reader_reads_a_dynamic_side_on_rows_of_its_own() {
    let m = super::regulator();
    let ctx = Ctx::new(&m);
    let e = |s: &str| Value::Scalar(m.reg().parse(s).unwrap());
    let l = e("(A2 + m2*L2^2)*ddot(theta2) + f*dot(theta2)");
    let r = e("-m2*g*L2*cos(theta2)");
    let rows = |a: &str, b: &str| {
        format!(
            "&\\left(A_{{2}} + m_{{2}}\\,L_{{2}}^{{2}}\\right)\\ddot{{\\theta}}_{{2}} \\\\\n\
             &\\quad {a} f\\,\\dot{{\\theta}}_{{2}} \\\\\n&= {b}m_{{2}}\\,g\\,L_{{2}}\\,\\cos\\theta_{{2}}"
        )
    };
    assert_eq!(prove_equality(&ctx, &rows("+", "-"), &l, &r), Ok(()));
    assert!(prove_equality(&ctx, &rows("-", "-"), &l, &r).is_err());
    assert!(prove_equality(&ctx, &rows("+", ""), &l, &r).is_err());
}

/// The strings of a JSON value (`canonical` or `presentation`), in `Value::exprs` order.
fn json_strings(v: &serde_json::Value, form: &str) -> Vec<String> {
    let flat = |x: &serde_json::Value| -> Vec<String> {
        let mut out = Vec::new();
        let mut stack = vec![x];
        while let Some(y) = stack.pop() {
            match y {
                serde_json::Value::String(s) => out.push(s.clone()),
                serde_json::Value::Array(a) => stack.extend(a.iter().rev()),
                _ => panic!("unexpected {y}"),
            }
        }
        out
    };
    match v["kind"].as_str().unwrap() {
        "torsor" => {
            let mut r = flat(&v["resultant"][form]);
            r.extend(flat(&v["moment"][form]));
            r
        }
        _ => flat(&v[form]),
    }
}

/// The text and JSON outputs of `derive` (canonical and presentation strings) read back by
/// the engine's parser equal the fast route's values, for every quantity of every spec,
/// under every hypothesis.
#[test]
fn every_derived_text_and_json_string_is_the_engines_value() {
    let mut n = 0;
    for path in spec_paths() {
        let m = torseur::spec::load(&path).unwrap();
        let ds = torseur::derivation::derive_values(&m, m.quantities()).unwrap();
        let j = torseur::output::derive_json(&m, &ds);
        for (d, jq) in ds.iter().zip(j["quantities"].as_array().unwrap()) {
            let mut cases = vec![(d.value.clone(), &jq["value"])];
            for h in m.hypotheses() {
                cases.push((
                    as_asked(&m, &d.quantity, &d.value, h),
                    &jq["hypotheses"][&h.name],
                ));
            }
            for (v, jv) in cases {
                for form in ["canonical", "presentation"] {
                    // A quotient is one string n/d: read by the fraction parser, compared by
                    // cross-multiplication.
                    if let Value::Quotient(q) = &v {
                        let g = jv[form].as_str().unwrap();
                        let (n1, d1) = m.reg().parse_fraction_with(g, &|_| None).unwrap();
                        assert!(
                            &n1 * &q.den == &q.num * &d1 && !d1.is_one(),
                            "{}: {} ({form}) printed {g}, engine {}/{}",
                            path.display(),
                            d.quantity,
                            q.num,
                            q.den
                        );
                        n += 1;
                        continue;
                    }
                    let got = json_strings(jv, form);
                    let want = v.exprs();
                    assert_eq!(got.len(), want.len(), "{}: {}", path.display(), d.quantity);
                    for (g, w) in got.iter().zip(want) {
                        let e = m.reg().parse(g).unwrap_or_else(|e| panic!("{g}: {e}"));
                        assert!(
                            &e == w,
                            "{}: {} ({form}) printed {g}, engine {w}",
                            path.display(),
                            d.quantity
                        );
                        n += 1;
                    }
                }
            }
        }
    }
    assert!(n > 500, "only {n} strings read back");
}

/// The value `v` of `q` under `h` by this reader's own route: the hypothesis applied, and for
/// a linearisation under small parameters ε, its terms in ε δ dropped, δ the small
/// coordinates and their rates (one combined first order): v − Σ εᵢ xⱼ ∂²v/∂εᵢ∂xⱼ, the
/// value being affine in each of them.
fn as_asked(
    m: &torseur::Mechanism,
    q: &torseur::quantity::Quantity,
    v: &Value,
    h: &torseur::mechanism::Hypothesis,
) -> Value {
    let under = v.under(h);
    if !q.linear || h.first_order.is_empty() {
        return under;
    }
    let reg = m.reg();
    let mut small = Vec::new();
    for s in &m.dynamics().small {
        small.extend(reg.value(s.coord).and_then(|e| e.single_variable()));
        for order in 1..=2 {
            small.extend(reg.rate(s.coord, order).single_variable());
        }
    }
    under.map(&|e| {
        let mut out = e.clone();
        for &p in &h.first_order {
            for &x in &small {
                let mixed = e.derivative(p).derivative(x);
                out = &out - &(&mixed * &(&reg.variable(p) * &reg.variable(x)));
            }
        }
        out
    })
}
