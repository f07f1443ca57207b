//! The Fundamental Principle of Dynamics: action torsors, isolation, the resultant and moment
//! theorems projected on chosen vectors, the linear solve for the unknowns, the equations of
//! motion, the kinetic energy, and Lagrange's equations as a second route.
//!
//! The course's statement: for a system E isolated in a Galilean frame R0,
//! {D(E/R0)} = {T(Ē→E)}, the sum of the torsors of the actions exterior to E. Each scalar
//! equation is kept as a residual, dynamic side minus actions, equal to zero; the unknowns of
//! perfect links (X01, …, N01) and of actions such as a motor torque enter it linearly.
//!
//! ```
//! use torseur::{derivation::{derive, Value}, quantity::Quantity, spec};
//! let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
//! // The motor torque, from the moment theorem on E = {1, 2} at O1 projected on z0.
//! let cm = derive(&m, &Quantity::parse("C_m").unwrap()).unwrap();
//! let delta = derive(&m, &Quantity::parse("delta(O1,E/0).z0").unwrap()).unwrap();
//! assert_eq!(cm.value.exprs(), delta.value.exprs());
//! ```

use crate::expr::{Expr, Fraction, VarId};
use crate::mechanism::{BodyId, Mechanism};
use crate::quantity::{Motion, Quantity, QuantityKind};
use crate::torsor::{self, Torsor};
use crate::vector::Vector;
use crate::wire::TheoremKind;
use std::collections::BTreeMap;

mod energy;
mod hyperstatic;
mod linear;
mod motion;
pub mod named;
pub mod structured;
mod transmitted;

pub use crate::mechanism::{Action, Dynamics, Small, Source, SpringPart, Theorem};
pub use energy::{
    action_power, equivalent_inertia, internal_actions, internal_power, kinetic_energy, lagrange,
    potential_energy, power,
};
pub use hyperstatic::Hyperstatic;
pub use linear::{first_order_jointly, linearise};
pub use motion::{CompiledEquations, EquationsOfMotion};
pub(crate) use motion::{rate_vars, split_row};
pub use transmitted::transmitted;

impl Action {
    /// The torsor at its point.
    pub fn torsor(&self) -> Torsor {
        Torsor {
            point: self.point,
            resultant: self.resultant.clone(),
            moment: self.moment.clone(),
        }
    }

    /// The mutual action {T(on→from)} = −{T(from→on)} (only for a solid source). A given
    /// action keeps its name: the motor's {T(moteur→1)} has the reaction {T(moteur→0)}.
    fn reversed(&self) -> Option<Action> {
        let Source::Body(b) = self.from else {
            return None;
        };
        let link = self.from_label == self.exerted_by;
        Some(Action {
            from_label: if link {
                self.on_label.clone()
            } else {
                self.from_label.clone()
            },
            on_label: self.exerted_by.clone(),
            exerted_by: self.on_label.clone(),
            from: Source::Body(self.on),
            on: b,
            point: self.point,
            resultant: self.resultant.neg(),
            moment: self.moment.neg(),
            basis: self.basis,
            description: self.description.clone(),
            label: self.label.clone(),
            // A link's reaction is exerted by its second solid; a given action keeps its
            // source (the motor's reaction {T(moteur→0)}).
            source: if link {
                self.on_label.clone()
            } else {
                self.source.clone()
            },
            mark: self.mark.clone(),
            spring: self.spring.as_ref().map(|s| SpringPart {
                potential: s.potential.clone(),
                resultant: s.resultant.neg(),
                moment: s.moment.neg(),
            }),
        })
    }
}

/// The solved PFD: each unknown in closed form, each equation of motion as a residual.
#[derive(Debug, Clone)]
pub struct Solution {
    /// Unknown name → value: a polynomial, or a quotient by a polynomial in the parameters
    /// when a pivot was one (two bearings a length L apart: Y_B = −D ω² / L).
    pub unknowns: BTreeMap<String, Fraction>,
    /// Coordinate name → residual of its equation of motion (= 0), unknowns eliminated.
    pub eom: BTreeMap<String, Expr>,
    /// The pivots that are not numbers (L), each a polynomial in the parameters: the
    /// solution holds where none of them is zero.
    pub conditions: Vec<Expr>,
    /// Coordinate name → the product of pivots its equation of motion stays multiplied by,
    /// where they do not divide out (1 − f1 f2 εA εB for a ladder with friction at both
    /// ends): `eom` is that factor times the residual. Absent when it is 1.
    pub eom_factors: BTreeMap<String, Expr>,
    /// What the declared equations leave undetermined when the mechanism is hyperstatic
    /// (those unknowns are not in `unknowns`); None when they determine every unknown.
    pub hyperstatic: Option<Hyperstatic>,
    /// The actions' unknowns that only equations of motion hold (a motor torque), in the
    /// unknowns' order: inputs of `eom`, which keeps them as symbols (the direct dynamics),
    /// and in `unknowns` as those equations solved for them (the inverse dynamics: the torque
    /// that imposes a motion, in terms of q, q̇, q̈).
    pub inputs: Vec<String>,
}

