//! Exact equivalence of a hand-written result with the derived one: « is this δ(O2,2/0)·x2
//! equal to the true one? », « is ẍ cos θ + l θ̈ + g sin θ = 0 the pendulum's equation? »,
//! « does L01 + a F = −J ω θ̇2 cos θ2 hold? ». The decision is the canonical form's zero test,
//! never sampling.
//!
//! Four checks, each reported by [`Check`]:
//!
//! - **a value** (`-q Q -e EXPR`): given − derived = 0, component by component;
//! - **an equation of motion** (`-q eom(q) -e "lhs = rhs"`): with G = lhs − rhs, the engine's
//!   eom(q) = k · G for a nonzero factor k made of parameters only (a number, m L, 1/(m L),
//!   (M + m)/m; never a coordinate, a rate or an unknown: an equation multiplied by θ̇ is
//!   another equation). k is found exactly ([`Expr::parameter_ratio`]) and reported;
//! - **a relation** (`-e "lhs = rhs"`, or `-q Q -e "lhs = rhs"` with Q in the equation): the
//!   equation holds when lhs − rhs is identically zero once every quantity written in it
//!   (`delta(O2,2/0).x2`, `eom(theta)`) is replaced by its derived value and every unknown of
//!   the PFD (`X01`, `C_m`) by its solved value ([`crate::pfd::solve`]); failing that, when it
//!   is one of the engine's equations of motion up to such a factor k;
//! - **along the motions** (a relation, or a scalar value, that is neither): lhs − rhs is a
//!   combination Σ cᵢ eom(qᵢ) of the equations of motion, its coefficients holding coordinates
//!   and rates (the kinetic energy theorem, Σ q̇ᵢ eom(qᵢ)); see `motions`. Where that cannot
//!   be decided the answer is [`VerifyError::OutOfReach`], never « NOT equivalent ».
//!
//! Under a hypothesis, everything (derived values, solved unknowns, equations of motion and the
//! text given) is taken under its substitutions.

mod closure;
mod factor;
mod motions;
mod reader;
mod report;

use crate::derivation::{Value, derive_values};
use crate::expr::{Expr, ExprError, Fraction, VarRole};
use crate::mechanism::{Hypothesis, Mechanism};
use crate::pfd::{PfdError, Solution};
use crate::quantity::{NotationError, Quantity, QuantityKind};
pub use factor::Factor;
use reader::{Reader, split_list};

