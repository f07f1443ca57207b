//! The page being written: the document [`Doc`] that every section of the answer key writes
//! into, with the record of its displayed formulas ([`Display`], [`DisplayRole`]) and of its
//! formulas in the text ([`Inline`]), what it has shown and where, and a quantity as a heading
//! ([`quantity_title`]).

use super::{VectorNames, VectorStyle};
use crate::derivation::Value;
use crate::mechanism::{Hypothesis, Mechanism};
use crate::quantity::Quantity;
use crate::quantity::QuantityKind;
use std::collections::HashMap;
use std::fmt::Write;

fn align(body: &str) -> String {
    format!("\\begin{{align*}}\n{body}\n\\end{{align*}}\n")
}

/// A boxed display (the results): the macro `\TResultat` of the preamble's block (a frame
/// around an `aligned`, which a teacher may redefine), its argument the lines as an `align*`
/// has them.
fn boxed(body: &str) -> String {
    format!("\\TResultat{{\n{body}\n}}\n")
}

/// What a displayed formula shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DisplayRole {
    /// An inertia operator as given by the spec, or its particular form under a hypothesis.
    Inertia,
    /// An intermediate step of a derivation.
    Step,
    /// The result of a question (a requested quantity).
    Result,
    /// An equation of a question (`C_m = …`), solved for an unknown.
    Equation,
}

/// One displayed formula of the answer key: the LaTeX exactly as printed (the body of its
/// `align*`), what it shows, and the engine's value it must equal.
#[derive(Debug, Clone)]
pub struct Display {
    /// What is shown.
    pub role: DisplayRole,
    /// The quantity in the notation (`delta(O2,2/0).x2`), the step's label, or `I(G2,2)`.
    pub what: String,
    /// The hypothesis it is specialised under, if any.
    pub hypothesis: Option<String>,
    /// The LaTeX, exactly as in the document.
    pub latex: String,
    /// The engine's value (of the left side, for an equality).
    pub value: Value,
    /// For an equality `a = b` (a theorem, an equation of motion): the value of `b`.
    pub rhs: Option<Value>,
    /// The solid whose own symbols the left side prints, where the writer chose them from
    /// the mechanism: a complementary term V(A/R) ∧ m V(G/R) of δ(A,S/R) prints the mass m
    /// and the centre G of this solid S. A reader checks the printed symbols against it.
    pub solid: Option<String>,
}

/// A formula inside the text (`$…$`) that shows a value: a point's position
/// (`\overrightarrow{OA} = …`, over the bases it is written in; its value in the ground basis)
/// or a solid's mass.
#[derive(Debug, Clone)]
pub struct Inline {
    /// `OA` for a position, `m(2)` for a mass.
    pub what: String,
    /// The math exactly as printed between the dollars.
    pub latex: String,
    /// The engine's value.
    pub value: Value,
}

/// The document being written, the record of its formulas, and what it has shown.
pub(super) struct Doc<'m> {
    pub(super) m: &'m Mechanism,
    pub(super) style: VectorStyle,
    /// The statement's names of the basis vectors, which every formula of the page uses.
    pub(super) names: VectorNames,
    pub(super) o: String,
    pub(super) displays: Vec<Display>,
    pub(super) inline: Vec<Inline>,
    /// Values already displayed: (left side, canonical value) → where (« la question 3 »).
    shown: HashMap<(String, String), String>,
    /// Isolated systems whose bilan of external actions is written → where.
    pub(super) bilans: HashMap<String, String>,
    /// Hypotheses stated: name, symmetric solids, effects.
    pub(super) stated: Vec<(
        String,
        Vec<crate::mechanism::BodyId>,
        Vec<crate::mechanism::Effect>,
    )>,
    /// Where the text is: « la question 3 ».
    pub(super) here: String,
    /// The hypothesis the current question works under.
    pub(super) under: Option<&'m Hypothesis>,
    /// The results, for the closing bilan: quantity, hypothesis, value, where.
    pub(super) results: Vec<(crate::quantity::Quantity, Option<String>, Value, String)>,
    /// Whether the conditions of the PFD's solution (its pivots that are not numbers,
    /// L ≠ 0) are stated.
    pub(super) conditions_stated: bool,
    /// The links whose Coulomb's law is stated (positions in the spec's `links`).
    pub(super) laws_stated: Vec<usize>,
    /// The width of a line, in characters (see [`super::LINE`]): narrower for a fragment
    /// pasted into a teacher's page.
    pub(super) line: usize,
}

