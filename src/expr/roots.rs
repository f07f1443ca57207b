//! Square roots in the canonical form (issue 37): a variable s per declared radicand P, reduced
//! by s² → P after every product, the same kind of rule as sin²q → 1 − cos²q.
//!
//! The rules' leading monomials (sin²q, p·p⁻¹, cos q·(1/cos q), s²) stay pairwise coprime
//! under an elimination order that puts the roots first (a radicand holds no root), so they
//! form a Gröbner basis and the reduced form is unique: every expression reads a₀ + Σ aᵢ sᵢ
//! (+ products of distinct roots), each aᵢ free of roots. Such a form is zero as a function
//! iff every aᵢ is zero **when no radicand is the square of a function** (then sᵢ is not a
//! quotient of polynomials, and a + b s = 0 forces a = b = 0), and no product of radicands is
//! one either. A radicand that is a square is refused when it is declared, the test made
//! through the rational parametrisation cos q = (1 − t²)/(1 + t²), sin q = 2t/(1 + t²) of each
//! angle, so that (2 + sin θ)², written out, is seen as one; products of two roots are not
//! tested (two roots of one mechanism have different radicands: the loop law's).
//!
//! A root denotes the nonnegative square root. Its time derivative, Ṗ/(2s), is not a
//! polynomial: a root whose radicand holds a coordinate is never differentiated (the loop law
//! is compared and printed, not derived again); one of the parameters alone is a constant.

use super::*;
use symbolica::poly::factor::Factorize;

/// Typed index of a square root of a [`Registry`] (see [`RegistryBuilder::roots`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct RootId(pub(crate) usize);

impl RootId {
    /// Index in declaration order.
    pub fn index(self) -> usize {
        self.0
    }
}

/// The symbol of a root's variable, `root(k)` in symbolica's atoms (never in a text: a text
/// writes `sqrt(...)`).
pub(super) fn root_symbol() -> Symbol {
    symbolica::symbol!("root")
}

impl Expr {
    /// s^(2k + r) → P^k s^r in every term, for every root s of radicand P.
    pub(super) fn reduce_roots(p: Poly, reg: &Registry) -> Poly {
        let live: Vec<&(usize, Poly)> = (reg.roots.iter())
            .filter(|(v, _)| p.degree(*v) >= 2)
            .collect();
        if live.is_empty() {
            return p;
        }
        let mut kept = p.zero();
        let mut parts = Vec::new();
        for t in 0..p.nterms() {
            let mut e = p.exponents(t).to_vec();
            let mut factor: Option<Poly> = None;
            for (v, radicand) in &live {
                let k = e[*v] / 2;
                if k == 0 {
                    continue;
                }
                e[*v] -= 2 * k;
                let power = radicand.pow(k as usize);
                factor = Some(match factor {
                    Some(f) => &f * &power,
                    None => power,
                });
            }
            let monomial = p.zero().monomial(p.coefficients[t].clone(), e);
            match factor {
                Some(f) => parts.push(&monomial * &f),
                None => kept = kept + monomial,
            }
        }
        parts.push(kept);
        super::reduce::balanced_sum(parts, reg)
    }

    /// (a, b) with self = a + b s for the root `r`: a and b free of s (the canonical form
    /// holds s to the first power at most).
    pub fn split_root(&self, r: RootId) -> (Expr, Expr) {
        let reg = self.registry();
        let v = reg.roots[r.0].0;
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for (c, e) in self.terms() {
            let mut e = e.to_vec();
            if e[v] == 0 {
                a.push((c.clone(), e));
            } else {
                e[v] -= 1;
                b.push((c.clone(), e));
            }
        }
        (Expr::from_terms(reg, a), Expr::from_terms(reg, b))
    }

