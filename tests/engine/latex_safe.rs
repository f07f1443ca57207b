//! An independent reader of the LaTeX a free text becomes (shared with the fuzz target
//! `free_text`): it knows nothing of the escaper or of the formula whitelist's code, only what
//! TeX accepts in running text and in math, and says why a piece of LaTeX could stop
//! pdflatex.
//!
//! Safe means: no control or invisible character; in text, no raw `{ } % # & ~ ^ _ < >` and only
//! the escapes a text needs (`\{`, `\textbackslash{}`…); every `$` opens a formula that a `$`
//! closes; in a formula, only ASCII, balanced braces, `\left`/`\right` paired in their group
//! with a delimiter, a known macro with its arguments, scripts with an argument TeX takes
//! and never twice on one atom (a prime is a superscript), `\textnormal{…}` holding running
//! text (safe as above), and bounded nesting.

/// Groups (braces, `\left`) a formula may nest.
const MAX_DEPTH: usize = 40;

/// Nested `\overrightarrow` (TeX typesets its argument four times per level).
const MAX_ARROWS: usize = 3;

/// Text-mode words, each written with `{}` after it.
const TEXT_WORDS: &[&str] = &[
    "textbackslash",
    "textasciicircum",
    "textasciitilde",
    "textless",
    "textgreater",
    "dots",
    "oe",
    "OE",
];

/// Text-mode control symbols.
const TEXT_SYMBOLS: &str = "{}$&#%_";

/// Math words that are one symbol: a script may take them as its argument.
pub const MATH_SYMBOLS: &[&str] = &[
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "varepsilon",
    "zeta",
    "eta",
    "theta",
    "vartheta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "pi",
    "varpi",
    "rho",
    "varrho",
    "sigma",
    "varsigma",
    "tau",
    "upsilon",
    "phi",
    "varphi",
    "chi",
    "psi",
    "omega",
    "Gamma",
    "Delta",
    "Theta",
    "Lambda",
    "Xi",
    "Pi",
    "Sigma",
    "Upsilon",
    "Phi",
    "Psi",
    "Omega",
    "cdot",
    "wedge",
    "times",
    "ell",
    "infty",
    "leq",
    "geq",
    "neq",
    "approx",
    "pm",
    "rightarrow",
];

/// Math words without argument that a script must not take bare.
pub const MATH_OTHERS: &[&str] = &["sin", "cos", "tan", "quad", "ldots"];

/// Math words with their number of arguments.
pub const MATH_MACROS: &[(&str, usize)] = &[
    ("vec", 1),
    ("overrightarrow", 1),
    ("mathcal", 1),
    ("mathrm", 1),
    ("dot", 1),
    ("ddot", 1),
    ("frac", 2),
];

/// The math word whose argument is running text.
pub const MATH_TEXT: &str = "textnormal";

/// Characters a formula holds as they are.
pub const MATH_CHARS: &str = "+-=()[],.;:/|<>!*";

#[derive(Debug, Clone, PartialEq)]
enum Tok {
    /// `\word`.
    Word(String),
    /// `\` and one other character.
    Symbol(char),
    /// Any other character.
    Ch(char),
}

/// Why `latex` could stop pdflatex, if it could.
pub fn check(latex: &str) -> Result<(), String> {
    for (k, c) in latex.chars().enumerate() {
        let code = c as u32;
        if c.is_control()
            || (0x200B..=0x200F).contains(&code)
            || (0x202A..=0x202E).contains(&code)
            || (0x2066..=0x2069).contains(&code)
            || code == 0xFEFF
        {
            return Err(format!("character {k} is U+{code:04X}"));
        }
    }
    let toks = tokens(latex)?;
    let mut r = Reader {
        t: &toks,
        i: 0,
        depth: 0,
        arrows: 0,
    };
    r.text()
}

/// TeX's tokens: a control word swallows the spaces after it.
fn tokens(s: &str) -> Result<Vec<Tok>, String> {
    let cs: Vec<char> = s.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < cs.len() {
        if cs[i] == '\\' {
            let mut j = i + 1;
            while j < cs.len() && cs[j].is_ascii_alphabetic() {
                j += 1;
            }
            if j > i + 1 {
                out.push(Tok::Word(cs[i + 1..j].iter().collect()));
                while j < cs.len() && cs[j] == ' ' {
                    j += 1;
                }
                i = j;
            } else if let Some(&c) = cs.get(i + 1) {
                out.push(Tok::Symbol(c));
                i += 2;
            } else {
                return Err("ends with a backslash".into());
            }
        } else {
            out.push(Tok::Ch(cs[i]));
            i += 1;
        }
    }
    Ok(out)
}

