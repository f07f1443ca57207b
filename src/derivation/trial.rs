//! An unknown of a trial motion (« régime forcé »): under its hypothesis, q = the motion, q̇
//! and q̈ its time derivatives in eom(q); the equation must hold at every t, so the
//! coefficient of each harmonic (cos Ω t, sin Ω t, the constant) vanishes: a linear system in
//! the unknowns, solved exactly (X = F0/(k − M Ω²)).

use super::{Derivation, DeriveError, Step, StepKind, Value};
use crate::expr::{Expr, Fraction, Registry, Trig, VarRole};
use crate::mechanism::{Hypothesis, Mechanism, Trial};
use crate::quantity::Quantity;
use std::rc::Rc;

/// The hypothesis whose trial motion has the unknown `name`.
pub fn trial_of<'a>(m: &'a Mechanism, name: &str) -> Option<(&'a Hypothesis, &'a Trial)> {
    m.hypotheses.iter().find_map(|h| {
        let t = h.trial.as_ref()?;
        t.unknowns.iter().any(|(n, _)| n == name).then_some((h, t))
    })
}

fn err(q: &Quantity, message: String) -> DeriveError {
    DeriveError::new(q, message)
}

/// The text of a harmonic: `cos(Omega*t)`, `sin(2*Omega*t)`, `1` for the constant.
fn harmonic_text(reg: &Rc<Registry>, angle: &[(crate::expr::CoordId, i32)], f: Trig) -> String {
    if angle.is_empty() {
        return "1".to_string();
    }
    let parts: Vec<String> = angle
        .iter()
        .map(|&(q, k)| {
            let n = &reg.coord_info(q).name;
            match k {
                1 => n.clone(),
                -1 => format!("-{n}"),
                _ => format!("{k}*{n}"),
            }
        })
        .collect();
    format!("{}({})", f.name(), parts.join(" + ").replace("+ -", "- "))
}

/// The residual of eom(q) under the trial's hypothesis, refused when a coordinate, a rate or
/// an angle other than a phase Ω t is left in it.
fn balance(m: &Mechanism, q: &Quantity, h: &Hypothesis, eom: &Expr) -> Result<Expr, DeriveError> {
    let reg = &m.reg;
    let r = h.apply(eom);
    for v in reg.var_ids().filter(|v| r.contains_var(*v)) {
        let left = match reg.role(v) {
            VarRole::Cos(c) | VarRole::Sin(c) => {
                let i = reg.coord_info(c);
                (!i.is_constant() && i.phase().is_none()).then(|| i.name.clone())
            }
            VarRole::Value(c) | VarRole::Rate(c, _) => Some(reg.coord_info(c).name.clone()),
            _ => None,
        };
        if let Some(c) = left {
            return Err(err(
                q,
                format!(
                    "under `{}`, the equation of motion still holds the coordinate `{c}`: the \
                     trial motion leaves it free (fix it in the hypothesis, `fixed_coordinates` \
                     or `equilibrium`)",
                    h.name
                ),
            ));
        }
    }
    Ok(r)
}

/// One row of the system per harmonic: the coefficients of the unknowns and the rest.
type Row = (String, Vec<Expr>, Expr);

/// The rows of the residual `r`, refused when it is not linear in the unknowns.
fn rows(m: &Mechanism, q: &Quantity, t: &Trial, r: &Expr) -> Result<Vec<Row>, DeriveError> {
    let reg = &m.reg;
    let f = r.to_fourier().ok_or_else(|| {
        err(
            q,
            "the equation of motion divides by a cosine or sine: no harmonic balance".into(),
        )
    })?;
    let zero = reg.zero();
    let mut out = Vec::new();
    for (angle, trig, c) in f.terms() {
        let coefficients: Vec<Expr> = t.unknowns.iter().map(|(_, v)| c.derivative(*v)).collect();
        let nonlinear = coefficients
            .iter()
            .any(|a| t.unknowns.iter().any(|(_, v)| a.contains_var(*v)));
        if nonlinear {
            return Err(err(
                q,
                format!(
                    "the equation of motion is not linear in `{}` along the trial motion: its \
                     unknowns cannot be solved harmonic by harmonic",
                    reg.coord_info(t.coord).name
                ),
            ));
        }
        let rest = (t.unknowns.iter()).fold(c.clone(), |e, (_, v)| e.substitute(*v, &zero));
        out.push((harmonic_text(reg, angle.terms(), trig), coefficients, rest));
    }
    Ok(out)
}

/// The determinant of a square matrix of expressions (Laplace along the first row: the
/// systems are 1×1 to 3×3).
fn determinant(reg: &Rc<Registry>, a: &[Vec<Expr>]) -> Expr {
    match a.len() {
        0 => reg.one(),
        1 => a[0][0].clone(),
        n => (0..n).fold(reg.zero(), |acc, j| {
            let minor: Vec<Vec<Expr>> = a[1..]
                .iter()
                .map(|row| (0..n).filter(|&k| k != j).map(|k| row[k].clone()).collect())
                .collect();
            let term = &a[0][j] * &determinant(reg, &minor);
            if j % 2 == 0 {
                &acc + &term
            } else {
                &acc - &term
            }
        }),
    }
}