impl Solution {
    /// Why the unknown `name` has no value when the mechanism is hyperstatic and the declared
    /// equations give it only through a relation with others; None otherwise.
    pub fn why_undetermined(&self, name: &str) -> Option<String> {
        match &self.hyperstatic {
            Some(h) if h.undetermined.iter().any(|n| n == name) => Some({
                let relations: Vec<String> =
                    h.relations.iter().map(|r| format!("{r} = 0")).collect();
                format!(
                    "the mechanism is hyperstatic of degree {}: the equations of `pfd` do not \
                     determine {} separately{}",
                    h.degree,
                    h.undetermined.join(", "),
                    match relations.is_empty() {
                        true => String::new(),
                        false => format!(", only {}", relations.join(" and ")),
                    }
                )
            }),
            _ => None,
        }
    }
}

/// Why the PFD cannot be solved as declared. `theorem` is the index of a declared equation
/// (`pfd[theorem]` in the spec); the unknowns are named as in the spec.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PfdError {
    /// Two unknowns multiply each other in an equation: the system is not linear in them.
    #[error("pfd[{theorem}]: the unknowns {first} and {second} multiply each other")]
    NotLinear {
        /// The equation.
        theorem: usize,
        /// One unknown.
        first: String,
        /// The other.
        second: String,
    },
    /// The equations without `eom` are not as many as the unknowns they hold.
    #[error(
        "{equations} equation(s) without `eom` for {} unknown(s) ({}): the system to solve \
         must be square",
        unknowns.len(),
        unknowns.join(", ")
    )]
    NotSquare {
        /// How many equations without `eom`.
        equations: usize,
        /// The unknowns they hold.
        unknowns: Vec<String>,
    },
    /// No remaining equation has a number, a polynomial in the parameters, or a product of
    /// parameters and cosines a loop closure divides by as the coefficient of this unknown.
    #[error(
        "cannot solve for {unknown}: in every remaining equation its coefficient is zero or \
         depends on the motion (project the theorems on the basis of the link's axis)"
    )]
    NoNumericPivot {
        /// The unknown.
        unknown: String,
    },
    /// The kinetic energy theorem marked as an equation of motion is not the coordinate's
    /// rate times an equation once the other unknowns are replaced (another rate is free).
    #[error(
        "pfd[{theorem}]: the kinetic energy theorem is not the rate of its `eom` coordinate \
         times an equation (another rate is free: the theorem gives one equation of motion \
         when a single rate moves E, the others driven by it or their equations used)"
    )]
    NotRateTimes {
        /// The theorem.
        theorem: usize,
    },
    /// An equation of motion keeps an unknown that the other equations do not determine.
    #[error(
        "pfd[{theorem}]: the equation of motion still contains the unknown {unknown}, which \
         the other equations do not determine"
    )]
    Undetermined {
        /// The equation of motion.
        theorem: usize,
        /// The unknown left in it.
        unknown: String,
    },
    /// The declared equations leave unknowns undetermined that the PFD of every solid would
    /// determine: an equation is missing (not a hyperstatic mechanism).
    #[error(
        "the equations without `eom` do not determine {}, which the PFD of each solid would \
         determine: declare the theorem that fixes {}",
        unknowns.join(", "),
        if unknowns.len() == 1 { "it" } else { "them" }
    )]
    MissingEquation {
        /// The unknowns left free.
        unknowns: Vec<String>,
    },
    /// Once the unknowns are eliminated, an equation without `eom` holds none of them and is
    /// not zero: it contradicts the others, or is an equation of motion.
    #[error(
        "pfd[{theorem}]: once the other equations give the unknowns, this one holds none of \
         them and is not 0 (is it an equation of motion? mark it with `eom`)"
    )]
    Dependent {
        /// The equation.
        theorem: usize,
    },
    /// The actions' unknowns that only equations of motion hold are not as many as those
    /// equations: the inverse dynamics cannot give each of them.
    #[error(
        "{} appear(s) only in equations of motion ({}): as many equations of motion must \
         hold such action unknowns as there are of them, to give each for an imposed motion",
        unknowns.join(", "),
        equations.join(", ")
    )]
    Inputs {
        /// The action unknowns only equations of motion hold.
        unknowns: Vec<String>,
        /// The coordinates whose equations of motion hold them.
        equations: Vec<String>,
    },
    /// An equation of motion is not linear in the accelerations (no mass matrix).
    #[error("the equation of motion of {coordinate} is not linear in the accelerations")]
    NotLinearIn {
        /// The coordinate whose equation it is.
        coordinate: String,
    },
}