    /// The roots of g = a v² + b v + c = 0 in the variable `v` (a length coordinate), when
    /// a is a nonzero number and b² − 4ac is no square: v = m ± √P, as (m, P) with
    /// m = −b/(2a) and P = (b² − 4ac)/(4a²), both free of v.
    ///
    /// ```
    /// use torseur::expr::{Registry, VarRole};
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::builder()
    ///     .parameters(&["R".into(), "L".into()])
    ///     .coordinate("theta", CoordinateKind::Angle)
    ///     .coordinate("x", CoordinateKind::Length)
    ///     .build()
    ///     .unwrap();
    /// let g = reg.parse("x^2 - 2*R*x*cos(theta) + R^2 - L^2").unwrap();
    /// let x = reg.index_of(VarRole::Value(reg.coord("x").unwrap())).unwrap();
    /// let (m, p) = g.quadratic_roots(x).unwrap();
    /// assert_eq!(m, reg.parse("R*cos(theta)").unwrap());
    /// assert_eq!(p, reg.parse("L^2 - R^2*sin(theta)^2").unwrap());
    /// ```
    pub fn quadratic_roots(&self, v: VarId) -> Option<(Expr, Expr)> {
        if self.p.degree(v.0) != 2 {
            return None;
        }
        let reg = self.registry();
        let d1 = self.derivative(v);
        let a2 = d1.derivative(v);
        let a = &a2.as_rational()? / &Rational::from(2);
        let x = reg.var(v.0);
        let b = &d1 - &(&a2 * &x);
        if b.contains_var(v) {
            return None;
        }
        let ax2 = &reg.constant(a.clone()) * &(&x * &x);
        let c = &(self - &ax2) - &(&b * &x);
        let four_a2 = &(&a * &a) * &Rational::from(4);
        let m = &b * &reg.constant(-(&a * &Rational::from(2)).inv());
        let disc = &(&b * &b) - &(&reg.constant(&a * &Rational::from(4)) * &c);
        let p = &disc * &reg.constant(four_a2.inv());
        (p.as_rational().is_none() && !is_square_function(&p)).then_some((m, p))
    }

    /// The roots this expression holds.
    pub fn roots_held(&self) -> Vec<RootId> {
        let reg = self.registry();
        (0..reg.roots.len())
            .filter(|&k| self.p.degree(reg.roots[k].0) > 0)
            .map(RootId)
            .collect()
    }
}

impl Registry {
    /// The square root `r` as an expression.
    pub fn root(self: &Rc<Self>, r: RootId) -> Expr {
        self.var(self.roots[r.0].0)
    }

    /// The radicand P of root `r`.
    pub fn radicand(self: &Rc<Self>, r: RootId) -> Expr {
        self.wrap(self.roots[r.0].1.clone())
    }

    /// The radicand's text, for printing `sqrt(...)`.
    pub(crate) fn radicand_text(&self, r: RootId) -> String {
        self.radicand_of(r).to_string()
    }

    /// The radicand of root `r`, over a registry of the same variables (for a printer that
    /// holds the registry by reference).
    pub(crate) fn radicand_of(&self, r: RootId) -> Expr {
        let reg = self.snapshot().expect("this thread holds symbolica");
        reg.wrap(self.roots[r.0].1.clone())
    }

    /// The declared roots, in order.
    pub fn root_ids(&self) -> impl Iterator<Item = RootId> + use<> {
        (0..self.roots.len()).map(RootId)
    }

    /// The root of radicand `p` (`sqrt(p)`): a declared root s of radicand P when p = c² P for
    /// a positive rational c (then c s), a rational constant's root when it is rational.
    pub fn sqrt_of(self: &Rc<Self>, p: &Expr) -> Result<Expr, String> {
        if let Some(c) = p.as_rational() {
            return rational_sqrt(&c).map(|r| self.constant(r)).ok_or_else(|| {
                format!("sqrt({c}) is not rational: only roots of declared radicands are exact")
            });
        }
        for (k, (_, radicand)) in self.roots.iter().enumerate() {
            let ratio = &p.p.lcoeff() / &radicand.lcoeff();
            if let Some(c) = rational_sqrt(&ratio)
                && p.p == radicand.clone().mul_coeff(ratio.clone())
            {
                return Ok(&self.constant(c) * &self.root(RootId(k)));
            }
        }
        let declared: Vec<String> = (self.root_ids())
            .map(|r| format!("sqrt({})", self.radicand(r)))
            .collect();
        Err(format!(
            "sqrt({p}) is not one of the mechanism's square roots ({})",
            match declared.is_empty() {
                true => "it has none".to_string(),
                false => declared.join(", "),
            }
        ))
    }

