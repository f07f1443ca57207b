//! The answer key (« corrigé »): the paramétrage and the model's hypotheses once, then each
//! question with the method applied to its objects (see `method`), results already shown
//! cited rather than re-derived, every result boxed. All text about the problem comes from
//! the spec; every formula is recorded with its value so a reader can prove it.

use super::hypotheses::hypothesis_block;
use super::method::quantity_block;
use super::rich_text_or_escaped;
use super::simulation::simulation_block;
use super::theorems::pfd_block;
use super::{VectorStyle, basis, basis_vector, escape_text, name, quantity, value_named};
use crate::derivation::{Value, derive};
use crate::mechanism::{Hypothesis, Mechanism};
use crate::quantity::Quantity;
use crate::quantity::QuantityKind;
use crate::wire::QuestionSpec;
use std::collections::HashMap;
use std::fmt::Write;

/// The preamble: 10 pt on A4 with 1.5 cm margins, tight display and heading spacing, a
/// quantity's heading run into its first line (a corrigé is photocopied: every line counts).
/// A page break just after a display costs a little (`\postdisplaypenalty`), so that a boxed
/// result is not left alone at the top of a page when a break between paragraphs is near.
const PREAMBLE: &str = "\\documentclass[a4paper,10pt]{article}\n\\usepackage[utf8]{inputenc}\n\
\\usepackage[T1]{fontenc}\n\\usepackage[french]{babel}\n\\usepackage{lmodern}\n\
\\usepackage{amsmath,amssymb,graphicx,empheq,multicol,tikz,needspace}\n\\usepackage[margin=1.5cm]{geometry}\n\
\\allowdisplaybreaks[1]\n\\postdisplaypenalty=300\n\\emergencystretch=3em\n\\setlength{\\parindent}{0pt}\n\\setlength{\\parskip}{0.3em}\n\
\\setlength{\\fboxsep}{3pt}\n\\setlength{\\multicolsep}{2pt}\n\\makeatletter\n\
\\g@addto@macro\\normalsize{\\setlength{\\abovedisplayskip}{3pt plus 2pt}\\setlength{\\belowdisplayskip}{3pt plus 2pt}\
\\setlength{\\abovedisplayshortskip}{1pt plus 2pt}\\setlength{\\belowdisplayshortskip}{1pt plus 2pt}}\n\
\\renewcommand\\section{\\@startsection{section}{1}{\\z@}{-1.8ex \\@plus -.5ex \\@minus -.2ex}{0.6ex \\@plus .2ex}{\\normalfont\\large\\bfseries}}\n\
\\renewcommand\\subsubsection{\\@startsection{subsubsection}{3}{\\z@}{-1.2ex \\@plus -.5ex \\@minus -.2ex}{-0.8em}{\\normalfont\\normalsize\\bfseries}}\n\
\\renewcommand\\paragraph{\\@startsection{paragraph}{4}{\\z@}{1ex \\@plus .5ex \\@minus .2ex}{-1em}{\\normalfont\\normalsize\\bfseries}}\n\
\\makeatother\n";

fn align(body: &str) -> String {
    format!("\\begin{{align*}}\n{body}\n\\end{{align*}}\n")
}

/// A boxed display (the results): `empheq`'s frame around an `align*`.
fn boxed(body: &str) -> String {
    format!("\\begin{{empheq}}[box=\\fbox]{{align*}}\n{body}\n\\end{{empheq}}\n")
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
    style: VectorStyle,
    pub(super) o: String,
    displays: Vec<Display>,
    pub(super) inline: Vec<Inline>,
    /// Values already displayed: (left side, canonical value) → where (« la question 3 »).
    shown: HashMap<(String, String), String>,
    /// Isolated systems whose bilan of external actions is written → where.
    pub(super) bilans: HashMap<String, String>,
    /// Hypotheses stated: name, symmetric solids, effects.
    pub(super) stated: Vec<(String, Vec<String>, Vec<String>)>,
    /// Where the text is: « la question 3 ».
    pub(super) here: String,
    /// The hypothesis the current question works under.
    pub(super) under: Option<&'m Hypothesis>,
    /// The results, for the closing bilan: quantity id, hypothesis, value, where.
    pub(super) results: Vec<(String, Option<String>, Value, String)>,
    /// Whether the conditions of the PFD's solution (its pivots that are not numbers,
    /// L ≠ 0) are stated.
    pub(super) conditions_stated: bool,
    /// The links whose Coulomb's law is stated (positions in the spec's `links`).
    pub(super) laws_stated: Vec<usize>,
}

