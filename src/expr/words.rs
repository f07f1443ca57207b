//! The words of the expression syntax: what a name may be, the names it reserves, and the
//! constant π, which every registry holds as a variable of its own.

use super::*;

/// A name usable in expressions (parameters, coordinates): an ASCII letter, then letters,
/// digits or `_`, at most 32 characters. (`21` would read as a number.)
///
/// ```
/// assert!(torseur::expr::validate_identifier("theta1").is_ok());
/// assert!(torseur::expr::validate_identifier("21").is_err());
/// assert!(torseur::expr::validate_identifier("m-1").is_err());
/// let e = torseur::expr::validate_identifier("𝜋").unwrap_err();
/// assert!(e.ends_with("; the constant π is written pi: 2*pi*R"), "{e}");
/// ```
pub fn validate_identifier(n: &str) -> Result<(), String> {
    let mut chars = n.chars();
    let first_ok = chars.next().is_some_and(|c| c.is_ascii_alphabetic());
    if !first_ok || n.len() > 32 || !n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
        // What the name was meant to be, when a character says (`𝜋`, `θ1`).
        let fix = (n.chars().map(fix_of).find(|f| !f.is_empty()))
            .map(|f| format!("; {f}"))
            .unwrap_or_default();
        return Err(format!(
            "`{n}` is not a valid name for an expression: a letter, then letters, digits or `_` \
             (at most 32 characters){fix}"
        ));
    }
    Ok(())
}

/// Names reserved by the expression syntax.
pub const RESERVED: &[&str] = &["sin", "cos", "dot", "ddot", "dddot", "pi", "t"];

/// The name of the constant π in every expression (see [`Registry::pi`]).
pub const PI: &str = "pi";

/// The characters a text may hold in place of `pi`: the Greek letter and its variant, the
/// capital, the mathematical italic, bold and double-struck forms (a formula pasted from a
/// document), the n-ary product and the Cyrillic pe.
const PI_LOOKALIKES: &[char] = &[
    'π', 'ϖ', 'Π', 'ℼ', 'ℿ', '∏', 'п', 'ᴨ', '𝛑', '𝛡', '𝜋', '𝜛', '𝝅', '𝝕', '𝝿', '𝞏', '𝞹', '𝟉', '𝚷',
    '𝛱', '𝜫', '𝝥', '𝞟',
];

/// What to type instead of a character that is not ASCII, when it says: a π of any form is
/// `pi`, a Greek letter is its ASCII name, a quote is a time derivative.
///
/// ```
/// assert_eq!(torseur::expr::char_hint('𝜋'), " (the constant π is written pi: 2*pi*R)");
/// assert_eq!(torseur::expr::char_hint('é'), "");
/// ```
pub fn char_hint(c: char) -> String {
    match fix_of(c) {
        "" => String::new(),
        f => format!(" ({f})"),
    }
}

/// [`char_hint`]'s words, empty when the character says nothing.
fn fix_of(c: char) -> &'static str {
    match c {
        _ if PI_LOOKALIKES.contains(&c) => "the constant π is written pi: 2*pi*R",
        '\'' | '’' | '′' => "a time derivative is written dot(q), ddot(q)",
        'θ' | 'φ' | 'ψ' | 'ω' | 'α' | 'β' | 'γ' | 'λ' | 'Ω' | 'ϑ' | 'ϕ' => {
            "names are ASCII: theta, phi, psi…"
        }
        // Mathematical alphanumeric symbols (𝜃, 𝑚): a formula pasted from a document.
        '\u{1D400}'..='\u{1D7FF}' => "names are ASCII letters: theta, m…",
        _ => "",
    }
}

/// A symbol of a text by the name the user typed: symbolica reads `pi` as its own constant,
/// whose name is not `pi`.
pub(super) fn typed_name(s: symbolica::atom::Symbol) -> String {
    if s == symbolica::atom::Symbol::PI {
        return PI.to_string();
    }
    s.get_stripped_name().to_string()
}

/// Why a declared name that is a word of the syntax is refused.
///
/// ```
/// assert_eq!(
///     torseur::expr::reserved_word("pi"),
///     "`pi` is reserved by the expression syntax: it is the constant π"
/// );
/// ```
pub fn reserved_word(n: &str) -> String {
    match n {
        PI => format!("`{n}` is reserved by the expression syntax: it is the constant π"),
        _ => format!("`{n}` is reserved by the expression syntax"),
    }
}

impl Registry {
    /// π, exact: a positive constant of no dimension, a variable of every registry that the
    /// canonical form keeps as it is (never a number), that a spec may divide by like a
    /// parameter, printed `pi` (\pi in the answer key) and evaluated to
    /// [`std::f64::consts::PI`].
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// let reg = Registry::new(&["p".into()], &[]).unwrap();
    /// let e = reg.parse("p/2*pi + pi*p").unwrap();
    /// assert_eq!(e, &reg.rational(3, 2) * &(&reg.pi() * &reg.parse("p").unwrap()));
    /// assert_eq!(e.to_string(), "3/2*p*pi");
    /// ```
    pub fn pi(self: &Rc<Self>) -> Expr {
        self.variable(
            self.index_of(VarRole::Parameter(self.pi))
                .expect("π has a variable"),
        )
    }

    /// Whether a parameter slot is π's.
    pub fn is_pi(&self, i: ParamId) -> bool {
        i == self.pi
    }

    /// The value of a scalar the registry fixes by itself: π's.
    pub fn constant_value(&self, i: ParamId) -> Option<f64> {
        self.is_pi(i).then_some(std::f64::consts::PI)
    }
}
