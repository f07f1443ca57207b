//! The spec's expression syntax, parsed by hand and evaluated over dual numbers.
//!
//! This is deliberately a second implementation of the syntax (the symbolic side has its own):
//! the float backend shares no code with the exact one. Grammar:
//!
//! ```text
//! expr    := term (('+' | '-') term)*
//! term    := unary (('*' | '/') unary)*
//! unary   := ('-' | '+') unary | power
//! power   := primary ('^' integer | '^' '(' integer ')')?      integer: optional sign, digits
//! primary := number | pi | name | sin(expr) | cos(expr) | dot(coord) | ddot(coord)
//!          | '(' expr ')'
//! ```
//!
//! `pi` is π, as on the symbolic side (`cos(theta2 + pi/2)`). Any other name is a parameter,
//! a time coordinate or, where vectors are allowed, a basis vector (`x1`, `y0`, `z2`) that
//! multiplies scalars.

mod walk;

pub(crate) use walk::*;

use nalgebra::{Matrix3, Vector3};
use num_dual::DualNum;

/// The name of the constant π in the syntax: reserved, so no parameter or coordinate has it.
pub(crate) const PI_NAME: &str = "pi";

/// Numbers the evaluator runs on: `f64` or a dual number over `f64`. Both are nalgebra
/// scalars (`DualNum` brings `Clone + PartialEq + Debug + 'static` and the closed arithmetic),
/// so `Vector3<T>` and `Matrix3<T>` have their whole algebra.
pub(crate) trait Num: DualNum<f64> + Copy {}
impl<T: DualNum<f64> + Copy> Num for T {}

/// Longest expression accepted: 16 MiB, the exact side's bound (`expr::MAX_INPUT_LEN`), which
/// holds every derived result of the planar family up to 30 links and of the spatial chain up
/// to 9 solids (chain 9's longest, δ(O1,E1/0)·z0, is 9.5 MB printed, 11.6 MB canonical).
const MAX_INPUT: usize = 16 << 20;
/// Deepest nesting of parentheses and signs.
const MAX_DEPTH: usize = 128;
/// Largest power exponent, in absolute value.
const MAX_POWER: i32 = 64;
/// Most digits a number literal may have, the exact side's bound (its parser reads a literal
/// in a time quadratic in its length).
const MAX_NUMBER_DIGITS: usize = 100;

/// A parsed expression whose names are resolved to indices of the model.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Node {
    /// A number.
    Num(f64),
    /// Parameter by index.
    Param(usize),
    /// Value q of a time coordinate, by index.
    Coord(usize),
    /// q̇ (order 1) or q̈ (order 2) of a coordinate.
    Rate(usize, u8),
    /// Basis vector: frame index, axis 0..3.
    Basis(usize, usize),
    /// An unknown of the PFD (a link component, a motor torque), by index.
    Unknown(usize),
    /// The time t (only inside a phase Ω t of sin or cos, see [`validate_time`]).
    Time,
    Neg(Box<Node>),
    Add(Box<Node>, Box<Node>),
    Sub(Box<Node>, Box<Node>),
    Mul(Box<Node>, Box<Node>),
    Div(Box<Node>, Box<Node>),
    Pow(Box<Node>, i32),
    Sin(Box<Node>),
    Cos(Box<Node>),
    /// The nonnegative square root.
    Sqrt(Box<Node>),
}

