//! The branch of an explicit loop law x = m ± √P (issue 37), read at the spec's assembly
//! configuration: the initial configuration of its first scenario (the one its simulation
//! starts the closure solver from), else the first closed configuration the float backend
//! draws (its own Newton solve of the loop, seeded as `verify` seeds it).

use crate::expr::Expr;
use crate::mechanism::{ExplicitLaw, Mechanism};
use crate::output::Values;

/// An explicit loop law with its branch.
#[derive(Debug, Clone)]
pub struct Branch {
    /// +1 for m + √P, −1 for m − √P.
    pub sign: i8,
    /// x = m ± √P, the sign applied.
    pub value: Expr,
    /// The configuration the sign was read at.
    pub at: Assembly,
    /// x − m there.
    pub offset: f64,
}

/// An assembly configuration of a spec.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Assembly {
    /// The initial configuration of the scenario of this name.
    Scenario(String),
    /// The first closed configuration the float backend draws.
    Drawn,
}

impl std::fmt::Display for Assembly {
    /// In English, for `verify`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Assembly::Scenario(n) => write!(f, "the initial configuration of the scenario `{n}`"),
            Assembly::Drawn => {
                f.write_str("the first closed configuration the float backend draws")
            }
        }
    }
}

/// Relative size below which a number is zero at a configuration (the loop closed to about
/// 1e-12 by Newton, or given to a few digits by a scenario).
const ZERO: f64 = 1e-6;

/// The assembly configurations of the spec, in the order tried: each scenario's initial
/// configuration (its values, q and q̇ as given, q̈ = 0), then the first closed configuration
/// the float backend draws; each with its description.
pub(crate) fn assembly_configurations(m: &Mechanism) -> Vec<(Values, Assembly)> {
    let mut out = Vec::new();
    for sc in &m.spec.scenarios {
        let values = Values {
            parameters: sc.values.clone(),
            coordinates: (sc.initial.iter())
                .map(|(q, [x, v])| (q.clone(), [*x, *v, 0.0]))
                .collect(),
            unknowns: Default::default(),
            time: Some(0.0),
        };
        out.push((values, Assembly::Scenario(sc.name.clone())));
    }
    if let Ok(model) = crate::numeric::NumericModel::new(&m.spec) {
        let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
        if let Ok(s) = model.sample(&mut rng) {
            let values = Values {
                parameters: s.parameters,
                coordinates: s.coordinates,
                unknowns: Default::default(),
                time: Some(s.time),
            };
            out.push((values, Assembly::Drawn));
        }
    }
    out
}

/// The point (every variable `exprs` hold) at the first assembly configuration where
/// `closed` holds, with its description.
pub(crate) fn at_assembly(
    m: &Mechanism,
    exprs: &[&Expr],
    closed: &dyn Fn(&[f64]) -> bool,
) -> Option<(Vec<f64>, Assembly)> {
    for (values, at) in assembly_configurations(m) {
        let Ok(point) = crate::output::numeric_point_for(m, &values, exprs) else {
            continue;
        };
        if exprs.iter().all(|e| e.eval(&point).is_finite()) && closed(&point) {
            return Some((point, at));
        }
    }
    None
}

/// The branch of `law`: the sign of x − m at the spec's assembly configuration, the first
/// one where the loop closes (x − m = ±√P) away from a dead point (√P = 0).
pub fn explicit_law(m: &Mechanism, law: &ExplicitLaw) -> Option<Branch> {
    let x = m.reg.value(law.coordinate)?;
    let offset = &x - &law.center;
    let closed = |p: &[f64]| {
        let (d, r) = (offset.eval(p), law.root.eval(p));
        let size = d.abs().max(r.abs());
        size > 0.0 && r > ZERO * size && (d.abs() - r).abs() <= ZERO * size
    };
    let (point, at) = at_assembly(m, &[&offset, &law.root], &closed)?;
    let d = offset.eval(&point);
    let sign: i8 = if d > 0.0 { 1 } else { -1 };
    let root = match sign {
        1 => law.root.clone(),
        _ => -&law.root,
    };
    Some(Branch {
        sign,
        value: &law.center + &root,
        at,
        offset: d,
    })
}
