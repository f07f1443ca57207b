//! The answer key (« corrigé »): the paramétrage and the model's hypotheses once, then each
//! question with the method applied to its objects (see `method`), results already shown
//! cited rather than re-derived, every result boxed. All text about the problem comes from
//! the spec; every formula is recorded with its value so a reader can prove it.

use super::hypotheses::hypothesis_block;
use super::method::quantity_block;
use super::page::{Display, DisplayRole, Doc, Inline};
use super::rich_text_or_escaped;
use super::simulation::simulation_block;
use super::theorems::pfd_block;
use super::{VectorStyle, basis, escape_text, name};
use crate::derivation::derive;
use crate::mechanism::Mechanism;
use crate::mechanism::{Equation, Question};
use crate::quantity::Quantity;
use crate::quantity::QuantityKind;
use crate::simulate::QuestionRuns;
use std::fmt::Write;

/// The preamble: 10 pt on A4 with 1.5 cm margins, tight display and heading spacing, a
/// quantity's heading run into its first line (a corrigé is photocopied: every line counts).
/// A page break just after a display costs a little (`\postdisplaypenalty`), so that a boxed
/// result is not left alone at the top of a page when a break between paragraphs is near.
/// Its run-in headings are its own sections', defined before the macro block [`MACROS`] (whose
/// class-independent headings serve a fragment).
const PREAMBLE: &str = "\\documentclass[a4paper,10pt]{article}\n\\usepackage[utf8]{inputenc}\n\
\\usepackage[T1]{fontenc}\n\\usepackage[french]{babel}\n\\usepackage{lmodern}\n\
\\usepackage{amsmath,amssymb,graphicx,multicol,tikz,needspace}\n\\usepackage[margin=1.5cm]{geometry}\n\
\\allowdisplaybreaks[1]\n\\postdisplaypenalty=300\n\\emergencystretch=3em\n\\setlength{\\parindent}{0pt}\n\\setlength{\\parskip}{0.3em}\n\
\\setlength{\\fboxsep}{3pt}\n\\setlength{\\multicolsep}{2pt}\n\\makeatletter\n\
\\g@addto@macro\\normalsize{\\setlength{\\abovedisplayskip}{3pt plus 2pt}\\setlength{\\belowdisplayskip}{3pt plus 2pt}\
\\setlength{\\abovedisplayshortskip}{1pt plus 2pt}\\setlength{\\belowdisplayshortskip}{1pt plus 2pt}}\n\
\\renewcommand\\section{\\@startsection{section}{1}{\\z@}{-1.8ex \\@plus -.5ex \\@minus -.2ex}{0.6ex \\@plus .2ex}{\\normalfont\\large\\bfseries}}\n\
\\renewcommand\\subsubsection{\\@startsection{subsubsection}{3}{\\z@}{-1.2ex \\@plus -.5ex \\@minus -.2ex}{-0.8em}{\\normalfont\\normalsize\\bfseries}}\n\
\\renewcommand\\paragraph{\\@startsection{paragraph}{4}{\\z@}{1ex \\@plus .5ex \\@minus .2ex}{-1em}{\\normalfont\\normalsize\\bfseries}}\n\
\\makeatother\n\
\\newcommand\\TTitre[1]{\\subsubsection*{#1}}\n\\newcommand\\TParagraphe[1]{\\paragraph{#1}}\n";

