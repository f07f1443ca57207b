//! The float backend's own checks of what a spec may say, made when its model is built, so
//! that it refuses the same specs as the exact side (`tests/engine/parity.rs`) by its own
//! reading: an angle of rotation, an inertia matrix (symmetric, fixed in its solid, made
//! symmetric by a hypothesis).

use super::expr::{self, Node};
use super::{FrameInfo, SolidInfo};
use crate::wire::SpecFile;
use nalgebra::{Matrix3, Vector3};
use std::collections::BTreeMap;

/// The value of a node whose names are parameters (and coordinates, at `coords`).
pub(super) fn at(node: &Node, params: &[f64], coords: &[f64]) -> Result<f64, String> {
    let env = expr::Env::<f64> {
        params,
        coords,
        rates: &[],
        frames: &[],
        time: 0.0,
    };
    expr::eval_scalar(node, &env)
}

/// Whether two constant nodes agree at both draws of [`check_draw`].
fn same(a: &Node, b: &Node, nparams: usize) -> Result<bool, String> {
    for draw in 0..2 {
        let p = check_draw(nparams, draw);
        let (x, y) = (at(a, &p, &[])?, at(b, &p, &[])?);
        if (x - y).abs() > 1e-9 * x.abs().max(y.abs()).max(1.0) {
            return Ok(false);
        }
    }
    Ok(true)
}

/// An inertia operator is symmetric: entries [r][c] and [c][r] agree at two draws of the
/// parameters (integers 2, 3, 5, … and then their squares: two polynomials that differ give
/// different values there unless by coincidence at both).
pub(super) fn symmetric(matrix: &[[Node; 3]; 3], nparams: usize) -> Result<(), String> {
    for (r, c) in [(0, 1), (0, 2), (1, 2)] {
        if !same(&matrix[r][c], &matrix[c][r], nparams)? {
            return Err(format!(
                "the inertia matrix is not symmetric: entries [{r}][{c}] and [{c}][{r}] differ"
            ));
        }
    }
    Ok(())
}

/// The angle of an elementary rotation is, as the course turns its frames, an integer
/// combination of angle coordinates and angle parameters plus a multiple of π/2 (a constant
/// angle with exact cos and sin); anything else is refused.
pub(super) fn linear_angle(
    node: &Node,
    angle_param: &dyn Fn(usize) -> bool,
    angle_coord: &dyn Fn(usize) -> bool,
) -> Result<(), String> {
    let angles = Angles {
        param: angle_param,
        coord: angle_coord,
    };
    let (vars, k) = angles.form(node)?;
    if !k.is_finite() || vars.values().any(|c| !c.is_finite()) {
        return Err("division by zero in an angle".to_string());
    }
    // A frame turns by ±q + a constant: one coordinate at most, with coefficient ±1.
    let turning: Vec<f64> = vars
        .iter()
        .filter(|((kind, _), c)| *kind >= 1 && **c != 0.0)
        .map(|(_, c)| *c)
        .collect();
    if turning.len() > 1 || turning.iter().any(|c| c.abs() != 1.0) {
        return Err(
            "a coordinate enters a rotation angle with coefficient 1 or -1 (the angle \
                    is ±q + a constant)"
                .to_string(),
        );
    }
    if vars.values().any(|c| c.fract() != 0.0) {
        return Err(
            "an angle takes integer multiples of the angle coordinates and angle \
                    parameters"
                .to_string(),
        );
    }
    let quarter_turns = k / std::f64::consts::FRAC_PI_2;
    if (quarter_turns - quarter_turns.round()).abs() > 1e-9 {
        return Err("a constant angle written with numbers must be a multiple of pi/2".to_string());
    }
    Ok(())
}

/// An angle as a linear form: (coefficient of each variable, constant), with the variables
/// as (0, param), (1, coordinate) or (2, the pulsation of a phase).
type Form = (BTreeMap<(u8, usize), f64>, f64);

/// Which parameters and coordinates are angles.
struct Angles<'a> {
    param: &'a dyn Fn(usize) -> bool,
    coord: &'a dyn Fn(usize) -> bool,
}

