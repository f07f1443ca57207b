//! TikZ figures of the set-up: the « figures planes » of the elementary rotations and the graph
//! of links, drawn from the spec's frames and links.
//!
//! Both need only `\usepackage{tikz}` (no TikZ library) and are written without `:` and
//! without polar coordinates, so they compile under `babel`'s French shorthands.

use super::{VectorNames, name, point};
use crate::expr::{CoordId, Registry};
use crate::frame::{Axis, Rotation};
use crate::mechanism::Link;
use crate::mechanism::Mechanism;
use crate::wire::LinkKind;
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// Angles, in degrees, at which a coordinate (or the variable part of an angle) is drawn:
/// small and positive, as a teacher draws it; the first that leaves room for the angle's name
/// between the vectors.
const DRAWN: [i64; 5] = [25, 30, 35, 40, 45];

/// Length of the basis vectors of a figure plane, in cm.
const VECTOR: f64 = 1.4;

/// The « figures planes » of every elementary rotation of the frames, side by side in a
/// `center` environment (about 3.5 cm each); empty when no frame is turned.
///
/// Each figure shows the parent's two basis vectors orthogonal to the rotation axis (thin) and
/// the child's (thick), the common axis pointing at the reader (⊙, named `\vec{z}_{0} =
/// \vec{z}_{1}`), and the arc from the parent's first vector to the child's, labelled with the
/// angle. Planes are (x, y) about z, (y, z) about x, (z, x) about y, first vector to the right.
/// The angle is drawn small and positive in the direct sense: a coordinate q as +25°,
/// `pi/2 - q` as 65°. An angle that would be drawn negative (a negative axis `-x`, an angle
/// `-q`) is drawn positive about the opposite axis, which then points at the reader
/// (`-\vec{x}_{1} = -\vec{x}_{2}`), with the angle as that axis counts it (the spec's angle
/// for a negative axis).
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let tex = torseur::latex::rotation_figures(&m);
/// assert_eq!(tex.matches("\\begin{tikzpicture}").count(), 2);
/// assert!(tex.contains("$\\vec{z}_{0} = \\vec{z}_{1}$"));
/// assert!(tex.contains("{$\\theta_{2}$}"));
/// ```
pub fn rotation_figures(m: &Mechanism) -> String {
    let pictures = rotation_pictures(m, &VectorNames::of(m));
    if pictures.is_empty() {
        return String::new();
    }
    super::plain(&format!(
        "\\begin{{center}}\n{}\\end{{center}}\n",
        pictures.join("\\hspace{1.5em}\n")
    ))
}

/// Printed width of one figure plane, in cm (arrows of 1.4 cm and their labels).
pub(super) const PLANE_WIDTH: f64 = 2.8;

/// The figures planes of [`rotation_figures`], one `tikzpicture` each, the basis vectors by
/// the statement's `names`.
pub(super) fn rotation_pictures(m: &Mechanism, names: &VectorNames) -> Vec<String> {
    m.frames
        .ids()
        .skip(1)
        .filter_map(|f| {
            let frame = m.frames.get(f);
            let rotation = frame.rotation.as_ref()?;
            let parent = m.frames.get(frame.parent?);
            let mut drawn = DRAWN
                .iter()
                .map(|&d| plane_figure(&m.reg, names, &parent.name, &frame.name, rotation, d));
            let first = drawn.next()?;
            let clean = std::iter::once(first.clone())
                .chain(drawn)
                .find(|(_, clean)| *clean);
            Some(clean.unwrap_or(first).0)
        })
        .collect()
}

