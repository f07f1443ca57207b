//! The reader of the printed math into the engine's syntax, and the checks that prove a
//! display equal to the value it claims to show (see `printed/mod.rs`).

use std::collections::HashMap;
use torseur::derivation::Value;
use torseur::expr::Expr;
use torseur::mechanism::Mechanism;

use super::macros::{Tok, greek, is_cmd, tokenize};

/// Reads LaTeX math into the engine's syntax. Basis vectors are replaced by what `basis`
/// says (`1` for the one whose component is wanted, `0` for the others): the printed vector
/// is linear in its basis vectors.
struct Reader<'a> {
    t: &'a [Tok],
    i: usize,
    names: &'a HashMap<String, String>,
    basis: &'a dyn Fn(char, &str) -> &'static str,
    seen: Vec<(char, String)>,
    /// Basis vectors the spec names as its statement does, as printed (`u`, `i1`): (axis,
    /// frame), read off the spec's `ground_basis` and `frames[].basis`.
    vectors: &'a HashMap<String, (char, String)>,
}

impl Reader<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.t.get(self.i)
    }

    fn next(&mut self) -> Result<Tok, String> {
        let t = self.t.get(self.i).cloned().ok_or("unexpected end")?;
        self.i += 1;
        Ok(t)
    }

    fn expect(&mut self, t: Tok) -> Result<(), String> {
        let got = self.next()?;
        if got == t {
            Ok(())
        } else {
            Err(format!(
                "expected {t:?}, found {got:?} at token {}",
                self.i - 1
            ))
        }
    }

    /// Spacing that means nothing (or an implicit product).
    fn skip_space(&mut self) {
        while let Some(Tok::Cmd(c)) = self.peek() {
            if [",", ";", "!", "quad", "qquad", " "].contains(&c.as_str()) {
                self.i += 1;
            } else {
                break;
            }
        }
    }

    /// The raw text of a `{…}` group of letters and digits (a subscript, a \mathrm name).
    fn raw_group(&mut self) -> Result<String, String> {
        let mut s = String::new();
        match self.next()? {
            Tok::Sym('{') => loop {
                match self.next()? {
                    Tok::Sym('}') => break,
                    Tok::Letter(c) | Tok::Digit(c) => s.push(c),
                    Tok::Cmd(c) if greek(&c).is_some() => {
                        s.push_str(&greek(&c).unwrap_or_default())
                    }
                    t => return Err(format!("unexpected {t:?} in a name")),
                }
            },
            Tok::Letter(c) | Tok::Digit(c) => s.push(c),
            t => return Err(format!("unexpected {t:?} after `_`")),
        }
        Ok(s)
    }

    /// A subscript, if one follows.
    fn subscript(&mut self) -> Result<String, String> {
        if self.peek() == Some(&Tok::Sym('_')) {
            self.i += 1;
            self.raw_group()
        } else {
            Ok(String::new())
        }
    }

    fn identifier(&self, written: &str) -> Result<String, String> {
        self.names
            .get(written)
            .cloned()
            .ok_or_else(|| format!("`{written}` names nothing of the spec"))
    }

    /// A name's head: a Latin letter, a Greek letter, or `\mathrm{…}`.
    fn head(&mut self) -> Result<String, String> {
        match self.next()? {
            Tok::Letter(c) => Ok(c.to_string()),
            Tok::Cmd(c) if greek(&c).is_some() => Ok(greek(&c).unwrap_or_default()),
            Tok::Cmd(c) if c == "mathrm" => self.raw_group(),
            t => Err(format!("expected a name, found {t:?}")),
        }
    }

    fn name(&mut self) -> Result<String, String> {
        let h = self.head()?;
        let s = self.subscript()?;
        self.identifier(&format!("{h}{s}"))
    }

    fn is_end(&self) -> bool {
        match self.peek() {
            None => true,
            Some(Tok::Sym(c)) => matches!(c, '}' | ')' | ']' | '&' | '+' | '-' | '='),
            Some(Tok::Cmd(c)) if c == "Big" => matches!(
                self.t.get(self.i + 1),
                Some(&Tok::Sym(')')) | Some(&Tok::Sym(']'))
            ),
            Some(Tok::Cmd(c)) => matches!(c.as_str(), "right" | "\\" | "end"),
            _ => false,
        }
    }

    /// sum := [±] product (± product)*
    fn sum(&mut self) -> Result<String, String> {
        let mut out = String::new();
        loop {
            self.skip_space();
            let sign = match self.peek() {
                Some(Tok::Sym('+')) => {
                    self.i += 1;
                    "+"
                }
                Some(Tok::Sym('-')) => {
                    self.i += 1;
                    "-"
                }
                _ if out.is_empty() => "+",
                _ => break,
            };
            self.skip_space();
            let p = self.product()?;
            out.push_str(&format!(" {sign} ({p})"));
        }
        if out.is_empty() {
            return Err(format!("empty sum at token {}", self.i));
        }
        Ok(format!("({out})"))
    }

    fn product(&mut self) -> Result<String, String> {
        let mut fs = Vec::new();
        loop {
            self.skip_space();
            if self.is_end() {
                break;
            }
            fs.push(self.power()?);
        }
        if fs.is_empty() {
            return Err(format!("empty product at token {}", self.i));
        }
        Ok(fs.join("*"))
    }

    fn exponent(&mut self) -> Result<Option<String>, String> {
        if self.peek() != Some(&Tok::Sym('^')) {
            return Ok(None);
        }
        self.i += 1;
        Ok(Some(self.raw_group()?))
    }

    fn power(&mut self) -> Result<String, String> {
        let base = self.primary()?;
        Ok(match self.exponent()? {
            Some(k) => format!("({base})^{k}"),
            None => base,
        })
    }

    /// A group closed by the given closing tokens.
    fn closed(&mut self, close: &[Tok]) -> Result<String, String> {
        let s = self.sum()?;
        for t in close {
            self.expect(t.clone())?;
        }
        Ok(s)
    }

    fn primary(&mut self) -> Result<String, String> {
        match self.peek().cloned().ok_or("unexpected end")? {
            Tok::Digit(_) => {
                let mut n = String::new();
                while let Some(Tok::Digit(d)) = self.peek() {
                    n.push(*d);
                    self.i += 1;
                }
                Ok(n)
            }
            Tok::Letter(_) => self.name(),
            Tok::Sym('(') => {
                self.i += 1;
                self.closed(&[Tok::Sym(')')])
            }
            Tok::Sym('{') => {
                self.i += 1;
                self.closed(&[Tok::Sym('}')])
            }
            Tok::Cmd(c) => {
                self.i += 1;
                match c.as_str() {
                    // ( … ) or [ … ], closed by the same size.
                    "left" | "Big" => {
                        let close = match self.next()? {
                            Tok::Sym('(') => ')',
                            Tok::Sym('[') => ']',
                            t => return Err(format!("\\{c} followed by {t:?}")),
                        };
                        let size = if c == "left" { "right" } else { "Big" };
                        self.closed(&[Tok::Cmd(size.into()), Tok::Sym(close)])
                    }
                    "frac" => {
                        self.expect(Tok::Sym('{'))?;
                        let n = self.closed(&[Tok::Sym('}')])?;
                        self.expect(Tok::Sym('{'))?;
                        let d = self.closed(&[Tok::Sym('}')])?;
                        Ok(format!("({n}/{d})"))
                    }
                    // \sqrt{P}: the engine's sqrt(P), one of the mechanism's roots.
                    "sqrt" => {
                        self.expect(Tok::Sym('{'))?;
                        let radicand = self.closed(&[Tok::Sym('}')])?;
                        Ok(format!("sqrt({radicand})"))
                    }
                    "sin" | "cos" => {
                        let k = self.exponent()?;
                        self.skip_space();
                        let arg = match self.peek() {
                            Some(Tok::Sym('(')) | Some(Tok::Sym('{')) => self.primary()?,
                            Some(Tok::Cmd(c)) if c == "left" => self.primary()?,
                            // \sin 2\theta_{2}: a multiple of an angle.
                            Some(Tok::Digit(_)) => {
                                let mut n = String::new();
                                while let Some(Tok::Digit(d)) = self.peek() {
                                    n.push(*d);
                                    self.i += 1;
                                }
                                format!("{n}*{}", self.name()?)
                            }
                            _ => self.name()?,
                        };
                        let f = format!("{c}({arg})");
                        Ok(match k {
                            Some(k) => format!("{f}^{k}"),
                            None => f,
                        })
                    }
                    "dot" | "ddot" | "dddot" => {
                        let h = match self.next()? {
                            Tok::Sym('{') => {
                                let h = self.head()?;
                                self.expect(Tok::Sym('}'))?;
                                h
                            }
                            t => return Err(format!("\\{c} of {t:?}")),
                        };
                        let s = self.subscript()?;
                        let q = self.identifier(&format!("{h}{s}"))?;
                        Ok(format!("{c}({q})"))
                    }
                    "vec" => {
                        let axis = self.raw_group()?;
                        if axis == "0" {
                            return Ok("0".into());
                        }
                        let sub = self.subscript()?;
                        let (a, f) = match self.vectors.get(&format!("{axis}{sub}")) {
                            Some((a, f)) => (*a, f.clone()),
                            None => (axis.chars().next().ok_or("empty \\vec")?, sub),
                        };
                        self.seen.push((a, f.clone()));
                        Ok((self.basis)(a, &f).to_string())
                    }
                    g if greek(g).is_some() => {
                        self.i -= 1;
                        self.name()
                    }
                    "mathrm" => {
                        self.i -= 1;
                        self.name()
                    }
                    other => Err(format!("unknown command \\{other}")),
                }
            }
            t => Err(format!("unexpected {t:?} at token {}", self.i)),
        }
    }
}

