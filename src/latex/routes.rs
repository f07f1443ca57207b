//! The short routes a teacher takes for a projected moment (d/dt(σ·u) at a fixed point on a
//! fixed axis; the change of point to G; a set's σ·u as the sum of its solids'), and V, Γ of
//! a point as derivatives of its position. Each route is taken only when its terms give the
//! engine's value exactly.

use super::omega::{omega_of, omega_sentence};
use super::page::{DisplayRole, Doc};
use super::words::{mass_of, shown_value, solid};
use super::{frame, point, quantity_tex};
use crate::derivation::{Derivation, Value, derive};
use crate::frame::FrameId;
use crate::mechanism::Mechanism;
use crate::quantity::{Motion, Quantity, QuantityKind};
use std::fmt::Write;

/// Shows a vector value computed by the engine, or cites it.
fn show_vector(
    doc: &mut Doc,
    what: &str,
    sentence: &str,
    lhs: &str,
    v: &crate::vector::Vector,
    b: FrameId,
) {
    let value = Value::Vector {
        basis: b,
        components: v.express_in(&doc.m.frames, b),
    };
    let value = shown_value(doc, &value);
    match doc.cited(lhs, &value) {
        Some(place) => {
            let _ = writeln!(
                doc.o,
                "{}",
                super::words::citation(&[(place, vec![lhs.to_string()])])
            );
        }
        None => {
            let _ = writeln!(doc.o, "{sentence}");
            doc.show_keyed(DisplayRole::Step, what, lhs, lhs, &value, false);
        }
    }
}

/// Shows a scalar value computed by the engine.
fn show_scalar(doc: &mut Doc, what: &str, sentence: &str, lhs: &str, e: crate::expr::Expr) {
    let value = shown_value(doc, &Value::Scalar(e));
    let _ = writeln!(doc.o, "{sentence}");
    doc.show_keyed(DisplayRole::Step, what, lhs, lhs, &value, false);
}

/// The short route a teacher takes for a projected dynamic moment δ(A,S/R)·u of one solid:
/// at a point fixed in R on an axis fixed in R, the derivative of σ(A,S/R)·u; elsewhere
/// (A ≠ G), the change of point to the centre of inertia, δ(G)·u + (AG ∧ m Γ(G))·u. Returns
/// false when neither applies (the steps of the vector are then shown).
pub(super) fn projected_moment_route(doc: &mut Doc, d: &Derivation) -> bool {
    let Some(pm) = ProjectedMoment::of(doc.m, &doc.names, d) else {
        return false;
    };
    if pm.fixed {
        fixed_point_route(doc, &pm)
    } else {
        centre_route(doc, &pm)
    }
}

/// A projected dynamic moment δ(A,S/R)·u of one solid, resolved: its objects and their
/// names in LaTeX, and the engine's value the route must give.
struct ProjectedMoment<'d> {
    /// δ(A,S/R)·u as asked.
    kind: &'d QuantityKind,
    a: &'d str,
    mo: &'d Motion,
    s: crate::mechanism::BodyId,
    pa: crate::point::PointId,
    /// The reference frame R.
    rf: FrameId,
    /// The axis u: its frame, its letter, its vector and its LaTeX.
    uf: FrameId,
    ua: crate::frame::Axis,
    u: crate::vector::Vector,
    ul: String,
    /// R and σ(A,S/R) in LaTeX.
    rl: String,
    sigma_a: String,
    /// The basis of the solid's inertia operator, and the basis asked.
    ib: FrameId,
    basis: FrameId,
    result: &'d crate::expr::Expr,
    /// A is at rest in R and u fixed in R.
    fixed: bool,
}

