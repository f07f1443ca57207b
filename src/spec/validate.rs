//! Validation of a spec into a [`Mechanism`]: every reference resolved, every expression
//! parsed, every error naming the JSON path of the offending value.

use super::SpecError;
use super::refusal::{at, bounded, expr_err, refused};
use super::solids::bodies;
use super::solved::Solved;
use super::texts::{expression_texts, free_text_limit, free_texts};
use crate::expr::{ExprError, Registry};
use crate::frame::{Angle, Axis, FrameId, Frames, Rotation};
use crate::mechanism::{Body, BodyId, Cause, Effect, Hypothesis, Mechanism, Stated};
use crate::point::{PointId, Points};
use crate::quantity::Quantity;
use crate::resolve::{Resolved, Unknowns};
use crate::vector::Vector;
use crate::wire::{CoordinateKind, ParameterKind, SpecFile};
use std::rc::Rc;

/// Solves a spec's loop closures and rolling conditions from the resolved spec (the
/// pipeline passes `spec/closures.rs`'s solver, which reads the loop on [`geometry`]).
pub(super) type Solver<'a> = &'a dyn Fn(&SpecFile, &Resolved) -> Result<Option<Solved>, SpecError>;

/// Builds the mechanism described by a spec, its closures solved by `solve`.
pub(super) fn build_solving(spec: &SpecFile, solve: Solver) -> Result<Mechanism, SpecError> {
    // Dry friction's signs are parameters of their own; loop closures and rolling conditions
    // give the dependent coordinates their rates (driven by the free ones), read on the
    // geometry alone; the mechanism keeps the spec as written.
    let signed = crate::resolve::with_signs(spec).map_err(refused)?;
    let written = spec;
    let spec = signed.as_ref();
    // Names, trees and references, and the PFD's unknowns named from this side's own reading
    // of which components each link transmits: resolved once for both sides.
    let resolved = crate::resolve::resolve(spec).map_err(refused)?;
    let transmitted = |kind, a: usize, d: Option<usize>, s: Option<usize>| {
        let axis = |k: usize| Axis::ALL[k];
        crate::pfd::transmitted(kind, axis(a), d.map(axis), s.map(axis))
    };
    let unknowns = crate::resolve::unknowns(spec, &resolved, &transmitted).map_err(refused)?;
    let solved = solve(spec, &resolved)?;
    build_with(spec, written, (&resolved, &unknowns), solved.as_ref())
}

/// The loop's geometry: the frames and points of `spec` (the closures' spec, which keeps
/// only what places them, see `spec/closures.rs`) over a registry of their own, and nothing
/// else. It exists because the dependent coordinates' rates are read on it: the mechanism's
/// registry imposes those rates, so it can only be built once they are solved, and it
/// inverts what they divide by.
pub(super) fn geometry(spec: &SpecFile, resolved: &Resolved) -> Result<Mechanism, SpecError> {
    let reg = registry(spec, &[], None)?;
    let frames = frames(spec, &reg, resolved)?;
    let points = points(spec, &reg, &frames, resolved)?;
    Ok(Mechanism {
        title: spec.title.clone(),
        description: None,
        frame_origins: resolved.frames.iter().map(|f| PointId(f.origin)).collect(),
        default_basis: frames.ground(),
        reg,
        frames,
        points,
        bodies: Vec::new(),
        sets: Default::default(),
        hypotheses: Vec::new(),
        quantities: Vec::new(),
        dynamics: Default::default(),
        links: Vec::new(),
        closures: Vec::new(),
        dependent: Vec::new(),
        statement: Default::default(),
        spec: spec.clone(),
        loop_law: None,
    })
}

