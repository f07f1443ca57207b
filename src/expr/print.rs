//! Printing: the plain-text form (parsable back) and the presentation form, collected by
//! kinematic monomials (q̈ᵢ, q̇ᵢq̇ⱼ) with the common parameter factor of each group pulled out.

use super::{CoordId, Expr, ParamId, Registry, Trig, VarId, VarRole};
use std::cmp::Reverse;
use std::rc::Rc;
use symbolica::domains::rational::Rational;

/// A term split the way a teacher reads it.
#[derive(Debug, Clone)]
pub struct TermParts {
    /// Rational coefficient.
    pub coef: Rational,
    /// (parameter, exponent), in declaration order.
    pub params: Vec<(ParamId, u8)>,
    /// (parameter, exponent) of the parameters the term divides by.
    pub inverses: Vec<(ParamId, u8)>,
    /// (coordinate, cos or sin, exponent) of what the term divides by (a loop closure's
    /// 1/cos q).
    pub reciprocals: Vec<(CoordId, Trig, u8)>,
    /// (coordinate, is_cos, exponent): trigonometric factors.
    pub trig: Vec<(CoordId, bool, u8)>,
    /// (coordinate, exponent): length coordinates.
    pub values: Vec<(CoordId, u8)>,
    /// (coordinate, derivative order, exponent): the kinematic monomial.
    pub rates: Vec<(CoordId, u8, u8)>,
    /// (square root, exponent), exponent 1 in a canonical form.
    pub roots: Vec<(super::RootId, u8)>,
}

/// Splits exponents into the parts of a term.
pub fn split(reg: &Registry, coef: &Rational, e: &[u8]) -> TermParts {
    let mut t = TermParts {
        coef: coef.clone(),
        params: vec![],
        inverses: vec![],
        reciprocals: vec![],
        trig: vec![],
        values: vec![],
        rates: vec![],
        roots: vec![],
    };
    for (i, &k) in e.iter().enumerate() {
        if k == 0 {
            continue;
        }
        match reg.role(VarId(i)) {
            VarRole::Parameter(p) => t.params.push((p, k)),
            VarRole::Inverse(p) => t.inverses.push((p, k)),
            VarRole::Reciprocal(q, f) => t.reciprocals.push((q, f, k)),
            VarRole::Cos(q) => t.trig.push((q, true, k)),
            VarRole::Sin(q) => t.trig.push((q, false, k)),
            VarRole::Value(q) => t.values.push((q, k)),
            VarRole::Rate(q, o) => t.rates.push((q, o, k)),
            VarRole::Root(r) => t.roots.push((r, k)),
        }
    }
    t.params.sort();
    t.inverses.sort();
    t.reciprocals.sort();
    t.trig.sort_by_key(|&(q, is_cos, _)| (q, !is_cos));
    t.rates.sort_by_key(|&(q, o, _)| (Reverse(o), q));
    t
}

/// Ordering key of a kinematic monomial: higher derivatives first, then by coordinate.
fn rate_key(rates: &[(CoordId, u8, u8)]) -> Vec<(Reverse<u8>, CoordId, Reverse<u8>)> {
    rates
        .iter()
        .map(|&(q, o, k)| (Reverse(o), q, Reverse(k)))
        .collect()
}

/// Ordering key of the non-kinematic part: parameters, then trigonometric factors.
/// Terms without parameters or trigonometric factors (plain numbers) come last.
///
/// Within that, as a teacher writes a sum: lower degree in the parameters first
/// (A2 + m2 L2², L1 + L2 cos θ2), then by parameter order.
type OtherKey = (
    bool,
    u32,
    Vec<(ParamId, Reverse<u8>)>,
    Vec<(CoordId, bool, Reverse<u8>)>,
);

fn other_key(t: &TermParts) -> OtherKey {
    (
        t.params.is_empty()
            && t.trig.is_empty()
            && t.inverses.is_empty()
            && t.reciprocals.is_empty()
            && t.roots.is_empty(),
        t.params.iter().map(|&(_, k)| k as u32).sum(),
        t.params.iter().map(|&(p, k)| (p, Reverse(k))).collect(),
        t.trig
            .iter()
            .map(|&(q, c, k)| (q, !c, Reverse(k)))
            .collect(),
    )
}

/// The terms of an expression in the stable reading order.
pub fn ordered_terms(e: &Expr) -> Vec<TermParts> {
    let reg = e.registry();
    let mut v: Vec<TermParts> = e.terms().map(|(c, x)| split(reg, c, x)).collect();
    // Each key built once (a stable sort): a 188,000-term equation of a planar chain spent
    // 15 % of its run building them at every comparison.
    v.sort_by_cached_key(|t| (rate_key(&t.rates), other_key(t)));
    v
}

