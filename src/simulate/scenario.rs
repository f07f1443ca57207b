//! A scenario of the spec made ready to integrate: the equations of motion solved for the
//! accelerations, imposed rate laws, and the quantities to record.

use super::SimulateError;
use super::law::TimeLaw;
use crate::expr::{Compiled, CoordId, Expr, Trig, VarRole};
use crate::mechanism::Mechanism;
use crate::pfd;
use crate::wire::ScenarioSpec;
use nalgebra::{DMatrix, DVector};

/// A coordinate whose motion is imposed: its rate law (and value by integration).
pub(super) struct Imposed {
    pub coord: CoordId,
    pub initial: f64,
    pub law: ImposedLaw,
}

/// An imposed rate: a piecewise law of t, or the spec's constant rate.
pub(super) enum ImposedLaw {
    Law(TimeLaw),
    Constant(f64),
}

impl ImposedLaw {
    /// Rate and its time derivative at t.
    pub fn at(&self, t: f64) -> Result<(f64, f64), String> {
        match self {
            ImposedLaw::Law(l) => l.rate(t),
            ImposedLaw::Constant(w) => Ok((*w, 0.0)),
        }
    }
}

/// Everything the right-hand side needs.
pub(super) struct Plan {
    /// Free coordinates (integrated through their equation of motion).
    pub free: Vec<CoordId>,
    /// Imposed coordinates.
    pub imposed: Vec<Imposed>,
    /// Registry variable values that do not change (parameters); the rest is filled per call.
    pub base: Vec<f64>,
    /// M (row-major, n×n) then h: M q̈ + h = 0 over the free coordinates.
    pub dynamics: Dynamics,
    /// The recorded expressions (unknowns, integrands), evaluated once q̈ is known.
    pub recorded: Compiled,
    /// What each recorded expression is multiplied by: 1 / its denominator at the parameters
    /// for an unknown solved as a quotient (Y_B = −D ω² / L), 1 otherwise.
    pub scales: Vec<f64>,
    /// Number of recorded expressions that are integrated (the last ones).
    pub integrals: usize,
    /// Initial [q, q̇] of the free coordinates.
    pub initial: Vec<[f64; 2]>,
    /// Breakpoints of the imposed laws.
    pub breakpoints: Vec<f64>,
    /// Coordinates driven by the free rates (a gear ratio, a loop closure): their values are
    /// integrated from their rates, in the state after the integrals.
    pub driven: Vec<CoordId>,
    /// Initial value of each driven coordinate.
    pub driven_initial: Vec<f64>,
    /// q̇ of each driven coordinate.
    pub driven_rates: Compiled,
    /// The nonzero components of the loop closures on the ground's basis (0 on the loop):
    /// what the integration lets them drift to.
    pub closure: Option<Compiled>,
    /// The links with dry friction: their sign's slot and relative rate.
    pub dry: Vec<Dry>,
}

/// Below this relative rate (SI: m/s or rad/s), a link with dry friction may stick: the
/// Karnopp model (D. Karnopp, « Computer simulation of stick-slip friction in mechanical
/// dynamic systems », J. Dyn. Sys., Meas., Control 107, 1985) then gives it the friction that
/// keeps its relative acceleration at 0, if that friction does not exceed the dry friction's
/// magnitude, and the full magnitude against the motion's tendency otherwise.
pub(super) const STICK_BAND: f64 = 1e-6;

/// While stuck, the residual relative rate (below [`STICK_BAND`]) is brought to 0 with this
/// time constant (s), so that a stuck link does not creep.
const STICK_TIME: f64 = 1e-3;

/// A link with dry friction: where its sign ε sits in a registry point, and its relative
/// rate and acceleration (two outputs).
pub(super) struct Dry {
    var: usize,
    motion: Compiled,
    /// Whether the relative acceleration is affine in the sign (a given magnitude).
    affine: bool,
}

