//! Relations that hold along the motions without being identities: lhs − rhs is then a
//! combination Σ cᵢ eom(qᵢ) of the spec's equations of motion whose coefficients may hold
//! the coordinates and the rates (the kinetic energy theorem, dEc/dt − P = Σ q̇ᵢ eom(qᵢ)).
//!
//! The decision: the equations of motion are affine in the accelerations of their
//! coordinates, E = M q̈ + h; along a motion they determine those accelerations. With a the
//! coefficients of the same accelerations in e = lhs − rhs (affine in them), the combination
//! c solves Mᵀ c = a, by Cramer's rule c = N / D, D = det M; then D e − Σ Nᵢ Eᵢ holds none of
//! the accelerations, and e vanishes along every motion exactly when it is zero: every state
//! (q, q̇), and every acceleration of a coordinate without an equation of motion (a motor's
//! coordinate whose torque is the unknown), is reached by some motion.

use super::reader::Reader;
use super::{Factor, VerifyError};
use crate::expr::{CoordId, Expr};

/// Beyond this many equations of motion the determinants are not expanded.
const MOST_EQUATIONS: usize = 4;

/// An equation of motion: its coordinate's name, the coordinate, its residual.
type Eom = (String, CoordId, Expr);

/// What the equations of motion say of e = lhs − rhs.
pub(super) enum Along {
    /// e = Σ cᵢ eom(qᵢ): each coordinate with its coefficient cᵢ (the nonzero ones).
    Combination(Vec<(String, Factor)>),
    /// e holds no acceleration the equations of motion determine (nothing to use them for),
    /// or it is not zero along the motions.
    No,
}

/// Whether e = lhs − rhs (times the denominator `den` typed, a polynomial in the parameters)
/// is zero along every motion; the combination of equations of motion it is then.
///
/// Under a hypothesis an equation of motion may hold no acceleration (constant rates: the
/// equation then constrains the states); what the others leave of e is then tried as an exact
/// multiple of one such equation.
pub(super) fn along_motions(
    reader: &mut Reader,
    e: &Expr,
    den: &Expr,
) -> Result<Along, VerifyError> {
    let m = reader.m;
    if !m.dynamics.theorems.iter().any(|t| t.eom.is_some()) {
        return Ok(Along::No);
    }
    let reg = m.reg.clone();
    let eoms: Vec<Eom> = (reader.solution()?.eom.clone().into_iter())
        .filter_map(|(n, eom)| reg.coord(&n).map(|q| (n, q, eom)))
        .map(|(n, q, eom)| (n, q, reader.under(eom)))
        .filter(|(_, _, eom)| !eom.is_zero())
        .collect();
    let all: Vec<CoordId> = eoms.iter().map(|(_, q, _)| *q).collect();
    let holds_acceleration = |x: &Expr| all.iter().any(|&q| !x.partial_rate(q, 2).is_zero());
    // The equations that determine accelerations, and those that constrain the states.
    let (dynamic, statics): (Vec<&Eom>, Vec<&Eom>) =
        eoms.iter().partition(|(_, _, eom)| holds_acceleration(eom));
    let qs: Vec<CoordId> = dynamic.iter().map(|(_, q, _)| *q).collect();
    let a: Vec<Expr> = qs.iter().map(|&q| e.partial_rate(q, 2)).collect();
    let eliminates = a.iter().any(|x| !x.is_zero());
    if !eliminates && statics.is_empty() {
        return Ok(Along::No);
    }
    let (d, n) = if eliminates {
        combination(&dynamic, &qs, &a)?
    } else {
        (reg.one(), vec![reg.zero(); qs.len()])
    };
    let combined = Expr::sum(
        &reg,
        (n.iter().zip(&dynamic)).map(|(ni, (_, _, ei))| ni * ei),
    );
    let rest = reader.under(&(&d * e) - &combined);
    let below = &d * den;
    let mut terms: Vec<(String, Factor)> = (dynamic.iter().zip(&n))
        .filter(|(_, ni)| !ni.is_zero())
        .map(|((name, _, _), ni)| (name.clone(), lowest(ni.clone(), &below)))
        .collect();
    if rest.is_zero() {
        return Ok(Along::Combination(terms));
    }
    // What is left, a multiple of an equation that holds no acceleration here.
    for (name, _, s) in &statics {
        if let Some(c) = rest.exact_div(s) {
            terms.push((name.clone(), lowest(c, &below)));
            terms.sort_by(|x, y| x.0.cmp(&y.0));
            return Ok(Along::Combination(terms));
        }
    }
    if !eliminates {
        return Ok(Along::No);
    }
    let out = |why: &str| Err(VerifyError::OutOfReach(why.to_string()));
    if !m.closures.is_empty() {
        return out(
            "lhs − rhs is not zero along the motions once the accelerations are replaced, but \
             the loop closure's relations between the coordinates themselves are not used \
             here: the question is undecided",
        );
    }
    if reader.hypothesis.is_some_and(|h| !h.first_order.is_empty()) {
        return out(
            "the equations of motion are not substituted at first order in small parameters: \
             the question is undecided",
        );
    }
    Ok(Along::No)
}

