//! The presentation tree: sums of signed products of atoms and parenthesised sums, its
//! operation count, its exact value, and its plain text (parsable back).

use super::super::{CoordId, Expr, ParamId, Registry, Trig, VarRole};
use std::collections::{BTreeMap, HashMap};
use std::rc::Rc;
use symbolica::domains::rational::Rational;

/// An angle Σ kᵢ qᵢ with integer coefficients, as the course writes it: the coordinate of
/// highest index first, with a positive coefficient (θ2 − θ1, 2θ2).
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Angle(pub(crate) Vec<(CoordId, i32)>);

impl Angle {
    /// The angle q itself.
    pub fn of(q: CoordId) -> Angle {
        Angle(vec![(q, 1)])
    }

    /// Normalises Σ kᵢ qᵢ: time coordinates before constant angles (the first `n_coords`
    /// coordinates are time coordinates), the highest first (θ2 − θ1, θ − α), the first
    /// coefficient positive. Returns the angle and whether it was negated (cos(−a) = cos a,
    /// sin(−a) = −sin a).
    pub fn normalized(mut terms: Vec<(CoordId, i32)>, n_coords: usize) -> (Angle, bool) {
        terms.retain(|&(_, k)| k != 0);
        terms.sort_by_key(|&(q, _)| (q.index() >= n_coords, std::cmp::Reverse(q)));
        let flip = terms.first().is_some_and(|&(_, k)| k < 0);
        if flip {
            terms.iter_mut().for_each(|t| t.1 = -t.1);
        }
        (Angle(terms), flip)
    }

    /// The terms (coordinate, integer coefficient), highest coordinate first.
    pub fn terms(&self) -> &[(CoordId, i32)] {
        &self.0
    }

    /// Whether the angle is a single coordinate with coefficient 1.
    pub fn is_simple(&self) -> bool {
        matches!(self.0.as_slice(), [(_, 1)])
    }

    /// Operations written inside the argument (2θ: one; θ2 − θ1: one).
    fn ops(&self) -> usize {
        let mut n = self.0.len().saturating_sub(1);
        n += self.0.iter().filter(|&&(_, k)| k.abs() != 1).count();
        n
    }

    pub(crate) fn text(&self, reg: &Registry) -> String {
        // The first coefficient's sign is not written: only normalised angles are printed.
        assert!(
            self.0.first().is_some_and(|t| t.1 > 0),
            "an angle is printed normalised"
        );
        let mut s = String::new();
        for (i, &(q, k)) in self.0.iter().enumerate() {
            let name = &reg.coord_info(q).name;
            let body = if k.abs() == 1 {
                name.clone()
            } else {
                format!("{}*{name}", k.abs())
            };
            match (i, k < 0) {
                (0, _) => s.push_str(&body),
                (_, true) => s.push_str(&format!(" - {body}")),
                (_, false) => s.push_str(&format!(" + {body}")),
            }
        }
        s
    }
}

/// A leaf of the presentation tree.
#[derive(Debug, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Leaf {
    /// A parameter or an unknown.
    Param(ParamId),
    /// 1/p, a parameter the mechanism divides by: written below the line of its product.
    Inverse(ParamId),
    /// 1/cos q or 1/sin q, an angle a loop closure divides by: written below the line of
    /// its product.
    Reciprocal(CoordId, Trig),
    /// A length coordinate, or an angle written as itself.
    Value(CoordId),
    /// A square root of the registry (see [`crate::expr::RegistryBuilder::roots`]).
    Root(super::super::RootId),
    /// q̇ (order 1), q̈ (order 2)…
    Rate(CoordId, u8),
    /// cos of an angle.
    Cos(Angle),
    /// sin of an angle.
    Sin(Angle),
}

impl Leaf {
    /// Whether the atom is a cos or a sin.
    pub fn is_trig(&self) -> bool {
        matches!(self, Leaf::Cos(_) | Leaf::Sin(_))
    }
}

/// A factor of a product.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Factor {
    /// A leaf.
    Leaf(Leaf),
    /// A parenthesised sum.
    Sum(Form),
}

