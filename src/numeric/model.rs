//! Building a [`NumericModel`] from a spec: names, frame and point trees, parsed expressions.

use super::expr::{self, Kind, Name, Node};
use super::{
    CoordInfo, FrameInfo, Hypothesis, InertiaInfo, NumericError, NumericModel, ParamInfo,
    PointInfo, SolidInfo, Symmetry,
};
use crate::wire::{CoordinateKind, ParameterKind, SpecFile, SymmetrySpec};
use nalgebra::{Matrix3, Vector3};
use std::collections::BTreeMap;

pub(super) fn spec_err(path: impl Into<String>, message: impl Into<String>) -> NumericError {
    NumericError::Spec {
        path: path.into(),
        message: message.into(),
    }
}

/// Where an expression appears, which decides the names it may use.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Context {
    /// Parameters only (masses, inertia entries, imposed rates).
    Constant,
    /// Parameters and coordinates (rotation angles).
    Angle,
    /// Parameters, coordinates and basis vectors (point positions).
    Position,
    /// Parameters, coordinates, their rates (a user expression at one instant).
    Instant,
    /// Parameters and basis vectors (gravity, a constant vector).
    ConstantVector,
    /// Parameters, coordinates, their rates, basis vectors and the unknowns given to
    /// [`Names::parse_with`] (the resultant or moment of an action).
    Action,
}

impl Context {
    /// Whether the expression is a vector (else a scalar).
    fn vector(self) -> bool {
        matches!(
            self,
            Context::Position | Context::ConstantVector | Context::Action
        )
    }
}

/// The names known while parsing expressions.
pub(super) struct Names<'a> {
    pub params: &'a BTreeMap<String, usize>,
    pub coords: &'a BTreeMap<String, usize>,
    pub frames: &'a BTreeMap<String, usize>,
}

impl Names<'_> {
    /// Splits `x2` into (frame index, axis) when frame `2` exists.
    pub fn basis_vector(&self, s: &str) -> Option<(usize, usize)> {
        let axis = match s.as_bytes().first()? {
            b'x' => 0,
            b'y' => 1,
            b'z' => 2,
            _ => return None,
        };
        self.frames.get(&s[1..]).map(|f| (*f, axis))
    }

    /// Parses `text` for `ctx` and checks its type (scalar, or vector for positions).
    pub fn parse(&self, text: &str, ctx: Context) -> Result<Node, String> {
        self.parse_with(text, ctx, &BTreeMap::new())
    }

    /// [`Names::parse`], where the names of `unknowns` are the unknowns of these indices.
    pub fn parse_with(
        &self,
        text: &str,
        ctx: Context,
        unknowns: &BTreeMap<String, usize>,
    ) -> Result<Node, String> {
        let resolve = |name: &str| -> Result<Name, String> {
            if ctx.vector()
                && let Some((f, a)) = self.basis_vector(name)
            {
                return Ok(Name::Basis(f, a));
            }
            if let Some(i) = self.params.get(name) {
                return Ok(Name::Param(*i));
            }
            if let Some(i) = unknowns.get(name) {
                return Ok(Name::Unknown(*i));
            }
            if let Some(i) = self.coords.get(name) {
                return if ctx == Context::Constant {
                    Err(format!(
                        "`{name}` is a time coordinate: only parameters can appear here"
                    ))
                } else if ctx == Context::ConstantVector {
                    Err(format!(
                        "`{name}` is a time coordinate: only parameters and basis vectors can \
                         appear here"
                    ))
                } else {
                    Ok(Name::Coord(*i))
                };
            }
            if self.basis_vector(name).is_some() {
                return Err(format!(
                    "the basis vector `{name}` cannot appear in a scalar"
                ));
            }
            Err(format!("unknown name `{name}`"))
        };
        let node = expr::parse(
            text,
            &resolve,
            matches!(ctx, Context::Instant | Context::Action),
        )?;
        let k = expr::kind(&node)?;
        match (ctx, k) {
            (Context::Position, Kind::Scalar) => Err(
                "a position is a vector: every term holds one basis vector (x0, y1, z2, …)".into(),
            ),
            (Context::ConstantVector | Context::Action, Kind::Scalar) => Err(
                "a vector was expected: every term holds one basis vector (x0, y1, z2, …)".into(),
            ),
            (_, Kind::Vector) if !ctx.vector() => Err("a scalar was expected, not a vector".into()),
            _ => Ok(node),
        }
    }
}

