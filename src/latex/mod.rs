//! LaTeX in the course's notation: names (θ1 → \theta_{1}), expressions collected by
//! kinematic monomials, vectors on their basis, torsors, inertia matrices; and the answer key.
//!
//! Nothing from a spec reaches the LaTeX unvalidated: identifiers are checked to be ASCII
//! letters, digits and `_` when the spec is loaded, and free text goes through [`escape_text`],
//! or [`rich_text`] where it may hold formulas (checked against a whitelist when the spec is
//! loaded).

mod action_method;
mod bilan;
mod coulomb;
mod document;
mod energy;
mod explicit;
mod expr;
mod fault;
mod figures;
mod greek;
mod helical;
mod hyperstatic;
mod hypotheses;
mod loop_law;
mod method;
mod motion;
mod omega;
mod page;
mod routes;
mod sentences;
mod setup;
mod simulation;
mod source;
mod text;
mod theorems;
mod trial;
mod values;
mod words;

pub use document::{AnswerKey, FRAGMENT_LINE, MACROS};
pub use expr::{expr, expr_lines, fraction};
pub use fault::text_at_fault;
pub use figures::{link_graph, link_text, rotation_figures};
pub use page::{Display, DisplayRole, Inline, quantity_title, quantity_title_in};
pub use source::action_source;
pub use text::{MAX_ARROW_DEPTH, MAX_FORMULA_DEPTH, MAX_LABEL_CHARS, MAX_PROSE_CHARS};
pub use text::{RichTextError, rich_text, rich_text_or_escaped};
pub use values::{matrix, value, value_named, value_styled, vector_column, vector_sum};

use crate::derivation::Value;
use crate::expr::Expr;
use crate::mechanism::Mechanism;
use crate::quantity::{ActionRef, Motion, QuantityKind};
use crate::simulate::QuestionRuns;
use greek::greek;
use std::fmt::Write as _;

/// The complete answer key of a mechanism as a LaTeX document: the set-up, then either each
/// question of the spec with its answer, or the hypotheses and every requested quantity. The
/// simulations the questions show are drawn from `runs`, which the caller ran
/// ([`crate::simulate::question_runs`]: one entry per question); the key runs nothing.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let runs = torseur::simulate::question_runs(&m);
/// let tex = torseur::latex::answer_key(&m, &runs).unwrap();
/// assert!(tex.contains("\\includegraphics"));
/// ```
pub fn answer_key(
    m: &Mechanism,
    runs: &[QuestionRuns],
) -> Result<String, crate::derivation::DeriveError> {
    answer_key_with(m, VectorStyle::Sum, runs)
}

/// [`answer_key`] with vectors written in the given style.
pub fn answer_key_with(
    m: &Mechanism,
    style: VectorStyle,
    runs: &[QuestionRuns],
) -> Result<String, crate::derivation::DeriveError> {
    answer_key_document(m, style, runs).map(|k| k.tex)
}

/// [`answer_key_with`], with the figures of the simulations the questions show
/// (`simulation-7.png` for question 7).
pub fn answer_key_document(
    m: &Mechanism,
    style: VectorStyle,
    runs: &[QuestionRuns],
) -> Result<AnswerKey, crate::derivation::DeriveError> {
    answer_key_named(m, style, "", runs)
}

/// [`answer_key_document`], its figure files named after the key's own file: `prefix`
/// (`corrige-`) before each name (`corrige-simulation-7.png`), so that two keys written in
/// one directory do not share their figures.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let runs = torseur::simulate::question_runs(&m);
/// let style = torseur::latex::VectorStyle::Sum;
/// let key = torseur::latex::answer_key_named(&m, style, "k-", &runs).unwrap();
/// assert!(key.figures.iter().all(|(n, _)| n.starts_with("k-simulation-")));
/// for (n, _) in &key.figures {
///     assert!(key.tex.contains(&format!("{{{n}}}")));
/// }
/// ```
pub fn answer_key_named(
    m: &Mechanism,
    style: VectorStyle,
    prefix: &str,
    runs: &[QuestionRuns],
) -> Result<AnswerKey, crate::derivation::DeriveError> {
    document::write_answer_key(m, style, prefix, runs)
}