fn factors_text(reg: &Registry, t: &TermParts) -> Vec<String> {
    let pw = |base: String, k: u8| {
        if k == 1 { base } else { format!("{base}^{k}") }
    };
    let mut f = Vec::new();
    for &(p, k) in &t.params {
        f.push(pw(reg.scalar_name(p).to_string(), k));
    }
    for &(q, is_cos, k) in &t.trig {
        let n = &reg.coord_info(q).name;
        f.push(pw(
            format!("{}({n})", if is_cos { "cos" } else { "sin" }),
            k,
        ));
    }
    for &(q, k) in &t.values {
        f.push(pw(reg.coord_info(q).name.clone(), k));
    }
    for &(r, k) in &t.roots {
        f.push(pw(format!("sqrt({})", reg.radicand_text(r)), k));
    }
    for &(q, o, k) in &t.rates {
        let n = &reg.coord_info(q).name;
        let head = ["dot", "ddot", "dddot"][(o.clamp(1, 3) - 1) as usize];
        f.push(pw(format!("{head}({n})"), k));
    }
    f
}

/// One term as text, with its sign folded into the returned flag (true = negative); the
/// parameters it divides by after a `/` (`m*g/k`, `2/(k*l^2)`).
fn term_text(reg: &Registry, t: &TermParts) -> (bool, String) {
    let neg = t.coef.is_negative();
    let abs = t.coef.abs();
    let f = factors_text(reg, t);
    let s = if f.is_empty() {
        abs.to_string()
    } else if abs.is_one() {
        f.join("*")
    } else {
        format!("{abs}*{}", f.join("*"))
    };
    let pw = |n: String, k: u8| if k == 1 { n } else { format!("{n}^{k}") };
    let below: Vec<String> = t
        .inverses
        .iter()
        .map(|&(p, k)| pw(reg.scalar_name(p).to_string(), k))
        .chain(
            t.reciprocals
                .iter()
                .map(|&(q, f, k)| pw(format!("{}({})", f.name(), reg.coord_info(q).name), k)),
        )
        .collect();
    let s = match below.len() {
        0 => s,
        1 => format!("{s}/{}", below[0]),
        _ => format!("{s}/({})", below.join("*")),
    };
    (neg, s)
}

fn join_signed(parts: Vec<(bool, String)>) -> String {
    if parts.is_empty() {
        return "0".to_string();
    }
    let mut out = String::new();
    for (i, (neg, s)) in parts.into_iter().enumerate() {
        match (i, neg) {
            (0, true) => out.push_str(&format!("-{s}")),
            (0, false) => out.push_str(&s),
            (_, true) => out.push_str(&format!(" - {s}")),
            (_, false) => out.push_str(&format!(" + {s}")),
        }
    }
    out
}

/// Plain text of the canonical form.
pub fn to_text(e: &Expr) -> String {
    let reg = e.registry();
    join_signed(ordered_terms(e).iter().map(|t| term_text(reg, t)).collect())
}

/// A kinematic monomial: (coordinate, derivative order, exponent).
type Kinematic = Vec<(CoordId, u8, u8)>;

/// One group of the presentation form: `factor · (rest) · kinematic`.
#[derive(Debug, Clone)]
pub struct GroupedTerm {
    /// Kinematic monomial: (coordinate, derivative order, exponent); empty for the part
    /// with no rate.
    pub kinematic: Vec<(CoordId, u8, u8)>,
    /// Common factor of the group: a signed rational times parameters (and trigonometric
    /// factors) shared by every term.
    pub factor: TermParts,
    /// What remains once the factor is pulled out (1 when the group is one term).
    pub rest: Expr,
}

/// The grouped form of an expression: groups by kinematic monomial, in reading order (the
/// compiled evaluator's starting point; the printed form is [`super::present`]'s).
#[derive(Debug, Clone)]
pub struct Grouped {
    /// The groups, q̈ first, then products of rates, then the rest.
    pub groups: Vec<GroupedTerm>,
    reg: Rc<Registry>,
}