/// Orders items of a tree so that each comes after the one it hangs from; `parent(i)` is the
/// index of the parent among the items, or `None` for a root. Errors name a cycle member.
fn topo_order(n: usize, parent: &dyn Fn(usize) -> Option<usize>) -> Result<Vec<usize>, usize> {
    let mut placed = vec![false; n];
    let mut order = Vec::with_capacity(n);
    while order.len() < n {
        let before = order.len();
        for i in 0..n {
            if !placed[i] && parent(i).is_none_or(|p| placed[p]) {
                placed[i] = true;
                order.push(i);
            }
        }
        if order.len() == before {
            return Err(placed.iter().position(|p| !p).unwrap_or(0));
        }
    }
    Ok(order)
}

fn unique<'a>(
    what: &str,
    path: &str,
    names: impl Iterator<Item = &'a str>,
    index: &mut BTreeMap<String, usize>,
) -> Result<(), NumericError> {
    for (i, n) in names.enumerate() {
        if crate::quantity::check_name(n).is_err() {
            return Err(spec_err(
                format!("{path}[{i}].name"),
                format!("{what} name `{n}`: only ASCII letters, digits and `_` are allowed"),
            ));
        }
        if index.insert(n.to_string(), i).is_some() {
            return Err(spec_err(
                format!("{path}[{i}].name"),
                format!("{what} `{n}` is defined twice"),
            ));
        }
    }
    Ok(())
}