/// [`build_solving`] once the closures are solved (`solved`, their dependent coordinates'
/// rates), resolved; `written` is the spec as the user wrote it, kept in the mechanism.
fn build_with(
    spec: &SpecFile,
    written: &SpecFile,
    (resolved, unknowns): (&Resolved, &Unknowns),
    solved: Option<&Solved>,
) -> Result<Mechanism, SpecError> {
    texts(spec)?;
    sources(spec)?;
    units(spec)?;
    let reg = registry(spec, &unknowns.names, solved)?;
    // The spec's own texts hold no root (see `Registry::refuse_roots_in_texts`).
    reg.refuse_roots_in_texts(true);

    let frames = frames(spec, &reg, resolved)?;
    let points = points(spec, &reg, &frames, resolved)?;
    let frame_origins = resolved.frames.iter().map(|f| PointId(f.origin)).collect();

    let bodies = bodies(spec, &reg, &frames, resolved)?;

    let sets = (resolved.sets.iter())
        .map(|(n, ids)| (n.to_string(), ids.iter().map(|&i| BodyId(i)).collect()))
        .collect();

    let hypotheses = hypotheses(spec, &reg, &bodies, resolved)?;

    let default_basis = match &spec.default_basis {
        None => frames.ground(),
        Some(b) => frames.find(b).ok_or_else(|| {
            let declared: Vec<&str> = frames.names().collect();
            let hint = crate::hint::suggestion(b, &declared);
            at("default_basis", format!("unknown frame `{b}`{hint}"))
        })?,
    };
    let mut quantities = Vec::new();
    for (i, q) in spec.quantities.iter().enumerate() {
        quantities
            .push(Quantity::parse(q).map_err(|e| at(format!("quantities[{i}]"), e.to_string()))?);
    }

    let statement = super::statement::statement(written, &reg, &hypotheses)?;
    let links = super::statement::links(written, &reg)?;
    let closures = super::statement::closures(written, &reg, &frames)?;
    let dependent = super::statement::dependent(written, &reg, solved);
    // The determinant the solved rates divide by, over this registry's variables (none when
    // it divides by what this registry does not invert: π, through a helical link's lead).
    let determinant = solved.and_then(|s| s.determinant.carried(&reg).ok());
    let explicit = solved.map_or(Vec::new(), |s| explicit_laws(&reg, s));

    let mut m = Mechanism {
        title: spec.title.clone(),
        description: spec.description.clone(),
        reg,
        frames,
        frame_origins,
        points,
        bodies,
        sets,
        hypotheses,
        default_basis,
        quantities,
        dynamics: Default::default(),
        links,
        closures,
        dependent,
        statement,
        spec: written.clone(),
        loop_law: solved.map(|s| crate::mechanism::LoopLaw {
            derivatives: s.derivatives.clone(),
            determinant,
            rolling: s.rolling.clone(),
            helical: s.helical.clone(),
            explicit: explicit.clone(),
        }),
    };
    m.dynamics = super::dynamics::build(&m, spec, (resolved, unknowns))?;
    requests(&m)?;
    super::scenarios::validate(&m)?;
    m.reg.refuse_roots_in_texts(false);
    Ok(m)
}

/// The free texts, after the shared resolution: one too long, or with a formula the answer
/// key could not print safely, refuses the spec.
fn texts(spec: &SpecFile) -> Result<(), SpecError> {
    for (path, text) in free_texts(spec) {
        let (max, what) = free_text_limit(&path);
        let n = text.chars().count();
        if n > max {
            return Err(at(
                path,
                format!("{n} characters: {what} may hold at most {max}"),
            ));
        }
        crate::latex::rich_text(text).map_err(|e| at(path, e.to_string()))?;
    }
    Ok(())
}

/// The sources the actions' torsors print ({T(poussée → 1)}), as texts: one the spec gives is
/// short, not blank, and holds no arrow. (That it is no other torsor's is resolved for both
/// sides, in [`crate::resolve`].)
fn sources(spec: &SpecFile) -> Result<(), SpecError> {
    for (i, a) in spec.actions.iter().enumerate() {
        let Some(s) = &a.source else {
            continue;
        };
        let path = format!("actions[{i}].source");
        let max = crate::wire::source::MAX_SOURCE_CHARS;
        let n = s.chars().count();
        if s.trim().is_empty() {
            return Err(at(
                path,
                "what exerts the action prints in {T(source→on)}: it may not be blank",
            ));
        }
        if n > max {
            return Err(at(
                path,
                format!(
                    "{n} characters: a source prints inside {{T(source→on)}} and may hold at most {max}"
                ),
            ));
        }
        if s.contains("\\overrightarrow") {
            return Err(at(
                path,
                "a source prints under the arrow of R(source→on): it may not hold \\overrightarrow",
            ));
        }
    }
    Ok(())
}