impl<'m> Doc<'m> {
    /// An empty document about `m`, in the paramétrage.
    pub(super) fn new(m: &'m Mechanism, style: VectorStyle) -> Self {
        Doc {
            m,
            style,
            names: VectorNames::of(m),
            o: String::new(),
            displays: Vec::new(),
            inline: Vec::new(),
            shown: HashMap::new(),
            bilans: HashMap::new(),
            stated: Vec::new(),
            here: "le paramétrage".to_string(),
            under: None,
            results: Vec::new(),
            conditions_stated: false,
            laws_stated: Vec::new(),
            line: super::LINE,
        }
    }

    /// What identifies a shown value: its left side and its value, vectors taken in the ground
    /// basis (the same vector shown in B2 and asked in B1 is cited, not re-derived).
    fn key(&self, lhs: &str, v: &Value) -> (String, String) {
        let m = self.m;
        let g = m.frames.ground();
        let ground = |b: crate::frame::FrameId, c: &[crate::expr::Expr; 3]| {
            crate::vector::Vector::new(b, c.clone()).express_in(&m.frames, g)
        };
        let exprs: Vec<crate::expr::Expr> = match v {
            Value::Vector { basis, components } => ground(*basis, components).to_vec(),
            Value::Torsor {
                basis,
                resultant,
                moment,
                ..
            } => {
                let mut e = ground(*basis, resultant).to_vec();
                e.extend(ground(*basis, moment));
                e
            }
            Value::Matrix(i) => {
                let mut e: Vec<crate::expr::Expr> = v.exprs().into_iter().cloned().collect();
                e.push(m.reg.integer(i.basis.index() as i64));
                e
            }
            Value::Scalar(x) => vec![x.clone()],
            Value::Quotient(q) => vec![q.num.clone(), q.den.clone()],
        };
        let vals: Vec<String> = exprs.iter().map(|e| e.to_string()).collect();
        (lhs.to_string(), vals.join(";"))
    }

    /// Where a value with this left side was already shown, if it was.
    pub(super) fn cited(&self, lhs: &str, v: &Value) -> Option<String> {
        self.shown.get(&self.key(lhs, v)).map(|p| {
            if *p == self.here {
                "ce qui précède".to_string()
            } else {
                p.clone()
            }
        })
    }

    /// Whether a hypothesis has been stated already.
    pub(super) fn is_stated(&self, h: &str) -> bool {
        self.stated.iter().any(|(n, _, _)| n == h)
    }

    /// Notes that a value was shown here (in the text).
    pub(super) fn remember(&mut self, lhs: &str, v: &Value) {
        let here = self.here.clone();
        let key = self.key(lhs, v);
        self.shown.entry(key).or_insert(here);
    }

    pub(super) fn record(
        &mut self,
        role: DisplayRole,
        what: &str,
        body: String,
        v: &Value,
        rhs: Option<Value>,
        boxed_display: bool,
    ) {
        // A display continues its sentence's paragraph: a blank line before it would add a
        // paragraph's skip above the display's own.
        while self.o.ends_with("\n\n") {
            self.o.pop();
        }
        self.o.push_str(&if boxed_display {
            boxed(&body)
        } else {
            align(&body)
        });
        self.displays.push(Display {
            role,
            what: what.to_string(),
            hypothesis: self.under.map(|h| h.name.clone()),
            latex: body,
            value: v.clone(),
            rhs,
            solid: None,
        });
    }

    /// Notes that the last display's left side prints the symbols of `solid` (its mass, its
    /// centre), for a reader to check them.
    pub(super) fn names_solid(&mut self, solid: &str) {
        if let Some(d) = self.displays.last_mut() {
            d.solid = Some(solid.to_string());
        }
    }

    /// What `write` adds to the document, taken out of it (to be placed in a cell of
    /// [`Doc::rows`]); the displays it records stay recorded, in order.
    pub(super) fn capture(&mut self, write: impl FnOnce(&mut Self)) -> String {
        let saved = std::mem::take(&mut self.o);
        write(self);
        std::mem::replace(&mut self.o, saved)
    }

