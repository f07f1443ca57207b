//! Free text with mathematics: the spec's titles, statements, answers and descriptions may hold
//! formulas between `$…$`, written with a small whitelist of macros; everything else is text.
//!
//! The whitelist is what a statement needs to name the course's objects (S1, z⃗0, ℛ0, θ̇1,
//! O1G2 ∧ m2 Γ⃗, ½ m v²) and nothing that can reach the file system, define a macro or change
//! how TeX reads the input: `\input`, `\write18`, `\def`, `\catcode`, `\csname` and every
//! macro not listed are refused, as are unbalanced braces, an unclosed `$` and characters that
//! would end or comment out the formula (`%`, `#`, `&`). Outside `$…$`, text is escaped as
//! [`super::escape_text`] does; `\$` is a literal dollar.
//!
//! What TeX could not typeset is refused too, so that every accepted text compiles: control
//! characters and invisible formatting characters anywhere, a formula nesting more than
//! [`MAX_FORMULA_DEPTH`] groups or more than [`MAX_ARROW_DEPTH`] `\overrightarrow`, a script
//! whose argument TeX does not take (a prime, `\sin`, `\quad`, `\ldots`).

use std::fmt::Write as _;

/// Macros without argument accepted in a formula (Greek letters, operators, functions).
const PLAIN: &[&str] = &[
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
    "sin",
    "cos",
    "tan",
    "quad",
    "ell",
    "infty",
    "leq",
    "geq",
    "neq",
    "approx",
    "pm",
    "rightarrow",
    "ldots",
];

/// Macros taking one argument.
const ONE_ARG: &[&str] = &["vec", "overrightarrow", "mathcal", "mathrm", "dot", "ddot"];

/// Words that are not a single math symbol: a script takes them only in braces (`x^\sin`
/// stops TeX with « Missing { inserted »).
const NOT_SYMBOLS: &[&str] = &["sin", "cos", "tan", "quad", "ldots"];

/// The most characters a title or a label may hold (a line of the key, sometimes inside a
/// box that does not break: 200 characters is some 1,000 pt, far from TeX's largest
/// dimension).
pub const MAX_LABEL_CHARS: usize = 200;

/// The most characters a prose free text (a statement, an answer, a description) may hold.
pub const MAX_PROSE_CHARS: usize = 20_000;

/// Deepest nesting of groups in a formula: braces and `\left … \right` pairs together. TeX
/// allows 255 grouping levels in a whole document, and each level of a formula may take
/// a few (`\frac`, `\mathrm`).
pub const MAX_FORMULA_DEPTH: usize = 32;

/// Deepest nesting of `\overrightarrow` (TeX typesets its argument four times, so each level
/// multiplies the work by four).
pub const MAX_ARROW_DEPTH: usize = 3;

/// Control symbols accepted: thin, medium and negative spaces, braces as characters.
const SYMBOLS: &[char] = &[',', ';', '!', '{', '}'];

/// Punctuation and operators accepted as they are in a formula.
const MATH_CHARS: &str = "+-=()[],.;:/'|<>!*";

/// The list of what a formula may hold, for the error messages.
const ALLOWED: &str = "letters, digits, + - = ( ) [ ] , . ; : / ' | < > ! *, _ and ^, braces, \
                       Greek letters, \\vec, \\overrightarrow, \\mathcal, \\mathrm, \\dot, \
                       \\ddot, \\frac, \\cdot, \\wedge, \\times, \\sin, \\cos, \\tan, \\left, \
                       \\right, \\quad, \\,, \\ell, \\infty, \\leq, \\geq, \\neq, \\approx, \\pm, \
                       \\rightarrow, \\ldots";

/// Why a free text was refused: what is wrong, and where (1-based character position).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message} (character {position})")]
pub struct RichTextError {
    /// What is wrong.
    pub message: String,
    /// 1-based position (in characters) of the offending character in the text.
    pub position: usize,
}

