//! A vector typed as a corrigé writes it (`a*x1 + b*y2 - c*z0`), read into components per
//! basis by walking its tree: a sum of vectors, or a product of scalars and of exactly one
//! vector; never expanded by symbolica first (see [`super::parse`]).

use super::parse::{Walker, parse_atom};
use super::{Expr, ExprError, Registry};
use std::rc::Rc;
use symbolica::atom::AtomView;

pub(super) fn parse_vector<K: Ord + Copy>(
    reg: &Rc<Registry>,
    s: &str,
    basis_vector: &dyn Fn(&str) -> Option<(K, usize)>,
    names: &dyn Fn(&str) -> Option<Expr>,
) -> Result<Vec<(K, [Expr; 3])>, ExprError> {
    let a = parse_atom(s)?;
    let w = Walker::new(reg, s, names);
    let is_basis = |v: AtomView| match v {
        AtomView::Var(v) => basis_vector(v.get_symbol().get_stripped_name()),
        _ => None,
    };
    let mut out: Vec<(K, [Expr; 3])> = Vec::new();
    w.vector(a.as_view(), &is_basis, &mut out)?;
    for e in out.iter().flat_map(|(_, c)| c) {
        w.numbers_bounded(e)?;
    }
    Ok(out)
}

impl Walker<'_> {
    /// Adds the vector written by `v` to `out`, walking the tree without expanding it (as
    /// [`Walker::linear`] does for an angle): a sum of vectors, or a product of scalars and of
    /// exactly one vector.
    fn vector<K: Ord + Copy>(
        &self,
        v: AtomView,
        basis: &dyn Fn(AtomView) -> Option<(K, usize)>,
        out: &mut Vec<(K, [Expr; 3])>,
    ) -> Result<(), ExprError> {
        let mut parts = Vec::new();
        self.vector_terms(v, basis, &self.reg.one(), &mut parts)?;
        for (k, axis, e) in parts {
            if let Some(slot) = out.iter_mut().find(|(kk, _)| *kk == k) {
                slot.1[axis] = &slot.1[axis] + &e;
            } else {
                let z = self.reg.zero();
                let mut c = [z.clone(), z.clone(), z];
                c[axis] = e;
                out.push((k, c));
            }
        }
        Ok(())
    }

    /// The terms `(basis, axis, coefficient)` of `factor · v`.
    fn vector_terms<K: Ord + Copy>(
        &self,
        v: AtomView,
        basis: &dyn Fn(AtomView) -> Option<(K, usize)>,
        factor: &Expr,
        parts: &mut Vec<(K, usize, Expr)>,
    ) -> Result<(), ExprError> {
        if let Some((k, axis)) = basis(v) {
            parts.push((k, axis, factor.clone()));
            return Ok(());
        }
        match v {
            AtomView::Add(a) => {
                for t in a.iter() {
                    self.vector_terms(t, basis, factor, parts)?;
                }
                Ok(())
            }
            AtomView::Mul(m) => {
                let factors: Vec<AtomView> = m.iter().collect();
                let with_vector: Vec<usize> = (0..factors.len())
                    .filter(|&i| holds_basis_vector(factors[i], basis))
                    .collect();
                let [at] = with_vector[..] else {
                    return Err(self.unsupported(if with_vector.is_empty() {
                        NO_BASIS_VECTOR
                    } else {
                        "a term holds two basis vectors"
                    }));
                };
                let mut scalar = factor.clone();
                for (i, f) in factors.iter().enumerate() {
                    if i != at {
                        scalar = self.times(&scalar, &self.scalar(*f)?)?;
                    }
                }
                self.vector_terms(factors[at], basis, &scalar, parts)
            }
            AtomView::Pow(p) if holds_basis_vector(p.get_base(), basis) => {
                Err(self.unsupported("a basis vector cannot be raised to a power"))
            }
            AtomView::Num(n) if n.is_zero() => Ok(()),
            _ if holds_basis_vector(v, basis) => Err(self.unsupported(
                "a basis vector appears inside a function: only sums and products of vectors \
                 are read",
            )),
            _ => Err(self.unsupported(NO_BASIS_VECTOR)),
        }
    }
}

/// Why a term of a vector without a basis vector is refused.
const NO_BASIS_VECTOR: &str = "every term of a vector must hold one basis vector (x0, y1, z2, …)";

/// Whether a basis vector occurs anywhere in `v`.
fn holds_basis_vector<K>(v: AtomView, basis: &dyn Fn(AtomView) -> Option<K>) -> bool {
    if basis(v).is_some() {
        return true;
    }
    match v {
        AtomView::Add(a) => a.iter().any(|t| holds_basis_vector(t, basis)),
        AtomView::Mul(m) => m.iter().any(|t| holds_basis_vector(t, basis)),
        AtomView::Pow(p) => {
            let (b, e) = p.get_base_exp();
            holds_basis_vector(b, basis) || holds_basis_vector(e, basis)
        }
        AtomView::Fun(f) => f.iter().any(|t| holds_basis_vector(t, basis)),
        _ => false,
    }
}

impl Registry {
    /// Parses a vector expression `d1*z0 + L1*y1`, where `basis_vector(name)` recognises the
    /// basis vector names (returning a basis key and an axis index). Returns, per basis key,
    /// the three components.
    pub fn parse_vector<K: Ord + Copy>(
        self: &Rc<Self>,
        s: &str,
        basis_vector: &dyn Fn(&str) -> Option<(K, usize)>,
    ) -> Result<Vec<(K, [Expr; 3])>, ExprError> {
        parse_vector(self, s, basis_vector, &|_| None)
    }

    /// [`Registry::parse_vector`], where `names` gives the value of names the registry does
    /// not know (as in [`Registry::parse_with`]).
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(&["a".into()], &[("q".into(), CoordinateKind::Angle)]).unwrap();
    /// let w = reg.parse("a*dot(q)").unwrap();
    /// let axis = |n: &str| match n {
    ///     "x1" => Some((1, 0)),
    ///     "y2" => Some((2, 1)),
    ///     _ => None,
    /// };
    /// let v = reg
    ///     .parse_vector_with("W*x1 - a*y2 + 2*W*x1", &axis, &|n| (n == "W").then(|| w.clone()))
    ///     .unwrap();
    /// let part = |k| &v.iter().find(|(b, _)| *b == k).unwrap().1;
    /// assert_eq!(part(1)[0], reg.parse("3*a*dot(q)").unwrap());
    /// assert_eq!(part(2)[1], reg.parse("-a").unwrap());
    /// assert!(reg.parse_vector_with("W*x1*y2", &axis, &|_| None).is_err());
    /// ```
    pub fn parse_vector_with<K: Ord + Copy>(
        self: &Rc<Self>,
        s: &str,
        basis_vector: &dyn Fn(&str) -> Option<(K, usize)>,
        names: &dyn Fn(&str) -> Option<Expr>,
    ) -> Result<Vec<(K, [Expr; 3])>, ExprError> {
        parse_vector(self, s, basis_vector, names)
    }
}
