//! Frames: a tree of elementary rotations, base changes along the tree, and Ω(i/j).
//!
//! Each frame R_k carries a basis B_k = (x_k, y_k, z_k) turned from its parent's basis by one
//! elementary rotation about a parent basis vector, by an angle (a time coordinate or a
//! constant angle), or not turned at all (a frame that only translates). A vector's
//! components are carried from one basis to another by applying the elementary rotations along
//! the path in the tree, one at a time: that keeps every intermediate expression as small as
//! the geometry allows, instead of forming a full direction-cosine matrix.

use crate::expr::{CoordId, Expr, Registry};
use std::rc::Rc;

/// Typed index of a frame in a [`Frames`] arena.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct FrameId(pub(crate) usize);

impl FrameId {
    /// Index in the arena (the ground is 0).
    pub fn index(self) -> usize {
        self.0
    }
}

/// A basis vector direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Axis {
    /// x
    X,
    /// y
    Y,
    /// z
    Z,
}

impl Axis {
    /// The three axes, each at its component index.
    ///
    /// ```
    /// use torseur::frame::Axis;
    /// assert!(Axis::ALL.iter().enumerate().all(|(k, a)| a.index() == k));
    /// ```
    pub const ALL: [Axis; 3] = [Axis::X, Axis::Y, Axis::Z];

    /// Component index 0, 1, 2.
    pub fn index(self) -> usize {
        match self {
            Axis::X => 0,
            Axis::Y => 1,
            Axis::Z => 2,
        }
    }

    /// Letter as written in the course.
    pub fn letter(self) -> char {
        ['x', 'y', 'z'][self.index()]
    }

    /// Parses `x`, `y`, `z`.
    pub fn parse(s: &str) -> Option<Axis> {
        match s {
            "x" => Some(Axis::X),
            "y" => Some(Axis::Y),
            "z" => Some(Axis::Z),
            _ => None,
        }
    }
}

/// The angle of an elementary rotation, `±q + c` counted positively about the (unsigned)
/// axis: one time coordinate q, or none, plus constants (multiples of π/2, constant angle
/// parameters). Its cos and sin are exact expressions; its rate is ±q̇.
#[derive(Debug, Clone)]
pub struct Angle {
    /// The coordinate turning the frame; for a frame turned by constants only, the first
    /// constant angle parameter (whose rate is 0).
    pub coord: CoordId,
    /// Coefficient of `coord` in the angle: +1 when the rotation is positive about the
    /// axis, -1 when drawn the other way (a negative axis, or `pi/2 - q`).
    pub sign: i32,
    /// Every term of the angle with its integer coefficient, `coord` first (the others are
    /// constant angle parameters).
    pub terms: Vec<(CoordId, i64)>,
    /// The constant offset k of k π/2 (`pi/2 - q` gives 1).
    pub quarter_turns: i64,
    /// cos of the angle.
    pub cos: Expr,
    /// sin of the angle.
    pub sin: Expr,
}

impl Angle {
    /// The angle in the spec syntax, counted about the unsigned axis (`pi/2 - q1`,
    /// `theta - alpha`, `-q`): a positive offset first when the first angle is negative.
    ///
    /// ```
    /// let m = torseur::spec::from_str(r#"{"title": "t",
    ///   "parameters": [{"name": "alpha", "kind": "angle"}],
    ///   "coordinates": [{"name": "q1", "kind": "angle"}],
    ///   "frames": [{"name": "1", "parent": "0", "rotation": {"axis": "z", "angle": "pi/2 - q1"}},
    ///              {"name": "2", "parent": "1", "rotation": {"axis": "-x", "angle": "q1 + alpha"}}]}"#
    /// ).unwrap();
    /// let text = |f: &str| {
    ///     let r = m.frames().get(m.frames().find(f).unwrap()).rotation.clone().unwrap();
    ///     r.angle.to_text(m.reg())
    /// };
    /// assert_eq!(text("1"), "pi/2 - q1");
    /// assert_eq!(text("2"), "-q1 - alpha");
    /// ```
    pub fn to_text(&self, reg: &Registry) -> String {
        let mut out = String::new();
        let mut push = |neg: bool, body: String| {
            match (out.is_empty(), neg) {
                (true, true) => out.push('-'),
                (true, false) => {}
                (false, true) => out.push_str(" - "),
                (false, false) => out.push_str(" + "),
            }
            out.push_str(&body);
        };
        let k = self.quarter_turns;
        let offset = (k != 0).then(|| {
            let body = match k.abs() {
                1 => "pi/2".to_string(),
                2 => "pi".to_string(),
                n if n % 2 == 0 => format!("{}*pi", n / 2),
                n => format!("{n}*pi/2"),
            };
            (k < 0, body)
        });
        let offset_first = k > 0 && self.terms.first().is_some_and(|t| t.1 < 0);
        if offset_first && let Some((neg, body)) = offset.clone() {
            push(neg, body);
        }
        for &(q, n) in &self.terms {
            let name = reg.coord_info(q).name.clone();
            let body = if n.abs() == 1 {
                name
            } else {
                format!("{}*{name}", n.abs())
            };
            push(n < 0, body);
        }
        if !offset_first && let Some((neg, body)) = offset {
            push(neg, body);
        }
        if out.is_empty() {
            out.push('0');
        }
        out
    }
}