/// Free text as LaTeX: formulas between `$…$` are kept (once checked against the whitelist),
/// the text around them is escaped as [`super::escape_text`] does, `\$` is a dollar sign.
///
/// A formula may hold letters, digits, `+ - = ( ) [ ] , . ; : / ' | < > ! *`, spaces,
/// subscripts and superscripts (one of each per atom, their argument a character, a group or
/// a Greek letter), balanced braces, the Greek letters (`\alpha` … `\Omega`, `\varepsilon`,
/// `\vartheta`, `\varphi`…), `\vec`, `\overrightarrow`, `\mathcal`, `\mathrm`, `\dot`,
/// `\ddot`, `\frac`, `\cdot`, `\wedge`, `\times`, `\sin`, `\cos`, `\tan`, `\left` and
/// `\right` (paired, with a delimiter), `\quad`, `\,`, `\;`, `\!`, `\{`, `\}`, `\ell`,
/// `\infty`, `\leq`, `\geq`, `\neq`, `\approx`, `\rightarrow`, `\ldots`; Unicode Greek
/// letters and `·`, `∧`, `×`, `≤`, `≥`, `≠`, `≈`, `→`, `∞`, `…` become those macros.
///
/// ```
/// use torseur::latex::rich_text;
/// assert_eq!(
///     rich_text("Le solide $S_1$ tourne autour de $(O_1, \\vec{z}_0)$ : 100 %").unwrap(),
///     "Le solide $S_1$ tourne autour de $(O_1, \\vec{z}_0)$ : 100 \\%"
/// );
/// assert_eq!(rich_text("5 \\$ & 1_2").unwrap(), "5 \\$ \\& 1\\_2");
/// assert!(rich_text("$\\input{/etc/passwd}$").is_err());
/// assert!(rich_text("$x^{2$").is_err());
/// assert!(rich_text("un $ seul").is_err());
/// ```
pub fn rich_text(s: &str) -> Result<String, RichTextError> {
    let chars: Vec<char> = s.chars().collect();
    if let Some((k, what)) = chars
        .iter()
        .enumerate()
        .find_map(|(k, &c)| unprintable(c).map(|w| (k, w)))
    {
        return Err(RichTextError {
            message: format!("{what} (U+{:04X}) is not allowed", chars[k] as u32),
            position: k + 1,
        });
    }
    let mut out = String::with_capacity(s.len() + 8);
    let mut text = String::new();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '\\' if chars.get(i + 1) == Some(&'$') => {
                text.push('$');
                i += 2;
            }
            '$' => {
                out.push_str(&super::escape_text(&text));
                text.clear();
                let mut p = Formula {
                    chars: &chars,
                    pos: i + 1,
                    out: String::new(),
                    depth: 0,
                    arrows: 0,
                };
                p.formula()?;
                out.push('$');
                out.push_str(&p.out);
                out.push('$');
                i = p.pos + 1;
            }
            c => {
                text.push(c);
                i += 1;
            }
        }
    }
    out.push_str(&super::escape_text(&text));
    Ok(out)
}

/// [`rich_text`] for a text already validated (every free text of a loaded spec is): the
/// LaTeX, or the whole text escaped if it were refused, so nothing unchecked is ever printed.
///
/// ```
/// use torseur::latex::rich_text_or_escaped;
/// assert_eq!(rich_text_or_escaped("$\\theta_1$"), "$\\theta_1$");
/// assert_eq!(rich_text_or_escaped("$\\def$"), "\\$\\textbackslash{}def\\$");
/// ```
pub fn rich_text_or_escaped(s: &str) -> String {
    rich_text(s).unwrap_or_else(|_| super::escape_text(s))
}

/// What kind of character TeX must never receive from a free text, if `c` is one: control
/// characters (C0 but tab and line ends, DEL, C1) and invisible formatting characters
/// (zero-width, bidirectional controls, byte order mark).
fn unprintable(c: char) -> Option<&'static str> {
    match c {
        '\t' | '\n' | '\r' => None,
        c if c.is_control() => Some("a control character"),
        '\u{61C}'
        | '\u{180E}'
        | '\u{200B}'..='\u{200F}'
        | '\u{202A}'..='\u{202E}'
        | '\u{2060}'..='\u{2064}'
        | '\u{2066}'..='\u{206F}'
        | '\u{FEFF}'
        | '\u{FFF9}'..='\u{FFFB}' => Some("an invisible formatting character"),
        _ => None,
    }
}