/// Why a verification could not be made (bad input, not a mismatch).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum VerifyError {
    /// The quantity is not in the notation.
    #[error(transparent)]
    Notation(#[from] NotationError),
    /// The quantity refers to unknown objects.
    #[error(transparent)]
    Resolve(#[from] crate::derivation::DeriveError),
    /// The expression does not parse.
    #[error(transparent)]
    Expr(#[from] ExprError),
    /// The expression has the wrong shape for the quantity.
    #[error("{0}")]
    Shape(String),
    /// No hypothesis of that name.
    #[error("unknown hypothesis `{0}`")]
    Hypothesis(String),
    /// Names the spec does not declare, all of them.
    #[error("{}{hint}", unknown_names(.names, .input))]
    UnknownNames {
        /// The names, in the order written.
        names: Vec<String>,
        /// The text given.
        input: String,
        /// ` (did you mean `theta`?)` for each name a declared one is close to
        /// (the crate's `hint`), else empty.
        hint: String,
    },
    /// The PFD, needed for an unknown or an equation of motion, cannot be solved.
    #[error("the spec's pfd: {0}")]
    Pfd(#[from] PfdError),
    /// The question is out of the checks' reach: neither « equivalent » nor « not
    /// equivalent » can be said, for the reason given.
    #[error("out of reach: {0}")]
    OutOfReach(String),
}

fn unknown_names(names: &[String], input: &str) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    let s = if names.len() > 1 { "s" } else { "" };
    format!(
        "unknown name{s} {} in `{input}`: neither a parameter, a coordinate nor an unknown of \
         the PFD of the spec",
        quoted.join(", ")
    )
}

/// Which check decided a verdict.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Check {
    /// A value: given − derived is zero, component by component.
    Value,
    /// An equation `lhs = rhs` against the equation of motion of `coordinate` (eom = 0): the
    /// same equation when eom = k · (lhs − rhs) for a nonzero factor k of parameters only.
    EquationOfMotion {
        /// The coordinate (`theta`).
        coordinate: String,
    },
    /// An equation `lhs = rhs` as a relation: it holds when lhs − rhs, every quantity replaced
    /// by its derived value and every unknown by its solved value, is identically zero.
    Relation,
    /// Not an identity, but zero along every motion: lhs − rhs (or given − derived) is
    /// Σ cᵢ eom(qᵢ), each coordinate with its coefficient cᵢ, which may hold the coordinates
    /// and the rates (the kinetic energy theorem is Σ q̇ᵢ eom(qᵢ)).
    AlongMotions {
        /// (coordinate, cᵢ), the nonzero coefficients in the order of the coordinates' names.
        combination: Vec<(String, Factor)>,
    },
    /// Not an identity, but a consequence of the loop closure at position level:
    /// lhs − rhs (or given − derived, each component) is k × one of the loop's relations as
    /// written by hand (the closure projected on a basis vector, or with one term's direction
    /// eliminated), k made of parameters.
    Closure {
        /// (the relation in words, k), one per nonzero component.
        relations: Vec<(String, Factor)>,
    },
}

/// The verdict: equivalent or not, which check decided, and the simplified difference.
#[derive(Debug, Clone)]
pub struct Verdict {
    /// The quantity checked, or the equation as written when no quantity was given.
    pub quantity: String,
    /// The equation as written, when the text was one (`lhs = rhs`).
    pub equation: Option<String>,
    /// The hypothesis everything was taken under.
    pub hypothesis: Option<String>,
    /// The check that decided (for a relation found to be an equation of motion, that one).
    pub check: Check,
    /// The derived value compared with: the quantity's value, the equation of motion's
    /// residual, 0 for a relation.
    pub derived: Value,
    /// given − derived, component by component, in canonical form. For an equation, given is
    /// lhs − rhs with its quantities and unknowns replaced; against an equation of motion with
    /// a factor k = n/d, the difference is n · given − d · derived (zero when equivalent).
    pub difference: Vec<Expr>,
    /// Against an equation of motion: when equivalent, the factor k with eom = k · (lhs − rhs);
    /// when not, the factor that makes most terms agree, used for the difference (if any).
    pub factor: Option<Factor>,
    /// The quantities and unknowns of the text replaced by their derived or solved values, in
    /// the order met.
    pub substituted: Vec<String>,
    /// The denominators typed (a nonzero polynomial in the parameters, 1 when none), one per
    /// component of `difference`: each difference is multiplied by its denominator (for an
    /// equation, lhs − rhs over a common one), so that it is a polynomial.
    pub denominators: Vec<Expr>,
    /// For a mechanism with loop closures, a verdict « not equivalent » found at a closed
    /// configuration the float backend drew: where, and the value of lhs − rhs there.
    pub counterexample: Option<String>,
}

impl Verdict {
    /// How the k-th difference is named: « difference » for a scalar, « component k + 1 »
    /// for a vector, a torsor or a matrix.
    pub fn difference_label(&self, k: usize) -> String {
        if self.difference.len() == 1 {
            "difference".to_string()
        } else {
            format!("component {}", k + 1)
        }
    }

    /// Whether the hand-written value equals the derived one exactly (for an equation: is
    /// equivalent to the engine's relation, see [`Check`]).
    pub fn is_equivalent(&self) -> bool {
        self.difference.iter().all(Expr::is_zero)
    }

    /// The quantity asked, when it is an equation of motion (`eom(q)`, `lin(eom(q))`).
    fn asked_equation_of_motion(&self) -> Option<String> {
        Quantity::parse(&self.quantity)
            .ok()
            .filter(|q| matches!(q.kind, QuantityKind::Eom(_)))
            .map(|q| q.to_string())
    }

    /// « with delta(O1,E/0).z0 replaced by its derived value and C_m by its solved value »,
    /// for the report; empty when nothing was replaced.
    fn replaced(&self) -> String {
        let (unknowns, quantities): (Vec<&String>, Vec<&String>) =
            self.substituted.iter().partition(|n| {
                Quantity::parse(n).is_ok_and(|q| matches!(q.kind, QuantityKind::Unknown(_)))
            });
        // « a, b replaced by their derived values », « c by its solved value ».
        let list = |names: &[&String], lead: &str, what: &str| {
            let joined: Vec<&str> = names.iter().map(|s| s.as_str()).collect();
            let (their, s) = if names.len() > 1 {
                ("their", "s")
            } else {
                ("its", "")
            };
            format!("{} {lead}{their} {what} value{s}", joined.join(", "))
        };
        match (quantities.is_empty(), unknowns.is_empty()) {
            (true, true) => String::new(),
            (false, true) => format!(" with {}", list(&quantities, "replaced by ", "derived")),
            (true, false) => format!(" with {}", list(&unknowns, "replaced by ", "solved")),
            (false, false) => format!(
                " with {} and {}",
                list(&quantities, "replaced by ", "derived"),
                list(&unknowns, "by ", "solved")
            ),
        }
    }
}

/// Parses the hand-written value in the shape of the derived one: a scalar; a vector as
/// `[x, y, z]` (components in the quantity's basis) or over any bases (`a*x1 + b*y2 - c*z0`);
/// a torsor as `[R, M]`, each element written either way; three rows for an inertia matrix.
/// 1 in the registry of a derived value.
fn reader_one(derived: &Value) -> Expr {
    derived.exprs()[0].registry().one()
}

fn parse_shaped(
    reader: &mut Reader,
    q: &Quantity,
    derived: &Value,
    text: &str,
) -> Result<Vec<(Expr, Expr)>, VerifyError> {
    let n = derived.fractions().len();
    let m = reader.m;
    // A vector of the torsor or the vector itself, in the quantity's basis.
    let one = || reader_one(derived);
    let vector = |reader: &mut Reader, t: &str, b| -> Result<Vec<(Expr, Expr)>, VerifyError> {
        match split_list(t) {
            Some(list) if list.len() == 3 => list
                .iter()
                .map(|s| reader.read_fraction(s.trim()))
                .collect(),
            Some(list) => Err(VerifyError::Shape(format!(
                "expected 3 components, got {}",
                list.len()
            ))),
            None => match reader.read_vector(t.trim(), b) {
                Ok(v) => Ok(v.into_iter().map(|e| (e, one())).collect()),
                // A scalar where a vector is expected: no basis vector in the text.
                Err(_)
                    if !crate::expr::bare_names(t)
                        .iter()
                        .any(|n| m.frames.basis_vector(n).is_some()) =>
                {
                    Err(VerifyError::Shape(format!(
                        "`{q}` is a vector: give [x, y, z], its components in B{}, or a sum over \
                         the basis vectors (a*x1 + b*y2), not the scalar `{}`",
                        m.frame_name(b),
                        crate::excerpt::excerpt(t.trim())
                    )))
                }
                Err(e) => Err(e),
            },
        }
    };
    let given: Vec<(Expr, Expr)> = match derived {
        Value::Scalar(_) | Value::Quotient(_) if split_list(text).is_some() => {
            return Err(VerifyError::Shape(format!(
                "`{q}` is a scalar: give one expression, not a list [x, y, z]"
            )));
        }
        Value::Scalar(_) | Value::Quotient(_) => vec![reader.read_fraction(text.trim())?],
        Value::Vector { basis, .. } => vector(reader, text, *basis)?,
        Value::Torsor { basis, .. } => {
            let rows = split_list(text).filter(|r| r.len() == 2).ok_or_else(|| {
                VerifyError::Shape(
                    "a torsor is written [R, M]: [[Rx, Ry, Rz], [Mx, My, Mz]] or over the bases, \
                     [a*x1 + b*y2, c*z0]"
                        .into(),
                )
            })?;
            let mut flat = vector(reader, &rows[0], *basis)?;
            flat.extend(vector(reader, &rows[1], *basis)?);
            flat
        }
        Value::Matrix(_) => {
            let rows = split_list(text)
                .ok_or_else(|| VerifyError::Shape("a matrix is written as three rows".into()))?;
            let mut flat = Vec::new();
            for r in rows {
                let cells = split_list(&r)
                    .ok_or_else(|| VerifyError::Shape("each row is written [a, b, c]".into()))?;
                for c in cells {
                    flat.push(reader.read_fraction(c.trim())?);
                }
            }
            flat
        }
    };
    if given.len() != n {
        return Err(VerifyError::Shape(format!(
            "expected {n} components, got {}",
            given.len()
        )));
    }
    Ok(given)
}

/// The hypothesis of that name (also for the Python module's `derive`).
pub(crate) fn hypothesis<'a>(
    m: &'a Mechanism,
    h: Option<&str>,
) -> Result<Option<&'a Hypothesis>, VerifyError> {
    h.map(|h| {
        m.hypotheses
            .iter()
            .find(|x| x.name == h)
            .ok_or_else(|| VerifyError::Hypothesis(h.to_string()))
    })
    .transpose()
}

