//! User expressions (`m2*L2^2*cos(theta2)*dot(theta1)^2`, `sin(2*theta1)`) into canonical form.
//!
//! symbolica parses the text; the tree is then walked into the polynomial of the registry.
//! sin and cos of a sum or of a multiple angle expand first (angle-addition formulas), so
//! `sin(2*theta)` and `2*sin(theta)*cos(theta)` have the same canonical form.

pub(super) use super::lexical::parse_atom;
use super::lexical::{MAX_NUMBER_DIGITS, MAX_POWER};
use super::time::{TIME, TIME_IN_PHASES, is_time, mentions_time};
use super::{CoordId, Expr, ExprError, LinearAngle, Registry};
use std::cell::Cell;
use std::rc::Rc;
use symbolica::atom::{AtomCore, AtomView, Symbol};
use symbolica::domains::rational::{Q, Rational, RationalField};
use symbolica::poly::polynomial::MultivariatePolynomial;

/// The work one expression's text may cost to read (ten times [`super::MAX_EXPANDED_TERMS`]),
/// counted over all its products: one unit per pair of terms multiplied, weighted by the machine
/// words of their coefficients. Six terms to the 25th cost 2.9·10^6; a product of single
/// terms costs nothing (its cost is linear in the text, which is bounded).
const PARSE_WORK: u128 = 10 * super::MAX_EXPANDED_TERMS;

pub(super) fn parse_scalar(reg: &Rc<Registry>, s: &str) -> Result<Expr, ExprError> {
    parse_scalar_with(reg, s, &|_| None)
}

/// [`parse_scalar`], where `names` gives the value of names the registry does not know.
pub(super) fn parse_scalar_with(
    reg: &Rc<Registry>,
    s: &str,
    names: &dyn Fn(&str) -> Option<Expr>,
) -> Result<Expr, ExprError> {
    let a = parse_atom(s)?;
    let walker = Walker::new(reg, s, names);
    let e = walker.scalar(a.as_view())?;
    walker.numbers_bounded(&e)?;
    Ok(e)
}

/// The sum of `parts`, added pairwise: adding n terms one by one to a growing sum is
/// quadratic.
pub(super) fn pairwise_sum(reg: &Rc<Registry>, mut parts: Vec<Expr>) -> Expr {
    while parts.len() > 1 {
        let mut next = Vec::with_capacity(parts.len().div_ceil(2));
        let mut it = parts.into_iter();
        while let Some(x) = it.next() {
            next.push(match it.next() {
                Some(y) => x + &y,
                None => x,
            });
        }
        parts = next;
    }
    parts.pop().unwrap_or_else(|| reg.zero())
}

pub(super) struct Walker<'a> {
    pub(super) reg: &'a Rc<Registry>,
    pub(super) input: &'a str,
    /// Values of names the registry does not know (none but in [`parse_scalar_with`]).
    pub(super) names: &'a dyn Fn(&str) -> Option<Expr>,
    /// The work spent so far on products (see [`PARSE_WORK`]).
    work: Cell<u128>,
}

impl<'a> Walker<'a> {
    pub(super) fn new(
        reg: &'a Rc<Registry>,
        input: &'a str,
        names: &'a dyn Fn(&str) -> Option<Expr>,
    ) -> Self {
        Walker {
            reg,
            input,
            names,
            work: Cell::new(0),
        }
    }

    /// Counts the work of multiplying `a` by `b`, refused once the text's whole work passes
    /// [`PARSE_WORK`]. The count weighs coefficient sizes: a 703-term polynomial with
    /// 60-digit rational coefficients to the 5th power, found by the fuzzer, forms few terms
    /// and still took 11 s.
    fn charge(&self, a: &Expr, b: &Expr) -> Result<(), ExprError> {
        if a.nterms() <= 1 && b.nterms() <= 1 {
            return Ok(());
        }
        let cost = (a.nterms() as u128 * a.coefficient_words())
            .saturating_mul(b.nterms() as u128 * b.coefficient_words());
        let work = self.work.get().saturating_add(cost);
        self.work.set(work);
        if work > PARSE_WORK {
            return Err(self.unsupported(&format!(
                "its products would take over {PARSE_WORK} term operations to expand"
            )));
        }
        Ok(())
    }