impl Plan {
    /// Builds the plan of a scenario. `record` are quantity ids of unknowns to record;
    /// `integrate` are extra expressions whose time integral is tracked (a power, for work).
    pub fn new(
        m: &Mechanism,
        sc: &ScenarioSpec,
        record: &[String],
        integrate: &[(String, Expr)],
    ) -> Result<Plan, SimulateError> {
        let err = |s: String| SimulateError::Scenario(format!("scenario `{}`: {s}", sc.name));
        let sol = pfd::solve(m).map_err(|e| err(e.to_string()))?;
        validate_values(m, sc, &sol.inputs).map_err(err)?;
        let base = base_values(m, sc).map_err(err)?;
        let (mut imposed, mut breakpoints) = imposed_laws(m, sc).map_err(err)?;
        let (free, driven) = split_coordinates(m, sc, &base, &mut imposed);
        let initial = free_initial(m, sc, &sol, &free).map_err(err)?;
        given_inputs(m, sc, &sol, &free).map_err(err)?;
        let dynamics = compile_dynamics(m, &sol, &free).map_err(err)?;
        let (recorded, scales) =
            compile_recorded(m, &sol, &base, record, integrate).map_err(err)?;
        breakpoints.sort_by(f64::total_cmp);
        breakpoints.dedup();
        let driven_initial: Vec<f64> = driven
            .iter()
            .map(|&q| {
                let name = &m.reg.coord_info(q).name;
                sc.initial.get(name).map(|v| v[0]).unwrap_or(0.0)
            })
            .collect();
        let driven_rates = compile_driven_rates(m, &driven).map_err(err)?;
        let closure = compile_closure(m).map_err(err)?;
        let dry = dry_links(m).map_err(err)?;
        Ok(Plan {
            dry,
            driven,
            driven_initial,
            driven_rates,
            closure,
            free,
            imposed,
            base,
            dynamics,
            recorded,
            scales,
            integrals: integrate.len(),
            initial,
            breakpoints,
        })
    }

    /// The initial state.
    pub fn initial_state(&self) -> Vec<f64> {
        let mut y: Vec<f64> = self.imposed.iter().map(|i| i.initial).collect();
        y.extend(self.initial.iter().map(|v| v[0]));
        y.extend(self.initial.iter().map(|v| v[1]));
        y.extend(std::iter::repeat_n(0.0, self.integrals));
        y.extend(&self.driven_initial);
        y
    }

    /// The largest component of the loop closures at state `y` (0 on the loop), or None
    /// without a closure.
    pub fn closure_residual(&mut self, m: &Mechanism, t: f64, y: &[f64]) -> Option<f64> {
        let point = self.point(m, t, y).ok()?;
        let c = self.closure.as_mut()?;
        let mut out = vec![0.0; c.outputs()];
        c.evaluate(&point, &mut out);
        Some(out.iter().fold(0.0_f64, |a, x| a.max(x.abs())))
    }

    /// The registry point of state `y` at t: parameters, the imposed and driven coordinates
    /// and the free ones with their rates (accelerations not yet known).
    fn point(&self, m: &Mechanism, t: f64, y: &[f64]) -> Result<Vec<f64>, String> {
        let ni = self.imposed.len();
        let n = self.free.len();
        let mut point = self.base.clone();
        for (k, im) in self.imposed.iter().enumerate() {
            let (w, a) = im.law.at(t)?;
            set(m, im.coord, [y[k], w, a], &mut point);
        }
        for (k, &q) in self.free.iter().enumerate() {
            set(m, q, [y[ni + k], y[ni + n + k], 0.0], &mut point);
        }
        let at = ni + 2 * n + self.integrals;
        for (k, &q) in self.driven.iter().enumerate() {
            set(m, q, [y[at + k], 0.0, 0.0], &mut point);
        }
        Ok(point)
    }