/// The bodies of the questions `chosen` (from 1; all when empty) as a fragment to paste into
/// another document: no preamble, the notation's macros as `\providecommand` at its top (a
/// teacher's own definitions win), lines broken for a narrower page; the simulations' runs
/// handed in as [`answer_key_named`] takes them.
///
/// ```
/// let m = torseur::spec::load("derivations/treuil.json").unwrap();
/// let runs = torseur::simulate::question_runs(&m);
/// let style = torseur::latex::VectorStyle::Sum;
/// let f = torseur::latex::answer_key_fragment(&m, style, "", &[1], &runs).unwrap();
/// assert!(!f.tex.contains("\\documentclass") && !f.tex.contains("\\begin{document}"));
/// assert!(f.tex.contains("\\providecommand\\TVec"));
/// ```
pub fn answer_key_fragment(
    m: &Mechanism,
    style: VectorStyle,
    prefix: &str,
    chosen: &[usize],
    runs: &[QuestionRuns],
) -> Result<AnswerKey, crate::derivation::DeriveError> {
    document::write_fragment(m, style, prefix, runs, chosen)
}

const GREEK: &[&str] = &[
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega",
];

/// An identifier as the course writes it: `L1` → `L_{1}`, `theta1` → `\theta_{1}`,
/// `x_a` → `x_{a}`, `omega` → `\omega`; φ and ε in the forms French courses write,
/// `phi` → `\varphi`, `epsilon01` → `\varepsilon_{01}`.
///
/// ```
/// assert_eq!(torseur::latex::name("theta1"), "\\theta_{1}");
/// assert_eq!(torseur::latex::name("phi"), "\\varphi");
/// assert_eq!(torseur::latex::name("A2"), "A_{2}");
/// assert_eq!(torseur::latex::name("lambda"), "\\lambda");
/// assert_eq!(torseur::latex::name("epsilonA"), "\\varepsilon_{A}");
/// ```
pub fn name(n: &str) -> String {
    let safe: String = n
        .chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect();
    // The sign of a link named by a letter under dry friction: `epsilonA` → ε_A.
    let sign =
        (safe.strip_prefix("epsilon")).filter(|r| r.starts_with(|c: char| c.is_ascii_uppercase()));
    let (head, sub) = match safe.split_once('_') {
        Some((h, s)) => (h.to_string(), s.replace('_', "")),
        None if sign.is_some() => ("epsilon".to_string(), sign.unwrap_or_default().to_string()),
        None => {
            let cut = safe
                .char_indices()
                .find(|(i, c)| *i > 0 && c.is_ascii_digit())
                .map(|(i, _)| i)
                .unwrap_or(safe.len());
            (safe[..cut].to_string(), safe[cut..].to_string())
        }
    };
    let head = if matches!(head.as_str(), "phi" | "epsilon") {
        format!("\\var{head}")
    } else if GREEK.contains(&head.as_str()) {
        format!("\\{head}")
    } else if head.len() > 1 {
        format!("\\mathrm{{{head}}}")
    } else {
        head
    };
    if sub.is_empty() {
        head
    } else {
        format!("{head}_{{{sub}}}")
    }
}

/// The LaTeX name of a coordinate: its name, or Ω\,t for the phase of the pulsation Ω.
pub(crate) fn coordinate(reg: &crate::expr::Registry, q: crate::expr::CoordId) -> String {
    let info = reg.coord_info(q);
    match info.phase() {
        Some(w) => format!("{}\\,t", name(w)),
        None => name(&info.name),
    }
}