    /// What parses must print to a text that parses back, and a printed number is a literal
    /// like any typed one: a number the text computes (777777777777777777777^26) may have at
    /// most the digits of a typed number, in its numerator and in its denominator.
    pub(super) fn numbers_bounded(&self, e: &Expr) -> Result<(), ExprError> {
        let longest =
            e.p.coefficients
                .iter()
                .flat_map(|c| {
                    c.to_string()
                        .split('/')
                        .map(|part| part.bytes().filter(u8::is_ascii_digit).count())
                        .collect::<Vec<_>>()
                })
                .max()
                .unwrap_or(0);
        if longest > MAX_NUMBER_DIGITS {
            return Err(self.unsupported(&format!(
                "it computes a number of {longest} digits: a number has at most {MAX_NUMBER_DIGITS}"
            )));
        }
        Ok(())
    }

    /// The refusal of `name`, declared nowhere: with the parameter, coordinate or alias it
    /// most likely misspells.
    pub(super) fn unknown_name(&self, name: &str) -> ExprError {
        let reg = self.reg;
        let aliases: Vec<&str> = reg.aliases().map(|(a, _)| a).collect();
        let declared: Vec<&str> = (reg.parameters().iter().map(String::as_str))
            .chain(reg.coordinates().iter().map(|c| c.name.as_str()))
            .chain(aliases)
            .collect();
        let hint = crate::hint::closest(name, &declared)
            .map(|d| format!("did you mean `{d}`?"))
            .unwrap_or_default();
        ExprError::UnknownName {
            name: name.to_string(),
            input: self.input.to_string(),
            hint,
        }
    }

    pub(super) fn unsupported(&self, reason: &str) -> ExprError {
        ExprError::Unsupported {
            input: self.input.to_string(),
            reason: reason.to_string(),
        }
    }

    fn degree_too_high(&self) -> ExprError {
        self.unsupported(&format!(
            "the expanded expression would have a degree over {} in one variable",
            super::MAX_INPUT_DEGREE
        ))
    }

    fn too_many_terms(&self) -> ExprError {
        self.unsupported(&format!(
            "the expanded expression would have over {} terms",
            super::MAX_EXPANDED_TERMS
        ))
    }

    /// `a * b`, refused when a degree or the number of terms would pass the bounds.
    pub(super) fn times(&self, a: &Expr, b: &Expr) -> Result<Expr, ExprError> {
        if !a.product_fits(b, 1) {
            return Err(self.degree_too_high());
        }
        if (a.nterms() as u128) * (b.nterms() as u128) > super::MAX_EXPANDED_TERMS {
            return Err(self.too_many_terms());
        }
        self.charge(a, b)?;
        Ok(a * b)
    }

    fn number(&self, v: AtomView) -> Result<Rational, ExprError> {
        let p: MultivariatePolynomial<RationalField, u8> = v
            .try_to_polynomial(&Q, None)
            .map_err(|_| self.unsupported("only rational numbers are allowed"))?;
        if !p.is_constant() {
            return Err(self.unsupported("only rational numbers are allowed"));
        }
        Ok(p.get_constant())
    }

    /// The expression a parsed atom stands for, in the registry's variables.
    pub(super) fn scalar(&self, v: AtomView) -> Result<Expr, ExprError> {
        let reg = self.reg;
        match v {
            AtomView::Num(_) => Ok(reg.constant(self.number(v)?)),
            AtomView::Var(var) => self.variable(var.get_symbol()),
            AtomView::Add(a) => {
                // Summed pairwise: adding n terms one by one to a growing sum is quadratic
                // (a chain's equation of motion holds 10^5 terms).
                let mut parts = Vec::new();
                for t in a.iter() {
                    parts.push(self.scalar(t)?);
                }
                Ok(pairwise_sum(reg, parts))
            }
            AtomView::Mul(m) => {
                let mut acc = reg.one();
                for t in m.iter() {
                    let f = self.scalar(t)?;
                    acc = self.times(&acc, &f)?;
                }
                Ok(acc)
            }
            AtomView::Pow(p) => {
                let (base, exp) = p.get_base_exp();
                self.power(base, exp)
            }
            AtomView::Fun(f) => {
                let arg = (f.get_nargs() == 1).then(|| f.get(0));
                self.function(f.get_symbol(), arg)
            }
        }
    }