/// The terms ±t₁ ± t₂ … (or the factors t₁ ×/÷ t₂ …, `true` for − or ÷) as a balanced tree,
/// so that its depth is log₂ of their number and a long result neither evaluates nor drops
/// through a recursion as deep as its length. Pairs combine as a ∘ b, a ∘⁻¹ b, b ∘⁻¹ a and
/// (a ∘ b)⁻¹; a leftover inverse at the top is applied last. The value is the left-to-right
/// one up to the rounding of a reordered sum.
fn balanced(
    mut items: Vec<(bool, Node)>,
    op: fn(Box<Node>, Box<Node>) -> Node,
    inverse_op: fn(Box<Node>, Box<Node>) -> Node,
    inverse: fn(Box<Node>) -> Node,
) -> Node {
    while items.len() > 1 {
        let mut next = Vec::with_capacity(items.len().div_ceil(2));
        let mut it = items.into_iter();
        while let Some((ia, a)) = it.next() {
            next.push(match it.next() {
                None => (ia, a),
                Some((ib, b)) => {
                    let (a, b) = (Box::new(a), Box::new(b));
                    match (ia, ib) {
                        (false, false) => (false, op(a, b)),
                        (false, true) => (false, inverse_op(a, b)),
                        (true, false) => (false, inverse_op(b, a)),
                        (true, true) => (true, op(a, b)),
                    }
                }
            });
        }
        items = next;
    }
    let (inv, node) = items.pop().expect("at least one item");
    if inv { inverse(Box::new(node)) } else { node }
}

/// What a name resolves to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Name {
    Param(usize),
    Coord(usize),
    Basis(usize, usize),
    Unknown(usize),
    Time,
    /// A named expression of the parameters, by index in the aliases given to [`parse`].
    Alias(usize),
}

/// Static type of an expression: the literal zero fits both a scalar and a vector.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    Zero,
    Scalar,
    Vector,
}

/// Parses `input`. `resolve` maps a name to what it means here, or explains why it cannot
/// appear; `rates` says whether `dot(q)` and `ddot(q)` are allowed.
pub(crate) fn parse(
    input: &str,
    resolve: &dyn Fn(&str) -> Result<Name, String>,
    rates: bool,
    aliases: &[Node],
) -> Result<Node, String> {
    if input.len() > MAX_INPUT {
        return Err(format!(
            "{} characters, longer than the {MAX_INPUT} (16 MiB) a typed expression may have",
            input.len()
        ));
    }
    if input.trim().is_empty() {
        return Err("empty expression".to_string());
    }
    if let Some(c) = input
        .chars()
        .find(|c| !(c.is_ascii_alphanumeric() || " \t\r\n+-*/^()._".contains(*c)))
    {
        return Err(format!("character `{c}` is not allowed"));
    }
    let mut p = Parser {
        s: input.as_bytes(),
        pos: 0,
        depth: 0,
        resolve,
        rates,
        aliases,
    };
    let node = p.expr()?;
    p.skip_ws();
    if p.pos < p.s.len() {
        return Err(format!(
            "unexpected `{}` at column {}",
            p.s[p.pos] as char,
            p.pos + 1
        ));
    }
    Ok(node)
}

struct Parser<'a> {
    s: &'a [u8],
    pos: usize,
    depth: usize,
    resolve: &'a dyn Fn(&str) -> Result<Name, String>,
    rates: bool,
    aliases: &'a [Node],
}