/// Lowercases the text of a free text outside its formulas (`Question 2 : $\Omega$` →
/// `question 2 : $\Omega$`), for a title cited in a sentence.
pub(crate) fn lowercase_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut math = false;
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'$') => {
                out.push(c);
                out.extend(chars.next());
            }
            '$' => {
                math = !math;
                out.push(c);
            }
            c if math => out.push(c),
            c => out.extend(c.to_lowercase()),
        }
    }
    out
}

/// A formula being checked and copied: `pos` is the index of the next character.
struct Formula<'a> {
    chars: &'a [char],
    pos: usize,
    out: String,
    /// Groups open around the next token (braces and `\left`).
    depth: usize,
    /// `\overrightarrow` open around the next token.
    arrows: usize,
}

/// What the current atom of a group already carries: a superscript, a subscript; whether it
/// ends with primes, which a `^` right after joins (any other token closes them into a
/// superscript).
#[derive(Default)]
struct Scripts {
    sup: bool,
    sub: bool,
    primes: bool,
}

/// What closes the group being read.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Close {
    /// The `$` that ends the formula.
    Dollar,
    /// The `}` of a group.
    Brace,
}

/// One token of a formula.
enum Token {
    /// A character copied as is (letter, digit, operator).
    Char(char),
    /// `{`.
    Open,
    /// `}`.
    Close,
    /// `$`.
    Dollar,
    /// `^` or `_`.
    Script(char),
    /// `\name`.
    Word(String),
    /// `\,` and the like.
    Symbol(char),
}