/// The first choice of `n` rows among `rows` (in order) whose matrix is regular, with its
/// determinant.
fn regular(reg: &Rc<Registry>, rows: &[Row], n: usize) -> Option<(Vec<usize>, Expr)> {
    fn choose(k: usize, from: usize, len: usize, acc: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if acc.len() == k {
            out.push(acc.clone());
            return;
        }
        for i in from..len {
            acc.push(i);
            choose(k, i + 1, len, acc, out);
            acc.pop();
        }
    }
    let mut all = Vec::new();
    choose(n, 0, rows.len(), &mut Vec::new(), &mut all);
    all.into_iter().find_map(|pick| {
        let a: Vec<Vec<Expr>> = pick.iter().map(|&i| rows[i].1.clone()).collect();
        let d = determinant(reg, &a);
        (!d.is_zero()).then_some((pick, d))
    })
}

/// The solution of Σⱼ aᵢⱼ uⱼ + bᵢ = 0 by Cramer's rule, each unknown nᵢ / det: (the nᵢ, det);
/// refused, with the fix, when a harmonic holds no unknown or the rows are too few or
/// incompatible.
fn solve(
    m: &Mechanism,
    q: &Quantity,
    t: &Trial,
    rows: &[Row],
) -> Result<(Vec<Expr>, Expr), DeriveError> {
    let reg = &m.reg;
    let coord = &reg.coord_info(t.coord).name;
    if let Some((h, _, _)) = rows.iter().find(|(_, a, _)| a.iter().all(Expr::is_zero)) {
        return Err(err(
            q,
            format!(
                "the harmonic `{h}` of eom({coord}) holds none of the trial's unknowns, so it \
                 cannot vanish: {}",
                add_term(h)
            ),
        ));
    }
    let n = t.unknowns.len();
    let (pick, det) = regular(reg, rows, n).ok_or_else(|| {
        err(
            q,
            format!(
                "the harmonics of eom({coord}) do not determine the trial's {n} unknowns: drop \
                 the unknowns the equation does not fix"
            ),
        )
    })?;
    let nums: Vec<Expr> = (0..n)
        .map(|j| {
            let a: Vec<Vec<Expr>> = (pick.iter())
                .map(|&i| {
                    let mut row = rows[i].1.clone();
                    row[j] = -&rows[i].2;
                    row
                })
                .collect();
            determinant(reg, &a)
        })
        .collect();
    // The other harmonics must vanish with this solution: Σ aⱼ nⱼ + b det = 0.
    for (_, (h, a, b)) in rows.iter().enumerate().filter(|(i, _)| !pick.contains(i)) {
        let rest = (a.iter().zip(&nums)).fold(b * &det, |acc, (aj, nj)| &acc + &(aj * nj));
        if !rest.is_zero() {
            return Err(err(
                q,
                format!(
                    "the harmonic `{h}` of eom({coord}) cannot vanish with the others: {}",
                    add_term(h)
                ),
            ));
        }
    }
    Ok((nums, det))
}

/// The value of the trial unknown `name` of `q`, with the trial's steps when `with_steps`.
pub(super) fn derive(
    m: &Mechanism,
    q: &Quantity,
    name: &str,
    eom: Expr,
    with_steps: bool,
) -> Result<Derivation, DeriveError> {
    let (h, t) = trial_of(m, name).ok_or_else(|| err(q, format!("`{name}` is no trial's")))?;
    let coord = m.reg.coord_info(t.coord).name.clone();
    let r = balance(m, q, h, &eom)?;
    let rows = rows(m, q, t, &r)?;
    let k = t.unknowns.iter().position(|(n, _)| n == name).unwrap_or(0);
    let value = value(m, q, t, &rows, k)?;
    let mut steps = Vec::new();
    if with_steps {
        let mut e = t.motion.clone();
        for order in 0..=2u8 {
            if order != 1 {
                steps.push(Step {
                    label: rate_label(&coord, order),
                    kind: StepKind::TrialMotion {
                        coordinate: coord.clone(),
                        order,
                    },
                    theorem: "mouvement cherché".to_string(),
                    value: Value::Scalar(e.clone()),
                });
            }
            e = e.dt();
        }
        steps.push(Step {
            label: format!("eom({coord})"),
            kind: StepKind::Balance {
                coordinate: coord,
                hypothesis: h.name.clone(),
                unknowns: t.unknowns.iter().map(|(_, v)| *v).collect(),
            },
            theorem: "équation du mouvement pour tout t".to_string(),
            value: Value::Scalar(r),
        });
    }
    Ok(Derivation {
        quantity: q.clone(),
        steps,
        value,
    })
}

/// The solved value of the `k`-th unknown: a polynomial, or a quotient by a polynomial in the
/// parameters.
fn value(
    m: &Mechanism,
    q: &Quantity,
    t: &Trial,
    rows: &[Row],
    k: usize,
) -> Result<Value, DeriveError> {
    let (nums, det) = solve(m, q, t, rows)?;
    let f = Fraction::new(nums[k].clone(), det.clone()).ok_or_else(|| {
        err(
            q,
            format!(
                "the trial's unknowns divide by `{det}`, which is not a polynomial in the \
                 parameters"
            ),
        )
    })?;
    Ok(if f.is_whole() {
        Value::Scalar(f.num)
    } else {
        Value::Quotient(f)
    })
}

/// The fix for a harmonic `h` the trial cannot cancel.
fn add_term(h: &str) -> String {
    format!("add `Y*{h}` to the trial motion, with `Y` among its unknowns (a name of its own)")
}

fn rate_label(c: &str, order: u8) -> String {
    match order {
        0 => c.to_string(),
        1 => format!("dot({c})"),
        _ => format!("ddot({c})"),
    }
}