struct Reader<'a> {
    t: &'a [Tok],
    i: usize,
    depth: usize,
    arrows: usize,
}

impl Reader<'_> {
    fn next(&mut self) -> Option<Tok> {
        let t = self.t.get(self.i).cloned();
        self.i += 1;
        t
    }

    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }

    /// Running text, to the end.
    fn text(&mut self) -> Result<(), String> {
        self.text_until(None)
    }

    /// Running text, to the end or through `close` (the `}` of a `\textnormal{…}` in a
    /// formula: a raw brace is never text, so the first one closes it).
    fn text_until(&mut self, close: Option<char>) -> Result<(), String> {
        while let Some(t) = self.next() {
            match t {
                Tok::Ch(c) if Some(c) == close => return Ok(()),
                Tok::Ch('$') => self.formula()?,
                Tok::Ch(c) => {
                    let ok = c == ' '
                        || c.is_ascii_alphanumeric()
                        || "!\"'()*+,-./:;=?@[]|`".contains(c)
                        || (0xA0..=0xFF).contains(&(c as u32));
                    if !ok {
                        return Err(format!("raw `{c}` in text"));
                    }
                }
                // `\string:`: the colon itself, out of babel-french's reach (a time 08:46).
                Tok::Word(w) if w == "string" => {
                    if self.next() != Some(Tok::Ch(':')) {
                        return Err("`\\string` not before a colon".into());
                    }
                }
                Tok::Word(w) => {
                    if !TEXT_WORDS.contains(&w.as_str()) {
                        return Err(format!("`\\{w}` in text"));
                    }
                    if self.next() != Some(Tok::Ch('{')) || self.next() != Some(Tok::Ch('}')) {
                        return Err(format!("`\\{w}` without `{{}}` after it"));
                    }
                }
                Tok::Symbol(c) => {
                    if !TEXT_SYMBOLS.contains(c) {
                        return Err(format!("`\\{c}` in text"));
                    }
                }
            }
        }
        match close {
            Some(c) => Err(format!("`{c}` missing at the end of a text in a formula")),
            None => Ok(()),
        }
    }

    /// A formula after its opening `$`, through its closing `$`.
    fn formula(&mut self) -> Result<(), String> {
        if self.peek() == Some(&Tok::Ch('$')) {
            return Err("`$$`".into());
        }
        self.list('$')
    }

    /// Math up to `close` (`$` or `}`), consumed.
    fn list(&mut self, close: char) -> Result<(), String> {
        let (mut sup, mut sub, mut prime) = (false, false, false);
        let mut lefts = 0usize;
        loop {
            let Some(t) = self.next() else {
                return Err(format!("`{close}` missing at the end"));
            };
            match t {
                Tok::Ch(c) if c == close => {
                    if lefts > 0 {
                        return Err("`\\left` without `\\right`".into());
                    }
                    return Ok(());
                }
                Tok::Ch('$') | Tok::Ch('}') => return Err("unbalanced `{`, `}` or `$`".into()),
                Tok::Ch(' ') => {
                    // A space ends the primes: they are a superscript now.
                    if std::mem::take(&mut prime) {
                        sup = true;
                    }
                    continue;
                }
                Tok::Ch('\'') => {
                    if sup {
                        return Err("a prime on a superscript".into());
                    }
                    prime = true;
                    continue;
                }
                Tok::Ch('^') => {
                    prime = false;
                    if sup {
                        return Err("double superscript".into());
                    }
                    sup = true;
                    self.argument(true)?;
                    continue;
                }
                Tok::Ch('_') => {
                    if std::mem::take(&mut prime) {
                        sup = true;
                    }
                    if sub {
                        return Err("double subscript".into());
                    }
                    sub = true;
                    self.argument(true)?;
                    continue;
                }
                _ => {}
            }
            // A new atom.
            (sup, sub, prime) = (false, false, false);
            match t {
                Tok::Ch('{') => self.group()?,
                Tok::Ch(c) => {
                    if !(c.is_ascii_alphanumeric() || MATH_CHARS.contains(c)) {
                        return Err(format!("raw `{c}` in a formula"));
                    }
                }
                Tok::Symbol(c) => {
                    if !",;!{}".contains(c) {
                        return Err(format!("`\\{c}` in a formula"));
                    }
                }
                Tok::Word(w) if w == "left" => {
                    lefts += 1;
                    self.depth += 1;
                    if self.depth > MAX_DEPTH {
                        return Err("nested too deep".into());
                    }
                    self.delimiter()?;
                }
                Tok::Word(w) if w == "right" => {
                    if lefts == 0 {
                        return Err("`\\right` without `\\left`".into());
                    }
                    lefts -= 1;
                    self.depth -= 1;
                    self.delimiter()?;
                }
                Tok::Word(w) => self.word(&w)?,
            }
        }
    }

    /// A math word and its arguments.
    fn word(&mut self, w: &str) -> Result<(), String> {
        if MATH_SYMBOLS.contains(&w) || MATH_OTHERS.contains(&w) {
            return Ok(());
        }
        // Text in a formula (what exerts an action, {T(poussée → 1)}): running text in its
        // group, which may hold formulas of its own.
        if w == MATH_TEXT {
            if self.next() != Some(Tok::Ch('{')) {
                return Err(format!("`\\{w}` without its `{{…}}`"));
            }
            self.depth += 1;
            if self.depth > MAX_DEPTH {
                return Err("nested too deep".into());
            }
            self.text_until(Some('}'))?;
            self.depth -= 1;
            return Ok(());
        }
        let Some(&(_, n)) = MATH_MACROS.iter().find(|(m, _)| *m == w) else {
            return Err(format!("`\\{w}` in a formula"));
        };
        let arrow = w == "overrightarrow";
        if arrow {
            self.arrows += 1;
            if self.arrows > MAX_ARROWS {
                return Err("`\\overrightarrow` nested too deep".into());
            }
        }
        for _ in 0..n {
            self.argument(false)?;
        }
        if arrow {
            self.arrows -= 1;
        }
        Ok(())
    }

    /// A braced group after its `{`, through its `}`.
    fn group(&mut self) -> Result<(), String> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err("nested too deep".into());
        }
        self.list('}')?;
        self.depth -= 1;
        Ok(())
    }

    /// The argument of a script (`script`) or of a macro.
    fn argument(&mut self, script: bool) -> Result<(), String> {
        while self.peek() == Some(&Tok::Ch(' ')) {
            self.i += 1;
        }
        match self.next() {
            Some(Tok::Ch('{')) => self.group(),
            Some(Tok::Ch('\'')) if script => Err("a script takes a bare prime".into()),
            Some(Tok::Ch(c)) if c.is_ascii_alphanumeric() || MATH_CHARS.contains(c) => Ok(()),
            Some(Tok::Ch('\'')) => Ok(()),
            Some(Tok::Word(w)) if MATH_SYMBOLS.contains(&w.as_str()) => Ok(()),
            Some(Tok::Word(w)) if !script && MATH_OTHERS.contains(&w.as_str()) => Ok(()),
            other => Err(format!("an argument TeX does not take: {other:?}")),
        }
    }

    /// The delimiter after `\left` or `\right`.
    fn delimiter(&mut self) -> Result<(), String> {
        match self.next() {
            Some(Tok::Ch(c)) if "()[]|./".contains(c) => Ok(()),
            Some(Tok::Symbol('{' | '}')) => Ok(()),
            other => Err(format!("`\\left` or `\\right` before {other:?}")),
        }
    }
}