    /// Cells side by side (two short torsors of a bilan, two inertia operators), each in a
    /// bottom-aligned minipage so that their displays line up: as many to a row as fit
    /// (`widths`: each cell's display width), at most `most`; cells in order, one under the
    /// other, when one is as wide as the line. A single narrow cell is set as its caption
    /// beside its display. A corrigé uses the width of the page.
    pub(super) fn rows(&mut self, cells: &[String], widths: &[usize], most: usize) {
        let w = widths.iter().copied().max().unwrap_or(0);
        let per_row = if cells.len() > 2 && w + 4 <= self.line / 3 {
            3
        } else if w + 4 <= self.line / 2 {
            2
        } else {
            1
        }
        .min(most);
        if let ([c], 2) = (cells, per_row)
            && let Some(at) = c.find("\\begin{align*}")
        {
            // « Solide 3 : masse m, … » on the left, its operator on the right.
            let (caption, display) = c.split_at(at);
            let _ = write!(
                self.o,
                "\\par\\noindent\n\\begin{{minipage}}[c]{{0.49\\linewidth}}\n{}\n\\end{{minipage}}\\hfill\n\
                 \\begin{{minipage}}[c]{{0.49\\linewidth}}\n{}\\end{{minipage}}\n\\par\n",
                caption.trim_end(),
                display.trim_end()
            );
            return;
        }
        if per_row == 1 || cells.len() == 1 {
            for c in cells {
                self.o.push_str(c);
            }
            return;
        }
        let frac = if per_row == 2 { "0.49" } else { "0.32" };
        for row in cells.chunks(per_row) {
            self.o.push_str("\\par\\noindent\n");
            for (k, c) in row.iter().enumerate() {
                if k > 0 {
                    self.o.push_str("\\hfill\n");
                }
                let _ = write!(
                    self.o,
                    "\\begin{{minipage}}[b]{{{frac}\\linewidth}}\n{}\\end{{minipage}}\n",
                    c.trim_end()
                );
            }
            self.o.push_str("\\par\n");
        }
    }

    /// The printed width of the last display written.
    pub(super) fn last_width(&self) -> usize {
        self.displays
            .last()
            .map(|d| super::display_width(&d.latex))
            .unwrap_or(0)
    }

    /// Writes `lhs = value` as a display, records it, and remembers it under `key_lhs`.
    pub(super) fn show_keyed(
        &mut self,
        role: DisplayRole,
        what: &str,
        lhs: &str,
        key_lhs: &str,
        v: &Value,
        boxed_display: bool,
    ) {
        let line = if boxed_display {
            self.line - 6
        } else {
            self.line
        };
        let body = super::values::value_within(self.m, &self.names, self.style, lhs, v, None, line);
        self.record(role, what, body, v, None, boxed_display);
        self.remember(key_lhs, v);
    }

    /// A result, boxed; a long torsor is written with its elements' names.
    pub(super) fn show_result(
        &mut self,
        role: DisplayRole,
        what: &str,
        hyp: Option<&str>,
        lhs: &str,
        v: &Value,
        names: Option<&(String, String)>,
    ) {
        let body = super::values::value_within(
            self.m,
            &self.names,
            self.style,
            lhs,
            v,
            names.map(|(r, mo)| (r.as_str(), mo.as_str())),
            self.line - 6,
        );
        self.record(role, what, body, v, None, true);
        if let Some(d) = self.displays.last_mut() {
            d.hypothesis = hyp.map(str::to_string);
        }
        self.remember(lhs, v);
    }

    /// An equality written as `body` (`… &= 0`), its left side's value `l` and its right
    /// side's `r`, recorded for the proof.
    pub(super) fn record_equality(
        &mut self,
        role: DisplayRole,
        what: &str,
        body: String,
        l: &Value,
        r: Value,
    ) {
        self.record(role, what, body, l, Some(r), false);
    }

    /// Two scalars, each on its own line: `l1 = v1` and `l2 = v2` (the two sides of a
    /// theorem, stated equal in the sentence before).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn show_equality(
        &mut self,
        role: DisplayRole,
        what: &str,
        l1: &str,
        v1: &Value,
        l2: &str,
        v2: &Value,
        boxed_display: bool,
    ) {
        let body = format!(
            "{} \\\\\n{}",
            super::values::value_within(self.m, &self.names, self.style, l1, v1, None, self.line),
            super::values::value_within(self.m, &self.names, self.style, l2, v2, None, self.line)
        );
        self.record(role, what, body, v1, Some(v2.clone()), boxed_display);
        // The first side (a theorem's dynamic side) may be cited by a later theorem.
        self.remember(l1, v1);
    }

    /// A law `lhs = b` (Coulomb's T = −f N ε), not boxed: recorded as the equality of the
    /// unknown `a` that `lhs` names and `b`, and remembered.
    pub(super) fn show_law(&mut self, what: &str, lhs: &str, a: &Value, b: &Value) {
        let body =
            super::values::value_within(self.m, &self.names, self.style, lhs, b, None, self.line);
        self.record(DisplayRole::Step, what, body, a, Some(b.clone()), false);
        self.remember(lhs, b);
    }

    /// An equation `a = b`, boxed, the shorter side on the left.
    pub(super) fn show_equation(
        &mut self,
        role: DisplayRole,
        what: &str,
        hyp: Option<&str>,
        a: &crate::expr::Expr,
        b: &crate::expr::Expr,
    ) {
        let a_tex = super::expr(a);
        let (l, r, lhs) = if super::width(&a_tex) <= self.line / 2 {
            (a, b, a_tex)
        } else {
            (b, a, super::expr(b))
        };
        let rv = Value::Scalar(r.clone());
        // The lines of the right side are aligned after the left side. A wide left side over
        // a right side of several lines goes on a line of its own, the right side's lines
        // starting at the margin with its `=` (else they would run into the margin).
        let own_line = super::width(&lhs) > self.line / 4
            && super::width(&super::expr(r)) + super::width(&lhs) > self.line - 6;
        let lhs = if own_line {
            format!("&{lhs} \\\\\n")
        } else {
            lhs
        };
        let body = super::values::value_within(
            self.m,
            &self.names,
            self.style,
            &lhs,
            &rv,
            None,
            self.line - 6,
        );
        self.record(role, what, body, &Value::Scalar(l.clone()), Some(rv), true);
        if let Some(d) = self.displays.last_mut() {
            d.hypothesis = hyp.map(str::to_string);
        }
    }
}

