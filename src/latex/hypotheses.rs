//! A hypothesis in the answer key, stated once: its text, the zeros its symmetries give and
//! the particular inertia matrices; a later hypothesis with the same symmetries refers to it.

use super::Inline;
use super::page::{DisplayRole, Doc};
use super::{escape_text, name, point, rich_text_or_escaped};
use crate::derivation::Value;
use crate::inertia::Symmetry;
use crate::mechanism::{Cause, Effect, Hypothesis, Mechanism, Stated};
use std::fmt::Write;

fn symmetry_text(
    m: &Mechanism,
    names: &super::VectorNames,
    basis_frame: &str,
    s: Symmetry,
    centre: &str,
) -> String {
    let axes = ['x', 'y', 'z'];
    match s {
        Symmetry::Plane(n) => {
            let others: Vec<String> = (0..3)
                .filter(|&k| k != n.index())
                .map(|k| names.basis_vector(axes[k], basis_frame))
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
                names.basis_vector(axes[a.index()], basis_frame)
            )
        }
    }
}

/// A hypothesis, stated once: its text, the zeros its symmetries give (each justified by
/// its plane or axis) and the particular inertia matrices; a later hypothesis with the same
/// symmetries refers to the first and adds only what is new (constant rates).
pub(super) fn hypothesis_block<'m>(d: &mut Doc<'m>, h: &'m Hypothesis) {
    if d.stated.iter().any(|(n, _, _)| n == &h.name) {
        return;
    }
    let _ = writeln!(
        d.o,
        "\\TParagraphe{{Hypothèse {}.}} {}\n",
        escape_text(&h.name),
        h.text
            .as_deref()
            .map(rich_text_or_escaped)
            .unwrap_or_default()
    );
    let same = d
        .stated
        .iter()
        .find(|(_, solids, _)| !solids.is_empty() && *solids == h.symmetric_solids)
        .map(|(n, _, e)| (n.clone(), e.clone()));
    let old_effects: Vec<Effect> = if let Some((other, effects)) = same {
        let _ = writeln!(
            d.o,
            "Les symétries sont celles de l'hypothèse {} : mêmes matrices d'inertie.\n",
            escape_text(&other)
        );
        effects
    } else {
        symmetric_matrices(d, h);
        // The symmetries' zeros are what the matrices show.
        h.effects
            .iter()
            .filter(|e| e.cause == Cause::Symmetry)
            .cloned()
            .collect()
    };
    new_effects(d, h, &old_effects);
    first_order(d, h);
    d.stated.push((
        h.name.clone(),
        h.symmetric_solids.clone(),
        h.effects.clone(),
    ));
}

/// Each symmetric solid's symmetries and its particular inertia matrix under `h`, side by
/// side.
fn symmetric_matrices<'m>(d: &mut Doc<'m>, h: &'m Hypothesis) {
    let m = d.m;
    let mut cells = Vec::new();
    let mut widths = Vec::new();
    for &id in &h.symmetric_solids {
        let b = m.body(id);
        let sname = b.name.as_str();
        let Some(i) = &b.inertia else { continue };
        cells.push(d.capture(|d| {
            let bn = m.frame_name(i.basis).to_string();
            let centre = m.point_name(i.point).to_string();
            if let Some(s) = symmetry_sentence(m, &d.names, sname, b, &bn, &centre) {
                let _ = writeln!(d.o, "{s}");
            }
            let under = Value::Matrix(i.clone()).under(h);
            let lhs = format!("I_{{{}}}({})", point(&centre), name(sname));
            let saved = d.under;
            d.under = Some(h);
            d.show_keyed(
                DisplayRole::Inertia,
                &format!("I({centre},{sname})"),
                &lhs,
                &lhs,
                &under,
                false,
            );
            d.under = saved;
        }));
        widths.push(d.last_width());
    }
    d.rows(&cells, &widths, 2);
}

/// One sentence per solid: its planes and axes of symmetry, then the products of inertia
/// they cancel (and the equal moments of a revolution); none without symmetries.
fn symmetry_sentence(
    m: &Mechanism,
    names: &super::VectorNames,
    sname: &str,
    b: &crate::mechanism::Body,
    bn: &str,
    centre: &str,
) -> Option<String> {
    let i = b.inertia.as_ref()?;
    let mut why = Vec::new();
    let mut zeros: Vec<String> = Vec::new();
    let mut equal = false;
    for s in &b.symmetries {
        why.push(symmetry_text(m, names, bn, *s, centre));
        for t in s
            .zero_entries()
            .iter()
            .map(|&(r, c)| super::expr(&i.matrix[r][c]))
            .filter(|t| t != "0")
            .map(|t| format!("${}$", t.trim_start_matches('-')))
        {
            if !zeros.contains(&t) {
                zeros.push(t);
            }
        }
        equal |= s.equal_moments().is_some();
    }
    if why.is_empty() {
        return None;
    }
    Some(format!(
        "Pour le solide ${}$, {} : {}{}.\n",
        name(sname),
        super::words::french_list(&why),
        if zeros.is_empty() {
            "les produits d'inertie correspondants sont nuls".to_string()
        } else {
            format!(
                "les produits d'inertie {} sont nuls",
                super::words::french_list(&zeros)
            )
        },
        if equal {
            " et les moments d'inertie autour des deux axes orthogonaux sont égaux"
        } else {
            ""
        }
    ))
}

