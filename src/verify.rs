//! Exact equivalence of a hand-written result with the derived one: « is this δ(O2,2/0)·x2
//! equal to the true one? ». The decision is the canonical form's zero test, never sampling.

use crate::derivation::{Value, derive_values};
use crate::expr::{Expr, ExprError};
use crate::mechanism::Mechanism;
use crate::quantity::{NotationError, Quantity};
use std::fmt;

/// Why a verification could not be made (bad input, not a mismatch).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum VerifyError {
    /// The quantity is not in the notation.
    #[error(transparent)]
    Notation(#[from] NotationError),
    /// The quantity refers to unknown objects.
    #[error(transparent)]
    Resolve(#[from] crate::derivation::ResolveError),
    /// The expression does not parse.
    #[error(transparent)]
    Expr(#[from] ExprError),
    /// The expression has the wrong shape for the quantity.
    #[error("{0}")]
    Shape(String),
    /// No hypothesis of that name.
    #[error("unknown hypothesis `{0}`")]
    Hypothesis(String),
}

/// The verdict: equivalent or not, and the simplified difference (given − derived).
#[derive(Debug, Clone)]
pub struct Verdict {
    /// The quantity checked.
    pub quantity: String,
    /// The derived value.
    pub derived: Value,
    /// given − derived, component by component, in canonical form.
    pub difference: Vec<Expr>,
}

impl Verdict {
    /// Whether the hand-written value equals the derived one exactly.
    pub fn is_equivalent(&self) -> bool {
        self.difference.iter().all(Expr::is_zero)
    }
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_equivalent() {
            return write!(f, "{}: equivalent", self.quantity);
        }
        writeln!(f, "{}: NOT equivalent; given − derived =", self.quantity)?;
        for (k, d) in self.difference.iter().enumerate() {
            if !d.is_zero() {
                writeln!(f, "  component {}: {}", k + 1, d.presentation())?;
            }
        }
        Ok(())
    }
}

/// Splits `[a, b, c]` (possibly nested) at its top-level commas.
fn split_list(s: &str) -> Option<Vec<String>> {
    let t = s.trim();
    let inner = t.strip_prefix('[')?.strip_suffix(']')?;
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut cur = String::new();
    for c in inner.chars() {
        match c {
            '(' | '[' => depth += 1,
            ')' | ']' => depth -= 1,
            _ => {}
        }
        if c == ',' && depth == 0 {
            out.push(std::mem::take(&mut cur));
        } else {
            cur.push(c);
        }
    }
    out.push(cur);
    Some(out)
}

/// Parses the hand-written value in the shape of the derived one: a scalar; `[x, y, z]` for a
/// vector (components in the quantity's basis); `[[Rx, Ry, Rz], [Mx, My, Mz]]` for a torsor;
/// three rows for an inertia matrix.
fn parse_shaped(m: &Mechanism, derived: &Value, text: &str) -> Result<Vec<Expr>, VerifyError> {
    let n = derived.exprs().len();
    let flat: Vec<String> =
        match derived {
            Value::Scalar(_) => vec![text.to_string()],
            Value::Vector { .. } => split_list(text)
                .ok_or_else(|| VerifyError::Shape("a vector is written [x, y, z]".into()))?,
            Value::Torsor { .. } | Value::Matrix(_) => {
                let rows = split_list(text).ok_or_else(|| {
                    VerifyError::Shape(
                        "a torsor is written [[Rx, Ry, Rz], [Mx, My, Mz]], a matrix as three rows"
                            .into(),
                    )
                })?;
                let mut flat = Vec::new();
                for r in rows {
                    flat.extend(split_list(&r).ok_or_else(|| {
                        VerifyError::Shape("each row is written [a, b, c]".into())
                    })?);
                }
                flat
            }
        };
    if flat.len() != n {
        return Err(VerifyError::Shape(format!(
            "expected {n} components, got {}",
            flat.len()
        )));
    }
    flat.iter()
        .map(|s| m.reg.parse(s.trim()).map_err(VerifyError::from))
        .collect()
}

/// Compares a hand-written value with the derived value of `quantity`, optionally under a
/// hypothesis of the spec.
///
/// ```
/// use torseur::{spec, verify::verify};
/// let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let v = verify(&m, "Omega(2/0) in B2",
///     "[dot(theta2), sin(theta2)*dot(theta1), cos(theta2)*dot(theta1)]", None).unwrap();
/// assert!(v.is_equivalent());
/// let v = verify(&m, "Omega(2/0) in B2", "[dot(theta2), 0, dot(theta1)]", None).unwrap();
/// assert!(!v.is_equivalent());
/// ```
pub fn verify(
    m: &Mechanism,
    quantity: &str,
    text: &str,
    hypothesis: Option<&str>,
) -> Result<Verdict, VerifyError> {
    let q = Quantity::parse(quantity)?;
    let mut derived = derive_values(m, std::slice::from_ref(&q))?
        .pop()
        .map(|d| d.value)
        .ok_or_else(|| VerifyError::Shape("nothing derived".into()))?;
    if let Some(h) = hypothesis {
        let h = m
            .hypotheses
            .iter()
            .find(|x| x.name == h)
            .ok_or_else(|| VerifyError::Hypothesis(h.to_string()))?;
        derived = derived.under(h);
    }
    // An equation of motion may be written `lhs = rhs`, and is the same equation when
    // multiplied by a nonzero number.
    let is_equation = matches!(q.kind, crate::quantity::QuantityKind::Eom(_));
    let given = match (is_equation, text.split_once('=')) {
        (true, Some((l, r))) => vec![&m.reg.parse(l.trim())? - &m.reg.parse(r.trim())?],
        _ => parse_shaped(m, &derived, text)?,
    };
    if is_equation
        && let (Some(g), Some(d)) = (given.first(), derived.exprs().first())
        && g.constant_multiple_of(d).is_some()
    {
        return Ok(Verdict {
            quantity: q.to_string(),
            difference: vec![m.reg.zero()],
            derived,
        });
    }
    let difference = given
        .iter()
        .zip(derived.exprs())
        .map(|(g, d)| g - d)
        .collect();
    Ok(Verdict {
        quantity: q.to_string(),
        derived,
        difference,
    })
}

/// Asserts that a hand-written expression equals a derived quantity exactly; on failure the
/// message shows the simplified difference in the course's notation.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// torseur::assert_equivalent!(m, "V(G2,2/0) in B2",
///     "[-(L1 + L2*cos(theta2))*dot(theta1), 0, L2*dot(theta2)]");
/// torseur::assert_equivalent!(m, "delta(O2,2/0).x2", under "H2",
///     "(sin(theta2)*(m2*L1*L2 + (C2 - B2 + m2*L2^2)*cos(theta2)) + D2*cos(2*theta2))*dot(theta1)^2");
/// ```
#[macro_export]
macro_rules! assert_equivalent {
    ($m:expr, $q:expr, under $h:expr, $e:expr) => {{
        let v = $crate::verify::verify(&$m, $q, $e, Some($h))
            .unwrap_or_else(|err| panic!("cannot verify {}: {}", $q, err));
        assert!(v.is_equivalent(), "{}", v);
    }};
    ($m:expr, $q:expr, $e:expr) => {{
        let v = $crate::verify::verify(&$m, $q, $e, None)
            .unwrap_or_else(|err| panic!("cannot verify {}: {}", $q, err));
        assert!(v.is_equivalent(), "{}", v);
    }};
}