impl<'d> ProjectedMoment<'d> {
    /// The projected dynamic moment of one solid that `d` derives, if it is one.
    fn of(m: &Mechanism, names: &super::VectorNames, d: &'d Derivation) -> Option<Self> {
        use crate::kinematics::{omega, point_velocity};
        let q = &d.quantity;
        let QuantityKind::DynamicMoment {
            point: a,
            motion: mo,
        } = &q.kind
        else {
            return None;
        };
        let r = crate::derivation::bind(m, q).ok()?;
        let (Some((uf, ua)), [s], Some(pa)) = (r.projection, r.solids.as_slice(), r.point) else {
            return None;
        };
        // A body of negligible mass has nothing to derive: its steps say so.
        if m.body(*s).massless {
            return None;
        }
        let rf = r.reference.unwrap_or(m.frames.ground());
        let fixed_axis = omega(m, uf, rf).is_zero(&m.frames);
        // δ(A) = dσ(A)/dt + V(A/R) ∧ m V(G): a point A at rest in R suffices.
        let fixed_point = point_velocity(m, pa, rf).is_zero(&m.frames);
        let Value::Scalar(result) = &d.value else {
            return None;
        };
        Some(ProjectedMoment {
            kind: &q.kind,
            a,
            mo,
            s: *s,
            pa,
            rf,
            uf,
            ua,
            u: crate::vector::Vector::along(uf, ua, m.reg.one()),
            ul: names.basis_vector(ua.letter(), m.frame_name(uf)),
            rl: frame(&mo.reference),
            sigma_a: quantity_tex(&QuantityKind::KineticMoment {
                point: a.clone(),
                motion: mo.clone(),
            }),
            ib: crate::torsor::inertia_basis(m, *s),
            basis: r.basis,
            result,
            fixed: fixed_point && fixed_axis,
        })
    }

    /// Ω(S/R), shown or cited, in the basis of the inertia operator.
    fn show_omega(&self, doc: &mut Doc) {
        let m = doc.m;
        let body = m.body(self.s);
        let om = crate::kinematics::omega(m, body.frame, self.rf);
        let oml = omega_of(&self.mo.moving, &self.mo.reference);
        show_vector(
            doc,
            &format!("Omega({})", self.mo),
            &omega_sentence(m, self.mo),
            &oml,
            &om,
            self.ib,
        );
    }
}

/// At a point fixed in R on an axis fixed in R: Ω, σ(A,S/R), then δ(A)·u as the derivative
/// of σ(A)·u. Taken only when it gives the engine's value exactly.
fn fixed_point_route(doc: &mut Doc, pm: &ProjectedMoment) -> bool {
    let m = doc.m;
    let (a, mo, ul, rl, sigma_a) = (pm.a, pm.mo, &pm.ul, &pm.rl, &pm.sigma_a);
    let body = m.body(pm.s);
    // The route must give the engine's value exactly, or it is not taken.
    let sig = crate::torsor::kinetic_moment_solid(m, pm.s, pm.pa, pm.rf);
    let proj = sig.dot(&m.frames, &pm.u);
    if &proj.dt() != pm.result {
        return false;
    }
    pm.show_omega(doc);
    let oml = omega_of(&mo.moving, &mo.reference);
    let il = format!("I_{{{}}}({})", point(a), mo.moving);
    // σ(A) = I_A Ω only when the point of S at A is at rest; else the general formula.
    let of_solid = crate::kinematics::velocity(m, pm.pa, body.frame, pm.rf).is_zero(&m.frames);
    let gn = m.point_name(body.centre).to_string();
    let sentence = if of_solid {
        format!(
            "${}$ est un point de ${}$ fixe dans ${rl}$ : ${sigma_a} = {il}\\cdot{oml}$ :",
            point(a),
            solid(&mo.moving)
        )
    } else {
        format!(
            "${sigma_a} = {il}\\cdot{oml} + {}\\,\\TVecLong{{{}{}}}\\wedge\\TVecLong{{V({},\\TMvt{{{}}}{{{}}})}}$ :",
            mass_of(m, &mo.moving),
            point(a),
            point(&gn),
            point(a),
            mo.moving,
            mo.reference
        )
    };
    show_vector(
        doc,
        &format!("sigma({a},{mo})"),
        &sentence,
        sigma_a,
        &sig,
        pm.ib,
    );
    show_scalar(
        doc,
        &format!("sigma({a},{mo}).{}{}", pm.ua.letter(), m.frame_name(pm.uf)),
        &format!(
            "${}$ est fixe dans ${rl}$ et ${ul}$ aussi : ${} \\cdot {ul} = \\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}\\left({sigma_a}\\cdot {ul}\\right)$, avec :",
            point(a),
            quantity_tex(pm.kind)
        ),
        &format!("{sigma_a}\\cdot {ul}"),
        proj,
    );
    true
}