    /// Fills the registry point from the state at t and solves for the free accelerations.
    pub fn evaluate(&mut self, m: &Mechanism, t: f64, y: &[f64]) -> Result<Evaluation, String> {
        let ni = self.imposed.len();
        let n = self.free.len();
        let mut point = self.point(m, t, y)?;
        let mut rates = Vec::with_capacity(ni);
        for im in &self.imposed {
            rates.push(im.law.at(t)?.0);
        }
        let mut out = vec![0.0; n * n + n];
        // Dry friction: ε = the sign of the relative rate, or (Karnopp) the friction that
        // holds a link whose rate is within the band, as far as its magnitude allows.
        let mut motion = [0.0; 2];
        let mut sticking = Vec::new();
        for (k, d) in self.dry.iter_mut().enumerate() {
            d.motion.evaluate(&point, &mut motion);
            point[d.var] = motion[0].signum();
            if motion[0].abs() <= STICK_BAND {
                point[d.var] = 0.0;
                sticking.push(k);
            }
        }
        for k in sticking {
            let eps = self.holding(m, (t, y), k, &mut point, &mut out)?;
            point[self.dry[k].var] = eps;
        }
        let acc = self.accelerations(m, t, y, &mut point, &mut out)?;
        let mut driven_rates = vec![0.0; self.driven_rates.outputs()];
        self.driven_rates.evaluate(&point, &mut driven_rates);
        driven_rates.truncate(self.driven.len());
        let mut recorded = vec![0.0; self.recorded.outputs()];
        self.recorded.evaluate(&point, &mut recorded);
        for (r, k) in recorded.iter_mut().zip(&self.scales) {
            *r *= k;
        }
        if let Some(bad) = out
            .iter()
            .chain(&recorded)
            .chain(&driven_rates)
            .find(|v| !v.is_finite())
        {
            return Err(format!("non-finite value {bad} at t = {t}"));
        }
        Ok(Evaluation {
            rates,
            accelerations: acc.iter().copied().collect(),
            recorded,
            driven_rates,
        })
    }

    /// The sign ε ∈ [−1, 1] of the stuck link `k` (Karnopp): the friction that brings its
    /// residual relative rate r to 0 in STICK_TIME, a(ε) = −r/τ, as far as |ε| ≤ 1 allows.
    /// a(ε) is affine when the friction's magnitude is given; when it is f N with N an unknown
    /// that the friction changes, it is not: secant steps from the affine guess then reach it.
    fn holding(
        &mut self,
        m: &Mechanism,
        ty: (f64, &[f64]),
        k: usize,
        point: &mut [f64],
        out: &mut [f64],
    ) -> Result<f64, String> {
        let r0 = self.relative(m, ty, k, 0.0, point, out)?;
        let (mut e1, mut r1) = (1.0, self.relative(m, ty, k, 1.0, point, out)?);
        let mut motion = [0.0; 2];
        self.dry[k].motion.evaluate(point, &mut motion);
        let target = -motion[0] / STICK_TIME;
        if r0 == r1 {
            return Ok(0.0);
        }
        let mut eps = ((r0 - target) / (r0 - r1)).clamp(-1.0, 1.0);
        if self.dry[k].affine {
            return Ok(eps);
        }
        let scale = r0.abs().max(r1.abs()).max(target.abs());
        for _ in 0..12 {
            let r = self.relative(m, ty, k, eps, point, out)?;
            if (r - target).abs() <= 1e-12 * scale || r == r1 {
                break;
            }
            // The secant through the last two points (ε, a(ε)).
            let (e0, a0) = (e1, r1);
            (e1, r1) = (eps, r);
            let next = (e1 - (r1 - target) * (e1 - e0) / (r1 - a0)).clamp(-1.0, 1.0);
            if next == e1 {
                break;
            }
            eps = next;
        }
        Ok(eps)
    }

    /// The relative acceleration of the dry link `k` when its sign is `eps`.
    fn relative(
        &mut self,
        m: &Mechanism,
        (t, y): (f64, &[f64]),
        k: usize,
        eps: f64,
        point: &mut [f64],
        out: &mut [f64],
    ) -> Result<f64, String> {
        point[self.dry[k].var] = eps;
        self.accelerations(m, t, y, point, out)?;
        let mut motion = [0.0; 2];
        self.dry[k].motion.evaluate(point, &mut motion);
        Ok(motion[1])
    }