/// `lhs = rhs` split at its one `=`; none for a text without `=`.
fn sides(text: &str) -> Result<Option<(&str, &str)>, VerifyError> {
    let Some((l, r)) = text.split_once('=') else {
        return Ok(None);
    };
    if r.contains('=') {
        return Err(VerifyError::Shape(format!(
            "`{text}`: an equation is written `lhs = rhs`, with one `=`"
        )));
    }
    for (side, s) in [("left", l), ("right", r)] {
        if s.trim().is_empty() {
            return Err(VerifyError::Shape(format!(
                "`{text}`: the {side} side of the equation is empty"
            )));
        }
    }
    Ok(Some((l.trim(), r.trim())))
}

/// Compares a hand-written value with the derived value of `quantity`, optionally under a
/// hypothesis of the spec. The text may also be an equation `lhs = rhs`: for `eom(q)`, the
/// equation of motion up to a nonzero factor of parameters; for another scalar quantity, a
/// relation that contains it ([`verify_equation`]). Quantities in the course's notation and
/// unknowns of the PFD may be written inside the text (see [`Check`]).
///
/// ```
/// use torseur::{spec, verify::verify};
/// let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let v = verify(&m, "Omega(2/0) in B2",
///     "[dot(theta2), sin(theta2)*dot(theta1), cos(theta2)*dot(theta1)]", None).unwrap();
/// assert!(v.is_equivalent());
/// let v = verify(&m, "Omega(2/0) in B2", "[dot(theta2), 0, dot(theta1)]", None).unwrap();
/// assert!(!v.is_equivalent());
/// // The motor torque is the dynamic moment of E at O1 on z0 (no other action has a moment
/// // on z0 there): a value written with a quantity.
/// assert!(verify(&m, "C_m", "delta(O1,E/0).z0", None).unwrap().is_equivalent());
/// // An action of the bilan, its links' unknowns as declared: the weight's moment at O1.
/// let w = "-m2*g*(L1 + L2*cos(theta2))*x1";
/// assert!(verify(&m, "M(O1,pes->E)", w, None).unwrap().is_equivalent());
/// assert!(verify(&m, "R(0->1)", "X01*x0 + Y01*y0 + Z01*z0", None).unwrap().is_equivalent());
/// assert!(!verify(&m, "R(0->1)", "X01*x0 + Y01*y0", None).unwrap().is_equivalent());
/// ```
pub fn verify(
    m: &Mechanism,
    quantity: &str,
    text: &str,
    hypothesis_name: Option<&str>,
) -> Result<Verdict, VerifyError> {
    let q = Quantity::parse(quantity)?;
    let h = hypothesis(m, hypothesis_name)?;
    // `X = F0/(k - M*Omega^2)` for a trial's unknown X: its value, the right side.
    let text = match (&q.kind, sides(text)?) {
        (QuantityKind::Unknown(n), Some((l, r)))
            if l.trim() == n && crate::derivation::trial_of(m, n).is_some() =>
        {
            r
        }
        _ => text,
    };
    if let Some((l, r)) = sides(text)? {
        return match &q.kind {
            QuantityKind::Eom(c) => equation_of_motion(m, &q, c, text, l, r, h),
            _ if q.is_scalar() => relation(m, Some(&q), text, l, r, h),
            _ => Err(VerifyError::Shape(format!(
                "`{q}` is not a scalar: an equation `lhs = rhs` is between scalars (write the \
                 vector alone, `a*x1 + b*y2` or [x, y, z] in its basis, or project it: `.x2`)"
            ))),
        };
    }
    let mut derived = derived_value(m, &q)?;
    if let Some(h) = h {
        derived = crate::derivation::value_under(m, &q, &derived, h);
    }
    let mut reader = Reader::new(m, h);
    // An action of the bilan holds its links' unknowns as declared: so does the text.
    reader.keep_unknowns = q.kind.action().is_some();
    let given = parse_shaped(&mut reader, &q, &derived, text)?;
    // n/d − N/D, multiplied by d D ≠ 0: n D − d N.
    // A linearisation under small parameters: one combined first order, on the text too.
    let joint = |e: Expr| match h {
        Some(h) if q.linear => crate::pfd::first_order_jointly(m, &e, h),
        _ => e,
    };
    let difference = given
        .iter()
        .zip(derived.fractions())
        .map(|((n, den), d)| joint(&(n * &d.den) - &(den * &d.num)))
        .collect();
    let denominators: Vec<Expr> = given.into_iter().map(|(_, den)| den).collect();
    // A scalar that differs from the derived one but not along the motions (dEc/dt written
    // as the power of the actions): given − derived, over d·D, is a combination of the
    // equations of motion.
    let mut check = Check::Value;
    let mut difference: Vec<Expr> = difference;
    if let ([diff], [den], [d]) = (
        difference.as_slice(),
        denominators.as_slice(),
        derived.fractions().as_slice(),
    ) && !diff.is_zero()
        && let motions::Along::Combination(combination) =
            motions::along_motions(&mut reader, diff, &(den * &d.den))?
    {
        check = Check::AlongMotions { combination };
        difference = vec![m.reg.zero()];
    }
    // A value that differs by a consequence of the loop closure (x for R cos θ + L cos φ).
    let mut counterexample = None;
    if check == Check::Value && difference.iter().any(|d| !d.is_zero()) {
        let mut relations = Vec::new();
        for d in difference.iter().filter(|d| !d.is_zero()) {
            match closure::modulo_closure(&reader, d)? {
                None => break,
                Some(closure::Closed::Proven { relation, factor }) => {
                    relations.push((relation, factor))
                }
                Some(closure::Closed::Counterexample(at)) => {
                    counterexample = Some(at);
                    break;
                }
                Some(closure::Closed::Undecided) => return Err(undecided()),
            }
        }
        if counterexample.is_none() && !relations.is_empty() {
            check = Check::Closure { relations };
            difference = vec![m.reg.zero(); difference.len()];
        }
    }
    Ok(Verdict {
        quantity: q.to_string(),
        equation: None,
        hypothesis: hypothesis_name.map(str::to_string),
        check,
        derived,
        difference,
        factor: None,
        substituted: reader.substituted,
        denominators,
        counterexample,
    })
}