impl Angles<'_> {
    /// The linear form of `n`, refused when it is not one in angles.
    fn form(&self, n: &Node) -> Result<Form, String> {
        let not_linear = || "an angle is an integer combination of angles and π/2".to_string();
        let constant = |f: &Form| f.0.values().all(|c| *c == 0.0).then_some(f.1);
        Ok(match n {
            // A phase k Ω t (checked when parsed): a variable of its own, Ω's.
            Node::Mul(..) | Node::Neg(_) | Node::Time if expr::holds_time(n) => {
                let (p, k) = expr::phase(n).ok_or_else(not_linear)?;
                (BTreeMap::from([((2, p), k)]), 0.0)
            }
            Node::Num(x) => (BTreeMap::new(), *x),
            Node::Param(p) if (self.param)(*p) => (BTreeMap::from([((0, *p), 1.0)]), 0.0),
            Node::Coord(c) if (self.coord)(*c) => (BTreeMap::from([((1, *c), 1.0)]), 0.0),
            Node::Param(_) | Node::Coord(_) => {
                return Err(
                    "this name is not an angle: an angle is an angle coordinate or a \
                            parameter declared with \"kind\": \"angle\""
                        .to_string(),
                );
            }
            Node::Neg(a) => {
                let (v, k) = self.form(a)?;
                (v.into_iter().map(|(x, c)| (x, -c)).collect(), -k)
            }
            Node::Add(a, b) | Node::Sub(a, b) => {
                let sign = if matches!(n, Node::Sub(..)) {
                    -1.0
                } else {
                    1.0
                };
                let (mut v, k) = self.form(a)?;
                let (w, l) = self.form(b)?;
                for (x, c) in w {
                    *v.entry(x).or_insert(0.0) += sign * c;
                }
                (v, k + sign * l)
            }
            Node::Mul(a, b) => {
                let (fa, fb) = (self.form(a)?, self.form(b)?);
                let (f, k) = match (constant(&fa), constant(&fb)) {
                    (Some(k), _) => (fb, k),
                    (None, Some(k)) => (fa, k),
                    (None, None) => return Err(not_linear()),
                };
                (f.0.into_iter().map(|(x, c)| (x, c * k)).collect(), f.1 * k)
            }
            Node::Div(a, b) => {
                let fa = self.form(a)?;
                let k = constant(&self.form(b)?).ok_or_else(not_linear)?;
                (
                    fa.0.into_iter().map(|(x, c)| (x, c / k)).collect(),
                    fa.1 / k,
                )
            }
            Node::Pow(a, e) => {
                let k = constant(&self.form(a)?).ok_or_else(not_linear)?;
                (BTreeMap::new(), k.powi(*e))
            }
            _ => return Err(not_linear()),
        })
    }
}

/// Parameter values for the checks at build time: integers 2, 3, 5, … (`draw` 0) and then
/// their square roots shifted (`draw` 1), so that two polynomials that differ give different
/// values at one of them unless by coincidence at both.
fn check_draw(n: usize, draw: usize) -> Vec<f64> {
    const PRIMES: [f64; 12] = [
        2.0, 3.0, 5.0, 7.0, 11.0, 13.0, 17.0, 19.0, 23.0, 29.0, 31.0, 37.0,
    ];
    (0..n)
        .map(|i| {
            let p = PRIMES[i % PRIMES.len()] + (i / PRIMES.len()) as f64 / 7.0;
            if draw == 0 { p } else { p.sqrt() + 0.5 }
        })
        .collect()
}