impl Parser<'_> {
    fn skip_ws(&mut self) {
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_ws();
        self.s.get(self.pos).copied()
    }

    fn expect(&mut self, c: u8) -> Result<(), String> {
        match self.peek() {
            Some(x) if x == c => {
                self.pos += 1;
                Ok(())
            }
            Some(x) => Err(format!(
                "expected `{}` at column {}, found `{}`",
                c as char,
                self.pos + 1,
                x as char
            )),
            None => Err(format!("expected `{}` at the end", c as char)),
        }
    }

    fn expr(&mut self) -> Result<Node, String> {
        let mut terms = vec![(false, self.term()?)];
        loop {
            match self.peek() {
                Some(b'+') => {
                    self.pos += 1;
                    terms.push((false, self.term()?));
                }
                Some(b'-') => {
                    self.pos += 1;
                    terms.push((true, self.term()?));
                }
                _ => return Ok(balanced(terms, Node::Add, Node::Sub, Node::Neg)),
            }
        }
    }

    fn term(&mut self) -> Result<Node, String> {
        let mut factors = vec![(false, self.unary()?)];
        loop {
            match self.peek() {
                Some(b'*') => {
                    self.pos += 1;
                    factors.push((false, self.unary()?));
                }
                Some(b'/') => {
                    self.pos += 1;
                    factors.push((true, self.unary()?));
                }
                _ => {
                    let reciprocal = |n| Node::Div(Box::new(Node::Num(1.0)), n);
                    return Ok(balanced(factors, Node::Mul, Node::Div, reciprocal));
                }
            }
        }
    }

    fn unary(&mut self) -> Result<Node, String> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(format!("nested deeper than {MAX_DEPTH}"));
        }
        let r = match self.peek() {
            Some(b'-') => {
                self.pos += 1;
                self.unary().map(|n| Node::Neg(Box::new(n)))
            }
            Some(b'+') => {
                self.pos += 1;
                self.unary()
            }
            _ => self.power(),
        };
        self.depth -= 1;
        r
    }

    fn power(&mut self) -> Result<Node, String> {
        let base = self.primary()?;
        if self.peek() != Some(b'^') {
            return Ok(base);
        }
        self.pos += 1;
        let paren = self.peek() == Some(b'(');
        if paren {
            self.pos += 1;
        }
        let mut sign = 1i64;
        match self.peek() {
            Some(b'-') => {
                sign = -1;
                self.pos += 1;
            }
            Some(b'+') => self.pos += 1,
            _ => {}
        }
        self.skip_ws();
        let start = self.pos;
        while self.pos < self.s.len() && self.s[self.pos].is_ascii_digit() {
            self.pos += 1;
        }
        let digits = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
        if digits.is_empty() {
            return Err(format!(
                "only integer powers are allowed (column {})",
                start + 1
            ));
        }
        let n: i64 = digits
            .parse::<i64>()
            .ok()
            .filter(|n| *n <= MAX_POWER as i64)
            .ok_or_else(|| format!("powers are limited to ±{MAX_POWER}"))?;
        if paren {
            self.expect(b')')?;
        }
        if self.peek() == Some(b'^') {
            return Err("write a^(b*c) as a single integer power: `^` cannot be chained".into());
        }
        Ok(Node::Pow(Box::new(base), (sign * n) as i32))
    }

    fn primary(&mut self) -> Result<Node, String> {
        let c = self
            .peek()
            .ok_or_else(|| "unexpected end of the expression".to_string())?;
        if c == b'(' {
            self.pos += 1;
            self.depth += 1;
            if self.depth > MAX_DEPTH {
                return Err(format!("nested deeper than {MAX_DEPTH}"));
            }
            let e = self.expr()?;
            self.depth -= 1;
            self.expect(b')')?;
            return Ok(e);
        }
        if c.is_ascii_digit() || c == b'.' {
            let start = self.pos;
            while self.pos < self.s.len()
                && (self.s[self.pos].is_ascii_digit() || self.s[self.pos] == b'.')
            {
                self.pos += 1;
            }
            let text = std::str::from_utf8(&self.s[start..self.pos]).unwrap_or("");
            let digits = text.bytes().filter(u8::is_ascii_digit).count();
            if digits > MAX_NUMBER_DIGITS {
                return Err(format!(
                    "a number of {digits} digits: a number has at most {MAX_NUMBER_DIGITS}"
                ));
            }
            let v: f64 = text
                .parse()
                .map_err(|_| format!("`{text}` is not a number"))?;
            if self.pos < self.s.len()
                && (self.s[self.pos].is_ascii_alphabetic() || self.s[self.pos] == b'_')
            {
                return Err(format!(
                    "`{text}` is followed by a name at column {}: write the product with `*`",
                    self.pos + 1
                ));
            }
            return Ok(Node::Num(v));
        }
        if c.is_ascii_alphabetic() || c == b'_' {
            let start = self.pos;
            while self.pos < self.s.len()
                && (self.s[self.pos].is_ascii_alphanumeric() || self.s[self.pos] == b'_')
            {
                self.pos += 1;
            }
            let name = std::str::from_utf8(&self.s[start..self.pos])
                .unwrap_or("")
                .to_string();
            if self.peek() == Some(b'(') {
                return self.call(&name);
            }
            if name == PI_NAME {
                return Ok(Node::Num(std::f64::consts::PI));
            }
            return Ok(match (self.resolve)(&name)? {
                Name::Param(i) => Node::Param(i),
                Name::Coord(i) => Node::Coord(i),
                Name::Basis(f, a) => Node::Basis(f, a),
                Name::Unknown(i) => Node::Unknown(i),
                Name::Time => Node::Time,
                Name::Alias(i) => self
                    .aliases
                    .get(i)
                    .cloned()
                    .ok_or("internal: an alias has no value")?,
            });
        }
        Err(format!(
            "unexpected `{}` at column {}",
            c as char,
            self.pos + 1
        ))
    }

    fn call(&mut self, name: &str) -> Result<Node, String> {
        self.expect(b'(')?;
        let node = match name {
            "sin" | "cos" | "sqrt" => {
                self.depth += 1;
                if self.depth > MAX_DEPTH {
                    return Err(format!("nested deeper than {MAX_DEPTH}"));
                }
                let arg = Box::new(self.expr()?);
                self.depth -= 1;
                match name {
                    "sin" => Node::Sin(arg),
                    "cos" => Node::Cos(arg),
                    _ => Node::Sqrt(arg),
                }
            }
            "dot" | "ddot" => {
                let order = if name == "dot" { 1 } else { 2 };
                if !self.rates {
                    return Err(format!(
                        "`{name}(..)` cannot appear here: only constants and coordinates can"
                    ));
                }
                let arg = match self.primary()? {
                    Node::Coord(i) => i,
                    _ => return Err(format!("`{name}(..)` takes a time coordinate")),
                };
                Node::Rate(arg, order)
            }
            other => {
                return Err(format!(
                    "unknown function `{other}` (known: sin, cos, sqrt, dot, ddot)"
                ));
            }
        };
        self.expect(b')')?;
        Ok(node)
    }
}