/// The refusal of a question the loop closure leaves open: lhs − rhs vanished at every
/// closed configuration drawn, but is not proven zero.
fn undecided() -> VerifyError {
    VerifyError::OutOfReach(
        "the difference is not zero as a polynomial, nor a multiple of one of the loop \
         closure's relations (its projections on the basis vectors, or one term's direction \
         eliminated), yet it vanished at every closed configuration the float backend drew: \
         the question is undecided"
            .to_string(),
    )
}

/// The derived value of a quantity.
fn derived_value(m: &Mechanism, q: &Quantity) -> Result<Value, VerifyError> {
    derive_values(m, std::slice::from_ref(q))?
        .pop()
        .map(|d| d.value)
        .ok_or_else(|| VerifyError::Shape("nothing derived".into()))
}

/// `-q eom(c) -e "lhs = rhs"`: eom(c) = k · (lhs − rhs) for a nonzero factor k of parameters.
fn equation_of_motion(
    m: &Mechanism,
    q: &Quantity,
    coordinate: &str,
    text: &str,
    l: &str,
    r: &str,
    h: Option<&Hypothesis>,
) -> Result<Verdict, VerifyError> {
    let mut derived = derived_value(m, q)?;
    if let Some(h) = h {
        derived = crate::derivation::value_under(m, q, &derived, h);
    }
    let mut reader = Reader::new(m, h);
    // lhs − rhs = given / den over a common denominator (1 when none is typed).
    let (given, den) = reader.read_difference(l, r)?;
    // A linearisation under small parameters: one combined first order, on the text too.
    let given = match h {
        Some(h) if q.linear => crate::pfd::first_order_jointly(m, &given, h),
        _ => given,
    };
    let d = derived.exprs()[0].clone();
    // Not equivalent: the difference is shown with the factor that matches most terms (a
    // wrong sign in one term then shows as that term alone).
    let factor = d
        .parameter_ratio(&given)
        .or_else(|| d.closest_parameter_ratio(&given))
        .map(|(numerator, denominator)| Factor {
            numerator,
            denominator,
        });
    // k · given − derived, written n · given − d · derived for k = n/d.
    let difference = match &factor {
        Some(k) => &(&given * &k.numerator) - &(&d * &k.denominator),
        None => &given - &d,
    };
    // Against lhs − rhs itself the factor holds the denominator: eom = (n · den / d)(lhs − rhs).
    // In lowest terms: l/l, when the typed denominator is the factor's, is 1.
    let factor = factor.map(|k| {
        let numerator = &k.numerator * &den;
        match Fraction::new(numerator.clone(), k.denominator.clone()) {
            Some(q) => Factor {
                numerator: q.num,
                denominator: q.den,
            },
            None => Factor {
                numerator,
                denominator: k.denominator,
            },
        }
    });
    Ok(Verdict {
        quantity: q.to_string(),
        equation: Some(text.trim().to_string()),
        hypothesis: h.map(|h| h.name.clone()),
        check: Check::EquationOfMotion {
            coordinate: coordinate.to_string(),
        },
        derived,
        difference: vec![difference],
        factor,
        substituted: reader.substituted,
        denominators: vec![den],
        counterexample: None,
    })
}

