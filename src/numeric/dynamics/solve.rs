//! The PFD at a sample: the action terms of every link and action, each theorem's residual
//! (dynamic side minus actions, affine in the unknowns), and the solve for the unknowns.

use super::linear::determined;
use super::*;

mod power;
use power::PowerSum;
pub(in crate::numeric) use power::{internal_power, power};
use std::ops::{Add, Mul, Neg};

/// c + Σ uₖ aₖ: a scalar or a vector affine in the unknowns u.
#[derive(Debug, Clone)]
struct Lin<T> {
    c: T,
    a: Vec<T>,
}

impl<T> Lin<T>
where
    T: Copy + Add<Output = T> + Neg<Output = T> + Mul<f64, Output = T>,
{
    fn constant(c: T, zero: T, n: usize) -> Lin<T> {
        Lin {
            c,
            a: vec![zero; n],
        }
    }

    fn add(&mut self, other: &Lin<T>) {
        self.c = self.c + other.c;
        for (x, y) in self.a.iter_mut().zip(&other.a) {
            *x = *x + *y;
        }
    }

    fn neg(&self) -> Lin<T> {
        self.map(|x| -*x)
    }

    /// Applies a linear map to the constant and every coefficient.
    fn map<U>(&self, f: impl Fn(&T) -> U) -> Lin<U> {
        Lin {
            c: f(&self.c),
            a: self.a.iter().map(&f).collect(),
        }
    }
}

impl Lin<Vector3<f64>> {
    /// The largest norm of its constant and coefficients.
    fn size(&self) -> f64 {
        self.a.iter().fold(self.c.norm(), |s, v| s.max(v.norm()))
    }
}

/// An action torsor {T(from→on)} at a point (ground components and position).
#[derive(Debug, Clone)]
struct Term {
    /// The source as the bilan writes it (a solid or frame, an action's name), and the
    /// receiver's name.
    names: [String; 2],
    /// The same for its reaction: a link's two solids exchanged, a given action keeping its
    /// name and acting on the solid that exerts it.
    reaction_names: [String; 2],
    from: Body,
    on: Body,
    point: Vector3<f64>,
    resultant: Lin<Vector3<f64>>,
    moment: Lin<Vector3<f64>>,
}

impl Term {
    /// {T(on→from)} = −{T(from→on)}.
    fn reaction(&self) -> Term {
        Term {
            names: self.reaction_names.clone(),
            reaction_names: self.names.clone(),
            from: self.on,
            on: self.from,
            point: self.point,
            resultant: self.resultant.neg(),
            moment: self.moment.neg(),
        }
    }
}

fn eval_err(what: String) -> impl Fn(String) -> NumericError {
    move |message| NumericError::Evaluation {
        what: what.clone(),
        message,
    }
}

pub(super) fn body_frame(m: &NumericModel, b: Body) -> usize {
    match b {
        Body::Solid(s) => m.solids[s].frame,
        Body::Frame(f) => f,
    }
}

/// Sets the sign parameter ε of every link with dry friction to the sign of its relative
/// rate at the sample: Ω(2/1)·u for a pivot, V(A,2/1)·u for a slider, V(P,2/1)·t for a
/// contact under Coulomb's law sliding along t (0 at rest); a sign that `fixed` says is set
/// otherwise (by a hypothesis: the impending motion's sign at the limit of sliding) is kept.
pub(in crate::numeric) fn set_signs(
    m: &NumericModel,
    vals: &mut Values,
    fixed: &dyn Fn(usize) -> bool,
) -> Result<(), NumericError> {
    let dry = |l: &LinkInfo| l.coulomb.is_some() || l.law.is_some();
    if !m.dynamics.links.iter().any(dry) {
        return Ok(());
    }
    let st = kin::state(m, vals)?;
    for l in &m.dynamics.links {
        let (eps, axis, slides) = match (&l.coulomb, &l.law) {
            (Some((_, eps)), _) => (*eps, l.axis, l.kind == LinkKind::Slider),
            (None, Some(law)) => (law.sign, law.tangent, true),
            (None, None) => continue,
        };
        if fixed(eps) {
            continue;
        }
        let [fa, fb] = l.between.map(|b| body_frame(m, b));
        let u = st.rot0(l.basis).column(axis).into_owned();
        let rate = if slides {
            kin::point_motion(&st, l.point, fb, fa)[0].dot(&u)
        } else {
            kin::omega(&st, fb, fa).dot(&u)
        };
        vals.params[eps] = if rate == 0.0 { 0.0 } else { rate.signum() };
    }
    Ok(())
}

