//! The answer key (« corrigé »): set-up, hypotheses with the particular forms of the inertia
//! matrices, then each requested quantity with the steps of the course's methodology, in the
//! general case and under each hypothesis. All text about the problem comes from the spec.

use super::{
    VectorStyle, basis, basis_vector, escape_text, frame, name, point, quantity, value_styled,
};
use crate::derivation::{Derivation, StepKind, Value, derive};
use crate::inertia::Symmetry;
use crate::mechanism::{Hypothesis, Mechanism};
use crate::quantity::Quantity;
use crate::quantity::QuantityKind;
use crate::spec::wire::{HypothesisSpec, QuestionSpec};
use std::fmt::Write;

fn step_lhs(k: &StepKind) -> String {
    match k {
        StepKind::Quantity(q) => quantity(q),
        StepKind::Derivative(q, r) => format!(
            "\\left[\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}{}\\right]_{{{}}}",
            quantity(q),
            frame(r)
        ),
        StepKind::Action { from, on, point: p } => format!(
            "\\left\\{{\\mathcal{{T}}({} \\rightarrow {})\\right\\}}_{{{}}}",
            action_side(from),
            action_side(on),
            point(p)
        ),
        StepKind::Projected(q, (f, a)) => format!("{} \\cdot {}", quantity(q), basis_vector(*a, f)),
        StepKind::External {
            isolate,
            point: p,
            on: (f, a),
        } => {
            let s = action_side(isolate);
            let arrow = format!("\\bar{{{s}}} \\rightarrow {s}");
            match p {
                Some(p) => format!(
                    "\\overrightarrow{{M({},{arrow})}} \\cdot {}",
                    point(p),
                    basis_vector(*a, f)
                ),
                None => format!(
                    "\\overrightarrow{{R({arrow})}} \\cdot {}",
                    basis_vector(*a, f)
                ),
            }
        }
        StepKind::Complementary(a, g, r) => format!(
            "\\overrightarrow{{V({}/{})}} \\wedge m\\,\\overrightarrow{{V({}/{})}}",
            point(a),
            frame(r),
            point(g),
            frame(r)
        ),
    }
}

/// A solid number as is, a name (`pes`, `moteur`) upright.
fn action_side(n: &str) -> String {
    if n.chars().all(|c| c.is_ascii_digit()) {
        n.to_string()
    } else if n.len() == 1 {
        name(n)
    } else {
        format!("\\mathrm{{{}}}", n.replace('_', "\\_"))
    }
}

fn theorem_text(t: &str) -> String {
    escape_text(t)
}

fn align(body: &str) -> String {
    format!("\\begin{{align*}}\n{body}\n\\end{{align*}}\n")
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
    /// The engine's value.
    pub value: Value,
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

/// The document being written and the record of its formulas.
struct Doc<'m> {
    m: &'m Mechanism,
    style: VectorStyle,
    o: String,
    displays: Vec<Display>,
    inline: Vec<Inline>,
}

impl Doc<'_> {
    /// Writes `lhs = value` as a display and records it.
    fn show(&mut self, role: DisplayRole, what: &str, hyp: Option<&str>, lhs: &str, v: &Value) {
        let body = value_styled(self.m, self.style, lhs, v);
        self.o.push_str(&align(&body));
        self.displays.push(Display {
            role,
            what: what.to_string(),
            hypothesis: hyp.map(str::to_string),
            latex: body,
            value: v.clone(),
        });
    }
}

fn symmetry_text(m: &Mechanism, basis_frame: &str, s: Symmetry, centre: &str) -> String {
    let axes = ['x', 'y', 'z'];
    match s {
        Symmetry::Plane(n) => {
            let others: Vec<String> = (0..3)
                .filter(|&k| k != n.index())
                .map(|k| basis_vector(axes[k], basis_frame))
                .collect();
            format!(
                "le plan $({}, {}, {})$ est un plan de symétrie",
                point(centre),
                others[0],
                others[1]
            )
        }
        Symmetry::Revolution(a) => {
            let _ = m;
            format!(
                "l'axe $({}, {})$ est un axe de révolution",
                point(centre),
                basis_vector(axes[a.index()], basis_frame)
            )
        }
    }
}

