//! `Display` for what the library derives, in the notation a spec is written in: scalars in the
//! presentation form (sin² θ as `sin(theta)^2`, cos(θ2 − θ1) kept whole), vectors as sums along
//! basis vectors (`L1*dot(theta1)*x1 + 1/2*L2*dot(theta2)*y2`), torsors as their resultant and
//! moment at a point. A value names frames and points by index, so it is shown through the
//! mechanism that gave it: `value.display(&m)`, as `Path::display` in the standard library.
//!
//! What is printed reads back: a scalar through [`crate::expr::Registry::parse`], a vector
//! through [`crate::expr::Registry::parse_vector`] (the spec's own reader).
//!
//! ```
//! use torseur::{derive, Quantity};
//! let m = torseur::spec::load("derivations/double_pendule.json").unwrap();
//! let d = derive(&m, &Quantity::parse("V(G2,2/0) in B2").unwrap()).unwrap();
//! assert_eq!(
//!     d.value.display(&m).to_string(),
//!     "(L1*dot(theta1)*cos(theta2 - theta1) + 1/2*L2*dot(theta2))*x2 \
//!      - L1*dot(theta1)*sin(theta2 - theta1)*y2"
//! );
//! let t = derive(&m, &Quantity::parse("{V(2/0)}_A").unwrap()).unwrap();
//! assert_eq!(
//!     t.value.display(&m).to_string(),
//!     "{ R = dot(theta2)*z0, M(A) = L1*dot(theta1)*cos(theta1)*x0 + L1*dot(theta1)*sin(theta1)*y0 }"
//! );
//! ```

use crate::derivation::{Derivation, Value};
use crate::expr::{Expr, signed_sum};
use crate::frame::FrameId;
use crate::mechanism::Mechanism;
use crate::point::PointId;
use crate::torsor::Torsor;
use crate::vector::Vector;
use std::fmt;

/// Something the library derived, shown through its mechanism: `value.display(&m)`.
pub struct Shown<'a, T: ?Sized> {
    m: &'a Mechanism,
    item: &'a T,
}

/// A sum of `coefficient * basis vector` terms, `0` when empty.
fn vector_text(m: &Mechanism, parts: &[(FrameId, &[Expr; 3])]) -> String {
    let mut terms = Vec::new();
    for (b, c) in parts {
        for (axis, e) in ["x", "y", "z"].iter().zip(c.iter()) {
            if !e.is_zero() {
                terms.push(e.times_text(&format!("{axis}{}", m.frame_name(*b))));
            }
        }
    }
    signed_sum(&terms)
}

/// `{ R = …, M(A) = … }`.
fn torsor_text(
    m: &Mechanism,
    point: PointId,
    resultant: &[(FrameId, &[Expr; 3])],
    moment: &[(FrameId, &[Expr; 3])],
) -> String {
    format!(
        "{{ R = {}, M({}) = {} }}",
        vector_text(m, resultant),
        m.point_name(point),
        vector_text(m, moment)
    )
}

impl fmt::Display for Shown<'_, Value> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = self.m;
        match self.item {
            Value::Vector { basis, components } => {
                f.write_str(&vector_text(m, &[(*basis, components)]))
            }
            Value::Torsor {
                point,
                basis,
                resultant,
                moment,
            } => f.write_str(&torsor_text(
                m,
                *point,
                &[(*basis, resultant)],
                &[(*basis, moment)],
            )),
            // Scalars, quotients and inertia operators: the CLI's text.
            v => f.write_str(&super::value_text_in(m, v, super::TextForm::Presentation)),
        }
    }
}

impl fmt::Display for Shown<'_, Vector> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<(FrameId, &[Expr; 3])> = self.item.parts().collect();
        f.write_str(&vector_text(self.m, &parts))
    }
}

impl fmt::Display for Shown<'_, Torsor> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r: Vec<(FrameId, &[Expr; 3])> = self.item.resultant.parts().collect();
        let mo: Vec<(FrameId, &[Expr; 3])> = self.item.moment.parts().collect();
        f.write_str(&torsor_text(self.m, self.item.point, &r, &mo))
    }
}

impl fmt::Display for Shown<'_, Derivation> {
    /// Each step on a line (`label = value  [theorem]`), then `quantity = value`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for s in &self.item.steps {
            writeln!(
                f,
                "{} = {}  [{}]",
                s.label,
                s.value.display(self.m),
                s.theorem
            )?;
        }
        write!(
            f,
            "{} = {}",
            self.item.quantity,
            self.item.value.display(self.m)
        )
    }
}

impl Value {
    /// This value shown in the spec's notation (see [`crate::output::Shown`]).
    pub fn display<'a>(&'a self, m: &'a Mechanism) -> Shown<'a, Value> {
        Shown { m, item: self }
    }
}

impl Vector {
    /// This vector shown as a sum along the basis vectors it is kept in.
    ///
    /// ```
    /// use torseur::kinematics::point_velocity;
    /// let m = torseur::spec::load("derivations/double_pendule.json").unwrap();
    /// let (g2, r0) = (m.point("G2").unwrap(), m.frames().find("0").unwrap());
    /// let v = point_velocity(&m, g2, r0);
    /// assert!(v.display(&m).to_string().contains("*x1"));
    /// ```
    pub fn display<'a>(&'a self, m: &'a Mechanism) -> Shown<'a, Vector> {
        Shown { m, item: self }
    }
}

impl Torsor {
    /// This torsor shown as `{ R = …, M(A) = … }`.
    pub fn display<'a>(&'a self, m: &'a Mechanism) -> Shown<'a, Torsor> {
        Shown { m, item: self }
    }
}

impl Derivation {
    /// This derivation shown step by step, then its result.
    pub fn display<'a>(&'a self, m: &'a Mechanism) -> Shown<'a, Derivation> {
        Shown { m, item: self }
    }
}
