//! A number written as an expression of other numbers (`atan(omega^2*a/g)`, `m*g/k`), for the
//! values file of `eval`: a relative equilibrium is often given by an arctangent or a quotient
//! of the parameters. symbolica parses the text; the tree is evaluated in f64.

use super::ExprError;
use super::lexical::{names_in, parse_checked, validate_chars_with};
use symbolica::atom::{AtomCore, AtomView, Symbol};
use symbolica::domains::rational::Q;

/// The value of `text`, its names read through `names` (the numbers already known); the
/// functions are sin, cos, tan, atan (or arctan), asin, acos, sqrt, exp, log (natural) and
/// the constant `pi`. A name without a value is reported by name.
///
/// ```
/// use torseur::expr::evaluate_number;
/// let v = |n: &str| match n { "omega" => Some(3.0), "a" => Some(0.1), "g" => Some(9.81), _ => None };
/// let beta = evaluate_number("atan(omega^2*a/g)", &v).unwrap();
/// assert!((beta - (0.9_f64 / 9.81).atan()).abs() < 1e-15);
/// assert!((evaluate_number("2*pi/omega", &v).unwrap() - 2.0 * std::f64::consts::PI / 3.0).abs() < 1e-15);
/// assert!(evaluate_number("k/2", &v).unwrap_err().to_string().contains("`k`"));
/// ```
pub fn evaluate_number(text: &str, names: &dyn Fn(&str) -> Option<f64>) -> Result<f64, ExprError> {
    validate_chars_with(text, FUNCTIONS).map_err(|reason| ExprError::Parse {
        input: text.to_string(),
        reason,
    })?;
    // Each function renamed before symbolica reads it, so that none of its own (exp, log,
    // sqrt) evaluates or rewrites the text: the walk below computes every one.
    let atom = parse_checked(&renamed(text))?;
    let unsupported = |reason: String| ExprError::Unsupported {
        input: text.to_string(),
        reason,
    };
    let v = walk(atom.as_view(), names, &unsupported)?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(unsupported(format!("its value is {v}")))
    }
}

/// The functions of a number's text.
const FUNCTIONS: &[&str] = &[
    "sin", "cos", "tan", "atan", "arctan", "asin", "arcsin", "acos", "arccos", "sqrt", "exp",
    "log", "ln",
];

/// The prefix of a renamed function.
const PREFIX: &str = "fn_";

/// The text with each function name `f(` written `fn_f(`.
fn renamed(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    let mut at = 0;
    for (start, end, called) in names_in(text) {
        if called && FUNCTIONS.contains(&&text[start..end]) {
            out.push_str(&text[at..start]);
            out.push_str(PREFIX);
            at = start;
        }
    }
    out.push_str(&text[at..]);
    out
}

fn walk(
    v: AtomView,
    names: &dyn Fn(&str) -> Option<f64>,
    unsupported: &dyn Fn(String) -> ExprError,
) -> Result<f64, ExprError> {
    let rec = |x: AtomView| walk(x, names, unsupported);
    match v {
        AtomView::Num(_) => v
            .try_to_polynomial::<_, u8>(&Q, None)
            .ok()
            .filter(|p| p.is_constant())
            .map(|p| p.get_constant().to_f64())
            .ok_or_else(|| unsupported("only rational numbers are allowed".into())),
        AtomView::Var(x) => {
            let s = x.get_symbol();
            let name = s.get_stripped_name();
            if s == Symbol::PI || name == "pi" {
                return Ok(std::f64::consts::PI);
            }
            names(name).ok_or_else(|| unsupported(format!("`{name}` has no value here")))
        }
        AtomView::Add(a) => a.iter().try_fold(0.0, |acc, t| Ok(acc + rec(t)?)),
        AtomView::Mul(m) => m.iter().try_fold(1.0, |acc, t| Ok(acc * rec(t)?)),
        AtomView::Pow(p) => {
            let (b, e) = p.get_base_exp();
            Ok(rec(b)?.powf(rec(e)?))
        }
        AtomView::Fun(f) => {
            let s = f.get_symbol();
            let name = s.get_stripped_name();
            let name = name.strip_prefix(PREFIX).unwrap_or(name);
            if f.get_nargs() != 1 {
                return Err(unsupported(format!("`{name}` takes one argument")));
            }
            let x = rec(f.get(0))?;
            Ok(match name {
                "sin" => x.sin(),
                "cos" => x.cos(),
                "tan" => x.tan(),
                "atan" | "arctan" => x.atan(),
                "asin" | "arcsin" => x.asin(),
                "acos" | "arccos" => x.acos(),
                "sqrt" => x.sqrt(),
                "exp" => x.exp(),
                "log" | "ln" => x.ln(),
                _ => return Err(unsupported(format!("unknown function `{name}`"))),
            })
        }
    }
}
