//! Named subexpressions: a straight-line program of definitions Nₖ = c + Σ aₖₗ Nₗ, each
//! right side exact and canonical in the registry's variables and linear in earlier names.
//!
//! A chain's equations of motion repeat, expanded, every sum over the solids downstream of a
//! joint: the dynamic resultant of links k..n and its moment appear in every equation above k.
//! Named once, each such sum is a few terms long, and the whole grows with the structure of
//! the mechanism instead of with its expansion. Linear combinations are enough: the only
//! products the recursion forms are a named vector with a known one (a lever arm, a rotation),
//! never two named ones together.
//!
//! Exactness stays: [`Program::expand`] substitutes every name back and gives the canonical
//! polynomial the engine's expanded route gives; [`Program::evaluate`] evaluates the names in
//! order, the cheap route a numeric tool takes.

use crate::expr::{CoordId, Expr, Registry, VarId, VarRole};
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::rc::Rc;

/// The index of a name in its [`Program`] (`N1` is index 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NameId(usize);

impl NameId {
    /// Position in the program's definitions.
    pub fn index(self) -> usize {
        self.0
    }
}

impl fmt::Display for NameId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "N{}", self.0 + 1)
    }
}

/// c + Σ aₗ Nₗ: an exact expression plus exact multiples of names.
#[derive(Debug, Clone, PartialEq)]
pub struct Lin {
    /// The part that holds no name.
    pub constant: Expr,
    /// The coefficient of each name, none zero.
    pub terms: BTreeMap<NameId, Expr>,
}

impl Lin {
    /// An expression with no name.
    pub fn of(e: Expr) -> Lin {
        Lin {
            constant: e,
            terms: BTreeMap::new(),
        }
    }

    /// A name alone.
    pub fn name(reg: &Rc<Registry>, n: NameId) -> Lin {
        let mut terms = BTreeMap::new();
        terms.insert(n, reg.one());
        Lin {
            constant: reg.zero(),
            terms,
        }
    }

    /// Whether it is 0 (no name, a zero constant).
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty() && self.constant.is_zero()
    }

    /// The sum of two.
    pub fn add(&self, other: &Lin) -> Lin {
        let mut terms = self.terms.clone();
        for (n, a) in &other.terms {
            let sum = match terms.get(n) {
                Some(b) => b + a,
                None => a.clone(),
            };
            if sum.is_zero() {
                terms.remove(n);
            } else {
                terms.insert(*n, sum);
            }
        }
        Lin {
            constant: &self.constant + &other.constant,
            terms,
        }
    }

    /// The difference of two.
    pub fn sub(&self, other: &Lin) -> Lin {
        self.add(&other.scale(&-&other.constant.registry().one()))
    }

    /// k times it.
    pub fn scale(&self, k: &Expr) -> Lin {
        if k.is_zero() {
            return Lin::of(k.clone());
        }
        Lin {
            constant: &self.constant * k,
            terms: self.terms.iter().map(|(n, a)| (*n, a * k)).collect(),
        }
    }

    /// Σ kᵢ vᵢ of known expressions kᵢ and linear ones vᵢ.
    pub fn combination<'a>(
        reg: &Rc<Registry>,
        parts: impl IntoIterator<Item = (&'a Expr, &'a Lin)>,
    ) -> Lin {
        parts
            .into_iter()
            .fold(Lin::of(reg.zero()), |acc, (k, v)| acc.add(&v.scale(k)))
    }

    /// The terms of every expression in it (its size).
    pub fn nterms(&self) -> usize {
        self.constant.nterms() + self.terms.values().map(Expr::nterms).sum::<usize>()
    }

    /// As text that reads back once each name is known: `c + (a)*N3 − …`, in the spec syntax.
    pub fn text(&self, show: impl Fn(&Expr) -> String) -> String {
        let mut parts: Vec<String> = Vec::new();
        if !self.constant.is_zero() || self.terms.is_empty() {
            parts.push(show(&self.constant));
        }
        for (n, a) in &self.terms {
            let one = a.registry().one();
            parts.push(if *a == one {
                n.to_string()
            } else if *a == -&one {
                format!("-{n}")
            } else if a.nterms() == 1 {
                format!("{}*{n}", show(a))
            } else {
                format!("({})*{n}", show(a))
            });
        }
        parts.join(" + ")
    }
}

