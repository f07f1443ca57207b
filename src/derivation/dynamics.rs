//! The derivations of the PFD's quantities, with the course's steps: the kinetic energy, an
//! unknown of the links or actions (`C_m`, `X01`), an equation of motion (`eom(theta2)`).
//! The PFD itself (actions, theorems, the linear solve) is [`crate::pfd`]; this module only
//! records its steps, and shares one run's cache of δ(G), m Γ(G) and the solved system.

use super::{Derivation, DeriveError, Step, StepKind, Value};
use crate::expr::{Expr, VarId};
use crate::mechanism::Mechanism;
use crate::pfd::{
    PfdError, Solution, Theorem, dynamic_quantity, kinetic_energy, solve_with_residuals,
    theorem_sides, unknown_vars, unknowns_in,
};
use crate::quantity::{Quantity, QuantityKind};
use crate::torsor;
use crate::wire::TheoremKind;
use std::collections::BTreeMap;

/// What the quantities of one run share: each solid's σ(G), δ(G), m V(G) and m Γ(G), and the
/// PFD, solved once (with each theorem's residual, in the spec's order).
#[derive(Debug, Default)]
pub struct Shared {
    /// Per-solid results at the centres of inertia.
    pub centre: torsor::Cache,
    pfd: Option<Result<(Solution, Vec<Expr>), PfdError>>,
    /// How many of the run's quantities still ask for each equation of motion: the last one
    /// takes it out of the solution instead of copying it (a chain's equations are long).
    eom_requests: BTreeMap<String, usize>,
}

impl Shared {
    /// The solved PFD and its residuals, solved on first use.
    fn pfd(&mut self, m: &Mechanism) -> Result<&(Solution, Vec<Expr>), PfdError> {
        self.solved(m).map(|s| &*s)
    }

    fn solved(&mut self, m: &Mechanism) -> Result<&mut (Solution, Vec<Expr>), PfdError> {
        self.pfd
            .get_or_insert_with(|| solve_with_residuals(m, &mut self.centre))
            .as_mut()
            .map_err(|e| e.clone())
    }

    /// Counts the quantities of a run that ask for each equation of motion, so that the last
    /// request moves it out of the solution.
    pub fn expect(&mut self, m: &Mechanism, qs: &[Quantity]) {
        for q in qs {
            let c = match &q.kind {
                QuantityKind::Eom(c) => c.clone(),
                // A trial's unknown is solved from its coordinate's equation.
                QuantityKind::Unknown(n) => match super::trial::trial_of(m, n) {
                    Some((_, t)) => m.reg.coord_info(t.coord).name.clone(),
                    None => continue,
                },
                _ => continue,
            };
            *self.eom_requests.entry(c).or_insert(0) += 1;
        }
    }

    /// The equation of motion of `c`: moved out of the solution for its last expected request,
    /// copied otherwise.
    fn eom(&mut self, m: &Mechanism, c: &str) -> Result<Option<Expr>, PfdError> {
        // The requests still expected, this one included (none when the run did not announce
        // its quantities).
        let expected = self.eom_requests.get_mut(c).map(|n| {
            let before = *n;
            *n = n.saturating_sub(1);
            before
        });
        let eom = &mut self.solved(m)?.0.eom;
        Ok(match expected {
            Some(1) => eom.remove(c),
            _ => eom.get(c).cloned(),
        })
    }
}

fn derive_err(q: &Quantity, message: String) -> DeriveError {
    DeriveError::new(q, message)
}

/// Why a name is not an unknown of the PFD.
pub(super) fn not_an_unknown(name: &str) -> String {
    format!("`{name}` is not an unknown of the PFD (links' components, actions' unknowns)")
}

/// Why a coordinate's bare name is no quantity: its rates are.
pub(super) fn a_coordinate(name: &str) -> String {
    format!(
        "`{name}` is a coordinate, not an unknown of the PFD: ask for its rate dot({name}) \
         or ddot({name}) (a loop law keeps the coordinate itself implicit)"
    )
}

/// Why `eom(c)` of a coordinate `c` has no equation.
pub(super) fn no_eom_marked(c: &str) -> String {
    format!("no equation of `pfd` is marked `\"eom\": \"{c}\"`")
}

