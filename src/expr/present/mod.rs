//! The presentation engine: an expression as a teacher writes it, chosen among exactly
//! equal forms by a documented cost. It sits on top of the canonical form and never feeds
//! back into computation.
//!
//! For an expression, the terms are grouped by kinematic monomial (q̈ᵢ, q̇ᵢq̇ⱼ, none) as the
//! course collects them. The coefficient of each group (a polynomial in the parameters, the
//! length coordinates, cos qᵢ and sin qᵢ) is written four ways: as it is; with the
//! trigonometric identities of [`rewrite`] applied to pairs of terms (cos(θ2 − θ1),
//! sin(θ2 + θ1), cos 2q, sin² q kept rather than 1 − cos² q); the same with sin 2q for
//! cos q sin q where the coefficient is even; and everywhere. Each of these is then written
//! by [`search`] in its cheapest arrangement: flat, its content pulled out, collected by a
//! leaf (a parameter group (C2 − B2 + m2 L2²) sin θ2 cos θ2, recursively), or factored by
//! symbolica (m2 (L1 + L2 cos θ2)²). The cheapest of all is kept, by
//! [`Form::cost`]: operations as `sympy.count_ops` counts them, then the number of leaves.
//! Last, the content shared by every group may come out in front (m L (L θ̈ + g sin θ)) when
//! that is cheaper.
//!
//! **A form is kept only if its exact value, rebuilt by the engine's arithmetic
//! ([`Form::to_expr`]), is the canonical form it started from**; otherwise the plain grouped
//! form is printed (this has never been observed; a debug build panics on it).
//!
//! The reading order of a product is: number, parameters in the course's order (masses,
//! then g, lengths, inertia moments, the rest, as set by [`RegistryBuilder::display_ranks`](super::RegistryBuilder::display_ranks);
//! declaration order otherwise), length coordinates, parenthesised sums, rates, then
//! trigonometric functions. Sums are written lower degree first.
//!
//! Above [`SEARCH_LIMIT`] terms an expression is only grouped, each group's common factor
//! out (the search would cost more than it gives on a chain's equations).

mod form;
mod harmonics;
pub(crate) use harmonics::fourier_form;
use harmonics::{coefficient_expr, exponents, fourier_monos};
mod rewrite;
mod search;

pub(crate) use form::num_den;
pub use form::{Angle, Cost, Factor, Form, Leaf, Product};

use super::{Expr, Registry, VarId, VarRole};
use rewrite::{Leaves, Mono, normalize};
use std::cmp::Reverse;
use std::fmt;
use std::rc::Rc;
use symbolica::domains::rational::Rational;

/// Expressions with more canonical terms than this are grouped by kinematic monomial, their
/// common factors out, without the search.
pub const SEARCH_LIMIT: usize = 60;

/// The presentation form of an expression, with its registry (for the names).
#[derive(Debug, Clone)]
pub struct Presentation {
    form: Form,
    reg: Rc<Registry>,
}

impl Presentation {
    /// The tree.
    pub fn form(&self) -> &Form {
        &self.form
    }

    /// The registry of the expression.
    pub fn registry(&self) -> &Rc<Registry> {
        &self.reg
    }
}

impl fmt::Display for Presentation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.form.text(&self.reg))
    }
}

/// The reading order of a kinematic monomial (see [`kinematic_key`]).
type GroupKey = (bool, Vec<(Reverse<u8>, usize, Reverse<u8>)>);

/// A kinematic monomial: the rates of a term, highest derivative first.
type Kinematic = Vec<(Leaf, u8)>;

