//! An equation of motion in the course's form: the dynamic side, each acceleration once with
//! its coefficient collected, then the terms in the rates, equal to the actions (weight,
//! springs, motors: the generalised forces); and for one free coordinate whose inertia depends
//! on it, the form J_eq(θ) θ̈ + ½ J_eq′(θ) θ̇² = Q.
//!
//! The split is the engine's M q̈ + h = Q ([`crate::pfd::split_row`], as
//! [`crate::pfd::EquationsOfMotion`] splits its rows), with one difference of reading: the
//! rate a spec imposes (a constant ω) counts as a rate here, so the centrifugal terms of an
//! imposed rotation stay on the dynamic side, where the theorem's dynamic moment puts them.

use super::page::{DisplayRole, Doc};
use crate::derivation::Value;
use crate::expr::{CoordId, Expr, Trig, VarId, VarRole};
use std::fmt::Write;

/// An equation of motion e = 0 written Σⱼ Mⱼ q̈ⱼ + h = Q, its sign chosen so that the leading
/// inertia reads positive.
pub(super) struct CourseForm {
    /// The coordinates whose accelerations occur, in the spec's order.
    coords: Vec<CoordId>,
    /// Mⱼ, the coefficient of q̈ⱼ, for each of `coords`.
    mass: Vec<Expr>,
    /// h: the terms in the rates (Coriolis, centrifugal, viscous friction).
    velocity: Expr,
    /// Q: the actions, what is left at rest.
    actions: Expr,
}

impl CourseForm {
    /// The dynamic side Σⱼ Mⱼ q̈ⱼ + h.
    fn dynamic(&self) -> Expr {
        let mut d = self.velocity.clone();
        for (q, mj) in self.coords.iter().zip(&self.mass) {
            d = &d + &(mj * &mj.registry().ddot(*q));
        }
        d
    }
}

/// The variables set to zero for the actions: every rate, and the parameters a spec imposes
/// as a constant rate (ω of an imposed rotation; not the pulsation of a forcing phase Ω t).
fn at_rest(e: &Expr) -> Vec<VarId> {
    let reg = e.registry();
    let mut vars = crate::pfd::rate_vars(reg);
    for (i, c) in reg.coordinates().iter().enumerate() {
        let constant_rate = c.has_imposed_rate() && !c.is_driven() && c.phase().is_none();
        if !constant_rate || c.is_constant() {
            continue;
        }
        let w = reg.rate(CoordId(i), 1);
        let seen = w.occurring();
        vars.extend((0..seen.len()).filter(|&k| seen[k]).map(VarId));
    }
    vars
}

/// Whether the inertia `e` is negative: its value where every parameter is 1 and each angle
/// takes a generic value (an inertia keeps its sign over every configuration, whatever form
/// prints it: −J − m sin²θ is printed m (cos²θ − 1) − J); where that value is too small to
/// tell, as printed.
fn inertia_negative(e: &Expr) -> bool {
    let reg = e.registry();
    let angle = |q: CoordId| 0.6 + 0.7 * q.0 as f64;
    let point: Vec<f64> = (0..reg.nvars())
        .map(|i| match reg.role(VarId(i)) {
            VarRole::Cos(q) => angle(q).cos(),
            VarRole::Sin(q) => angle(q).sin(),
            VarRole::Reciprocal(q, Trig::Cos) => 1.0 / angle(q).cos(),
            VarRole::Reciprocal(q, Trig::Sin) => 1.0 / angle(q).sin(),
            _ => 1.0,
        })
        .collect();
    let v = e.eval(&point);
    if v.abs() > 1e-9 * e.eval_magnitude(&point) {
        return v < 0.0;
    }
    printed_negative(e)
}

/// Whether `e` reads negative as printed: most terms of its presentation form negative.
fn printed_negative(e: &Expr) -> bool {
    let p = e.presentation();
    let t = &p.form().terms;
    2 * t.iter().filter(|p| p.coef.is_negative()).count() > t.len()
}

/// `h` split as (its terms of degree other than one in the variables `rates`, those of degree
/// one).
fn by_degree_one(h: &Expr, rates: &[VarId]) -> (Expr, Expr) {
    let reg = h.registry();
    let (mut other, mut one) = (Vec::new(), Vec::new());
    for (c, x) in h.terms() {
        let degree: u32 = rates.iter().map(|v| u32::from(x[v.index()])).sum();
        let t = (c.clone(), x.to_vec());
        if degree == 1 {
            one.push(t);
        } else {
            other.push(t);
        }
    }
    (Expr::from_terms(reg, other), Expr::from_terms(reg, one))
}