/// A signed product: a rational coefficient times factors with their exponents, in the
/// course's reading order (see [`Product::ordered`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Product {
    /// The coefficient (its sign is the product's sign).
    pub coef: Rational,
    /// The factors with their exponents (≥ 1).
    pub factors: Vec<(Factor, u8)>,
}

/// A sum of products: the presentation form of an expression. Zero is the empty sum.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default)]
pub struct Form {
    /// The terms, in reading order.
    pub terms: Vec<Product>,
}

/// Cost of a form: operations as `sympy.count_ops` counts them, then the number of leaves
/// (the course's preference among forms of equal operation count: D2 sin 2θ2 over
/// 2 D2 cos θ2 sin θ2).
pub type Cost = (usize, usize);

impl Form {
    /// A form of one product.
    pub fn single(p: Product) -> Form {
        Form { terms: vec![p] }
    }

    /// Operations: each + or − between terms, each product, power, function and argument
    /// operation, a leading minus sign, and a division for a fraction.
    pub fn cost(&self) -> Cost {
        self.cost_at(0)
    }

    /// The cost of a group's coefficient where it will stand: a sum in parentheses before
    /// its rates (depth 1), or one product that needs none (depth 0).
    pub fn placed_cost(&self) -> Cost {
        if self.terms.len() == 1 {
            self.cost_at(0)
        } else {
            self.cost_at(1)
        }
    }

    /// The cost of a sum at nesting `depth` (0: the expression; 1: a parenthesised sum in
    /// it). A sum inside a parenthesised sum costs 2 (depth − 1) operations more: a teacher
    /// nests only where it pays (m2 (L1 + L2 cos θ2)²), never 2 (a + b) inside a bracket,
    /// nor a Horner scheme ((… cos θ2 + …) sin θ2).
    pub fn cost_at(&self, depth: usize) -> Cost {
        let mut ops = self.terms.len().saturating_sub(1);
        if depth >= 2 {
            ops += 2 * (depth - 1);
        }
        let mut leaves = 0;
        if self.terms.first().is_some_and(|p| p.coef.is_negative()) {
            ops += 1;
        }
        for p in &self.terms {
            let (o, l) = p.cost(depth);
            ops += o;
            leaves += l;
        }
        (ops, leaves)
    }

    /// The exact value: rebuilt from the leaves with the engine's arithmetic (cos and sin of
    /// compound angles by the angle-addition formulas).
    pub fn to_expr(&self, reg: &Rc<Registry>) -> Expr {
        self.to_expr_with(reg, &mut HashMap::new())
    }