    /// Solves M q̈ + h = 0 at `point` for the free accelerations and writes them in it.
    fn accelerations(
        &mut self,
        m: &Mechanism,
        t: f64,
        y: &[f64],
        point: &mut [f64],
        out: &mut [f64],
    ) -> Result<DVector<f64>, String> {
        let ni = self.imposed.len();
        let n = self.free.len();
        if n == 0 {
            // Every motion is imposed: no equation of motion to solve.
            return Ok(DVector::zeros(0));
        }
        self.dynamics.evaluate(point, out);
        let mass = DMatrix::from_row_slice(n, n, &out[..n * n]);
        let h = DVector::from_column_slice(&out[n * n..]);
        let acc = mass
            .lu()
            .solve(&(-h))
            .ok_or_else(|| format!("the mass matrix is singular at t = {t}"))?;
        for (k, &q) in self.free.iter().enumerate() {
            set(m, q, [y[ni + k], y[ni + n + k], acc[k]], point);
        }
        Ok(acc)
    }

    /// The right-hand side y' = f(t, y).
    pub fn rhs(&mut self, m: &Mechanism, t: f64, y: &[f64], dy: &mut [f64]) -> Result<(), String> {
        let ni = self.imposed.len();
        let n = self.free.len();
        let e = self.evaluate(m, t, y)?;
        dy[..ni].copy_from_slice(&e.rates);
        for k in 0..n {
            dy[ni + k] = y[ni + n + k];
            dy[ni + n + k] = e.accelerations[k];
        }
        let first = e.recorded.len() - self.integrals;
        let at = ni + 2 * n + self.integrals;
        dy[ni + 2 * n..at].copy_from_slice(&e.recorded[first..]);
        dy[at..].copy_from_slice(&e.driven_rates);
        Ok(())
    }
}

/// One evaluation of the right-hand side's ingredients.
pub(super) struct Evaluation {
    /// q̇ of the imposed coordinates.
    pub rates: Vec<f64>,
    /// q̈ of the free coordinates.
    pub accelerations: Vec<f64>,
    /// The recorded expressions (unknowns, then integrands).
    pub recorded: Vec<f64>,
    /// q̇ of the driven coordinates.
    pub driven_rates: Vec<f64>,
}

/// Fills the variable slots of coordinate `q` (cos, sin, value, 1/cos or 1/sin, q̇, q̈) in a
/// registry point from [q, q̇, q̈].
fn set(m: &Mechanism, q: CoordId, v: [f64; 3], point: &mut [f64]) {
    let reg = &m.reg;
    let roles = [
        (VarRole::Cos(q), v[0].cos()),
        (VarRole::Sin(q), v[0].sin()),
        (VarRole::Value(q), v[0]),
        (VarRole::Reciprocal(q, Trig::Cos), 1.0 / v[0].cos()),
        (VarRole::Reciprocal(q, Trig::Sin), 1.0 / v[0].sin()),
        (VarRole::Rate(q, 1), v[1]),
        (VarRole::Rate(q, 2), v[2]),
    ];
    for (role, x) in roles {
        if let Some(i) = reg.index_of(role) {
            point[i.index()] = x;
        }
    }
}

/// Every parameter given a finite value, and only parameters or `inputs` of the equations of
/// motion (a motor torque; a dry friction's sign is set by the simulation).
fn validate_values(m: &Mechanism, sc: &ScenarioSpec, inputs: &[String]) -> Result<(), String> {
    let reg = &m.reg;
    let sign = |p: &str| m.dynamics.dry.iter().any(|d| d.sign == p);
    for p in reg.parameters() {
        if !sc.values.contains_key(p) && !sign(p) {
            return Err(format!("no value for the parameter `{p}`"));
        }
    }
    for (k, v) in &sc.values {
        if sign(k) {
            return Err(format!(
                "`{k}` is the sign of a link's relative rate under dry friction: the \
                 simulation sets it"
            ));
        }
        if reg.unknowns().contains(k) && !inputs.contains(k) {
            return Err(format!(
                "`{k}` is found by the equations of `pfd` without `eom`: the scenario cannot \
                 give it (an action's unknown is an input only where equations of motion \
                 alone hold it)"
            ));
        }
        if !reg.parameters().contains(k) && !inputs.contains(k) {
            return Err(format!("`{k}` is not a parameter"));
        }
        if !v.is_finite() {
            return Err(format!("the value of `{k}` is not finite"));
        }
    }
    Ok(())
}