/// Evaluates a constant scalar.
fn constant(node: &Node, vals: &Values, what: impl Fn() -> String) -> Result<f64, NumericError> {
    expr::eval_scalar(node, &vals.constants()).map_err(eval_err(what()))
}

/// g⃗ in ground components (zero when gravity is neglected).
fn gravity(m: &NumericModel, st: &State, vals: &Values) -> Result<Vector3<f64>, NumericError> {
    let Some(node) = &m.dynamics.gravity else {
        return Ok(Vector3::zeros());
    };
    let frames: Vec<Matrix3<f64>> = (0..m.frames.len()).map(|f| st.rot0(f)).collect();
    let env = Env {
        params: &vals.params,
        coords: &[],
        rates: &[],
        frames: &frames,
        time: vals.time,
    };
    expr::eval_vector(node, &env).map_err(eval_err("gravity".into()))
}

/// Every declared action (links and given actions) at the sampled instant, each followed by
/// its reaction.
fn terms(m: &NumericModel, st: &State, vals: &Values) -> Result<Vec<Term>, NumericError> {
    let n = m.dynamics.unknowns.len();
    let zero = Lin::constant(Vector3::zeros(), Vector3::zeros(), n);
    let mut out = Vec::new();
    for i in 0..m.dynamics.links.len() {
        let t = link_term(m, st, vals, i, &zero)?;
        out.push(t.reaction());
        out.push(t);
    }
    given_terms(m, st, vals, &zero, &mut out)?;
    Ok(out)
}

/// The action of link `i`: its unknowns on the link's basis, and its viscous friction, dry
/// friction and spring.
fn link_term(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    i: usize,
    zero: &Lin<Vector3<f64>>,
) -> Result<Term, NumericError> {
    let l = &m.dynamics.links[i];
    let rb = st.rot0(l.basis);
    let mut resultant = zero.clone();
    let mut moment = zero.clone();
    for (k, idx) in &l.components {
        let e = rb.column(k % 3).into_owned();
        if *k < 3 {
            resultant.a[*idx] = e;
        } else {
            moment.a[*idx] = e;
        }
    }
    let [fa, fb] = l.between.map(|b| body_frame(m, b));
    let u = rb.column(l.axis).into_owned();
    if let Some(p) = &l.pitch {
        // Zero power of the perfect screw: X λ̇ + L θ̇ = 0 with λ̇ = p θ̇/(2π), so the axial
        // moment is −p/(2π) times the axial resultant's unknown.
        let p = constant(p, vals, || format!("pitch of links[{i}]"))?;
        let axial = l.components.iter().find(|(k, _)| *k == l.axis);
        if let Some((_, idx)) = axial {
            moment.a[*idx] -= u * (p / (2.0 * std::f64::consts::PI));
        }
    }
    let slider = l.kind == LinkKind::Slider;
    if let Some(f) = &l.friction {
        let f = constant(f, vals, || format!("friction of links[{i}]"))?;
        if slider {
            let [v, _] = kin::point_motion(st, l.point, fb, fa);
            resultant.c -= u * (f * v.dot(&u));
        } else {
            let w = kin::omega(st, fb, fa);
            moment.c -= u * (f * w.dot(&u));
        }
    }
    if let Some((c, eps)) = &l.coulomb {
        let c = constant(c, vals, || format!("dry friction of links[{i}]"))?;
        let push = u * (c * vals.params[*eps]);
        if slider {
            resultant.c -= push;
        } else {
            moment.c -= push;
        }
    }
    if let Some(s) = &l.spring {
        let k = constant(&s.stiffness, vals, || {
            format!("stiffness of the spring of links[{i}]")
        })?;
        let q0 = match &s.free {
            Some(q0) => constant(q0, vals, || {
                format!("free value of the spring of links[{i}]")
            })?,
            None => 0.0,
        };
        let push = u * (-k * (vals.coords[s.coord][0] - q0));
        if slider {
            resultant.c += push;
        } else {
            moment.c += push;
        }
    }
    Ok(Term {
        names: l.names.clone(),
        reaction_names: [l.names[1].clone(), l.names[0].clone()],
        from: l.between[0],
        on: l.between[1],
        point: st.pos0(l.point),
        resultant,
        moment,
    })
}