/// Builds the model; every error names the JSON path of the faulty value.
pub(super) fn build(spec: &SpecFile) -> Result<NumericModel, NumericError> {
    // Parameters and coordinates.
    let mut param_index = BTreeMap::new();
    unique(
        "parameter",
        "parameters",
        spec.parameters.iter().map(|p| p.name.as_str()),
        &mut param_index,
    )?;
    let mut coord_index = BTreeMap::new();
    unique(
        "coordinate",
        "coordinates",
        spec.coordinates.iter().map(|c| c.name.as_str()),
        &mut coord_index,
    )?;
    // A name that expressions read: a letter, then letters, digits or `_`.
    for (path, list) in [
        (
            "parameters",
            spec.parameters.iter().map(|p| &p.name).collect::<Vec<_>>(),
        ),
        (
            "coordinates",
            spec.coordinates.iter().map(|c| &c.name).collect(),
        ),
    ] {
        for (i, n) in list.into_iter().enumerate() {
            if !n.starts_with(|c: char| c.is_ascii_alphabetic()) || n.len() > 32 {
                return Err(spec_err(
                    format!("{path}[{i}].name"),
                    format!(
                        "`{n}` is not a valid name for an expression: a letter, then letters, \
                         digits or `_` (at most 32 characters)"
                    ),
                ));
            }
        }
    }
    // `pi` is π in every expression, so it cannot name a parameter or a coordinate.
    for (path, what, i) in [
        ("parameters", "parameter", param_index.get(expr::PI_NAME)),
        ("coordinates", "coordinate", coord_index.get(expr::PI_NAME)),
    ] {
        if let Some(i) = i {
            return Err(spec_err(
                format!("{path}[{i}].name"),
                format!(
                    "{what} name `{}`: the name is reserved for π",
                    expr::PI_NAME
                ),
            ));
        }
    }
    for (i, c) in spec.coordinates.iter().enumerate() {
        if param_index.contains_key(&c.name) {
            return Err(spec_err(
                format!("coordinates[{i}].name"),
                format!("`{}` is both a parameter and a coordinate", c.name),
            ));
        }
    }

    let angle_params: Vec<usize> = (0..spec.parameters.len())
        .filter(|&i| spec.parameters[i].kind == ParameterKind::Angle)
        .collect();

    // Frames: the ground first, then parents before children.
    let ground = spec.ground.clone();
    let mut spec_frame_index = BTreeMap::new();
    unique(
        "frame",
        "frames",
        spec.frames.iter().map(|f| f.name.as_str()),
        &mut spec_frame_index,
    )?;
    if let Some(i) = spec_frame_index.get(&ground) {
        return Err(spec_err(
            format!("frames[{i}].name"),
            format!("`{ground}` is the ground frame: it has no parent"),
        ));
    }
    let mut parents = Vec::with_capacity(spec.frames.len());
    for (i, f) in spec.frames.iter().enumerate() {
        if f.parent == ground {
            parents.push(None);
        } else {
            let p = spec_frame_index.get(&f.parent).ok_or_else(|| {
                spec_err(
                    format!("frames[{i}].parent"),
                    format!("unknown frame `{}`", f.parent),
                )
            })?;
            parents.push(Some(*p));
        }
    }
    let order = topo_order(spec.frames.len(), &|i| parents[i]).map_err(|i| {
        spec_err(
            format!("frames[{i}].parent"),
            format!("frame `{}` is its own ancestor", spec.frames[i].name),
        )
    })?;
    let mut frame_index = BTreeMap::new();
    frame_index.insert(ground.clone(), 0usize);
    for (k, i) in order.iter().enumerate() {
        frame_index.insert(spec.frames[*i].name.clone(), k + 1);
    }
    let names = Names {
        params: &param_index,
        coords: &coord_index,
        frames: &frame_index,
    };

    let coords = spec
        .coordinates
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let rate = c
                .rate
                .as_ref()
                .map(|r| {
                    names
                        .parse(r, Context::Constant)
                        .map_err(|m| spec_err(format!("coordinates[{i}].rate"), m))
                })
                .transpose()?;
            Ok(CoordInfo {
                name: c.name.clone(),
                kind: c.kind,
                rate,
                rate_text: c.rate.clone(),
            })
        })
        .collect::<Result<Vec<_>, NumericError>>()?;

    // Points: the ground origin first, then each after the point it is placed from.
    let ground_origin = spec
        .ground_origin
        .clone()
        .unwrap_or_else(|| "O0".to_string());
    let mut spec_point_index = BTreeMap::new();
    unique(
        "point",
        "points",
        spec.points.iter().map(|p| p.name.as_str()),
        &mut spec_point_index,
    )?;
    if let Some(i) = spec_point_index.get(&ground_origin) {
        return Err(spec_err(
            format!("points[{i}].name"),
            format!("`{ground_origin}` is the ground origin: it cannot be placed"),
        ));
    }
    let mut from = Vec::with_capacity(spec.points.len());
    for (i, p) in spec.points.iter().enumerate() {
        let f = p.from.as_deref().unwrap_or(&ground_origin);
        if f == ground_origin {
            from.push(None);
        } else {
            let k = spec_point_index.get(f).ok_or_else(|| {
                spec_err(format!("points[{i}].from"), format!("unknown point `{f}`"))
            })?;
            from.push(Some(*k));
        }
    }
    let porder = topo_order(spec.points.len(), &|i| from[i]).map_err(|i| {
        spec_err(
            format!("points[{i}].from"),
            format!("point `{}` is placed from itself", spec.points[i].name),
        )
    })?;
    let mut point_index = BTreeMap::new();
    point_index.insert(ground_origin.clone(), 0usize);
    for (k, i) in porder.iter().enumerate() {
        point_index.insert(spec.points[*i].name.clone(), k + 1);
    }
    let mut points = vec![PointInfo {
        name: ground_origin.clone(),
        from: 0,
        position: Node::Num(0.0),
    }];
    for i in &porder {
        let p = &spec.points[*i];
        let position = names
            .parse(&p.position, Context::Position)
            .map_err(|m| spec_err(format!("points[{i}].position"), m))?;
        let f = p.from.as_deref().unwrap_or(&ground_origin);
        points.push(PointInfo {
            name: p.name.clone(),
            from: point_index[f],
            position,
        });
    }

    // Frames, now that points are known (origins).
    let mut frames = vec![FrameInfo {
        name: ground.clone(),
        parent: 0,
        rotation: None,
        origin: 0,
    }];
    for i in &order {
        let f = &spec.frames[*i];
        let rotation = match &f.rotation {
            None => None,
            Some(r) => {
                let (sign, axis_txt) = match r.axis.trim().strip_prefix('-') {
                    Some(a) => (-1.0, a.trim()),
                    None => (1.0, r.axis.trim()),
                };
                let axis = match axis_txt {
                    "x" => 0,
                    "y" => 1,
                    "z" => 2,
                    _ => {
                        return Err(spec_err(
                            format!("frames[{i}].rotation.axis"),
                            format!("axis `{}` is not x, y, z, -x, -y or -z", r.axis),
                        ));
                    }
                };
                let angle = names
                    .parse(&r.angle, Context::Angle)
                    .and_then(|a| {
                        linear_angle(&a, &|p| angle_params.contains(&p), &|c| {
                            spec.coordinates[c].kind == CoordinateKind::Angle
                        })?;
                        Ok(a)
                    })
                    .map_err(|m| spec_err(format!("frames[{i}].rotation.angle"), m))?;
                Some((axis, sign, angle))
            }
        };
        let origin = match &f.origin {
            None => 0,
            Some(o) => *point_index.get(o).ok_or_else(|| {
                spec_err(
                    format!("frames[{i}].origin"),
                    format!("unknown point `{o}`"),
                )
            })?,
        };
        frames.push(FrameInfo {
            name: f.name.clone(),
            parent: frame_index[&f.parent],
            rotation,
            origin,
        });
    }

    // Solids.
    let mut solid_index = BTreeMap::new();
    unique(
        "solid",
        "solids",
        spec.solids.iter().map(|s| s.name.as_str()),
        &mut solid_index,
    )?;
    let mut solids = Vec::with_capacity(spec.solids.len());
    for (i, s) in spec.solids.iter().enumerate() {
        let path = format!("solids[{i}]");
        let frame = *frame_index.get(&s.frame).ok_or_else(|| {
            spec_err(
                format!("{path}.frame"),
                format!("unknown frame `{}`", s.frame),
            )
        })?;
        let mass = names
            .parse(&s.mass, Context::Constant)
            .map_err(|m| spec_err(format!("{path}.mass"), m))?;
        let centre = *point_index.get(&s.centre).ok_or_else(|| {
            spec_err(
                format!("{path}.centre"),
                format!("unknown point `{}`", s.centre),
            )
        })?;
        let inertia = match &s.inertia {
            None => None,
            Some(inr) => {
                let point = *point_index.get(&inr.point).ok_or_else(|| {
                    spec_err(
                        format!("{path}.inertia.point"),
                        format!("unknown point `{}`", inr.point),
                    )
                })?;
                let basis = *frame_index.get(&inr.basis).ok_or_else(|| {
                    spec_err(
                        format!("{path}.inertia.basis"),
                        format!("unknown frame `{}`", inr.basis),
                    )
                })?;
                let mut err = None;
                let matrix: [[Node; 3]; 3] = std::array::from_fn(|r| {
                    std::array::from_fn(|c| {
                        names
                            .parse(&inr.matrix[r][c], Context::Constant)
                            .unwrap_or_else(|m| {
                                err.get_or_insert(spec_err(
                                    format!("{path}.inertia.matrix[{r}][{c}]"),
                                    m,
                                ));
                                Node::Num(0.0)
                            })
                    })
                });
                if let Some(e) = err {
                    return Err(e);
                }
                symmetric(&matrix, spec.parameters.len())
                    .map_err(|m| spec_err(format!("{path}.inertia.matrix"), m))?;
                fixed_in_solid(&frames, basis, frame, &matrix, spec)
                    .map_err(|m| spec_err(format!("{path}.inertia.basis"), m))?;
                Some(InertiaInfo {
                    point,
                    basis,
                    matrix,
                    text: inr.matrix.clone(),
                })
            }
        };
        let mut symmetries = Vec::new();
        for (k, sym) in s.symmetries.iter().enumerate() {
            let (txt, revolution) = match sym {
                SymmetrySpec::Plane { normal } => (normal, false),
                SymmetrySpec::Revolution { axis } => (axis, true),
            };
            let (f, axis) = names.basis_vector(txt).ok_or_else(|| {
                spec_err(
                    format!("{path}.symmetries[{k}]"),
                    format!("`{txt}` is not a basis vector such as x1"),
                )
            })?;
            symmetries.push(Symmetry {
                frame: f,
                axis,
                revolution,
            });
        }
        solids.push(SolidInfo {
            name: s.name.clone(),
            frame,
            mass,
            centre,
            inertia,
            symmetries,
        });
    }

    // Sets.
    let mut sets = BTreeMap::new();
    for (name, members) in &spec.sets {
        let path = format!("sets.{name}");
        if crate::quantity::check_name(name).is_err() {
            return Err(spec_err(
                path,
                format!("set name `{name}` is not a valid name"),
            ));
        }
        if solid_index.contains_key(name) {
            return Err(spec_err(
                path,
                format!("`{name}` is both a set and a solid"),
            ));
        }
        if members.is_empty() {
            return Err(spec_err(path, "a set holds at least one solid"));
        }
        let mut list = Vec::new();
        for (k, m) in members.iter().enumerate() {
            let s = *solid_index
                .get(m)
                .ok_or_else(|| spec_err(format!("{path}[{k}]"), format!("unknown solid `{m}`")))?;
            if list.contains(&s) {
                return Err(spec_err(
                    format!("{path}[{k}]"),
                    format!("solid `{m}` listed twice"),
                ));
            }
            list.push(s);
        }
        sets.insert(name.clone(), list);
    }

    // Hypotheses.
    let mut hypotheses = BTreeMap::new();
    for (i, h) in spec.hypotheses.iter().enumerate() {
        let path = format!("hypotheses[{i}]");
        let mut symmetric_solids = Vec::new();
        for (k, s) in h.symmetric_solids.iter().enumerate() {
            let sp = format!("{path}.symmetric_solids[{k}]");
            let si = *solid_index
                .get(s)
                .ok_or_else(|| spec_err(&sp, format!("unknown solid `{s}`")))?;
            symmetric_solids.push(si);
            symmetries_hold(&solids[si], spec.parameters.len()).map_err(|m| spec_err(&sp, m))?;
        }
        let mut constant_rates = Vec::new();
        for (k, q) in h.constant_rates.iter().enumerate() {
            constant_rates.push(*coord_index.get(q).ok_or_else(|| {
                spec_err(
                    format!("{path}.constant_rates[{k}]"),
                    format!("unknown coordinate `{q}`"),
                )
            })?);
        }
        if hypotheses
            .insert(
                h.name.clone(),
                Hypothesis {
                    symmetric_solids,
                    constant_rates,
                },
            )
            .is_some()
        {
            return Err(spec_err(
                format!("{path}.name"),
                format!("hypothesis `{}` is defined twice", h.name),
            ));
        }
    }

    // Parameters: which ones are drawn positive (lengths, masses).
    let mut in_masses = std::collections::BTreeSet::new();
    for s in &solids {
        expr::params_in(&s.mass, &mut in_masses);
    }
    let params = spec
        .parameters
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let unit = p.unit.as_deref().map(str::trim).unwrap_or("");
            ParamInfo {
                name: p.name.clone(),
                positive: in_masses.contains(&i)
                    || matches!(unit, "m" | "mm" | "cm" | "km" | "kg" | "g"),
            }
        })
        .collect();

    let model = NumericModel {
        params,
        coords,
        frames,
        points,
        solids,
        sets,
        hypotheses,
        param_index,
        coord_index,
        frame_index,
        point_index,
        solid_index,
        dynamics: Default::default(),
    };
    Ok(model)
}