/// « Sous cette hypothèse : … », the effects of `h` not already said (`old_effects`).
fn new_effects(d: &mut Doc, h: &Hypothesis, old_effects: &[Effect]) {
    let side = |s: &Stated| match s {
        Stated::Expr(e) => super::expr(e),
        Stated::Name(n) => name(n),
    };
    let eff: Vec<String> = (h.effects.iter())
        .filter(|e| !old_effects.contains(e))
        .map(|e| format!("${} = {}$", side(&e.lhs), side(&e.rhs)))
        .collect();
    if eff.is_empty() {
        return;
    }
    let _ = writeln!(d.o, "Sous cette hypothèse : {}.\n", eff.join(", "));
}

/// The small parameters of a hypothesis at first order, said once with the hypothesis.
fn first_order(d: &mut Doc, h: &Hypothesis) {
    if h.first_order.is_empty() {
        return;
    }
    let small: Vec<String> = h
        .first_order
        .iter()
        .map(|v| format!("${}$", super::expr(&d.m.reg.variable(*v))))
        .collect();
    let _ = writeln!(
        d.o,
        "Les résultats sont écrits au premier ordre en {} : les termes de degré 2 ou plus \
         en ces petits paramètres sont négligés.\n",
        super::words::french_list(&small)
    );
    // A linearisation keeps one first order in the small parameters and coordinates together.
    let m = d.m;
    if m.dynamics.small.is_empty() || !m.quantities.iter().any(|q| q.linear) {
        return;
    }
    let coordinates: Vec<String> = (m.dynamics.small.iter())
        .map(|s| format!("${}$", super::name(&m.reg.coord_info(s.coord).name)))
        .collect();
    let _ = writeln!(
        d.o,
        "Pour les équations linéarisées, ce premier ordre est pris avec les petits mouvements \
         en {} : le produit d'un petit paramètre par l'une de ces coordonnées ou par sa \
         dérivée est du second ordre, et négligé.\n",
        super::words::french_list(&coordinates)
    );
}

/// The model's hypotheses, stated once: the reference frame, the links, gravity.
pub(super) fn model_hypotheses(doc: &mut Doc) {
    let m = doc.m;
    let ground = super::frame(m.frame_name(m.frames.ground()));
    let mut parts = vec![format!("le référentiel ${ground}$ est galiléen")];
    if let Some(g) = &m.dynamics.gravity {
        parts.push(format!(
            "l'accélération de la pesanteur est ${}$",
            super::values::vector_over_bases(m, &doc.names, g)
        ));
    }
    if !m.links.is_empty() {
        // Friction makes a link imperfect (it dissipates); a spring mounted on it does not.
        let mut said = Vec::new();
        let mut tex = |what: String, e: Option<&crate::expr::Expr>| match e {
            Some(e) => {
                let latex = super::expr(e);
                said.push(Inline {
                    what,
                    latex: latex.clone(),
                    value: Value::Scalar(e.clone()),
                });
                latex
            }
            None => String::new(),
        };
        let lossy: Vec<String> = (m.links.iter())
            .flat_map(|l| {
                let viscous = l.viscous.as_ref().map(|f| {
                    format!(
                        "{} (frottement visqueux de coefficient ${}$)",
                        rich_text_or_escaped(&l.label),
                        tex(format!("friction of {}", l.name), Some(f))
                    )
                });
                let dry = l.dry.as_ref().map(|c| {
                    format!(
                        "{} (frottement sec d'intensité ${}$, opposé au glissement : \
                         ${}$ est le signe de la vitesse relative)",
                        rich_text_or_escaped(&l.label),
                        tex(format!("dry friction of {}", l.name), Some(c)),
                        tex(format!("sign of {}", l.name), l.sign.as_ref())
                    )
                });
                let contact = l.coefficient.as_ref().map(|c| {
                    format!(
                        "{} (frottement sec de coefficient ${}$, loi de Coulomb)",
                        rich_text_or_escaped(&l.label),
                        tex(format!("coefficient of {}", l.name), Some(c))
                    )
                });
                viscous.into_iter().chain(dry).chain(contact)
            })
            .collect();
        parts.push(if lossy.is_empty() {
            "les liaisons sont parfaites".to_string()
        } else {
            format!("les liaisons sont parfaites, sauf {}", lossy.join(" et "))
        });
        for l in &m.links {
            if let Some(sp) = &l.spring {
                let torsion = if sp.torsion { " de torsion" } else { "" };
                parts.push(format!(
                    "un ressort{torsion} de raideur ${}$ agit dans {}",
                    tex(format!("stiffness of {}", l.name), Some(&sp.stiffness)),
                    rich_text_or_escaped(&l.label)
                ));
            }
        }
        doc.inline.extend(said);
    }
    let mut text = parts.join(" ; ");
    if let Some(c) = text.get(..1) {
        text = c.to_uppercase() + &text[1..];
    }
    let _ = writeln!(doc.o, "\\TParagraphe{{Hypothèses du modèle.}} {text}.\n");
}