/// The actions exterior to the solids `s`: the declared actions received by a member from a
/// non-member (an action exerted by a member on a non-member is received as its opposite),
/// and gravity on every member.
pub fn external_actions(m: &Mechanism, s: &[BodyId]) -> Vec<Action> {
    let inside = |src: &Source| matches!(src, Source::Body(b) if s.contains(b));
    let mut out = Vec::new();
    for a in &m.dynamics.actions {
        let on_in = s.contains(&a.on);
        let from_in = inside(&a.from);
        if on_in && !from_in {
            out.push(a.clone());
        } else if from_in
            && !on_in
            && let Some(r) = a.reversed()
        {
            out.push(r);
        }
    }
    if let Some(g) = &m.dynamics.gravity {
        // A body of negligible mass has no weight: the bilan does not list it.
        for &b in s.iter().filter(|&&b| !m.body(b).massless) {
            let body = m.body(b);
            out.push(Action {
                from_label: "pes".to_string(),
                on_label: body.name.clone(),
                exerted_by: "pes".to_string(),
                from: Source::Outside,
                on: b,
                point: body.centre,
                resultant: g.scale(&body.mass),
                moment: Vector::zero(),
                basis: m.frames.ground(),
                description: "pesanteur, au centre d'inertie".to_string(),
                label: crate::wire::GRAVITY_LABEL.to_string(),
                source: "pes".to_string(),
                mark: None,
                spring: None,
            });
        }
    }
    out
}

/// The actions `from` exerts on the solids `on` (a solid or a set named `on_name`), as the
/// « bilan des actions mécaniques extérieures » lists them: `from` is matched against each
/// exterior action's source as written there (a solid or frame for its links, `pes` for
/// gravity, a given action's name), and `ext` takes them all (the course's Ē→E).
///
/// ```
/// use torseur::pfd::actions_of;
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let e = m.solids_of("E").unwrap();
/// assert_eq!(actions_of(&m, "0", &e, "E").unwrap().len(), 1);
/// assert_eq!(actions_of(&m, "pes", &e, "E").unwrap().len(), 2);
/// assert!(actions_of(&m, "ext", &e, "E").unwrap().len() >= 4);
/// assert_eq!(actions_of(&m, "2", &e, "E").unwrap_err(),
///     "`2` is part of `E`: its actions on `E` are internal");
/// ```
pub fn actions_of(
    m: &Mechanism,
    from: &str,
    on: &[BodyId],
    on_name: &str,
) -> Result<Vec<Action>, String> {
    let all = external_actions(m, on);
    if from == "ext" {
        return Ok(all);
    }
    let chosen: Vec<Action> = all
        .iter()
        .filter(|a| a.from_label == from)
        .cloned()
        .collect();
    if !chosen.is_empty() {
        return Ok(chosen);
    }
    if m.find_body(from).is_some_and(|b| on.contains(&b)) {
        return Err(format!(
            "`{from}` is part of `{on_name}`: its actions on `{on_name}` are internal"
        ));
    }
    let mut sources: Vec<&str> = Vec::new();
    for a in &all {
        if !sources.contains(&a.from_label.as_str()) {
            sources.push(&a.from_label);
        }
    }
    sources.push("ext");
    Err(format!(
        "no action of `{from}` on `{on_name}` is declared (the actions on `{on_name}` come \
         from: {})",
        sources.join(", ")
    ))
}

