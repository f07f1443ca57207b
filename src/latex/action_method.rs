//! The method's sentence of a quantity that is no theorem's result: an action asked as a
//! quantity (the sum of the bilan's actions at the point asked), a power, a kinetic energy.

use super::{point, quantity_tex};
use crate::derivation::{Derivation, StepKind};
use crate::quantity::QuantityKind;

/// The method of an action asked as a quantity (R(0→1), M(A, ext→E)·z0): the sum of the
/// actions of the bilan cited above, each reduced at the point asked. None when there is
/// nothing to say (one action, asked where it is given).
pub(super) fn action_sentence(m: &crate::mechanism::Mechanism, d: &Derivation) -> Option<String> {
    if let Some(s) = power_sentence(m, d) {
        return Some(s);
    }
    let at = match &d.quantity.kind {
        QuantityKind::ActionResultant(_) => None,
        QuantityKind::ActionMoment { point, .. } | QuantityKind::ActionTorsor { point, .. } => {
            Some(point.as_str())
        }
        _ => return None,
    };
    let points: Vec<&str> = d
        .steps
        .iter()
        .filter_map(|s| match &s.kind {
            StepKind::Action { point, .. } => Some(point.as_str()),
            _ => None,
        })
        .collect();
    let many = points.len() > 1;
    let mut moved: Vec<String> = Vec::new();
    if let Some(a) = at {
        for p in &points {
            let p = super::point(p);
            if *p != *super::point(a) && !moved.contains(&p) {
                moved.push(p);
            }
        }
    }
    let sum = if many {
        ", puis on somme les actions"
    } else {
        ""
    };
    match (at, moved.as_slice()) {
        (Some(a), [_, ..]) => {
            let a = point(a);
            let list = moved
                .iter()
                .map(|p| format!("${p}$"))
                .collect::<Vec<_>>()
                .join(", ");
            Some(if many {
                format!(
                    "Chaque action est réduite en ${a}$ par $\\TVec{{M}}({a}) = \\TVec{{M}}(P) + \
                     \\TVecLong{{{a}P}}\\wedge\\TVec{{R}}$ ($P$ = {list}){sum} :"
                )
            } else {
                let p = &moved[0];
                format!(
                    "Changement de point, de ${p}$ à ${a}$ ($\\TVec{{M}}({a}) = \\TVec{{M}}({p}) + \
                     \\TVecLong{{{a}{p}}}\\wedge\\TVec{{R}}$) :"
                )
            })
        }
        _ if many => Some("On somme les actions :".to_string()),
        _ => None,
    }
}

/// The method of a power: the product of each action's torsor by the kinematic torsor of the
/// solid that receives it, at the action's point (« $\mathcal{P} = \vec{R}\cdot
/// \overrightarrow{V(A\in S/R)} + \vec{M}(A)\cdot\overrightarrow{\Omega(S/R)}$ »); between the
/// solids of a set, in their relative motion.
fn power_sentence(m: &crate::mechanism::Mechanism, d: &Derivation) -> Option<String> {
    let many = d.steps.len() > 1;
    let sum = if many { "\\sum " } else { "" };
    match &d.quantity.kind {
        QuantityKind::Power { reference, .. } => {
            let r = super::escape_ident(reference);
            Some(format!(
                "Puissance {} : ${} = {sum}\\TTorseur{{\\mathcal{{T}}}}{{}}\\otimes\\TTorseur{{\\mathcal{{V}}(\\TMvt{{S}}{{{r}}})}}{{}}$, \
                 produit du torseur de chaque action par le torseur cinématique du solide $S$ qui la \
                 reçoit, réduits au même point{} :",
                if many { "des actions" } else { "de l'action" },
                // A given action by its source, as its torsor prints it.
                super::VectorNames::of(m).quantity(&d.quantity.kind),
                if many { ", puis on somme" } else { "" }
            ))
        }
        QuantityKind::EquivalentInertia(c) => {
            let x = m.reg.coord(c)?;
            let (q, dq) = (super::name(c), super::expr::rate(&m.reg, x, 1));
            let length = m.reg.coord_info(x).kind == crate::expr::CoordinateKind::Length;
            Some(format!(
                "Les vitesses des autres coordonnées se déduisent de ${dq}$ : l'énergie \
                 cinétique du mécanisme s'écrit $E_c = \\frac{{1}}{{2}}\\,{}\\,{dq}^{{2}}$, \
                 où ${}$ est {} ramenée à ${q}$ :",
                quantity_tex(&d.quantity.kind),
                quantity_tex(&d.quantity.kind),
                if length {
                    "la masse équivalente"
                } else {
                    "l'inertie équivalente"
                }
            ))
        }
        QuantityKind::InternalPower(_) if d.steps.is_empty() => Some(format!(
            "Aucune action n'est déclarée entre les solides de l'ensemble : ${} = 0$.",
            quantity_tex(&d.quantity.kind)
        )),
        QuantityKind::InternalPower(_) => Some(format!(
            "Puissance des inter-efforts : ${} = {sum}\\TTorseur{{\\mathcal{{T}}(i\\rightarrow j)}}{{}}\\otimes\\TTorseur{{\\mathcal{{V}}(\\TMvt{{j}}{{i}})}}{{}}$ \
             pour chaque liaison entre deux solides $i$, $j$ de l'ensemble (nulle pour une liaison \
             parfaite) :",
            quantity_tex(&d.quantity.kind)
        )),
        _ => None,
    }
}

/// The method of a kinetic energy: König's theorem applied to each solid, with its objects
/// (« $E_c(2/0) = \frac{1}{2}\,m\,\overrightarrow{V(G,2/0)}^2 + \frac{1}{2}\,
/// \overrightarrow{\Omega(2/0)}\cdot I_G(2)\,\overrightarrow{\Omega(2/0)}$ »; a point mass has
/// no rotation term).
pub(super) fn kinetic_energy_sentence(
    m: &crate::mechanism::Mechanism,
    d: &Derivation,
) -> Option<String> {
    let QuantityKind::KineticEnergy(mo) = &d.quantity.kind else {
        return None;
    };
    // The members of negligible mass were said to have no kinetic energy (their steps).
    let solids: Vec<_> = m
        .solids_of(&mo.moving)?
        .into_iter()
        .filter(|&s| !m.body(s).massless)
        .collect();
    if solids.is_empty() {
        return None;
    }
    let terms: Vec<String> = solids
        .iter()
        .map(|&s| {
            let b = m.body(s);
            let of = |k: QuantityKind| quantity_tex(&k);
            let motion = crate::quantity::Motion {
                moving: b.name.clone(),
                reference: mo.reference.clone(),
            };
            let g = m.point_name(b.centre).to_string();
            let v = of(QuantityKind::Velocity {
                point: g.clone(),
                motion: motion.clone(),
            });
            let mass = super::words::mass_of(m, &b.name);
            let translation = format!("\\frac{{1}}{{2}}\\,{mass}\\,{v}^2");
            if b.inertia.is_none() {
                return translation;
            }
            let w = of(QuantityKind::Omega(motion));
            let i = of(QuantityKind::Inertia {
                point: g,
                solid: b.name.clone(),
            });
            format!("{translation} + \\frac{{1}}{{2}}\\,{w}\\cdot {i}\\,{w}")
        })
        .collect();
    let ec = quantity_tex(&d.quantity.kind);
    Some(format!(
        "Théorème de König{} : ${ec} = {}$ :",
        if solids.len() > 1 {
            ", solide par solide"
        } else {
            ""
        },
        terms.join(" + ")
    ))
}