/// A hypothesis: its statement, the zeros its symmetries give (each justified by its plane or
/// axis), the particular inertia matrices, and what it sets.
fn hypothesis_block(d: &mut Doc, h: &Hypothesis, hs: &HypothesisSpec) {
    let m = d.m;
    let _ = writeln!(
        d.o,
        "\\subsection*{{Hypothèse {}}}\n{}\n",
        escape_text(&h.name),
        h.text.as_deref().map(escape_text).unwrap_or_default()
    );
    for sname in &hs.symmetric_solids {
        let Some(b) = m.bodies.iter().find(|b| &b.name == sname) else {
            continue;
        };
        let Some(i) = &b.inertia else { continue };
        let bn = m.frame_name(i.basis).to_string();
        let centre = m.point_name(i.point).to_string();
        for s in &b.symmetries {
            let entries: Vec<String> = s
                .zero_entries()
                .iter()
                .map(|&(r, c)| super::expr(&i.matrix[r][c]))
                .filter(|t| t != "0")
                .map(|t| format!("${}$", t.trim_start_matches('-')))
                .collect();
            let _ = writeln!(
                d.o,
                "Pour le solide ${}$, {} : {}{}.\n",
                name(sname),
                symmetry_text(m, &bn, *s, &centre),
                if entries.is_empty() {
                    "les produits d'inertie correspondants sont nuls".to_string()
                } else {
                    format!("les produits d'inertie {} sont nuls", entries.join(", "))
                },
                if s.equal_moments().is_some() {
                    " et les moments d'inertie autour des deux axes orthogonaux sont égaux"
                } else {
                    ""
                }
            );
        }
        let under = Value::Matrix(i.clone()).under(h);
        let lhs = format!("I_{{{}}}({})", point(&centre), name(sname));
        d.show(
            DisplayRole::Inertia,
            &format!("I({centre},{sname})"),
            Some(&h.name),
            &lhs,
            &under,
        );
    }
    if !h.effects.is_empty() {
        let eff: Vec<String> = h
            .effects
            .iter()
            .map(|e| {
                let (l, r) = e.split_once(" = ").unwrap_or((e, "0"));
                let lx = m.reg.parse(l).map(|x| super::expr(&x)).unwrap_or_default();
                let rx = m.reg.parse(r).map(|x| super::expr(&x)).unwrap_or_default();
                format!("${lx} = {rx}$")
            })
            .collect();
        let _ = writeln!(d.o, "Sous cette hypothèse : {}.\n", eff.join(", "));
    }
}

/// A quantity: the steps of the methodology, the result, and the result under each hypothesis.
fn quantity_block(doc: &mut Doc, d: &Derivation) {
    let m = doc.m;
    let q = &d.quantity;
    let title = quantity_title(q);
    let _ = writeln!(doc.o, "\\subsection*{{${title}$}}");
    for s in &d.steps {
        let _ = writeln!(doc.o, "{} :", theorem_text(&s.theorem));
        doc.show(
            DisplayRole::Step,
            &s.label,
            None,
            &step_lhs(&s.kind),
            &s.value,
        );
    }
    doc.o.push_str("Résultat :\n");
    let lhs = match &q.kind {
        k if k.is_torsor() => quantity(k),
        QuantityKind::Inertia { .. } => quantity(&q.kind),
        // An equation of motion is written 0 = … (the residual, dynamic side minus actions).
        QuantityKind::Eom(_) => "0".to_string(),
        _ => title.clone(),
    };
    let id = q.to_string();
    doc.show(DisplayRole::Result, &id, None, &lhs, &d.value);
    for h in &m.hypotheses {
        let under = d.value.under(h);
        if under.exprs() == d.value.exprs() {
            let _ = writeln!(
                doc.o,
                "Sous l'hypothèse {}, le résultat est inchangé.\n",
                escape_text(&h.name)
            );
            continue;
        }
        let _ = writeln!(doc.o, "Sous l'hypothèse {} :", escape_text(&h.name));
        doc.show(DisplayRole::Result, &id, Some(&h.name), &lhs, &under);
    }
}