/// Given actions, each followed by its reaction: the part free of unknowns, and each
/// unknown's coefficient exactly (the expressions are affine in the unknowns: checked when
/// the model is built).
fn given_terms(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    zero: &Lin<Vector3<f64>>,
    out: &mut Vec<Term>,
) -> Result<(), NumericError> {
    let frames: Vec<Matrix3<f64>> = (0..m.frames.len()).map(|f| st.rot0(f)).collect();
    let (coords, rates) = vals.split();
    let env = Env {
        params: &vals.params,
        coords: &coords,
        rates: &rates,
        frames: &frames,
        time: vals.time,
    };
    for (i, a) in m.dynamics.actions.iter().enumerate() {
        let mut parts = [zero.clone(), zero.clone()];
        for (part, (node, field)) in parts
            .iter_mut()
            .zip([(&a.resultant, "resultant"), (&a.moment, "moment")])
        {
            let Some(node) = node else { continue };
            let run = |n: &Node| {
                expr::eval_vector(n, &env).map_err(eval_err(format!("{field} of actions[{i}]")))
            };
            part.c = run(&expr::without_unknowns(node))?;
            for k in &a.unknowns {
                part.a[*k] = run(&expr::unknown_coefficient(node, *k))?;
            }
        }
        let [resultant, moment] = parts;
        let t = Term {
            names: [a.names[0].clone(), a.names[1].clone()],
            reaction_names: [a.names[0].clone(), a.names[2].clone()],
            from: a.from,
            on: a.on,
            point: st.pos0(a.point),
            resultant,
            moment,
        };
        out.push(t.reaction());
        out.push(t);
    }
    Ok(())
}

/// The residual of a declared equation, dynamic side minus actions, and the size of the terms
/// it sums (for the rounding noise).
fn residual(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    terms: &[Term],
    g: &Vector3<f64>,
    t: &TheoremInfo,
) -> Result<(Lin<f64>, f64), NumericError> {
    if t.energy {
        return energy_residual(m, st, vals, terms, g, t);
    }
    let n = m.dynamics.unknowns.len();
    let member = |b: Body| matches!(b, Body::Solid(s) if t.solids.contains(&s));
    let p = st.pos0(t.point);
    let u = st.rot0(t.on.0).column(t.on.1).into_owned();
    let [_, _, rd, delta] = cloud::kinetic(m, st, vals, &t.solids, 0, t.point)?;
    let dynamic = if t.moment { delta } else { rd };
    let mut size = dynamic.norm();
    let mut sum = Lin::constant(Vector3::zeros(), Vector3::zeros(), n);
    for term in terms {
        if !member(term.on) || member(term.from) {
            continue;
        }
        let part = if t.moment {
            let arm = term.point - p;
            let mut at_p = term.moment.clone();
            at_p.add(&term.resultant.map(|r| arm.cross(r)));
            at_p
        } else {
            term.resultant.clone()
        };
        size = size.max(part.size());
        sum.add(&part);
    }
    // Gravity on every point mass of every member.
    if g.norm() > 0.0 {
        for s in &t.solids {
            let f = m.solids[*s].frame;
            let (rf, of) = (st.rot0(f), st.origin(f).map(|x| x.re));
            for (mk, local) in cloud::solid_cloud(m, st, vals, *s)? {
                let weight = g * mk;
                let part = if t.moment {
                    (of + rf * local - p).cross(&weight)
                } else {
                    weight
                };
                size = size.max(part.norm());
                sum.c += part;
            }
        }
    }
    let actions = sum.map(|v| v.dot(&u));
    let mut r = actions.neg();
    r.c += dynamic.dot(&u);
    Ok((r, size))
}

/// The kinetic energy theorem's residual, dEc(E/R0)/dt − P(ext→E/R0) − P_int(E), and the
/// size of its terms: Σ mₖ vₖ·Γₖ over the clouds of the members (velocities relative to the
/// ground), the weight of every point mass, and every action received by a member at its
/// point, R·V(P∈S/R0) + M(P)·Ω(S/R0) (an action between two members and its reaction sum to
/// {T(i→j)} ⊗ {V(j/i)}).
fn energy_residual(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    terms: &[Term],
    g: &Vector3<f64>,
    t: &TheoremInfo,
) -> Result<(Lin<f64>, f64), NumericError> {
    let member = |b: Body| matches!(b, Body::Solid(s) if t.solids.contains(&s));
    let mut rate = 0.0;
    let mut sum = PowerSum::new(m.dynamics.unknowns.len());
    for s in &t.solids {
        let f = m.solids[*s].frame;
        for (mk, u) in cloud::solid_cloud(m, st, vals, *s)? {
            let path = st.track(f, &u, 0);
            let (v, a) = (path.map(|x| x.v1), path.map(|x| x.v2));
            rate += mk * v.dot(&a);
            let weight = (g * mk).dot(&v);
            sum.size = sum.size.max(weight.abs());
            sum.c += weight;
        }
    }
    for term in terms.iter().filter(|x| member(x.on)) {
        let f = body_frame(m, term.on);
        let v = kin::velocity_at(st, f, &term.point, 0);
        let w = kin::omega(st, f, 0);
        sum.add(&term.resultant, &term.moment, &v, &w);
    }
    let size = sum.size.max(rate.abs());
    Ok((
        Lin {
            c: rate - sum.c,
            a: sum.a.iter().map(|x| -x).collect(),
        },
        size,
    ))
}