/// The steps of one theorem: each exterior action's torsor, the dynamic side, the actions'
/// side (for the kinetic energy theorem, see [`super::energy::theorem_steps`]).
fn theorem_steps(m: &Mechanism, th: &Theorem, cache: &mut torsor::Cache, steps: &mut Vec<Step>) {
    let (dynamic, parts) = theorem_sides(m, th, cache);
    if th.kind == TheoremKind::Energy {
        super::energy::theorem_steps(m, th, dynamic, &parts, steps);
        return;
    }
    // Each action as the bilan words it: « liaison pivot d'axe (O1, z0), action de 0 sur
    // 1 », « pesanteur sur $S_{1}$ », « le moteur, action de 0 sur 1 ».
    for (a, _) in &parts {
        steps.push(super::steps::action_step(m, a));
    }
    let on = (m.frame_name(th.on.0).to_string(), th.on.1.letter());
    let dq = dynamic_quantity(m, th);
    let (theorem_name, at) = match th.kind {
        TheoremKind::Resultant => (
            "Théorème de la résultante dynamique".to_string(),
            String::new(),
        ),
        TheoremKind::Moment => (
            "Théorème du moment dynamique".to_string(),
            format!(" en {}", m.point_name(th.point)),
        ),
        TheoremKind::Energy => unreachable!("written by energy::theorem_steps"),
    };
    steps.push(Step {
        label: dq.to_string(),
        kind: StepKind::Projected(dq.kind.clone(), on.clone()),
        theorem: format!(
            "{theorem_name} appliqué à {}{at}, en projection sur {}{} : côté dynamique",
            th.isolate, on.1, on.0
        ),
        value: Value::Scalar(dynamic),
    });
    let total = Expr::sum(&m.reg, parts.iter().map(|(_, v)| v.clone()));
    steps.push(Step {
        label: format!("actions on {}", th.isolate),
        kind: StepKind::External {
            isolate: th.isolate.clone(),
            point: match th.kind {
                TheoremKind::Moment => Some(m.point_name(th.point).to_string()),
                _ => None,
            },
            on,
        },
        theorem: "Somme des actions mécaniques extérieures, projetée".to_string(),
        value: Value::Scalar(total),
    });
}

/// Derives `Ec(S/0)`, an unknown (`C_m`) or `eom(q)`, with the steps of the PFD when
/// `with_steps`.
pub(super) fn derive(
    m: &Mechanism,
    q: &Quantity,
    shared: &mut Shared,
    with_steps: bool,
) -> Result<Derivation, DeriveError> {
    let mut steps = Vec::new();
    let value = match &q.kind {
        QuantityKind::KineticEnergy(mo) => {
            let solids = m
                .solids_of(&mo.moving)
                .ok_or_else(|| DeriveError::unknown(m, q, "solid or set", &mo.moving))?;
            if m.frames.find(&mo.reference) != Some(m.frames.ground()) {
                return Err(derive_err(
                    q,
                    format!(
                        "the kinetic energy is taken relative to the ground `{}`",
                        m.frame_name(m.frames.ground())
                    ),
                ));
            }
            if with_steps {
                // Each member of negligible mass: its kinetic energy is zero, said so.
                for &s in solids.iter().filter(|&&s| m.body(s).massless) {
                    let motion = crate::quantity::Motion {
                        moving: m.body(s).name.clone(),
                        reference: mo.reference.clone(),
                    };
                    let kind = QuantityKind::KineticEnergy(motion);
                    steps.push(super::massless_step(kind, Value::Scalar(m.reg.zero())));
                }
            }
            Value::Scalar(kinetic_energy(m, &solids))
        }
        QuantityKind::Unknown(name) if super::trial::trial_of(m, name).is_some() => {
            let (_, t) = super::trial::trial_of(m, name).expect("a trial's unknown");
            let c = m.reg.coord_info(t.coord).name.clone();
            let eom = shared.eom(m, &c).map_err(|e| DeriveError::new(q, e))?;
            let eom = eom.ok_or_else(|| derive_err(q, no_eom_marked(&c)))?;
            return super::trial::derive(m, q, name, eom, with_steps);
        }
        QuantityKind::Unknown(name) => unknown_value(m, q, name, shared, (with_steps, &mut steps))?,
        QuantityKind::Eom(c) => {
            let coord = m
                .reg
                .coord(c)
                .ok_or_else(|| DeriveError::unknown(m, q, "coordinate", c))?;
            let th = m
                .dynamics
                .theorems
                .iter()
                .find(|t| t.eom == Some(coord))
                .ok_or_else(|| derive_err(q, no_eom_marked(c)))?;
            let value = shared
                .eom(m, c)
                .map_err(|e| DeriveError::new(q, e))?
                .ok_or_else(|| derive_err(q, format!("no equation of motion for `{c}`")))?;
            if with_steps {
                theorem_steps(m, th, &mut shared.centre, &mut steps);
            }
            Value::Scalar(value)
        }
        _ => return Err(derive_err(q, "not a PFD quantity".to_string())),
    };
    Ok(Derivation {
        quantity: q.clone(),
        steps,
        value,
    })
}

