//! The set-up of the answer key: the « Paramétrage » (coordinates and how their rates are
//! known, aliases, frames, positions of the points, the figures planes and the graph of
//! links) and each solid's mass, centre and inertia operator; every formula recorded.

use super::page::{DisplayRole, Doc, Inline};
use super::{basis, name, point, rich_text_or_escaped, rotation_figures};
use crate::derivation::Value;
use crate::mechanism::{Coordinate, DeterminedBy, Mechanism};
use std::fmt::Write;

/// The « Paramétrage » section: an item per coordinate, alias, frame and point in two
/// columns, then the figures.
pub(super) fn parametrage(doc: &mut Doc) {
    doc.o
        .push_str("\\section*{Paramétrage}\n\\begin{multicols}{2}\n\\begin{itemize}\n");
    coordinate_items(doc);
    alias_items(doc);
    frame_items(doc);
    position_items(doc);
    doc.o.push_str("\\end{itemize}\n\\end{multicols}\n");
    setup_figures(doc);
}

/// The paramétrage's item of each coordinate: its description, and how its rate is known
/// (closure, rolling, imposed); an imposed rate's formula is recorded.
fn coordinate_items(doc: &mut Doc) {
    let m = doc.m;
    for c in &m.statement.coordinates {
        let desc = c
            .description
            .as_deref()
            .map(rich_text_or_escaped)
            .unwrap_or_default();
        let t = if c.constant { "" } else { "(t)" };
        let (imposed, rate) = rate_clause(m, c);
        let _ = writeln!(doc.o, "\\item ${}{t}$ : {desc}{imposed}", name(&c.name));
        doc.inline.extend(rate);
    }
}

/// How a coordinate's rate is known, as a clause of its item (« , de vitesse imposée
/// $\dot\psi = \omega$ »), and the imposed rate's formula to record.
fn rate_clause(m: &Mechanism, c: &Coordinate) -> (String, Option<Inline>) {
    // An imposed rate is stated where the coordinate is: ψ̇ = ω.
    let by = c.coord.and_then(|q| m.determined_by(q));
    match (c.coord, by) {
        // Its rate is the loop law's, written after the paramétrage.
        (Some(_), Some(DeterminedBy::Closure)) => (
            ", déterminée par la fermeture géométrique".to_string(),
            None,
        ),
        (Some(_), Some(by @ DeterminedBy::Rolling { .. })) => (
            format!(
                ", de vitesse déterminée par {}",
                by.rolling_name().unwrap_or_default()
            ),
            None,
        ),
        (Some(q), _) if !c.constant && m.reg.coord_info(q).has_imposed_rate() => {
            let rate = m.reg.dot(q);
            let math = format!(
                "{} = {}",
                super::expr::rate(&m.reg, q, 1),
                super::expr(&rate)
            );
            // In one piece: a column break after « = » would split the relation.
            let text = if m.reg.coord_info(q).is_driven() {
                format!(", liée aux autres par \\mbox{{${math}$}}")
            } else {
                format!(", de vitesse imposée \\mbox{{${math}$}}")
            };
            let inline = Inline {
                what: format!("dot({})", c.name),
                latex: math,
                value: Value::Scalar(rate),
            };
            (text, Some(inline))
        }
        _ => (String::new(), None),
    }
}

/// The aliases the statement poses: « On pose K = C ω », each formula recorded.
fn alias_items(doc: &mut Doc) {
    let m = doc.m;
    for (a, (n, v)) in m.statement.aliases.iter().zip(m.reg.aliases()) {
        let math = format!("{} = {}", name(n), super::expr(&v));
        let desc = a
            .as_deref()
            .map(|d| format!(" : {}", rich_text_or_escaped(d)))
            .unwrap_or_default();
        let _ = writeln!(doc.o, "\\item On pose ${math}${desc}.");
        doc.inline.push(Inline {
            what: format!("alias {n}"),
            latex: math,
            value: Value::Scalar(v),
        });
    }
}