/// The torsor at the point `p` of the actions `from` exerts on the solids `on` (named
/// `on_name`): the declared actions a member receives from a non-member whose source is
/// written `from`, gravity on every point mass for `pes`, all of them for `ext`. The
/// unknowns take the values `unknowns` gives: the resultant or the moment is an error when
/// it holds one that has none.
#[allow(clippy::too_many_arguments)]
pub(in crate::numeric) fn action(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    from: &str,
    on: &[usize],
    on_name: &str,
    p: usize,
    unknowns: &BTreeMap<String, f64>,
) -> Result<[Result<Vector3<f64>, NumericError>; 2], NumericError> {
    let member = |b: Body| matches!(b, Body::Solid(s) if on.contains(&s));
    let at = st.pos0(p);
    let dy = &m.dynamics;
    let u: Vec<f64> = dy
        .unknowns
        .iter()
        .map(|n| unknowns.get(n).copied().unwrap_or(f64::NAN))
        .collect();
    let value = |l: &Lin<Vector3<f64>>| -> Result<Vector3<f64>, NumericError> {
        let mut v = l.c;
        for (k, a) in l.a.iter().enumerate() {
            if *a == Vector3::zeros() {
                continue;
            }
            if u[k].is_nan() {
                return Err(NumericError::Quantity {
                    quantity: format!("{from}->{on_name}"),
                    message: format!("no value for the unknown `{}`", dy.unknowns[k]),
                });
            }
            v += a * u[k];
        }
        Ok(v)
    };
    // The resultant and the moment at p, affine in the unknowns, each moved as the theorems'
    // residuals move them; evaluated at the unknowns' values once summed.
    let n = dy.unknowns.len();
    let mut r = Lin::constant(Vector3::zeros(), Vector3::zeros(), n);
    let mut mo = r.clone();
    let mut found = false;
    for t in terms(m, st, vals)? {
        if !member(t.on) || member(t.from) || (from != "ext" && t.names[0] != from) {
            continue;
        }
        let arm = t.point - at;
        mo.add(&t.moment);
        mo.add(&t.resultant.map(|x| arm.cross(x)));
        r.add(&t.resultant);
        found = true;
    }
    let g = gravity(m, st, vals)?;
    if (from == "pes" || from == "ext") && m.dynamics.gravity.is_some() {
        for s in on {
            let f = m.solids[*s].frame;
            let (rf, of) = (st.rot0(f), st.origin(f).map(|x| x.re));
            for (mk, local) in cloud::solid_cloud(m, st, vals, *s)? {
                r.c += g * mk;
                mo.c += (of + rf * local - at).cross(&(g * mk));
            }
        }
        found = true;
    }
    // `ext` on a solid that receives nothing is the zero torsor, as the exact side has it.
    if !found && from != "ext" {
        return Err(NumericError::Quantity {
            quantity: format!("{from}->{on_name}"),
            message: format!("no action of `{from}` on `{on_name}`"),
        });
    }
    Ok([value(&r), value(&mo)])
}

/// The solved PFD at one sample.
struct Solution {
    /// Value of each unknown that the equations without `eom` determine.
    values: Vec<Option<f64>>,
    /// The unknowns that appear in them but that they do not determine one by one (a
    /// hyperstatic mechanism's: only a combination of them is fixed).
    undetermined: Vec<usize>,
    /// Each declared equation's residual, coefficients of absent unknowns set to zero.
    residuals: Vec<Lin<f64>>,
    /// The given actions' unknowns that only equations with `eom` hold (a motor torque): the
    /// inputs of the equations of motion.
    inputs: Vec<usize>,
}