/// Static type of `node`, or why a scalar and a vector are mixed wrongly.
pub(crate) fn kind(node: &Node) -> Result<Kind, String> {
    use Kind::*;
    Ok(match node {
        Node::Num(v) => {
            if *v == 0.0 {
                Zero
            } else {
                Scalar
            }
        }
        Node::Param(_) | Node::Coord(_) | Node::Rate(..) | Node::Unknown(_) | Node::Time => Scalar,
        Node::Basis(..) => Vector,
        Node::Neg(a) => kind(a)?,
        Node::Add(a, b) | Node::Sub(a, b) => match (kind(a)?, kind(b)?) {
            (Zero, k) | (k, Zero) => k,
            (Scalar, Scalar) => Scalar,
            (Vector, Vector) => Vector,
            _ => {
                return Err(
                    "a sum mixes a scalar and a vector (every term of a vector holds one \
                     basis vector such as x1)"
                        .into(),
                );
            }
        },
        Node::Mul(a, b) => match (kind(a)?, kind(b)?) {
            (Vector, Vector) => return Err("a term holds two basis vectors".into()),
            (Zero, _) | (_, Zero) => Zero,
            (Scalar, Scalar) => Scalar,
            _ => Vector,
        },
        Node::Div(a, b) => match (kind(a)?, kind(b)?) {
            (_, Vector) => return Err("division by a vector".into()),
            (_, Zero) => return Err("division by zero".into()),
            (k, Scalar) => k,
        },
        Node::Pow(a, n) => match kind(a)? {
            Vector => return Err("a basis vector cannot be raised to a power".into()),
            Zero if *n <= 0 => return Err("zero raised to a non-positive power".into()),
            k => k,
        },
        Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => match kind(a)? {
            Vector => return Err("sin, cos and sqrt take a scalar".into()),
            Zero if matches!(node, Node::Sqrt(_)) => Zero,
            _ => Scalar,
        },
    })
}

/// Why the time is refused where it stands.
const TIME_ONLY_IN_PHASES: &str = "the time t enters only as a phase inside sin and cos: \
     Omega*t, Omega a parameter, times an integer";