impl Formula<'_> {
    fn err(&self, at: usize, message: impl Into<String>) -> RichTextError {
        RichTextError {
            message: message.into(),
            position: at + 1,
        }
    }

    /// Reads the formula up to its closing `$` (left at `pos`).
    fn formula(&mut self) -> Result<(), RichTextError> {
        let start = self.pos - 1;
        if self.chars.get(self.pos) == Some(&'$') {
            return Err(self.err(
                start,
                "empty formula `$$` (display formulas are not supported; write `\\$` for a \
                 dollar sign)",
            ));
        }
        self.group(Close::Dollar, start)
    }

    /// The next token, its start index, and whether the source had spaces before it.
    fn token(&mut self) -> Result<Option<(Token, usize)>, RichTextError> {
        while let Some(c) = self.chars.get(self.pos)
            && c.is_whitespace()
        {
            self.pos += 1;
            if !self.out.ends_with(' ') {
                self.out.push(' ');
            }
        }
        let at = self.pos;
        let Some(&c) = self.chars.get(at) else {
            return Ok(None);
        };
        self.pos += 1;
        let t = match c {
            '{' => Token::Open,
            '}' => Token::Close,
            '$' => Token::Dollar,
            '^' | '_' => Token::Script(c),
            '\\' => {
                let mut name = String::new();
                while let Some(&l) = self.chars.get(self.pos)
                    && l.is_ascii_alphabetic()
                {
                    name.push(l);
                    self.pos += 1;
                }
                if name.is_empty() {
                    match self.chars.get(self.pos) {
                        Some(&s) if SYMBOLS.contains(&s) => {
                            self.pos += 1;
                            Token::Symbol(s)
                        }
                        Some(&s) => {
                            return Err(self.err(
                                at,
                                format!("`\\{s}` is not allowed in a formula (allowed: {ALLOWED})"),
                            ));
                        }
                        None => return Err(self.err(at, "a formula ends with `\\`")),
                    }
                } else {
                    Token::Word(name)
                }
            }
            c if c.is_ascii_alphanumeric() || MATH_CHARS.contains(c) => Token::Char(c),
            c => match unicode_math(c) {
                Some(m) => Token::Word(m.to_string()),
                None => {
                    let what = match c {
                        '%' => "`%` (it would comment out the end of the formula)".to_string(),
                        '#' | '&' | '~' => format!("`{c}`"),
                        c if c.is_control() => format!("the control character U+{:04X}", c as u32),
                        c => format!("the character `{c}`"),
                    };
                    return Err(self.err(
                        at,
                        format!("{what} is not allowed in a formula (allowed: {ALLOWED})"),
                    ));
                }
            },
        };
        Ok(Some((t, at)))
    }

    /// Reads items up to `close` (consumed), checking scripts, `\left`/`\right` and macro
    /// arguments. `open` is where the group started, for the message of an unclosed group.
    fn group(&mut self, close: Close, open: usize) -> Result<(), RichTextError> {
        let mut scripts = Scripts::default();
        let mut lefts: Vec<usize> = Vec::new();
        loop {
            let Some((t, at)) = self.token()? else {
                return Err(match close {
                    Close::Dollar => self.err(open, "a formula opened by `$` is never closed"),
                    Close::Brace => self.err(open, "a `{` is never closed"),
                });
            };
            if scripts.primes && matches!(t, Token::Script('^') | Token::Char('\'')) {
                // `x' ^2`, `x' '`: TeX joins a `^` or a prime only right after a prime.
                while self.out.ends_with(' ') {
                    self.out.pop();
                }
            }
            match t {
                Token::Dollar | Token::Close => {
                    return self.group_end(&t, close, open, at, &lefts);
                }
                Token::Script(c) => self.script(&mut scripts, c, at)?,
                Token::Char('\'') => {
                    // A prime is a superscript that a following `^` joins.
                    if scripts.sup {
                        return Err(self.err(
                            at,
                            "double superscript: a prime after a superscript needs braces",
                        ));
                    }
                    self.out.push('\'');
                    scripts.primes = true;
                }
                Token::Word(w) if w == "left" || w == "right" => {
                    self.left_right(&w, at, &mut lefts)?;
                    scripts = Scripts::default();
                }
                other => {
                    self.atom(other, at)?;
                    scripts = Scripts::default();
                }
            }
        }
    }

    /// The end of a group, at a `$` or a `}` (`t`, at `at`): refused when it is not the one
    /// that closes it (`close`, opened at `open`) or when a `\left` of the group (`lefts`) has
    /// no `\right`.
    fn group_end(
        &mut self,
        t: &Token,
        close: Close,
        open: usize,
        at: usize,
        lefts: &[usize],
    ) -> Result<(), RichTextError> {
        if let Token::Dollar = t {
            if close == Close::Brace {
                return Err(self.err(open, "a `{` is not closed before the closing `$`"));
            }
            if let Some(&l) = lefts.last() {
                return Err(self.err(l, "a `\\left` has no `\\right`"));
            }
            // `pos` is just after the `$`; leave it on the `$`.
            self.pos -= 1;
            return Ok(());
        }
        if close == Close::Dollar {
            return Err(self.err(at, "a `}` closes no `{`"));
        }
        if let Some(&l) = lefts.last() {
            return Err(self.err(l, "a `\\left` has no `\\right` in its group"));
        }
        self.out.push('}');
        Ok(())
    }

    /// A `^` or a `_` (`c`, at `at`) and its argument; refused when the atom has one already.
    fn script(&mut self, scripts: &mut Scripts, c: char, at: usize) -> Result<(), RichTextError> {
        // Primes followed by `_` are a superscript already.
        if std::mem::take(&mut scripts.primes) && c == '_' {
            scripts.sup = true;
        }
        let seen = if c == '^' {
            &mut scripts.sup
        } else {
            &mut scripts.sub
        };
        if *seen {
            let what = if c == '^' { "superscript" } else { "subscript" };
            return Err(self.err(
                at,
                format!("double {what}: put braces around the first one"),
            ));
        }
        *seen = true;
        self.out.push(c);
        self.argument(at, &format!("`{c}`"), true)
    }

    /// A `\left` or a `\right` (`w`, at `at`) and its delimiter; the `\left`s open in the
    /// group are `lefts`.
    fn left_right(
        &mut self,
        w: &str,
        at: usize,
        lefts: &mut Vec<usize>,
    ) -> Result<(), RichTextError> {
        if w == "left" {
            lefts.push(at);
            self.enter(at)?;
        } else if lefts.pop().is_none() {
            return Err(self.err(at, "a `\\right` has no `\\left`"));
        } else {
            self.depth -= 1;
        }
        self.word(w);
        self.delimiter(at, w)
    }

    /// One more group open at `at` (a `{` or a `\left`), refused past [`MAX_FORMULA_DEPTH`].
    fn enter(&mut self, at: usize) -> Result<(), RichTextError> {
        self.depth += 1;
        if self.depth > MAX_FORMULA_DEPTH {
            return Err(self.err(
                at,
                format!(
                    "a formula may nest at most {MAX_FORMULA_DEPTH} groups (braces and \
                     `\\left … \\right`)"
                ),
            ));
        }
        Ok(())
    }

    /// Writes the control word `\w`.
    fn word(&mut self, w: &str) {
        let _ = write!(self.out, "\\{w}");
    }

    /// Copies one atom that starts with token `t`: a character, a group, or a macro with its
    /// arguments.
    fn atom(&mut self, t: Token, at: usize) -> Result<(), RichTextError> {
        match t {
            Token::Char(c) => {
                // A letter right after a control word (`θx` → `\theta x`) stays apart from it.
                if c.is_ascii_alphabetic() && ends_with_word(&self.out) {
                    self.out.push(' ');
                }
                self.out.push(c);
            }
            Token::Symbol(s) => {
                let _ = write!(self.out, "\\{s}");
            }
            Token::Open => {
                self.enter(at)?;
                self.out.push('{');
                self.group(Close::Brace, at)?;
                self.depth -= 1;
            }
            Token::Word(w) => {
                let args = if PLAIN.contains(&w.as_str()) {
                    0
                } else if ONE_ARG.contains(&w.as_str()) {
                    1
                } else if w == "frac" {
                    2
                } else {
                    return Err(self.err(
                        at,
                        format!("`\\{w}` is not allowed in a formula (allowed: {ALLOWED})"),
                    ));
                };
                let arrow = w == "overrightarrow";
                if arrow {
                    self.arrows += 1;
                    if self.arrows > MAX_ARROW_DEPTH {
                        return Err(self.err(
                            at,
                            format!(
                                "a formula may nest at most {MAX_ARROW_DEPTH} `\\overrightarrow`"
                            ),
                        ));
                    }
                }
                self.word(&w);
                for _ in 0..args {
                    self.argument(at, &format!("`\\{w}`"), false)?;
                }
                if arrow {
                    self.arrows -= 1;
                }
            }
            Token::Close | Token::Dollar | Token::Script(_) => {
                unreachable!("handled by the group")
            }
        }
        Ok(())
    }

    /// The argument of a macro or a script: a group, a character, or a macro without
    /// argument (a script takes neither a prime nor a word that is not one symbol).
    fn argument(&mut self, of_at: usize, of: &str, script: bool) -> Result<(), RichTextError> {
        let Some((t, at)) = self.token()? else {
            return Err(self.err(of_at, format!("{of} has no argument")));
        };
        match t {
            Token::Char('\'') if script => Err(self.err(
                at,
                format!("{of} takes a prime as argument: put it in braces"),
            )),
            Token::Word(ref w) if script && NOT_SYMBOLS.contains(&w.as_str()) => Err(self.err(
                at,
                format!("{of} takes `\\{w}` as argument: put it in braces"),
            )),
            Token::Open | Token::Char(_) => self.atom(t, at),
            Token::Word(ref w) if PLAIN.contains(&w.as_str()) => {
                // `\vec\omega`: keep the control word apart from what follows.
                self.atom(t, at)?;
                self.out.push(' ');
                Ok(())
            }
            Token::Word(w) => Err(self.err(
                at,
                format!("{of} takes `\\{w}` as argument: put it in braces"),
            )),
            Token::Close | Token::Dollar | Token::Script(_) | Token::Symbol(_) => {
                Err(self.err(of_at, format!("{of} has no argument")))
            }
        }
    }

    /// The delimiter after `\left` or `\right`.
    fn delimiter(&mut self, at: usize, w: &str) -> Result<(), RichTextError> {
        match self.token()? {
            Some((Token::Char(c), _)) if "()[]|./".contains(c) => {
                self.out.push(c);
                Ok(())
            }
            Some((Token::Symbol(s), _)) if s == '{' || s == '}' => {
                let _ = write!(self.out, "\\{s}");
                Ok(())
            }
            _ => Err(self.err(
                at,
                format!("`\\{w}` is followed by a delimiter: ( ) [ ] | . / \\{{ \\}}"),
            )),
        }
    }
}