/// The two sides of a theorem: the dynamic side (Rd·u or δ(P)·u) and each action's
/// contribution (R·u or M(P)·u, moved to P by M(P) = M(A) + PA ∧ R).
///
/// The dynamic side is Σ m Γ(G_i)·u, or Σ δ(G_i)·u + m Γ(G_i)·(u ∧ PG_i) by transport from
/// each centre of inertia, read from `cache`: a solid's δ(G) and m Γ(G) are computed once for
/// all the theorems of a run.
pub fn theorem_sides(
    m: &Mechanism,
    th: &Theorem,
    cache: &mut torsor::Cache,
) -> (Expr, Vec<(Action, Expr)>) {
    if th.kind == TheoremKind::Energy {
        return energy::energy_sides(m, th);
    }
    let g0 = m.frames.ground();
    let u = Vector::along(th.on.0, th.on.1, m.reg.one());
    let dynamic = match th.kind {
        TheoremKind::Resultant => Expr::sum(
            &m.reg,
            th.solids
                .iter()
                .map(|&s| cache.at_centre(m, s, g0, true).1.dot(&m.frames, &u)),
        ),
        TheoremKind::Moment => {
            torsor::moment_by_transport(m, cache, &th.solids, th.point, g0, true, Some(&u))
                .1
                .unwrap_or_else(|| m.reg.zero())
        }
        TheoremKind::Energy => unreachable!("the energy theorem's sides are its own"),
    };
    let parts = external_actions(m, &th.solids)
        .into_iter()
        .map(|a| {
            let v = match th.kind {
                TheoremKind::Moment => a.torsor().at(m, th.point).moment.dot(&m.frames, &u),
                _ => a.resultant.dot(&m.frames, &u),
            };
            (a, v)
        })
        .collect();
    (dynamic, parts)
}

/// The quantity of the dynamic side of a theorem (`delta(O1,E/0).z0`, `Rd(2/0).x0`).
pub fn dynamic_quantity(m: &Mechanism, th: &Theorem) -> Quantity {
    let motion = Motion {
        moving: th.isolate.clone(),
        reference: m.frame_name(m.frames.ground()).to_string(),
    };
    let kind = match th.kind {
        TheoremKind::Resultant => QuantityKind::DynamicResultant(motion),
        TheoremKind::Moment => QuantityKind::DynamicMoment {
            point: m.point_name(th.point).to_string(),
            motion,
        },
        // dEc(E/R0)/dt, a scalar.
        TheoremKind::Energy => {
            return Quantity::parse(&format!("d/dt(Ec({motion}))")).expect("the notation");
        }
    };
    Quantity {
        kind,
        basis: None,
        projection: Some((m.frame_name(th.on.0).to_string(), th.on.1.letter())),
        linear: false,
    }
}

/// The residual of a theorem: dynamic side minus the actions.
pub fn residual(m: &Mechanism, th: &Theorem, cache: &mut torsor::Cache) -> Expr {
    let (d, parts) = theorem_sides(m, th, cache);
    Expr::sum(
        &m.reg,
        std::iter::once(d).chain(parts.into_iter().map(|(_, v)| -v)),
    )
}

/// Variable indices of the unknowns that occur in `e`.
pub fn unknowns_in(m: &Mechanism, e: &Expr) -> Vec<VarId> {
    let occurs = e.occurring();
    unknown_vars(m)
        .into_iter()
        .filter(|&(_, v)| occurs[v.index()])
        .map(|(_, v)| v)
        .collect()
}

/// (unknown name, variable index) of every unknown.
pub fn unknown_vars(m: &Mechanism) -> Vec<(String, VarId)> {
    let reg = &m.reg;
    reg.unknowns()
        .iter()
        .filter_map(|n| {
            let p = reg.param_id(n)?;
            reg.index_of(crate::expr::VarRole::Parameter(p))
                .map(|v| (n.clone(), v))
        })
        .collect()
}

/// Replaces the unknown variable `v`, which enters `e` linearly, by `value` = n / d: the
/// result is d · e[v := n/d], `e` itself when `d` is 1 (an equation `e = 0` keeps its meaning).
fn eliminate(e: &Expr, v: VarId, value: &Fraction) -> Expr {
    let c = e.derivative(v);
    if c.is_zero() {
        return e.clone();
    }
    let x = e.registry().variable(v);
    let rest = e - &(&c * &x);
    if value.is_whole() {
        &rest + &(&c * &value.num)
    } else {
        &(&rest * &value.den) + &(&c * &value.num)
    }
}