/// The value of the unknown `name` at the sample, solved from the equations without `eom`.
pub(in crate::numeric) fn unknown(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    name: &str,
) -> Result<f64, NumericError> {
    let fail = |message: String| NumericError::Quantity {
        quantity: name.to_string(),
        message,
    };
    let dy = &m.dynamics;
    let Some(k) = dy.unknown_index.get(name) else {
        return Err(fail(format!(
            "`{name}` is not an unknown of the PFD (its unknowns: {})",
            if dy.unknowns.is_empty() {
                "none".to_string()
            } else {
                dy.unknowns.join(", ")
            }
        )));
    };
    let solution = solve(m, st, vals)?.map_err(fail)?;
    if solution.inputs.contains(k) {
        return inverse(m, &solution, *k).map_err(fail);
    }
    if solution.undetermined.contains(k) {
        return Err(fail(format!(
            "the equations of the PFD without eom fix `{name}` only together with other \
             unknowns (hyperstatic): it has no value of its own"
        )));
    }
    solution.values[*k].ok_or_else(|| {
        fail(format!(
            "the unknown `{name}` appears in no equation of the PFD without eom: nothing \
             determines it"
        ))
    })
}

/// An input of the equations of motion (the unknown `k`, a motor torque) for the sample's
/// motion taken as imposed: the equations with `eom` that hold inputs, as many as them, solved
/// for them by LU, the other unknowns at their solved values (the inverse dynamics).
fn inverse(m: &NumericModel, solution: &Solution, k: usize) -> Result<f64, String> {
    let dy = &m.dynamics;
    let inputs = &solution.inputs;
    let rows: Vec<usize> = (0..dy.theorems.len())
        .filter(|&i| dy.theorems[i].eom.is_some())
        .filter(|&i| inputs.iter().any(|&j| solution.residuals[i].a[j] != 0.0))
        .collect();
    if rows.len() != inputs.len() {
        return Err(format!(
            "{} equation(s) of motion hold the {} input(s) of the equations of motion: the \
             inverse dynamics needs one per input",
            rows.len(),
            inputs.len()
        ));
    }
    let n = inputs.len();
    let mut a = DMatrix::zeros(n, n);
    let mut b = DVector::zeros(n);
    for (r, &i) in rows.iter().enumerate() {
        let res = &solution.residuals[i];
        let mut c = res.c;
        for (j, x) in res.a.iter().enumerate() {
            match inputs.iter().position(|&u| u == j) {
                Some(col) => a[(r, col)] = *x,
                None if *x != 0.0 => {
                    c += x * solution.values[j]
                        .ok_or_else(|| format!("the unknown `{}` has no value", dy.unknowns[j]))?
                }
                None => {}
            }
        }
        b[r] = -c;
    }
    let y = a.lu().solve(&b).ok_or_else(|| {
        "the equations of motion do not determine their inputs at this sample".to_string()
    })?;
    Ok(y[inputs.iter().position(|&u| u == k).expect("an input")])
}

/// The residual of the equation of motion of coordinate `q` at the sample (q̈ the sample's),
/// the unknowns solved from the equations without `eom` substituted, and its inputs (a motor
/// torque) at their `given` values.
pub(in crate::numeric) fn eom(
    m: &NumericModel,
    st: &State,
    vals: &Values,
    q: &str,
    given: &BTreeMap<String, f64>,
) -> Result<f64, NumericError> {
    let fail = |message: String| NumericError::Quantity {
        quantity: format!("eom({q})"),
        message,
    };
    let dy = &m.dynamics;
    let Some(c) = m.coord_index.get(q) else {
        return Err(fail(format!("`{q}` is not a time coordinate")));
    };
    let Some(i) = dy.theorems.iter().position(|t| t.eom == Some(*c)) else {
        return Err(fail(format!("no equation of the PFD has eom `{q}`")));
    };
    let solution = solve(m, st, vals)?.map_err(fail)?;
    let r = &solution.residuals[i];
    let mut x = r.c;
    for (k, a) in r.a.iter().enumerate() {
        if *a == 0.0 {
            continue;
        }
        let name = &dy.unknowns[k];
        if solution.inputs.contains(&k) {
            let v = given.get(name).ok_or_else(|| {
                fail(format!(
                    "its input `{name}` is given no value at this sample"
                ))
            })?;
            x += a * v;
            continue;
        }
        let v = solution.values[k].ok_or_else(|| {
            fail(format!(
                "its equation still holds the unknown `{}`, which the equations without eom \
                 do not determine",
                dy.unknowns[k]
            ))
        })?;
        x += a * v;
    }
    // The energy theorem is q̇ times the equation of motion.
    if dy.theorems[i].energy {
        x /= vals.coords[*c][1];
    }
    Ok(x)
}