/// One elementary rotation from the parent basis.
#[derive(Debug, Clone)]
pub struct Rotation {
    /// Axis, shared by the parent and the child basis.
    pub axis: Axis,
    /// Angle.
    pub angle: Angle,
}

/// A frame R_k and its basis B_k.
#[derive(Debug, Clone)]
pub struct Frame {
    /// Name, also the subscript of its vectors (`1` gives x1, y1, z1).
    pub name: String,
    /// Parent frame, none for the ground.
    pub parent: Option<FrameId>,
    /// Rotation from the parent basis, none when both bases coincide.
    pub rotation: Option<Rotation>,
    /// Depth in the tree (the ground is 0).
    pub depth: usize,
    /// Names of its basis vectors as the statement writes them (`u`, `v`, `w`), if given.
    pub vector_names: Option<[String; 3]>,
}

/// Arena of frames; the ground (Galilean) frame is always `FrameId(0)`.
#[derive(Debug, Clone)]
pub struct Frames {
    reg: Rc<Registry>,
    frames: Vec<Frame>,
}

impl Frames {
    /// A tree holding only the ground frame `ground`.
    pub fn new(reg: Rc<Registry>, ground: &str) -> Self {
        Frames {
            reg,
            frames: vec![Frame {
                name: ground.to_string(),
                parent: None,
                rotation: None,
                depth: 0,
                vector_names: None,
            }],
        }
    }

    /// The ground frame.
    pub fn ground(&self) -> FrameId {
        FrameId(0)
    }

    /// The expression registry shared by all frames.
    pub fn registry(&self) -> &Rc<Registry> {
        &self.reg
    }

    /// Adds a frame turned from `parent`.
    pub fn add(&mut self, name: &str, parent: FrameId, rotation: Option<Rotation>) -> FrameId {
        let depth = self.frames[parent.0].depth + 1;
        self.frames.push(Frame {
            name: name.to_string(),
            parent: Some(parent),
            rotation,
            depth,
            vector_names: None,
        });
        FrameId(self.frames.len() - 1)
    }

    /// Names the basis vectors of frame `f` as the statement does (`["u", "v", "w"]`).
    pub fn name_vectors(&mut self, f: FrameId, names: [String; 3]) {
        self.frames[f.0].vector_names = Some(names);
    }

    /// The name of a basis vector in expressions: the statement's (`u`) or `x1`.
    pub fn vector_name(&self, f: FrameId, axis: Axis) -> String {
        let fr = &self.frames[f.0];
        match &fr.vector_names {
            Some(n) => n[axis.index()].clone(),
            None => format!("{}{}", axis.letter(), fr.name),
        }
    }

    /// Frame by id.
    pub fn get(&self, id: FrameId) -> &Frame {
        &self.frames[id.0]
    }

    /// Frame by name.
    pub fn find(&self, name: &str) -> Option<FrameId> {
        self.frames.iter().position(|f| f.name == name).map(FrameId)
    }

    /// The basis vector named `x2` (an axis letter, then a frame name), if the frame exists.
    ///
    /// ```
    /// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
    /// let (f, axis) = m.frames().basis_vector("y2").unwrap();
    /// assert_eq!((m.frame_name(f), axis.letter()), ("2", 'y'));
    /// assert!(m.frames().basis_vector("y9").is_none());
    /// ```
    pub fn basis_vector(&self, s: &str) -> Option<(FrameId, Axis)> {
        for (i, f) in self.frames.iter().enumerate() {
            if let Some(k) = f.vector_names.iter().flatten().position(|n| n == s) {
                return Some((FrameId(i), Axis::ALL[k]));
            }
        }
        let mut c = s.chars();
        let axis = Axis::parse(&c.next()?.to_string())?;
        let f = self.find(c.as_str())?;
        Some((f, axis))
    }