/// Elsewhere (A ≠ G), the change of point to the centre of inertia: δ(G)·u + (AG ∧ m Γ(G))·u,
/// each term shown. Taken only when it gives the engine's value exactly.
fn centre_route(doc: &mut Doc, pm: &ProjectedMoment) -> bool {
    let m = doc.m;
    let body = m.body(pm.s);
    let g = body.centre;
    if pm.pa == g {
        return false;
    }
    let dg = crate::torsor::dynamic_moment_solid(m, pm.s, g, pm.rf).dot(&m.frames, &pm.u);
    let gam = crate::kinematics::acceleration(m, g, body.frame, pm.rf);
    let ag = crate::kinematics::position(m, pm.pa, g);
    let transport = ag
        .cross(&m.frames, &gam.scale(&body.mass))
        .dot(&m.frames, &pm.u);
    // δ(A)·u = δ(G)·u + (AG ∧ m Γ(G))·u must give the engine's value exactly.
    if &(&dg + &transport) != pm.result {
        return false;
    }
    let terms = CentreTerms {
        gn: m.point_name(g).to_string(),
        dg,
        gam,
        transport,
    };
    centre_route_intro(doc, pm, &terms);
    centre_route_terms(doc, pm, terms);
    true
}

/// The terms of δ(A)·u through the centre of inertia G: δ(G)·u, Γ(G), (AG ∧ m Γ(G))·u.
struct CentreTerms {
    gn: String,
    dg: crate::expr::Expr,
    gam: crate::vector::Vector,
    transport: crate::expr::Expr,
}

/// δ(G) and Γ(G) of the solid's motion.
fn centre_kinds(pm: &ProjectedMoment, gn: &str) -> (QuantityKind, QuantityKind) {
    (
        QuantityKind::DynamicMoment {
            point: gn.to_string(),
            motion: pm.mo.clone(),
        },
        QuantityKind::Acceleration {
            point: gn.to_string(),
            motion: pm.mo.clone(),
        },
    )
}

/// The change of point written out, then Ω and σ(G) = I_G Ω.
fn centre_route_intro(doc: &mut Doc, pm: &ProjectedMoment, t: &CentreTerms) {
    let m = doc.m;
    let (a, mo, ul, gn) = (pm.a, pm.mo, &pm.ul, &t.gn);
    let (delta_g, gamma) = centre_kinds(pm, gn);
    let mass = mass_of(m, &mo.moving);
    let _ = writeln!(
        doc.o,
        "Changement de point vers le centre d'inertie :\n\\[{} \\cdot {ul} = {} \\cdot {ul} + \\left(\\TVecLong{{{}{}}}\\wedge {mass}\\,{}\\right)\\cdot {ul}\\]",
        quantity_tex(pm.kind),
        quantity_tex(&delta_g),
        point(a),
        point(gn),
        quantity_tex(&gamma)
    );
    pm.show_omega(doc);
    let oml = omega_of(&mo.moving, &mo.reference);
    let sigma_g = quantity_tex(&QuantityKind::KineticMoment {
        point: gn.clone(),
        motion: mo.clone(),
    });
    let sig = crate::torsor::kinetic_moment_solid(m, pm.s, m.body(pm.s).centre, pm.rf);
    show_vector(
        doc,
        &format!("sigma({gn},{mo})"),
        &format!(
            "En ${}$, centre d'inertie : ${sigma_g} = I_{{{}}}({})\\cdot{oml}$ :",
            point(gn),
            point(gn),
            mo.moving
        ),
        &sigma_g,
        &sig,
        pm.ib,
    );
}