/// Marks gravity, friction coefficients and stiffnesses, once the PFD is read, to be drawn
/// positive, like lengths.
pub(super) fn mark_positive(model: &mut NumericModel) {
    let dy = &model.dynamics;
    let mut positive = std::collections::BTreeSet::new();
    for node in dy.gravity.iter().chain(dy.links.iter().flat_map(|l| {
        l.friction
            .iter()
            .chain(l.spring.iter().map(|s| &s.stiffness))
    })) {
        expr::params_in(node, &mut positive);
    }
    for i in positive {
        model.params[i].positive = true;
    }
}

/// An inertia operator is symmetric: entries [r][c] and [c][r] agree at two draws of the
/// parameters (integers 2, 3, 5, … and then their squares: two polynomials that differ give
/// different values there unless by coincidence at both).
fn symmetric(matrix: &[[Node; 3]; 3], nparams: usize) -> Result<(), String> {
    for draw in 0..2 {
        let params = check_draw(nparams, draw);
        let env = expr::Env::<f64> {
            params: &params,
            coords: &[],
            rates: &[],
            frames: &[],
        };
        for (r, c) in [(0, 1), (0, 2), (1, 2)] {
            let (a, b) = (
                expr::eval_scalar(&matrix[r][c], &env)?,
                expr::eval_scalar(&matrix[c][r], &env)?,
            );
            if (a - b).abs() > 1e-9 * a.abs().max(b.abs()).max(1.0) {
                return Err(format!(
                    "the inertia matrix is not symmetric: entries [{r}][{c}] and [{c}][{r}] differ"
                ));
            }
        }
    }
    Ok(())
}