/// The equations of an `align*` body: (left side, right side) as tokens; `&\phantom{=}`
/// rows continue the previous right side. Rows inside environments are kept whole.
pub(crate) fn equations(body: &str) -> Vec<(Vec<Tok>, Vec<Tok>)> {
    let toks = tokenize(body);
    let mut rows: Vec<Vec<Tok>> = vec![vec![]];
    let mut env = 0;
    for t in toks {
        match &t {
            Tok::Cmd(c) if c == "begin" => env += 1,
            Tok::Cmd(c) if c == "end" => env -= 1,
            Tok::Cmd(c) if c == "\\" && env == 0 => {
                rows.push(vec![]);
                continue;
            }
            _ => {}
        }
        rows.last_mut().unwrap().push(t);
    }
    let mut eqs: Vec<(Vec<Tok>, Vec<Tok>)> = Vec::new();
    // A wide left side on a row of its own (`&lhs`), continued by rows `&\quad …` (an
    // equation of motion's dynamic side), its `&= …` on the next row.
    let mut alone: Option<Vec<Tok>> = None;
    for r in rows {
        let more = [Tok::Sym('&'), Tok::Cmd("quad".into())];
        if let (Some(lhs), true) = (alone.as_mut(), r.starts_with(&more)) {
            lhs.extend_from_slice(&r[1..]);
            continue;
        }
        if let Some(lhs) = alone.take() {
            assert!(
                r.starts_with(&[Tok::Sym('&'), Tok::Sym('=')]),
                "a left side alone is followed by its `&=`: {r:?}"
            );
            eqs.push((lhs, r[2..].to_vec()));
            continue;
        }
        if r.first() == Some(&Tok::Sym('&')) && !r.contains(&Tok::Sym('=')) {
            alone = Some(r[1..].to_vec());
            continue;
        }
        let phantom = [
            Tok::Sym('&'),
            Tok::Cmd("phantom".into()),
            Tok::Sym('{'),
            Tok::Sym('='),
            Tok::Sym('}'),
        ];
        if r.starts_with(&phantom) {
            eqs.last_mut()
                .expect("a continuation row follows an equation")
                .1
                .extend_from_slice(&r[phantom.len()..]);
            continue;
        }
        let at = (0..r.len().saturating_sub(1))
            .find(|&k| r[k] == Tok::Sym('&') && r[k + 1] == Tok::Sym('='))
            .unwrap_or_else(|| panic!("a row without `&=`: {r:?}"));
        eqs.push((r[..at].to_vec(), r[at + 2..].to_vec()));
    }
    eqs
}