/// The given actions' unknowns that no equation without `eom` holds (`cols` are those they
/// hold) but an equation of motion does: the inputs of the equations of motion.
fn inputs(dy: &Dynamics, residuals: &[Lin<f64>], cols: &[usize]) -> Vec<usize> {
    (dy.given_unknowns.iter().copied())
        .filter(|k| !cols.contains(k))
        .filter(|&k| residuals.iter().any(|r| r.a[k] != 0.0))
        .collect()
}

/// Builds every declared equation at the sample and solves those without `eom`: the outer
/// error is an evaluation failure, the inner one a system that cannot be solved.
fn solve(
    m: &NumericModel,
    st: &State,
    vals: &Values,
) -> Result<Result<Solution, String>, NumericError> {
    let dy = &m.dynamics;
    let n = dy.unknowns.len();
    let terms = terms(m, st, vals)?;
    let g = gravity(m, st, vals)?;
    let mut residuals = Vec::with_capacity(dy.theorems.len());
    for t in &dy.theorems {
        let (mut r, size) = residual(m, st, vals, &terms, &g, t)?;
        for a in &mut r.a {
            if a.abs() <= APPEARS * size {
                *a = 0.0;
            }
        }
        residuals.push(r);
    }
    // Coulomb's laws, T + f ε N = 0, after the theorems: equations of the system too.
    for l in &dy.links {
        let Some(law) = &l.law else { continue };
        let f = constant(&law.coefficient, vals, || "a friction coefficient".into())?;
        let mut r = Lin::constant(0.0, 0.0, n);
        r.a[law.unknowns[0]] = 1.0;
        r.a[law.unknowns[1]] = f * vals.params[law.sign];
        residuals.push(r);
    }
    let rows: Vec<usize> = (0..residuals.len())
        .filter(|i| dy.theorems.get(*i).is_none_or(|t| t.eom.is_none()))
        .collect();
    let cols: Vec<usize> = (0..n)
        .filter(|k| rows.iter().any(|i| residuals[*i].a[*k] != 0.0))
        .collect();
    let listed = |ks: &[usize]| -> String {
        if ks.is_empty() {
            return "none".into();
        }
        ks.iter()
            .map(|k| dy.unknowns[*k].as_str())
            .collect::<Vec<_>>()
            .join(", ")
    };
    if rows.len() > cols.len() {
        return Ok(Err(format!(
            "the PFD's equations without eom must determine the unknowns that appear in them: \
             {} equation(s) for {} unknown(s) ({})",
            rows.len(),
            cols.len(),
            listed(&cols)
        )));
    }
    let mut values = vec![None; n];
    let mut undetermined = Vec::new();
    if !rows.is_empty() {
        let (k, c) = (rows.len(), cols.len());
        let mut a = DMatrix::from_fn(k, c, |r, j| residuals[rows[r]].a[cols[j]]);
        let mut b = DVector::from_fn(k, |r, _| -residuals[rows[r]].c);
        // Scale rows then columns to unit largest entries, so that the pivot test is
        // independent of units.
        for r in 0..k {
            let s = a.row(r).amax();
            if s > 0.0 {
                a.row_mut(r).scale_mut(1.0 / s);
                b[r] /= s;
            }
        }
        let col_scale: Vec<f64> = (0..c).map(|j| a.column(j).amax()).collect();
        for (j, s) in col_scale.iter().enumerate() {
            a.column_mut(j).scale_mut(1.0 / s);
        }
        let y = match determined(&a, &b) {
            Ok((y, free)) => {
                undetermined = free.into_iter().map(|j| cols[j]).collect();
                y
            }
            Err(()) => {
                return Ok(Err(format!(
                    "the PFD's equations without eom are singular at this sample: they do not \
                     determine their unknowns ({})",
                    listed(&cols)
                )));
            }
        };
        for (j, col) in cols.iter().enumerate() {
            if !undetermined.contains(col) {
                values[*col] = Some(y[j] / col_scale[j]);
            }
        }
    }
    let inputs = inputs(dy, &residuals, &cols);
    Ok(Ok(Solution {
        values,
        undetermined,
        residuals,
        inputs,
    }))
}
