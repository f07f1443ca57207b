//! Vectors kept per basis: components are stored in the basis they were born in, and moved
//! to another basis only on an explicit call (express_in) or when an operation needs it.

use crate::expr::Expr;
use crate::frame::{Axis, FrameId, Frames};
use std::collections::BTreeMap;

/// A vector as a sum of component triples, each in one basis: u = Σ_b (u_b,x x_b + u_b,y y_b +
/// u_b,z z_b).
///
/// Keeping the parts apart avoids re-expressing what a teacher writes compactly (d1 z0 + L1 y1
/// stays two short terms). Operations that mix bases move one operand into the other's basis.
#[derive(Debug, Clone, Default)]
pub struct Vector {
    parts: BTreeMap<FrameId, [Expr; 3]>,
}

impl Vector {
    /// The zero vector.
    pub fn zero() -> Self {
        Vector {
            parts: BTreeMap::new(),
        }
    }

    /// The vector with components `c` in basis `b`.
    pub fn new(b: FrameId, c: [Expr; 3]) -> Self {
        let mut v = Vector::zero();
        v.add_part(b, c);
        v
    }

    /// `coef` times the basis vector `axis` of `b`.
    pub fn along(b: FrameId, axis: Axis, coef: Expr) -> Self {
        let z = coef.zero_like();
        let mut c = [z.clone(), z.clone(), z];
        c[axis.index()] = coef;
        Vector::new(b, c)
    }

    /// The parts, by basis (deterministic order).
    pub fn parts(&self) -> impl Iterator<Item = (FrameId, &[Expr; 3])> {
        self.parts.iter().map(|(b, c)| (*b, c))
    }

    /// Adds components in basis `b`, dropping a part that becomes zero.
    pub fn add_part(&mut self, b: FrameId, c: [Expr; 3]) {
        match self.parts.get_mut(&b) {
            Some(e) => {
                for k in 0..3 {
                    e[k] = &e[k] + &c[k];
                }
                if e.iter().all(Expr::is_zero) {
                    self.parts.remove(&b);
                }
            }
            None => {
                if !c.iter().all(Expr::is_zero) {
                    self.parts.insert(b, c);
                }
            }
        }
    }

    /// u + v (no re-expression).
    pub fn add(&self, other: &Vector) -> Vector {
        let mut r = self.clone();
        for (b, c) in other.parts() {
            r.add_part(b, c.clone());
        }
        r
    }

    /// Σ vᵢ, each basis's components added along a balanced tree ([`Expr::sum`]) rather than
    /// into a running total.
    pub fn sum(
        reg: &std::rc::Rc<crate::expr::Registry>,
        vectors: impl IntoIterator<Item = Vector>,
    ) -> Vector {
        let mut by_basis: BTreeMap<FrameId, [Vec<Expr>; 3]> = BTreeMap::new();
        for v in vectors {
            for (b, c) in v.parts {
                let slot = by_basis.entry(b).or_default();
                for (k, e) in c.into_iter().enumerate() {
                    slot[k].push(e);
                }
            }
        }
        let mut r = Vector::zero();
        for (b, c) in by_basis {
            r.add_part(b, c.map(|terms| Expr::sum(reg, terms)));
        }
        r
    }

    /// u − v.
    pub fn sub(&self, other: &Vector) -> Vector {
        self.add(&other.neg())
    }

    /// −u.
    pub fn neg(&self) -> Vector {
        self.map(|e| -e)
    }

    /// k u for a scalar k.
    pub fn scale(&self, k: &Expr) -> Vector {
        let mut r = Vector::zero();
        for (b, c) in self.parts() {
            r.add_part(b, [k * &c[0], k * &c[1], k * &c[2]]);
        }
        r
    }

    /// Applies `f` to every component.
    pub fn map(&self, f: impl Fn(&Expr) -> Expr) -> Vector {
        let mut r = Vector::zero();
        for (b, c) in self.parts() {
            r.add_part(b, [f(&c[0]), f(&c[1]), f(&c[2])]);
        }
        r
    }