/// The angle of an elementary rotation is, as the course turns its frames, an integer
/// combination of angle coordinates and angle parameters plus a multiple of π/2 (a constant
/// angle with exact cos and sin); anything else is refused.
fn linear_angle(
    node: &Node,
    angle_param: &dyn Fn(usize) -> bool,
    angle_coord: &dyn Fn(usize) -> bool,
) -> Result<(), String> {
    // The form as (coefficient of each variable, constant), with the variables as
    // (0, param) or (1, coordinate).
    type Form = (BTreeMap<(u8, usize), f64>, f64);
    fn walk(
        n: &Node,
        angle_param: &dyn Fn(usize) -> bool,
        angle_coord: &dyn Fn(usize) -> bool,
    ) -> Result<Form, String> {
        let not_linear = || "an angle is an integer combination of angles and π/2".to_string();
        let constant = |f: &Form| f.0.values().all(|c| *c == 0.0).then_some(f.1);
        Ok(match n {
            Node::Num(x) => (BTreeMap::new(), *x),
            Node::Param(p) if angle_param(*p) => (BTreeMap::from([((0, *p), 1.0)]), 0.0),
            Node::Coord(c) if angle_coord(*c) => (BTreeMap::from([((1, *c), 1.0)]), 0.0),
            Node::Param(_) | Node::Coord(_) => {
                return Err(
                    "this name is not an angle: an angle is an angle coordinate or a \
                            parameter declared with \"kind\": \"angle\""
                        .to_string(),
                );
            }
            Node::Neg(a) => {
                let (v, k) = walk(a, angle_param, angle_coord)?;
                (v.into_iter().map(|(x, c)| (x, -c)).collect(), -k)
            }
            Node::Add(a, b) | Node::Sub(a, b) => {
                let sign = if matches!(n, Node::Sub(..)) {
                    -1.0
                } else {
                    1.0
                };
                let (mut v, k) = walk(a, angle_param, angle_coord)?;
                let (w, l) = walk(b, angle_param, angle_coord)?;
                for (x, c) in w {
                    *v.entry(x).or_insert(0.0) += sign * c;
                }
                (v, k + sign * l)
            }
            Node::Mul(a, b) => {
                let (fa, fb) = (
                    walk(a, angle_param, angle_coord)?,
                    walk(b, angle_param, angle_coord)?,
                );
                let (f, k) = match (constant(&fa), constant(&fb)) {
                    (Some(k), _) => (fb, k),
                    (None, Some(k)) => (fa, k),
                    (None, None) => return Err(not_linear()),
                };
                (f.0.into_iter().map(|(x, c)| (x, c * k)).collect(), f.1 * k)
            }
            Node::Div(a, b) => {
                let fa = walk(a, angle_param, angle_coord)?;
                let k = constant(&walk(b, angle_param, angle_coord)?).ok_or_else(not_linear)?;
                (
                    fa.0.into_iter().map(|(x, c)| (x, c / k)).collect(),
                    fa.1 / k,
                )
            }
            Node::Pow(a, e) => {
                let k = constant(&walk(a, angle_param, angle_coord)?).ok_or_else(not_linear)?;
                (BTreeMap::new(), k.powi(*e))
            }
            _ => return Err(not_linear()),
        })
    }
    let (vars, k) = walk(node, angle_param, angle_coord)?;
    if vars.values().any(|c| c.fract() != 0.0) {
        return Err(
            "an angle takes integer multiples of the angle coordinates and angle \
                    parameters"
                .to_string(),
        );
    }
    let quarter_turns = k / std::f64::consts::FRAC_PI_2;
    if (quarter_turns - quarter_turns.round()).abs() > 1e-9 {
        return Err("a constant angle written with numbers must be a multiple of pi/2".to_string());
    }
    Ok(())
}