/// Each requested quantity, and each of the questions' quantities and equations, refers to
/// known objects of the built mechanism.
fn requests(m: &Mechanism) -> Result<(), SpecError> {
    for (i, q) in m.quantities.iter().enumerate() {
        crate::derivation::bind(m, q).map_err(|e| at(format!("quantities[{i}]"), e.to_string()))?;
    }
    for (i, qs) in m.statement.questions.iter().enumerate() {
        let quantities = (qs.quantities.iter()).map(|q| (format!("questions[{i}].quantities"), q));
        let equations =
            (qs.equations.iter()).map(|e| (format!("questions[{i}].equations"), &e.quantity));
        for (path, q) in quantities.chain(equations) {
            crate::derivation::bind(m, q).map_err(|e| at(&path, e.to_string()))?;
        }
    }
    Ok(())
}

/// The parameters' units: each a dimension, rad for an angle.
fn units(spec: &SpecFile) -> Result<(), SpecError> {
    for (i, p) in spec.parameters.iter().enumerate() {
        if let Some(u) = &p.unit {
            let path = format!("parameters[{i}].unit");
            let d = crate::units::Dimension::parse(u).map_err(|e| at(&path, e.to_string()))?;
            if p.kind == ParameterKind::Angle && !d.is_dimensionless() {
                return Err(at(
                    path,
                    format!(
                        "`{}` is an angle (\"kind\": \"angle\"): its unit is rad, not `{u}`",
                        p.name
                    ),
                ));
            }
        }
    }
    Ok(())
}

/// The angle coordinates that get a variable of their own besides cos and sin: a small
/// angle's (sin q ≈ q), a torsion spring's (½ k (q − q0)²), one an expression writes as
/// itself (a disc's centre at R*theta*x1).
fn raw_angles(spec: &SpecFile) -> Vec<String> {
    let angle =
        |n: &str| (spec.coordinates.iter()).any(|c| c.name == n && c.kind == CoordinateKind::Angle);
    let small = spec.small.iter().map(|s| s.coordinate.clone());
    let springs = (spec.links.iter()).filter_map(|l| Some(l.spring.as_ref()?.coordinate.clone()));
    let bare = (expression_texts(spec).into_iter()).flat_map(|(_, t)| crate::expr::bare_names(t));
    let mut raw: Vec<String> = Vec::new();
    for n in small.chain(springs).chain(bare) {
        if angle(&n) && !raw.contains(&n) {
            raw.push(n);
        }
    }
    raw
}

/// The registry of the spec's variables: its parameters, coordinates (with their rates),
/// the PFD's unknowns, the angles written as themselves, the phases Ω t, the divisors and,
/// from the loop closures, the reciprocals of cos φ.
fn registry(
    spec: &SpecFile,
    unknowns: &[String],
    solved: Option<&Solved>,
) -> Result<Rc<Registry>, SpecError> {
    let mut params: Vec<String> = spec.parameters.iter().map(|p| p.name.clone()).collect();
    // A trial motion's unknowns (X of x = X cos(Ω t)) are scalars as the parameters are.
    params.extend(super::trial::unknown_names(spec, unknowns)?);
    let angle_params: Vec<String> = spec
        .parameters
        .iter()
        .filter(|p| p.kind == ParameterKind::Angle)
        .map(|p| p.name.clone())
        .collect();
    let raw_angles = raw_angles(spec);
    // The time enters as phases Ω t (a forcing F0 cos(Ω t), a frame turned by Ω t): each
    // pulsation that is a parameter gets its phase coordinate.
    let mut pulsations: Vec<String> = Vec::new();
    let texts = expression_texts(spec).into_iter().map(|(_, t)| t).chain(
        spec.frames
            .iter()
            .filter_map(|f| Some(f.rotation.as_ref()?.angle.as_str())),
    );
    let trials = (spec.hypotheses.iter()).filter_map(|h| Some(h.trial.as_ref()?.motion.as_str()));
    let texts = texts.chain(trials);
    for text in texts {
        for w in crate::expr::pulsations_in(text) {
            if params.contains(&w) && !angle_params.contains(&w) && !pulsations.contains(&w) {
                pulsations.push(w);
            }
        }
    }
    let solved_divisors = solved.map_or(&[][..], |s| &s.divisors);
    let divisors = super::texts::divisors(spec, &params, solved_divisors);
    let solved_rate = |k: usize| {
        let s = solved?;
        let n = s.rates.iter().find(|r| r.0 == k)?;
        Some((n.1.clone(), s.determinant.clone()))
    };
    let builder = (spec.coordinates.iter().enumerate())
        .fold(
            Registry::builder().parameters(&params),
            |b, (k, c)| match (&c.rate, solved_rate(k)) {
                (Some(rate), _) => b.coordinate_with_rate(&c.name, c.kind, rate),
                (None, Some(quotient)) => b.coordinate_with_quotient(&c.name, c.kind, quotient),
                (None, None) => b.coordinate(&c.name, c.kind),
            },
        )
        .unknowns(unknowns)
        .raw_angles(&raw_angles)
        .angle_parameters(&angle_params)
        .phases(&pulsations)
        .inverses(&divisors)
        .inverses(solved.map_or(&[][..], |s| &s.inverses))
        .secants(solved.map_or(&[][..], |s| &s.secants))
        .cosecants(solved.map_or(&[][..], |s| &s.cosecants))
        .holonomic(solved.map_or(&[][..], |s| &s.dependent))
        .roots_of(solved.map_or(Vec::new(), |s| {
            s.explicit.iter().map(|e| e.radicand.clone()).collect()
        }))
        .display_ranks(spec.parameters.iter().map(display_rank).collect());
    let aliases: Vec<(String, String)> = spec
        .aliases
        .iter()
        .map(|a| (a.name.clone(), a.value.clone()))
        .collect();
    builder
        .clone()
        .aliases(&aliases)
        .build()
        .map_err(|e| super::texts::registry_error(spec, &builder, &aliases, e))
}