/// One definition of a [`Program`].
#[derive(Debug, Clone)]
pub struct Definition {
    /// What the name stands for, in the course's notation (`Rd(E3/0).x0`,
    /// `d/d ddot(q2) [Rd(E3/0).x0]`).
    pub meaning: String,
    /// Its value, over the names defined before it.
    pub value: Lin,
}

/// Named subexpressions, each over the ones before it.
#[derive(Debug, Clone)]
pub struct Program {
    reg: Rc<Registry>,
    defs: Vec<Definition>,
    /// The partial derivative of a name with respect to a coordinate's acceleration, once
    /// formed (a zero one as the zero Lin).
    partials: HashMap<(NameId, CoordId), Lin>,
    /// A name with the rates from an order on set to zero, once formed.
    rest: HashMap<(NameId, &'static str), Lin>,
}

impl Program {
    /// No definitions yet.
    pub fn new(reg: &Rc<Registry>) -> Program {
        Program {
            reg: reg.clone(),
            defs: Vec::new(),
            partials: HashMap::new(),
            rest: HashMap::new(),
        }
    }

    /// The definitions, in order.
    pub fn definitions(&self) -> &[Definition] {
        &self.defs
    }

    /// The registry of every expression in it.
    pub fn registry(&self) -> &Rc<Registry> {
        &self.reg
    }

    /// `v` under a name, unless naming it saves nothing (zero, a name alone, or one term).
    pub fn named(&mut self, meaning: String, v: Lin) -> Lin {
        let bare = v.terms.is_empty() && v.constant.nterms() <= 1;
        let alias = v.constant.is_zero()
            && v.terms.len() == 1
            && v.terms.values().all(|a| *a == self.reg.one());
        if bare || alias {
            return v;
        }
        self.defs.push(Definition { meaning, value: v });
        Lin::name(&self.reg, NameId(self.defs.len() - 1))
    }

    /// The value of every name at a registry point, in order.
    pub fn evaluate(&self, point: &[f64]) -> Vec<f64> {
        let mut vals: Vec<f64> = Vec::with_capacity(self.defs.len());
        for d in &self.defs {
            let v = lin_value(&d.value, point, &vals);
            vals.push(v);
        }
        vals
    }

    /// `v` with every name replaced by its expansion: the canonical polynomial.
    pub fn expand(&self, v: &Lin, memo: &mut Vec<Option<Expr>>) -> Expr {
        memo.resize(self.defs.len(), None);
        let mut parts = vec![v.constant.clone()];
        for (n, a) in &v.terms {
            let e = self.expand_name(*n, memo);
            parts.push(a * &e);
        }
        Expr::sum(&self.reg, parts)
    }

    fn expand_name(&self, n: NameId, memo: &mut Vec<Option<Expr>>) -> Expr {
        if let Some(e) = &memo[n.0] {
            return e.clone();
        }
        let e = self.expand(&self.defs[n.0].value.clone(), memo);
        memo[n.0] = Some(e.clone());
        e
    }

    /// ∂v/∂q̈ of the coordinate `q`, over names of the partial derivatives of the names.
    pub fn partial(&mut self, v: &Lin, q: CoordId) -> Lin {
        let mut out = Lin::of(v.constant.partial_rate(q, 2));
        for (n, a) in &v.terms {
            let da = a.partial_rate(q, 2);
            if !da.is_zero() {
                out = out.add(&Lin::name(&self.reg, *n).scale(&da));
            }
            let dn = self.partial_name(*n, q);
            out = out.add(&dn.scale(a));
        }
        out
    }

    fn partial_name(&mut self, n: NameId, q: CoordId) -> Lin {
        if let Some(l) = self.partials.get(&(n, q)) {
            return l.clone();
        }
        let value = self.defs[n.0].value.clone();
        let d = self.partial(&value, q);
        let rate = self.reg.ddot(q);
        let meaning = format!("d/d {} [{}]", rate, self.defs[n.0].meaning);
        let l = self.named(meaning, d);
        self.partials.insert((n, q), l.clone());
        l
    }

    /// v with the variables `vars` set to zero (rates, accelerations), its names replaced by
    /// names of theirs with the same variables zero; `what` says which in those names'
    /// meanings (`at rest`), and keys them.
    pub fn without(&mut self, v: &Lin, vars: &[VarId], what: &'static str) -> Lin {
        let mut out = Lin::of(zero_vars(&v.constant, vars));
        for (n, a) in &v.terms {
            let a0 = zero_vars(a, vars);
            if a0.is_zero() {
                continue;
            }
            let n0 = self.name_without(*n, vars, what);
            out = out.add(&n0.scale(&a0));
        }
        out
    }

