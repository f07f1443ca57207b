//! Building a [`NumericModel`] from a spec: names, frame and point trees, parsed expressions.

use super::expr::{self, Kind, Name, Node};
use super::validate::{
    divisors, fixed_in_solid, linear_angle, rate_degree, symmetric, symmetries_hold,
};
use super::{
    CoordInfo, FrameInfo, Hypothesis, InertiaInfo, NumericError, NumericModel, ParamInfo,
    PointInfo, SolidInfo, Symmetry,
};
use crate::resolve::Resolved;
use crate::wire::{CoordinateKind, ParameterKind, SpecFile, SymmetrySpec};
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
    /// The aliases read so far, (name, value), in order.
    pub aliases: &'a [(String, Node)],
    /// Basis vectors named as the statement does (`u`): (frame index, axis).
    pub vectors: &'a BTreeMap<String, (usize, usize)>,
}

impl Names<'_> {
    /// A basis vector: a name the spec gives one (`u`), or `x2` split into (frame index, axis)
    /// when frame `2` exists.
    pub fn basis_vector(&self, s: &str) -> Option<(usize, usize)> {
        if let Some(v) = self.vectors.get(s) {
            return Some(*v);
        }
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
            if let Some(i) = self.aliases.iter().position(|(n, _)| n == name) {
                return Ok(Name::Alias(i));
            }
            if let Some(i) = unknowns.get(name) {
                return Ok(Name::Unknown(*i));
            }
            if name == "t" {
                return match ctx {
                    Context::Constant | Context::ConstantVector => {
                        Err("the time `t` cannot appear here: only parameters can".to_string())
                    }
                    _ => Ok(Name::Time),
                };
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
        let values: Vec<Node> = self.aliases.iter().map(|(_, v)| v.clone()).collect();
        let node = expr::parse(
            text,
            &resolve,
            matches!(ctx, Context::Instant | Context::Action),
            &values,
        )?;
        let k = expr::kind(&node)?;
        divisors(&node)?;
        expr::validate_time(&node, ctx == Context::Angle)?;
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

/// Builds the model from the spec and its names and trees, resolved once for both sides
/// (parameters, coordinates and aliases in one namespace, the statement's names of basis
/// vectors, each frame after its parent, each point after the point it is placed from, every
/// reference found); every error names the JSON path of the faulty value.
pub(super) fn build(spec: &SpecFile, trees: &Resolved) -> Result<NumericModel, NumericError> {
    let owned = |m: &BTreeMap<&str, usize>| -> BTreeMap<String, usize> {
        m.iter().map(|(n, i)| (n.to_string(), *i)).collect()
    };
    let mut param_index = owned(&trees.names.params);
    // A trial motion's unknowns are scalars drawn as the parameters, after them.
    for (k, u) in trial_unknowns(spec).into_iter().enumerate() {
        param_index.insert(u, spec.parameters.len() + k);
    }
    let coord_index = owned(&trees.names.coords);
    let vectors: BTreeMap<String, (usize, usize)> = (trees.names.vectors.iter())
        .map(|(n, v)| (n.to_string(), *v))
        .collect();

    let angle_params: Vec<usize> = (0..spec.parameters.len())
        .filter(|&i| spec.parameters[i].kind == ParameterKind::Angle)
        .collect();

    let frame_index = trees.frame_positions();
    let aliases = aliases(spec, &param_index, &coord_index, &frame_index, &vectors)?;
    let names = Names {
        params: &param_index,
        coords: &coord_index,
        frames: &frame_index,
        aliases: &aliases,
        vectors: &vectors,
    };

    let coords = coordinates(spec, &names)?;

    let point_index = trees.point_positions();
    let points = points(spec, &names, trees)?;
    let frames = frames(spec, &names, trees, &angle_params)?;

    // Solids: named and referenced in the trees.
    let solid_index: BTreeMap<String, usize> = trees
        .solids
        .iter()
        .enumerate()
        .map(|(i, s)| (s.name.to_string(), i))
        .collect();
    let solids = solids(spec, &names, trees, &frames)?;

    // Sets, as resolved.
    let sets = (trees.sets.iter())
        .map(|(n, list)| (n.to_string(), list.clone()))
        .collect();

    let hypotheses = hypotheses(spec, &names, &solids, &coords, trees)?;
    let params = parameters(spec, &solids);

    Ok(NumericModel {
        params,
        aliases,
        vectors,
        uses_time: false,
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
        closures: Vec::new(),
        rolling: Vec::new(),
        helices: Vec::new(),
    })
}

/// The aliases: named expressions of the parameters, each reading those before it.
fn aliases(
    spec: &SpecFile,
    param_index: &BTreeMap<String, usize>,
    coord_index: &BTreeMap<String, usize>,
    frame_index: &BTreeMap<String, usize>,
    vectors: &BTreeMap<String, (usize, usize)>,
) -> Result<Vec<(String, Node)>, NumericError> {
    let mut aliases: Vec<(String, Node)> = Vec::new();
    for (i, a) in spec.aliases.iter().enumerate() {
        let names = Names {
            params: param_index,
            coords: coord_index,
            frames: frame_index,
            aliases: &aliases,
            vectors,
        };
        let v = names
            .parse(&a.value, Context::Constant)
            .map_err(|m| spec_err(format!("aliases[{i}].value"), m))?;
        aliases.push((a.name.clone(), v));
    }
    Ok(aliases)
}

/// The coordinates, each with its imposed rate or the relation that drives it.
fn coordinates(spec: &SpecFile, names: &Names) -> Result<Vec<CoordInfo>, NumericError> {
    spec.coordinates
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let path = format!("coordinates[{i}].rate");
            let (rate, driven) = match c.rate.as_ref() {
                None => (None, false),
                Some(r) => match names.parse(r, Context::Constant) {
                    Ok(node) => (Some(node), false),
                    // A relation between coordinates: affine in the rates of the others.
                    Err(constant) => {
                        let node = names
                            .parse(r, Context::Instant)
                            .map_err(|_| spec_err(&path, constant.clone()))?;
                        let free = |j: usize| j != i && spec.coordinates[j].rate.is_none();
                        match rate_degree(&node, &free) {
                            Ok(1) => (Some(node), true),
                            _ => return Err(spec_err(&path, constant)),
                        }
                    }
                },
            };
            Ok(CoordInfo {
                name: c.name.clone(),
                kind: c.kind,
                rate,
                rate_text: c.rate.clone(),
                driven,
            })
        })
        .collect::<Result<Vec<_>, NumericError>>()
}