impl Expr {
    /// The presentation form: the cheapest exactly-equal form found (see the module
    /// documentation of `expr::present`).
    ///
    /// ```
    /// use torseur::expr::Registry;
    /// use torseur::spec::wire::CoordinateKind;
    /// let reg = Registry::new(
    ///     &["m2".into(), "L1".into(), "L2".into(), "B2".into(), "C2".into(), "D2".into()],
    ///     &[("theta1".into(), CoordinateKind::Angle), ("theta2".into(), CoordinateKind::Angle)],
    /// ).unwrap();
    /// let e = reg.parse("(B2*sin(theta2)^2 + C2*cos(theta2)^2 - D2*sin(2*theta2) \
    ///     + m2*(L1 + L2*cos(theta2))^2)*ddot(theta1)").unwrap();
    /// assert_eq!(e.presentation().to_string(),
    ///     "(B2*sin(theta2)^2 + C2*cos(theta2)^2 - D2*sin(2*theta2) \
    ///      + m2*(L1 + L2*cos(theta2))^2)*ddot(theta1)");
    /// let d = reg.parse("3*m2*L2*cos(theta1)*cos(theta2) + 3*m2*L2*sin(theta1)*sin(theta2)").unwrap();
    /// assert_eq!(d.presentation().to_string(), "3*m2*L2*cos(theta2 - theta1)");
    /// ```
    pub fn presentation(&self) -> Presentation {
        let reg = self.registry().clone();
        let form = self.presentation_candidate();
        let form = if form.to_expr(&reg) == *self {
            form
        } else {
            debug_assert!(false, "a presentation form differs from its value: {self}");
            grouped(self, true)
        };
        Presentation { form, reg }
    }

    /// This expression times `unit` (a basis vector `x2`, an acceleration `ddot(q)`; `""` for
    /// none) as one term of a sum, in the presentation form: whether it reads negative, and
    /// its text without that sign (`m*l*x2`, `(a + b)*x2`, `x2` for a coefficient 1).
    /// [`signed_sum`] joins such terms.
    ///
    /// ```
    /// use torseur::expr::{Registry, signed_sum};
    /// let reg = Registry::new(&["a".into(), "b".into()], &[]).unwrap();
    /// let terms = [
    ///     reg.parse("a + b").unwrap().times_text("x1"),
    ///     reg.parse("-a").unwrap().times_text("y1"),
    ///     reg.parse("1").unwrap().times_text("z1"),
    /// ];
    /// assert_eq!(signed_sum(&terms), "(a + b)*x1 - a*y1 + z1");
    /// assert_eq!(signed_sum(&[]), "0");
    /// ```
    pub fn times_text(&self, unit: &str) -> (bool, String) {
        let text = self.presentation().to_string();
        // One term as written (a product, sin(θ2 − θ1) whole), whatever the expansion holds.
        let mut depth = 0i32;
        let single = !text.char_indices().any(|(i, c)| {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ => {}
            }
            depth == 0 && i > 0 && (text[i..].starts_with(" + ") || text[i..].starts_with(" - "))
        });
        let (minus, body) = match text.strip_prefix('-') {
            Some(rest) if single => (true, rest.to_string()),
            _ => (false, text),
        };
        let term = match (unit, body.as_str()) {
            ("", _) => body,
            (_, "1") => unit.to_string(),
            _ if single => format!("{body}*{unit}"),
            _ => format!("({body})*{unit}"),
        };
        (minus, term)
    }

    /// The form the search chooses, before the exactness check of [`Expr::presentation`]
    /// (for the tests that require the check never to fail).
    #[doc(hidden)]
    pub fn presentation_candidate(&self) -> Form {
        let cheap = self.nterms() > SEARCH_LIMIT;
        let mut form = grouped(self, cheap);
        if !cheap
            && let Some(f) = completed_square(self)
            && f.cost() < form.cost()
        {
            form = f;
        }
        form
    }

    /// The leaves of each canonical term.
    fn monos(&self) -> Vec<Mono> {
        let reg = self.registry();
        self.terms()
            .map(|(c, e)| {
                let mut atoms: Vec<(Leaf, u8)> = e
                    .iter()
                    .enumerate()
                    .filter(|x| *x.1 > 0)
                    .map(|(i, &k)| {
                        let a = match reg.role(VarId(i)) {
                            VarRole::Parameter(p) => Leaf::Param(p),
                            VarRole::Inverse(p) => Leaf::Inverse(p),
                            VarRole::Reciprocal(q, f) => Leaf::Reciprocal(q, f),
                            VarRole::Value(q) => Leaf::Value(q),
                            VarRole::Root(r) => Leaf::Root(r),
                            VarRole::Rate(q, o) => Leaf::Rate(q, o),
                            VarRole::Cos(q) => Leaf::Cos(Angle::of(q)),
                            VarRole::Sin(q) => Leaf::Sin(Angle::of(q)),
                        };
                        (a, k)
                    })
                    .collect();
                atoms.sort();
                Mono {
                    coef: c.clone(),
                    atoms,
                }
            })
            .collect()
    }
}

