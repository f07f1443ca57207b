//! Expressions in LaTeX: the presentation form ([`crate::expr::Presentation`]) with the
//! course's typography (\sin^{2}\theta_{2}, \sin 2\theta_{2}, \cos(\theta_{2} - \theta_{1}),
//! brackets around a sum that holds a parenthesised one), and its line breaking.

use super::{name, width};
use crate::expr::{
    Angle, CoordId, Expr, Factor, Form, Fraction, Leaf, Presentation, Product, Registry, Trig,
};

/// A rate: \dot{\theta}_{1}, the accent on the head, the subscript after.
pub(super) fn rate(reg: &Registry, q: CoordId, order: u8) -> String {
    rate_of(&reg.coord_info(q).name, order)
}

/// The rate of order `order` of the coordinate named `coordinate`, as [`rate`] writes it.
pub(super) fn rate_of(coordinate: &str, order: u8) -> String {
    let n = name(coordinate);
    let (head, sub) = match n.split_once("_{") {
        Some((h, s)) => (h.to_string(), format!("_{{{s}")),
        None => (n.clone(), String::new()),
    };
    let acc = ["\\dot", "\\ddot", "\\dddot"][(order.clamp(1, 3) - 1) as usize];
    format!("{acc}{{{head}}}{sub}")
}

/// An angle: (text, whether it needs parentheses after sin or cos).
fn angle(reg: &Registry, a: &Angle) -> (String, bool) {
    // The first coefficient's sign is not written: only normalised angles are printed.
    assert!(
        a.terms().first().is_some_and(|t| t.1 > 0),
        "an angle is printed normalised"
    );
    let mut s = String::new();
    let mut phase = false;
    for (i, &(q, k)) in a.terms().iter().enumerate() {
        // A phase is written Ω t, and always in parentheses: cos(Ω t).
        phase |= reg.coord_info(q).phase().is_some();
        let n = super::coordinate(reg, q);
        let body = if k.abs() == 1 {
            n
        } else {
            format!("{}{n}", k.abs())
        };
        s.push_str(match (i, k < 0) {
            (0, _) => "",
            (_, true) => " - ",
            (_, false) => " + ",
        });
        s.push_str(&body);
    }
    (s, phase || a.terms().len() > 1)
}

/// cos q or sin q as a leaf.
fn trig_leaf(q: CoordId, f: Trig) -> Leaf {
    match f {
        Trig::Cos => Leaf::Cos(Angle::of(q)),
        Trig::Sin => Leaf::Sin(Angle::of(q)),
    }
}

/// A leaf raised to `k`: \cos^{2}\theta_{2}, L_{2}^{2}, \dot{\theta}_{1}^{2}.
fn leaf(reg: &Registry, l: &Leaf, k: u8) -> String {
    let pw = |b: String| {
        if k == 1 { b } else { format!("{b}^{{{k}}}") }
    };
    match l {
        Leaf::Param(p) => pw(name(reg.scalar_name(*p))),
        // Alone (a factor of a product broken across lines); a whole product writes its
        // inverses below one line (see `product`).
        Leaf::Inverse(p) => format!("\\frac{{1}}{{{}}}", pw(name(reg.scalar_name(*p)))),
        Leaf::Reciprocal(q, f) => format!("\\frac{{1}}{{{}}}", leaf(reg, &trig_leaf(*q, *f), k)),
        Leaf::Value(q) => pw(name(&reg.coord_info(*q).name)),
        Leaf::Root(r) => pw(format!("\\sqrt{{{}}}", expr(&reg.radicand_of(*r)))),
        Leaf::Rate(q, o) => pw(rate(reg, *q, *o)),
        Leaf::Cos(a) | Leaf::Sin(a) => {
            let fun = if matches!(l, Leaf::Cos(_)) {
                "\\cos"
            } else {
                "\\sin"
            };
            let fun = if k == 1 {
                fun.to_string()
            } else {
                format!("{fun}^{{{k}}}")
            };
            let (arg, compound) = angle(reg, a);
            if compound {
                format!("{fun}\\left({arg}\\right)")
            } else if arg.starts_with('\\') {
                format!("{fun}{arg}")
            } else {
                // `\sin q_{1}`, `\sin 2\theta`: a space, never `\sinq`.
                format!("{fun} {arg}")
            }
        }
    }
}

/// Whether a sum holds a parenthesised sum (it is then written in brackets).
fn nests(f: &Form) -> bool {
    f.terms
        .iter()
        .any(|p| p.factors.iter().any(|(f, _)| matches!(f, Factor::Sum(_))))
}

