//! The answer key's LaTeX as tokens: the notation macros of the preamble, expanded as the
//! reader understands them, and the lexer (see `printed/mod.rs`).

#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Tok {
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
pub(crate) fn course(tex: &str) -> String {
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
pub(crate) fn tokenize(s: &str) -> Vec<Tok> {
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
pub(super) fn greek(c: &str) -> Option<String> {
    let plain = c
        .strip_prefix("var")
        .filter(|p| ["phi", "epsilon"].contains(p));
    let c = plain.unwrap_or(c);
    GREEK.contains(&c).then(|| c.to_string())
}

pub(super) fn is_cmd(t: Option<&Tok>, name: &str) -> bool {
    matches!(t, Some(Tok::Cmd(c)) if c == name)
}

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
];