    /// A name: π, a parameter, a coordinate written as itself, an alias, or a name the
    /// caller defines; the time alone and an unknown name are refused.
    fn variable(&self, symbol: Symbol) -> Result<Expr, ExprError> {
        let reg = self.reg;
        // π: `pi` as typed, which symbolica reads as its own constant.
        if symbol == Symbol::PI {
            return Ok(reg.pi());
        }
        let name = symbol.get_stripped_name().to_string();
        if name == super::PI {
            return Ok(reg.pi());
        }
        if let Some(p) = reg.param(&name) {
            return Ok(p);
        }
        if let Some(q) = reg.coord(&name) {
            return reg.value(q).ok_or_else(|| {
                self.unsupported(&format!(
                    "the angle `{name}` is written as itself in no expression of the \
                     spec, so no result holds it: here it enters only through \
                     sin({name}) and cos({name})"
                ))
            });
        }
        if let Some(e) = reg.alias(&name) {
            return Ok(e);
        }
        if let Some(e) = (self.names)(&name) {
            return Ok(e);
        }
        if name == TIME {
            return Err(self.unsupported(TIME_IN_PHASES));
        }
        Err(self.unknown_name(&name))
    }

    /// base^exp for an integer exponent: expanded when nonnegative (each product charged
    /// first), else the inverse of a number or of a monomial of the inverted parameters.
    fn power(&self, base: AtomView, exp: AtomView) -> Result<Expr, ExprError> {
        let reg = self.reg;
        let e = self.number(exp)?;
        // `sqrt(P)`, which symbolica reads as P^(1/2), and P^(n/2): a root of the registry.
        if !e.is_integer() && (&e * &Rational::from(2)).is_integer() {
            let n = (&e * &Rational::from(2)).to_f64() as i64;
            if n < 0 {
                return Err(self.unsupported(
                    "a text does not divide by a square root: multiply above and below by its \
                     conjugate",
                ));
            }
            if reg.roots_refused.get() {
                return Err(self.unsupported(
                    "a spec's text writes no square root: its time derivative is not a \
                     polynomial (the answer key gives a closure's explicit law)",
                ));
            }
            let root = reg
                .sqrt_of(&self.scalar(base)?)
                .map_err(|why| self.unsupported(&why))?;
            return Ok(root.pow(n as u32));
        }
        if !e.is_integer() {
            return Err(self.unsupported("only integer powers are allowed"));
        }
        let n = e.to_f64() as i64;
        if n.abs() > MAX_POWER {
            return Err(self.unsupported(&format!("powers are limited to ±{MAX_POWER}")));
        }
        if n >= 0 {
            let b = self.scalar(base)?;
            if !reg.zero().product_fits(&b, 0) || !b.product_fits(&reg.zero(), n as u32) {
                return Err(self.degree_too_high());
            }
            if b.power_terms_bound(n as u32) > super::MAX_EXPANDED_TERMS {
                return Err(self.too_many_terms());
            }
            // The result may be small while the work to reach it is not: each
            // product is charged before it is done (see `charge`).
            let mut acc = reg.one();
            for _ in 0..n {
                self.charge(&acc, &b)?;
                acc = &acc * &b;
            }
            return Ok(acc);
        }
        // A negative power of a number, or of a product of the parameters the
        // mechanism divides by (their 1/p variables): the canonical form is a
        // polynomial in these.
        let b = self.scalar(base)?;
        match b.as_rational() {
            Some(r) if !r.is_zero() => Ok(reg.constant(r.inv().pow((-n) as u64))),
            Some(_) => Err(self.unsupported("division by zero")),
            None => {
                let inv = b.monomial_inverse().map_err(|why| self.unsupported(&why))?;
                if !inv.product_fits(&reg.zero(), (-n) as u32) {
                    return Err(self.degree_too_high());
                }
                Ok(inv.pow((-n) as u32))
            }
        }
    }

    /// sin, cos, dot or ddot of its one argument (`None` when there is not exactly one).
    fn function(&self, s: Symbol, arg: Option<AtomView>) -> Result<Expr, ExprError> {
        let reg = self.reg;
        let name = s.get_stripped_name();
        let Some(arg) = arg else {
            return Err(self.unsupported(&format!("`{name}` takes one argument")));
        };
        if s == Symbol::SIN || s == Symbol::COS {
            let (c, sn) = self.trig(arg)?;
            return Ok(if s == Symbol::SIN { sn } else { c });
        }
        let order = match name {
            "dot" => 1,
            "ddot" => 2,
            _ => {
                return Err(self.unsupported(&format!(
                    "unknown function `{name}` (known: sin, cos, sqrt, dot, ddot)"
                )));
            }
        };
        let AtomView::Var(qv) = arg else {
            return Err(self.unsupported(&format!("{name}() takes a coordinate name")));
        };
        let qn = super::words::typed_name(qv.get_symbol());
        let qn = qn.as_str();
        let q = reg.coord(qn).ok_or_else(|| {
            self.unsupported(&format!("{name}({qn}): `{qn}` is not a coordinate"))
        })?;
        Ok(reg.rate(q, order))
    }