/// One figure plane: the rotation of `child` from `parent`, its variable part drawn at
/// `small` degrees; and whether the angle's name stays clear of the vectors.
fn plane_figure(
    reg: &Registry,
    names: &VectorNames,
    parent: &str,
    child: &str,
    r: &Rotation,
    small: i64,
) -> (String, bool) {
    let terms = &r.angle.terms;
    let k = r.angle.quarter_turns;
    let lead = terms.first().map_or(1, |t| t.1.signum());
    let drawn = 90 * k + small * lead;
    // The vectors of the plane in the direct order about the (unsigned) axis.
    let (u, w) = match r.axis {
        Axis::Z => ('x', 'y'),
        Axis::X => ('y', 'z'),
        Axis::Y => ('z', 'x'),
    };
    let a = r.axis.letter();
    // Seen from the opposite axis, (w, u) is direct and the angle changes sign.
    let (flip, h, v) = if drawn < 0 { (-1, w, u) } else { (1, u, w) };
    let phi = (drawn * flip).rem_euclid(360) as f64;
    let signed: Vec<(CoordId, i64)> = terms.iter().map(|&(q, n)| (q, n * flip)).collect();
    let label = angle_latex(reg, &signed, k * flip);
    let minus = if flip < 0 { "-" } else { "" };
    let axis_label = format!(
        "{minus}{} = {minus}{}",
        names.basis_vector(a, parent),
        names.basis_vector(a, child)
    );

    let mut o = String::from("\\begin{tikzpicture}[>=stealth, font=\\small]\n");
    let mut taken = Layout::default();
    // Parent basis, then child basis; each name outside its tip.
    let vectors = [
        (0.0, names.basis_vector(h, parent), "->"),
        (90.0, names.basis_vector(v, parent), "->"),
        (phi, names.basis_vector(h, child), "->, thick"),
        (phi + 90.0, names.basis_vector(v, child), "->, thick"),
    ];
    draw_vectors(&mut o, &mut taken, &vectors);
    let clean = draw_angle(&mut o, &mut taken, phi, &label);
    draw_axis(&mut o, &taken, &axis_label);
    o.push_str("\\end{tikzpicture}\n");
    (o, clean)
}

/// The basis vectors of a figure plane, (direction in degrees, name, TikZ style) each, from
/// the origin with its name outside its tip; each taken in the layout.
fn draw_vectors(o: &mut String, taken: &mut Layout, vectors: &[(f64, String, &str)]) {
    for (deg, _, _) in vectors {
        taken.segment(*deg, VECTOR);
    }
    taken.boxes.push(Rect::around((0.0, 0.0), 0.26, 0.26));
    for (deg, vec, style) in vectors {
        let (x, y) = polar(*deg, VECTOR);
        taken
            .boxes
            .push(Rect::anchored((x, y), *deg, VECTOR_NAME, VECTOR_NAME));
        let _ = writeln!(
            o,
            "\\draw[{style}] (0,0) -- ({},{}) node[anchor={}, inner sep=2pt] {{${vec}$}};",
            num(x),
            num(y),
            num((deg + 180.0).rem_euclid(360.0))
        );
    }
}

/// The angle `phi`, from the parent's first vector to the child's, named `label` in the
/// widest gap between the vectors it sweeps; whether the name stays clear of the vectors.
fn draw_angle(o: &mut String, taken: &mut Layout, phi: f64, label: &str) -> bool {
    let radius = 0.8;
    let _ = writeln!(
        o,
        "\\draw[->] ({},0) arc[start angle=0, end angle={}, radius={}];",
        num(radius),
        num(phi),
        num(radius)
    );
    let mut inside: Vec<f64> = vec![0.0, phi];
    inside.extend(
        [90.0, phi + 90.0]
            .into_iter()
            .map(|d| d.rem_euclid(360.0))
            .filter(|d| *d > 0.0 && *d < phi),
    );
    inside.sort_by(f64::total_cmp);
    let (gap_start, gap) = inside
        .windows(2)
        .map(|p| (p[0], p[1] - p[0]))
        .fold((0.0, -1.0), |best, g| if g.1 > best.1 { g } else { best });
    // Along the gap and outwards, the first place where the name touches no vector.
    let lw = width(label);
    let spots: Vec<(f64, f64)> = [0.5, 0.4, 0.6]
        .into_iter()
        .flat_map(|f| [0.05, 0.2].map(|dr| (gap_start + f * gap, radius + dr)))
        .collect();
    let free = spots
        .iter()
        .copied()
        .find(|&(a, r)| !taken.hits(&Rect::anchored(polar(a, r), a, lw, 0.3).shrunk(0.03)));
    let clean = free.is_some();
    let (mid, r) = free.unwrap_or(spots[0]);
    let at = polar(mid, r);
    let angle_box = Rect::anchored(at, mid, lw, 0.3);
    for step in 0..=20 {
        let (x, y) = polar(phi * f64::from(step) / 20.0, radius);
        taken.boxes.push(Rect::around((x, y), 0.04, 0.04));
    }
    let _ = writeln!(
        o,
        "\\node[anchor={}, inner sep=1.5pt] at ({},{}) {{${label}$}};",
        num((mid + 180.0).rem_euclid(360.0)),
        num(at.0),
        num(at.1)
    );
    taken.boxes.push(angle_box);
    clean
}

