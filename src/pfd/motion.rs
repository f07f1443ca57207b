//! The equations of motion in matrix form, M(q) q̈ + h(q, q̇, t) = Q(q, t): the mass matrix,
//! the terms that vanish at rest, and the generalised forces, each entry exact and canonical;
//! and their compiled evaluation, for a tool that integrates or linearises them itself.
//!
//! The engine keeps each equation of motion as the residual of its theorem, dynamic side minus
//! actions, with the unknowns of the links eliminated: eom(qᵢ) = 0. That residual is linear in
//! the accelerations, and splits without any choice:
//! - Mᵢⱼ is the coefficient of q̈ⱼ in eom(qᵢ);
//! - Qᵢ is minus what is left when every rate and every acceleration is zero (the weight, the
//!   springs, the given actions, a forcing in t; a rate the spec imposes, a constant ω, is a
//!   parameter and stays, so the centrifugal terms of an imposed rotation are in Q);
//! - hᵢ is the rest: the terms that vanish at rest (Coriolis and centrifugal terms, viscous
//!   friction, and the accelerations of coordinates that have no equation of their own, an
//!   imposed rotation's θ̈₁).
//!
//! So eom(qᵢ) = Σⱼ Mᵢⱼ q̈ⱼ + hᵢ − Qᵢ, exactly. The signs follow the theorem's projection (a
//! moment projected on −z⃗₀ gives a negative M).

use super::{PfdError, Solution};
use crate::expr::{Compiled, CoordId, Expr, ExprError, VarId, VarRole, signed_sum};
use crate::mechanism::Mechanism;
use nalgebra::{DMatrix, DVector};
use std::fmt;

/// The equations of motion as M(q) q̈ + h(q, q̇, t) = Q(q, t), each entry exact.
///
/// The engine keeps each equation of motion as the residual of its theorem, dynamic side minus
/// actions, the links' unknowns eliminated: eom(qᵢ) = 0, linear in the accelerations. Mᵢⱼ is
/// the coefficient of q̈ⱼ in eom(qᵢ); Qᵢ is minus what is left when every rate and
/// acceleration is zero (the weight, springs, given actions, a forcing in t; a rate the spec
/// imposes, a constant ω, is a parameter and stays); hᵢ is the rest, the terms that vanish at
/// rest (Coriolis and centrifugal terms, viscous friction, the accelerations of coordinates
/// without an equation of their own). So eom(qᵢ) = Σⱼ Mᵢⱼ q̈ⱼ + hᵢ − Qᵢ exactly; the signs
/// follow the theorem's projection.
///
/// ```
/// use torseur::pfd::EquationsOfMotion;
/// let m = torseur::spec::load("examples/pendule_simple.json").unwrap();
/// let eq = EquationsOfMotion::of(&m).unwrap();
/// // The pendulum of length l: m l² θ̈ = −m g l sin θ.
/// assert_eq!(eq.coordinates(), ["theta"]);
/// let e = |s: &str| m.reg().parse(s).unwrap();
/// assert_eq!(eq.mass[0][0], e("m*l^2"));
/// assert!(eq.velocity_terms[0].is_zero());
/// assert_eq!(eq.forces[0], e("-m*g*l*sin(theta)"));
/// println!("{eq}");
/// ```
#[derive(Debug, Clone)]
pub struct EquationsOfMotion {
    coordinates: Vec<CoordId>,
    names: Vec<String>,
    /// M(q): `mass[i][j]` is the coefficient of q̈ⱼ in the equation of qᵢ.
    pub mass: Vec<Vec<Expr>>,
    /// h(q, q̇, t): the terms of each equation that vanish when every rate is zero.
    pub velocity_terms: Vec<Expr>,
    /// Q(q, t): the generalised forces, on the right.
    pub forces: Vec<Expr>,
}

impl EquationsOfMotion {
    /// The equations of motion of every coordinate the spec gives one (a theorem with `eom`),
    /// in the order of the spec's coordinates.
    pub fn of(m: &Mechanism) -> Result<EquationsOfMotion, PfdError> {
        let sol = super::solve(m)?;
        let coords: Vec<CoordId> = (0..m.reg.coordinates().len())
            .map(CoordId)
            .filter(|&q| sol.eom.contains_key(&m.reg.coord_info(q).name))
            .collect();
        EquationsOfMotion::over(m, &sol, &coords)
            .map_err(|coordinate| PfdError::NotLinearIn { coordinate })
    }

    /// The equations of `coords` (each must have one in `sol`), the accelerations of these
    /// coordinates in M and every other one's in h. Fails with the name of a coordinate whose
    /// equation is not linear in these accelerations.
    pub(crate) fn over(
        m: &Mechanism,
        sol: &Solution,
        coords: &[CoordId],
    ) -> Result<EquationsOfMotion, String> {
        let reg = &m.reg;
        let rates = rate_vars(reg);
        let mut mass = Vec::with_capacity(coords.len());
        let mut velocity_terms = Vec::with_capacity(coords.len());
        let mut forces = Vec::with_capacity(coords.len());
        let mut names = Vec::with_capacity(coords.len());
        for &qi in coords {
            let name = reg.coord_info(qi).name.clone();
            let (row, h, q) = split_row(&sol.eom[&name], coords, &rates).ok_or(name.clone())?;
            velocity_terms.push(h);
            forces.push(q);
            mass.push(row);
            names.push(name);
        }
        Ok(EquationsOfMotion {
            coordinates: coords.to_vec(),
            names,
            mass,
            velocity_terms,
            forces,
        })
    }

    /// The coordinates, in the order of the rows and columns.
    pub fn coordinates(&self) -> Vec<&str> {
        self.names.iter().map(String::as_str).collect()
    }