/// The registry variables fixed by the scenario's values: parameters, their inverses, cos and
/// sin of constant angles (0 for the others).
fn base_values(m: &Mechanism, sc: &ScenarioSpec) -> Result<Vec<f64>, String> {
    let reg = &m.reg;
    let mut base = vec![0.0; reg.nvars()];
    for v in reg.var_ids() {
        let i = v.index();
        match reg.role(v) {
            // π and 1/π.
            VarRole::Parameter(k) | VarRole::Inverse(k) if reg.constant_value(k).is_some() => {
                let c = reg.constant_value(k).unwrap_or(f64::NAN);
                base[i] = if matches!(reg.role(v), VarRole::Inverse(_)) {
                    1.0 / c
                } else {
                    c
                };
            }
            // A parameter, or an input of the equations of motion the scenario gives (a
            // motor torque; [`given_inputs`] demands those a free coordinate's equation holds).
            VarRole::Parameter(k) => {
                base[i] = sc.values.get(reg.scalar_name(k)).copied().unwrap_or(0.0);
            }
            // 1/k, for a parameter k the spec divides by.
            VarRole::Inverse(k) => {
                let name = reg.scalar_name(k);
                if sc.values[name] == 0.0 {
                    return Err(format!("`{name}` = 0, and the spec divides by it"));
                }
                base[i] = 1.0 / sc.values[name];
            }
            // cos and sin of a constant angle parameter.
            VarRole::Cos(q) if reg.coord_info(q).is_constant() => {
                base[i] = sc.values[&reg.coord_info(q).name].cos();
            }
            VarRole::Sin(q) if reg.coord_info(q).is_constant() => {
                base[i] = sc.values[&reg.coord_info(q).name].sin();
            }
            _ => {}
        }
    }
    Ok(base)
}

/// The scenario's imposed rate laws, and their breakpoints.
fn imposed_laws(m: &Mechanism, sc: &ScenarioSpec) -> Result<(Vec<Imposed>, Vec<f64>), String> {
    let reg = &m.reg;
    let params: Vec<f64> = reg
        .parameters()
        .iter()
        .map(|p| sc.values.get(p).copied().unwrap_or(0.0))
        .collect();
    let mut imposed = Vec::new();
    let mut breakpoints = Vec::new();
    for (k, im) in sc.imposed.iter().enumerate() {
        let q = reg.coord(&im.coordinate).ok_or_else(|| {
            let c = &im.coordinate;
            format!(
                "imposed[{k}]: unknown coordinate `{c}`{}",
                reg.coordinate_hint(c)
            )
        })?;
        let law = TimeLaw::new(&im.rate, reg.parameters(), &params)
            .and_then(|law| law.validate_starts(sc.duration).map(|()| law))
            .map_err(|e| {
                let at = e.path_under(&format!("imposed[{k}].rate"));
                format!("{at}: {}", e.message)
            })?;
        breakpoints.extend(law.breakpoints());
        imposed.push(Imposed {
            coord: q,
            initial: im.initial,
            law: ImposedLaw::Law(law),
        });
    }
    // A law on a driven coordinate would contradict its relation.
    if let Some(im) = imposed
        .iter()
        .find(|im| reg.coord_info(im.coord).is_driven())
    {
        return Err(format!(
            "`{}` is driven by other coordinates' rates: its motion cannot be imposed",
            reg.coord_info(im.coord).name
        ));
    }
    Ok((imposed, breakpoints))
}

/// The coordinates neither imposed by the scenario nor driven: a constant rate of the spec
/// joins `imposed`; the others are returned as (free, driven).
fn split_coordinates(
    m: &Mechanism,
    sc: &ScenarioSpec,
    base: &[f64],
    imposed: &mut Vec<Imposed>,
) -> (Vec<CoordId>, Vec<CoordId>) {
    let reg = &m.reg;
    let mut free = Vec::new();
    let mut driven = Vec::new();
    for (i, c) in reg.coordinates().iter().enumerate() {
        let q = CoordId(i);
        if imposed.iter().any(|x| x.coord == q) {
            continue;
        }
        if c.is_driven() {
            driven.push(q);
            continue;
        }
        if c.has_imposed_rate() {
            let w = reg.rate(q, 1).eval(base);
            imposed.push(Imposed {
                coord: q,
                initial: sc.initial.get(&c.name).map(|v| v[0]).unwrap_or(0.0),
                law: ImposedLaw::Constant(w),
            });
            continue;
        }
        free.push(q);
    }
    (free, driven)
}