/// The points, in the resolved order, each placed from its parent.
fn points(
    spec: &SpecFile,
    names: &Names,
    trees: &Resolved,
) -> Result<Vec<PointInfo>, NumericError> {
    let mut points = Vec::with_capacity(trees.points.len());
    for node in &trees.points {
        let position = match node.spec {
            None => Node::Num(0.0),
            Some(i) => names
                .parse(&spec.points[i].position, Context::Position)
                .map_err(|m| spec_err(format!("points[{i}].position"), m))?,
        };
        points.push(PointInfo {
            name: node.name.to_string(),
            from: node.from,
            position,
        });
    }

    Ok(points)
}

/// The frames, in the resolved order: each turned from its parent about one of its axes by
/// an angle of its own reading.
fn frames(
    spec: &SpecFile,
    names: &Names,
    trees: &Resolved,
    angle_params: &[usize],
) -> Result<Vec<FrameInfo>, NumericError> {
    let mut frames = vec![FrameInfo {
        name: spec.ground.clone(),
        parent: 0,
        rotation: None,
        origin: 0,
    }];
    for node in &trees.frames[1..] {
        let i = node.spec.expect("a frame of the spec");
        let f = &spec.frames[i];
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
        frames.push(FrameInfo {
            name: f.name.clone(),
            parent: node.parent,
            rotation,
            origin: node.origin,
        });
    }

    Ok(frames)
}