/// The value of the PFD's unknown `name` (a link's component, an action's unknown), with
/// the steps of the theorems that determine it when `with_steps`.
fn unknown_value(
    m: &Mechanism,
    q: &Quantity,
    name: &String,
    shared: &mut Shared,
    (with_steps, steps): (bool, &mut Vec<Step>),
) -> Result<Value, DeriveError> {
    if !m.reg.unknowns().contains(name) {
        return Err(derive_err(q, not_an_unknown(name)));
    }
    let var = unknown_vars(m)
        .into_iter()
        .find(|(n, _)| n == name)
        .map(|(_, v)| v);
    let (sol, residuals) = shared.pfd(m).map_err(|e| DeriveError::new(q, e))?;
    let v = (sol.unknowns.get(name).cloned()).ok_or_else(|| {
        let why = sol.why_undetermined(name);
        derive_err(
            q,
            why.unwrap_or_else(|| format!("no equation of `pfd` determines `{name}`")),
        )
    })?;
    // The theorems that determine the unknown, whose steps are recorded: those that
    // hold it, and those that hold the other unknowns of these (X_A + X_B = … needs
    // the moment that gives X_B), in the spec's order.
    let cited: Vec<usize> = match var {
        Some(v) if with_steps && sol.inputs.contains(name) => driving(m, residuals, v),
        Some(v) if with_steps => determining(m, residuals, v),
        _ => Vec::new(),
    };
    let theorems = m.dynamics.theorems.len();
    for &i in cited.iter().filter(|&&i| i < theorems) {
        theorem_steps(m, &m.dynamics.theorems[i], &mut shared.centre, steps);
    }
    for &i in cited.iter().filter(|&&i| i >= theorems) {
        steps.push(law_step(m, &m.dynamics.laws[i - theorems]));
    }
    Ok(if v.is_whole() {
        Value::Scalar(v.num)
    } else {
        Value::Quotient(v)
    })
}

/// Coulomb's law of a contact as a step: T = −f N ε, its value the equation's right side.
fn law_step(m: &Mechanism, law: &crate::mechanism::CoulombLaw) -> Step {
    let l = &m.links[law.link];
    Step {
        label: format!("Coulomb({})", l.name),
        kind: StepKind::Coulomb {
            link: l.name.clone(),
            tangential: law.unknowns[0].clone(),
        },
        theorem: format!("Loi de Coulomb, contact {} (glissement)", l.name),
        value: Value::Scalar(law.friction()),
    }
}

/// The equations without `eom` that determine the unknown `v`: one that holds it (the one
/// with the fewest unknowns that works), and, for each other unknown it holds, those that
/// determine that one (X_A + X_B = … needs the moment that gives X_B), in the spec's order.
fn determining(m: &Mechanism, residuals: &[Expr], v: VarId) -> Vec<usize> {
    // The theorems without eom, then Coulomb's laws (whose residuals follow them).
    let theorems = &m.dynamics.theorems;
    let rows: Vec<(usize, Vec<VarId>)> = (0..residuals.len())
        .filter(|&i| theorems.get(i).is_none_or(|t| t.eom.is_none()))
        .map(|i| (i, unknowns_in(m, &residuals[i])))
        .collect();
    // A system that no such chain solves (every equation holds two unknowns around a loop,
    // as Coulomb's laws make it): the equations that share unknowns with it, all together.
    let mut cited = block(&rows, v, &mut Vec::new()).unwrap_or_else(|| coupled(&rows, v));
    cited.sort_unstable();
    cited
}

/// The theorems that give an input of the equations of motion `v` (a motor torque) for an
/// imposed motion: the equations of motion that hold it, and those that determine the other
/// unknowns these hold, in the spec's order.
fn driving(m: &Mechanism, residuals: &[Expr], v: VarId) -> Vec<usize> {
    let theorems = &m.dynamics.theorems;
    let mut cited: Vec<usize> = Vec::new();
    for (i, t) in theorems.iter().enumerate() {
        if t.eom.is_none() || residuals[i].derivative(v).is_zero() {
            continue;
        }
        cited.push(i);
        for u in unknowns_in(m, &residuals[i])
            .into_iter()
            .filter(|&u| u != v)
        {
            cited.extend(determining(m, residuals, u));
        }
    }
    cited.sort_unstable();
    cited.dedup();
    cited
}

/// The rows linked to `v` through the unknowns they share.
fn coupled(rows: &[(usize, Vec<VarId>)], v: VarId) -> Vec<usize> {
    let mut reached = vec![v];
    let mut out: Vec<usize> = Vec::new();
    let mut grew = true;
    while grew {
        grew = false;
        for (i, us) in rows {
            if !out.contains(i) && us.iter().any(|u| reached.contains(u)) {
                out.push(*i);
                for u in us {
                    if !reached.contains(u) {
                        reached.push(*u);
                    }
                }
                grew = true;
            }
        }
    }
    out
}

/// A set of rows, none in `used`, that determines `v` (see [`determining`]).
fn block(rows: &[(usize, Vec<VarId>)], v: VarId, used: &mut Vec<usize>) -> Option<Vec<usize>> {
    let mut holding: Vec<&(usize, Vec<VarId>)> = rows
        .iter()
        .filter(|(i, us)| !used.contains(i) && us.contains(&v))
        .collect();
    holding.sort_by_key(|(_, us)| us.len());
    for (i, us) in holding {
        let mark = used.len();
        used.push(*i);
        let mut found = vec![*i];
        let mut ok = true;
        for &u in us.iter().filter(|&&u| u != v) {
            match block(rows, u, used) {
                Some(more) => found.extend(more),
                None => {
                    ok = false;
                    break;
                }
            }
        }
        if ok {
            return Some(found);
        }
        used.truncate(mark);
    }
    None
}