/// The frames, each after its parent (the spec may list them in any order; the resolved
/// positions are the arena's ids), and the names the statement gives their basis vectors.
fn frames(spec: &SpecFile, reg: &Rc<Registry>, resolved: &Resolved) -> Result<Frames, SpecError> {
    let mut frames = Frames::new(reg.clone(), &spec.ground);
    for node in &resolved.frames[1..] {
        let i = node.spec.expect("a frame of the spec");
        let rotation = match &spec.frames[i].rotation {
            None => None,
            Some(r) => {
                let path = format!("frames[{i}].rotation");
                let (sign, axis_txt) = match r.axis.strip_prefix('-') {
                    Some(a) => (-1, a),
                    None => (1, r.axis.as_str()),
                };
                let axis = Axis::parse(axis_txt).ok_or_else(|| {
                    at(
                        format!("{path}.axis"),
                        format!("axis `{}` is not x, y, z, -x, -y or -z", r.axis),
                    )
                })?;
                let angle = rotation_angle(reg, &r.angle, sign)
                    .map_err(|m| at(format!("{path}.angle"), m))?;
                Some(Rotation { axis, angle })
            }
        };
        frames.add(node.name, FrameId(node.parent), rotation);
    }
    // Basis vectors named as the statement does ((u, v, w), (i, j, k)), checked by the
    // resolution.
    for (pos, node) in resolved.frames.iter().enumerate() {
        let given = node
            .spec
            .map_or(&spec.ground_basis, |i| &spec.frames[i].basis);
        if let Some(given) = given {
            frames.name_vectors(FrameId(pos), given.clone());
        }
    }
    Ok(frames)
}

/// The points, each after the point it is placed from.
fn points(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    frames: &Frames,
    resolved: &Resolved,
) -> Result<Points, SpecError> {
    let bv = |s: &str| frames.basis_vector(s).map(|(f, a)| (f, a.index()));

    // Points, each after the point it is placed from.
    let mut points = Points::new(resolved.points[0].name);
    for node in &resolved.points[1..] {
        let i = node.spec.expect("a point of the spec");
        let path = format!("points[{i}].position");
        let parts = reg
            .parse_vector(&spec.points[i].position, &bv)
            .map_err(|e| expr_err(&path, e))?;
        let mut v = Vector::zero();
        for (f, c) in parts {
            let [x, y, z] = c;
            v.add_part(
                f,
                [bounded(&path, x)?, bounded(&path, y)?, bounded(&path, z)?],
            );
        }
        points.add(node.name, PointId(node.from), v);
    }
    Ok(points)
}