    /// Reads each root's radicand (after the aliases): an expression of the registry, with no
    /// root, no reciprocal and no rate in it, that is not the square of a function.
    pub(super) fn read_roots(&mut self, texts: &[(usize, RootText)]) -> Result<(), ExprError> {
        for (v, text) in texts {
            let base = self.snapshot()?;
            let (e, input) = match text {
                RootText::Text(t) => (base.parse(t)?, t.clone()),
                RootText::Expr(e) => {
                    let e = e.carried(&base)?;
                    let input = e.to_string();
                    (e, input)
                }
            };
            let refuse = |reason: String| ExprError::Unsupported {
                input: input.clone(),
                reason,
            };
            let bad = (0..base.nvars()).find(|&i| {
                e.contains_var(VarId(i))
                    && matches!(
                        base.roles[i],
                        VarRole::Root(_) | VarRole::Reciprocal(..) | VarRole::Rate(..)
                    )
            });
            if let Some(i) = bad {
                return Err(refuse(format!(
                    "a square root's radicand holds no root, no rate and no division by a \
                     coordinate (it holds `{}`)",
                    base.variable(VarId(i))
                )));
            }
            if e.as_rational().is_some() {
                return Err(refuse(
                    "a square root of a number is not a root of the mechanism".to_string(),
                ));
            }
            if is_square_function(&e) {
                return Err(refuse(format!(
                    "`{e}` is a square (or minus one): its root is that function or its \
                     opposite, write it"
                )));
            }
            self.roots.push((*v, e.into_poly()));
        }
        Ok(())
    }

    /// The value of every root in `point`, from its radicand's variables there (NaN when the
    /// radicand is negative or not given).
    pub fn fill_roots(&self, point: &mut [f64]) {
        for (v, radicand) in &self.roots {
            let mut total = 0.0;
            for t in 0..radicand.nterms() {
                let mut x = radicand.coefficients[t].to_f64();
                for (i, &k) in radicand.exponents(t).iter().enumerate() {
                    if k > 0 {
                        x *= point[i].powi(i32::from(k));
                    }
                }
                total += x;
            }
            point[*v] = total.sqrt();
        }
    }
}

/// A radicand as declared: a text of the spec syntax, or an expression of another registry
/// carried by name (the loop law's, solved over the geometry's registry).
#[derive(Debug, Clone)]
pub(crate) enum RootText {
    /// A text.
    Text(String),
    /// An expression of another registry.
    Expr(Expr),
}

/// √r for a rational r ≥ 0 that is the square of a rational.
fn rational_sqrt(r: &Rational) -> Option<Rational> {
    if r.is_negative() {
        return None;
    }
    let root = |n: &symbolica::domains::integer::Integer| {
        let f = n.to_string().parse::<f64>().ok()?.sqrt().round();
        let k = symbolica::domains::integer::Integer::from(f as i64);
        (f < 9.0e15 && &(&k * &k) == n).then_some(k)
    };
    let (n, d) = (root(&r.numerator())?, root(&r.denominator())?);
    Some(Rational::from_unchecked(n, d))
}

/// Whether `p` is ± the square of a function: with each angle's cos and sin replaced by their
/// rational parametrisation, p (1 + t²)^d, d even, is ± a square polynomial.
fn is_square_function(p: &Expr) -> bool {
    let reg = p.registry();
    let mut poly = p.p.clone();
    for c in &reg.coords {
        let Some((ci, si)) = c.trig else {
            continue;
        };
        if poly.degree(ci) == 0 && poly.degree(si) == 0 {
            continue;
        }
        poly = parametrised(&poly, ci, si);
    }
    let factors = poly.factor();
    if factors.iter().any(|(f, k)| !f.is_constant() && k % 2 == 1) {
        return false;
    }
    let mut product = poly.one();
    for (f, k) in &factors {
        if !f.is_constant() {
            product = &product * &f.pow(*k);
        }
    }
    let ratio = &poly.lcoeff() / &product.lcoeff();
    rational_sqrt(&ratio.abs()).is_some()
}

/// p with cos → (1 − t²), sin → 2t over (1 + t²) (t in the sine's variable), times
/// (1 + t²)^d for an even d at least the degree in (cos, sin).
fn parametrised(p: &Poly, ci: usize, si: usize) -> Poly {
    let d = (0..p.nterms())
        .map(|t| p.exponents(t)[ci] as usize + p.exponents(t)[si] as usize)
        .max()
        .unwrap_or(0);
    let d = d + d % 2;
    let mut t2 = vec![0u8; p.nvars()];
    t2[si] = 2;
    let one = p.one();
    let t_squared = p.zero().monomial(Rational::one(), t2);
    let cos = &one - &t_squared;
    let den = &one + &t_squared;
    let mut t1 = vec![0u8; p.nvars()];
    t1[si] = 1;
    let sin = p.zero().monomial(Rational::from(2), t1);
    let mut out = p.zero();
    for t in 0..p.nterms() {
        let mut e = p.exponents(t).to_vec();
        let (i, j) = (e[ci] as usize, e[si] as usize);
        e[ci] = 0;
        e[si] = 0;
        let term = p.zero().monomial(p.coefficients[t].clone(), e);
        out = out + &(&(&term * &cos.pow(i)) * &sin.pow(j)) * &den.pow(d - i - j);
    }
    out
}
