//! Trigonometric rewritings of a sum of monomials, each an identity applied to a pair of
//! terms that differ only by the trigonometric factors it replaces:
//!
//! | pair of terms (same coefficient monomial r) | becomes |
//! |---|---|
//! | a r cos qᵢ cos qⱼ + a r sin qᵢ sin qⱼ | a r cos(qⱼ − qᵢ) |
//! | a r cos qᵢ cos qⱼ − a r sin qᵢ sin qⱼ | a r cos(qᵢ + qⱼ) |
//! | a r sin qⱼ cos qᵢ − a r cos qⱼ sin qᵢ | a r sin(qⱼ − qᵢ) |
//! | a r sin qⱼ cos qᵢ + a r cos qⱼ sin qᵢ | a r sin(qᵢ + qⱼ) |
//! | b r − 2b r cos² q | −b r cos 2q |
//! | b r − b r cos² q | b r sin² q |
//! | a r cos² q − a r sin² q | a r cos 2q |
//! | a r cos q sin q (alone) | a/2 r sin 2q |
//!
//! Every rule is an identity, and the presentation keeps a form only if its exact value is
//! the canonical form it started from, so a wrong rule could cost readability, never a sign.

use super::super::{CoordId, Trig};
use super::form::{Angle, Leaf};
use std::collections::HashMap;
use symbolica::domains::rational::Rational;

/// A partner's leaves, and the merged term built from the partner's coefficient (none when
/// the coefficients do not fit the rule).
type Partner = (Mono, Box<dyn Fn(&Rational) -> Option<Mono>>);

/// Leaves with their exponents.
pub(crate) type Leaves = Vec<(Leaf, u8)>;

/// A monomial of the presentation: a coefficient and leaves with exponents, sorted.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub(crate) struct Mono {
    pub coef: Rational,
    pub atoms: Vec<(Leaf, u8)>,
}

impl Mono {
    pub fn power(&self, a: &Leaf) -> u8 {
        self.atoms.iter().find(|x| &x.0 == a).map_or(0, |x| x.1)
    }

    /// The monomial divided by a^k, when it divides.
    pub fn div(&self, a: &Leaf, k: u8) -> Option<Mono> {
        let have = self.power(a);
        if have < k {
            return None;
        }
        let mut atoms = self.atoms.clone();
        if have == k {
            atoms.retain(|x| &x.0 != a);
        } else {
            atoms
                .iter_mut()
                .filter(|x| &x.0 == a)
                .for_each(|x| x.1 -= k);
        }
        Some(Mono {
            coef: self.coef.clone(),
            atoms,
        })
    }

    /// The monomial times a^k.
    pub fn mul(&self, a: Leaf, k: u8) -> Mono {
        let mut atoms = self.atoms.clone();
        match atoms.iter_mut().find(|x| x.0 == a) {
            Some(x) => x.1 += k,
            None => {
                atoms.push((a, k));
                atoms.sort();
            }
        }
        Mono {
            coef: self.coef.clone(),
            atoms,
        }
    }

    /// The monomial divided by a common factor `g · leaves` (which must divide it; a
    /// common denominator 1/p^k divides every term, a term with fewer 1/p getting p's).
    pub fn divided(&self, g: &Rational, leaves: &[(Leaf, u8)]) -> Mono {
        let mut r = self.clone();
        for (a, k) in leaves {
            let have = r.power(a);
            r = match a {
                Leaf::Inverse(p) if have < *k => {
                    let without = r.div(a, have).expect("its own power divides a term");
                    without.mul(Leaf::Param(*p), *k - have)
                }
                Leaf::Reciprocal(q, f) if have < *k => {
                    let without = r.div(a, have).expect("its own power divides a term");
                    let x = Angle::of(*q);
                    let t = match f {
                        Trig::Cos => Leaf::Cos(x),
                        Trig::Sin => Leaf::Sin(x),
                    };
                    without.mul(t, *k - have)
                }
                _ => r.div(a, *k).expect("a common factor divides every term"),
            };
        }
        r.coef = &r.coef / g;
        r
    }

    fn with_coef(&self, coef: Rational) -> Mono {
        Mono {
            coef,
            atoms: self.atoms.clone(),
        }
    }
}

/// Combines like terms, drops zeros, sorts by leaves.
pub(crate) fn normalize(ms: Vec<Mono>) -> Vec<Mono> {
    let mut out: Vec<Mono> = Vec::with_capacity(ms.len());
    let mut at: HashMap<Vec<(Leaf, u8)>, usize> = HashMap::new();
    for m in ms {
        match at.get(&m.atoms) {
            Some(&i) => out[i].coef = &out[i].coef + &m.coef,
            None => {
                at.insert(m.atoms.clone(), out.len());
                out.push(m);
            }
        }
    }
    out.retain(|m| !m.coef.is_zero());
    out.sort_by(|a, b| a.atoms.cmp(&b.atoms));
    out
}

/// Simple angles (q with coefficient 1) under a cos in the terms.
fn cos_angles(ms: &[Mono]) -> Vec<CoordId> {
    let mut v: Vec<CoordId> = ms
        .iter()
        .flat_map(|m| m.atoms.iter())
        .filter_map(|(a, _)| match a {
            Leaf::Cos(x) | Leaf::Sin(x) if x.is_simple() => Some(x.0[0].0),
            _ => None,
        })
        .collect();
    v.sort();
    v.dedup();
    v
}

fn cos(q: CoordId) -> Leaf {
    Leaf::Cos(Angle::of(q))
}

fn sin(q: CoordId) -> Leaf {
    Leaf::Sin(Angle::of(q))
}