    /// All frame ids, ground first.
    pub fn ids(&self) -> impl Iterator<Item = FrameId> + '_ {
        (0..self.frames.len()).map(FrameId)
    }

    /// The frames' names, the ground first.
    pub fn names(&self) -> impl Iterator<Item = &str> + '_ {
        self.frames.iter().map(|f| f.name.as_str())
    }

    /// Number of frames.
    pub fn len(&self) -> usize {
        self.frames.len()
    }

    /// Whether only... never: the ground always exists.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// The path between two frames: frames climbed from `a` (excluding the common ancestor)
    /// and frames descended to `b` (excluding the common ancestor, in descending order).
    pub fn path(&self, a: FrameId, b: FrameId) -> (Vec<FrameId>, Vec<FrameId>) {
        let (mut x, mut y) = (a, b);
        let mut up = Vec::new();
        let mut down = Vec::new();
        while self.frames[x.0].depth > self.frames[y.0].depth {
            up.push(x);
            x = self.frames[x.0].parent.expect("depth > 0 has a parent");
        }
        while self.frames[y.0].depth > self.frames[x.0].depth {
            down.push(y);
            y = self.frames[y.0].parent.expect("depth > 0 has a parent");
        }
        while x != y {
            up.push(x);
            down.push(y);
            x = self.frames[x.0]
                .parent
                .expect("distinct roots are impossible");
            y = self.frames[y.0]
                .parent
                .expect("distinct roots are impossible");
        }
        down.reverse();
        (up, down)
    }

    /// cos and sin of the angle of a frame's rotation.
    fn cos_sin(&self, rot: &Rotation) -> (Expr, Expr) {
        (rot.angle.cos.clone(), rot.angle.sin.clone())
    }

    /// Components in the parent basis of a vector given in the basis of `child`.
    ///
    /// For a rotation by θ about z: x_k = cos θ x_p + sin θ y_p, y_k = −sin θ x_p + cos θ y_p.
    pub fn to_parent(&self, child: FrameId, v: &[Expr; 3]) -> [Expr; 3] {
        match &self.frames[child.0].rotation {
            None => v.clone(),
            Some(rot) => {
                let (c, s) = self.cos_sin(rot);
                rotate(rot.axis, &c, &s, v)
            }
        }
    }

    /// Components in the basis of `child` of a vector given in its parent's basis.
    pub fn from_parent(&self, child: FrameId, v: &[Expr; 3]) -> [Expr; 3] {
        match &self.frames[child.0].rotation {
            None => v.clone(),
            Some(rot) => {
                let (c, s) = self.cos_sin(rot);
                rotate(rot.axis, &c, &(-s), v)
            }
        }
    }

    /// Components in basis `to` of a vector whose components in basis `from` are `v`,
    /// by the elementary rotations along the tree path.
    pub fn convert(&self, from: FrameId, to: FrameId, v: &[Expr; 3]) -> [Expr; 3] {
        if from == to {
            return v.clone();
        }
        let (up, down) = self.path(from, to);
        let mut w = v.clone();
        for f in up {
            w = self.to_parent(f, &w);
        }
        for f in down {
            w = self.from_parent(f, &w);
        }
        w
    }

    /// The direction-cosine matrix P with columns the vectors of basis `b` written in basis
    /// `a`: components in `a` = P · components in `b`.
    pub fn dcm(&self, a: FrameId, b: FrameId) -> [[Expr; 3]; 3] {
        let zero = self.reg.zero();
        let mut cols: Vec<[Expr; 3]> = Vec::with_capacity(3);
        for k in 0..3 {
            let mut e = [zero.clone(), zero.clone(), zero.clone()];
            e[k] = self.reg.one();
            cols.push(self.convert(b, a, &e));
        }
        std::array::from_fn(|i| std::array::from_fn(|j| cols[j][i].clone()))
    }

    /// Ω(a/b) as (basis, rate about an axis of that basis) terms: + each rotation on the way
    /// down from the common ancestor to `a`, − each on the way down to `b`.
    ///
    /// Ω(k/p) = θ̇ u where u is the rotation axis, a vector of both B_p and B_k; it is kept in
    /// B_k.
    pub fn omega_terms(&self, a: FrameId, b: FrameId) -> Vec<(FrameId, Axis, Expr)> {
        let (up_from_a, down_to_b) = self.path(a, b);
        let mut out = Vec::new();
        // Climbing from a: Ω(a/anc) = Σ Ω(k/parent(k)) for k on the way up, with + sign.
        // A rotation by a constant angle adds nothing.
        for f in up_from_a.iter().rev() {
            if let Some(rot) = &self.frames[f.0].rotation {
                let rate = self.rate(rot);
                if !rate.is_zero() {
                    out.push((*f, rot.axis, rate));
                }
            }
        }
        for f in down_to_b.iter() {
            if let Some(rot) = &self.frames[f.0].rotation {
                let rate = self.rate(rot);
                if !rate.is_zero() {
                    out.push((*f, rot.axis, -rate));
                }
            }
        }
        out
    }

    /// The rate of a rotation's angle: Σ nᵢ q̇ᵢ (constant angles have none).
    fn rate(&self, rot: &Rotation) -> Expr {
        let mut r = self.reg.zero();
        for &(q, n) in &rot.angle.terms {
            r = &r + &(&self.reg.dot(q) * &self.reg.integer(n));
        }
        r
    }
}

/// Applies the rotation by the angle whose cosine and sine are `c`, `s` about `axis` to the
/// components `v`: the image of the child basis vector combination in the parent basis.
fn rotate(axis: Axis, c: &Expr, s: &Expr, v: &[Expr; 3]) -> [Expr; 3] {
    // Indices (i, j) of the plane turned, in the right-handed order following the axis.
    let (i, j) = match axis {
        Axis::X => (1, 2),
        Axis::Y => (2, 0),
        Axis::Z => (0, 1),
    };
    let reg = c.registry();
    let mut w = v.clone();
    w[i] = Expr::sum_of_products(reg, &[(c, &v[i], false), (s, &v[j], true)]);
    w[j] = Expr::sum_of_products(reg, &[(s, &v[i], false), (c, &v[j], false)]);
    w
}