/// A question: its statement, the teacher's answer text, the hypotheses it discusses, its
/// quantities derived step by step, and its equations written out.
fn question_block(doc: &mut Doc, qs: &QuestionSpec) -> Result<(), crate::derivation::ResolveError> {
    let m = doc.m;
    let _ = writeln!(doc.o, "\\section*{{{}}}", escape_text(&qs.title));
    if let Some(st) = &qs.statement {
        let _ = writeln!(doc.o, "\\emph{{{}}}\n", escape_text(st));
    }
    if let Some(a) = &qs.answer {
        let _ = writeln!(doc.o, "{}\n", escape_text(a));
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
    for text in &qs.quantities {
        let q = Quantity::parse(text).map_err(|e| crate::derivation::ResolveError {
            quantity: text.clone(),
            message: e.to_string(),
        })?;
        quantity_block(doc, &derive(m, &q)?);
    }
    for e in &qs.equations {
        let q = Quantity::parse(&e.quantity).map_err(|er| crate::derivation::ResolveError {
            quantity: e.quantity.clone(),
            message: er.to_string(),
        })?;
        let d = derive(m, &q)?;
        if let Some(r) = &e.reason {
            let _ = writeln!(doc.o, "{} :", escape_text(r));
        }
        let lhs = format!("{} = {}", name(&e.lhs), quantity_title(&q));
        let id = q.to_string();
        doc.show(DisplayRole::Equation, &id, None, &lhs, &d.value);
        for h in &m.hypotheses {
            let under = d.value.under(h);
            if under.exprs() != d.value.exprs() {
                let _ = writeln!(doc.o, "Sous l'hypothèse {} :", escape_text(&h.name));
                doc.show(
                    DisplayRole::Equation,
                    &id,
                    Some(&h.name),
                    &name(&e.lhs),
                    &under,
                );
            }
        }
    }
    Ok(())
}

/// A quantity as a heading: \\overrightarrow{\\delta(O_2,2/0)}\\cdot\\vec{x}_2 for a projection.
fn quantity_title(q: &Quantity) -> String {
    if q.linear {
        let inner = Quantity {
            linear: false,
            ..q.clone()
        };
        return format!("{} \\text{{ (linéarisé)}}", quantity_title(&inner));
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

/// [`answer_key_with`], with the figures of the simulations the questions show.
pub fn answer_key_document(
    m: &Mechanism,
    style: VectorStyle,
) -> Result<AnswerKey, crate::derivation::ResolveError> {
    let mut figures = Vec::new();
    let mut doc = Doc {
        m,
        style,
        o: String::new(),
        displays: Vec::new(),
        inline: Vec::new(),
    };
    let o = &mut doc.o;
    o.push_str(
        "\\documentclass[a4paper,11pt]{article}\n\\usepackage[utf8]{inputenc}\n\
         \\usepackage[T1]{fontenc}\n\\usepackage[french]{babel}\n\\usepackage{lmodern}\n\
         \\usepackage{amsmath,amssymb,graphicx}\n\\usepackage[margin=2cm]{geometry}\n\
         \\allowdisplaybreaks\n\\setlength{\\parindent}{0pt}\n\\setlength{\\parskip}{0.5em}\n",
    );
    let _ = writeln!(
        o,
        "\\title{{Corrigé -- {}}}\n\\author{{torseur}}\n\\date{{}}",
        escape_text(&m.title)
    );
    o.push_str("\\begin{document}\n\\maketitle\n");
    if let Some(d) = &m.description {
        let _ = writeln!(o, "{}\n", escape_text(d));
    }

    // Set-up.
    o.push_str("\\section*{Paramétrage}\n\\begin{itemize}\n");
    for c in &m.spec.coordinates {
        let kind = match c.kind {
            crate::spec::wire::CoordinateKind::Angle => "angle",
            crate::spec::wire::CoordinateKind::Length => "longueur",
        };
        let desc = c
            .description
            .as_deref()
            .map(escape_text)
            .unwrap_or_default();
        let _ = writeln!(o, "\\item ${}(t)$ ({kind}) : {desc}", name(&c.name));
    }
    for f in m.frames.ids().skip(1) {
        let fr = m.frames.get(f);
        let parent = m.frames.get(fr.parent.unwrap_or(m.frames.ground()));
        match &fr.rotation {
            Some(r) => {
                // The course's paramétrage: (x0, x1) = (y0, y1) = θ1 about z0 = z1.
                let k = r.axis.index();
                let (u, v) = (['y', 'z', 'x'][k], ['z', 'x', 'y'][k]);
                let angle = angle_latex(m, &r.angle);
                let _ = writeln!(
                    o,
                    "\\item $({}, {}) = ({}, {}) = {angle}$, autour de ${} = {}$.",
                    basis_vector(u, &parent.name),
                    basis_vector(u, &fr.name),
                    basis_vector(v, &parent.name),
                    basis_vector(v, &fr.name),
                    basis_vector(r.axis.letter(), &parent.name),
                    basis_vector(r.axis.letter(), &fr.name)
                );
            }
            None => {
                let _ = writeln!(
                    o,
                    "\\item La base ${}$ est celle de ${}$.",
                    basis(&fr.name),
                    frame(&parent.name)
                );
            }
        }
    }
    let mut positions = Vec::new();
    for p in m.points.ids().skip(1) {
        let pt = m.points.get(p);
        let from = m.point_name(pt.parent.unwrap_or(m.points.origin()));
        let parts: Vec<String> = pt
            .offset
            .parts()
            .flat_map(|(b, c)| {
                let bn = m.frame_name(b).to_string();
                (0..3)
                    .filter(|&k| !c[k].is_zero())
                    .map(|k| {
                        let e = super::expr(&c[k]);
                        let bv = basis_vector(['x', 'y', 'z'][k], &bn);
                        if c[k].nterms() > 1 {
                            format!("\\left({e}\\right){bv}")
                        } else if e == "1" {
                            bv
                        } else if e == "-1" {
                            format!("-{bv}")
                        } else {
                            format!("{e}\\,{bv}")
                        }
                    })
                    .collect::<Vec<_>>()
            })
            .collect();
        let rhs = if parts.is_empty() {
            "\\vec{0}".to_string()
        } else {
            parts.join(" + ").replace("+ -", "- ")
        };
        let math = format!(
            "\\overrightarrow{{{}{}}} = {rhs}",
            point(from),
            point(&pt.name)
        );
        let _ = writeln!(o, "\\item ${math}$.");
        let ground = m.frames.ground();
        positions.push(Inline {
            what: format!("{from}{}", pt.name),
            latex: math,
            value: Value::Vector {
                basis: ground,
                components: pt.offset.express_in(&m.frames, ground),
            },
        });
    }
    o.push_str("\\end{itemize}\n");
    doc.inline.extend(positions);
    for b in &m.bodies {
        let mass = super::expr(&b.mass);
        let _ = write!(
            doc.o,
            "Solide ${}$ : masse ${mass}$, centre d'inertie ${}$",
            name(&b.name),
            point(m.point_name(b.centre))
        );
        doc.inline.push(Inline {
            what: format!("m({})", b.name),
            latex: mass,
            value: Value::Scalar(b.mass.clone()),
        });
        match &b.inertia {
            Some(i) => {
                doc.o.push_str(", opérateur d'inertie\n");
                let lhs = format!("I_{{{}}}({})", point(m.point_name(i.point)), name(&b.name));
                let what = format!("I({},{})", m.point_name(i.point), b.name);
                doc.show(
                    DisplayRole::Inertia,
                    &what,
                    None,
                    &lhs,
                    &Value::Matrix(i.clone()),
                );
            }
            None => doc.o.push_str(" (masse ponctuelle).\n\n"),
        }
    }

    if m.spec.questions.is_empty() {
        if !m.hypotheses.is_empty() {
            doc.o.push_str("\\section*{Hypothèses}\n");
            for (h, hs) in m.hypotheses.iter().zip(&m.spec.hypotheses) {
                hypothesis_block(&mut doc, h, hs);
            }
        }
        doc.o.push_str("\\section*{Résultats}\n");
        for q in &m.quantities {
            quantity_block(&mut doc, &derive(m, q)?);
        }
    } else {
        for (k, qs) in m.spec.questions.iter().enumerate() {
            question_block(&mut doc, qs)?;
            if let Some(sim) = &qs.simulation {
                let file = format!("simulation-{}.png", k + 1);
                figures.push((file.clone(), simulation_block(&mut doc.o, m, sim, &file)?));
            }
        }
    }
    doc.o.push_str("\\end{document}\n");
    Ok(AnswerKey {
        tex: doc.o,
        figures,
        displays: doc.displays,
        inline: doc.inline,
    })
}

/// The angle of a rotation as written: `\theta_{1}`, `\frac{\pi}{2} - q_{1}`, `\theta - \alpha`.
fn angle_latex(m: &Mechanism, a: &crate::frame::Angle) -> String {
    let mut parts: Vec<(bool, String)> = a
        .terms
        .iter()
        .map(|&(q, n)| {
            let nm = name(&m.reg.coord_info(q).name);
            let body = if n.abs() == 1 {
                nm
            } else {
                format!("{}\\,{nm}", n.abs())
            };
            (n < 0, body)
        })
        .collect();
    let k = a.quarter_turns;
    if k != 0 {
        let body = match k.abs() {
            1 => "\\frac{\\pi}{2}".to_string(),
            2 => "\\pi".to_string(),
            n if n % 2 == 0 => format!("{}\\pi", n / 2),
            n => format!("\\frac{{{n}\\pi}}{{2}}"),
        };
        // A positive offset reads first: π/2 − q rather than −q + π/2.
        if k > 0 && parts.first().is_some_and(|p| p.0) {
            parts.insert(0, (false, body));
        } else {
            parts.push((k < 0, body));
        }
    }
    let mut o = String::new();
    for (i, (neg, body)) in parts.iter().enumerate() {
        o.push_str(match (i, neg) {
            (0, true) => "-",
            (0, false) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        o.push_str(body);
    }
    if o.is_empty() { "0".to_string() } else { o }
}

/// A number as the French text writes it: three significant digits, decimal comma.
fn french(v: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let digits = (2 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    format!("{v:.digits$}").replace('.', "{,}")
}

/// The simulations of a question: the assumed values, the curves, the maxima against the
/// statement's.
fn simulation_block(
    o: &mut String,
    m: &Mechanism,
    sim: &crate::spec::wire::SimulationSpec,
    file: &str,
) -> Result<crate::simulate::Figure, crate::derivation::ResolveError> {
    let fail = |what: &str, e: String| crate::derivation::ResolveError {
        quantity: what.to_string(),
        message: e,
    };
    let mut runs = Vec::new();
    for name in &sim.scenarios {
        runs.push(crate::simulate::simulate(m, name).map_err(|e| fail(name, e.to_string()))?);
    }
    // The assumed values, as the statement gives none.
    if let Some(first) = sim
        .scenarios
        .first()
        .and_then(|n| m.spec.scenarios.iter().find(|s| &s.name == n))
    {
        o.push_str(
            "Le sujet ne donne pas de valeurs numériques : les simulations utilisent les valeurs \
             supposées suivantes (unités SI).\n\n\\begin{center}\n\\begin{tabular}{llll}\n",
        );
        let cells: Vec<String> = first
            .values
            .iter()
            .map(|(k, v)| format!("${} = {}$", name(k), french_sci(*v)))
            .collect();
        for row in cells.chunks(4) {
            let _ = writeln!(o, "{} \\\\", row.join(" & "));
        }
        o.push_str("\\end{tabular}\n\\end{center}\n");
    }
    for (name, sc) in sim.scenarios.iter().filter_map(|n| {
        m.spec
            .scenarios
            .iter()
            .find(|s| &s.name == n)
            .map(|s| (n, s))
    }) {
        if let Some(d) = &sc.description {
            let _ = writeln!(
                o,
                "\\textbf{{{}}} : {}\n",
                escape_text(name),
                escape_text(d)
            );
        }
    }
    let pairs: Vec<(&str, &crate::simulate::Run)> = sim
        .scenarios
        .iter()
        .map(String::as_str)
        .zip(runs.iter())
        .collect();
    let ids: Vec<&str> = sim.plot.iter().map(String::as_str).collect();
    let figure = crate::simulate::figure(&m.title, &pairs, &ids, true);
    let _ = writeln!(
        o,
        "\\begin{{center}}\n\\includegraphics[width=0.85\\textwidth]{{{file}}}\n\\end{{center}}"
    );
    if let Some(col) = &sim.maximum {
        let unit = runs
            .first()
            .and_then(|r| r.columns.iter().find(|c| &c.id == col))
            .map(|c| format!(" ({})", escape_text(&c.unit)))
            .unwrap_or_default();
        let _ = writeln!(
            o,
            "\\begin{{center}}\n\\begin{{tabular}}{{lcc}}\nCas & ${}$ maximal calculé{unit} & \
             ${}$ maximal du sujet{unit} \\\\\n\\hline",
            name(col),
            name(col)
        );
        for (scenario, run) in sim.scenarios.iter().zip(&runs) {
            let (v, t) = run
                .max_abs(col)
                .ok_or_else(|| fail(scenario, format!("no column `{col}` in the run")))?;
            let reference = sim
                .reference
                .get(scenario)
                .map(|r| format!("${}$", french(*r)))
                .unwrap_or_else(|| "--".to_string());
            let _ = writeln!(
                o,
                "{} & ${}$ (à $t = {}$~s) & {} \\\\",
                escape_text(scenario),
                french(v),
                french(t),
                reference
            );
        }
        o.push_str("\\end{tabular}\n\\end{center}\n");
    }
    Ok(figure)
}

/// A value for the table of assumed values: plain when moderate, else a power of ten.
fn french_sci(v: f64) -> String {
    if v == 0.0 {
        return "0".to_string();
    }
    let e = v.abs().log10().floor() as i32;
    if (-2..=3).contains(&e) {
        return format!("{v}").replace('.', "{,}");
    }
    let mant = v / 10f64.powi(e);
    let mant = format!("{mant:.3}");
    let mant = mant
        .trim_end_matches('0')
        .trim_end_matches('.')
        .replace('.', "{,}");
    format!("{mant} \\cdot 10^{{{e}}}")
}