pub(crate) struct Ctx<'a> {
    pub(crate) m: &'a Mechanism,
    names: HashMap<String, String>,
    vectors: HashMap<String, (char, String)>,
}

impl Ctx<'_> {
    pub(crate) fn new(m: &Mechanism) -> Ctx<'_> {
        let mut names = HashMap::new();
        let ids = m
            .reg()
            .parameters()
            .iter()
            .chain(m.reg().unknowns())
            .cloned()
            .chain(m.spec().aliases.iter().map(|a| a.name.clone()))
            .chain(m.reg().coordinates().iter().map(|c| match c.phase() {
                // A phase is printed Ω t: the time is then a name of its own.
                Some(_) => "t".to_string(),
                None => c.name.clone(),
            }))
            // \pi is the constant π, `pi` in the engine's syntax (no spec may take the name).
            .chain(std::iter::once("pi".to_string()));
        for n in ids {
            let written: String = n.chars().filter(|&c| c != '_').collect();
            if let Some(other) = names.insert(written.clone(), n.clone())
                && other != n
            {
                panic!("`{n}` and `{other}` print alike ({written})");
            }
        }
        let mut vectors = HashMap::new();
        let spec = &m.spec();
        let given = std::iter::once((&spec.ground, &spec.ground_basis))
            .chain(spec.frames.iter().map(|f| (&f.name, &f.basis)));
        for (frame, names) in given {
            for (k, n) in names.iter().flatten().enumerate() {
                let written: String = n.chars().filter(|&c| c != '_').collect();
                vectors.insert(written, (['x', 'y', 'z'][k], frame.clone()));
            }
        }
        Ctx { m, names, vectors }
    }

    /// A scalar read from tokens, with basis vectors set by `basis`.
    fn read(
        &self,
        t: &[Tok],
        basis: &dyn Fn(char, &str) -> &'static str,
    ) -> Result<(Expr, Vec<(char, String)>), String> {
        let mut r = Reader {
            t,
            i: 0,
            names: &self.names,
            basis,
            seen: vec![],
            vectors: &self.vectors,
        };
        let text = r.sum()?;
        if r.i != t.len() {
            return Err(format!("trailing {:?}", &t[r.i..]));
        }
        let e = self
            .m
            .reg()
            .parse(&text)
            .map_err(|e| format!("{text}: {e}"))?;
        Ok((e, r.seen))
    }

    /// A scalar that may be a quotient, as (numerator, denominator) read by the engine's
    /// fraction parser.
    pub(super) fn quotient(&self, t: &[Tok]) -> Result<(Expr, Expr), String> {
        let mut r = Reader {
            t,
            i: 0,
            names: &self.names,
            basis: &|_, _| "0",
            seen: vec![],
            vectors: &self.vectors,
        };
        let text = r.sum()?;
        if r.i != t.len() || !r.seen.is_empty() {
            return Err(format!("not a scalar: {text}"));
        }
        self.m
            .reg()
            .parse_fraction_with(&text, &|_| None)
            .map_err(|e| format!("{text}: {e}"))
    }

    pub(crate) fn scalar(&self, t: &[Tok]) -> Result<Expr, String> {
        let (e, seen) = self.read(t, &|_, _| "0")?;
        if !seen.is_empty() {
            return Err(format!("a scalar printed with basis vectors {seen:?}"));
        }
        Ok(e)
    }

    /// The components of a vector printed as a sum over the basis vectors of `frame`.
    fn vector(&self, t: &[Tok], frame: &str) -> Result<[Expr; 3], String> {
        let axes = ['x', 'y', 'z'];
        let mut out: Vec<Expr> = Vec::new();
        for &a in &axes {
            let f = frame.to_string();
            let pick = move |ax: char, fr: &str| if ax == a && fr == f { "1" } else { "0" };
            let (e, seen) = self.read(t, &pick)?;
            if let Some(bad) = seen.iter().find(|(_, fr)| fr != frame) {
                return Err(format!("basis vector {bad:?} outside the basis {frame}"));
            }
            out.push(e);
        }
        Ok([out[0].clone(), out[1].clone(), out[2].clone()])
    }
}