/// The course's form of the equation of motion `e` = 0 in the coordinate `own`, or None when
/// it is not linear in the accelerations.
pub(super) fn course_form(e: &Expr, own: Option<CoordId>) -> Option<CourseForm> {
    let reg = e.registry();
    let coords: Vec<CoordId> = (0..reg.coordinates().len())
        .map(CoordId)
        .filter(|&q| !e.partial_rate(q, 2).is_zero())
        .collect();
    let rest = at_rest(e);
    let (mass, velocity, actions) = crate::pfd::split_row(e, &coords, &rest)?;
    // A term of degree one in the rates is an action (a viscous friction −c q̇), not an
    // inertia term (those are quadratic in the rates, an imposed ω counted as one).
    let (velocity, viscous) = by_degree_one(&velocity, &rest);
    let actions = &actions - &viscous;
    let mut f = CourseForm {
        coords,
        mass,
        velocity,
        actions,
    };
    // The leading inertia: the own acceleration's, else the first one, else the rate terms.
    let at = own.and_then(|q| f.coords.iter().position(|&c| c == q));
    // Without an acceleration (an equilibrium, a first integral), the printed sign decides.
    let negative = match at.or((!f.mass.is_empty()).then_some(0)) {
        Some(k) => inertia_negative(&f.mass[k]),
        None => printed_negative(&f.velocity),
    };
    if negative {
        f.mass = f.mass.iter().map(|m| -m).collect();
        f.velocity = -&f.velocity;
        f.actions = -&f.actions;
    }
    Some(f)
}

/// A coefficient times an acceleration (or any factor `x`), as pieces of lines: `m\,\ddot{x}`,
/// `\left(J + m\,R^{2}\right)\ddot{\theta}`, or a long coefficient in `\Big( … \Big)` over
/// several pieces; `first`: it opens the side.
fn times(c: &Expr, x: &str, first: bool, max: usize) -> Vec<String> {
    if c.is_one() || (-c).is_one() {
        let s = match (first, c.is_one()) {
            (true, true) => "",
            (true, false) => "-",
            (false, true) => "+ ",
            (false, false) => "- ",
        };
        return vec![format!("{s}{x}")];
    }
    let p = c.presentation();
    let ls = super::expr::presentation_lines(&p, max);
    if ls.len() == 1 || p.form().terms.len() > 1 {
        return super::values::component_lines(c, x, first, max);
    }
    // One product over several lines: no parentheses around it, the factor after its last.
    let mut out: Vec<String> = ls.into_iter().map(|l| l.trim_start().to_string()).collect();
    if !first {
        out[0] = match out[0].strip_prefix('-') {
            Some(rest) => format!("- {rest}"),
            None => format!("+ {}", out[0]),
        };
    }
    if let Some(last) = out.last_mut() {
        last.push_str(&format!("\\,{x}"));
    }
    out
}

/// The pieces of the dynamic side: each acceleration once, then the terms in the rates.
fn dynamic_pieces(f: &CourseForm, max: usize) -> Vec<String> {
    let reg = f.actions.registry();
    let mut out: Vec<String> = Vec::new();
    for (q, mj) in f.coords.iter().zip(&f.mass) {
        let x = super::expr::rate(reg, *q, 2);
        out.extend(times(mj, &x, out.is_empty(), max));
    }
    if !f.velocity.is_zero() {
        let ls = super::expr::expr_lines(&f.velocity, max);
        for (i, l) in ls.into_iter().enumerate() {
            let l = l.trim_start().to_string();
            if i > 0 || out.is_empty() {
                out.push(l);
            } else if let Some(rest) = l.strip_prefix('-') {
                out.push(format!("- {rest}"));
            } else {
                out.push(format!("+ {l}"));
            }
        }
    }
    out
}

/// Pieces packed into lines of at most `max` (a piece wider stays alone on its line).
fn pack(pieces: Vec<String>, max: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for p in pieces {
        if !cur.is_empty() && super::width(&cur) + 1 + super::width(&p) > max {
            lines.push(std::mem::take(&mut cur));
        }
        if !cur.is_empty() {
            cur.push(' ');
        }
        cur.push_str(&p);
    }
    if !cur.is_empty() {
        lines.push(cur);
    }
    lines
}

/// The equation of motion `e` = 0 of the quantity `id` (in the coordinate `own`), boxed in the
/// course's form (see [`course_form`]) under the hypothesis `hyp`; then, for one free
/// coordinate whose inertia depends on it, its J_eq form. Returns false when `e` is not linear
/// in the accelerations (the caller writes it otherwise).
pub(super) fn show(
    doc: &mut Doc,
    (id, hyp): (&str, Option<&str>),
    e: &Expr,
    own: &str,
    jeq: bool,
) -> bool {
    let reg = e.registry();
    let q = reg.coord(own);
    let Some(f) = course_form(e, q) else {
        return false;
    };
    let dynamic = f.dynamic();
    let max = doc.line - 6;
    if dynamic.is_zero() {
        // An equilibrium: the actions balance, Q = 0.
        let a = if printed_negative(&f.actions) {
            -&f.actions
        } else {
            f.actions.clone()
        };
        let lines = pack(super::expr::expr_lines(&a, max), max);
        doc.show_motion(DisplayRole::Result, (id, hyp), &lines, &a, &reg.zero());
        return true;
    }
    let lines = pack(dynamic_pieces(&f, max), max);
    doc.show_motion(DisplayRole::Result, (id, hyp), &lines, &dynamic, &f.actions);
    if let Some(q) = q.filter(|_| jeq) {
        equivalent_inertia(doc, id, &f, q);
    }
    true
}

