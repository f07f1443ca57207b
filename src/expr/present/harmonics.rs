//! Coefficients as expressions of the registry, and in the linearised trigonometric form:
//! cos q1 cos q2 + sin q1 sin q2 written cos(q2 − q1) when that has fewer terms.

use super::form::{Form, Leaf, Product};
use super::rewrite::Mono;
use crate::expr::{Expr, Registry, VarRole};
use std::rc::Rc;

/// A long coefficient in the linearised trigonometric form ([`crate::expr::Fourier`]) when that
/// has fewer terms, as monomials whose trigonometric leaf is cos or sin of a combination of
/// angles: a planar chain's cos q1 cos q2 + sin q1 sin q2 is written cos(q2 − q1), which the
/// pair rules of the search reach only below its limit of terms.
///
/// Only coefficients whose terms hold at most two cos or sin are tried: a product of d of them
/// linearises into up to 2^(d−1) harmonics, and the spatial chain's, where d reaches 2n, come
/// out larger (chain 6: 90,201 terms against 14,026) after a conversion that costs more than
/// the whole derivation.
pub(super) fn fourier_monos(reg: &Rc<Registry>, ms: &[Mono]) -> Option<Vec<Mono>> {
    let trig_degree = |m: &Mono| -> u32 {
        m.atoms
            .iter()
            .filter(|(a, _)| matches!(a, Leaf::Cos(_) | Leaf::Sin(_)))
            .map(|&(_, k)| u32::from(k))
            .sum()
    };
    if ms.iter().any(|m| trig_degree(m) > 2) {
        return None;
    }
    let e = coefficient_expr(reg, ms);
    let f = e.to_fourier()?;
    if f.nterms() >= e.nterms() {
        return None;
    }
    Some(harmonic_monos(&f))
}

/// The monomials of a Fourier form, each harmonic a leaf of its own (m L q̈2 cos(q2 − q1)).
fn harmonic_monos(f: &crate::expr::Fourier) -> Vec<Mono> {
    let mut out = Vec::with_capacity(f.nterms());
    for (a, g, c) in f.terms() {
        let leaf = (!a.terms().is_empty()).then(|| match g {
            crate::expr::Trig::Cos => Leaf::Cos(a.clone()),
            crate::expr::Trig::Sin => Leaf::Sin(a.clone()),
        });
        for mut m in c.monos() {
            if let Some(l) = &leaf {
                m.atoms.push((l.clone(), 1));
                m.atoms.sort();
            }
            out.push(m);
        }
    }
    out
}

/// A Fourier form as a flat sum of products, in the order of its harmonics (its text).
pub(crate) fn fourier_form(f: &crate::expr::Fourier) -> Form {
    Form {
        terms: harmonic_monos(f)
            .into_iter()
            .map(|m| Product::of_atoms(m.coef, m.atoms))
            .collect(),
    }
}

/// A coefficient (monomials of plain leaves) as an expression.
pub(super) fn coefficient_expr(reg: &Rc<Registry>, ms: &[Mono]) -> Expr {
    Expr::from_terms(
        reg,
        ms.iter()
            .map(|m| (m.coef.clone(), exponents(reg, m)))
            .collect(),
    )
}

/// The exponent vector of a monomial of plain leaves (no compound angle).
pub(super) fn exponents(reg: &Registry, m: &Mono) -> Vec<u8> {
    let mut e = vec![0u8; reg.nvars()];
    for (a, k) in &m.atoms {
        let role = match a {
            Leaf::Param(p) => VarRole::Parameter(*p),
            Leaf::Inverse(p) => VarRole::Inverse(*p),
            Leaf::Reciprocal(q, f) => VarRole::Reciprocal(*q, *f),
            Leaf::Value(q) => VarRole::Value(*q),
            Leaf::Root(r) => VarRole::Root(*r),
            Leaf::Rate(q, o) => VarRole::Rate(*q, *o),
            // Only single angles here: a compound angle is no variable of the registry.
            Leaf::Cos(x) if x.is_simple() => VarRole::Cos(x.terms()[0].0),
            Leaf::Sin(x) if x.is_simple() => VarRole::Sin(x.terms()[0].0),
            Leaf::Cos(_) | Leaf::Sin(_) => {
                unreachable!("a compound angle is not a variable of the canonical form")
            }
        };
        let i = reg
            .index_of(role)
            .expect("a leaf of a canonical term is a variable");
        e[i.index()] += k;
    }
    e
}