/// Solves the declared PFD: the equations without `eom` determine the unknowns that occur in
/// them (a square system; pivots must be nonzero numbers, which projecting on the links'
/// own bases gives), then each equation of motion has them substituted.
pub fn solve(m: &Mechanism) -> Result<Solution, PfdError> {
    solve_with_residuals(m, &mut torsor::Cache::default()).map(|(s, _)| s)
}

/// Equations of the system as (index of the theorem, or of the law after the theorems, residual).
type Equations = Vec<(usize, Expr)>;

/// Expressions by coordinate name.
type ByCoordinate = BTreeMap<String, Expr>;

/// The unknowns solved so far, each as its variable and its value.
type Solved = Vec<(VarId, Fraction)>;

/// [`solve`], also returning each declared theorem's residual (in the spec's order), then
/// each Coulomb law's (T + f N ε, in the order of `Dynamics::laws`).
pub fn solve_with_residuals(
    m: &Mechanism,
    cache: &mut torsor::Cache,
) -> Result<(Solution, Vec<Expr>), PfdError> {
    let (rows, eoms, residuals) = equations(m, cache)?;
    let mut cols: Vec<VarId> = Vec::new();
    for (_, r) in &rows {
        for v in unknowns_in(m, r) {
            if !cols.contains(&v) {
                cols.push(v);
            }
        }
    }
    let names: BTreeMap<VarId, String> = unknown_vars(m).into_iter().map(|(n, v)| (v, n)).collect();
    if cols.len() < rows.len() {
        return Err(PfdError::NotSquare {
            equations: rows.len(),
            unknowns: cols.iter().map(|v| names[v].clone()).collect(),
        });
    }
    let (solved, conditions, free) = eliminate_unknowns(m, &cols, rows, &names)?;
    let hyperstatic = match free.is_empty() {
        true => None,
        false => Some(hyperstatic::undetermined(m, cache, &free, &solved, &|v| {
            names[&v].clone()
        })?),
    };
    let mut unknowns = BTreeMap::new();
    for (v, value) in &solved {
        let held = |h: &Hyperstatic| h.undetermined.contains(&names[v]);
        if !hyperstatic.as_ref().is_some_and(held) {
            unknowns.insert(names[v].clone(), value.clone());
        }
    }
    let (eom, eom_factors) = equations_of_motion(m, eoms, &solved, &names, &cols)?;
    let (inputs, more) = inverse_dynamics(m, &eom, &names)?;
    let mut conditions = conditions;
    for c in more {
        if !conditions.contains(&c) {
            conditions.push(c);
        }
    }
    for (v, value) in &inputs {
        unknowns.insert(names[v].clone(), value.clone());
    }
    let inputs = inputs.into_iter().map(|(v, _)| names[&v].clone()).collect();
    Ok((
        Solution {
            unknowns,
            eom,
            conditions,
            eom_factors,
            hyperstatic,
            inputs,
        },
        residuals,
    ))
}

/// The system's equations as (index, residual): the theorems without `eom` then Coulomb's
/// laws (the rows that determine the unknowns), the theorems with `eom` apart, and every
/// residual in the order [`solve_with_residuals`] returns them. Each must be linear in the
/// unknowns.
fn equations(
    m: &Mechanism,
    cache: &mut torsor::Cache,
) -> Result<(Equations, Equations, Vec<Expr>), PfdError> {
    let mut residuals = Vec::with_capacity(m.dynamics.theorems.len());
    let mut rows: Equations = Vec::new();
    let mut eoms: Equations = Vec::new();
    for (i, th) in m.dynamics.theorems.iter().enumerate() {
        let r = residual(m, th, cache);
        validate_linear(m, &r).map_err(|(first, second)| PfdError::NotLinear {
            theorem: i,
            first,
            second,
        })?;
        residuals.push(r.clone());
        if th.eom.is_some() {
            eoms.push((i, r));
        } else {
            rows.push((i, r));
        }
    }
    // Coulomb's laws on contacts' unknowns, T + f N ε = 0: equations of the system too, after
    // the theorems (their residuals follow the theorems' in the same order).
    let theorems = m.dynamics.theorems.len();
    for (k, law) in m.dynamics.laws.iter().enumerate() {
        let r = law.residual();
        residuals.push(r.clone());
        rows.push((theorems + k, r));
    }
    Ok((rows, eoms, residuals))
}