/// Escapes free text (titles, statements) for LaTeX: every special character is neutralised,
/// so `\input`, `\write18` or unbalanced braces print as text and execute nothing. Greek
/// letters and the dots of θ̇, θ̈ become math. Control characters are dropped, and a combining
/// dot goes only over a letter or a digit this escaper printed itself (elsewhere it is
/// dropped).
///
/// ```
/// assert_eq!(torseur::latex::escape_text("ω, θ̇"), "$\\omega$, $\\dot{\\theta}$");
/// assert_eq!(torseur::latex::escape_text("\\input{x} 50% & $"),
///            "\\textbackslash{}input\\{x\\} 50\\% \\& \\$");
/// assert_eq!(torseur::latex::escape_text("$\u{307}"), "\\$");
/// // Dashes as TeX writes them; a time keeps babel-french's space off its colons.
/// assert_eq!(torseur::latex::escape_text("Treuil — essai à 08:46 : C ≤ 2"),
///            "Treuil --- essai à 08\\string:46 : C $\\leq$ 2");
/// ```
pub fn escape_text(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    // The last character printed, when a combining dot may go over it: where its LaTeX starts
    // in `o`, and its LaTeX in math mode.
    let mut dottable: Option<(usize, String)> = None;
    let mut chars = s.chars().peekable();
    let mut previous = None;
    while let Some(c) = chars.next() {
        let start = o.len();
        let between_digits = previous.is_some_and(|p: char| p.is_ascii_digit())
            && chars.peek().is_some_and(char::is_ascii_digit);
        previous = Some(c);
        let mut letter = None;
        match c {
            '\\' => o.push_str("\\textbackslash{}"),
            '{' => o.push_str("\\{"),
            '}' => o.push_str("\\}"),
            '$' => o.push_str("\\$"),
            '&' => o.push_str("\\&"),
            '#' => o.push_str("\\#"),
            '%' => o.push_str("\\%"),
            '_' => o.push_str("\\_"),
            '^' => o.push_str("\\textasciicircum{}"),
            '~' => o.push_str("\\textasciitilde{}"),
            '<' => o.push_str("\\textless{}"),
            '>' => o.push_str("\\textgreater{}"),
            '\n' | '\r' | '\t' => o.push(' '),
            // C0, DEL and C1: TeX reads them as invalid or undefined characters.
            c if c.is_control() => {}
            // A time or a ratio (08:46, 1:2): not French punctuation, no space before it.
            ':' if between_digits => o.push_str("\\string:"),
            c if c.is_ascii_alphanumeric() => {
                o.push(c);
                letter = Some(format!("\\mathrm{{{c}}}"));
            }
            c if (c as u32) <= 0xFF => o.push(c),
            '’' => o.push('\''),
            '«' | '»' => o.push('"'),
            '∧' => o.push_str("$\\wedge$"),
            '·' => o.push_str("$\\cdot$"),
            '−' => o.push('-'),
            '–' => o.push_str("--"),
            '—' => o.push_str("---"),
            '…' => o.push_str("\\dots{}"),
            '‘' => o.push('`'),
            '“' | '”' => o.push('"'),
            'œ' => o.push_str("\\oe{}"),
            'Œ' => o.push_str("\\OE{}"),
            '\u{202F}' | '\u{2009}' => o.push(' '),
            '≤' => o.push_str("$\\leq$"),
            '≥' => o.push_str("$\\geq$"),
            '≠' => o.push_str("$\\neq$"),
            '≈' => o.push_str("$\\approx$"),
            '→' => o.push_str("$\\rightarrow$"),
            c if greek(c).is_some() => {
                let g = greek(c).unwrap_or_default();
                let _ = write!(o, "$\\{g}$");
                letter = Some(format!("\\{g}"));
            }
            // A combining dot above or two dots (θ̇, θ̈) over the letter just printed:
            // $\theta$ → $\dot{\theta}$, x → $\dot{\mathrm{x}}$.
            '\u{307}' | '\u{308}' => {
                if let Some((at, math)) = dottable.take() {
                    let accent = if c == '\u{307}' { "dot" } else { "ddot" };
                    o.truncate(at);
                    let _ = write!(o, "$\\{accent}{{{math}}}$");
                }
            }
            _ => o.push('?'),
        }
        dottable = letter.map(|l| (start, l));
    }
    o
}