/// The hypotheses: each as substitutions (constant rates, the symmetries of the solids it
/// names, motions, small parameters) and the effects the answer key states.
fn hypotheses(
    spec: &SpecFile,
    reg: &Rc<Registry>,
    bodies: &[Body],
    resolved: &Resolved,
) -> Result<Vec<Hypothesis>, SpecError> {
    let mut hypotheses = Vec::new();
    for ((i, h), node) in spec.hypotheses.iter().enumerate().zip(&resolved.hypotheses) {
        let path = format!("hypotheses[{i}]");
        let mut subs = Vec::new();
        let mut effects = Vec::new();
        for (k, c) in h.constant_rates.iter().enumerate() {
            let q = reg.coord(c).expect("a coordinate, as resolved");
            if reg.coord_info(q).is_driven() {
                return Err(at(
                    format!("{path}.constant_rates[{k}]"),
                    format!(
                        "`{c}` is driven by other coordinates' rates: hold those constant \
                         instead"
                    ),
                ));
            }
            let dd = reg.ddot(q);
            if let Some(v) = dd.single_variable() {
                subs.push((v, reg.zero()));
                effects.push(Effect::posed(dd, reg.zero()));
            }
        }
        for (k, &b) in node.symmetric_solids.iter().enumerate() {
            let sp = format!("{path}.symmetric_solids[{k}]");
            symmetric_solid(reg, &bodies[b], &sp, &mut subs, &mut effects)?;
        }
        super::coulomb::signs(spec, reg, h, &path)?;
        super::hypotheses::motions(reg, h, &path, &mut subs, &mut effects)?;
        let trial = super::trial::trial(reg, h, &path, &mut subs, &mut effects)?;
        let first_order = super::hypotheses::small_parameters(reg, h, &path)?;
        let subs = super::hypotheses::with_inverses(reg, subs, &first_order, &path)?;
        hypotheses.push(Hypothesis {
            name: h.name.clone(),
            text: h.text.clone(),
            symmetric_solids: node.symmetric_solids.iter().map(|&b| BodyId(b)).collect(),
            substitutions: subs,
            effects,
            first_order,
            trial,
        });
    }

    Ok(hypotheses)
}

/// The substitutions a solid's symmetries make (`sp`: the hypothesis' path to it): entries
/// of its inertia matrix zero, moments equal about an axis of revolution.
fn symmetric_solid(
    reg: &Rc<Registry>,
    b: &Body,
    sp: &str,
    subs: &mut Vec<(crate::expr::VarId, crate::expr::Expr)>,
    effects: &mut Vec<Effect>,
) -> Result<(), SpecError> {
    let sname = &b.name;
    let Some(ine) = &b.inertia else {
        return Ok(());
    };
    for sym in &b.symmetries {
        for (r, c) in sym.zero_entries() {
            let e = &ine.matrix[r][c];
            if e.is_zero() {
                continue;
            }
            let v = e
                .single_variable()
                .or_else(|| (-e).single_variable())
                .ok_or_else(|| {
                    at(
                        sp,
                        format!(
                            "the symmetries of solid {sname} make entry [{r}][{c}] zero, but \
                         it is `{e}`, which is not a single parameter"
                        ),
                    )
                })?;
            if !subs.iter().any(|(x, _)| *x == v) {
                subs.push((v, reg.zero()));
                let zeroed = if e.single_variable().is_some() {
                    e.clone()
                } else {
                    -e
                };
                effects.push(Effect {
                    cause: Cause::Symmetry,
                    lhs: Stated::Expr(zeroed),
                    rhs: Stated::Expr(reg.zero()),
                });
            }
        }
        if let Some((a, bb)) = sym.equal_moments() {
            // Through the substitutions already made: two axes of revolution (a
            // sphere-like solid) chain B = A then C = B into C = A.
            let resolve = |e: &crate::expr::Expr| {
                subs.iter()
                    .fold(e.clone(), |acc, (x, val)| acc.substitute(*x, val))
            };
            let (ea, eb) = (resolve(&ine.matrix[a][a]), resolve(&ine.matrix[bb][bb]));
            let (ea, eb) = (&ea, &eb);
            if ea != eb {
                let v = eb.single_variable().ok_or_else(|| {
                    at(
                        sp,
                        format!(
                            "the axis of revolution of solid {sname} makes entries \
                             [{a}][{a}] and [{bb}][{bb}] equal, but `{eb}` is not a \
                             single parameter"
                        ),
                    )
                })?;
                for (_, val) in subs.iter_mut() {
                    *val = val.substitute(v, ea);
                }
                subs.push((v, ea.clone()));
                effects.push(Effect {
                    cause: Cause::Symmetry,
                    lhs: Stated::Expr(eb.clone()),
                    rhs: Stated::Expr(ea.clone()),
                });
            }
        }
    }
    Ok(())
}