/// One pass of a pair rule: for each term `t`, `find(t)` names the partner's leaves and
/// builds the merged term from the partner's coefficient; both are replaced.
fn pairs(ms: Vec<Mono>, find: impl Fn(&Mono) -> Vec<Partner>) -> (Vec<Mono>, bool) {
    let index: HashMap<Vec<(Leaf, u8)>, usize> = ms
        .iter()
        .enumerate()
        .map(|(i, m)| (m.atoms.clone(), i))
        .collect();
    let mut used = vec![false; ms.len()];
    let mut out = Vec::new();
    let mut changed = false;
    for i in 0..ms.len() {
        if used[i] {
            continue;
        }
        for (partner, merge) in find(&ms[i]) {
            let Some(&j) = index.get(&partner.atoms) else {
                continue;
            };
            if j == i || used[j] {
                continue;
            }
            if let Some(m) = merge(&ms[j].coef) {
                used[i] = true;
                used[j] = true;
                out.push(m);
                changed = true;
                break;
            }
        }
    }
    out.extend(ms.into_iter().zip(used).filter(|(_, u)| !u).map(|(m, _)| m));
    (normalize(out), changed)
}

/// cos(qⱼ ∓ qᵢ), sin(qⱼ ∓ qᵢ) from products of cos and sin of two angles.
pub(crate) fn compound_angles(ms: Vec<Mono>, n_coords: usize) -> Vec<Mono> {
    let angles = cos_angles(&ms);
    let (out, _) = pairs(ms, |t| {
        let mut v: Vec<Partner> = Vec::new();
        for (ii, &qi) in angles.iter().enumerate() {
            for &qj in &angles[ii + 1..] {
                // cos qi cos qj with sin qi sin qj.
                if let Some(rest) = t.div(&cos(qi), 1).and_then(|r| r.div(&cos(qj), 1)) {
                    let partner = rest.mul(sin(qi), 1).mul(sin(qj), 1);
                    let a = t.coef.clone();
                    let rest2 = rest.clone();
                    v.push((
                        partner,
                        Box::new(move |b: &Rational| {
                            let (ang, _) = if *b == a {
                                Angle::normalized(vec![(qj, 1), (qi, -1)], n_coords)
                            } else if *b == -a.clone() {
                                Angle::normalized(vec![(qj, 1), (qi, 1)], n_coords)
                            } else {
                                return None;
                            };
                            Some(rest2.mul(Leaf::Cos(ang), 1).with_coef(a.clone()))
                        }),
                    ));
                }
                // sin qj cos qi with cos qj sin qi (and the same with i, j exchanged).
                for (x, y) in [(qj, qi), (qi, qj)] {
                    if let Some(rest) = t.div(&sin(x), 1).and_then(|r| r.div(&cos(y), 1)) {
                        let partner = rest.mul(cos(x), 1).mul(sin(y), 1);
                        let a = t.coef.clone();
                        let rest2 = rest.clone();
                        v.push((
                            partner,
                            Box::new(move |b: &Rational| {
                                // a (sin x cos y ∓ cos x sin y) = a sin(x ∓ y).
                                let terms = if *b == -a.clone() {
                                    vec![(x, 1), (y, -1)]
                                } else if *b == a {
                                    vec![(x, 1), (y, 1)]
                                } else {
                                    return None;
                                };
                                let (ang, flip) = Angle::normalized(terms, n_coords);
                                let c = if flip { -a.clone() } else { a.clone() };
                                Some(rest2.mul(Leaf::Sin(ang), 1).with_coef(c))
                            }),
                        ));
                    }
                }
            }
        }
        v
    });
    out
}

/// cos 2q and sin² q from a term in cos² q and its partner without it.
pub(crate) fn squares(ms: Vec<Mono>) -> Vec<Mono> {
    let angles = cos_angles(&ms);
    let mut ms = ms;
    // cos 2q first (b − 2b cos²), then sin² (b − b cos²), then cos² − sin² = cos 2q.
    for rule in 0..3 {
        let (out, _) = pairs(ms, |t| {
            let mut v: Vec<Partner> = Vec::new();
            for &q in &angles {
                let Some(rest) = t.div(&cos(q), 2) else {
                    continue;
                };
                let a = t.coef.clone();
                let partner = if rule == 2 {
                    rest.mul(sin(q), 2)
                } else {
                    rest.clone()
                };
                v.push((
                    partner,
                    Box::new(move |b: &Rational| {
                        let double = Leaf::Cos(Angle(vec![(q, 2)]));
                        let two = Rational::new(2, 1);
                        match rule {
                            0 if a == -(b * &two) => {
                                Some(rest.mul(double, 1).with_coef(-b.clone()))
                            }
                            1 if a == -b.clone() => Some(rest.mul(sin(q), 2).with_coef(b.clone())),
                            2 if *b == -a.clone() => Some(rest.mul(double, 1).with_coef(a.clone())),
                            _ => None,
                        }
                    }),
                ));
            }
            v
        });
        ms = out;
    }
    ms
}

/// sin 2q for cos q sin q: in every term (`all`), or where the coefficient is even.
pub(crate) fn double_sines(ms: Vec<Mono>, all: bool) -> Vec<Mono> {
    let two = Rational::new(2, 1);
    let out = ms
        .into_iter()
        .map(|m| {
            let half = &m.coef / &two;
            if !all && half.to_string().contains('/') {
                return m;
            }
            for (a, _) in m.atoms.clone() {
                let Leaf::Cos(x) = &a else { continue };
                if !x.is_simple() {
                    continue;
                }
                let q = x.0[0].0;
                if let Some(rest) = m.div(&cos(q), 1).and_then(|r| r.div(&sin(q), 1)) {
                    return rest.mul(Leaf::Sin(Angle(vec![(q, 2)])), 1).with_coef(half);
                }
            }
            m
        })
        .collect();
    normalize(out)
}