    /// (cos a, sin a) of an angle a = Σ nᵢ qᵢ + k π/2, by the angle-addition formulas.
    fn trig(&self, arg: AtomView) -> Result<(Expr, Expr), ExprError> {
        let (terms, quarter_turns) = self.linear_angle(arg)?;
        Ok(cos_sin(self.reg, &terms, quarter_turns))
    }

    /// An angle as Σ nᵢ aᵢ (angle coordinates and constant angle parameters, integer nᵢ, like
    /// terms combined) and k π/2.
    fn linear_angle(&self, arg: AtomView) -> Result<(Vec<(CoordId, i64)>, i64), ExprError> {
        let lin = self.linear(arg)?;
        if !lin.constant.is_zero() {
            return Err(self.unsupported(NOT_QUARTER_TURNS));
        }
        let mut out: Vec<(CoordId, i64)> = Vec::new();
        for (q, coef) in lin.coords {
            if !coef.is_integer() {
                return Err(self.unsupported(
                    "an angle takes integer multiples of the angle coordinates, the angle \
                     parameters and the phases Omega*t (declare a pulsation Omega/2 as a \
                     parameter of its own)",
                ));
            }
            if coef.is_zero() {
                continue;
            }
            if coef.to_f64().abs() > MAX_POWER as f64 {
                return Err(self.unsupported("multiple angle too large"));
            }
            out.push((q, coef.to_f64() as i64));
        }
        // Exact values for multiples of π/2 only.
        let twice = &lin.pi * &Rational::new(2, 1);
        if !twice.is_integer() || twice.to_f64().abs() > 1e15 {
            return Err(self.unsupported(NOT_QUARTER_TURNS));
        }
        Ok((out, twice.to_f64() as i64))
    }

    /// The tree of an angle read as a linear form, walked without expanding it: symbolica's
    /// `expand` of `cos((m*(m + L)^4 + L)^63)` ran for minutes before the argument could be
    /// refused (found by the expression fuzzer). Only a number may multiply or be raised to a
    /// power.
    fn linear(&self, v: AtomView) -> Result<Linear, ExprError> {
        let nonlinear = || self.unsupported("sin and cos take a linear angle");
        match v {
            AtomView::Num(_) => Ok(Linear::constant(self.number(v)?)),
            AtomView::Var(var) => {
                let sym = var.get_symbol();
                let name = sym.get_stripped_name();
                let mut lin = Linear::constant(Rational::zero());
                if sym == Symbol::PI || name == "pi" {
                    lin.pi = Rational::one();
                    return Ok(lin);
                }
                if name == TIME {
                    return Err(self.unsupported(TIME_IN_PHASES));
                }
                match self.reg.angle(name) {
                    Some(q) => {
                        lin.coords.push((q, Rational::one()));
                        Ok(lin)
                    }
                    None if self.reg.param(name).is_none()
                        && self.reg.coord(name).is_none()
                        && self.reg.alias(name).is_none() =>
                    {
                        Err(self.unknown_name(name))
                    }
                    None => Err(self.unsupported(&format!(
                        "`{name}` is not an angle: an angle is an angle coordinate or a \
                         parameter declared with \"kind\": \"angle\""
                    ))),
                }
            }
            AtomView::Add(a) => {
                let mut sum = Linear::constant(Rational::zero());
                for t in a.iter() {
                    sum.add(self.linear(t)?);
                }
                Ok(sum)
            }
            AtomView::Mul(m) if m.iter().any(|f| mentions_time(f)) => {
                // Ω t, times numbers: the phase of the pulsation Ω.
                let mut pulsation = None;
                let mut k = Rational::one();
                for f in m.iter() {
                    match f {
                        _ if is_time(f) => {}
                        _ if mentions_time(f) => return Err(self.unsupported(TIME_IN_PHASES)),
                        AtomView::Var(v) if pulsation.is_none() => {
                            pulsation = Some(super::words::typed_name(v.get_symbol()))
                        }
                        _ => match self.linear(f).ok().and_then(|l| l.as_constant()) {
                            Some(c) => k = &k * &c,
                            None => return Err(self.unsupported(TIME_IN_PHASES)),
                        },
                    }
                }
                let w = pulsation.ok_or_else(|| self.unsupported(TIME_IN_PHASES))?;
                let q = self
                    .reg
                    .phase(&w)
                    .ok_or_else(|| self.unsupported(TIME_IN_PHASES))?;
                let mut lin = Linear::constant(Rational::zero());
                lin.coords.push((q, k));
                Ok(lin)
            }
            AtomView::Mul(m) => {
                let mut product = Linear::constant(Rational::one());
                for f in m.iter() {
                    let f = self.linear(f)?;
                    product = match (product.as_constant(), f.as_constant()) {
                        (Some(c), _) => f.scaled(&c),
                        (None, Some(c)) => product.scaled(&c),
                        (None, None) => return Err(nonlinear()),
                    };
                }
                Ok(product)
            }
            AtomView::Pow(p) => {
                let (base, exp) = p.get_base_exp();
                let base = self.linear(base)?.as_constant().ok_or_else(nonlinear)?;
                let e = self.number(exp)?;
                if !e.is_integer() {
                    return Err(nonlinear());
                }
                let n = e.to_f64() as i64;
                if n < 0 && base.is_zero() {
                    return Err(self.unsupported("division by zero"));
                }
                let power = if n >= 0 {
                    base.pow(n as u64)
                } else {
                    base.inv().pow((-n) as u64)
                };
                Ok(Linear::constant(power))
            }
            _ => Err(nonlinear()),
        }
    }
}

