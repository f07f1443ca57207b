//! The time derivative of a quantity: d/dt(Q) of a scalar (d/dt(Ec(E/0))), the total time
//! derivative of its value; [d/dt Q]_R of a vector (d/dt(sigma(A,2/0))|0), the vector's own
//! derivative in the frame R, each basis vector turning by Ω(b/R) ∧ (the Bour formula,
//! [`Vector::derivative_in`]).

use super::{Derivation, DeriveError, Step, StepKind, Value, vec_value};
use crate::frame::FrameId;
use crate::mechanism::Mechanism;
use crate::quantity::Quantity;
use crate::vector::Vector;

/// What a derivative finds: a scalar's derivative, or a vector's, still to be written in the
/// basis asked or projected.
pub(super) enum Derived {
    Scalar(crate::expr::Expr),
    Vector(Vector),
}

/// The frame `r` of [d/dt Q]_r, by name: a solid's frame or a frame (`R0` is named `0`).
pub(super) fn frame(m: &Mechanism, q: &Quantity, r: &str) -> Result<FrameId, DeriveError> {
    m.frame_of(r).ok_or_else(|| {
        let named = r
            .strip_prefix('R')
            .filter(|n| m.frame_of(n).is_some())
            .map(|n| format!(" (the frame R{n} is written |{n})"))
            .unwrap_or_default();
        DeriveError::new(q, format!("unknown frame `{r}`{named}"))
    })
}

/// Derives d/dt(`of`) (in the frame `r` for a vector), the inner quantity's steps and its
/// value recorded first, then the derivative's; intermediate vectors in basis `b`.
pub(super) fn derive(
    m: &Mechanism,
    q: &Quantity,
    of: &Quantity,
    r: Option<FrameId>,
    b: FrameId,
    steps: &mut Vec<Step>,
) -> Result<Derived, DeriveError> {
    // A vector is derived in the basis asked, so that its steps are written there.
    let inner = match (r, &of.projection) {
        (Some(_), None) => of.with_basis(m.frame_name(b)),
        _ => of.clone(),
    };
    let d: Derivation = super::derive_unbounded(m, &inner)?;
    steps.extend(d.steps);
    let label = inner.to_string();
    let last_is_it = steps
        .last()
        .is_some_and(|s| s.value.exprs() == d.value.exprs() && same_kind(&s.kind, &inner));
    if !last_is_it {
        steps.push(Step {
            label: label.clone(),
            kind: match &inner.projection {
                Some(p) => StepKind::Projected(inner.kind.clone(), p.clone()),
                None => StepKind::Quantity(inner.kind.clone()),
            },
            theorem: "la quantité dérivée".into(),
            value: d.value.clone(),
        });
    }
    match (r, d.value) {
        (None, Value::Scalar(e)) => Ok(Derived::Scalar(e.dt())),
        (Some(r), Value::Vector { basis, components }) => {
            let v = Vector::new(basis, components).derivative_in(&m.frames, r);
            let rn = m.frame_name(r).to_string();
            steps.push(Step {
                label: format!("d/dt({})|{rn}", of.kind),
                kind: StepKind::Derivative(of.kind.clone(), rn),
                theorem: "dérivation vectorielle (formule de Bour)".into(),
                value: vec_value(m, &v, b),
            });
            Ok(Derived::Vector(v))
        }
        _ => Err(DeriveError::new(
            q,
            format!("{of}: d/dt takes a scalar, or a vector in a frame"),
        )),
    }
}

/// Whether a step computes the quantity `q` itself (its kind, and its projection if any).
fn same_kind(k: &StepKind, q: &Quantity) -> bool {
    match (k, &q.projection) {
        (StepKind::Quantity(x), None) => *x == q.kind,
        (StepKind::Projected(x, p), Some(pq)) => *x == q.kind && p == pq,
        _ => false,
    }
}