impl Expr {
    /// The grouped form: terms collected by kinematic monomial (q̈ᵢ, q̇ᵢq̇ⱼ), each group's
    /// common factor (sign, rational, parameters and trigonometric factors) pulled out. Its
    /// text is what symbolica's evaluator compiles (sin and cos of single angles only).
    pub(crate) fn grouped(&self) -> Grouped {
        let reg = self.registry().clone();
        let terms = ordered_terms(self);
        let mut groups: Vec<(Kinematic, Vec<TermParts>)> = Vec::new();
        for t in terms {
            match groups.iter_mut().find(|(k, _)| *k == t.rates) {
                Some(g) => g.1.push(t),
                None => groups.push((t.rates.clone(), vec![t])),
            }
        }
        let groups = groups
            .into_iter()
            .map(|(kin, ts)| {
                let factor = common_factor(&ts);
                let rest_terms = ts
                    .iter()
                    .map(|t| {
                        let mut e = vec![0u8; reg.nvars()];
                        let strip = |e: &mut Vec<u8>, role: VarRole, k: u8| {
                            if let Some(i) = reg.index_of(role) {
                                e[i.index()] += k;
                            }
                        };
                        for &(p, k) in &t.params {
                            let fk = factor
                                .params
                                .iter()
                                .find(|x| x.0 == p)
                                .map(|x| x.1)
                                .unwrap_or(0);
                            strip(&mut e, VarRole::Parameter(p), k - fk);
                        }
                        for &(q, c, k) in &t.trig {
                            let fk = factor
                                .trig
                                .iter()
                                .find(|x| x.0 == q && x.1 == c)
                                .map(|x| x.2)
                                .unwrap_or(0);
                            let role = if c { VarRole::Cos(q) } else { VarRole::Sin(q) };
                            strip(&mut e, role, k - fk);
                        }
                        for &(q, k) in &t.values {
                            strip(&mut e, VarRole::Value(q), k);
                        }
                        for &(r, k) in &t.roots {
                            strip(&mut e, VarRole::Root(r), k);
                        }
                        for &(p, k) in &t.inverses {
                            strip(&mut e, VarRole::Inverse(p), k);
                        }
                        for &(q, f, k) in &t.reciprocals {
                            strip(&mut e, VarRole::Reciprocal(q, f), k);
                        }
                        (&t.coef * &factor.coef.inv(), e)
                    })
                    .collect();
                GroupedTerm {
                    kinematic: kin,
                    factor,
                    rest: Expr::from_terms(&reg, rest_terms),
                }
            })
            .collect();
        Grouped { groups, reg }
    }
}

/// The common factor of a group: gcd of the monomials in parameters and trigonometric
/// factors, with the rational content, and the sign of most of its terms.
fn common_factor(ts: &[TermParts]) -> TermParts {
    let first = &ts[0];
    let mut params = first.params.clone();
    let mut trig = first.trig.clone();
    for t in &ts[1..] {
        params = params
            .into_iter()
            .filter_map(|(p, k)| t.params.iter().find(|x| x.0 == p).map(|x| (p, k.min(x.1))))
            .collect();
        trig = trig
            .into_iter()
            .filter_map(|(q, c, k)| {
                t.trig
                    .iter()
                    .find(|x| x.0 == q && x.1 == c)
                    .map(|x| (q, c, k.min(x.2)))
            })
            .collect();
    }
    let mut coef = first.coef.abs();
    for t in &ts[1..] {
        coef = coef.gcd(&t.coef);
    }
    // A minus sign comes out of the group only when most of its terms are negative (a tie
    // stays positive).
    let negatives = ts.iter().filter(|t| t.coef.is_negative()).count();
    let negative = 2 * negatives > ts.len();
    let coef = if negative {
        coef.abs().neg()
    } else {
        coef.abs()
    };
    TermParts {
        coef,
        params,
        inverses: vec![],
        reciprocals: vec![],
        trig,
        values: vec![],
        rates: vec![],
        roots: vec![],
    }
}

impl std::fmt::Display for Grouped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let reg = &self.reg;
        let mut parts = Vec::new();
        for g in &self.groups {
            let (neg, head) = term_text(reg, &g.factor);
            let mut factors: Vec<String> = Vec::new();
            if head != "1" || (g.kinematic.is_empty() && g.rest.is_one()) {
                factors.push(head);
            }
            if !(g.rest.nterms() == 1 && g.rest.as_rational().is_some_and(|r| r.is_one())) {
                let r = to_text(&g.rest);
                factors.push(if g.rest.nterms() > 1 {
                    format!("({r})")
                } else {
                    r
                });
            }
            let kin = TermParts {
                coef: Rational::one(),
                params: vec![],
                inverses: vec![],
                reciprocals: vec![],
                trig: vec![],
                values: vec![],
                rates: g.kinematic.clone(),
                roots: vec![],
            };
            factors.extend(factors_text(reg, &kin));
            if factors.is_empty() {
                factors.push("1".to_string());
            }
            parts.push((neg, factors.join("*")));
        }
        f.write_str(&join_signed(parts))
    }
}