/// Refuses a relation `text`, read by `reader`, that does not contain the quantity (or the
/// unknown) `q` it is said to be about.
fn contains(reader: &Reader, q: &Quantity, text: &str) -> Result<(), VerifyError> {
    let present = match &q.kind {
        QuantityKind::Unknown(n) if !q.linear => reader.names.contains(n),
        _ => reader.quantities.iter().any(|(x, _)| x == q),
    };
    if !present {
        return Err(VerifyError::Shape(format!(
            "`{text}` does not contain {q}: write {q} in the equation, or verify the \
             equation without --quantity"
        )));
    }
    Ok(())
}

/// A relation: lhs − rhs, quantities and unknowns replaced, is zero, or else an equation of
/// motion of the spec up to a nonzero factor of parameters. With `subject`, the equation must
/// contain that quantity.
fn relation(
    m: &Mechanism,
    subject: Option<&Quantity>,
    text: &str,
    l: &str,
    r: &str,
    h: Option<&Hypothesis>,
) -> Result<Verdict, VerifyError> {
    let mut reader = Reader::new(m, h);
    // lhs − rhs = e / den, den ≠ 0: the relation holds iff e = 0.
    let (e, den) = reader.read_difference(l, r)?;
    if let Some(q) = subject {
        contains(&reader, q, text)?;
    }
    let quantity = subject.map_or_else(|| text.trim().to_string(), Quantity::to_string);
    let denominators = vec![den.clone()];
    let verdict = |check, derived: Expr, difference, factor, substituted| Verdict {
        quantity: quantity.clone(),
        equation: Some(text.trim().to_string()),
        hypothesis: h.map(|h| h.name.clone()),
        check,
        derived: Value::Scalar(derived),
        difference: vec![difference],
        factor,
        substituted,
        denominators: denominators.clone(),
        counterexample: None,
    };
    if e.is_zero() {
        let zero = m.reg.zero();
        return Ok(verdict(
            Check::Relation,
            zero.clone(),
            zero,
            None,
            reader.substituted,
        ));
    }
    // Not an identity: is it one of the equations of motion, up to a factor?
    if m.dynamics.theorems.iter().any(|t| t.eom.is_some()) {
        let eoms = reader.solution()?.eom.clone();
        for (coordinate, eom) in eoms {
            let d = reader.under(eom);
            if let Some((numerator, denominator)) = d.parameter_ratio(&e) {
                let difference = &(&e * &numerator) - &(&d * &denominator);
                return Ok(verdict(
                    Check::EquationOfMotion { coordinate },
                    d,
                    difference,
                    Some(Factor {
                        numerator: &numerator * &den,
                        denominator,
                    }),
                    reader.substituted,
                ));
            }
        }
    }
    // Not an identity nor an equation of motion: zero along the motions?
    if let motions::Along::Combination(combination) = motions::along_motions(&mut reader, &e, &den)?
    {
        let zero = m.reg.zero();
        return Ok(verdict(
            Check::AlongMotions { combination },
            zero.clone(),
            zero,
            None,
            reader.substituted,
        ));
    }
    // Not zero along the motions: a consequence of the loop closure?
    let zero = m.reg.zero();
    match closure::modulo_closure(&reader, &e)? {
        Some(closure::Closed::Proven { relation, factor }) => {
            let relations = vec![(relation, factor)];
            Ok(verdict(
                Check::Closure { relations },
                zero.clone(),
                zero,
                None,
                reader.substituted,
            ))
        }
        Some(closure::Closed::Undecided) => Err(undecided()),
        Some(closure::Closed::Counterexample(at)) => {
            let mut v = verdict(Check::Relation, zero, e, None, reader.substituted);
            v.counterexample = Some(at);
            Ok(v)
        }
        None => Ok(verdict(Check::Relation, zero, e, None, reader.substituted)),
    }
}