/// For one free coordinate q whose inertia M depends on it, when the terms in the rates are
/// exactly ½ (dM/dq) q̇²: the sentence that writes the equation as J_eq(q) q̈ + ½ J_eq′(q) q̇²
/// = Q, each formula recorded for the proof (J_eq, J_eq′, and the form's right side).
fn equivalent_inertia(doc: &mut Doc, id: &str, f: &CourseForm, q: CoordId) {
    let ([c], [j]) = (f.coords.as_slice(), f.mass.as_slice()) else {
        return;
    };
    let reg = j.registry();
    let dq = reg.dot(q);
    // dM/dt = M′ q̇ exactly: M depends on q alone (through coordinates driven by q too).
    let dj = j.dt();
    let jp = dj.partial_rate(q, 1);
    if *c != q || jp.is_zero() || dj != &jp * &dq {
        return;
    }
    let half = reg.rational(1, 2);
    if f.velocity != &(&half * &jp) * &(&dq * &dq) {
        return;
    }
    // Written beside the collected form, it is worth its lines only when J_eq′ fits on one.
    if super::width(&super::expr(&jp)) > doc.line - 10 {
        return;
    }
    let info = reg.coord_info(q);
    let angle = matches!(info.kind, crate::wire::CoordinateKind::Angle);
    let (sym, what) = if angle {
        ("J", "l'inertie équivalente ramenée à")
    } else {
        ("M", "la masse équivalente ramenée à")
    };
    let qn = super::name(&info.name);
    let (dq_tex, ddq_tex) = (super::expr::rate(reg, q, 1), super::expr::rate(reg, q, 2));
    let jeq = format!("{sym}_{{\\mathrm{{eq}}}}({qn})");
    let jeqp = format!("{sym}_{{\\mathrm{{eq}}}}'({qn})");
    let _ = writeln!(
        doc.o,
        "Une seule accélération, ${ddq_tex}$, dont le coefficient dépend de ${qn}$ : \
         c'est {what} ${qn}$,"
    );
    let scalar = |e: &Expr| Value::Scalar(e.clone());
    doc.show_keyed(
        DisplayRole::Step,
        &format!("J_eq of {id}"),
        &jeq,
        &jeq,
        &scalar(j),
        false,
    );
    let _ = writeln!(
        doc.o,
        "et les termes en ${dq_tex}^{{2}}$ sont exactement $\\frac{{1}}{{2}}\\,{jeqp}\\,\
         {dq_tex}^{{2}}$, avec"
    );
    let d =
        format!("{jeqp} = \\frac{{\\mathrm{{d}}{sym}_{{\\mathrm{{eq}}}}}}{{\\mathrm{{d}}{qn}}}");
    doc.show_keyed(
        DisplayRole::Step,
        &format!("J_eq' of {id}"),
        &d,
        &d,
        &scalar(&jp),
        false,
    );
    let _ = writeln!(doc.o, "L'équation s'écrit donc sous la forme du cours :");
    let form = format!("{jeq}\\,{ddq_tex} + \\frac{{1}}{{2}}\\,{jeqp}\\,{dq_tex}^{{2}}");
    doc.show_keyed(
        DisplayRole::Step,
        &format!("J_eq form of {id}"),
        &form,
        &form,
        &scalar(&f.actions),
        true,
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::Registry;
    use crate::wire::CoordinateKind;

    /// A residual written with the theorem's sign (−M θ̈ − h + Q): the course's form turns it
    /// so that the inertia reads positive, each acceleration once, and its rate terms are
    /// ½ J′ θ̇², the J_eq form's test.
    #[test]
    fn the_inertia_leads_positive_and_the_rate_terms_are_half_its_derivative() {
        let reg = Registry::new(
            &["J".into(), "m".into(), "C".into(), "w".into()],
            &[("theta".into(), CoordinateKind::Angle)],
        )
        .unwrap();
        let e = reg
            .parse("-(J + m*sin(theta)^2)*ddot(theta) - m*sin(theta)*cos(theta)*dot(theta)^2 + C")
            .unwrap();
        let q = reg.coord("theta");
        let f = course_form(&e, q).unwrap();
        assert_eq!(f.mass, [reg.parse("J + m*sin(theta)^2").unwrap()]);
        assert_eq!(f.actions, reg.parse("C").unwrap());
        assert_eq!(&f.dynamic() - &f.actions, -&e);
        let jp = f.mass[0].dt().partial_rate(q.unwrap(), 1);
        let dq = reg.dot(q.unwrap());
        assert_eq!(f.velocity, &(&reg.rational(1, 2) * &jp) * &(&dq * &dq));
        // The same equation with the other sign keeps its sign: the inertia already leads
        // positive, and the actions are −C's opposite.
        let g = course_form(&-&e, q).unwrap();
        assert_eq!(g.mass, f.mass);
        assert_eq!(g.actions, f.actions);
        // Not linear in θ̈: no course form.
        let e2 = reg.parse("J*ddot(theta)^2 + C").unwrap();
        assert!(course_form(&e2, q).is_none());
    }
}