/// An inertia matrix given in a basis `b` other than its solid's frame `f` must describe the
/// same body however the coordinates move: moved to f (I_f = C I_b Cᵀ, C = R_fᵀ R_b), it is
/// the same at three positions of the mechanism. A basis turning relative to the solid is
/// refused unless the matrix is of revolution about the relative rotation's axis.
pub(super) fn fixed_in_solid(
    frames: &[FrameInfo],
    b: usize,
    f: usize,
    matrix: &[[Node; 3]; 3],
    spec: &SpecFile,
) -> Result<(), String> {
    if b == f {
        return Ok(());
    }
    let params = check_draw(spec.parameters.len(), 1);
    let value = |node: &Node, coords: &[f64]| at(node, &params, coords);
    let ib = Matrix3::from_fn(|r, c| value(&matrix[r][c], &[]).unwrap_or(f64::NAN));
    let mut seen: Vec<Matrix3<f64>> = Vec::new();
    for draw in 0..3 {
        let coords: Vec<f64> = (0..spec.coordinates.len())
            .map(|i| 0.3 + 0.7 * draw as f64 + 0.11 * i as f64)
            .collect();
        // Orientations down the tree, parents first: R_k = R_parent · Rot(axis, ±angle).
        let mut rot: Vec<Matrix3<f64>> = Vec::with_capacity(frames.len());
        for fr in frames {
            let r = match &fr.rotation {
                None if rot.is_empty() => Matrix3::identity(),
                None => rot[fr.parent],
                Some((axis, sign, angle)) => {
                    let a = sign * value(angle, &coords)?;
                    let axis = nalgebra::Unit::new_unchecked(Vector3::ith(*axis, 1.0));
                    rot[fr.parent] * nalgebra::Rotation3::from_axis_angle(&axis, a).into_inner()
                }
            };
            rot.push(r);
        }
        let c = rot[f].transpose() * rot[b];
        seen.push(c * ib * c.transpose());
    }
    let size = ib.amax().max(1.0);
    if seen.iter().all(|m| (m - seen[0]).amax() <= 1e-9 * size) {
        Ok(())
    } else {
        Err(format!(
            "the inertia matrix is given in basis {} which turns relative to the solid's frame \
             {}: give it in the solid's basis (or in a basis where it is of revolution about \
             the relative rotation axis)",
            frames[b].name, frames[f].name
        ))
    }
}

/// A hypothesis that makes a solid symmetric imposes its symmetries on the written matrix: a
/// product of inertia across a plane of symmetry (or about an axis of revolution) is zero,
/// and the two moments about an axis of revolution are equal. Each imposed entry must be
/// zero or equal already, or a single parameter that the hypothesis then sets.
pub(super) fn symmetries_hold(solid: &SolidInfo, nparams: usize) -> Result<(), String> {
    let Some(inr) = &solid.inertia else {
        return Ok(());
    };
    // The parameter an entry is, up to its sign.
    let single = |n: &Node| match n {
        Node::Param(p) => Some(*p),
        Node::Neg(a) => match **a {
            Node::Param(p) => Some(p),
            _ => None,
        },
        _ => None,
    };
    // Parameters the hypothesis has already set, and their value: no longer free.
    let mut set: BTreeMap<usize, Node> = BTreeMap::new();
    let same = |a: &Node, b: &Node| same(a, b, nparams).unwrap_or(false);
    let zero = Node::Num(0.0);
    for sym in &solid.symmetries {
        if sym.frame != inr.basis {
            continue;
        }
        let k = sym.axis;
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let mut zeros = vec![(k.min(i), k.max(i)), (k.min(j), k.max(j))];
        if sym.revolution {
            zeros.push((i.min(j), i.max(j)));
        }
        for (r, c) in zeros {
            let e = &inr.matrix[r][c];
            if same(e, &zero) {
                continue;
            }
            match single(e) {
                Some(p) => {
                    set.entry(p).or_insert(Node::Num(0.0));
                }
                None => {
                    return Err(format!(
                        "the symmetries of solid {} make entry [{r}][{c}] zero, but it is `{}`, \
                         which is not a single parameter",
                        solid.name, inr.text[r][c]
                    ));
                }
            }
        }
        if sym.revolution {
            let (a, b) = (i.min(j), i.max(j));
            // Through what the hypothesis has set already (B = A, then C = B is C = A).
            let resolved = |n: &Node| match single(n).and_then(|p| set.get(&p)) {
                Some(v) => v.clone(),
                None => n.clone(),
            };
            let (ea, eb) = (resolved(&inr.matrix[a][a]), resolved(&inr.matrix[b][b]));
            if same(&ea, &eb) {
                continue;
            }
            match single(&eb).filter(|p| !set.contains_key(p)) {
                Some(p) => {
                    set.insert(p, ea);
                }
                None => {
                    return Err(format!(
                        "the axis of revolution of solid {} makes entries [{a}][{a}] and \
                         [{b}][{b}] equal, but `{}` is not a single parameter",
                        solid.name, inr.text[b][b]
                    ));
                }
            }
        }
    }
    Ok(())
}