/// Initial [q, q̇] of each free coordinate, each with its equation of motion; `initial` names
/// only coordinates.
fn free_initial(
    m: &Mechanism,
    sc: &ScenarioSpec,
    sol: &pfd::Solution,
    free: &[CoordId],
) -> Result<Vec<[f64; 2]>, String> {
    let reg = &m.reg;
    let mut initial = Vec::new();
    for &q in free {
        let name = &reg.coord_info(q).name;
        if !sol.eom.contains_key(name) {
            return Err(format!(
                "the coordinate `{name}` is neither imposed nor given an equation of motion \
                 (mark one equation of `pfd` with \"eom\": \"{name}\")"
            ));
        }
        initial.push(sc.initial.get(name).copied().unwrap_or([0.0, 0.0]));
    }
    for name in sc.initial.keys() {
        if reg.coord(name).is_none() {
            let hint = reg.coordinate_hint(name);
            return Err(format!("initial: unknown coordinate `{name}`{hint}"));
        }
    }
    Ok(initial)
}

/// Every input of the equations of motion (a motor torque) that a free coordinate's equation
/// holds is given a value by the scenario: the direct dynamics integrates the motion it drives.
/// (An imposed coordinate's inputs are found from its motion, and may be recorded.)
fn given_inputs(
    m: &Mechanism,
    sc: &ScenarioSpec,
    sol: &pfd::Solution,
    free: &[CoordId],
) -> Result<(), String> {
    for &q in free {
        let name = &m.reg.coord_info(q).name;
        let Some(e) = sol.eom.get(name) else { continue };
        for (input, v) in pfd::unknown_vars(m) {
            let held = e.contains_var(v);
            if held && sol.inputs.contains(&input) && !sc.values.contains_key(&input) {
                return Err(format!(
                    "the equation of motion of `{name}` holds the input `{input}`: give its \
                     value in `values`, or impose the motion of `{name}`"
                ));
            }
        }
    }
    Ok(())
}

/// M q̈ + h = 0 over the free coordinates, compiled: over the structured form's names when it
/// holds exactly these equations (a chain's equations are then never expanded into the
/// evaluator), else from the expanded equations.
pub(super) enum Dynamics {
    /// M (row-major) then h − Q, one compiled list.
    Expanded(Compiled),
    /// M and Q − h over the names ([`pfd::structured`]).
    Named(pfd::structured::CompiledMotion),
}

impl Dynamics {
    /// M (row-major, n×n) then h − Q at a registry point, into `out`.
    fn evaluate(&mut self, point: &[f64], out: &mut [f64]) {
        match self {
            Dynamics::Expanded(c) => c.evaluate(point, out),
            Dynamics::Named(c) => {
                let (mass, rhs) = c.evaluate(point);
                let n = rhs.len();
                for i in 0..n {
                    for j in 0..n {
                        out[i * n + j] = mass[(i, j)];
                    }
                    out[n * n + i] = -rhs[i];
                }
            }
        }
    }
}

/// The equations of motion of `free` over the structured form's names, when that form holds
/// exactly these equations (each from a resultant or moment theorem free of the links'
/// unknowns; its rows then are the solution's, as `tests/engine/structured.rs` proves).
fn named_dynamics(m: &Mechanism, free: &[CoordId]) -> Option<Dynamics> {
    let qs: Vec<crate::quantity::Quantity> = free
        .iter()
        .map(|&q| crate::quantity::Quantity {
            kind: crate::quantity::QuantityKind::Eom(m.reg.coord_info(q).name.clone()),
            basis: None,
            projection: None,
            linear: false,
        })
        .collect();
    let s = pfd::structured::Structured::of(m, &qs).ok()?;
    let motion = s.motion.as_ref().filter(|e| e.coordinates == free)?;
    motion.compile(&s.program).ok().map(Dynamics::Named)
}