impl Ctx<'_> {
    /// A vector printed over the basis vectors of any frames, expressed in the ground basis.
    pub(super) fn any_basis(&self, t: &[Tok]) -> Result<[Expr; 3], String> {
        let (_, seen) = self.read(t, &|_, _| "0")?;
        let mut v = torseur::vector::Vector::zero();
        let mut done: Vec<(char, String)> = Vec::new();
        for (a, f) in seen {
            if done.contains(&(a, f.clone())) {
                continue;
            }
            let g = f.clone();
            let pick = move |ax: char, fr: &str| if ax == a && fr == g { "1" } else { "0" };
            let (c, _) = self.read(t, &pick)?;
            let frame = self.m.frames().find(&f).ok_or(format!("no frame {f}"))?;
            let axis = match a {
                'x' => torseur::frame::Axis::X,
                'y' => torseur::frame::Axis::Y,
                _ => torseur::frame::Axis::Z,
            };
            v = v.add(&torseur::vector::Vector::along(frame, axis, c));
            done.push((a, f));
        }
        Ok(v.express_in(self.m.frames(), self.m.frames().ground()))
    }
}

/// Splits an environment's content (`\begin{env}{spec}? … \end{env}`) starting at `t[0]`
/// into rows of cells, and returns what follows it.
fn environment(t: &[Tok]) -> (Vec<Vec<Vec<Tok>>>, &[Tok]) {
    assert!(is_cmd(t.first(), "begin"), "expected \\begin: {t:?}");
    // Skip `{name}` and, for an array, its column spec.
    let mut i = 1;
    let mut groups = 0;
    while groups < 2 {
        if t[i] == Tok::Sym('}') {
            groups += 1;
            if !matches!(t.get(i + 1), Some(Tok::Sym('{'))) {
                break;
            }
        }
        i += 1;
    }
    i += 1;
    let mut rows = vec![vec![vec![]]];
    let mut depth = 0;
    while !(depth == 0 && is_cmd(t.get(i), "end")) {
        match &t[i] {
            Tok::Cmd(c) if c == "begin" => depth += 1,
            Tok::Cmd(c) if c == "end" => depth -= 1,
            _ => {}
        }
        match &t[i] {
            Tok::Cmd(c) if c == "\\" && depth == 0 => rows.push(vec![vec![]]),
            Tok::Sym('&') if depth == 0 => rows.last_mut().unwrap().push(vec![]),
            tok => rows
                .last_mut()
                .unwrap()
                .last_mut()
                .unwrap()
                .push(tok.clone()),
        }
        i += 1;
    }
    // `\end{name}`
    i += 1;
    while t[i] != Tok::Sym('}') {
        i += 1;
    }
    (rows, &t[i + 1..])
}