/// A quadratic form in the rates (a kinetic energy) with one square completed, when a rate's
/// square coefficient a divides its cross terms b q̇ q̇ⱼ: a (q̇ + Σ b/(2a) q̇ⱼ)² + the rest
/// (the top: ½ C (ψ̇ cos θ + φ̇)² + ½ (A + m h²)(θ̇² + ψ̇² sin² θ)). Each rate is tried as
/// the pivot; the cheapest result is returned.
fn completed_square(e: &Expr) -> Option<Form> {
    let reg = e.registry();
    let rates: Vec<_> = reg
        .coordinates()
        .iter()
        .filter(|c| !c.has_imposed_rate())
        .filter_map(|c| reg.coord(&c.name))
        .collect();
    // Every term holds exactly two first derivatives, and nothing else of the kind.
    let quadratic = e.terms().all(|(_, x)| {
        let mut d = 0;
        for (i, &k) in x.iter().enumerate() {
            match reg.role(VarId(i)) {
                VarRole::Rate(_, 1) => d += k as u32,
                VarRole::Rate(..) if k > 0 => return false,
                _ => {}
            }
        }
        d == 2
    });
    if !quadratic || rates.len() < 2 {
        return None;
    }
    let half = reg.constant(Rational::new(1, 2));
    let mut best: Option<Form> = None;
    for &p in &rates {
        let dp = e.partial_rate(p, 1);
        let a = &dp.partial_rate(p, 1) * &half;
        if a.is_zero() {
            continue;
        }
        let two_a = &a * &reg.integer(2);
        let mut s = reg.dot(p);
        let mut crossed = false;
        for &j in rates.iter().filter(|&&j| j != p) {
            let b = dp.partial_rate(j, 1);
            if b.is_zero() {
                continue;
            }
            let Some(c) = b.exact_div(&two_a) else {
                s = reg.zero();
                break;
            };
            s = &s + &(&c * &reg.dot(j));
            crossed = true;
        }
        if !crossed || s.is_zero() {
            continue;
        }
        let rest = e - &(&a * &(&s * &s));
        let mut search = search::Search::new(reg);
        let af = best_coefficient(&mut search, normalize(a.monos()), reg.coordinates().len());
        let mut square = times_rates(af, vec![]);
        square.factors.push((Factor::Sum(grouped(&s, false)), 2));
        let mut terms = grouped(&rest, false).terms;
        terms.push(square);
        let f = Form { terms };
        if best.as_ref().is_none_or(|b| f.cost() < b.cost()) {
            best = Some(f);
        }
    }
    best
}

/// Ordering key of a kinematic monomial: higher derivatives first, then by coordinate; the
/// part without rates last (m l² θ̈ + c θ̇ + m g l sin θ).
fn kinematic_key(k: &Kinematic) -> GroupKey {
    let mut v: Vec<_> = k
        .iter()
        .map(|(a, e)| match a {
            Leaf::Rate(q, o) => (Reverse(*o), q.index(), Reverse(*e)),
            _ => unreachable!("a kinematic monomial holds rates only"),
        })
        .collect();
    v.sort();
    (k.is_empty(), v)
}