/// The degree of `node` in the first derivatives q̇ⱼ of the coordinates `free(j)` allows, or
/// why it is not a polynomial in them: a q̈, a rate inside sin, cos, or below a division line,
/// the time, a basis vector or an unknown (what a rate driven by other coordinates may hold:
/// a gear ratio −r1/r2 θ̇1, R θ̇ cos ψ; coordinates' values are coefficients).
pub(super) fn rate_degree(node: &Node, free: &dyn Fn(usize) -> bool) -> Result<u32, String> {
    let no = |what: &str| Err(format!("a driven rate holds {what}"));
    match node {
        Node::Num(_) | Node::Param(_) => Ok(0),
        Node::Rate(j, 1) if free(*j) => Ok(1),
        Node::Rate(..) => no("a rate that is not free, or an acceleration"),
        // A coefficient may hold the coordinates (ẋ = R θ̇ cos ψ, rolling on a plane).
        Node::Coord(_) => Ok(0),
        Node::Unknown(_) | Node::Time | Node::Basis(..) => no("an unknown, the time or a vector"),
        Node::Neg(a) => rate_degree(a, free),
        Node::Add(a, b) | Node::Sub(a, b) => Ok(rate_degree(a, free)?.max(rate_degree(b, free)?)),
        Node::Mul(a, b) => Ok(rate_degree(a, free)? + rate_degree(b, free)?),
        Node::Div(a, b) => match rate_degree(b, free)? {
            0 => rate_degree(a, free),
            _ => no("a rate below a division line"),
        },
        Node::Pow(a, n) => match (rate_degree(a, free)?, *n) {
            (0, _) => Ok(0),
            (d, n) if n > 0 => Ok(d * n as u32),
            _ => no("a rate to a negative power"),
        },
        Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => match rate_degree(a, free)? {
            0 => Ok(0),
            _ => no("a rate inside sin, cos or sqrt"),
        },
    }
}

/// Why a divisor is refused: what a spec may divide by.
const DIVISOR: &str = "a spec divides by a product of parameters only (…/k, …/(2*m*l)), not by a \
     sum, a coordinate, a rate or a sin or cos";

/// Whether `node` is a number times a product of powers of parameters (what a spec may
/// divide by: the exact side then keeps a variable 1/p for each).
fn product_of_parameters(node: &Node) -> bool {
    match node {
        Node::Num(_) | Node::Param(_) => true,
        Node::Neg(a) | Node::Pow(a, _) => product_of_parameters(a),
        Node::Mul(a, b) | Node::Div(a, b) => product_of_parameters(a) && product_of_parameters(b),
        _ => false,
    }
}

/// Every division of `node` is by a product of parameters (a negative power likewise); an
/// unknown below the line is left to its own message (`expr::unknown_degree`).
pub(super) fn divisors(node: &Node) -> Result<(), String> {
    let refused = |d: &Node| !product_of_parameters(d) && matches!(expr::unknown_degree(d), Ok(0));
    match node {
        Node::Div(a, b) if refused(b) => Err(DIVISOR.into()),
        Node::Pow(a, n) if *n < 0 && refused(a) => Err(DIVISOR.into()),
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            divisors(a)?;
            divisors(b)
        }
        Node::Neg(a) | Node::Pow(a, _) | Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => divisors(a),
        _ => Ok(()),
    }
}