/// Parameter values for the checks at build time: integers 2, 3, 5, … (`draw` 0) and then
/// their square roots shifted (`draw` 1), so that two polynomials that differ give different
/// values at one of them unless by coincidence at both.
fn check_draw(n: usize, draw: usize) -> Vec<f64> {
    const PRIMES: [f64; 12] = [
        2.0, 3.0, 5.0, 7.0, 11.0, 13.0, 17.0, 19.0, 23.0, 29.0, 31.0, 37.0,
    ];
    (0..n)
        .map(|i| {
            let p = PRIMES[i % PRIMES.len()] + (i / PRIMES.len()) as f64 / 7.0;
            if draw == 0 { p } else { p.sqrt() + 0.5 }
        })
        .collect()
}

/// An inertia matrix given in a basis `b` other than its solid's frame `f` must describe the
/// same body however the coordinates move: moved to f (I_f = C I_b Cᵀ, C = R_fᵀ R_b), it is
/// the same at three positions of the mechanism. A basis turning relative to the solid is
/// refused unless the matrix is of revolution about the relative rotation's axis.
fn fixed_in_solid(
    frames: &[FrameInfo],
    b: usize,
    f: usize,
    matrix: &[[Node; 3]; 3],
    spec: &SpecFile,
) -> Result<(), String> {
    if b == f {
        return Ok(());
    }
    let params = check_draw(spec.parameters.len(), 1);
    let value = |node: &Node, coords: &[f64]| {
        let env = expr::Env::<f64> {
            params: &params,
            coords,
            rates: &[],
            frames: &[],
        };
        expr::eval_scalar(node, &env)
    };
    let ib = Matrix3::from_fn(|r, c| value(&matrix[r][c], &[]).unwrap_or(f64::NAN));
    let mut seen: Vec<Matrix3<f64>> = Vec::new();
    for draw in 0..3 {
        let coords: Vec<f64> = (0..spec.coordinates.len())
            .map(|i| 0.3 + 0.7 * draw as f64 + 0.11 * i as f64)
            .collect();
        // Orientations down the tree, parents first: R_k = R_parent · Rot(axis, ±angle).
        let mut rot: Vec<Matrix3<f64>> = Vec::with_capacity(frames.len());
        for fr in frames {
            let r = match &fr.rotation {
                None if rot.is_empty() => Matrix3::identity(),
                None => rot[fr.parent],
                Some((axis, sign, angle)) => {
                    let a = sign * value(angle, &coords)?;
                    let axis = nalgebra::Unit::new_unchecked(Vector3::ith(*axis, 1.0));
                    rot[fr.parent] * nalgebra::Rotation3::from_axis_angle(&axis, a).into_inner()
                }
            };
            rot.push(r);
        }
        let c = rot[f].transpose() * rot[b];
        seen.push(c * ib * c.transpose());
    }
    let size = ib.amax().max(1.0);
    if seen.iter().all(|m| (m - seen[0]).amax() <= 1e-9 * size) {
        Ok(())
    } else {
        Err(format!(
            "the inertia matrix is given in basis {} which turns relative to the solid's frame \
             {}: give it in the solid's basis (or in a basis where it is of revolution about \
             the relative rotation axis)",
            frames[b].name, frames[f].name
        ))
    }
}