/// The solids: mass, centre, inertia matrix (symmetric, fixed in the solid) and symmetries.
fn solids(
    spec: &SpecFile,
    names: &Names,
    trees: &Resolved,
    frames: &[FrameInfo],
) -> Result<Vec<SolidInfo>, NumericError> {
    let mut solids = Vec::with_capacity(spec.solids.len());
    for ((i, s), node) in spec.solids.iter().enumerate().zip(&trees.solids) {
        let path = format!("solids[{i}]");
        let frame = node.frame;
        let (mass, centre) = mass_and_centre(s, names, trees, node, &path)?;
        let inertia = match (&s.inertia, node.inertia) {
            (None, _) | (_, None) => None,
            (Some(inr), Some((point, basis))) => {
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
                fixed_in_solid(frames, basis, frame, &matrix, spec)
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

    Ok(solids)
}

/// A solid's mass and centre. A body of negligible mass: no mass written (or 0), no centre
/// needed (its frame's origin stands for it); its point cloud is empty, so it adds nothing
/// to any moment, resultant or energy.
fn mass_and_centre(
    s: &crate::wire::SolidSpec,
    names: &Names,
    trees: &Resolved,
    node: &crate::resolve::SolidNode,
    path: &str,
) -> Result<(Node, usize), NumericError> {
    let mass = match &s.mass {
        Some(t) => names
            .parse(t, Context::Constant)
            .map_err(|m| spec_err(format!("{path}.mass"), m))?,
        None => Node::Num(0.0),
    };
    let centre = match node.centre {
        Some(c) => c,
        None => {
            massless_body(s, &mass, path)?;
            trees.frames[node.frame].origin
        }
    };
    if s.massless || mass == Node::Num(0.0) {
        massless_body(s, &mass, path)?;
    }
    Ok((mass, centre))
}

/// A solid without a centre, or declared of negligible mass: it must be one (`massless`, or
/// no mass, or a mass of 0) and then have no inertia operator and no symmetries.
fn massless_body(s: &crate::wire::SolidSpec, mass: &Node, path: &str) -> Result<(), NumericError> {
    let zero = *mass == Node::Num(0.0);
    if s.mass.is_none() && !s.massless {
        return Err(spec_err(
            format!("{path}.mass"),
            "missing: a solid has a mass, or is declared `\"massless\": true`",
        ));
    }
    if !(s.massless || zero) {
        return Err(spec_err(
            format!("{path}.centre"),
            "missing: a solid with a mass has a centre of inertia",
        ));
    }
    if s.massless && !zero {
        return Err(spec_err(
            format!("{path}.mass"),
            "a solid declared `\"massless\": true` has no mass",
        ));
    }
    if s.inertia.is_some() {
        return Err(spec_err(
            format!("{path}.inertia"),
            "a body of negligible mass has no inertia operator",
        ));
    }
    if !s.symmetries.is_empty() {
        return Err(spec_err(
            format!("{path}.symmetries[0]"),
            "a body of negligible mass has no symmetry to declare",
        ));
    }
    Ok(())
}

/// The hypotheses: the solids whose symmetries they use, the rates they hold constant, the
/// motions and relations they impose.
fn hypotheses(
    spec: &SpecFile,
    names: &Names,
    solids: &[SolidInfo],
    coords: &[CoordInfo],
    trees: &Resolved,
) -> Result<BTreeMap<String, Hypothesis>, NumericError> {
    let mut hypotheses = BTreeMap::new();
    for ((i, h), node) in spec.hypotheses.iter().enumerate().zip(&trees.hypotheses) {
        let path = format!("hypotheses[{i}]");
        let mut symmetric_solids = Vec::new();
        for (k, &si) in node.symmetric_solids.iter().enumerate() {
            let sp = format!("{path}.symmetric_solids[{k}]");
            symmetric_solids.push(si);
            symmetries_hold(&solids[si], spec.parameters.len()).map_err(|m| spec_err(&sp, m))?;
        }
        let mut constant_rates = Vec::new();
        for (k, (q, &i)) in h
            .constant_rates
            .iter()
            .zip(&node.constant_rates)
            .enumerate()
        {
            // Its q̈ follows the others' rates: hold those constant instead.
            if coords[i].driven {
                return Err(spec_err(
                    format!("{path}.constant_rates[{k}]"),
                    format!("`{q}` is driven by other coordinates' rates"),
                ));
            }
            constant_rates.push(i);
        }
        let (motions, relations) = held_motions(spec, names, names.coords, names.params, h, &path)?;
        let trial = match &h.trial {
            None => None,
            Some(t) => {
                let c = *(names.coords.get(&t.coordinate)).ok_or_else(|| {
                    spec_err(
                        format!("{path}.trial.coordinate"),
                        format!("unknown coordinate `{}`", t.coordinate),
                    )
                })?;
                let node = (names.parse(&t.motion, Context::Instant))
                    .map_err(|m| spec_err(format!("{path}.trial.motion"), m))?;
                trial_unknowns_held(names, &node, &t.unknowns, &path)?;
                Some((c, node))
            }
        };
        // Small parameters: results kept to first order, which no sample realises; only
        // their names are checked here (`check` does not compare such a hypothesis).
        for (k, p) in h.small_parameters.iter().enumerate() {
            let field = format!("{path}.small_parameters[{k}]");
            if !names.params.contains_key(p) {
                return Err(spec_err(&field, format!("unknown parameter `{p}`")));
            }
            if h.small_parameters[..k].contains(p) {
                return Err(spec_err(&field, format!("`{p}` is small twice")));
            }
        }
        hypotheses.insert(
            h.name.clone(),
            Hypothesis {
                symmetric_solids,
                constant_rates,
                motions,
                relations,
                trial,
            },
        );
    }
    Ok(hypotheses)
}

/// Each unknown of a trial motion named once and held by its motion `node`.
fn trial_unknowns_held(
    names: &Names,
    node: &Node,
    unknowns: &[String],
    path: &str,
) -> Result<(), NumericError> {
    let mut held = std::collections::BTreeSet::new();
    expr::params_in(node, &mut held);
    for (k, u) in unknowns.iter().enumerate() {
        let field = format!("{path}.trial.unknowns[{k}]");
        if unknowns[..k].contains(u) {
            return Err(spec_err(&field, format!("`{u}` is listed twice")));
        }
        if !names.params.get(u).is_some_and(|i| held.contains(i)) {
            return Err(spec_err(&field, format!("the motion does not hold `{u}`")));
        }
    }
    Ok(())
}

/// The unknowns of the spec's trial motions, in order.
fn trial_unknowns(spec: &SpecFile) -> Vec<String> {
    (spec.hypotheses.iter())
        .filter_map(|h| h.trial.as_ref())
        .flat_map(|t| t.unknowns.iter().cloned())
        .collect()
}

/// The parameters, those drawn positive marked (lengths, masses), then the trial motions'
/// unknowns.
fn parameters(spec: &SpecFile, solids: &[SolidInfo]) -> Vec<ParamInfo> {
    let mut in_masses = std::collections::BTreeSet::new();
    for s in solids {
        expr::params_in(&s.mass, &mut in_masses);
    }
    spec.parameters
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
        .chain((trial_unknowns(spec).into_iter()).map(|name| ParamInfo {
            name,
            positive: false,
        }))
        .collect()
}

/// Marks gravity, frictions and stiffnesses, once the PFD is read, to be drawn positive.
pub(super) fn mark_positive(model: &mut NumericModel) {
    let dy = &model.dynamics;
    let mut positive = std::collections::BTreeSet::new();
    for node in dy.gravity.iter().chain(dy.links.iter().flat_map(|l| {
        l.friction
            .iter()
            .chain(l.coulomb.iter().map(|c| &c.0))
            .chain(l.law.iter().map(|c| &c.coefficient))
            .chain(l.spring.iter().map(|s| &s.stiffness))
    })) {
        expr::params_in(node, &mut positive);
    }
    for i in positive {
        model.params[i].positive = true;
    }
}

/// A hypothesis' fixed coordinates, equilibrium, given rates and relations, resolved:
/// (coordinate, value, rate) and (parameter, expression).
#[allow(clippy::type_complexity)]
fn held_motions(
    spec: &SpecFile,
    names: &Names,
    coord_index: &BTreeMap<String, usize>,
    param_index: &BTreeMap<String, usize>,
    h: &crate::wire::HypothesisSpec,
    path: &str,
) -> Result<(Vec<(usize, Option<Node>, Option<Node>)>, Vec<(usize, Node)>), NumericError> {
    let mut motions: Vec<(usize, Option<Node>, Option<Node>)> = Vec::new();
    let coord = |field: &str, c: &str, motions: &[(usize, Option<Node>, Option<Node>)]| {
        let i = *coord_index
            .get(c)
            .ok_or_else(|| spec_err(field, format!("unknown coordinate `{c}`")))?;
        if spec.coordinates[i].rate.is_some() {
            return Err(spec_err(
                field,
                format!("`{c}` has an imposed rate already"),
            ));
        }
        if motions.iter().any(|(j, _, _)| *j == i) {
            return Err(spec_err(field, format!("`{c}` is given two motions")));
        }
        Ok(i)
    };
    let constant = |field: &str, text: &str| {
        names
            .parse(text, Context::Constant)
            .map_err(|m| spec_err(field, m))
    };
    for (k, c) in h.fixed_coordinates.iter().enumerate() {
        let i = coord(&format!("{path}.fixed_coordinates[{k}]"), c, &motions)?;
        motions.push((i, None, None));
    }
    for (c, text) in &h.equilibrium {
        let field = format!("{path}.equilibrium.{c}");
        let i = coord(&field, c, &motions)?;
        let t = text.trim();
        if spec.coordinates[i].kind == CoordinateKind::Angle
            && t != "0"
            && !spec
                .parameters
                .iter()
                .any(|p| p.name == t && p.kind == ParameterKind::Angle)
        {
            return Err(spec_err(
                &field,
                format!("an angle is held at 0 or at a parameter of kind angle, not at `{t}`"),
            ));
        }
        motions.push((i, Some(constant(&field, t)?), None));
    }
    for (c, text) in &h.rates {
        let field = format!("{path}.rates.{c}");
        let i = coord(&field, c, &motions)?;
        motions.push((i, None, Some(constant(&field, text)?)));
    }
    let mut relations = Vec::new();
    for (p, text) in &h.relations {
        let field = format!("{path}.relations.{p}");
        let i = *param_index
            .get(p)
            .ok_or_else(|| spec_err(&field, format!("unknown parameter `{p}`")))?;
        let node = constant(&field, text)?;
        let mut used = std::collections::BTreeSet::new();
        expr::params_in(&node, &mut used);
        if used.contains(&i) {
            return Err(spec_err(&field, format!("`{p}` is defined by itself")));
        }
        // The sign of a dry friction's sliding velocity, at the limit of sliding: ±1.
        let sign = (spec.links.iter()).any(|l| l.sign_parameter().as_deref() == Some(p.as_str()));
        let unit = used.is_empty()
            && expr::eval_scalar(&node, &no_values()).is_ok_and(|x: f64| x.abs() == 1.0);
        if sign && !unit {
            return Err(spec_err(
                &field,
                format!("the sign `{p}` is set to 1 or -1"),
            ));
        }
        relations.push((i, node));
    }
    Ok((motions, relations))
}

/// An environment without values: for a constant written with numbers only.
fn no_values() -> expr::Env<'static, f64> {
    expr::Env {
        params: &[],
        coords: &[],
        rates: &[],
        frames: &[],
        time: 0.0,
    }
}