/// A point name: `O2` → `O_{2}`.
pub fn point(n: &str) -> String {
    name(n)
}

/// The basis vectors named as the statement does (\vec{u} rather than \vec{x}_{2}), per frame
/// name, and the given actions by their sources ({T(poussée → 1)}): what the key's writers
/// hold (the page [`page::Doc`], the figures of the rotations) and hand to every function that
/// writes a basis vector or an action. [`VectorNames::default`] names none, as the public
/// functions that take no mechanism write.
#[derive(Debug, Clone, Default)]
pub(crate) struct VectorNames {
    by_frame: std::collections::HashMap<String, [String; 3]>,
    /// Each given action's name → what its torsor prints as exerting it (« poussée »).
    sources: std::collections::HashMap<String, String>,
}

impl VectorNames {
    /// The names of `m`'s frames.
    pub(crate) fn of(m: &Mechanism) -> VectorNames {
        let mut now: std::collections::HashMap<String, [String; 3]> =
            std::collections::HashMap::new();
        // Parents come before their children: a frame that only translates from a named
        // basis has the same vectors, and is written with the same names.
        for f in m.frames.ids() {
            let fr = m.frames.get(f);
            let inherited = match (&fr.rotation, fr.parent) {
                (None, Some(p)) => now.get(&m.frames.get(p).name).cloned(),
                _ => None,
            };
            if let Some(n) = fr.vector_names.clone().or(inherited) {
                now.insert(fr.name.clone(), n);
            }
        }
        // A given action's name, its source (a link's `from` is its solid's name already).
        let sources = (m.dynamics.actions.iter())
            .filter(|a| a.from_label != a.exerted_by)
            .map(|a| (a.from_label.clone(), a.source.clone()))
            .collect();
        VectorNames {
            by_frame: now,
            sources,
        }
    }

    /// An action `from \rightarrow on`, the exterior of `on` written \bar{on}, a given
    /// action by its source (`\textnormal{poussée} \rightarrow 1`).
    pub(crate) fn action(&self, a: &ActionRef) -> String {
        let on = action_side(&a.on);
        let from = match self.sources.get(&a.from) {
            _ if a.from == "ext" => exterior(&on),
            Some(text) => action_source(text),
            None => action_side(&a.from),
        };
        format!("{from} \\rightarrow {on}")
    }

    /// A basis vector the statement names (`u`), in LaTeX.
    pub(crate) fn named_vector(&self, s: &str) -> Option<String> {
        let (frame, k) = self
            .by_frame
            .iter()
            .find_map(|(f, n)| n.iter().position(|x| x == s).map(|k| (f.clone(), k)))?;
        Some(self.basis_vector(['x', 'y', 'z'][k], &frame))
    }

    /// Basis vector `\vec{x}_{2}`, or the statement's name (`\vec{u}`, `\vec{i}_{1}`) when
    /// it names the frame's vectors.
    pub(crate) fn basis_vector(&self, axis: char, frame: &str) -> String {
        let k = match axis {
            'x' => 0,
            'y' => 1,
            _ => 2,
        };
        match self.by_frame.get(frame).map(|n| &n[k]) {
            Some(n) => {
                let latex = name(n);
                match latex.split_once("_{") {
                    Some((head, sub)) => format!("\\TVec{{{head}}}_{{{sub}"),
                    None => format!("\\TVec{{{latex}}}"),
                }
            }
            None => format!("\\TVec{{{axis}}}_{{{}}}", escape_ident(frame)),
        }
    }
}

