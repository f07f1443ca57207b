//! The canonical form's reduction and the sums that build it: sin²q → 1 − cos²q (cos²q →
//! 1 − sin²q for an angle whose sine a loop closure divides by) and p·(1/p) → 1 after a
//! product, in one pass; sums of products reduced once; sums added along a balanced tree.

use super::*;
use std::collections::BTreeMap;

impl Expr {
    /// Brings a product back to canonical form: s² → P for every square root s of radicand P
    /// (first: P may bring sin² back), sin²q → 1 − cos²q for every angle, and
    /// p·(1/p) → 1 for every parameter the mechanism divides by. The two rules' leading
    /// monomials (sin²q, p·p⁻¹) are pairwise coprime, so they form a Gröbner basis and the
    /// reduced form is unique: equality stays structural.
    pub(super) fn reduce(p: Poly, reg: &Registry) -> Poly {
        let p = Expr::reduce_roots(p, reg);
        let p = Expr::reduce_trig(p, reg);
        Expr::reduce_inverses(p, reg)
    }

    /// p^a (1/p)^b → p^(a − min) (1/p)^(b − min) in every term.
    fn reduce_inverses(p: Poly, reg: &Registry) -> Poly {
        let pairs: Vec<(usize, usize)> = reg
            .inverse_pairs()
            .filter(|&(v, w)| p.degree(v) > 0 && p.degree(w) > 0)
            .collect();
        if pairs.is_empty() {
            return p;
        }
        let n = p.nvars();
        let mut coefficients = Vec::with_capacity(p.nterms());
        let mut exponents = Vec::with_capacity(p.nterms() * n);
        for t in 0..p.nterms() {
            let mut e = p.exponents(t).to_vec();
            for &(v, w) in &pairs {
                let k = e[v].min(e[w]);
                e[v] -= k;
                e[w] -= k;
            }
            coefficients.push(p.coefficients[t].clone());
            exponents.extend_from_slice(&e);
        }
        // Sorts and combines the terms that became alike.
        Poly::from_coefficient_list(coefficients, exponents, reg.vars.clone(), &Q)
    }

    /// sin²q → 1 − cos²q for every angle (cos²q → 1 − sin²q for an angle whose sine a loop
    /// closure divides by), in one pass: a term with sin^(2k+r) q becomes
    /// Σⱼ C(k, j) (−1)ʲ cos^(2j) q sin^r q, for every such angle at once.
    ///
    /// The terms that share the powers k and the choices j of every angle are all moved by the
    /// same exponent vector, and a translation keeps the lex order: each such class is a
    /// sorted run, built in place. The runs are then merged, with no sort.
    fn reduce_trig(p: Poly, reg: &Registry) -> Poly {
        // (reduced variable, its partner) of each angle whose reduced power reaches 2.
        let rules: Vec<(usize, usize)> = reg
            .coords
            .iter()
            .filter_map(|c| {
                let (ci, si) = c.trig?;
                let (ci, si) = if c.cos_reduced { (si, ci) } else { (ci, si) };
                (p.degree(si) >= 2).then_some((si, ci))
            })
            .collect();
        if rules.is_empty() {
            return p;
        }
        let mut kept = p.zero();
        let mut runs: BTreeMap<Vec<(u8, u8)>, Poly> = BTreeMap::new();
        let (mut ks, mut js) = (vec![0u8; rules.len()], vec![0u8; rules.len()]);
        let mut key: Vec<(u8, u8)> = Vec::with_capacity(rules.len());
        let mut y: Vec<u8> = Vec::with_capacity(p.nvars());
        for t in 0..p.nterms() {
            let e = p.exponents(t);
            for (k, &(s, _)) in ks.iter_mut().zip(&rules) {
                *k = e[s] / 2;
            }
            if ks.iter().all(|&k| k == 0) {
                kept.coefficients.push(p.coefficients[t].clone());
                kept.exponents.extend_from_slice(e);
                continue;
            }
            // Every choice j ≤ k of every rule, as an odometer.
            js.fill(0);
            loop {
                let mut coef = p.coefficients[t].clone();
                y.clear();
                y.extend_from_slice(e);
                for (r, &(s, c)) in rules.iter().enumerate() {
                    let (k, j) = (ks[r], js[r]);
                    if k == 0 {
                        continue;
                    }
                    y[s] -= 2 * k;
                    y[c] += 2 * j;
                    let b = binomial(k, j);
                    if j % 2 == 1 || b != 1 {
                        let sign = if j % 2 == 0 { 1 } else { -1 };
                        coef = &coef * &Rational::new(sign * b, 1);
                    }
                }
                key.clear();
                key.extend(ks.iter().copied().zip(js.iter().copied()));
                let run = match runs.get_mut(key.as_slice()) {
                    Some(run) => run,
                    None => runs.entry(key.clone()).or_insert_with(|| p.zero()),
                };
                run.coefficients.push(coef);
                run.exponents.extend_from_slice(&y);
                // Next choice.
                let Some(r) = (0..rules.len()).find(|&r| js[r] < ks[r]) else {
                    break;
                };
                js[r] += 1;
                js[..r].fill(0);
            }
        }
        let mut runs: Vec<Poly> = runs.into_values().collect();
        runs.push(kept);
        balanced_sum(runs, reg)
    }