/// The terms of `e` grouped by kinematic monomial (their rates), each group's coefficient as
/// monomials without rates, the groups in the order of [`kinematic_key`].
fn by_kinematic(e: &Expr) -> Vec<(Kinematic, Vec<Mono>)> {
    let mut groups: Vec<(Kinematic, Vec<Mono>)> = Vec::new();
    let mut index: std::collections::HashMap<Kinematic, usize> = Default::default();
    for m in e.monos() {
        let (kin, coef): (Leaves, Leaves) = m
            .atoms
            .into_iter()
            .partition(|(a, _)| matches!(a, Leaf::Rate(..)));
        let c = Mono {
            coef: m.coef,
            atoms: coef,
        };
        match index.get(&kin) {
            Some(&i) => groups[i].1.push(c),
            None => {
                index.insert(kin.clone(), groups.len());
                groups.push((kin, vec![c]));
            }
        }
    }
    groups.sort_by_key(|g| kinematic_key(&g.0));
    groups
}

/// The expression grouped by kinematic monomial, each coefficient written by the search (or
/// only with its content out when `cheap`), then the content common to every group out when
/// that is cheaper.
fn grouped(e: &Expr, cheap: bool) -> Form {
    let reg = e.registry();
    let groups = by_kinematic(e);
    let mut search = search::Search::new(reg);
    let mut terms = Vec::new();
    let mut units = Vec::new();
    for (kin, mut ms) in groups {
        // The canonical terms are distinct and split into (rates, rest) one to one: nothing
        // to combine, only the order to set.
        ms.sort_unstable_by(|a, b| a.atoms.cmp(&b.atoms));
        if !cheap {
            // The part without trigonometric functions and the rest, apart: (m1/3 + m2) L1² θ̈1
            // stays whole when the part in cos(θ2 − θ1) θ̈1 joins another group.
            let (plain, trig): (Vec<Mono>, Vec<Mono>) = ms
                .iter()
                .cloned()
                .partition(|m| !m.atoms.iter().any(|x| x.0.is_trig()));
            // A single plain term stays with the rest: (L1 + L2 cos θ2) θ̈1 is a distance.
            let (plain, trig) = if plain.len() < 2 {
                (vec![], ms.clone())
            } else {
                (plain, trig)
            };
            for part in [plain, trig] {
                if !part.is_empty() {
                    units.push((kin.clone(), coefficient_expr(reg, &part)));
                }
            }
        }
        let coef = if cheap {
            let ms = fourier_monos(reg, &ms).unwrap_or(ms);
            search.content_only(ms)
        } else if kin.is_empty() {
            // The part without rates stands in the expression's own sum.
            best_coefficient(
                &mut search::Search::at_top(reg),
                ms,
                reg.coordinates().len(),
            )
        } else {
            best_coefficient(&mut search, ms, reg.coordinates().len())
        };
        if kin.is_empty() && coef.terms.len() > 1 {
            // The part without rates is a plain sum: its terms stand in the sum.
            terms.extend(coef.terms);
        } else {
            terms.push(times_rates(coef, kin));
        }
    }
    let mut whole = Form { terms };
    if cheap || whole.terms.len() < 2 {
        return whole;
    }
    // Groups that share a factor, written once: m l (θ̈ cos θ − θ̇² sin θ).
    let across = clustered(reg, &units, &mut search);
    if across.cost() < whole.cost() {
        whole = across;
    }
    // The content of every group out: m L (L θ̈ + g sin θ).
    let all = e.monos();
    let (g, mut common) = search::content(&all);
    // A 1/p out in front only when no term keeps one: never a fraction inside a fraction.
    common.retain(|(a, k)| {
        !matches!(a, Leaf::Inverse(_) | Leaf::Reciprocal(..))
            || all.iter().all(|m| m.power(a) == *k)
    });
    if common.is_empty() && g.abs().is_one() {
        return whole;
    }
    // Both signs in front are tried: m (g − h (…)) may be shorter than −m (h (…) − g).
    let mut best = whole;
    let signs = if g.is_negative() {
        vec![g.clone(), g.abs()]
    } else {
        vec![g]
    };
    for g in signs {
        let inner = Expr::from_terms(
            reg,
            all.iter()
                .map(|m| {
                    let r = m.divided(&g, &common);
                    (r.coef.clone(), exponents(reg, &r))
                })
                .collect(),
        );
        // The factor in front does not nest what follows: its cost is the inner form's plus
        // one operation per factor (m2 [−(L1 + L2 cos θ2) θ̈1 + 2 L2 θ̇1 θ̇2 sin θ2]).
        let inner = grouped(&inner, false);
        let n = common.len() + usize::from(!g.abs().is_one()) + usize::from(g.is_negative());
        let (o, l) = inner.cost();
        let out = search::wrap(g, common.clone(), inner);
        if (o + n, l + n) < best.cost() {
            best = out;
        }
    }
    best
}