/// The notation of the answer key, one macro per notion, each defined only where the document
/// does not define it already (`\providecommand`): the full document writes the block in its
/// preamble, a fragment at its top, so a teacher's own definitions, made before, win. The
/// heading macros do not depend on the class's sectioning (a run-in heading stays run in).
pub const MACROS: &str = "% Notation du corrigé (torseur) : chaque macro peut être redéfinie avant ce bloc.\n\
\\providecommand\\TVec[1]{\\vec{#1}}% vecteur de base, vecteur nul, résultante\n\
\\providecommand\\TVecLong[1]{\\overrightarrow{#1}}% vecteur nommé : V(G,2/0), OA\n\
\\providecommand\\TMvt[2]{#1/#2}% mouvement de #1 par rapport à #2\n\
\\providecommand\\TTorseur[2]{\\left\\{#1\\right\\}_{#2}}% torseur #1 au point #2\n\
\\providecommand\\TElements[3]{\\left\\{ \\begin{array}{c|c} #1 \\end{array} \\right\\}_{#2,\\,#3}}% éléments de réduction en #2, base #3\n\
\\providecommand\\TDeriv[2]{\\left[\\frac{\\mathrm{d}}{\\mathrm{d}t}#2\\right]_{#1}}% dérivée dans le repère #1\n\
\\providecommand\\TResultat[1]{\\[\\boxed{\\begin{aligned}#1\\end{aligned}}\\]}% résultat encadré\n\
\\providecommand\\TQuestion[1]{\\ifdefined\\needspace\\needspace{8\\baselineskip}\\fi\\section*{#1}}\n\
\\providecommand\\TTitre[1]{\\par\\addvspace{1.2ex}\\noindent\\textbf{#1}\\hspace{0.8em}\\ignorespaces}% titre en ligne\n\
\\providecommand\\TParagraphe[1]{\\par\\addvspace{1ex}\\noindent\\textbf{#1}\\hspace{1em}\\ignorespaces}\n";

/// A question: its statement, the teacher's answer text, the hypotheses it states, its
/// quantities (kinematics and kinetics step by step, the PFD as bilan and theorems), its
/// equations written out.
fn question_block(doc: &mut Doc, qs: &Question) -> Result<(), crate::derivation::DeriveError> {
    question_heading(doc, qs);
    for q in &qs.quantities {
        question_quantity(doc, q)?;
    }
    for e in &qs.equations {
        question_equation(doc, e)?;
    }
    // The spec's own text discusses the results: the method (the isolation, the actions,
    // the theorem) is the writer's, above; a question without results is the text alone.
    if let Some(a) = &qs.answer
        && derives(qs)
    {
        let _ = writeln!(doc.o, "\n{}\n", rich_text_or_escaped(a));
    }
    doc.under = None;
    Ok(())
}

/// Whether a question derives something (quantities or equations): its answer text then
/// discusses the results, after them; else it is the whole answer.
fn derives(qs: &Question) -> bool {
    !(qs.quantities.is_empty() && qs.equations.is_empty())
}

/// A question's title, statement and answer text, the hypotheses it states and the one it
/// works under (kept in `doc.under` for its quantities and equations).
fn question_heading(doc: &mut Doc, qs: &Question) {
    let m = doc.m;
    let _ = writeln!(doc.o, "\\TQuestion{{{}}}", rich_text_or_escaped(&qs.title));
    // A title may hold formulas ($S_1$), which keep their case.
    doc.here = format!(
        "la {}",
        rich_text_or_escaped(&super::text::lowercase_text(&qs.title))
    );
    if let Some(st) = &qs.statement {
        let _ = writeln!(doc.o, "\\emph{{{}}}\n", rich_text_or_escaped(st));
    }
    if let Some(a) = &qs.answer
        && !derives(qs)
    {
        let _ = writeln!(doc.o, "{}\n", rich_text_or_escaped(a));
    }
    for &k in &qs.hypotheses {
        hypothesis_block(doc, &m.hypotheses[k]);
    }
    doc.under = qs.under.map(|k| &m.hypotheses[k]);
    if let Some(h) = doc.under
        && derives(qs)
    {
        let _ = writeln!(
            doc.o,
            "On se place sous l'hypothèse {}.\n",
            escape_text(&h.name)
        );
    }
}