/// Gauss–Jordan elimination of the unknowns `cols` from the system `rows`, fraction-free:
/// returns each unknown's value, the conditions of the solution (the pivots that are not
/// numbers, each nonzero) and the unknowns no remaining row held (a hyperstatic mechanism's,
/// which the others' values may hold). A row left over must read 0.
fn eliminate_unknowns(
    m: &Mechanism,
    cols: &[VarId],
    rows: Equations,
    names: &BTreeMap<VarId, String>,
) -> Result<(Solved, Vec<Expr>, Vec<VarId>), PfdError> {
    let mut solved: Solved = Vec::new();
    let mut conditions: Vec<Expr> = Vec::new();
    // Unknowns no remaining equation holds (a hyperstatic mechanism's).
    let mut free: Vec<VarId> = Vec::new();
    let mut pending = rows;
    for &v in cols {
        let Some(pos) = pivot_row(&pending, v) else {
            if pending.iter().all(|(_, r)| r.derivative(v).is_zero()) {
                free.push(v);
                continue;
            }
            return Err(PfdError::NoNumericPivot {
                unknown: names[&v].clone(),
            });
        };
        let (_, row) = pending.remove(pos);
        let c = row.derivative(v);
        let x = m.reg.variable(v);
        // row = c x + rest = 0  =>  x = −rest / c.
        let rest = &row - &(&c * &x);
        let value = Fraction::new(-&rest, c.clone()).ok_or_else(|| PfdError::NoNumericPivot {
            unknown: names[&v].clone(),
        })?;
        if c.as_rational().is_none() {
            // The pivot itself, its first coefficient made 1 (r2, L, not 1/r2 when the
            // mechanism divides by r2 and the value came out whole).
            let lead = c.terms().next().map(|(r, _)| r.clone());
            let unit = lead.map(|r| &c * &m.reg.constant(r.inv()));
            if let Some(p) = unit.filter(|p| !conditions.contains(p)) {
                conditions.push(p);
            }
        }
        for (_, r) in pending.iter_mut() {
            *r = eliminate(r, v, &value);
        }
        for (_, s) in solved.iter_mut() {
            if value.is_whole() {
                s.num = eliminate(&s.num, v, &value);
            } else if !s.num.derivative(v).is_zero() {
                let den = &s.den * &value.den;
                *s = Fraction::new(eliminate(&s.num, v, &value), den).expect("a product of pivots");
            }
        }
        solved.push((v, value));
    }
    if let Some((i, _)) = pending.iter().find(|(_, r)| !r.is_zero()) {
        return Err(PfdError::Dependent { theorem: *i });
    }
    Ok((solved, conditions, free))
}

/// The row of `pending` to solve for `v`: a pivot is a number when one exists, else a nonzero
/// polynomial in the parameters (a length between two bearings, the fewest terms), whose
/// value is then a quotient and whose nonvanishing is a condition of the solution.
fn pivot_row(pending: &[(usize, Expr)], v: VarId) -> Option<usize> {
    let coefficient = |r: &Expr| r.derivative(v);
    pending
        .iter()
        .position(|(_, r)| coefficient(r).is_nonzero_constant())
        .or_else(|| {
            pending
                .iter()
                .enumerate()
                .map(|(i, (_, r))| (i, coefficient(r)))
                .filter(|(_, c)| c.is_parameter_polynomial())
                .min_by_key(|(_, c)| c.nterms())
                .map(|(i, _)| i)
        })
        .or_else(|| {
            // A product of parameters and cosines a loop closure divides by (L cos φ):
            // inverted exactly, its nonvanishing a condition.
            pending
                .iter()
                .position(|(_, r)| coefficient(r).monomial_inverse().is_ok())
        })
}