/// The angle of a rotation, `±q + c` (one time coordinate, with coefficient ±1, plus
/// constants: multiples of π/2 and angle parameters), turned the other way when the axis is
/// negative (`sign` −1).
fn rotation_angle(reg: &Rc<Registry>, text: &str, sign: i32) -> Result<Angle, String> {
    let a = reg.parse_angle(text).map_err(|e| match e {
        ExprError::UnknownName { name, hint, .. } if !hint.is_empty() => {
            format!("unknown name `{name}` in the angle `{text}` ({hint})")
        }
        ExprError::UnknownName { name, .. } => format!(
            "unknown name `{name}` in the angle `{text}` (declare it as an angle coordinate, or \
             as a parameter with \"kind\": \"angle\" for a constant angle)"
        ),
        other => other.to_string(),
    })?;
    let moving: Vec<(crate::expr::CoordId, i64)> = a
        .terms
        .iter()
        .copied()
        .filter(|(q, _)| !reg.coord_info(*q).is_constant())
        .collect();
    let constants = || {
        a.terms
            .iter()
            .copied()
            .filter(|(q, _)| reg.coord_info(*q).is_constant())
    };
    let (coord, coef) = match moving.as_slice() {
        [(q, n)] if n.abs() == 1 => (*q, *n),
        [(q, _)] => {
            return Err(format!(
                "`{text}`: the coordinate {} enters a rotation angle with coefficient 1 or -1 \
                 (the angle is ±q + a constant)",
                reg.coord_info(*q).name
            ));
        }
        [] => match constants().next() {
            Some(first) => first,
            None => {
                return Err(format!(
                    "`{text}` is a constant multiple of pi/2: a frame turned by it alone has its \
                     axes along the parent's, so name them so (no rotation), or declare the angle \
                     as a parameter with \"kind\": \"angle\""
                ));
            }
        },
        _ => {
            return Err(format!(
                "`{text}` holds several coordinates: a rotation angle is ±q + a constant, one \
                 coordinate per elementary rotation (chain one frame per coordinate)"
            ));
        }
    };
    let s = i64::from(sign);
    let mut terms = vec![(coord, coef * s)];
    terms.extend(
        constants()
            .filter(|(q, _)| *q != coord)
            .map(|(q, n)| (q, n * s)),
    );
    Ok(Angle {
        coord,
        sign: (coef * s) as i32,
        terms,
        quarter_turns: a.quarter_turns * s,
        cos: a.cos,
        sin: if sign < 0 { -a.sin } else { a.sin },
    })
}

/// The course's order of parameters in a written product, from their units: masses, then
/// accelerations (g), lengths, inertia moments, then the rest (m g L, m2 L2², A + m h²).
fn display_rank(p: &crate::wire::ParameterSpec) -> u32 {
    use crate::units::Dimension;
    let d = p.unit.as_deref().and_then(|u| Dimension::parse(u).ok());
    match d {
        Some(Dimension::MASS) => 0,
        Some(Dimension::ACCELERATION) => 1,
        Some(Dimension::LENGTH) => 2,
        Some(Dimension::INERTIA) => 3,
        _ => 4,
    }
}

/// The explicit loop laws over the mechanism's registry (each radicand is one of its roots);
/// a law whose parts do not carry over is left out.
fn explicit_laws(reg: &Rc<Registry>, solved: &Solved) -> Vec<crate::mechanism::ExplicitLaw> {
    (solved.explicit.iter())
        .filter_map(|e| {
            let radicand = e.radicand.carried(reg).ok()?;
            Some(crate::mechanism::ExplicitLaw {
                coordinate: reg.coord(&e.coordinate)?,
                closure: e.closure,
                eliminated: e.eliminated.clone(),
                center: e.center.carried(reg).ok()?,
                root: reg.sqrt_of(&radicand).ok()?,
            })
        })
        .collect()
}