/// The common axis, towards the reader (⊙), named `axis_label` where nothing else is drawn:
/// a diagonal below first.
fn draw_axis(o: &mut String, taken: &Layout, axis_label: &str) {
    let (aw, ah) = (width(axis_label), 0.42);
    let candidates = [225.0, 315.0, 135.0, 45.0, 270.0, 180.0, 0.0, 90.0];
    let place = [0.14, 0.45, 0.8]
        .into_iter()
        .flat_map(|d| candidates.into_iter().map(move |c| (c, d)))
        .chain((0..24).map(|i| (f64::from(i) * 15.0, 1.6)))
        .find(|&(c, d)| !taken.hits(&Rect::anchored(polar(c, d), c, aw, ah)))
        .unwrap_or((225.0, 0.14));
    let at = polar(place.0, place.1);
    let _ = writeln!(
        o,
        "\\draw (0,0) circle[radius=0.1];\n\\fill (0,0) circle[radius=0.025];\n\\node[anchor={}, \
         inner sep=1pt] at ({},{}) {{${axis_label}$}};",
        num((place.0 + 180.0).rem_euclid(360.0)),
        num(at.0),
        num(at.1)
    );
}

/// Size of a basis vector's name (`\vec{x}_{1}` in `\small`, with its inner sep), in cm.
const VECTOR_NAME: f64 = 0.5;

/// The point at `deg` degrees and distance `r` from the origin.
fn polar(deg: f64, r: f64) -> (f64, f64) {
    let t = deg.to_radians();
    (r * t.cos(), r * t.sin())
}

/// An estimate of the width of a formula in `\small`, in cm: enough to keep labels apart.
fn width(latex: &str) -> f64 {
    let mut w = 0.1;
    let mut chars = latex.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let mut word = String::new();
                while let Some(&l) = chars.peek()
                    && l.is_ascii_alphabetic()
                {
                    word.push(l);
                    chars.next();
                }
                // `\vec` and `\frac` draw nothing of their own; a Greek letter is one glyph.
                w += match word.as_str() {
                    "vec" | "frac" | "mathrm" => 0.0,
                    _ => 0.22,
                };
            }
            '{' | '}' | '_' | '^' | ' ' => {}
            '=' | '+' | '-' => w += 0.45,
            c if c.is_ascii_digit() => w += 0.12,
            _ => w += 0.22,
        }
    }
    w
}

/// An axis-aligned rectangle, in cm.
#[derive(Debug, Clone, Copy)]
struct Rect {
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
}

impl Rect {
    /// The `w` × `h` rectangle centred on `c`.
    fn around(c: (f64, f64), w: f64, h: f64) -> Rect {
        Rect {
            x0: c.0 - w / 2.0,
            y0: c.1 - h / 2.0,
            x1: c.0 + w / 2.0,
            y1: c.1 + h / 2.0,
        }
    }

    /// The `w` × `h` rectangle of a node whose border point at `deg + 180` is `p` (TikZ's
    /// `anchor=deg+180`): the node lies away from `p` in the direction `deg`.
    fn anchored(p: (f64, f64), deg: f64, w: f64, h: f64) -> Rect {
        let (c, s) = (deg.to_radians().cos(), deg.to_radians().sin());
        let t = (w / 2.0 / c.abs().max(1e-9)).min(h / 2.0 / s.abs().max(1e-9));
        Rect::around((p.0 + c * t, p.1 + s * t), w, h)
    }

    /// The rectangle with `d` less on every side.
    fn shrunk(&self, d: f64) -> Rect {
        Rect {
            x0: self.x0 + d,
            y0: self.y0 + d,
            x1: self.x1 - d,
            y1: self.y1 - d,
        }
    }

    fn meets(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }
}

/// What a figure already holds, to name the axis where nothing is drawn.
#[derive(Debug, Default)]
struct Layout {
    boxes: Vec<Rect>,
}

impl Layout {
    /// A segment from the origin along `deg` over `len`, as small boxes.
    fn segment(&mut self, deg: f64, len: f64) {
        for step in 0..=56 {
            let p = polar(deg, len * f64::from(step) / 56.0);
            self.boxes.push(Rect::around(p, 0.02, 0.02));
        }
    }