/// Each equation of motion with the solved unknowns substituted, by coordinate name, and the
/// factor it was left multiplied by when a pivot did not divide back (only those not 1). An
/// unknown left in one must be an action's that no equation without `eom` holds (`cols`
/// are those the others hold): an input, such as a motor torque.
fn equations_of_motion(
    m: &Mechanism,
    eoms: Equations,
    solved: &[(VarId, Fraction)],
    names: &BTreeMap<VarId, String>,
    cols: &[VarId],
) -> Result<(ByCoordinate, ByCoordinate), PfdError> {
    let input = |v: &VarId| !cols.contains(v) && m.dynamics.action_unknowns.contains(&names[v]);
    let mut eom = BTreeMap::new();
    let mut eom_factors = BTreeMap::new();
    for (i, mut r) in eoms {
        // r stays `factor` times the residual with the unknowns eliminated so far.
        let mut factor = m.reg.one();
        for (v, value) in solved {
            if r.derivative(*v).is_zero() {
                continue;
            }
            r = eliminate(&r, *v, value);
            // The equation was multiplied by the pivot: divide it back when it goes.
            if !value.is_whole() {
                match r.exact_div(&value.den) {
                    Some(q) => r = q,
                    None => factor = &factor * &value.den,
                }
            }
        }
        let left = unknowns_in(m, &r);
        if let Some(v) = left.iter().find(|v| !input(v)) {
            return Err(PfdError::Undetermined {
                theorem: i,
                unknown: names[v].clone(),
            });
        }
        let th = &m.dynamics.theorems[i];
        let q = th.eom.expect("eom equation");
        if th.kind == TheoremKind::Energy {
            r = energy::per_rate(m, &r, q).ok_or(PfdError::NotRateTimes { theorem: i })?;
        }
        let name = m.reg.coord_info(q).name.clone();
        if factor != m.reg.one() {
            eom_factors.insert(name.clone(), factor);
        }
        eom.insert(name, r);
    }
    Ok((eom, eom_factors))
}

/// The inputs of the equations of motion (the actions' unknowns left in them) with their
/// values for an imposed motion: the equations that hold them, one per input, solved for them
/// (a motor torque C_m = J θ̈ + …), and the conditions of that solve (its pivots that are not
/// numbers).
fn inverse_dynamics(
    m: &Mechanism,
    eom: &ByCoordinate,
    names: &BTreeMap<VarId, String>,
) -> Result<(Solved, Vec<Expr>), PfdError> {
    let mut inputs: Vec<VarId> = Vec::new();
    let mut rows: Equations = Vec::new();
    let mut coordinates: Vec<String> = Vec::new();
    for (c, r) in eom {
        let held = unknowns_in(m, r);
        if held.is_empty() {
            continue;
        }
        for v in held {
            if !inputs.contains(&v) {
                inputs.push(v);
            }
        }
        let i = (m.dynamics.theorems.iter())
            .position(|t| t.eom.is_some_and(|q| m.reg.coord_info(q).name == *c))
            .expect("an equation of motion is a theorem's");
        rows.push((i, r.clone()));
        coordinates.push(c.clone());
    }
    if inputs.is_empty() {
        return Ok((Vec::new(), Vec::new()));
    }
    inputs.sort();
    let refused = || PfdError::Inputs {
        unknowns: inputs.iter().map(|v| names[v].clone()).collect(),
        equations: coordinates.iter().map(|c| format!("eom({c})")).collect(),
    };
    if rows.len() != inputs.len() {
        return Err(refused());
    }
    // A pivot that depends on the motion is said as such (NoNumericPivot names the input).
    let (solved, conditions, free) = eliminate_unknowns(m, &inputs, rows, names)?;
    match free.is_empty() {
        true => Ok((solved, conditions)),
        false => Err(refused()),
    }
}

/// Unknowns must enter linearly (no term with two unknown factors); else the two that multiply,
/// the first pair in the unknowns' order (an unknown with itself for a square).
fn validate_linear(m: &Mechanism, r: &Expr) -> Result<(), (String, String)> {
    let vars = unknown_vars(m);
    // The pairs (i, j) of unknowns, by their rank in `vars`, that some term multiplies.
    let mut products = std::collections::BTreeSet::new();
    for (_, e) in r.terms() {
        let here: Vec<(usize, u8)> = vars
            .iter()
            .enumerate()
            .filter(|(_, (_, v))| e[v.index()] > 0)
            .map(|(i, (_, v))| (i, e[v.index()]))
            .collect();
        for (a, &(i, k)) in here.iter().enumerate() {
            if k >= 2 {
                products.insert((i, i));
            }
            for &(j, _) in &here[a + 1..] {
                products.insert((i, j));
            }
        }
    }
    match products.first() {
        Some(&(i, j)) => Err((vars[i].0.clone(), vars[j].0.clone())),
        None => Ok(()),
    }
}