    /// Σ ± aᵢ bᵢ (`true` subtracts), brought to the canonical form once for the whole sum.
    /// The reduction is the normal form modulo sin²q + cos²q − 1 and p·p⁻¹ − 1, a linear map,
    /// so reducing the sum equals summing the reduced products, at a fraction of the cost.
    pub(crate) fn sum_of_products(reg: &Rc<Registry>, terms: &[(&Expr, &Expr, bool)]) -> Expr {
        super::budget::product(terms.iter().map(|(a, b, _)| (a.nterms(), b.nterms())));
        let raw: Vec<Poly> = terms
            .iter()
            .filter(|(a, b, _)| !a.is_zero() && !b.is_zero())
            .map(|(a, b, minus)| {
                debug_assert!(Rc::ptr_eq(&a.reg, &b.reg), "expressions of two registries");
                let p = &a.p * &b.p;
                if *minus { -p } else { p }
            })
            .collect();
        reg.wrap(Expr::reduce(balanced_sum(raw, reg), reg))
    }

    /// Σ eᵢ, added pairwise along a balanced tree: each term is copied about log₂ k times
    /// instead of up to k times by a running total.
    ///
    /// ```
    /// use torseur::expr::{Expr, Registry};
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["m".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let terms = ["m*cos(q)", "m*sin(q)", "-m*cos(q)", "1"].map(|t| reg.parse(t).unwrap());
    /// assert_eq!(Expr::sum(&reg, terms), reg.parse("m*sin(q) + 1").unwrap());
    /// assert!(Expr::sum(&reg, Vec::new()).is_zero());
    /// ```
    pub fn sum(reg: &Rc<Registry>, terms: impl IntoIterator<Item = Expr>) -> Expr {
        reg.wrap(balanced_sum(
            terms.into_iter().map(Expr::into_poly).collect(),
            reg,
        ))
    }
}

/// C(k, j).
fn binomial(k: u8, j: u8) -> i64 {
    (0..j as i64).fold(1, |b, i| b * (k as i64 - i) / (i + 1))
}

/// Σ of polynomials added pairwise along a balanced tree.
pub(super) fn balanced_sum(mut polys: Vec<Poly>, reg: &Registry) -> Poly {
    while polys.len() > 1 {
        let mut next = Vec::with_capacity(polys.len().div_ceil(2));
        let mut it = polys.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) => a + b,
                None => a,
            });
        }
        polys = next;
    }
    polys.pop().unwrap_or_else(|| reg.poly_zero())
}