/// δ(G)·u as the derivative of σ(G), Γ(G), and the term of transport.
fn centre_route_terms(doc: &mut Doc, pm: &ProjectedMoment, t: CentreTerms) {
    let m = doc.m;
    let (a, mo, ul, rl, gn) = (pm.a, pm.mo, &pm.ul, &pm.rl, &t.gn);
    let (delta_g, gamma) = centre_kinds(pm, gn);
    let mass = mass_of(m, &mo.moving);
    let sigma_g = quantity_tex(&QuantityKind::KineticMoment {
        point: gn.clone(),
        motion: mo.clone(),
    });
    show_scalar(
        doc,
        &format!("delta({gn},{mo}).{}{}", pm.ua.letter(), m.frame_name(pm.uf)),
        &format!(
            "${} = \\TDeriv{{{rl}}}{{{sigma_g}}}$ (centre d'inertie), projeté sur ${ul}$ :",
            quantity_tex(&delta_g)
        ),
        &format!("{} \\cdot {ul}", quantity_tex(&delta_g)),
        t.dg,
    );
    show_vector(
        doc,
        &format!("Gamma({gn},{mo})"),
        &format!("Accélération de ${}$ :", point(gn)),
        &quantity_tex(&gamma),
        &t.gam,
        pm.basis,
    );
    show_scalar(
        doc,
        "transport",
        "Terme de transport :",
        &format!(
            "\\left(\\TVecLong{{{}{}}}\\wedge {mass}\\,{}\\right)\\cdot {ul}",
            point(a),
            point(gn),
            quantity_tex(&gamma)
        ),
        t.transport,
    );
}

/// V(P,S/R) and Γ(P,S/R) have no steps of their own: the method sentence (derivative of the
/// position from the ground origin, fixed in R), and for Γ the velocity first.
pub(super) fn position_route(doc: &mut Doc, d: &Derivation) {
    let m = doc.m;
    let (p, mo, accel) = match &d.quantity.kind {
        QuantityKind::Velocity { point, motion } => (point, motion, false),
        QuantityKind::Acceleration { point, motion } => (point, motion, true),
        _ => return,
    };
    // d/dt O0P in R is V(P,S/R) only for P fixed in S, R the ground (where O0 is fixed).
    let moving = m
        .bodies
        .iter()
        .find(|b| b.name == mo.moving)
        .map(|b| b.frame)
        .or_else(|| m.frames.find(&mo.moving));
    let (Some(pid), Some(sf), Some(rf)) = (m.points.find(p), moving, m.frames.find(&mo.reference))
    else {
        return;
    };
    if rf != m.frames.ground() || !crate::kinematics::is_fixed_in(m, pid, sf) {
        return;
    }
    let o = m.point_name(m.points.origin()).to_string();
    let rl = frame(&mo.reference);
    let vk = QuantityKind::Velocity {
        point: p.clone(),
        motion: mo.clone(),
    };
    let vl = quantity_tex(&vk);
    if !accel {
        let _ = writeln!(doc.o, "{}", position_sentence(&vl, &o, p, &mo.reference));
        return;
    }
    // Γ: the velocity first (shown or cited), in the basis of the result.
    let Value::Vector { basis, .. } = &d.value else {
        return;
    };
    let vq = Quantity {
        kind: vk.clone(),
        basis: Some(m.frame_name(*basis).to_string()),
        projection: None,
        linear: false,
    };
    if derived_step(doc, &vq, &vl, &position_sentence(&vl, &o, p, &mo.reference)).is_none() {
        return;
    }
    let _ = writeln!(
        doc.o,
        "${} = \\TDeriv{{{rl}}}{{{vl}}}$ :",
        quantity_tex(&d.quantity.kind)
    );
}

/// « V(P,S/R) = [d/dt O0P]_R (O0 fixe dans R) : », the velocity of a point fixed in its solid.
pub(super) fn position_sentence(vl: &str, o: &str, p: &str, r: &str) -> String {
    format!(
        "${vl} = \\TDeriv{{{}}}{{\\TVecLong{{{}{}}}}}$ (${}$ fixe dans ${}$) :",
        frame(r),
        point(o),
        point(p),
        point(o),
        frame(r)
    )
}