impl<'m> Doc<'m> {
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
        let per_row = if cells.len() > 2 && w + 4 <= super::LINE / 3 {
            3
        } else if w + 4 <= super::LINE / 2 {
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
            super::LINE - 6
        } else {
            super::LINE
        };
        let body = super::value_within(self.m, self.style, lhs, v, None, line);
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
        let body = super::value_within(
            self.m,
            self.style,
            lhs,
            v,
            names.map(|(r, mo)| (r.as_str(), mo.as_str())),
            super::LINE - 6,
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
            value_named(self.m, self.style, l1, v1, None),
            value_named(self.m, self.style, l2, v2, None)
        );
        self.record(role, what, body, v1, Some(v2.clone()), boxed_display);
    }

    /// A law `lhs = b` (Coulomb's T = −f N ε), not boxed: recorded as the equality of the
    /// unknown `a` that `lhs` names and `b`, and remembered.
    pub(super) fn show_law(&mut self, what: &str, lhs: &str, a: &Value, b: &Value) {
        let body = super::value_within(self.m, self.style, lhs, b, None, super::LINE);
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
        let (l, r, lhs) = if super::width(&a_tex) <= super::LINE / 2 {
            (a, b, a_tex)
        } else {
            (b, a, super::expr(b))
        };
        let rv = Value::Scalar(r.clone());
        // The lines of the right side are aligned after the left side. A wide left side over
        // a right side of several lines goes on a line of its own, the right side's lines
        // starting at the margin with its `=` (else they would run into the margin).
        let own_line = super::width(&lhs) > super::LINE / 4
            && super::width(&super::expr(r)) + super::width(&lhs) > super::LINE - 6;
        let lhs = if own_line {
            format!("&{lhs} \\\\\n")
        } else {
            lhs
        };
        let body = super::value_within(self.m, self.style, &lhs, &rv, None, super::LINE - 6);
        self.record(role, what, body, &Value::Scalar(l.clone()), Some(rv), true);
        if let Some(d) = self.displays.last_mut() {
            d.hypothesis = hyp.map(str::to_string);
        }
    }
}