impl Doc<'_> {
    /// An equation of motion `l = r`, boxed, its left side (the dynamic side) written as the
    /// `lines` given: on the row of `=` when it fits beside the right side, else on rows of its
    /// own (`&…`, continued by `&\quad …`), the right side after them from `&=`.
    pub(super) fn show_motion(
        &mut self,
        role: DisplayRole,
        (what, hyp): (&str, Option<&str>),
        lines: &[String],
        l: &crate::expr::Expr,
        r: &crate::expr::Expr,
    ) {
        let rv = Value::Scalar(r.clone());
        let max = self.line - 6;
        let one = lines.len() == 1
            && (super::width(&lines[0]) <= self.line / 2
                || super::width(&lines[0]) + super::width(&super::expr(r)) + 3 <= max);
        let body = if one {
            super::values::value_within(self.m, &self.names, self.style, &lines[0], &rv, None, max)
        } else {
            let mut out = format!("&{}", lines[0]);
            for x in &lines[1..] {
                let _ = write!(out, " \\\\\n&\\quad {x}");
            }
            let rl = super::expr::expr_lines(r, max - 4);
            let _ = write!(out, " \\\\\n&= {}", rl[0]);
            for x in &rl[1..] {
                let _ = write!(out, " \\\\\n&\\phantom{{=}} {x}");
            }
            out
        };
        self.record(role, what, body, &Value::Scalar(l.clone()), Some(rv), true);
        if let Some(d) = self.displays.last_mut() {
            d.hypothesis = hyp.map(str::to_string);
        }
    }
}

/// A quantity as a heading: \\overrightarrow{\\delta(O_2,2/0)}\\cdot\\vec{x}_2 for a projection
/// (the course's LaTeX, without the key's notation macros).
///
/// ```
/// let q = torseur::Quantity::parse("Omega(2/0)").unwrap();
/// assert_eq!(torseur::latex::quantity_title(&q), "\\overrightarrow{\\Omega(2/0)}");
/// ```
pub fn quantity_title(q: &Quantity) -> String {
    super::plain(&VectorNames::default().quantity_title(q))
}

/// [`quantity_title`] in the mechanism's own words: the basis vectors by the statement's
/// names, a given action by its source (`\textnormal{poussée}`).
///
/// ```
/// let m = torseur::spec::load("derivations/pendule_sur_chariot.json").unwrap();
/// let q = torseur::Quantity::parse("R(poussee->1)").unwrap();
/// assert_eq!(
///     torseur::latex::quantity_title_in(&m, &q),
///     "\\overrightarrow{R(\\textnormal{poussée} \\rightarrow 1)}"
/// );
/// ```
pub fn quantity_title_in(m: &crate::mechanism::Mechanism, q: &Quantity) -> String {
    super::plain(&VectorNames::of(m).quantity_title(q))
}

impl VectorNames {
    /// [`quantity_title`], the basis vectors by the statement's names.
    pub(super) fn quantity_title(&self, q: &Quantity) -> String {
        if q.linear {
            let inner = Quantity {
                linear: false,
                ..q.clone()
            };
            // « équation … linéarisée », « moment … linéarisé ».
            let agree = if matches!(q.kind, QuantityKind::Eom(_)) {
                "e"
            } else {
                ""
            };
            return format!(
                "{} \\text{{ (linéarisé{agree})}}",
                self.quantity_title(&inner)
            );
        }
        match &q.projection {
            Some((f, axis)) => format!(
                "{} \\cdot {}",
                self.quantity(&q.kind),
                self.basis_vector(*axis, f)
            ),
            None => self.quantity(&q.kind),
        }
    }
}