/// The frame named by a `_{\mathcal{B}_{2}}` subscript.
fn basis_subscript(t: &[Tok]) -> String {
    // The frame of the last `\mathcal{B}_{…}` in the subscript (`_{O_{2},\,\mathcal{B}_{1}}`
    // names the point first); empty when there is none.
    let at = (0..t.len()).rev().find(|&k| {
        t[k] == Tok::Cmd("mathcal".into())
            && t.get(k + 2) == Some(&Tok::Letter('B'))
            && t.get(k + 4) == Some(&Tok::Sym('_'))
    });
    let Some(k) = at else {
        return String::new();
    };
    let mut out = String::new();
    let mut depth = 0;
    for x in &t[k + 5..] {
        match x {
            Tok::Sym('{') => depth += 1,
            Tok::Sym('}') => {
                depth -= 1;
                if depth <= 0 {
                    break;
                }
            }
            Tok::Letter(c) | Tok::Digit(c) => {
                out.push(*c);
                if depth == 0 {
                    break;
                }
            }
            _ => {}
        }
    }
    out
}

/// Proves that a displayed formula equals its value; returns what is wrong otherwise.
pub(super) fn prove(ctx: &Ctx, latex: &str, v: &Value) -> Result<(), String> {
    let m = ctx.m;
    let eqs = equations(latex);
    let same = |what: &str, got: &Expr, want: &Expr| -> Result<(), String> {
        if got == want {
            Ok(())
        } else {
            Err(format!("{what}: printed {got}, engine {want}"))
        }
    };
    match v {
        Value::Scalar(e) => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a scalar", eqs.len()));
            };
            same("scalar", &ctx.scalar(rhs)?, e)
        }
        Value::Quotient(q) => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a quotient", eqs.len()));
            };
            // n / d = N / D, cross-multiplied.
            let (n, d) = ctx.quotient(rhs)?;
            same("quotient", &(&n * &q.den), &(&q.num * &d))
        }
        Value::Vector { basis, components } => {
            let [(_, rhs)] = eqs.as_slice() else {
                return Err(format!("{} equations for a vector", eqs.len()));
            };
            let f = m.frame_name(*basis);
            let got = if is_cmd(rhs.first(), "begin") {
                let (rows, rest) = environment(rhs);
                if basis_subscript(rest) != f {
                    return Err(format!("column in basis {rest:?}, engine {f}"));
                }
                let c: Result<Vec<Expr>, String> = rows.iter().map(|r| ctx.scalar(&r[0])).collect();
                c?
            } else {
                ctx.vector(rhs, f)?.to_vec()
            };
            for k in 0..3 {
                same(&format!("component {k}"), &got[k], &components[k])?;
            }
            Ok(())
        }
        Value::Matrix(i) => {
            let (_, rhs) = &eqs[0];
            let (rows, rest) = environment(rhs);
            let f = m.frame_name(i.basis);
            if basis_subscript(rest) != f {
                return Err(format!("matrix in basis {rest:?}, engine {f}"));
            }
            for r in 0..3 {
                for c in 0..3 {
                    let cell = &rows[r][c];
                    let def = eqs[1..].iter().find(|(l, _)| l == cell);
                    let got = ctx.scalar(def.map(|d| &d.1[..]).unwrap_or(cell))?;
                    same(&format!("entry ({r},{c})"), &got, &i.matrix[r][c])?;
                }
            }
            Ok(())
        }
        Value::Torsor {
            basis,
            resultant,
            moment,
            ..
        } => {
            let f = m.frame_name(*basis);
            let (res, mom) = if eqs.len() == 2 {
                (ctx.vector(&eqs[0].1, f)?, ctx.vector(&eqs[1].1, f)?)
            } else {
                let rhs = &eqs[0].1;
                // \left\{ \begin{array}{c|c} … \end{array} \right\}_{O,\,B}, or the zero
                // torsor \left\{ 0 \right\}.
                assert!(is_cmd(rhs.first(), "left"), "torsor opens with \\left\\{{");
                if rhs.get(2) == Some(&Tok::Digit('0')) && is_cmd(rhs.get(3), "right") {
                    let zero = || -> [Expr; 3] {
                        [0, 1, 2].map(|_| ctx.scalar(&[Tok::Digit('0')]).unwrap())
                    };
                    let z = zero();
                    for k in 0..3 {
                        same(&format!("resultant {k}"), &z[k], &resultant[k])?;
                        same(&format!("moment {k}"), &z[k], &moment[k])?;
                    }
                    return Ok(());
                }
                let (rows, rest) = environment(&rhs[2..]);
                let b = basis_subscript(rest);
                if b != f {
                    return Err(format!("torsor in basis {b}, engine {f}"));
                }
                let col = |k: usize| -> Result<[Expr; 3], String> {
                    Ok([
                        ctx.scalar(&rows[0][k])?,
                        ctx.scalar(&rows[1][k])?,
                        ctx.scalar(&rows[2][k])?,
                    ])
                };
                (col(0)?, col(1)?)
            };
            for k in 0..3 {
                same(&format!("resultant {k}"), &res[k], &resultant[k])?;
                same(&format!("moment {k}"), &mom[k], &moment[k])?;
            }
            Ok(())
        }
    }
}