/// Decides an equation `lhs = rhs` between quantities (`delta(O2,2/0).x2`, `eom(theta)`),
/// unknowns of the PFD (`X01`, `C_m`) and expressions of the spec's names: it holds when
/// lhs − rhs, every quantity replaced by its derived value and every unknown by its solved
/// value, is identically zero, or else when it is an equation of motion of the spec up to a
/// nonzero factor made of parameters, or else when it holds along every motion, a combination
/// of the equations of motion with coefficients that may hold coordinates and rates
/// (the verdict's [`Check`] says which).
///
/// ```
/// use torseur::{spec, verify::{verify_equation, Check}};
/// let m = spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// // The moment theorem on E at O1 on z0: the motor torque balances δ(O1,E/0)·z0.
/// let v = verify_equation(&m, "C_m - delta(O1,E/0).z0 = 0", None).unwrap();
/// assert!(v.is_equivalent());
/// assert_eq!(v.check, Check::Relation);
/// // Twice the pendulum's equation, read as a relation: the equation of motion of theta2.
/// let v = verify_equation(&m, "2*eom(theta2) = 0", Some("H2")).unwrap();
/// assert_eq!(v.check, Check::EquationOfMotion { coordinate: "theta2".into() });
/// assert_eq!(v.factor.unwrap().to_string(), "1/2");
/// assert!(!verify_equation(&m, "C_m = 0", None).unwrap().is_equivalent());
/// // The kinetic energy theorem: θ̇2 times the equation of motion of θ2.
/// let v = verify_equation(&m, "d/dt(Ec(E/0)) = P(ext->E/0) + Pint(E)", None).unwrap();
/// assert!(v.is_equivalent());
/// assert!(matches!(v.check, Check::AlongMotions { .. }));
/// ```
pub fn verify_equation(
    m: &Mechanism,
    text: &str,
    hypothesis_name: Option<&str>,
) -> Result<Verdict, VerifyError> {
    let h = hypothesis(m, hypothesis_name)?;
    let (l, r) = sides(text)?.ok_or_else(|| {
        VerifyError::Shape(format!(
            "`{text}` is not an equation `lhs = rhs` (a value is verified with --quantity)"
        ))
    })?;
    relation(m, None, text, l, r, h)
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