/// A hypothesis that makes a solid symmetric imposes its symmetries on the written matrix: a
/// product of inertia across a plane of symmetry (or about an axis of revolution) is zero,
/// and the two moments about an axis of revolution are equal. Each imposed entry must be
/// zero or equal already, or a single parameter that the hypothesis then sets.
fn symmetries_hold(solid: &SolidInfo, nparams: usize) -> Result<(), String> {
    let Some(inr) = &solid.inertia else {
        return Ok(());
    };
    // The parameter an entry is, up to its sign.
    let single = |n: &Node| match n {
        Node::Param(p) => Some(*p),
        Node::Neg(a) => match **a {
            Node::Param(p) => Some(p),
            _ => None,
        },
        _ => None,
    };
    // Parameters the hypothesis has already set, and their value: no longer free.
    let mut set: BTreeMap<usize, Node> = BTreeMap::new();
    let draws: Vec<Vec<f64>> = (0..2).map(|d| check_draw(nparams, d)).collect();
    let value = |n: &Node, params: &[f64]| {
        let env = expr::Env::<f64> {
            params,
            coords: &[],
            rates: &[],
            frames: &[],
        };
        expr::eval_scalar(n, &env).unwrap_or(f64::NAN)
    };
    let same = |a: &Node, b: &Node| {
        draws.iter().all(|p| {
            let (x, y) = (value(a, p), value(b, p));
            (x - y).abs() <= 1e-9 * x.abs().max(y.abs()).max(1.0)
        })
    };
    let zero = Node::Num(0.0);
    for sym in &solid.symmetries {
        if sym.frame != inr.basis {
            continue;
        }
        let k = sym.axis;
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let mut zeros = vec![(k.min(i), k.max(i)), (k.min(j), k.max(j))];
        if sym.revolution {
            zeros.push((i.min(j), i.max(j)));
        }
        for (r, c) in zeros {
            let e = &inr.matrix[r][c];
            if same(e, &zero) {
                continue;
            }
            match single(e) {
                Some(p) => {
                    set.entry(p).or_insert(Node::Num(0.0));
                }
                None => {
                    return Err(format!(
                        "the symmetries of solid {} make entry [{r}][{c}] zero, but it is `{}`, \
                         which is not a single parameter",
                        solid.name, inr.text[r][c]
                    ));
                }
            }
        }
        if sym.revolution {
            let (a, b) = (i.min(j), i.max(j));
            // Through what the hypothesis has set already (B = A, then C = B is C = A).
            let resolved = |n: &Node| match single(n).and_then(|p| set.get(&p)) {
                Some(v) => v.clone(),
                None => n.clone(),
            };
            let (ea, eb) = (resolved(&inr.matrix[a][a]), resolved(&inr.matrix[b][b]));
            if same(&ea, &eb) {
                continue;
            }
            match single(&eb).filter(|p| !set.contains_key(p)) {
                Some(p) => {
                    set.insert(p, ea);
                }
                None => {
                    return Err(format!(
                        "the axis of revolution of solid {} makes entries [{a}][{a}] and \
                         [{b}][{b}] equal, but `{}` is not a single parameter",
                        solid.name, inr.text[b][b]
                    ));
                }
            }
        }
    }
    Ok(())
}