/// The bodies of the `align*` displays of a document (boxed in `\\TResultat` or not), in order.
pub(super) fn align_bodies(tex: &str) -> Vec<&str> {
    let kinds = [
        ("\\begin{align*}\n", "\n\\end{align*}"),
        ("\\TResultat{\n", "\n}\n"),
    ];
    let mut out = Vec::new();
    let mut rest = tex;
    loop {
        let next = kinds
            .iter()
            .filter_map(|(o, c)| rest.find(o).map(|a| (a, *o, *c)))
            .min_by_key(|x| x.0);
        let Some((a, open, close)) = next else { break };
        let from = &rest[a + open.len()..];
        let b = from.find(close).expect("display closes");
        out.push(&from[..b]);
        rest = &from[b..];
    }
    out
}

/// An equality display: its left side (first equation's right side, or the left side of a
/// single equation) and its right side.
pub(super) fn prove_equality(ctx: &Ctx, latex: &str, l: &Value, r: &Value) -> Result<(), String> {
    let eqs = equations(latex);
    let (Value::Scalar(l), Value::Scalar(r)) = (l, r) else {
        return Err("an equality of non-scalars".into());
    };
    let (a, b) = match eqs.as_slice() {
        [(_, a), (_, b)] => (ctx.scalar(a)?, ctx.scalar(b)?),
        [(a, b)] => (ctx.scalar(a)?, ctx.scalar(b)?),
        _ => return Err(format!("{} equations in an equality", eqs.len())),
    };
    if &a != l {
        return Err(format!("left side printed {a}, engine {l}"));
    }
    if &b != r {
        return Err(format!("right side printed {b}, engine {r}"));
    }
    Ok(())
}