fn sum_factor(reg: &Registry, s: &Form, k: u8) -> String {
    let (l, r) = if nests(s) {
        ("\\left[", "\\right]")
    } else {
        ("\\left(", "\\right)")
    };
    let body = format!("{l}{}{r}", form(reg, s));
    if k == 1 {
        body
    } else {
        format!("{body}^{{{k}}}")
    }
}

fn coefficient(p: &Product) -> Option<String> {
    let s = p.coef.abs().to_string();
    match s.split_once('/') {
        Some((n, d)) => Some(format!("\\frac{{{n}}}{{{d}}}")),
        None if s == "1" => None,
        None => Some(s),
    }
}

/// The factors of a product, in reading order, each as LaTeX.
fn factors(reg: &Registry, p: &Product) -> Vec<(bool, String)> {
    let mut out: Vec<(bool, String)> = coefficient(p).into_iter().map(|c| (false, c)).collect();
    // What the product divides by, below one line at its end: \frac{1}{L_{2}\,\sin\psi}.
    let mut below = Vec::new();
    for (f, k) in p.ordered(reg) {
        match f {
            Factor::Leaf(Leaf::Inverse(q)) => below.push(leaf(reg, &Leaf::Param(*q), *k)),
            Factor::Leaf(Leaf::Reciprocal(q, t)) => below.push(leaf(reg, &trig_leaf(*q, *t), *k)),
            Factor::Leaf(l) => out.push((false, leaf(reg, l, *k))),
            Factor::Sum(s) => out.push((true, sum_factor(reg, s, *k))),
        }
    }
    if !below.is_empty() {
        out.push((false, format!("\\frac{{1}}{{{}}}", below.join("\\,"))));
    }
    out
}

/// A product without its sign; the parameters it divides by below one line with the
/// coefficient's denominator: \frac{m\,g\,\sin\beta}{k}, \frac{m}{2\,k\,l}.
fn product(reg: &Registry, p: &Product) -> String {
    let divides = p
        .factors
        .iter()
        .any(|(f, _)| matches!(f, Factor::Leaf(Leaf::Inverse(_) | Leaf::Reciprocal(..))));
    if !divides {
        let f: Vec<String> = factors(reg, p).into_iter().map(|x| x.1).collect();
        return if f.is_empty() {
            "1".to_string()
        } else {
            f.join("\\,")
        };
    }
    let (n, d) = crate::expr::num_den(&p.coef);
    let mut top: Vec<String> = Vec::new();
    let mut below: Vec<String> = Vec::new();
    if n != "1" {
        top.push(n);
    }
    if d != "1" {
        below.push(d);
    }
    let ordered = p.ordered(reg);
    // A whole sum over one line needs no bracket: \frac{a + b}{\sin\psi}.
    let alone = top.is_empty()
        && ordered
            .iter()
            .filter(|(f, _)| !matches!(f, Factor::Leaf(Leaf::Inverse(_) | Leaf::Reciprocal(..))))
            .count()
            == 1;
    for (f, k) in ordered {
        match f {
            Factor::Leaf(Leaf::Inverse(q)) => below.push(leaf(reg, &Leaf::Param(*q), *k)),
            Factor::Leaf(Leaf::Reciprocal(q, f)) => below.push(leaf(reg, &trig_leaf(*q, *f), *k)),
            Factor::Leaf(l) => top.push(leaf(reg, l, *k)),
            Factor::Sum(s) if alone && *k == 1 => top.push(form(reg, s)),
            Factor::Sum(s) => top.push(sum_factor(reg, s, *k)),
        }
    }
    let top = if top.is_empty() {
        "1".to_string()
    } else {
        top.join("\\,")
    };
    format!("\\frac{{{top}}}{{{}}}", below.join("\\,"))
}

fn sign(neg: bool, first: bool) -> &'static str {
    match (first, neg) {
        (true, true) => "-",
        (true, false) => "",
        (false, true) => " - ",
        (false, false) => " + ",
    }
}

/// A sum of products.
pub(crate) fn form(reg: &Registry, f: &Form) -> String {
    if f.terms.is_empty() {
        return "0".to_string();
    }
    let mut o = String::new();
    for (i, p) in f.terms.iter().enumerate() {
        o.push_str(sign(p.coef.is_negative(), i == 0));
        o.push_str(&product(reg, p));
    }
    o
}

