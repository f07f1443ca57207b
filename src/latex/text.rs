//! Free text with mathematics: the spec's titles, statements, answers and descriptions may hold
//! formulas between `$…$`, written with a small whitelist of macros; everything else is text.
//!
//! The whitelist is what a statement needs to name the course's objects (S1, z⃗0, ℛ0, θ̇1,
//! O1G2 ∧ m2 Γ⃗, ½ m v²) and nothing that can reach the file system, define a macro or change
//! how TeX reads the input: `\input`, `\write18`, `\def`, `\catcode`, `\csname` and every
//! macro not listed are refused, as are unbalanced braces, an unclosed `$` and characters that
//! would end or comment out the formula (`%`, `#`, `&`). Outside `$…$`, text is escaped as
//! [`super::escape_text`] does; `\$` is a literal dollar.

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

/// A formula being checked and copied: `pos` is the index of the next character.
struct Formula<'a> {
    chars: &'a [char],
    pos: usize,
    out: String,
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
        // Whether the current atom already has a superscript, a subscript.
        let (mut sup, mut sub) = (false, false);
        let mut lefts: Vec<usize> = Vec::new();
        loop {
            let Some((t, at)) = self.token()? else {
                return Err(match close {
                    Close::Dollar => self.err(open, "a formula opened by `$` is never closed"),
                    Close::Brace => self.err(open, "a `{` is never closed"),
                });
            };
            match t {
                Token::Dollar => {
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
                Token::Close => {
                    if close == Close::Dollar {
                        return Err(self.err(at, "a `}` closes no `{`"));
                    }
                    if let Some(&l) = lefts.last() {
                        return Err(self.err(l, "a `\\left` has no `\\right` in its group"));
                    }
                    self.out.push('}');
                    return Ok(());
                }
                Token::Script(c) => {
                    let seen = if c == '^' { &mut sup } else { &mut sub };
                    if *seen {
                        let what = if c == '^' { "superscript" } else { "subscript" };
                        return Err(self.err(
                            at,
                            format!("double {what}: put braces around the first one"),
                        ));
                    }
                    *seen = true;
                    self.out.push(c);
                    self.argument(at, &format!("`{c}`"))?;
                }
                Token::Char('\'') => {
                    // A prime is a superscript that a following `^` joins.
                    if sup {
                        return Err(self.err(
                            at,
                            "double superscript: a prime after a superscript needs braces",
                        ));
                    }
                    self.out.push('\'');
                }
                Token::Word(w) if w == "left" || w == "right" => {
                    if w == "left" {
                        lefts.push(at);
                    } else if lefts.pop().is_none() {
                        return Err(self.err(at, "a `\\right` has no `\\left`"));
                    }
                    let _ = write!(self.out, "\\{w}");
                    self.delimiter(at, &w)?;
                    (sup, sub) = (false, false);
                }
                other => {
                    self.atom(other, at)?;
                    (sup, sub) = (false, false);
                }
            }
        }
    }

    /// Copies one atom that starts with token `t`: a character, a group, or a macro with its
    /// arguments.
    fn atom(&mut self, t: Token, at: usize) -> Result<(), RichTextError> {
        match t {
            Token::Char(c) => self.out.push(c),
            Token::Symbol(s) => {
                let _ = write!(self.out, "\\{s}");
            }
            Token::Open => {
                self.out.push('{');
                self.group(Close::Brace, at)?;
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
                let _ = write!(self.out, "\\{w}");
                for _ in 0..args {
                    self.argument(at, &format!("`\\{w}`"))?;
                }
            }
            Token::Close | Token::Dollar | Token::Script(_) => {
                unreachable!("handled by the group")
            }
        }
        Ok(())
    }

    /// The argument of a macro or a script: a group, a character, or a macro without
    /// argument.
    fn argument(&mut self, of_at: usize, of: &str) -> Result<(), RichTextError> {
        let Some((t, at)) = self.token()? else {
            return Err(self.err(of_at, format!("{of} has no argument")));
        };
        match t {
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