    /// The coordinate of row (and column) `i`.
    pub fn coordinate(&self, i: usize) -> CoordId {
        self.coordinates[i]
    }

    /// The engine's eom(qᵢ) rebuilt: Σⱼ Mᵢⱼ q̈ⱼ + hᵢ − Qᵢ.
    pub fn residual(&self, i: usize) -> Expr {
        let mut r = &self.velocity_terms[i] - &self.forces[i];
        for (j, mij) in self.mass[i].iter().enumerate() {
            r = &r + &(mij * &mij.registry().ddot(self.coordinates[j]));
        }
        r
    }

    /// Compiles M and Q − h into one evaluator. Its input is a registry point (the value of
    /// every variable, [`crate::output::numeric_point`]); the accelerations in it are not read
    /// for the coordinates of the rows.
    ///
    /// ```
    /// use torseur::pfd::EquationsOfMotion;
    /// use torseur::output::{Values, numeric_point};
    /// let m = torseur::spec::load("examples/pendule_simple.json").unwrap();
    /// let mut c = EquationsOfMotion::of(&m).unwrap().compile().unwrap();
    /// let values = Values::parse(r#"{"parameters": {"m": 2, "l": 0.5, "g": 9.81},
    ///     "coordinates": {"theta": [0.3, 0, 0]}}"#).unwrap();
    /// let point = numeric_point(&m, &values).unwrap();
    /// let a = c.accelerations(&point).unwrap();
    /// // θ̈ = −(g / l) sin θ.
    /// assert!((a[0] + 9.81 / 0.5 * 0.3_f64.sin()).abs() < 1e-12);
    /// ```
    pub fn compile(&self) -> Result<CompiledEquations, ExprError> {
        let n = self.mass.len();
        let mut exprs: Vec<Expr> = self.mass.iter().flatten().cloned().collect();
        exprs.extend((0..n).map(|i| &self.forces[i] - &self.velocity_terms[i]));
        let Some(first) = exprs.first() else {
            return Ok(CompiledEquations { compiled: None, n });
        };
        let reg = first.registry().clone();
        let refs: Vec<&Expr> = exprs.iter().collect();
        Ok(CompiledEquations {
            compiled: Some(reg.compile(&refs)?),
            n,
        })
    }
}

/// Every rate and acceleration variable of every coordinate (q̇, q̈ and the third
/// derivative): what is set to zero for the terms at rest.
pub(crate) fn rate_vars(reg: &crate::expr::Registry) -> Vec<VarId> {
    (0..reg.coordinates().len())
        .flat_map(|q| (1..=3u8).map(move |k| (q, k)))
        .filter_map(|(q, k)| reg.index_of(VarRole::Rate(CoordId(q), k)))
        .collect()
}

/// One equation e = 0 split as Σⱼ Mⱼ q̈ⱼ + h − Q: Mⱼ the coefficient of q̈ⱼ for each of
/// `coords`, Q minus what is left when the variables `at_rest` are zero, h the rest; None when
/// e is not linear in these accelerations. [`EquationsOfMotion::over`] splits each row so,
/// `at_rest` every rate ([`rate_vars`]); the answer key splits the equation it writes so.
pub(crate) fn split_row(
    e: &Expr,
    coords: &[CoordId],
    at_rest: &[VarId],
) -> Option<(Vec<Expr>, Expr, Expr)> {
    let reg = e.registry();
    let mut rest = e.clone();
    let mut row = Vec::with_capacity(coords.len());
    for &qj in coords {
        let mij = e.partial_rate(qj, 2);
        if !mij.partial_rate(qj, 2).is_zero() {
            return None;
        }
        rest = &rest - &(&mij * &reg.ddot(qj));
        row.push(mij);
    }
    let mut still = rest.clone();
    for &v in at_rest {
        still = still.substitute(v, &reg.zero());
    }
    Some((row, &rest - &still, -&still))
}

/// M(q) and Q − h compiled ([`EquationsOfMotion::compile`]).
pub struct CompiledEquations {
    compiled: Option<Compiled>,
    n: usize,
}

impl CompiledEquations {
    /// M and Q − h at a registry point.
    pub fn evaluate(&mut self, point: &[f64]) -> (DMatrix<f64>, DVector<f64>) {
        let n = self.n;
        let mut out = vec![0.0; n * n + n];
        if let Some(c) = self.compiled.as_mut() {
            c.evaluate(point, &mut out);
        }
        (
            DMatrix::from_row_slice(n, n, &out[..n * n]),
            DVector::from_column_slice(&out[n * n..]),
        )
    }

    /// The accelerations q̈ = M⁻¹ (Q − h) at a registry point, or None where M is singular.
    pub fn accelerations(&mut self, point: &[f64]) -> Option<DVector<f64>> {
        let (mass, rhs) = self.evaluate(point);
        if self.n == 0 {
            return Some(rhs);
        }
        mass.lu().solve(&rhs)
    }
}

impl fmt::Display for EquationsOfMotion {
    /// One line per coordinate, `q: M q̈ + h = Q` written out in the presentation form.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, name) in self.names.iter().enumerate() {
            let mut left: Vec<(bool, String)> = Vec::new();
            for (j, mij) in self.mass[i].iter().enumerate() {
                if !mij.is_zero() {
                    left.push(mij.times_text(&format!("ddot({})", self.names[j])));
                }
            }
            if !self.velocity_terms[i].is_zero() {
                left.push(self.velocity_terms[i].times_text(""));
            }
            let right = self.forces[i].presentation();
            writeln!(f, "{name}: {} = {right}", signed_sum(&left))?;
        }
        Ok(())
    }
}