/// Whether `node` holds the time t itself (not only coordinates).
pub(crate) fn holds_time(node: &Node) -> bool {
    match node {
        Node::Time => true,
        Node::Num(_)
        | Node::Param(_)
        | Node::Coord(_)
        | Node::Rate(..)
        | Node::Basis(..)
        | Node::Unknown(_) => false,
        Node::Neg(a) | Node::Pow(a, _) | Node::Sin(a) | Node::Cos(a) | Node::Sqrt(a) => {
            holds_time(a)
        }
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            holds_time(a) || holds_time(b)
        }
    }
}

/// Where the time may stand: only in a phase k Ω t (k an integer, Ω a parameter), a term of
/// the argument of sin or cos; `angle` says that `node` is itself an angle (a frame's
/// rotation), whose terms may then be phases too.
pub(crate) fn validate_time(node: &Node, angle: bool) -> Result<(), String> {
    if !holds_time(node) {
        return Ok(());
    }
    if angle {
        return match node {
            Node::Add(a, b) | Node::Sub(a, b) => {
                validate_time(a, true)?;
                validate_time(b, true)
            }
            Node::Neg(a) => validate_time(a, true),
            _ => phase_term(node),
        };
    }
    match node {
        Node::Sin(a) | Node::Cos(a) => validate_time(a, true),
        Node::Neg(a) | Node::Pow(a, _) | Node::Sqrt(a) => validate_time(a, false),
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            validate_time(a, false)?;
            validate_time(b, false)
        }
        _ => Err(TIME_ONLY_IN_PHASES.into()),
    }
}

/// A term k Ω t of an angle: one time, one parameter, and integer numbers as factors.
fn phase_term(node: &Node) -> Result<(), String> {
    phase(node)
        .map(|_| ())
        .ok_or_else(|| TIME_ONLY_IN_PHASES.into())
}

/// The pulsation Ω (a parameter index) and the integer k of a phase term k Ω t.
pub(crate) fn phase(node: &Node) -> Option<(usize, f64)> {
    fn factors<'a>(n: &'a Node, sign: f64, out: &mut Vec<&'a Node>) -> f64 {
        match n {
            Node::Mul(a, b) => factors(a, sign, out) * factors(b, 1.0, out),
            Node::Neg(a) => -factors(a, sign, out),
            _ => {
                out.push(n);
                sign
            }
        }
    }
    let mut fs = Vec::new();
    let mut k = factors(node, 1.0, &mut fs);
    let (mut times, mut pulsation) = (0, None);
    for f in fs {
        match f {
            Node::Time => times += 1,
            Node::Param(p) if pulsation.is_none() => pulsation = Some(*p),
            _ => {
                // A constant made of numbers: it must be a nonzero integer.
                let env = Env::<f64> {
                    params: &[],
                    coords: &[],
                    rates: &[],
                    frames: &[],
                    time: 0.0,
                };
                let mut free = std::collections::BTreeSet::new();
                params_in(f, &mut free);
                if !free.is_empty() || depends_on_time(f) {
                    return None;
                }
                let c = eval_scalar(f, &env).ok()?;
                if c == 0.0 || c.fract() != 0.0 {
                    return None;
                }
                k *= c;
            }
        }
    }
    (times == 1).then_some(())?;
    pulsation.map(|p| (p, k))
}

/// A scalar or a vector (components in the ground basis).
#[derive(Debug, Clone, Copy)]
pub(crate) enum Val<T> {
    S(T),
    V(Vector3<T>),
}

/// What names evaluate to.
pub(crate) struct Env<'a, T> {
    /// Parameter values.
    pub params: &'a [f64],
    /// Coordinate values q.
    pub coords: &'a [T],
    /// [q̇, q̈] of each coordinate.
    pub rates: &'a [[T; 2]],
    /// Orientation of each frame: column k is its k-th basis vector in ground components.
    pub frames: &'a [Matrix3<T>],
    /// The time t (a dual number of derivative 1 where rates are followed).
    pub time: T,
}