/// A quantity derived by the engine (`V(G2,2/0) in B2`) shown with its sentence, or cited
/// where it was shown already; its value as shown, or None when it does not derive.
pub(super) fn derived_step(
    doc: &mut Doc,
    q: &Quantity,
    lhs: &str,
    sentence: &str,
) -> Option<Value> {
    let d = derive(doc.m, q).ok()?;
    let text = q.to_string();
    let v = shown_value(doc, &d.value);
    match doc.cited(lhs, &v) {
        Some(place) => {
            let _ = writeln!(
                doc.o,
                "{}",
                super::words::citation(&[(place, vec![lhs.to_string()])])
            );
        }
        None => {
            let _ = writeln!(doc.o, "{sentence}");
            doc.show_keyed(DisplayRole::Step, &text, lhs, lhs, &v, false);
        }
    }
    Some(v)
}

/// σ(A,S/R)·u for each solid of a set, each shown with the formula that gives it; returns
/// their sum.
fn kinetic_projections(
    doc: &mut Doc,
    solids: &[crate::mechanism::BodyId],
    pa: crate::point::PointId,
    rf: FrameId,
    u: &crate::vector::Vector,
    ul: &str,
    reference: &str,
) -> crate::expr::Expr {
    let m = doc.m;
    let a = m.point_name(pa).to_string();
    let mut total = m.reg.zero();
    for &s in solids {
        let mo = Motion {
            moving: m.body(s).name.clone(),
            reference: reference.to_string(),
        };
        let sigma = quantity_tex(&QuantityKind::KineticMoment {
            point: a.clone(),
            motion: mo.clone(),
        });
        let sentence = kinetic_moment_formula(m, s, pa, rf, &mo, &sigma);
        let p = crate::torsor::kinetic_moment_solid(m, s, pa, rf).dot(&m.frames, u);
        total = &total + &p;
        let lhs = format!("{sigma} \\cdot {ul}");
        let v = shown_value(doc, &Value::Scalar(p.clone()));
        match doc.cited(&lhs, &v) {
            Some(place) => {
                let _ = writeln!(
                    doc.o,
                    "{}",
                    super::words::citation(&[(place, vec![lhs.to_string()])])
                );
            }
            None => show_scalar(doc, &format!("sigma({a},{mo})"), &sentence, &lhs, p),
        }
    }
    total
}

/// The formula that gives σ(A,S/R) (`sigma`) of the solid `s` in its motion `mo`: a point
/// mass's, a solid's at a point of it at rest, or by its centre of inertia.
fn kinetic_moment_formula(
    m: &Mechanism,
    s: crate::mechanism::BodyId,
    pa: crate::point::PointId,
    rf: FrameId,
    mo: &Motion,
    sigma: &str,
) -> String {
    let body = m.body(s);
    let a = m.point_name(pa).to_string();
    let reference = mo.reference.as_str();
    let fixed = crate::kinematics::velocity(m, pa, body.frame, rf).is_zero(&m.frames);
    let point_velocity = crate::kinematics::point_velocity;
    let oml = omega_of(&mo.moving, &mo.reference);
    if body.inertia.is_none() {
        let p = m.point_name(body.centre).to_string();
        format!(
            "${}$ est une masse ponctuelle : ${sigma} = \\TVecLong{{{}{}}}\\wedge {}\\,{}$ :",
            point(&p),
            point(&a),
            point(&p),
            mass_of(m, &mo.moving),
            quantity_tex(&QuantityKind::Velocity {
                point: p.clone(),
                motion: mo.clone()
            })
        )
    } else if fixed {
        let how = if point_velocity(m, pa, rf).is_zero(&m.frames) {
            "fixe"
        } else {
            "de vitesse nulle"
        };
        format!(
            "${}$ est un point de ${}$ {how} dans ${}$ : ${sigma} = I_{{{}}}({})\\cdot{oml}$ :",
            point(&a),
            solid(&mo.moving),
            frame(reference),
            point(&a),
            mo.moving
        )
    } else {
        let g = m.point_name(body.centre).to_string();
        format!(
            "${sigma} = {} + \\TVecLong{{{}{}}}\\wedge {}\\,{}$ :",
            quantity_tex(&QuantityKind::KineticMoment {
                point: g.clone(),
                motion: mo.clone()
            }),
            point(&a),
            point(&g),
            mass_of(m, &mo.moving),
            quantity_tex(&QuantityKind::Velocity {
                point: g.clone(),
                motion: mo.clone()
            })
        )
    }
}