    fn name_without(&mut self, n: NameId, vars: &[VarId], what: &'static str) -> Lin {
        if let Some(l) = self.rest.get(&(n, what)) {
            return l.clone();
        }
        let value = self.defs[n.0].value.clone();
        let r = self.without(&value, vars, what);
        let meaning = format!("{} {what}", self.defs[n.0].meaning);
        let l = self.named(meaning, r);
        self.rest.insert((n, what), l.clone());
        l
    }

    /// The variables of every rate of order `from` and above of the coordinates `coords`.
    pub fn rate_vars(&self, coords: impl IntoIterator<Item = CoordId>, from: u8) -> Vec<VarId> {
        coords
            .into_iter()
            .flat_map(|q| (from..=3u8).map(move |k| (q, k)))
            .filter_map(|(q, k)| self.reg.index_of(VarRole::Rate(q, k)))
            .collect()
    }
}

/// `e` with the variables `vars` set to zero.
fn zero_vars(e: &Expr, vars: &[VarId]) -> Expr {
    let mut e = e.clone();
    for &v in vars {
        if e.contains_var(v) {
            e = e.substitute(v, &e.registry().zero());
        }
    }
    e
}

/// Where each expression of a linear value sits in a compiled program's outputs.
#[derive(Debug, Clone)]
struct Slots {
    constant: usize,
    terms: Vec<(NameId, usize)>,
}

/// A [`Program`] and some values over its names, compiled into one evaluator
/// ([`Program::compile`]): every exact expression is evaluated at once, then the names in
/// order, then the values.
pub struct CompiledProgram {
    compiled: crate::expr::Compiled,
    outputs: Vec<f64>,
    names: Vec<Slots>,
    values: Vec<Slots>,
}

impl Program {
    /// Compiles the definitions and the values `vs` over them. The evaluator's input is a
    /// registry point ([`crate::output::numeric_point`]).
    pub fn compile(&self, vs: &[&Lin]) -> Result<CompiledProgram, crate::expr::ExprError> {
        let mut exprs: Vec<&Expr> = Vec::new();
        let mut names = Vec::with_capacity(self.defs.len());
        for d in &self.defs {
            names.push(place(&d.value, &mut exprs));
        }
        let values = vs.iter().map(|v| place(v, &mut exprs)).collect();
        let zero = self.reg.zero();
        if exprs.is_empty() {
            exprs.push(&zero);
        }
        let outputs = vec![0.0; exprs.len()];
        let compiled = self.reg.compile(&exprs)?;
        Ok(CompiledProgram {
            compiled,
            outputs,
            names,
            values,
        })
    }
}

/// Appends the expressions of `v` to `exprs`, returning where they sit.
fn place<'a>(v: &'a Lin, exprs: &mut Vec<&'a Expr>) -> Slots {
    let constant = exprs.len();
    exprs.push(&v.constant);
    let terms = v
        .terms
        .iter()
        .map(|(n, a)| {
            exprs.push(a);
            (*n, exprs.len() - 1)
        })
        .collect();
    Slots { constant, terms }
}

impl CompiledProgram {
    /// The compiled values at a registry point, in the order given to [`Program::compile`].
    pub fn evaluate(&mut self, point: &[f64]) -> Vec<f64> {
        self.compiled.evaluate(point, &mut self.outputs);
        let out = &self.outputs;
        let value = |s: &Slots, names: &[f64]| {
            s.terms
                .iter()
                .fold(out[s.constant], |acc, (n, k)| acc + out[*k] * names[n.0])
        };
        let mut names: Vec<f64> = Vec::with_capacity(self.names.len());
        for s in &self.names {
            let v = value(s, &names);
            names.push(v);
        }
        self.values.iter().map(|s| value(s, &names)).collect()
    }
}

/// The value of `v` at a registry point, the names' values known.
pub fn lin_value(v: &Lin, point: &[f64], names: &[f64]) -> f64 {
    v.terms.iter().fold(v.constant.eval(point), |acc, (n, a)| {
        acc + a.eval(point) * names[n.0]
    })
}
