//! The search for the cheapest written form of a sum of monomials: flat, its content
//! pulled out, collected by a leaf (recursively), or factored by symbolica's polynomial
//! factorisation (perfect squares, products of sums). Memoised, with a budget.

use super::super::Registry;
use super::form::{Factor, Form, Leaf, Product, leads_negative, positive_first, sort_terms};
use super::rewrite::{Leaves, Mono, normalize};
use std::collections::HashMap;
use std::sync::Arc;
use symbolica::domains::rational::{Q, Rational};
use symbolica::poly::PolyVariable;
use symbolica::poly::factor::Factorize;
use symbolica::poly::polynomial::MultivariatePolynomial;

/// Sums with more terms than this are only written flat or with their content out.
const SEARCH_TERMS: usize = 14;
/// Sums factored by symbolica: at most this many terms.
const FACTOR_TERMS: usize = 12;
/// Distinct subproblems solved per expression before the search stops exploring.
const BUDGET: usize = 4000;

pub(crate) struct Search<'a> {
    reg: &'a Registry,
    /// The sums searched stand in the expression's own sum (the part without rates), not in
    /// parentheses before rates: they are costed at depth 0.
    top: bool,
    memo: HashMap<Vec<Mono>, Form>,
    spent: usize,
}

impl<'a> Search<'a> {
    pub fn new(reg: &'a Registry) -> Search<'a> {
        Search {
            reg,
            top: false,
            memo: HashMap::new(),
            spent: 0,
        }
    }

    /// A search whose sums stand in the expression's own sum (see `top`).
    pub fn at_top(reg: &'a Registry) -> Search<'a> {
        let mut s = Search::new(reg);
        s.top = true;
        s
    }

    /// The cost of a coefficient where it will stand.
    pub fn placed(&self, f: &Form) -> super::form::Cost {
        if self.top {
            f.cost_at(0)
        } else {
            f.placed_cost()
        }
    }

    /// A fresh budget for the next coefficient (the memo is kept): a group written late
    /// gets the same search as the first.
    pub fn fresh_budget(&mut self) {
        self.spent = 0;
    }

    /// The cheapest form found for the sum of `ms` (normalised monomials).
    pub fn best(&mut self, ms: Vec<Mono>) -> Form {
        match ms.len() {
            0 => return Form::default(),
            1 => {
                let m = &ms[0];
                return Form::single(Product::of_atoms(m.coef.clone(), m.atoms.clone()));
            }
            _ => {}
        }
        if let Some(f) = self.memo.get(&ms) {
            return f.clone();
        }
        self.spent += 1;
        let mut best = self.flat(&ms);
        // A coefficient is costed where it will stand: in parentheses, before its rates.
        let top = self.top;
        let placed = move |f: &Form| if top { f.cost_at(0) } else { f.placed_cost() };
        let consider = |f: Form, best: &mut Form| {
            if placed(&f) < placed(best) {
                *best = f;
            }
        };
        if let Some((g, common)) = common_denominator(&ms) {
            let inner: Vec<Mono> = normalize(ms.iter().map(|m| m.divided(&g, &common)).collect());
            let f = self.best(inner);
            consider(wrap(g, common, f), &mut best);
        }
        let (g, common) = content(&ms);
        if !common.is_empty() || !g.abs().is_one() {
            let inner: Vec<Mono> = ms.iter().map(|m| m.divided(&g, &common)).collect();
            let f = self.best(inner);
            consider(wrap(g.clone(), common.clone(), f), &mut best);
            if g.is_negative() {
                // The sign may stay inside: m (g − h (…)) rather than −m (h (…) − g).
                let pos = g.abs();
                let inner: Vec<Mono> = ms.iter().map(|m| m.divided(&pos, &common)).collect();
                let f = self.best(inner);
                consider(wrap(pos, common, f), &mut best);
            }
        } else if ms.len() <= SEARCH_TERMS && self.spent < BUDGET {
            if g.is_negative() {
                // Only a sign in common: −(a + b) is a candidate, not the rule.
                let inner: Vec<Mono> = ms
                    .iter()
                    .map(|m| Mono {
                        coef: -m.coef.clone(),
                        atoms: m.atoms.clone(),
                    })
                    .collect();
                let f = self.best(inner);
                consider(wrap(g.clone(), vec![], f), &mut best);
            }
            for a in self.leaves(&ms) {
                let (with, rest): (Vec<Mono>, Vec<Mono>) =
                    ms.iter().cloned().partition(|m| m.power(&a) > 0);
                // The leaf with everything the terms holding it share (2 L1 of 2 L1 θ̈1 cos θ1
                // − 2 L1 θ̇1² sin θ1).
                let (wg, wc) = content(&with);
                let wc = if wc.iter().any(|x| x.0 == a) {
                    wc
                } else {
                    vec![(a.clone(), 1)]
                };
                let with: Vec<Mono> = with.iter().map(|m| m.divided(&wg, &wc)).collect();
                let fw = self.best(normalize(with));
                let fr = self.best(rest);
                let mut terms = wrap(wg, wc, fw).terms;
                terms.extend(fr.terms);
                consider(Form { terms }, &mut best);
            }
            if let Some(f) = self.by_trig(&ms) {
                consider(f, &mut best);
            }
            if ms.len() >= 3
                && ms.len() <= FACTOR_TERMS
                && let Some(f) = self.factored(&ms)
            {
                consider(f, &mut best);
            }
            if ms.len() >= 4 {
                for f in self.completed_squares(&ms) {
                    consider(f, &mut best);
                }
            }
        }
        self.sort(&mut best);
        self.memo.insert(ms, best.clone());
        best
    }

    /// The sum with only its content out (for large expressions).
    pub fn content_only(&self, ms: Vec<Mono>) -> Form {
        if ms.len() < 2 {
            return self.flat(&ms);
        }
        let (g, common) = content(&ms);
        let inner: Vec<Mono> = if common.is_empty() && g.abs().is_one() {
            // Only the sign comes out: no leaf to divide by (a long coefficient's usual case).
            ms.into_iter()
                .map(|mut m| {
                    if g.is_negative() {
                        m.coef = -m.coef;
                    }
                    m
                })
                .collect()
        } else {
            ms.iter().map(|m| m.divided(&g, &common)).collect()
        };
        let mut f = Form {
            terms: inner
                .into_iter()
                .map(|m| Product::of_atoms(m.coef, m.atoms))
                .collect(),
        };
        self.sort(&mut f);
        wrap(g, common, f)
    }

    fn flat(&self, ms: &[Mono]) -> Form {
        let mut f = Form {
            terms: ms
                .iter()
                .map(|m| Product::of_atoms(m.coef.clone(), m.atoms.clone()))
                .collect(),
        };
        self.sort(&mut f);
        f
    }

    fn sort(&self, f: &mut Form) {
        sort_terms(self.reg, &mut f.terms);
    }

    /// The terms collected by their trigonometric part, each class with at least two terms
    /// written as (its coefficient sum) · cos… sin… ((C2 − B2 + m2 L2²) sin θ2 cos θ2).
    fn by_trig(&mut self, ms: &[Mono]) -> Option<Form> {
        let mut classes: Vec<(Leaves, Vec<Mono>)> = Vec::new();
        for m in ms {
            let (trig, rest): (Leaves, Leaves) =
                m.atoms.iter().cloned().partition(|(a, _)| a.is_trig());
            let r = Mono {
                coef: m.coef.clone(),
                atoms: rest,
            };
            match classes.iter_mut().find(|c| c.0 == trig) {
                Some(c) => c.1.push(r),
                None => classes.push((trig, vec![r])),
            }
        }
        if classes.len() == ms.len() || classes.len() == 1 {
            return None;
        }
        let mut terms = Vec::new();
        for (trig, rest) in classes {
            let inner = self.best(normalize(rest));
            terms.extend(wrap(Rational::one(), trig, inner).terms);
        }
        Some(Form { terms })
    }

    /// Leaves that appear in at least two terms, most frequent first (the first few only
    /// for larger sums). A trigonometric leaf is collected only where one of the terms that
    /// hold it has no other (as for [`content`]): a teacher collects by parameters, never in
    /// nested powers of cos q (((B2 − C2) cos θ2 + …) cos θ2).
    fn leaves(&self, ms: &[Mono]) -> Vec<Leaf> {
        let mut count: HashMap<&Leaf, usize> = HashMap::new();
        for m in ms {
            for (a, _) in &m.atoms {
                *count.entry(a).or_default() += 1;
            }
        }
        count.retain(|a, _| {
            !a.is_trig()
                || ms
                    .iter()
                    .filter(|m| m.power(a) > 0)
                    .any(|m| m.div(a, 1).is_some_and(|r| !has_trig(&r)))
        });
        let mut v: Vec<(&Leaf, usize)> = count.into_iter().filter(|x| x.1 >= 2).collect();
        v.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
        let keep = if ms.len() > 8 { 3 } else { v.len() };
        v.into_iter().take(keep).map(|x| x.0.clone()).collect()
    }

    /// The sum as a product of sums when symbolica's factorisation finds one (a perfect
    /// square, or two sums).
    fn factored(&mut self, ms: &[Mono]) -> Option<Form> {
        let mut leaves: Vec<Leaf> = ms
            .iter()
            .flat_map(|m| m.atoms.iter().map(|x| x.0.clone()))
            .collect();
        leaves.sort();
        leaves.dedup();
        if leaves.len() > 8 {
            return None;
        }
        let vars: Vec<PolyVariable> = (0..leaves.len())
            .map(|i| {
                PolyVariable::Symbol({
                    let name = format!("torseur_leaf_{i}");
                    symbolica::symbol!(name.as_str())
                })
            })
            .collect();
        let vars = Arc::new(vars);
        let mut p = MultivariatePolynomial::<_, u8>::new(&Q, Some(ms.len()), vars);
        for m in ms {
            let mut e = vec![0u8; leaves.len()];
            for (a, k) in &m.atoms {
                let i = leaves.binary_search(a).expect("every leaf is listed");
                e[i] = *k;
            }
            p.append_monomial(m.coef.clone(), &e);
        }
        let factors = p.factor();
        let nontrivial: Vec<_> = factors.iter().filter(|(f, _)| f.nterms() > 1).collect();
        let repeated = nontrivial.iter().any(|(_, k)| *k > 1);
        if !(repeated || nontrivial.len() >= 2) {
            return None;
        }
        let mut coef = Rational::one();
        let mut atoms: Vec<(Leaf, u8)> = Vec::new();
        let mut sums: Vec<(Form, u8)> = Vec::new();
        for (f, k) in &factors {
            let mono_list: Vec<Mono> = (0..f.nterms())
                .map(|t| Mono {
                    coef: f.coefficients[t].clone(),
                    atoms: f
                        .exponents(t)
                        .iter()
                        .enumerate()
                        .filter(|x| *x.1 > 0)
                        .map(|(i, &e)| (leaves[i].clone(), e))
                        .collect(),
                })
                .collect();
            let k = u8::try_from(*k).ok()?;
            if mono_list.len() == 1 {
                let m = &mono_list[0];
                for _ in 0..k {
                    coef = &coef * &m.coef;
                }
                for (a, e) in &m.atoms {
                    atoms.push((a.clone(), e * k));
                }
            } else {
                let inner = self.best(normalize(mono_list));
                sums.push((inner, k));
            }
        }
        let mut factors: Vec<(Factor, u8)> = atoms
            .into_iter()
            .map(|(a, k)| (Factor::Leaf(a), k))
            .collect();
        for (mut s, k) in sums {
            // A sum with mostly negative terms is written with the minus sign out.
            if negative_majority(&s) {
                s.terms.iter_mut().for_each(|p| p.coef = -p.coef.clone());
                if k % 2 == 1 {
                    coef = -coef;
                }
            }
            factors.push((Factor::Sum(s), k));
        }
        Some(Form::single(Product { coef, factors }))
    }
}

impl Search<'_> {
    /// The sum with a perfect square completed out of three of its terms and the rest
    /// written after it: c a² + t a b + (t²/4c) b² + r = c (a + t/(2c) b)² + r, the damped
    /// oscillator's (k − M Ω²)² + c² Ω² instead of k² + (c² − 2 M k + M² Ω²) Ω². Exact: the
    /// three terms are matched with rational arithmetic (t² = 4 c d), and the form is checked
    /// against the canonical one like every other.
    fn completed_squares(&mut self, ms: &[Mono]) -> Vec<Form> {
        let mut out = Vec::new();
        for (i, j) in square_pairs(ms) {
            if self.spent >= BUDGET {
                break;
            }
            let (a, b) = (half(&ms[i]), half(&ms[j]));
            let cross = product_atoms(&a, &b);
            let Some(t) = (0..ms.len()).find(|&t| {
                t != i && t != j && ms[t].atoms == cross && {
                    let four = Rational::new(4, 1);
                    &ms[t].coef * &ms[t].coef == &(&four * &ms[i].coef) * &ms[j].coef
                }
            }) else {
                continue;
            };
            let c = ms[i].coef.clone();
            let ratio = &ms[t].coef / &(&Rational::new(2, 1) * &c);
            let inner = vec![
                Mono {
                    coef: Rational::one(),
                    atoms: a,
                },
                Mono {
                    coef: ratio,
                    atoms: b,
                },
            ];
            let mut square = self.best(normalize(inner));
            // (−s)² = s²: the sum is written from a positive first term in a teacher's order.
            if leads_negative(self.reg, &square.terms) {
                square
                    .terms
                    .iter_mut()
                    .for_each(|p| p.coef = -p.coef.clone());
                self.sort(&mut square);
            }
            if square.terms.len() < 2 {
                continue;
            }
            let rest: Vec<Mono> = (ms.iter().enumerate())
                .filter(|(k, _)| ![i, j, t].contains(k))
                .map(|(_, m)| m.clone())
                .collect();
            let rest = self.best(normalize(rest));
            // A square written first, then what remains.
            let mut terms = vec![Product {
                coef: c,
                factors: vec![(Factor::Sum(square), 2)],
            }];
            terms.extend(rest.terms);
            out.push(Form { terms });
        }
        out
    }
}

/// The pairs (i, j) of terms that are squares of monomials with a positive coefficient
/// (every exponent even), both ways: the first one's coefficient goes out of the square,
/// 4 k² + 4 k x + x² as (2 k + x)² or 4 (k + x/2)², and the cost chooses.
fn square_pairs(ms: &[Mono]) -> Vec<(usize, usize)> {
    let square = |m: &Mono| {
        !m.coef.is_negative() && !m.coef.is_zero() && m.atoms.iter().all(|(_, k)| k % 2 == 0)
    };
    let squares: Vec<usize> = (0..ms.len()).filter(|&k| square(&ms[k])).collect();
    let mut pairs = Vec::new();
    for (x, &i) in squares.iter().enumerate() {
        for &j in &squares[x + 1..] {
            pairs.push((i, j));
            pairs.push((j, i));
        }
    }
    pairs
}

/// The leaves of a square monomial, each at half its exponent.
fn half(m: &Mono) -> Vec<(Leaf, u8)> {
    m.atoms.iter().map(|(a, k)| (a.clone(), k / 2)).collect()
}

/// The leaves of a product of two monomials, sorted as a monomial's are.
fn product_atoms(a: &[(Leaf, u8)], b: &[(Leaf, u8)]) -> Vec<(Leaf, u8)> {
    let mut out: Vec<(Leaf, u8)> = a.to_vec();
    for (l, k) in b {
        match out.iter_mut().find(|x| &x.0 == l) {
            Some(x) => x.1 += k,
            None => out.push((l.clone(), *k)),
        }
    }
    out.sort();
    out
}

pub(crate) fn negative_majority(f: &Form) -> bool {
    let neg = f.terms.iter().filter(|p| p.coef.is_negative()).count();
    2 * neg > f.terms.len()
}

fn has_trig(m: &Mono) -> bool {
    m.atoms.iter().any(|x| x.0.is_trig())
}

/// The common factor of a sum: the gcd of its coefficients (negative when most terms are)
/// and the leaves every term shares; trigonometric leaves only when a term is left without
/// one ((L1 + L2 cos θ2) cos θ2, a distance times a cosine), never when every term keeps one
/// (((B2 − C2) cos θ2 + 2 D2 sin θ2) cos θ2 is a Horner scheme, not the course's writing).
pub(crate) fn content(ms: &[Mono]) -> (Rational, Vec<(Leaf, u8)>) {
    let (g, common) = raw_content(ms);
    // Only trigonometric leaves may be kept in: with none in common, nothing to decide.
    if !common.iter().any(|x| x.0.is_trig()) {
        return (g, common);
    }
    let keeps_trig = ms.iter().all(|m| has_trig(&m.divided(&g, &common)));
    let common = if keeps_trig {
        common.into_iter().filter(|x| !x.0.is_trig()).collect()
    } else {
        common
    };
    (g, common)
}

/// The content with the common denominator below the line: the highest power of each 1/p
/// any term holds ((r1 J2 θ̈1 + r2 C_r)/r2², never a fraction inside a fraction); none when
/// it is the content itself.
fn common_denominator(ms: &[Mono]) -> Option<(Rational, Vec<(Leaf, u8)>)> {
    let (g, mut common) = content(ms);
    let mut changed = false;
    for m in ms {
        for (a, k) in &m.atoms {
            if !matches!(a, Leaf::Inverse(_) | Leaf::Reciprocal(..)) {
                continue;
            }
            match common.iter_mut().find(|x| &x.0 == a) {
                Some(x) if x.1 >= *k => {}
                Some(x) => {
                    x.1 = *k;
                    changed = true;
                }
                None => {
                    common.push((a.clone(), *k));
                    changed = true;
                }
            }
        }
    }
    common.sort();
    changed.then_some((g, common))
}

fn raw_content(ms: &[Mono]) -> (Rational, Vec<(Leaf, u8)>) {
    let mut common = ms[0].atoms.clone();
    for m in &ms[1..] {
        common = common
            .into_iter()
            .filter_map(|(a, k)| {
                let h = m.power(&a);
                (h > 0).then_some((a, k.min(h)))
            })
            .collect();
    }
    let mut g = ms[0].coef.abs();
    for m in &ms[1..] {
        g = g.gcd(&m.coef);
    }
    let g = g.abs();
    let neg = ms.iter().filter(|m| m.coef.is_negative()).count();
    let g = if 2 * neg > ms.len() { -g } else { g };
    (g, common)
}

/// `g · leaves · (inner)`, merged into one product when `inner` is one.
pub(crate) fn wrap(g: Rational, leaves: Vec<(Leaf, u8)>, inner: Form) -> Form {
    let mut factors: Vec<(Factor, u8)> = leaves
        .into_iter()
        .map(|(a, k)| (Factor::Leaf(a), k))
        .collect();
    let mut coef = g;
    if inner.terms.len() == 1 {
        let p = inner.terms.into_iter().next().expect("one term");
        coef = &coef * &p.coef;
        for (f, k) in p.factors {
            match factors.iter_mut().find(|x| x.0 == f) {
                Some(x) => x.1 += k,
                None => factors.push((f, k)),
            }
        }
    } else {
        let mut inner = inner;
        if negative_majority(&inner) {
            inner
                .terms
                .iter_mut()
                .for_each(|p| p.coef = -p.coef.clone());
            coef = -coef;
        }
        positive_first(&mut inner.terms);
        factors.push((Factor::Sum(inner), 1));
    }
    Form::single(Product { coef, factors })
}