/// Basis vector `\vec{x}_{2}` (the statement's names of the vectors are the answer key's:
/// its writers hold them).
pub fn basis_vector(axis: char, frame: &str) -> String {
    plain(&VectorNames::default().basis_vector(axis, frame))
}

pub(crate) fn escape_ident(s: &str) -> String {
    s.chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .map(|c| if c == '_' { ' ' } else { c })
        .collect::<String>()
        .replace(' ', "")
}

/// A frame `\mathcal{R}_{0}` and a basis `\mathcal{B}_{2}`.
pub fn frame(n: &str) -> String {
    format!("\\mathcal{{R}}_{{{}}}", escape_ident(n))
}

/// A basis `\mathcal{B}_{2}`.
pub fn basis(n: &str) -> String {
    format!("\\mathcal{{B}}_{{{}}}", escape_ident(n))
}

/// A solid number as is, a name (`pes`, `moteur`) upright; solids isolated together as
/// `1+2`.
pub(crate) fn action_side(n: &str) -> String {
    if n.contains('+') {
        return n.split('+').map(action_side).collect::<Vec<_>>().join("+");
    }
    if n.chars().all(|c| c.is_ascii_digit()) {
        n.to_string()
    } else if n.len() == 1 {
        name(n)
    } else {
        format!("\\mathrm{{{}}}", n.replace('_', "\\_"))
    }
}

/// The exterior of a system written as an action's side (`s` its LaTeX): \bar{1}, and
/// \overline{1+2} over several solids.
pub(crate) fn exterior(s: &str) -> String {
    if s.contains('+') {
        format!("\\overline{{{s}}}")
    } else {
        format!("\\bar{{{s}}}")
    }
}

fn motion(m: &Motion) -> String {
    // Several solids moving together (`1+2`) keep their `+`.
    let moving: Vec<String> = m.moving.split('+').map(escape_ident).collect();
    format!(
        "\\TMvt{{{}}}{{{}}}",
        moving.join("+"),
        escape_ident(&m.reference)
    )
}

/// A quantity in the seed's notation: `\overrightarrow{\delta(O_{2},2/0)}`, `\{\mathcal{D}(2/0)\}_{O_2}`
/// (the course's LaTeX, without the key's notation macros: see [`plain`]).
///
/// ```
/// use torseur::quantity::Quantity;
/// let q = Quantity::parse("{D(2/0)}_O2").unwrap();
/// assert_eq!(torseur::latex::quantity(&q.kind), "\\left\\{\\mathcal{D}(2/0)\\right\\}_{O_{2}}");
/// ```
pub fn quantity(k: &QuantityKind) -> String {
    plain(&quantity_tex(k))
}

/// [`quantity`] in the key's notation macros (`\TVecLong{…}`), as the key's writers print it.
pub(crate) fn quantity_tex(k: &QuantityKind) -> String {
    VectorNames::default().quantity(k)
}

/// The notation macros of [`MACROS`]: name, number of arguments, definition.
fn macro_definitions() -> Vec<(&'static str, usize, &'static str)> {
    MACROS
        .lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("\\providecommand\\")?;
            let (name, rest) = rest.split_once('[')?;
            let (n, rest) = rest.split_once("]{")?;
            let end = group_end(rest)?;
            Some((name, n.parse().ok()?, &rest[..end]))
        })
        .collect()
}