/// A linear form Σ cᵢ aᵢ + p π + c read from an angle's tree.
struct Linear {
    coords: Vec<(CoordId, Rational)>,
    pi: Rational,
    constant: Rational,
}

impl Linear {
    fn constant(c: Rational) -> Self {
        Linear {
            coords: Vec::new(),
            pi: Rational::zero(),
            constant: c,
        }
    }

    /// The number this form is, if it holds no angle and no π.
    fn as_constant(&self) -> Option<Rational> {
        (self.pi.is_zero() && self.coords.iter().all(|(_, c)| c.is_zero()))
            .then(|| self.constant.clone())
    }

    fn scaled(mut self, k: &Rational) -> Self {
        for (_, c) in &mut self.coords {
            *c = &*c * k;
        }
        self.pi = &self.pi * k;
        self.constant = &self.constant * k;
        self
    }

    fn add(&mut self, other: Linear) {
        for (q, c) in other.coords {
            match self.coords.iter_mut().find(|(x, _)| *x == q) {
                Some(slot) => slot.1 = &slot.1 + &c,
                None => self.coords.push((q, c)),
            }
        }
        self.pi = &self.pi + &other.pi;
        self.constant = &self.constant + &other.constant;
    }
}

/// Why a constant angle is refused.
const NOT_QUARTER_TURNS: &str = "a constant angle written with numbers must be a multiple of \
     pi/2 (the only ones whose cos and sin are exact rationals: sin(pi/3) is not): declare any \
     other constant angle as a parameter with \"kind\": \"angle\"";

/// (cos a, sin a) of a = Σ nᵢ aᵢ + k π/2.
pub(super) fn cos_sin(
    reg: &Rc<Registry>,
    terms: &[(CoordId, i64)],
    quarter_turns: i64,
) -> (Expr, Expr) {
    let (mut c, mut s) = (reg.one(), reg.zero());
    for &(q, n) in terms {
        let (cn, sn) = multiple_angle(reg, q, n);
        let nc = &(&c * &cn) - &(&s * &sn);
        let ns = &(&s * &cn) + &(&c * &sn);
        c = nc;
        s = ns;
    }
    match quarter_turns.rem_euclid(4) {
        0 => (c, s),
        1 => (-s, c),
        2 => (-c, -s),
        _ => (s, -c),
    }
}

/// Reads an angle `Σ nᵢ aᵢ + k π/2` (see [`Registry::parse_angle`]).
pub(super) fn parse_angle(reg: &Rc<Registry>, s: &str) -> Result<LinearAngle, ExprError> {
    let a = parse_atom(s)?;
    let w = Walker::new(reg, s, &|_| None);
    let (terms, quarter_turns) = w.linear_angle(a.as_view())?;
    let (cos, sin) = cos_sin(reg, &terms, quarter_turns);
    Ok(LinearAngle {
        terms,
        quarter_turns,
        cos,
        sin,
    })
}

/// (cos nq, sin nq) by repeated angle addition (de Moivre), for any integer n.
fn multiple_angle(reg: &Rc<Registry>, q: CoordId, n: i64) -> (Expr, Expr) {
    let (c1, s1) = (reg.cos(q), reg.sin(q));
    let (mut c, mut s) = (reg.one(), reg.zero());
    for _ in 0..n.unsigned_abs() {
        let nc = &(&c * &c1) - &(&s * &s1);
        let ns = &(&s * &c1) + &(&c * &s1);
        c = nc;
        s = ns;
    }
    if n < 0 { (c, -s) } else { (c, s) }
}