/// The presentation form in LaTeX.
///
/// ```
/// use torseur::expr::Registry;
/// use torseur::spec::wire::CoordinateKind;
/// let reg = Registry::new(&["m".into(), "L".into()], &[("theta1".into(), CoordinateKind::Angle)]).unwrap();
/// let e = reg.parse("m*L^2*ddot(theta1) - m*L*sin(theta1)*dot(theta1)^2").unwrap();
/// assert_eq!(torseur::latex::expr(&e),
///     "m\\,L\\,\\left(L\\,\\ddot{\\theta}_{1} - \\dot{\\theta}_{1}^{2}\\,\\sin\\theta_{1}\\right)");
/// ```
pub fn expr(e: &Expr) -> String {
    let p = e.presentation();
    form(p.registry(), p.form())
}

/// A quotient in LaTeX, `\frac{num}{den}`, a minus of a one-term numerator in front.
///
/// ```
/// use torseur::expr::{Fraction, Registry};
/// let reg = Registry::new(&["D".into(), "L".into(), "w".into()], &[]).unwrap();
/// let q = Fraction::new(reg.parse("-D*w^2").unwrap(), reg.parse("L").unwrap()).unwrap();
/// assert_eq!(torseur::latex::fraction(&q), "-\\frac{D\\,w^{2}}{L}");
/// ```
pub fn fraction(q: &Fraction) -> String {
    if q.is_whole() {
        return expr(&q.num);
    }
    let den = expr(&q.den);
    if q.reads_negative() {
        return format!("-\\frac{{{}}}{{{den}}}", expr(&-&q.num));
    }
    format!("\\frac{{{}}}{{{den}}}", expr(&q.num))
}

/// Unbreakable pieces of the presentation form: each product, or, for a product too wide
/// for a line, its factors before its widest sum, then that sum's terms one by one (`\Big(`
/// and `\Big)` may span lines, `\left(` and `\right)` may not), then the factors after.
fn pieces(p: &Presentation, max: usize) -> Vec<String> {
    let reg = p.registry();
    let mut out = Vec::new();
    for (i, t) in p.form().terms.iter().enumerate() {
        out.extend(product_pieces(
            reg,
            t,
            sign(t.coef.is_negative(), i == 0),
            max,
        ));
    }
    if out.is_empty() {
        out.push("0".to_string());
    }
    out
}

/// A signed product as pieces of lines: whole when it fits, else broken inside its widest
/// sum, each term of that sum broken again when it is still too wide.
fn product_pieces(reg: &Registry, t: &Product, s: &str, max: usize) -> Vec<String> {
    let whole = product(reg, t);
    let fs = factors(reg, t);
    let widest = fs
        .iter()
        .enumerate()
        .filter(|(_, f)| f.0)
        .max_by_key(|(_, f)| width(&f.1))
        .map(|(k, _)| k);
    let Some(k) = widest.filter(|_| width(&whole) > max) else {
        return vec![format!("{s}{whole}")];
    };
    let sum = t
        .ordered(reg)
        .into_iter()
        .filter_map(|(f, e)| match f {
            Factor::Sum(s) => Some((s, *e)),
            Factor::Leaf(_) => None,
        })
        .max_by_key(|(s, e)| width(&sum_factor(reg, s, *e)))
        .expect("a sum factor");
    let (l, r) = if nests(sum.0) {
        ("\\Big[", "\\Big]")
    } else {
        ("\\Big(", "\\Big)")
    };
    let mut head = s.to_string();
    for b in &fs[..k] {
        head.push_str(&b.1);
        head.push_str("\\,");
    }
    head.push_str(l);
    let mut tail = r.to_string();
    if sum.1 > 1 {
        tail.push_str(&format!("^{{{}}}", sum.1));
    }
    for a in &fs[k + 1..] {
        tail.push_str("\\,");
        tail.push_str(&a.1);
    }
    let mut out: Vec<String> = Vec::new();
    for (j, q) in sum.0.terms.iter().enumerate() {
        out.extend(product_pieces(
            reg,
            q,
            sign(q.coef.is_negative(), j == 0),
            max,
        ));
    }
    if let Some(first) = out.first_mut() {
        first.insert_str(0, &head);
    }
    if let Some(last) = out.last_mut() {
        last.push_str(&tail);
    }
    out
}

/// Lines of at most `max` width (as far as single terms allow), broken between products
/// and, when a product is too wide, inside its widest sum.
pub fn expr_lines(e: &Expr, max: usize) -> Vec<String> {
    presentation_lines(&e.presentation(), max)
}

/// [`expr_lines`] of a presentation already computed.
pub(crate) fn presentation_lines(p: &Presentation, max: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut cur = String::new();
    for piece in pieces(p, max) {
        if !cur.is_empty() && width(&cur) + width(&piece) > max {
            lines.push(std::mem::take(&mut cur));
        }
        cur.push_str(&piece);
    }
    lines.push(cur);
    lines
}