/// A quantity of a question: the PFD for an unknown or an equation of motion, else its
/// method step by step.
fn question_quantity(doc: &mut Doc, q: &Quantity) -> Result<(), crate::derivation::DeriveError> {
    let d = derive(doc.m, q)?;
    let title = doc.names.quantity_title(q);
    // The heading names the basis asked: the same vector in B2 and in B1 reads apart.
    let heading = match &q.basis {
        Some(b) => format!("{title} \\text{{ dans }} {}", basis(b)),
        None => title.clone(),
    };
    match &q.kind {
        QuantityKind::Unknown(n) if crate::derivation::trial_of(doc.m, n).is_some() => {
            super::trial::trial_block(doc, &d, &title)
        }
        QuantityKind::Unknown(_) | QuantityKind::Eom(_) => pfd_block(doc, &d, &title),
        k => {
            let lhs = match k {
                k if k.is_torsor() => doc.names.quantity(k),
                QuantityKind::Inertia { .. } => doc.names.quantity(k),
                QuantityKind::KineticEnergy(_) => doc.names.quantity(k),
                _ => title.clone(),
            };
            quantity_block(doc, &d, &heading, &lhs)
        }
    }
    Ok(())
}

/// An equation of a question (`C_m = δ(O1,E/0)·z0`): its reason, then the equation boxed,
/// under the question's hypothesis.
fn question_equation(doc: &mut Doc, e: &Equation) -> Result<(), crate::derivation::DeriveError> {
    let q = &e.quantity;
    let d = derive(doc.m, q)?;
    if let Some(r) = &e.reason {
        let _ = writeln!(doc.o, "{} :", rich_text_or_escaped(r));
    }
    let lhs = format!("{} = {}", name(&e.lhs), doc.names.quantity_title(q));
    let id = q.to_string();
    let v = match doc.under {
        Some(h) => d.value_under(doc.m, h),
        None => d.value.clone(),
    };
    let hyp = doc.under.map(|h| h.name.clone());
    doc.show_result(DisplayRole::Equation, &id, hyp.as_deref(), &lhs, &v, None);
    Ok(())
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

/// The answer key of `m` from the runs of its simulations, which the caller ran
/// ([`crate::simulate::question_runs`]: one entry per question of the spec): the document
/// draws and tabulates them, it runs nothing. The figure files are named after `prefix`, as
/// [`super::answer_key_named`] says.
pub(super) fn write_answer_key(
    m: &Mechanism,
    style: VectorStyle,
    prefix: &str,
    runs: &[QuestionRuns],
) -> Result<AnswerKey, crate::derivation::DeriveError> {
    let mut doc = Doc::new(m, style);
    set_up(&mut doc);
    let figures = questions(&mut doc, prefix, runs, &|_| true)?;
    super::bilan::bilan(&mut doc);
    doc.o.push_str("\\end{document}\n");
    Ok(AnswerKey {
        tex: doc.o,
        figures,
        displays: doc.displays,
        inline: doc.inline,
    })
}

/// The width of a fragment's line, in characters: a page of 12 pt with margins of 2.5 cm on
/// A4 (16 cm of text) holds about 52 of the full document's (10 pt on 18 cm: [`super::LINE`]),
/// a few less taken as the width of a formula is an estimate.
pub const FRAGMENT_LINE: usize = 48;

/// A fragment of the answer key, to paste into a teacher's own document: the bodies of the
/// questions `chosen` (numbered from 1; all when empty), without `\documentclass`, preamble or
/// `\begin{document}`, headed by the packages they need (in a comment) and the macro block
/// [`MACROS`]. Their lines are broken for a narrower page ([`FRAGMENT_LINE`]). The questions
/// are written as in the full key (a result shown by an earlier question is cited), only the
/// chosen ones kept; the record of displays holds theirs.
pub(super) fn write_fragment(
    m: &Mechanism,
    style: VectorStyle,
    prefix: &str,
    runs: &[QuestionRuns],
    chosen: &[usize],
) -> Result<AnswerKey, crate::derivation::DeriveError> {
    let n = m.statement.questions.len();
    if let Some(k) = chosen.iter().find(|&&k| k == 0 || k > n) {
        return Err(crate::derivation::DeriveError::new(
            &format!("question {k}"),
            format!("the spec has {n} question(s), numbered from 1"),
        ));
    }
    let mut doc = Doc::new(m, style);
    doc.line = FRAGMENT_LINE;
    set_up(&mut doc);
    doc.o.clear();
    doc.displays.clear();
    doc.inline.clear();
    let keep = |k: usize| chosen.is_empty() || chosen.contains(&(k + 1));
    let figures = questions(&mut doc, prefix, runs, &keep)?;
    let asked: Vec<String> = (1..=n)
        .filter(|k| keep(k - 1))
        .map(|k| k.to_string())
        .collect();
    let graphics = if figures.is_empty() { "" } else { ", graphicx" };
    let head = format!(
        "% Corrigé de « {} » (torseur), {} : fragment à coller dans un document.\n\
         % Paquets nécessaires : amsmath{graphics}.\n\
         % Un groupe : les macros et la souplesse des lignes ne valent que pour le fragment.\n\
         \\begingroup\\setlength{{\\emergencystretch}}{{3em}}\n{MACROS}",
        m.title.replace(['\n', '\r'], " "),
        if asked.is_empty() {
            "aucune question (la spec n'en pose pas)".to_string()
        } else {
            format!("question(s) {}", asked.join(", "))
        }
    );
    Ok(AnswerKey {
        tex: head + doc.o.as_str() + "\\par\\endgroup\n",
        figures,
        displays: doc.displays,
        inline: doc.inline,
    })
}

/// What comes before the questions: the preamble and title, the paramétrage, the closure
/// law, the links, the solids and the model's hypotheses.
fn set_up(doc: &mut Doc) {
    title_block(doc);
    super::setup::parametrage(doc);
    super::loop_law::loop_law(doc);
    super::helical::links(doc);
    super::setup::solids(doc);
    super::hypotheses::model_hypotheses(doc);
}

/// The preamble, the title as a teacher's handout has it (one line, no page of its own) and
/// the problem's description.
fn title_block(doc: &mut Doc) {
    let m = doc.m;
    let o = &mut doc.o;
    o.push_str(PREAMBLE);
    o.push_str(MACROS);
    let _ = writeln!(
        o,
        "\\begin{{document}}\n\\begin{{center}}\n{{\\Large\\bfseries Corrigé -- {}\\par}}\n\\end{{center}}",
        rich_text_or_escaped(&m.title)
    );
    if let Some(d) = &m.description {
        let _ = writeln!(o, "{}\n", rich_text_or_escaped(d));
    }
}

/// The questions of the spec with their simulations (`runs`, one entry per question; figure
/// files named after `prefix`),
/// or, without questions, the hypotheses and every requested quantity. A question whose
/// position `keep` refuses is written (what it shows is cited later) and taken out again.
fn questions(
    doc: &mut Doc,
    prefix: &str,
    runs: &[QuestionRuns],
    keep: &dyn Fn(usize) -> bool,
) -> Result<Vec<(String, crate::simulate::Figure)>, crate::derivation::DeriveError> {
    let m = doc.m;
    let mut figures = Vec::new();
    if m.statement.questions.is_empty() {
        if !m.hypotheses.is_empty() {
            doc.o.push_str("\\section*{Hypothèses}\n");
            for h in &m.hypotheses {
                hypothesis_block(doc, h);
            }
        }
        let all = Question {
            title: "Résultats".to_string(),
            statement: None,
            answer: None,
            hypotheses: vec![],
            under: None,
            quantities: m.quantities.clone(),
            equations: vec![],
            simulation: None,
        };
        question_block(doc, &all)?;
    } else {
        for (k, qs) in m.statement.questions.iter().enumerate() {
            let at = (doc.o.len(), doc.displays.len(), doc.inline.len());
            question_block(doc, qs)?;
            if let Some(sim) = &qs.simulation {
                let file = format!("{prefix}simulation-{}.png", k + 1);
                let runs = runs.get(k).ok_or_else(|| {
                    crate::derivation::DeriveError::new(
                        &qs.title,
                        "the runs of its simulation were not given".to_string(),
                    )
                })?;
                let line = doc.line;
                let figure = simulation_block(&mut doc.o, m, sim, runs, (&file, line))?;
                if keep(k) {
                    figures.push((file, figure));
                }
            }
            if !keep(k) {
                doc.o.truncate(at.0);
                doc.displays.truncate(at.1);
                doc.inline.truncate(at.2);
            }
        }
    }
    Ok(figures)
}