/// A unit of [`clustered`]: a kinematic monomial and (part of) its coefficient.
type Unit = (Kinematic, Expr);

/// `coefficient · κ` for units, those of one kinematic monomial added first; each coefficient
/// written by the search. With the ordering key of its first kinematic monomial.
fn unit_products(
    reg: &Rc<Registry>,
    units: &[&Unit],
    search: &mut search::Search,
) -> Vec<(GroupKey, Product)> {
    let mut merged: Vec<(Kinematic, Expr)> = Vec::new();
    for (k, c) in units {
        match merged.iter_mut().find(|m| &m.0 == k) {
            Some(m) => m.1 = &m.1 + c,
            None => merged.push((k.clone(), c.clone())),
        }
    }
    merged
        .into_iter()
        .filter(|m| !m.1.is_zero())
        .map(|(k, c)| {
            let f = best_coefficient(search, normalize(c.monos()), reg.coordinates().len());
            (kinematic_key(&k), times_rates(f, k))
        })
        .collect()
}

/// The groups written with the factors they share pulled out once, greedily: among the
/// polynomial gcds of two units' coefficients, the one that saves the most operations
/// gathers every unit it divides (m l (θ̈ cos θ − θ̇² sin θ), (M + m)(ẍ + g sin α)); again
/// on the rest until nothing is saved; what is left is written group by group.
fn clustered(reg: &Rc<Registry>, units: &[Unit], search: &mut search::Search) -> Form {
    let mut left: Vec<&Unit> = units.iter().collect();
    let mut out: Vec<(GroupKey, Product)> = Vec::new();
    loop {
        let mut best: Option<(usize, Vec<usize>, Product, GroupKey)> = None;
        // A gcd already tried gives the same members and the same gain (the first one found
        // is kept); the cost of a set of members written apart does not depend on the gcd.
        let mut tried: Vec<Expr> = Vec::new();
        let mut apart: std::collections::HashMap<Vec<usize>, usize> = Default::default();
        for i in 0..left.len() {
            for j in i + 1..left.len() {
                let Some(d) = left[i].1.polynomial_gcd(&left[j].1) else {
                    continue;
                };
                if tried.contains(&d) {
                    continue;
                }
                tried.push(d.clone());
                let members: Vec<usize> = (0..left.len())
                    .filter(|&k| left[k].1.exact_div(&d).is_some())
                    .collect();
                let alone: Vec<&Unit> = members.iter().map(|&k| left[k]).collect();
                let separate = match apart.get(&members) {
                    Some(&c) => c,
                    None => {
                        let c = unit_products(reg, &alone, search)
                            .iter()
                            .map(|p| Form::single(p.1.clone()).cost().0)
                            .sum::<usize>()
                            + alone.len().saturating_sub(1);
                        apart.insert(members.clone(), c);
                        c
                    }
                };
                let Some((together, key)) = factored(reg, search, &d, &alone) else {
                    continue;
                };
                let cost = Form::single(together.clone()).cost().0;
                if cost < separate {
                    let gain = separate - cost;
                    if best.as_ref().is_none_or(|b| gain > b.0) {
                        best = Some((gain, members, together, key));
                    }
                }
            }
        }
        let Some((_, members, p, key)) = best else {
            break;
        };
        out.push((key, p));
        left = left
            .into_iter()
            .enumerate()
            .filter(|(k, _)| !members.contains(k))
            .map(|x| x.1)
            .collect();
    }
    out.extend(unit_products(reg, &left, search));
    out.sort_by(|a, b| a.0.cmp(&b.0));
    let mut terms = Vec::new();
    for (key, p) in out {
        if key.0 && p.factors.len() == 1 && p.factors[0].1 == 1 && p.coef.is_one() {
            // A sum without rates stands in the sum.
            if let Factor::Sum(s) = &p.factors[0].0 {
                terms.extend(s.terms.clone());
                continue;
            }
        }
        terms.push(p);
    }
    Form { terms }
}