/// `s` with the key's notation macros ([`MACROS`]) replaced by their definitions: the course's
/// plain LaTeX, for a formula written outside the key (a value alone, a figure, Python).
///
/// ```
/// assert_eq!(
///     torseur::latex::plain("\\TVecLong{V(G,\\TMvt{2}{0})} = v\\,\\TVec{x}_{1}"),
///     "\\overrightarrow{V(G,2/0)} = v\\,\\vec{x}_{1}"
/// );
/// ```
pub fn plain(s: &str) -> String {
    let defs = macro_definitions();
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(at) = rest.find('\\') {
        out.push_str(&rest[..at]);
        let after = &rest[at + 1..];
        let len = after
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(after.len());
        let Some((_, k, body)) = defs.iter().find(|d| len > 0 && d.0 == &after[..len]) else {
            // Not a macro of the block: the command (or the escaped character) as it is.
            let take = match len {
                0 => after.chars().next().map_or(0, char::len_utf8),
                n => n,
            };
            out.push('\\');
            out.push_str(&after[..take]);
            rest = &after[take..];
            continue;
        };
        let mut tail = &after[len..];
        let mut expansion = body.to_string();
        for i in 1..=*k {
            let Some(inner) = tail.strip_prefix('{') else {
                break;
            };
            let end = group_end(inner).unwrap_or(inner.len());
            expansion = expansion.replace(&format!("#{i}"), &inner[..end]);
            tail = inner.get(end + 1..).unwrap_or("");
        }
        out.push_str(&plain(&expansion));
        rest = tail;
    }
    out.push_str(rest);
    out
}

impl VectorNames {
    /// [`quantity`], a basis vector (of a derivative's projection) by the statement's name.
    pub(crate) fn quantity(&self, k: &QuantityKind) -> String {
        use QuantityKind::*;
        let arrow = |s: String| format!("\\TVecLong{{{s}}}");
        // A torsor {𝒯(of)} at the point p.
        let torsor = |t: char, of: String, p: &str| {
            format!("\\TTorseur{{\\mathcal{{{t}}}({of})}}{{{}}}", point(p))
        };
        match k {
            Omega(mo) => arrow(format!("\\Omega({})", motion(mo))),
            ActionResultant(a) => arrow(format!("R({})", self.action(a))),
            ActionMoment {
                point: p,
                action: a,
            } => arrow(format!("M({},{})", point(p), self.action(a))),
            ActionTorsor {
                action: a,
                point: p,
            } => torsor('T', self.action(a), p),
            Velocity {
                point: p,
                motion: mo,
            } => arrow(format!("V({},{})", point(p), motion(mo))),
            Acceleration {
                point: p,
                motion: mo,
            } => arrow(format!("\\Gamma({},{})", point(p), motion(mo))),
            Inertia { point: p, solid } => format!("I_{{{}}}({})", point(p), escape_ident(solid)),
            KineticResultant(mo) => arrow(format!("R_c({})", motion(mo))),
            KineticMoment {
                point: p,
                motion: mo,
            } => arrow(format!("\\sigma({},{})", point(p), motion(mo))),
            DynamicResultant(mo) => arrow(format!("R_d({})", motion(mo))),
            DynamicMoment {
                point: p,
                motion: mo,
            } => arrow(format!("\\delta({},{})", point(p), motion(mo))),
            KinematicTorsor {
                motion: mo,
                point: p,
            } => torsor('V', motion(mo), p),
            KineticTorsor {
                motion: mo,
                point: p,
            } => torsor('C', motion(mo), p),
            DynamicTorsor {
                motion: mo,
                point: p,
            } => torsor('D', motion(mo), p),
            KineticEnergy(mo) => format!("E_{{c}}({})", motion(mo)),
            Power {
                action: a,
                reference,
            } => format!(
                "\\mathcal{{P}}({}/{})",
                self.action(a),
                escape_ident(reference)
            ),
            InternalPower(set) => {
                format!("\\mathcal{{P}}_{{\\mathrm{{int}}}}({})", escape_ident(set))
            }
            EquivalentInertia(c) => format!("J_{{\\mathrm{{eq}}}}({})", name(c)),
            Rate { coordinate, order } => expr::rate_of(coordinate, *order),
            Unknown(n) => name(n),
            Eom(q) => format!("\\text{{Équation du mouvement en }} {}", name(q)),
            Derivative { of, frame: r } => self.derivative(of, r.as_deref()),
        }
    }