/// Whether `out` ends with a control word (`\theta`), which a letter would lengthen.
fn ends_with_word(out: &str) -> bool {
    let letters = out.trim_end_matches(|c: char| c.is_ascii_alphabetic());
    letters.len() < out.len() && letters.ends_with('\\')
}

/// The macro for a Unicode letter or operator written in a formula (`θ` → `theta`).
fn unicode_math(c: char) -> Option<&'static str> {
    match c {
        '·' => Some("cdot"),
        '∧' => Some("wedge"),
        '×' => Some("times"),
        '≤' => Some("leq"),
        '≥' => Some("geq"),
        '≠' => Some("neq"),
        '≈' => Some("approx"),
        '→' => Some("rightarrow"),
        '∞' => Some("infty"),
        '…' => Some("ldots"),
        _ => super::greek(c).filter(|g| PLAIN.contains(g)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn whitelist_is_copied() {
        for f in [
            "$\\overrightarrow{O_1G_2} \\wedge m_2 \\vec{\\Gamma}(G_2)$",
            "$\\mathcal{R}_0$",
            "$\\dot{\\theta}_1^2 \\leq \\frac{1}{2} m v^2$",
            "$\\left( \\frac{\\pi}{2} - q_1 \\right)$",
            "$\\left\\{ \\mathcal{V}(2/0) \\right\\}_{O_2}$",
            "$\\sin\\theta \\cos\\theta \\tan x$",
            "$a \\cdot b \\times c \\quad \\ell \\infty \\geq \\neq \\approx \\pm \\rightarrow \\ldots$",
            "$f'(x) + f''^2$",
            "$x^{2}_{1}$",
        ] {
            assert_eq!(rich_text(f).unwrap(), f, "{f}");
        }
    }

    #[test]
    fn unicode_in_formulas_becomes_macros() {
        assert_eq!(
            rich_text("$θ_1 · ω$").unwrap(),
            "$\\theta_1 \\cdot \\omega$"
        );
        assert_eq!(rich_text("$\\dot\\theta$").unwrap(), "$\\dot\\theta $");
    }

    #[test]
    fn forbidden_constructs_are_refused() {
        for (bad, what) in [
            ("$\\input{x}$", "`\\input`"),
            ("$\\write18{rm}$", "`\\write`"),
            ("$\\def\\a{b}$", "`\\def`"),
            ("$\\catcode`\\$=11$", "`\\catcode`"),
            ("$\\immediate$", "`\\immediate`"),
            ("$\\csname x\\endcsname$", "`\\csname`"),
            ("$\\textbf{x}$", "`\\textbf`"),
            ("$x^{2$", "not closed"),
            ("$x}$", "closes no"),
            ("un $ seul", "never closed"),
            ("$$x$$", "empty formula"),
            ("$x % y$", "`%`"),
            ("$a & b$", "`&`"),
            ("$x^2^3$", "double superscript"),
            ("$x_1_2$", "double subscript"),
            ("$x^2'$", "double superscript"),
            ("$x_$", "no argument"),
            ("$\\vec$", "no argument"),
            ("$\\left( x$", "no `\\right`"),
            ("$x \\right)$", "no `\\left`"),
            ("$\\left x$", "delimiter"),
            ("$x^\\frac{1}{2}$", "braces"),
            ("$x\\\\y$", "`\\\\`"),
            ("$é$", "`é`"),
        ] {
            let e = rich_text(bad).expect_err(bad);
            assert!(e.message.contains(what), "{bad}: {e}");
        }
    }

    #[test]
    fn text_outside_formulas_is_escaped() {
        assert_eq!(
            rich_text("\\input{x} 50% & # _ ~").unwrap(),
            super::super::escape_text("\\input{x} 50% & # _ ~")
        );
        assert_eq!(rich_text("coût : 5 \\$").unwrap(), "coût : 5 \\$");
        assert_eq!(rich_text("a $x$ b $y$").unwrap(), "a $x$ b $y$");
    }

    #[test]
    fn positions_count_characters() {
        let e = rich_text("θ̇ $\\input$").unwrap_err();
        assert_eq!(e.position, 5);
    }
}