/// Evaluates a node that passed [`kind`].
pub(crate) fn eval<T: Num>(node: &Node, env: &Env<T>) -> Result<Val<T>, String> {
    let missing = || "internal: a name has no value".to_string();
    Ok(match node {
        Node::Num(v) => Val::S(T::from(*v)),
        Node::Param(i) => Val::S(T::from(*env.params.get(*i).ok_or_else(missing)?)),
        Node::Coord(i) => Val::S(*env.coords.get(*i).ok_or_else(missing)?),
        Node::Rate(i, o) => {
            let r = env.rates.get(*i).ok_or_else(missing)?;
            Val::S(if *o == 1 { r[0] } else { r[1] })
        }
        Node::Basis(f, a) => {
            let m = env.frames.get(*f).ok_or_else(missing)?;
            Val::V(m.column(*a).into_owned())
        }
        // Unknowns are replaced by numbers first ([`without_unknowns`], [`unknown_coefficient`]).
        Node::Unknown(_) => return Err("internal: an unknown of the PFD has no value here".into()),
        Node::Time => Val::S(env.time),
        Node::Neg(a) => match eval(a, env)? {
            Val::S(x) => Val::S(-x),
            Val::V(v) => Val::V(-v),
        },
        Node::Add(a, b) | Node::Sub(a, b) => {
            let sub = matches!(node, Node::Sub(..));
            match (eval(a, env)?, eval(b, env)?) {
                (Val::S(x), Val::S(y)) => Val::S(if sub { x - y } else { x + y }),
                (Val::V(u), Val::V(v)) => Val::V(if sub { u - v } else { u + v }),
                // The scalar is the literal zero (checked by `kind`).
                (Val::V(u), Val::S(_)) => Val::V(u),
                (Val::S(_), Val::V(v)) => Val::V(if sub { -v } else { v }),
            }
        }
        Node::Mul(a, b) => match (eval(a, env)?, eval(b, env)?) {
            (Val::S(x), Val::S(y)) => Val::S(x * y),
            (Val::S(x), Val::V(v)) | (Val::V(v), Val::S(x)) => Val::V(v * x),
            (Val::V(_), Val::V(_)) => return Err("a term holds two basis vectors".into()),
        },
        Node::Div(a, b) => {
            let d = match eval(b, env)? {
                Val::S(d) => d,
                Val::V(_) => return Err("division by a vector".into()),
            };
            if d.re() == 0.0 {
                return Err("division by zero at these values".into());
            }
            match eval(a, env)? {
                Val::S(x) => Val::S(x / d),
                Val::V(v) => Val::V(v / d),
            }
        }
        Node::Pow(a, n) => match eval(a, env)? {
            Val::S(x) => {
                if *n < 0 && x.re() == 0.0 {
                    return Err("zero raised to a negative power at these values".into());
                }
                Val::S(x.powi(*n))
            }
            Val::V(_) => return Err("a basis vector cannot be raised to a power".into()),
        },
        Node::Sin(a) | Node::Cos(a) => match eval(a, env)? {
            Val::S(x) => Val::S(if matches!(node, Node::Sin(_)) {
                x.sin()
            } else {
                x.cos()
            }),
            Val::V(_) => return Err("sin and cos take a scalar".into()),
        },
        Node::Sqrt(a) => match eval(a, env)? {
            Val::S(x) if x.re() < 0.0 => {
                return Err(format!("square root of {} < 0 at these values", x.re()));
            }
            Val::S(x) => Val::S(x.sqrt()),
            Val::V(_) => return Err("sqrt takes a scalar".into()),
        },
    })
}

/// Evaluates a scalar node.
pub(crate) fn eval_scalar<T: Num>(node: &Node, env: &Env<T>) -> Result<T, String> {
    match eval(node, env)? {
        Val::S(x) => Ok(x),
        Val::V(_) => Err("a vector where a scalar was expected".into()),
    }
}

/// Evaluates a vector node (the literal zero gives the zero vector).
pub(crate) fn eval_vector<T: Num>(node: &Node, env: &Env<T>) -> Result<Vector3<T>, String> {
    match eval(node, env)? {
        Val::V(v) => Ok(v),
        Val::S(x) if x.re() == 0.0 => Ok(Vector3::zeros()),
        Val::S(_) => Err("a scalar where a vector was expected".into()),
    }
}