/// « ($S_1$ et $S_2$ sont de masse négligeable) » for the members `light` of a set, or nothing.
fn massless_note(m: &Mechanism, light: &[crate::mechanism::BodyId]) -> String {
    if light.is_empty() {
        return String::new();
    }
    let names: Vec<String> = light
        .iter()
        .map(|&s| format!("${}$", solid(&m.body(s).name)))
        .collect();
    let verb = if light.len() > 1 { "sont" } else { "est" };
    format!(
        " ({} {verb} de masse négligeable)",
        super::words::french_list(&names)
    )
}

/// A projection on an axis u of the kinetic or dynamic moment of a set, σ(A,E/R)·u or
/// δ(A,E/R)·u, resolved: its objects, their names in LaTeX, the sum of its massive solids'
/// σ(A,S/R)·u, and the engine's value the route must give.
struct ProjectedSet<'d> {
    /// σ(A,E/R)·u or δ(A,E/R)·u as asked, and whether it is δ.
    kind: &'d QuantityKind,
    dynamic: bool,
    a: &'d str,
    mo: &'d Motion,
    pa: crate::point::PointId,
    /// The reference frame R.
    rf: FrameId,
    /// The axis u: its frame, its vector and its LaTeX.
    uf: FrameId,
    u: crate::vector::Vector,
    ul: String,
    /// The solids of the set that have a mass, and the note naming the others.
    solids: Vec<crate::mechanism::BodyId>,
    light_note: String,
    /// σ(A,E/R) in LaTeX, and the sum of the solids' σ(A,S/R)·u.
    sigma_e: String,
    sum: crate::expr::Expr,
    result: &'d crate::expr::Expr,
}

impl<'d> ProjectedSet<'d> {
    /// The projected kinetic or dynamic moment of a set of two solids or more that `d`
    /// derives, if it is one.
    fn of(m: &Mechanism, names: &super::VectorNames, d: &'d Derivation) -> Option<Self> {
        let q = &d.quantity;
        let (a, mo, dynamic) = match &q.kind {
            QuantityKind::KineticMoment { point, motion } => (point, motion, false),
            QuantityKind::DynamicMoment { point, motion } => (point, motion, true),
            _ => return None,
        };
        let r = crate::derivation::bind(m, q).ok()?;
        let (Some((uf, ua)), Some(pa)) = (r.projection, r.point) else {
            return None;
        };
        if r.solids.len() < 2 {
            return None;
        }
        let Value::Scalar(result) = &d.value else {
            return None;
        };
        // The members of negligible mass add nothing: the sum is over the others, the
        // sentence names them.
        let (light, solids): (Vec<_>, Vec<_>) = r.solids.iter().partition(|&&s| m.body(s).massless);
        if solids.is_empty() {
            return None;
        }
        let light_note = massless_note(m, &light);
        let rf = r.reference.unwrap_or(m.frames.ground());
        let u = crate::vector::Vector::along(uf, ua, m.reg.one());
        let ul = names.basis_vector(ua.letter(), m.frame_name(uf));
        let sigma_e = quantity_tex(&QuantityKind::KineticMoment {
            point: a.clone(),
            motion: mo.clone(),
        });
        let sum = crate::expr::Expr::sum(
            &m.reg,
            solids
                .iter()
                .map(|&s| crate::torsor::kinetic_moment_solid(m, s, pa, rf).dot(&m.frames, &u)),
        );
        Some(ProjectedSet {
            kind: &q.kind,
            dynamic,
            a,
            mo,
            pa,
            rf,
            uf,
            u,
            ul,
            solids,
            light_note,
            sigma_e,
            sum,
            result,
        })
    }
}