    /// Whether every part is zero once expressed in one basis (an exact test).
    pub fn is_zero(&self, frames: &Frames) -> bool {
        match self.parts.keys().next() {
            None => true,
            Some(b) => self.express_in(frames, *b).iter().all(Expr::is_zero),
        }
    }

    /// Components in basis `b`.
    pub fn express_in(&self, frames: &Frames, b: FrameId) -> [Expr; 3] {
        let reg = frames.registry();
        let mut acc: [Vec<Expr>; 3] = Default::default();
        for (fb, c) in self.parts() {
            for (k, w) in frames.convert(fb, b, c).into_iter().enumerate() {
                acc[k].push(w);
            }
        }
        acc.map(|terms| Expr::sum(reg, terms))
    }

    /// The same vector with a single part, in basis `b`.
    pub fn in_basis(&self, frames: &Frames, b: FrameId) -> Vector {
        Vector::new(b, self.express_in(frames, b))
    }

    /// Scalar product u · v. Each part of v is moved into the basis of each part of u.
    pub fn dot(&self, frames: &Frames, other: &Vector) -> Expr {
        let moved: Vec<(&[Expr; 3], [Expr; 3])> = self
            .parts()
            .map(|(b, u)| (u, other.express_in(frames, b)))
            .collect();
        let terms: Vec<(&Expr, &Expr, bool)> = moved
            .iter()
            .flat_map(|(u, v)| (0..3).map(move |k| (&u[k], &v[k], false)))
            .collect();
        Expr::sum_of_products(frames.registry(), &terms)
    }

    /// Vector product u ∧ v, with the result in the bases of u's parts.
    pub fn cross(&self, frames: &Frames, other: &Vector) -> Vector {
        let mut r = Vector::zero();
        if other.parts.is_empty() {
            return r;
        }
        for (b, u) in self.parts() {
            let v = other.express_in(frames, b);
            r.add_part(b, cross3(u, &v));
        }
        r
    }

    /// Time derivative in frame `r`, by the Bour formula applied to each part:
    /// d/dt|R u = Σ_b ( d/dt|B_b u_b + Ω(b/R) ∧ u_b ).
    pub fn derivative_in(&self, frames: &Frames, r: FrameId) -> Vector {
        let mut out = Vector::zero();
        for (b, u) in self.parts() {
            out.add_part(b, [u[0].dt(), u[1].dt(), u[2].dt()]);
            let part = Vector::new(b, u.clone());
            let omega = omega(frames, b, r);
            // Ω ∧ u = −(u ∧ Ω): keeps the result in u's basis.
            out = out.add(&part.cross(frames, &omega).neg());
        }
        out
    }

    /// Time derivative of the components in basis `b`, with no Bour term: the derivative in
    /// the frame of `b` of the vector re-expressed there. A second route for tests.
    pub fn derivative_by_components(&self, frames: &Frames, b: FrameId) -> Vector {
        let c = self.express_in(frames, b);
        Vector::new(b, [c[0].dt(), c[1].dt(), c[2].dt()])
    }
}

/// Ω(a/b), the angular velocity of frame a relative to frame b, composed along the tree:
/// Ω(a/b) = Σ Ω(k/parent(k)) down to a − Σ Ω(k/parent(k)) down to b.
pub fn omega(frames: &Frames, a: FrameId, b: FrameId) -> Vector {
    let mut v = Vector::zero();
    for (f, axis, rate) in frames.omega_terms(a, b) {
        v = v.add(&Vector::along(f, axis, rate));
    }
    v
}

/// u ∧ v for component triples in one basis.
pub fn cross3(u: &[Expr; 3], v: &[Expr; 3]) -> [Expr; 3] {
    let reg = u[0].registry();
    let d = |a: usize, b: usize| {
        Expr::sum_of_products(reg, &[(&u[a], &v[b], false), (&u[b], &v[a], true)])
    };
    [d(1, 2), d(2, 0), d(0, 1)]
}