/// The units `alone`, all divided by `d`, written as one product d (…) with the numbers their
/// terms share out too, and the key it sorts by; `None` when a 1/p would stand both in front
/// and inside.
fn factored(
    reg: &Rc<Registry>,
    search: &mut search::Search,
    d: &Expr,
    alone: &[&Unit],
) -> Option<(Product, GroupKey)> {
    let inner_units: Vec<Unit> = alone
        .iter()
        .map(|u| (u.0.clone(), u.1.exact_div(d).expect("d divides it")))
        .collect();
    // A 1/p out in front only when no term keeps one: never a fraction inside a
    // fraction.
    let nested = reg.var_ids().any(|w| {
        matches!(reg.role(w), VarRole::Inverse(_) | VarRole::Reciprocal(..))
            && d.contains_var(w)
            && inner_units.iter().any(|u| u.1.contains_var(w))
    });
    if nested {
        return None;
    }
    let inner_refs: Vec<&Unit> = inner_units.iter().collect();
    let mut inner = unit_products(reg, &inner_refs, search);
    inner.sort_by(|a, b| a.0.cmp(&b.0));
    let key = inner[0].0.clone();
    let mut inner = Form {
        terms: inner.into_iter().map(|x| x.1).collect(),
    };
    form::positive_first(&mut inner.terms);
    // The numbers the terms share come out too: m2 L1 L2/2 (…), not m2 L1 L2 (½ … + ½ …).
    let mut n = inner.terms[0].coef.abs();
    for t in &inner.terms[1..] {
        n = n.gcd(&t.coef);
    }
    let n = n.abs();
    inner.terms.iter_mut().for_each(|t| t.coef = &t.coef / &n);
    let df = best_coefficient(search, normalize(d.monos()), reg.coordinates().len());
    let mut together = times_form(df, inner);
    together.coef = &together.coef * &n;
    Some((together, key))
}

/// `a · (b)` as one product, `b` a sum (or one product).
fn times_form(a: Form, b: Form) -> Product {
    let mut p = times_rates(a, vec![]);
    match <[Product; 1]>::try_from(b.terms) {
        Ok([q]) => {
            p.coef = &p.coef * &q.coef;
            p.factors.extend(q.factors);
        }
        Err(terms) => {
            let mut inner = Form { terms };
            if search::negative_majority(&inner) {
                inner
                    .terms
                    .iter_mut()
                    .for_each(|q| q.coef = -q.coef.clone());
                p.coef = -p.coef.clone();
            }
            p.factors.push((Factor::Sum(inner), 1));
        }
    }
    p
}

/// The cheapest of the coefficient's rewritings (see the module documentation).
fn best_coefficient(search: &mut search::Search, ms: Vec<Mono>, n_coords: usize) -> Form {
    let plain = searched_coefficient(search, ms.clone(), n_coords);
    // What a loop closure divides by (1/cos φ, 1/sin ψ) goes below one line for the whole
    // coefficient when the plain form would write a fraction inside a fraction, or when one
    // line makes it a single product: R sin(φ − θ)/cos φ, not R (sin φ cos θ/cos φ − sin θ).
    if !divides_inside(&plain) {
        return plain;
    }
    // Below the line: the cosines and sines, and the parameters divided by with them.
    let mut below: Vec<(Leaf, u8)> = Vec::new();
    for m in &ms {
        for (a, k) in &m.atoms {
            if matches!(a, Leaf::Reciprocal(..) | Leaf::Inverse(_)) {
                match below.iter_mut().find(|x| &x.0 == a) {
                    Some(x) => x.1 = x.1.max(*k),
                    None => below.push((a.clone(), *k)),
                }
            }
        }
    }
    let top: Vec<Mono> = ms
        .iter()
        .map(|m| m.divided(&Rational::one(), &below))
        .collect();
    let n = searched_coefficient(search, top, n_coords);
    let p = times_rates(n, below);
    let single = !p.factors.iter().any(|(x, _)| matches!(x, Factor::Sum(_)));
    let over_one_line = p
        .factors
        .iter()
        .any(|(x, _)| matches!(x, Factor::Leaf(Leaf::Reciprocal(..))));
    if over_one_line && (single || nested_fraction(&plain)) {
        Form::single(p)
    } else {
        plain
    }
}