    /// [d/dt Q]_R of a vector, `\left[\frac{d}{dt}\overrightarrow{\sigma(A,2/0)}\right]_{\mathcal{R}_0}`;
    /// dQ/dt of a scalar, `\frac{dE_c(E/0)}{dt}`, a projection in parentheses.
    fn derivative(&self, of: &crate::quantity::Quantity, r: Option<&str>) -> String {
        let d = "\\mathrm{d}";
        let inner = self.quantity(&of.kind);
        match (r, &of.projection) {
            (Some(r), _) => format!("\\TDeriv{{{}}}{{{inner}}}", frame(r)),
            (None, Some((f, a))) => format!(
                "\\frac{{{d}}}{{{d}t}}\\left({inner} \\cdot {}\\right)",
                self.basis_vector(*a, f)
            ),
            (None, None) => format!("\\frac{{{d}{inner}}}{{{d}t}}"),
        }
    }
}

/// Approximate printed width of LaTeX math, in characters of the body text.
pub(crate) fn width(s: &str) -> usize {
    let mut w = 0usize;
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let mut cmd = String::new();
                while let Some(&d) = chars.peek() {
                    if d.is_ascii_alphabetic() {
                        cmd.push(d);
                        chars.next();
                    } else {
                        break;
                    }
                }
                w += match cmd.as_str() {
                    "" | "left" | "right" | "mathrm" | "dot" | "ddot" | "dddot" | "vec"
                    | "TVec" | "TTorseur" | "TElements" | "TResultat" => 0,
                    // [d/dt …]_R: the brackets and d/dt.
                    "TDeriv" => 6,
                    "frac" => 1,
                    "sin" | "cos" => 3,
                    _ => 1,
                };
                if cmd.is_empty() {
                    chars.next();
                }
            }
            '{' | '}' | '_' | '^' => {}
            ' ' => {}
            '+' | '-' | '=' => w += 2,
            _ => w += 1,
        }
    }
    w
}

/// Approximate printed width of a display body, in characters: its widest line; for an
/// array or a matrix, what stands before it plus its widest row (and the subscript after).
pub(crate) fn display_width(body: &str) -> usize {
    let Some(at) = ["\\begin{array}", "\\begin{pmatrix}", "\\TElements{"]
        .iter()
        .filter_map(|e| body.find(e))
        .min()
    else {
        return body.split("\\\\").map(width).max().unwrap_or(0);
    };
    let (head, inner) = body.split_at(at);
    // A torsor's elements are the first argument of \TElements, closed by its brace.
    let end_of = |inner: &str| match body[at..].starts_with("\\TElements{") {
        true => group_end(inner),
        false => inner.find("\\end{"),
    };
    let inner = inner
        .strip_prefix("\\begin{array}{c|c}")
        .or_else(|| inner.strip_prefix("\\TElements{"))
        .or_else(|| inner.strip_prefix("\\begin{pmatrix}"))
        .unwrap_or(inner);
    let end = end_of(inner).unwrap_or(inner.len());
    let rows = inner[..end].split("\\\\").map(width).max().unwrap_or(0);
    width(head) + rows + 6
}

/// Where the group that `s` is inside closes (`s` starts just after its `{`): the position of
/// its `}`, if it closes.
fn group_end(s: &str) -> Option<usize> {
    let mut depth = 0usize;
    for (i, c) in s.char_indices() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => return Some(i),
            '}' => depth -= 1,
            _ => {}
        }
    }
    None
}

/// Width (in characters) beyond which a vector is written over several lines.
pub const LINE: usize = 70;

/// How vectors are written in the answer key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum VectorStyle {
    /// As a sum over the basis vectors: `a\,\vec{x}_2 + b\,\vec{y}_2` (the default).
    #[default]
    Sum,
    /// As a column with its basis as subscript, when it fits the line (else as a sum).
    Column,
}