/// M (row-major) then h of M q̈ + h = 0 over the free coordinates, compiled; every eom is
/// linear in the q̈.
fn compile_dynamics(
    m: &Mechanism,
    sol: &pfd::Solution,
    free: &[CoordId],
) -> Result<Dynamics, String> {
    if let Some(d) = named_dynamics(m, free) {
        return Ok(d);
    }
    let eq = pfd::EquationsOfMotion::over(m, sol, free)
        .map_err(|_| "an equation of motion is not linear in the accelerations".to_string())?;
    // M, then h − Q: M q̈ + (h − Q) = 0 over the free coordinates.
    let mut exprs: Vec<Expr> = eq.mass.into_iter().flatten().collect();
    exprs.extend(eq.velocity_terms.iter().zip(&eq.forces).map(|(h, q)| h - q));
    // Every coordinate imposed: nothing to solve for (the evaluator gets one dummy output).
    if exprs.is_empty() {
        exprs.push(m.reg.zero());
    }
    let refs: Vec<&Expr> = exprs.iter().collect();
    m.reg
        .compile(&refs)
        .map(Dynamics::Expanded)
        .map_err(|e| format!("compiling the equations of motion: {e}"))
}

/// The recorded unknowns' numerators then the integrands, compiled, with each one's scale
/// (1 / the unknown's denominator at the parameters).
fn compile_recorded(
    m: &Mechanism,
    sol: &pfd::Solution,
    base: &[f64],
    record: &[String],
    integrate: &[(String, Expr)],
) -> Result<(Compiled, Vec<f64>), String> {
    let reg = &m.reg;
    let mut rec: Vec<Expr> = Vec::new();
    let mut scales = Vec::new();
    for id in record {
        let v = sol
            .unknowns
            .get(id)
            .ok_or_else(|| format!("record: `{id}` is not a solved unknown"))?;
        rec.push(v.num.clone());
        scales.push(1.0 / v.den.eval(base));
    }
    for (_, e) in integrate {
        rec.push(e.clone());
        scales.push(1.0);
    }
    if rec.is_empty() {
        rec.push(reg.zero());
    }
    let refs: Vec<&Expr> = rec.iter().collect();
    let recorded = reg
        .compile(&refs)
        .map_err(|e| format!("compiling the recorded quantities: {e}"))?;
    Ok((recorded, scales))
}

/// q̇ of each driven coordinate, compiled.
fn compile_driven_rates(m: &Mechanism, driven: &[CoordId]) -> Result<Compiled, String> {
    let reg = &m.reg;
    let mut rates: Vec<Expr> = driven.iter().map(|&q| reg.dot(q)).collect();
    if rates.is_empty() {
        rates.push(reg.zero());
    }
    let refs: Vec<&Expr> = rates.iter().collect();
    reg.compile(&refs)
        .map_err(|e| format!("compiling the driven rates: {e}"))
}

/// The nonzero ground components of the loop closures, compiled; `None` without any.
fn compile_closure(m: &Mechanism) -> Result<Option<Compiled>, String> {
    let g0 = m.frames.ground();
    let rows: Vec<Expr> = m
        .closure_vectors()
        .iter()
        .flat_map(|v| v.express_in(&m.frames, g0))
        .filter(|e| !e.is_zero())
        .collect();
    if rows.is_empty() {
        return Ok(None);
    }
    let refs: Vec<&Expr> = rows.iter().collect();
    m.reg
        .compile(&refs)
        .map(Some)
        .map_err(|e| format!("compiling the loop closures: {e}"))
}

/// The links with dry friction: their sign's variable and their relative rate and
/// acceleration, compiled.
fn dry_links(m: &Mechanism) -> Result<Vec<Dry>, String> {
    let reg = &m.reg;
    let mut dry = Vec::new();
    for d in &m.dynamics.dry {
        let var = reg
            .var_ids()
            .find(|&v| matches!(reg.role(v), VarRole::Parameter(k) if reg.scalar_name(k) == d.sign))
            .ok_or_else(|| format!("no variable for `{}`", d.sign))?;
        let acc = d.rate.dt();
        let motion = reg
            .compile(&[&d.rate, &acc])
            .map_err(|e| format!("compiling the dry friction's rates: {e}"))?;
        dry.push(Dry {
            var: var.index(),
            motion,
            affine: crate::pfd::unknowns_in(m, &d.magnitude).is_empty(),
        });
    }
    Ok(dry)
}