/// Whether a product written as a fraction (it divides by a loop closure's cos q or sin q)
/// holds a sum that divides too: a fraction inside a fraction.
fn nested_fraction(f: &Form) -> bool {
    f.terms.iter().any(|p| {
        let over = p
            .factors
            .iter()
            .any(|(x, _)| matches!(x, Factor::Leaf(Leaf::Reciprocal(..) | Leaf::Inverse(_))));
        (over && divides_inside(&Form::single(p.clone())))
            || p.factors
                .iter()
                .any(|(x, _)| matches!(x, Factor::Sum(s) if nested_fraction(s)))
    })
}

/// Whether a parenthesised sum of the form holds a term that divides by a loop closure's
/// cos q or sin q (a fraction inside a bracket).
fn divides_inside(f: &Form) -> bool {
    fn divides(f: &Form) -> bool {
        f.terms.iter().any(|p| {
            p.factors.iter().any(|(x, _)| match x {
                Factor::Leaf(l) => matches!(l, Leaf::Reciprocal(..) | Leaf::Inverse(_)),
                Factor::Sum(s) => divides(s),
            })
        })
    }
    f.terms.iter().any(|p| {
        p.factors
            .iter()
            .any(|(x, _)| matches!(x, Factor::Sum(s) if divides(s)))
    })
}

fn searched_coefficient(search: &mut search::Search, ms: Vec<Mono>, n_coords: usize) -> Form {
    search.fresh_budget();
    let compound = rewrite::squares(rewrite::compound_angles(ms.clone(), n_coords));
    let candidates = [
        ms,
        rewrite::double_sines(compound.clone(), false),
        rewrite::double_sines(compound.clone(), true),
        compound,
    ];
    let mut best: Option<Form> = None;
    for c in candidates {
        let f = search.best(c);
        if best
            .as_ref()
            .is_none_or(|b| search.placed(&f) < search.placed(b))
        {
            best = Some(f);
        }
    }
    best.unwrap_or_default()
}

/// `coefficient · rates` as one product (or `numerator · what it divides by`).
fn times_rates(coef: Form, kin: Kinematic) -> Product {
    let rates = kin.into_iter().map(|(a, k)| (Factor::Leaf(a), k));
    match <[Product; 1]>::try_from(coef.terms) {
        Ok([mut p]) => {
            p.factors.extend(rates);
            p
        }
        Err(terms) => {
            let mut inner = Form { terms };
            let mut coef = Rational::one();
            if search::negative_majority(&inner) {
                inner
                    .terms
                    .iter_mut()
                    .for_each(|p| p.coef = -p.coef.clone());
                coef = -coef;
            }
            let mut factors = vec![(Factor::Sum(inner), 1)];
            factors.extend(rates);
            Product { coef, factors }
        }
    }
}

/// Terms from [`Expr::times_text`] joined into one sum (`0` when there are none).
pub fn signed_sum(terms: &[(bool, String)]) -> String {
    let mut out = String::new();
    for (minus, term) in terms {
        out.push_str(match (out.is_empty(), minus) {
            (true, false) => "",
            (true, true) => "-",
            (false, false) => " + ",
            (false, true) => " - ",
        });
        out.push_str(term);
    }
    if out.is_empty() { "0".into() } else { out }
}