/// The equations `dynamic` (affine in the accelerations of `qs`) and the coefficients `a`
/// of these accelerations in e: D = det M and the numerators N of c = N / D, Mᵀ c = a
/// (Cramer's rule), so that D e − Σ Nᵢ Eᵢ holds none of the accelerations.
fn combination(
    dynamic: &[&Eom],
    qs: &[CoordId],
    a: &[Expr],
) -> Result<(Expr, Vec<Expr>), VerifyError> {
    let out = |why: String| VerifyError::OutOfReach(why);
    let affine = |x: &Expr| qs.iter().all(|&q| x.partial_rate(q, 2).is_zero());
    if !a.iter().all(affine) {
        return Err(out(
            "lhs − rhs is not linear in the accelerations: the equations of motion are not \
             substituted into a product of accelerations"
                .into(),
        ));
    }
    if qs.len() > MOST_EQUATIONS {
        return Err(out(format!(
            "lhs − rhs holds accelerations and the spec has {} equations of motion: their \
             combination is sought for at most {MOST_EQUATIONS}",
            qs.len()
        )));
    }
    // Mᵀ: row j, column i is the coefficient of q̈ⱼ in eom(qᵢ).
    let mt: Vec<Vec<Expr>> = qs
        .iter()
        .map(|&qj| {
            dynamic
                .iter()
                .map(|(_, _, ei)| ei.partial_rate(qj, 2))
                .collect()
        })
        .collect();
    if !mt.iter().flatten().all(affine) {
        return Err(out(
            "an equation of motion is not linear in the accelerations".into(),
        ));
    }
    let d = determinant(&mt);
    if d.is_zero() {
        return Err(out(
            "the equations of motion do not determine the accelerations here (their matrix of \
             inertia is singular under the hypothesis)"
                .into(),
        ));
    }
    let n = (0..qs.len())
        .map(|i| {
            let replaced: Vec<Vec<Expr>> = (mt.iter().zip(a))
                .map(|(row, aj)| {
                    let mut row = row.clone();
                    row[i] = aj.clone();
                    row
                })
                .collect();
            determinant(&replaced)
        })
        .collect();
    Ok((d, n))
}

/// n / d in lowest terms: an exact quotient when d divides n, else both divided by their
/// polynomial gcd.
fn lowest(n: Expr, d: &Expr) -> Factor {
    if let Some(q) = n.exact_div(d) {
        let one = d.registry().one();
        return Factor {
            numerator: q,
            denominator: one,
        };
    }
    match n.polynomial_gcd(d) {
        Some(g) => match (n.exact_div(&g), d.exact_div(&g)) {
            (Some(a), Some(b)) => normalised(a, b),
            _ => normalised(n, d.clone()),
        },
        None => normalised(n, d.clone()),
    }
}

/// A numeric denominator folded into the numerator (n / 2 is ½ n).
fn normalised(n: Expr, d: Expr) -> Factor {
    if d.as_rational().is_some()
        && let Some(q) = n.div_constant(&d)
    {
        return Factor {
            numerator: q,
            denominator: d.registry().one(),
        };
    }
    Factor {
        numerator: n,
        denominator: d,
    }
}

/// The determinant of a square matrix of at most [`MOST_EQUATIONS`] rows, by expansion along
/// its first row.
fn determinant(a: &[Vec<Expr>]) -> Expr {
    match a.len() {
        0 => unreachable!("a matrix of the equations of motion has a row"),
        1 => a[0][0].clone(),
        k => {
            let reg = a[0][0].registry().clone();
            let terms = (0..k).filter(|&j| !a[0][j].is_zero()).map(|j| {
                let minor: Vec<Vec<Expr>> = a[1..]
                    .iter()
                    .map(|row| (0..k).filter(|&c| c != j).map(|c| row[c].clone()).collect())
                    .collect();
                let t = &a[0][j] * &determinant(&minor);
                if j % 2 == 0 { t } else { -&t }
            });
            Expr::sum(&reg, terms.collect::<Vec<_>>())
        }
    }
}