#[test]
fn the_reader_refuses_what_stops_tex() {
    for bad in [
        "50%",
        "a & b",
        "#1",
        "x_1",
        "x^2",
        "{",
        "}",
        "\\",
        "$x",
        "$x}$",
        "$\\thetax$",
        "$x^'$",
        "$x^\\sin$",
        "$x^2^3$",
        "$x' ^2$",
        "$x'_1^2$",
        "$\\left( x$",
        "$\\input{a}$",
        "$é$",
        "\\textbackslash",
        "a\u{85}b",
        "a\u{202e}b",
        "$$x$$",
        "$\\overrightarrow{\\overrightarrow{\\overrightarrow{\\overrightarrow{x}}}}$",
        "$\\textnormal x$",
        "$\\textnormal{50%}$",
        "$\\textnormal{a$",
        "$\\textnormal{a}",
        "\\textnormal{a}",
    ] {
        assert!(check(bad).is_err(), "{bad}");
    }
    for good in [
        "50\\% \\& \\#1 x\\_1 \\textasciicircum{}2 \\{ \\} \\$ é",
        "$\\dot{\\mathrm{x}}$ $\\ddot{\\theta}$",
        "$x'^2_1 + f''(x) + \\frac{1}{2} m v^2$",
        "$\\left( \\vec{x}_{1} \\right)^{2} \\sin\\theta \\quad \\left\\{ a \\right.$",
        "$\\overrightarrow{\\overrightarrow{\\overrightarrow{x}}}$",
        "$\\mathcal{T}(\\textnormal{poussée} \\rightarrow 1)$",
        "$\\mathcal{T}_{A}(\\textnormal{moteur $M_1$ \\% \\{\\}} \\rightarrow 1)$",
    ] {
        assert_eq!(check(good), Ok(()), "{good}");
    }
}