/// A question: its statement, the teacher's answer text, the hypotheses it states, its
/// quantities (kinematics and kinetics step by step, the PFD as bilan and theorems), its
/// equations written out.
fn question_block(doc: &mut Doc, qs: &QuestionSpec) -> Result<(), crate::derivation::ResolveError> {
    let m = doc.m;
    let _ = writeln!(
        doc.o,
        "\\needspace{{8\\baselineskip}}\n\\section*{{{}}}",
        rich_text_or_escaped(&qs.title)
    );
    // A title may hold formulas ($S_1$), which keep their case.
    doc.here = format!(
        "la {}",
        rich_text_or_escaped(&super::text::lowercase_text(&qs.title))
    );
    if let Some(st) = &qs.statement {
        let _ = writeln!(doc.o, "\\emph{{{}}}\n", rich_text_or_escaped(st));
    }
    if let Some(a) = &qs.answer {
        let _ = writeln!(doc.o, "{}\n", rich_text_or_escaped(a));
    }
    for name in &qs.hypotheses {
        if let Some((h, hs)) = m
            .hypotheses
            .iter()
            .zip(&m.spec.hypotheses)
            .find(|(h, _)| &h.name == name)
        {
            hypothesis_block(doc, h, hs);
        }
    }
    doc.under = qs
        .under
        .as_ref()
        .and_then(|n| m.hypotheses.iter().find(|h| &h.name == n));
    if let Some(h) = doc.under
        && !(qs.quantities.is_empty() && qs.equations.is_empty())
    {
        let _ = writeln!(
            doc.o,
            "On se place sous l'hypothèse {}.\n",
            escape_text(&h.name)
        );
    }
    for text in &qs.quantities {
        let q = Quantity::parse(text)
            .map_err(|e| crate::derivation::ResolveError::new(text, e.to_string()))?;
        let d = derive(m, &q)?;
        let title = quantity_title(&q);
        // The heading names the basis asked: the same vector in B2 and in B1 reads apart.
        let heading = match &q.basis {
            Some(b) => format!("{title} \\text{{ dans }} {}", basis(b)),
            None => title.clone(),
        };
        match &q.kind {
            QuantityKind::Unknown(_) | QuantityKind::Eom(_) => pfd_block(doc, &d, &title),
            k => {
                let lhs = match k {
                    k if k.is_torsor() => quantity(k),
                    QuantityKind::Inertia { .. } => quantity(k),
                    QuantityKind::KineticEnergy(_) => quantity(k),
                    _ => title.clone(),
                };
                quantity_block(doc, &d, &heading, &lhs)
            }
        }
    }
    for e in &qs.equations {
        let q = Quantity::parse(&e.quantity)
            .map_err(|er| crate::derivation::ResolveError::new(&e.quantity, er.to_string()))?;
        let d = derive(m, &q)?;
        if let Some(r) = &e.reason {
            let _ = writeln!(doc.o, "{} :", rich_text_or_escaped(r));
        }
        let lhs = format!("{} = {}", name(&e.lhs), quantity_title(&q));
        let id = q.to_string();
        let v = match doc.under {
            Some(h) => d.value.under(h),
            None => d.value.clone(),
        };
        let hyp = doc.under.map(|h| h.name.clone());
        doc.show_result(DisplayRole::Equation, &id, hyp.as_deref(), &lhs, &v, None);
    }
    doc.under = None;
    Ok(())
}

/// A quantity as a heading: \\overrightarrow{\\delta(O_2,2/0)}\\cdot\\vec{x}_2 for a projection.
///
/// ```
/// let q = torseur::Quantity::parse("Omega(2/0)").unwrap();
/// assert_eq!(torseur::latex::quantity_title(&q), "\\overrightarrow{\\Omega(2/0)}");
/// ```
pub fn quantity_title(q: &Quantity) -> String {
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
        return format!("{} \\text{{ (linéarisé{agree})}}", quantity_title(&inner));
    }
    match &q.projection {
        Some((f, axis)) => format!("{} \\cdot {}", quantity(&q.kind), basis_vector(*axis, f)),
        None => quantity(&q.kind),
    }
}

/// The complete answer key of a mechanism as a LaTeX document: the set-up, then either each
/// question of the spec with its answer, or the hypotheses and every requested quantity.
pub fn answer_key(m: &Mechanism) -> Result<String, crate::derivation::ResolveError> {
    answer_key_with(m, VectorStyle::Sum)
}

/// [`answer_key`] with vectors written in the given style.
pub fn answer_key_with(
    m: &Mechanism,
    style: VectorStyle,
) -> Result<String, crate::derivation::ResolveError> {
    answer_key_document(m, style).map(|k| k.tex)
}

/// An answer key with the figures it includes (`\includegraphics{name}`): the caller writes
/// each figure as PNG under its name, next to the .tex file.
pub struct AnswerKey {
    /// The LaTeX document.
    pub tex: String,
    /// File name (`simulation-q7.png`) and figure.
    pub figures: Vec<(String, crate::simulate::Figure)>,
    /// Every displayed formula, in the order of the document, with the value it shows.
    pub displays: Vec<Display>,
    /// The formulas in the text that carry a value (positions of the points, masses).
    pub inline: Vec<Inline>,
}