    /// [`Form::to_expr`], each compound cos or sin expanded once (`leaves`).
    fn to_expr_with(&self, reg: &Rc<Registry>, leaves: &mut HashMap<Leaf, Expr>) -> Expr {
        // All the products' terms at once: adding them one by one to a growing sum would be
        // quadratic on a chain's long results.
        let mut terms = Vec::new();
        // The products that are a monomial times one compound cos or sin (a long coefficient
        // in the linearised form): Σ monomials, multiplied by the leaf once.
        let mut by_leaf: BTreeMap<&Leaf, Vec<(Rational, Vec<u8>)>> = BTreeMap::new();
        for p in &self.terms {
            match p.monomial_and_rest(reg) {
                Some((mono, Some(Factor::Leaf(leaf)))) => {
                    by_leaf
                        .entry(leaf)
                        .or_default()
                        .push((p.coef.clone(), mono));
                }
                Some((mono, Some(Factor::Sum(s)))) => {
                    let e = s.to_expr_with(reg, leaves);
                    if !times_monomial(reg, &p.coef, &mono, &e, &mut terms) {
                        let m = Expr::from_terms(reg, vec![(p.coef.clone(), mono)]);
                        terms.extend((&m * &e).terms().map(|(c, x)| (c.clone(), x.to_vec())));
                    }
                }
                Some((mono, None)) => terms.push((p.coef.clone(), mono)),
                None => {
                    let e = p.to_expr(reg, leaves);
                    terms.extend(e.terms().map(|(c, x)| (c.clone(), x.to_vec())));
                }
            }
        }
        for (leaf, monos) in by_leaf {
            let base = leaves
                .entry(leaf.clone())
                .or_insert_with(|| leaf_expr(reg, leaf));
            if !monos.iter().all(|(_, m)| adds_exponents(reg, m, base)) {
                let e = &Expr::from_terms(reg, monos) * &*base;
                terms.extend(e.terms().map(|(c, x)| (c.clone(), x.to_vec())));
                continue;
            }
            for (c, m) in &monos {
                times_monomial(reg, c, m, base, &mut terms);
            }
        }
        Expr::from_terms(reg, terms)
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether the form is zero.
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// The plain text in the spec syntax (parses back to the same canonical form).
    pub fn text(&self, reg: &Registry) -> String {
        if self.terms.is_empty() {
            return "0".to_string();
        }
        let mut s = String::new();
        for (i, p) in self.terms.iter().enumerate() {
            let (neg, body) = p.text(reg);
            s.push_str(match (i, neg) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            s.push_str(&body);
        }
        s
    }
}

impl Product {
    /// A product of one coefficient and leaves.
    pub fn of_atoms(coef: Rational, atoms: Vec<(Leaf, u8)>) -> Product {
        Product {
            coef,
            factors: atoms
                .into_iter()
                .map(|(a, k)| (Factor::Leaf(a), k))
                .collect(),
        }
    }

    fn cost(&self, depth: usize) -> Cost {
        let num = !self.coef.abs().is_one();
        let (n, d) = num_den(&self.coef);
        let mut ops = (self.factors.len() + usize::from(num)).saturating_sub(1);
        if d != "1" && n != "1" {
            ops += 1;
        }
        let mut leaves = usize::from(num);
        for (f, k) in &self.factors {
            if *k > 1 {
                ops += 1;
            }
            match f {
                Factor::Leaf(a) => {
                    leaves += 1;
                    if let Leaf::Cos(x) | Leaf::Sin(x) = a {
                        ops += 1 + x.ops();
                    }
                }
                Factor::Sum(s) => {
                    let (o, l) = s.cost_at(depth + 1);
                    ops += o;
                    leaves += l;
                }
            }
        }
        (ops, leaves)
    }

    fn to_expr(&self, reg: &Rc<Registry>, leaves: &mut HashMap<Leaf, Expr>) -> Expr {
        // The plain leaves (parameters, coordinates, rates, cos and sin of one angle) make one
        // monomial, built directly unless it holds a sin² (which the canonical form reduces).
        let mut mono = vec![0u8; reg.nvars()];
        let mut rest: Vec<&(Factor, u8)> = Vec::new();
        for f in &self.factors {
            match plain_var(reg, &f.0) {
                Some((i, is_sin)) if !(is_sin && mono[i] + f.1 >= 2) => mono[i] += f.1,
                _ => rest.push(f),
            }
        }
        let mut acc = Expr::from_terms(reg, vec![(self.coef.clone(), mono)]);
        // cos²q of an angle whose sine a closure divides by, or cos q·(1/cos q): reduced.
        if !reg.reciprocals.is_empty() {
            acc = &acc * &reg.one();
        }
        for (f, k) in rest {
            let base = match f {
                Factor::Leaf(a) => leaves
                    .entry(a.clone())
                    .or_insert_with(|| leaf_expr(reg, a))
                    .clone(),
                Factor::Sum(s) => s.to_expr_with(reg, leaves),
            };
            acc = &acc * &base.pow(*k as u32);
        }
        acc
    }

    /// (exponents of its plain leaves, its one other factor if any) when the product is a
    /// monomial, or a monomial times one cos or sin of a compound angle or one sum, with no
    /// power of a sine to reduce and no reciprocal to cancel among its leaves.
    fn monomial_and_rest(&self, reg: &Registry) -> Option<(Vec<u8>, Option<&Factor>)> {
        if !reg.reciprocals.is_empty() {
            return None;
        }
        let mut mono = vec![0u8; reg.nvars()];
        let mut other = None;
        for (f, k) in &self.factors {
            match plain_var(reg, f) {
                Some((i, is_sin)) if !(is_sin && mono[i] + k >= 2) => mono[i] += k,
                None if *k == 1 && other.is_none() => other = Some(f),
                _ => return None,
            }
        }
        Some((mono, other))
    }

    /// The factors in reading order: parameters (course order), length coordinates, sums,
    /// rates, then trigonometric functions.
    pub fn ordered(&self, reg: &Registry) -> Vec<&(Factor, u8)> {
        let mut v: Vec<&(Factor, u8)> = self.factors.iter().collect();
        v.sort_by_key(|a| factor_key(reg, &a.0));
        v
    }

    /// (negative, text without the sign): `m*g*sin(beta)/k`, `1/2*m*L^2`, `m/(2*k*l)`.
    fn text(&self, reg: &Registry) -> (bool, String) {
        let neg = self.coef.is_negative();
        let (n, d) = num_den(&self.coef);
        let mut parts: Vec<String> = Vec::new();
        let mut below: Vec<String> = Vec::new();
        for (f, k) in self.ordered(reg) {
            let base = match f {
                Factor::Leaf(a) => leaf_text(reg, a),
                Factor::Sum(s) => format!("({})", s.text(reg)),
            };
            let text = if *k == 1 { base } else { format!("{base}^{k}") };
            match f {
                Factor::Leaf(Leaf::Inverse(_) | Leaf::Reciprocal(..)) => below.push(text),
                _ => parts.push(text),
            }
        }
        if below.is_empty() {
            if n != "1" || d != "1" {
                parts.insert(0, if d == "1" { n } else { format!("{n}/{d}") });
            }
        } else {
            if n != "1" {
                parts.insert(0, n);
            }
            if d != "1" {
                below.insert(0, d);
            }
        }
        if parts.is_empty() {
            parts.push("1".to_string());
        }
        let top = parts.join("*");
        (
            neg,
            match below.len() {
                0 => top,
                1 => format!("{top}/{}", below[0]),
                _ => format!("{top}/({})", below.join("*")),
            },
        )
    }
}

/// |c| as (numerator, denominator) text.
pub(crate) fn num_den(c: &Rational) -> (String, String) {
    let s = c.abs().to_string();
    match s.split_once('/') {
        Some((n, d)) => (n.to_string(), d.to_string()),
        None => (s, "1".to_string()),
    }
}

/// The variable of a plain leaf (and whether it is a sine): a parameter, a coordinate, a
/// rate, the cos or sin of one angle.
fn plain_var(reg: &Registry, f: &Factor) -> Option<(usize, bool)> {
    let Factor::Leaf(l) = f else { return None };
    let (role, is_sin) = match l {
        Leaf::Param(p) => (VarRole::Parameter(*p), false),
        Leaf::Inverse(p) => (VarRole::Inverse(*p), false),
        Leaf::Reciprocal(q, f) => (VarRole::Reciprocal(*q, *f), false),
        Leaf::Value(q) => (VarRole::Value(*q), false),
        Leaf::Root(r) => (VarRole::Root(*r), false),
        Leaf::Rate(q, o) => (VarRole::Rate(*q, *o), false),
        Leaf::Cos(a) if a.is_simple() => (VarRole::Cos(a.0[0].0), false),
        Leaf::Sin(a) if a.is_simple() => (VarRole::Sin(a.0[0].0), true),
        _ => return None,
    };
    reg.index_of(role).map(|i| (i.index(), is_sin))
}

/// Whether the terms of x^mono · e are those of e with `mono`'s exponents added: no sine of
/// `mono` is met again in `e` (sin² is reduced by the canonical form), no reciprocal is in
/// the registry, and no exponent passes 255.
fn adds_exponents(reg: &Registry, mono: &[u8], e: &Expr) -> bool {
    reg.reciprocals.is_empty()
        && !reg
            .coords
            .iter()
            .filter_map(|c| c.trig)
            .any(|(_, s)| mono[s] > 0 && e.p.degree(s) > 0)
        && mono
            .iter()
            .enumerate()
            .all(|(i, &k)| k == 0 || usize::from(k) + usize::from(e.p.degree(i)) <= 255)
}

/// Appends the terms of `coef · x^mono · e` to `terms` when [`adds_exponents`] holds;
/// otherwise appends nothing and returns false.
fn times_monomial(
    reg: &Registry,
    coef: &Rational,
    mono: &[u8],
    e: &Expr,
    terms: &mut Vec<(Rational, Vec<u8>)>,
) -> bool {
    if !adds_exponents(reg, mono, e) {
        return false;
    }
    terms.reserve(e.nterms());
    for (c, x) in e.terms() {
        let sum = x.iter().zip(mono).map(|(a, b)| a + b).collect();
        terms.push((c * coef, sum));
    }
    true
}

/// Reading-order key of a factor.
pub(crate) fn factor_key(reg: &Registry, f: &Factor) -> (u8, u32, usize, u8, Vec<(CoordId, i32)>) {
    match f {
        // A group of parameters first, as a physical quantity ((M + m) g sin α,
        // (C − A) ω², (A + m h²) θ̈); a sum with coordinates after the parameters
        // (m2 (L1 + L2 cos θ2)²).
        Factor::Sum(s)
            if s.terms
                .iter()
                .all(|p| !p.factors.iter().any(|x| varies(&x.0))) =>
        {
            (0, 0, 0, 0, vec![])
        }
        Factor::Leaf(Leaf::Param(p)) => (1, reg.display_rank(*p), p.0, 0, vec![]),
        // Below the line, in the parameters' order (m g / (k l)).
        Factor::Leaf(Leaf::Inverse(p)) => (6, reg.display_rank(*p), p.0, 0, vec![]),
        // The cosines a loop closure divides by, after the parameters below the line.
        Factor::Leaf(Leaf::Reciprocal(q, f)) => (6, u32::MAX, q.0, 1 + *f as u8, vec![]),
        Factor::Leaf(Leaf::Value(q)) => (2, 0, q.0, 0, vec![]),
        // A root after the sums it may multiply, before the rates.
        Factor::Leaf(Leaf::Root(r)) => (3, 2, r.0, 0, vec![]),
        Factor::Sum(s) => (3, u32::from(s.terms.iter().any(has_rates)), 0, 0, vec![]),
        Factor::Leaf(Leaf::Rate(q, o)) => (4, 0, usize::MAX - *o as usize, q.0 as u8, vec![]),
        // sin θ cos θ, as the course writes it.
        Factor::Leaf(Leaf::Sin(a)) => (5, 0, 0, 0, a.0.clone()),
        Factor::Leaf(Leaf::Cos(a)) => (5, 0, 1, 0, a.0.clone()),
    }
}

/// Whether a factor depends on the motion or the geometry's angles: a coordinate, a rate, a
/// trigonometric function, or a sum holding one.
fn varies(f: &Factor) -> bool {
    match f {
        Factor::Leaf(Leaf::Param(_) | Leaf::Inverse(_)) => false,
        Factor::Leaf(_) => true,
        Factor::Sum(s) => s
            .terms
            .iter()
            .any(|p| p.factors.iter().any(|x| varies(&x.0))),
    }
}

fn leaf_text(reg: &Registry, a: &Leaf) -> String {
    match a {
        Leaf::Param(p) | Leaf::Inverse(p) => reg.scalar_name(*p).to_string(),
        Leaf::Value(q) => reg.coord_info(*q).name.clone(),
        Leaf::Root(r) => format!("sqrt({})", reg.radicand_text(*r)),
        // Below the line: `/cos(phi)`.
        Leaf::Reciprocal(q, f) => format!("{}({})", f.name(), reg.coord_info(*q).name),
        Leaf::Rate(q, o) => {
            let head = ["dot", "ddot", "dddot"][(o.clamp(&1, &3) - 1) as usize];
            format!("{head}({})", reg.coord_info(*q).name)
        }
        Leaf::Cos(x) => format!("cos({})", x.text(reg)),
        Leaf::Sin(x) => format!("sin({})", x.text(reg)),
    }
}

/// The exact value of a leaf.
pub(crate) fn leaf_expr(reg: &Rc<Registry>, a: &Leaf) -> Expr {
    let var = |role: VarRole| {
        reg.index_of(role)
            .map(|i| reg.variable(i))
            .expect("a presentation leaf comes from a variable of the registry")
    };
    match a {
        Leaf::Param(p) => var(VarRole::Parameter(*p)),
        Leaf::Inverse(p) => var(VarRole::Inverse(*p)),
        Leaf::Reciprocal(q, f) => var(VarRole::Reciprocal(*q, *f)),
        Leaf::Value(q) => var(VarRole::Value(*q)),
        Leaf::Root(r) => var(VarRole::Root(*r)),
        Leaf::Rate(q, o) => var(VarRole::Rate(*q, *o)),
        Leaf::Cos(x) | Leaf::Sin(x) => {
            let terms: Vec<(CoordId, i64)> = x.0.iter().map(|&(q, k)| (q, k as i64)).collect();
            let (c, s) = super::super::parse::cos_sin(reg, &terms, 0);
            if matches!(a, Leaf::Cos(_)) { c } else { s }
        }
    }
}

/// Sorts the terms of a sum as a teacher writes it (see [`ProductKey`]), then brings the
/// first positive term to the front when the sum would start with a minus sign
/// (C2 − B2 + m2 L2², not −B2 + C2 + m2 L2²).
pub(crate) fn sort_terms(reg: &Registry, terms: &mut Vec<Product>) {
    // Each key built once (a stable sort), not at every comparison.
    terms.sort_by_cached_key(|p| product_key(reg, p));
    positive_first(terms);
}

/// Whether the sum's first term in a teacher's order (lower degree first) is negative: then
/// a sum whose sign does not matter (a squared one) is better written with its signs changed,
/// k − M Ω² rather than M Ω² − k.
pub(crate) fn leads_negative(reg: &Registry, terms: &[Product]) -> bool {
    (terms.iter().min_by_key(|p| product_key(reg, p))).is_some_and(|p| p.coef.is_negative())
}

/// Brings the first positive term to the front when the sum starts with a minus sign.
pub(crate) fn positive_first(terms: &mut Vec<Product>) {
    if terms.first().is_some_and(|p| p.coef.is_negative())
        && let Some(i) = terms.iter().position(|p| !p.coef.is_negative())
    {
        let p = terms.remove(i);
        terms.insert(0, p);
    }
}

/// The order of products as a teacher writes a sum: terms with rates first, then lower
/// degree in the parameters, then the course order of their parameters; plain numbers last.
type ProductKey = (
    bool,
    bool,
    u32,
    Vec<(u32, ParamId, std::cmp::Reverse<u8>)>,
    Vec<(u8, Vec<(CoordId, i32)>)>,
);

fn product_key(reg: &Registry, p: &Product) -> ProductKey {
    let mut degree = 0u32;
    let mut params = Vec::new();
    let mut trig = Vec::new();
    collect_key(reg, p, 1, &mut degree, &mut params, &mut trig);
    params.sort();
    // Terms with rates first (ẍ + g sin α), then by parameters; plain numbers last.
    (
        !has_rates(p),
        params.is_empty() && trig.is_empty() && !has_rates(p),
        degree,
        params,
        trig,
    )
}

fn has_rates(p: &Product) -> bool {
    p.factors.iter().any(|(f, _)| match f {
        Factor::Leaf(Leaf::Rate(..)) => true,
        Factor::Leaf(_) => false,
        Factor::Sum(s) => s.terms.iter().any(has_rates),
    })
}

fn collect_key(
    reg: &Registry,
    p: &Product,
    power: u32,
    degree: &mut u32,
    params: &mut Vec<(u32, ParamId, std::cmp::Reverse<u8>)>,
    trig: &mut Vec<(u8, Vec<(CoordId, i32)>)>,
) {
    for (f, k) in &p.factors {
        match f {
            Factor::Leaf(Leaf::Param(i)) => {
                *degree += *k as u32 * power;
                params.push((reg.display_rank(*i), *i, std::cmp::Reverse(*k)));
            }
            Factor::Leaf(Leaf::Cos(a)) => trig.push((0, a.0.clone())),
            Factor::Leaf(Leaf::Sin(a)) => trig.push((1, a.0.clone())),
            Factor::Leaf(_) => {}
            Factor::Sum(s) => {
                // A sum weighs its first term's degree.
                if let Some(first) = s.terms.first() {
                    let mut d = 0;
                    collect_key(reg, first, *k as u32, &mut d, params, trig);
                    *degree += d * power;
                }
            }
        }
    }
}