/// Each frame's item: its rotation from its parent, or that its basis is its parent's.
fn frame_items(doc: &mut Doc) {
    let m = doc.m;
    for f in m.frames.ids().skip(1) {
        let fr = m.frames.get(f);
        let parent = m.frames.get(fr.parent.unwrap_or(m.frames.ground()));
        match &fr.rotation {
            Some(r) => {
                // The course's paramétrage: (x0, x1) = (y0, y1) = θ1 about z0 = z1.
                let k = r.axis.index();
                let (u, v) = (['y', 'z', 'x'][k], ['z', 'x', 'y'][k]);
                let angle =
                    super::figures::angle_latex(&m.reg, &r.angle.terms, r.angle.quarter_turns);
                let _ = writeln!(
                    doc.o,
                    "\\item $({}, {}) = ({}, {}) = {angle}$, autour de ${} = {}$.",
                    doc.names.basis_vector(u, &parent.name),
                    doc.names.basis_vector(u, &fr.name),
                    doc.names.basis_vector(v, &parent.name),
                    doc.names.basis_vector(v, &fr.name),
                    doc.names.basis_vector(r.axis.letter(), &parent.name),
                    doc.names.basis_vector(r.axis.letter(), &fr.name)
                );
            }
            None => {
                let _ = writeln!(
                    doc.o,
                    "\\item La base ${}$ est confondue avec ${}$.",
                    basis(&fr.name),
                    basis(&parent.name)
                );
            }
        }
    }
}

/// Each point's item: its position from its parent point, recorded with its value in the
/// ground basis.
fn position_items(doc: &mut Doc) {
    let m = doc.m;
    for p in m.points.ids().skip(1) {
        let pt = m.points.get(p);
        let from = m.point_name(pt.parent.unwrap_or(m.points.origin()));
        let rhs = super::values::vector_over_bases(m, &doc.names, &pt.offset);
        let math = format!("\\TVecLong{{{}{}}} = {rhs}", point(from), point(&pt.name));
        let _ = writeln!(doc.o, "\\item ${math}$.");
        let ground = m.frames.ground();
        doc.inline.push(Inline {
            what: format!("{from}{}", pt.name),
            latex: math,
            value: Value::Vector {
                basis: ground,
                components: pt.offset.express_in(&m.frames, ground),
            },
        });
    }
}

/// The figures planes of the rotations and the graph of links, side by side when small.
fn setup_figures(doc: &mut Doc) {
    let m = doc.m;
    let planes = super::figures::rotation_pictures(m, &doc.names);
    let graph = super::figures::link_picture(m, &doc.names);
    let o = &mut doc.o;
    let planes_width = planes.len() as f64 * (super::figures::PLANE_WIDTH + 0.5);
    match graph {
        Some((g, w)) if !planes.is_empty() && planes_width + w + 1.0 <= 17.5 => {
            let _ = write!(
                o,
                "\\begin{{center}}\n{}\\hspace{{2em}}\n{g}\\end{{center}}\n",
                planes.join("\\hspace{1.5em}\n")
            );
        }
        _ => {
            o.push_str(&rotation_figures(m));
            o.push_str(&super::figures::link_graph_with(m, &doc.names));
        }
    }
}

/// Each solid's mass, centre and inertia operator; the operators side by side.
pub(super) fn solids(doc: &mut Doc) {
    let m = doc.m;
    let mut cells = Vec::new();
    let mut widths = Vec::new();
    for b in &m.bodies {
        if b.massless {
            // No mass, centre or operator to state: a line of its own, in the spec's order.
            cells.push(format!(
                "Le solide ${}$ est de masse négligeable : ses torseurs cinétique et dynamique \
                 sont nuls.\n\n",
                super::words::solid(&b.name)
            ));
            widths.push(super::LINE);
            continue;
        }
        let mass = super::expr(&b.mass);
        // A carried solid says what carries it, as the statement does.
        let carried = (b.carried_by)
            .map(|c| format!(", porté par ${}$", super::words::solid(&m.body(c).name)))
            .unwrap_or_default();
        let intro = format!(
            "Solide ${}${carried} : masse ${mass}$, centre d'inertie ${}$",
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
                let lhs = format!("I_{{{}}}({})", point(m.point_name(i.point)), name(&b.name));
                let what = format!("I({},{})", m.point_name(i.point), b.name);
                cells.push(doc.capture(|doc| {
                    let _ = writeln!(doc.o, "{intro}, opérateur d'inertie");
                    doc.show_keyed(
                        DisplayRole::Inertia,
                        &what,
                        &lhs,
                        &lhs,
                        &Value::Matrix(i.clone()),
                        false,
                    );
                }));
                widths.push(doc.last_width());
            }
            None => {
                // A line of its own: the solids then stay in the spec's order.
                cells.push(format!("{intro} (masse ponctuelle).\n\n"));
                widths.push(super::LINE);
            }
        }
    }
    doc.rows(&cells, &widths, 2);
}