/// [`answer_key_with`], with the figures of the simulations the questions show
/// (`simulation-7.png` for question 7).
pub fn answer_key_document(
    m: &Mechanism,
    style: VectorStyle,
) -> Result<AnswerKey, crate::derivation::ResolveError> {
    answer_key_named(m, style, "")
}

/// [`answer_key_document`], its figure files named after the key's own file: `prefix`
/// (`corrige-`) before each name (`corrige-simulation-7.png`), so that two keys written in
/// one directory do not share their figures.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let key = torseur::latex::answer_key_named(&m, torseur::latex::VectorStyle::Sum, "k-").unwrap();
/// assert!(key.figures.iter().all(|(n, _)| n.starts_with("k-simulation-")));
/// for (n, _) in &key.figures {
///     assert!(key.tex.contains(&format!("{{{n}}}")));
/// }
/// ```
pub fn answer_key_named(
    m: &Mechanism,
    style: VectorStyle,
    prefix: &str,
) -> Result<AnswerKey, crate::derivation::ResolveError> {
    let _names = super::VectorNames::of(m);
    let mut doc = Doc::new(m, style);
    title_block(&mut doc);
    super::setup::parametrage(&mut doc);
    super::loop_law::loop_law(&mut doc);
    super::helical::links(&mut doc);
    super::setup::solids(&mut doc);
    super::hypotheses::model_hypotheses(&mut doc);
    let figures = questions(&mut doc, prefix)?;
    super::bilan::bilan(&mut doc);
    doc.o.push_str("\\end{document}\n");
    Ok(AnswerKey {
        tex: doc.o,
        figures,
        displays: doc.displays,
        inline: doc.inline,
    })
}

impl<'m> Doc<'m> {
    /// An empty document about `m`, in the paramétrage.
    fn new(m: &'m Mechanism, style: VectorStyle) -> Self {
        Doc {
            m,
            style,
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
        }
    }
}

/// The preamble, the title as a teacher's handout has it (one line, no page of its own) and
/// the problem's description.
fn title_block(doc: &mut Doc) {
    let m = doc.m;
    let o = &mut doc.o;
    o.push_str(PREAMBLE);
    let _ = writeln!(
        o,
        "\\begin{{document}}\n\\begin{{center}}\n{{\\Large\\bfseries Corrigé -- {}\\par}}\n\\end{{center}}",
        rich_text_or_escaped(&m.title)
    );
    if let Some(d) = &m.description {
        let _ = writeln!(o, "{}\n", rich_text_or_escaped(d));
    }
}

/// The questions of the spec with their simulations (figure files named after `prefix`),
/// or, without questions, the hypotheses and every requested quantity.
fn questions(
    doc: &mut Doc,
    prefix: &str,
) -> Result<Vec<(String, crate::simulate::Figure)>, crate::derivation::ResolveError> {
    let m = doc.m;
    let mut figures = Vec::new();
    if m.spec.questions.is_empty() {
        if !m.hypotheses.is_empty() {
            doc.o.push_str("\\section*{Hypothèses}\n");
            for (h, hs) in m.hypotheses.iter().zip(&m.spec.hypotheses) {
                hypothesis_block(doc, h, hs);
            }
        }
        let all = QuestionSpec {
            title: "Résultats".to_string(),
            statement: None,
            answer: None,
            hypotheses: vec![],
            under: None,
            quantities: m.quantities.iter().map(|q| q.to_string()).collect(),
            equations: vec![],
            simulation: None,
        };
        question_block(doc, &all)?;
    } else {
        for (k, qs) in m.spec.questions.iter().enumerate() {
            question_block(doc, qs)?;
            if let Some(sim) = &qs.simulation {
                let file = format!("{prefix}simulation-{}.png", k + 1);
                figures.push((file.clone(), simulation_block(&mut doc.o, m, sim, &file)?));
            }
        }
    }
    Ok(figures)
}