    fn hits(&self, r: &Rect) -> bool {
        self.boxes.iter().any(|b| b.meets(r))
    }
}

/// An angle `Σ nᵢ qᵢ + k π/2` in LaTeX, in the order of [`crate::frame::Angle::to_text`]
/// (a positive offset first when the first angle is negative): `\frac{\pi}{2} - q_{1}`.
pub(super) fn angle_latex(reg: &Registry, terms: &[(CoordId, i64)], k: i64) -> String {
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
    let offset = (k != 0).then(|| {
        let body = match k.abs() {
            1 => "\\frac{\\pi}{2}".to_string(),
            2 => "\\pi".to_string(),
            n if n % 2 == 0 => format!("{}\\pi", n / 2),
            n => format!("\\frac{{{n}\\pi}}{{2}}"),
        };
        (k < 0, body)
    });
    let offset_first = k > 0 && terms.first().is_some_and(|t| t.1 < 0);
    if offset_first && let Some((neg, body)) = offset.clone() {
        push(neg, body);
    }
    for &(q, n) in terms {
        let nm = super::coordinate(reg, q);
        let body = if n.abs() == 1 {
            nm
        } else {
            format!("{}\\,{nm}", n.abs())
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

/// A coordinate for TikZ: centimetres, three decimals at most, no `-0`.
fn num(x: f64) -> String {
    let s = format!("{:.3}", x);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// A basis vector of the spec (`z0`) in LaTeX (`\vec{z}_{0}`), or by the statement's `names`.
pub(super) fn spec_vector(names: &VectorNames, s: &str) -> String {
    if let Some(v) = names.named_vector(s) {
        return v;
    }
    let mut c = s.chars();
    match c.next() {
        Some(a @ ('x' | 'y' | 'z')) => names.basis_vector(a, c.as_str()),
        _ => format!("\\vec{{{}}}", name(s)),
    }
}

/// A link's kind and geometry as the course writes it, in LaTeX: « pivot d'axe $(O_{1},
/// \vec{z}_{0})$ », « glissière de direction $\vec{x}_{0}$ », « rotule de centre $O$ », with
/// « avec frottement visqueux » and « avec ressort » when declared.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// assert_eq!(
///     torseur::latex::link_text(&m.links()[1]),
///     "pivot d'axe $(O_{2}, \\vec{x}_{1})$, avec frottement visqueux"
/// );
/// ```
pub fn link_text(l: &Link) -> String {
    super::plain(&link_text_with(&VectorNames::default(), l))
}

/// [`link_text`], the basis vectors by the statement's `names`.
pub(super) fn link_text_with(names: &VectorNames, l: &Link) -> String {
    let p = point(&l.point);
    let spec_vector = |s: &str| spec_vector(names, s);
    let axis = l.axis.as_deref().map(spec_vector);
    let mut t = match (l.kind, axis) {
        (LinkKind::Fixed, _) => "encastrement".to_string(),
        (LinkKind::Ball, _) => format!("rotule de centre ${p}$"),
        (LinkKind::Pivot, Some(a)) => format!("pivot d'axe $({p}, {a})$"),
        (LinkKind::Slider, Some(a)) => format!("glissière de direction ${a}$"),
        (LinkKind::PivotSlider, Some(a)) => format!("pivot glissant d'axe $({p}, {a})$"),
        (LinkKind::Plane, Some(a)) => format!("appui plan de normale ${a}$"),
        (LinkKind::Annular, Some(a)) => {
            format!("linéaire annulaire de centre ${p}$ et d'axe ${a}$")
        }
        (LinkKind::Line, Some(a)) => match l.direction.as_deref().map(spec_vector) {
            Some(d) => format!("linéaire rectiligne de normale ${a}$ et de ligne $({p}, {d})$"),
            None => format!("linéaire rectiligne de normale ${a}$ en ${p}$"),
        },
        (LinkKind::Point, Some(a)) => format!("ponctuelle de normale $({p}, {a})$"),
        // The pitch by its name when it is one (a longer pitch is written with the relation).
        (LinkKind::Helical, Some(a)) => match &l.pitch_name {
            Some(n) => format!(
                "hélicoïdale d'axe $({p}, {a})$ et de pas ${}$",
                super::name(n)
            ),
            None => format!("hélicoïdale d'axe $({p}, {a})$"),
        },
        (kind, None) => {
            let n = kind.course_name();
            format!(
                "{} de centre ${p}$",
                n.strip_prefix("liaison ").unwrap_or(n)
            )
        }
    };
    if l.viscous.is_some() {
        t.push_str(", avec frottement visqueux");
    }
    if l.dry.is_some() || l.coefficient.is_some() {
        t.push_str(", avec frottement sec");
    }
    if l.spring.is_some() {
        t.push_str(", avec ressort");
    }
    t
}

/// Horizontal distance between the solids of two successive levels of the graph, in cm.
const LEVEL: f64 = 4.0;

/// Vertical distance between two branches of the graph, in cm.
const BRANCH: f64 = 2.0;

/// The graph of links (« graphe des liaisons ») in a `center` environment: each solid a circled
/// node (the ground, « bâti », first, on the left), each link an edge labelled with
/// [`link_text`]; links in parallel between the same two solids share one edge. Empty when the
/// spec declares no link.
///
/// ```
/// let m = torseur::spec::load("derivations/regulateur_centrifuge.json").unwrap();
/// let tex = torseur::latex::link_graph(&m);
/// assert!(tex.contains("pivot d'axe $(O_{1}, \\vec{z}_{0})$"));
/// assert!(tex.contains("bâti"));
/// ```
pub fn link_graph(m: &Mechanism) -> String {
    super::plain(&link_graph_with(m, &VectorNames::of(m)))
}

/// [`link_graph`], the basis vectors by the statement's `names`.
pub(super) fn link_graph_with(m: &Mechanism, names: &VectorNames) -> String {
    match link_picture(m, names) {
        Some((p, _)) => format!("\\begin{{center}}\n{p}\\end{{center}}\n"),
        None => String::new(),
    }
}

/// The `tikzpicture` of [`link_graph`] and its printed width in cm; none without links.
pub(super) fn link_picture(m: &Mechanism, names: &VectorNames) -> Option<(String, f64)> {
    let links = &m.links;
    if links.is_empty() && m.bodies.iter().all(|b| b.carried_by.is_none()) {
        return None;
    }
    let (nodes, edges) = link_graph_of(m, names, links);
    let forest = Forest::of(nodes.len(), &edges);
    let row = forest.rows();
    let o = draw_link_graph(&nodes, &edges, &forest, &row);
    // The deepest level, the node and the labels' overhang on both sides, and the label
    // beside a vertical edge of the deepest level.
    let deepest = forest.depth.iter().copied().max().unwrap_or(0);
    let beside = (edges.keys())
        .any(|&(a, b)| forest.depth[a] == forest.depth[b] && forest.depth[a] == deepest);
    let extra = if beside { 3.6 } else { 0.0 };
    Some((o, deepest as f64 * LEVEL + 1.6 + extra))
}

/// Edges between two nodes (by index, the smaller first), with the texts of their links.
type Edges = BTreeMap<(usize, usize), Vec<String>>;

/// The solids in order of appearance, the ground first, and the edges between them.
fn link_graph_of(m: &Mechanism, names: &VectorNames, links: &[Link]) -> (Vec<String>, Edges) {
    let ground = m.frame_name(m.frames.ground()).to_string();
    let mut nodes: Vec<String> = vec![ground];
    for l in links {
        for s in &l.between {
            if !nodes.contains(s) {
                nodes.push(s.clone());
            }
        }
    }
    // A solid carried by another (`carried_by`) hangs from its carrier, with no link: the
    // two are « solidaires » (fixed together, as an encastrement would hold them).
    let carried: Vec<(&str, &str)> = (m.bodies.iter())
        .filter_map(|b| {
            b.carried_by
                .map(|c| (m.body(c).name.as_str(), b.name.as_str()))
        })
        .collect();
    for &(c, b) in &carried {
        for s in [c, b] {
            if !nodes.iter().any(|n| n == s) {
                nodes.push(s.to_string());
            }
        }
    }
    let index = |s: &str| nodes.iter().position(|n| n == s).unwrap_or(0);
    let mut edges = Edges::new();
    for l in links {
        let (a, b) = (index(&l.between[0]), index(&l.between[1]));
        edges
            .entry((a.min(b), a.max(b)))
            .or_default()
            .push(link_text_with(names, l));
    }
    for &(c, b) in &carried {
        let (a, b) = (index(c), index(b));
        let text = "solidaires (encastrement)".to_string();
        edges.entry((a.min(b), a.max(b))).or_default().push(text);
    }
    (nodes, edges)
}

/// A spanning forest of the graph of links from the ground (then from any solid not
/// reached), breadth first.
struct Forest {
    parent: Vec<Option<usize>>,
    depth: Vec<usize>,
    children: Vec<Vec<usize>>,
    roots: Vec<usize>,
}

impl Forest {
    fn of(n: usize, edges: &Edges) -> Forest {
        let mut f = Forest {
            parent: vec![None; n],
            depth: vec![0usize; n],
            children: vec![Vec::new(); n],
            roots: Vec::new(),
        };
        let mut seen = vec![false; n];
        for root in 0..n {
            if seen[root] {
                continue;
            }
            seen[root] = true;
            f.roots.push(root);
            let mut queue = std::collections::VecDeque::from([root]);
            while let Some(x) = queue.pop_front() {
                for &(a, b) in edges.keys() {
                    let y = match (a == x, b == x) {
                        (true, _) => b,
                        (_, true) => a,
                        _ => continue,
                    };
                    if !seen[y] {
                        seen[y] = true;
                        f.parent[y] = Some(x);
                        f.depth[y] = f.depth[x] + 1;
                        f.children[x].push(y);
                        queue.push_back(y);
                    }
                }
            }
        }
        f
    }

    /// Each node's row: leaves take successive rows; a node sits at the middle of its
    /// children.
    fn rows(&self) -> Vec<f64> {
        fn place(x: usize, children: &[Vec<usize>], next: &mut f64, row: &mut [f64]) {
            if children[x].is_empty() {
                row[x] = *next;
                *next += 1.0;
                return;
            }
            for &c in &children[x] {
                place(c, children, next, row);
            }
            let (first, last) = (children[x][0], children[x][children[x].len() - 1]);
            row[x] = (row[first] + row[last]) / 2.0;
        }
        let mut row = vec![0.0; self.parent.len()];
        let mut next = 0.0;
        for &r in &self.roots {
            place(r, &self.children, &mut next, &mut row);
        }
        row
    }
}

/// The `tikzpicture` of the graph of links: each solid a circled node at its depth and
/// row (« bâti » under the ground), each edge labelled with its links.
fn draw_link_graph(nodes: &[String], edges: &Edges, forest: &Forest, row: &[f64]) -> String {
    let mut o = String::from(
        "\\begin{tikzpicture}[font=\\small]\n\
         \\tikzset{solide/.style={draw, circle, minimum size=0.75cm, inner sep=1pt}}\n",
    );
    for (i, s) in nodes.iter().enumerate() {
        let (x, y) = (forest.depth[i] as f64 * LEVEL, -row[i] * BRANCH);
        let _ = writeln!(
            o,
            "\\node[solide] (n{i}) at ({},{}) {{${}$}};",
            num(x),
            num(y),
            name(s)
        );
        if i == 0 {
            let _ = writeln!(
                o,
                "\\node[anchor=north, font=\\footnotesize] at ({},{}) {{bâti}};",
                num(x),
                num(y - 0.4)
            );
        }
    }
    for ((a, b), texts) in edges {
        // Drawn from the node nearer the ground.
        let (a, b) = if forest.parent[*a] == Some(*b) {
            (*b, *a)
        } else {
            (*a, *b)
        };
        // Two solids of one level joined by a link that closes a loop (a screw and its
        // nut, each on the frame): the edge is vertical, its label beside it, to the right.
        if forest.depth[a] == forest.depth[b] {
            let _ = writeln!(
                o,
                "\\draw (n{a}) -- (n{b}) node[midway, right, align=left, text width=3.4cm, \
                 font=\\footnotesize\\hyphenpenalty10000\\relax] {{{}}};",
                texts.join("\\\\ ")
            );
            continue;
        }
        // Above a rising or level edge, below a falling one: never between two branches.
        let side = if row[b] > row[a] { "below" } else { "above" };
        let _ = writeln!(
            o,
            "\\draw (n{a}) -- (n{b}) node[midway, sloped, {side}, align=center, \
             text width=3.4cm, font=\\footnotesize\\hyphenpenalty10000\\relax] {{{}}};",
            texts.join("\\\\ ")
        );
    }
    o.push_str("\\end{tikzpicture}\n");
    o
}