/// The short route for a projection on an axis u of the kinetic or dynamic moment of a set:
/// σ(A,E/R)·u as the sum of the solids' projections; δ(A,E/R)·u, at a point A fixed in R
/// and u fixed in R, as d/dt(σ(A,E/R)·u). Taken only when it gives the engine's value.
pub(super) fn projected_set_route(doc: &mut Doc, d: &Derivation) -> bool {
    let Some(ps) = ProjectedSet::of(doc.m, &doc.names, d) else {
        return false;
    };
    if ps.dynamic {
        dynamic_set_route(doc, &ps)
    } else {
        kinetic_set_route(doc, &ps)
    }
}

/// σ(A,E/R)·u as the sum of its solids' σ(A,S/R)·u, when that is the engine's value.
fn kinetic_set_route(doc: &mut Doc, ps: &ProjectedSet) -> bool {
    let m = doc.m;
    let (a, mo, ul, sigma_e) = (ps.a, ps.mo, &ps.ul, &ps.sigma_e);
    let members: Vec<String> = ps
        .solids
        .iter()
        .map(|&s| {
            quantity_tex(&QuantityKind::KineticMoment {
                point: a.to_string(),
                motion: Motion {
                    moving: m.body(s).name.clone(),
                    reference: mo.reference.clone(),
                },
            })
        })
        .collect();
    if &ps.sum != ps.result {
        return false;
    }
    let _ = writeln!(
        doc.o,
        "Le moment cinétique de ${}$ est la somme de ceux de ses solides, ${sigma_e} = {}${} ; en projection sur ${ul}$ :\n",
        solid(&mo.moving),
        members.join(" + "),
        ps.light_note
    );
    kinetic_projections(doc, &ps.solids, ps.pa, ps.rf, &ps.u, ul, &mo.reference);
    true
}

/// δ(A,E/R)·u as d/dt(σ(A,E/R)·u), A and u fixed in R, when that is the engine's value: the
/// solids' σ(A,S/R)·u and their sum, or where that sum was shown.
fn dynamic_set_route(doc: &mut Doc, ps: &ProjectedSet) -> bool {
    use crate::kinematics::{omega, point_velocity};
    let m = doc.m;
    let (a, mo, ul, sigma_e) = (ps.a, ps.mo, &ps.ul, &ps.sigma_e);
    let (pa, rf) = (ps.pa, ps.rf);
    let fixed =
        point_velocity(m, pa, rf).is_zero(&m.frames) && omega(m, ps.uf, rf).is_zero(&m.frames);
    if !fixed || &ps.sum.dt() != ps.result {
        return false;
    }
    let lhs = format!("{sigma_e} \\cdot {ul}");
    let _ = writeln!(
        doc.o,
        "${}$ est fixe dans ${}$ et ${ul}$ aussi : ${} \\cdot {ul} = \\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}}\\left({sigma_e}\\cdot {ul}\\right)${}.\n",
        point(a),
        frame(&mo.reference),
        quantity_tex(ps.kind),
        ps.light_note
    );
    let v = shown_value(doc, &Value::Scalar(ps.sum.clone()));
    match doc.cited(&lhs, &v) {
        Some(place) => {
            let _ = writeln!(
                doc.o,
                "{}",
                super::words::citation(&[(place, vec![lhs.to_string()])])
            );
        }
        None => {
            kinetic_projections(doc, &ps.solids, pa, rf, &ps.u, ul, &mo.reference);
            show_scalar(
                doc,
                &format!("sigma({a},{mo})"),
                "d'où, en sommant :",
                &lhs,
                ps.sum.clone(),
            );
        }
    }
    true
}
