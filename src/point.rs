//! Points and the position tree: each point is placed from another by a vector.

use crate::frame::Frames;
use crate::vector::Vector;

/// Typed index of a point in a [`Points`] arena.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct PointId(pub(crate) usize);

/// A named point, placed from its parent point (none for the ground origin).
#[derive(Debug, Clone)]
pub struct Point {
    /// Name (`O2`, `G2`).
    pub name: String,
    /// The point it is placed from.
    pub parent: Option<PointId>,
    /// Vector from the parent to this point.
    pub offset: Vector,
    depth: usize,
}

/// Arena of points; the ground origin is `PointId(0)`.
#[derive(Debug, Clone)]
pub struct Points {
    points: Vec<Point>,
}

impl Points {
    /// A tree holding only the origin `origin` of the ground frame.
    pub fn new(origin: &str) -> Self {
        Points {
            points: vec![Point {
                name: origin.to_string(),
                parent: None,
                offset: Vector::zero(),
                depth: 0,
            }],
        }
    }

    /// The ground origin.
    pub fn origin(&self) -> PointId {
        PointId(0)
    }

    /// Adds a point at `parent + offset`.
    pub fn add(&mut self, name: &str, parent: PointId, offset: Vector) -> PointId {
        let depth = self.points[parent.0].depth + 1;
        self.points.push(Point {
            name: name.to_string(),
            parent: Some(parent),
            offset,
            depth,
        });
        PointId(self.points.len() - 1)
    }

    /// Point by id.
    pub fn get(&self, id: PointId) -> &Point {
        &self.points[id.0]
    }

    /// The points' names, the ground's origin first.
    pub fn names(&self) -> impl Iterator<Item = &str> + '_ {
        self.points.iter().map(|p| p.name.as_str())
    }

    /// Point by name.
    pub fn find(&self, name: &str) -> Option<PointId> {
        self.points.iter().position(|p| p.name == name).map(PointId)
    }

    /// All ids, origin first.
    pub fn ids(&self) -> impl Iterator<Item = PointId> + '_ {
        (0..self.points.len()).map(PointId)
    }

    /// The vector AB, summed along the tree path A → common ancestor → B (parts stay in the
    /// bases the statement used).
    pub fn vector(&self, a: PointId, b: PointId) -> Vector {
        let (mut x, mut y) = (a, b);
        let mut from_a = Vector::zero(); // ancestor -> a
        let mut to_b = Vector::zero(); // ancestor -> b
        while self.points[x.0].depth > self.points[y.0].depth {
            from_a = from_a.add(&self.points[x.0].offset);
            x = self.points[x.0].parent.expect("non-root");
        }
        while self.points[y.0].depth > self.points[x.0].depth {
            to_b = to_b.add(&self.points[y.0].offset);
            y = self.points[y.0].parent.expect("non-root");
        }
        while x != y {
            from_a = from_a.add(&self.points[x.0].offset);
            to_b = to_b.add(&self.points[y.0].offset);
            x = self.points[x.0].parent.expect("non-root");
            y = self.points[y.0].parent.expect("non-root");
        }
        to_b.sub(&from_a)
    }

    /// Whether A and B coincide at all times (AB is exactly zero).
    pub fn coincide(&self, frames: &Frames, a: PointId, b: PointId) -> bool {
        a == b || self.vector(a, b).is_zero(frames)
    }
}
