//! Loop closures (« fermeture géométrique »): the rates of the dependent coordinates, solved
//! exactly from the derivative of the loop's vector equation.
//!
//! A closure OA + AB + BO = 0 projected on the ground's basis gives scalar relations
//! fᵢ(q) = 0. Their derivative is linear in the rates, J_d q̇_d + J_f q̇_f = 0, and Cramer's
//! rule gives each dependent rate as a linear form of the free ones, q̇_d = N_d / det J_d.
//! The determinant must be a product of parameters and cosines of coordinates (the
//! crank–slider's L cos φ), which the canonical form inverts exactly (1/p, 1/cos q); the
//! relation itself stays implicit. The rates become driven rates of the registry, holonomic.

use super::SpecError;
use super::refusal::{at, expr_err};
use super::solved::{Solved, SolvedExplicit};
use super::validate::geometry as geometry_of;
use crate::expr::{CoordId, Expr, Registry, VarRole};
use crate::frame::{Axis, FrameId};
use crate::mechanism::{HelicalLaw, Mechanism, RollingLaw};
use crate::point::PointId;
use crate::resolve::{HelixNode, Resolved, RollingNode};
use crate::vector::Vector;
use crate::wire::RollingSpec;
use crate::wire::SpecFile;

/// The spec with only what places the frames and points: the closures are read on it. Each
/// helical link of `helices` that determines a coordinate leaves its lead per radian
/// p/(2π) as an alias of the geometry (named apart from every name of the spec), so that
/// its relation is read with the divisors its pitch brings; their names, in order.
fn geometry(spec: &SpecFile, helices: &[HelixNode]) -> (SpecFile, Vec<String>) {
    let taken = |n: &str| {
        (spec.parameters.iter().map(|p| &p.name))
            .chain(spec.coordinates.iter().map(|c| &c.name))
            .chain(spec.aliases.iter().map(|a| &a.name))
            .any(|x| x == n)
    };
    let mut leads = Vec::new();
    let mut aliases = Vec::new();
    for h in helices.iter().filter(|h| h.dependent.is_some()) {
        let mut name = format!("lead{}", h.link);
        while taken(&name) {
            name.insert(0, 'z');
        }
        let pitch = spec.links[h.link].pitch.as_deref().unwrap_or("0");
        aliases.push(crate::wire::AliasSpec {
            name: name.clone(),
            value: format!("({pitch})/(2*pi)"),
            description: None,
        });
        leads.push(name);
    }
    let mut g = spec.clone();
    g.aliases.extend(aliases);
    g.closures.clear();
    g.rolling.clear();
    g.solids.clear();
    g.sets.clear();
    g.hypotheses.clear();
    g.quantities.clear();
    g.questions.clear();
    g.gravity = None;
    g.links.clear();
    g.actions.clear();
    g.pfd.clear();
    g.scenarios.clear();
    g.small.clear();
    g.default_basis = None;
    (g, leads)
}

/// The determinant of a square matrix by cofactors along the first row (n ≤ a few).
fn det(m: &[Vec<Expr>], zero: &Expr) -> Expr {
    match m.len() {
        0 => zero.registry().integer(1),
        1 => m[0][0].clone(),
        n => {
            let mut acc = zero.clone();
            for j in 0..n {
                if m[0][j].is_zero() {
                    continue;
                }
                let minor: Vec<Vec<Expr>> = m[1..]
                    .iter()
                    .map(|r| {
                        r.iter()
                            .enumerate()
                            .filter(|(k, _)| *k != j)
                            .map(|(_, e)| e.clone())
                            .collect()
                    })
                    .collect();
                let t = &m[0][j] * &det(&minor, zero);
                acc = if j % 2 == 0 { &acc + &t } else { &acc - &t };
            }
            acc
        }
    }
}

/// Solves the closures of a spec, if it has any, on their resolved references (the
/// coordinates they determine, the rolling conditions' points, frames and directions).
pub(super) fn solve(spec: &SpecFile, resolved: &Resolved) -> Result<Option<Solved>, SpecError> {
    let helices: Vec<&HelixNode> = (resolved.helices.iter())
        .filter(|h| h.dependent.is_some())
        .collect();
    if spec.closures.is_empty() && spec.rolling.is_empty() && helices.is_empty() {
        return Ok(None);
    }
    let dependent: Vec<(String, usize)> = (resolved.closures.iter().map(|c| &c.dependent))
        .chain(resolved.rolling.iter().map(|r| &r.dependent))
        .flatten()
        .copied()
        .chain(helices.iter().filter_map(|h| h.dependent))
        .map(|k| (spec.coordinates[k].name.clone(), k))
        .collect();
    let (geometry, leads) = geometry(spec, &resolved.helices);
    // A pitch the geometry cannot read as a constant is refused at the link, in its words.
    let m = geometry_of(&geometry, resolved).map_err(|e| at_pitch(spec, &helices, e))?;
    let reg = m.reg.clone();
    let zero = reg.zero();
    let ids: Vec<CoordId> = dependent
        .iter()
        .map(|(d, _)| reg.coord(d).expect("a declared coordinate"))
        .collect();
    let rows = closure_rows(spec, &m)?;
    let explicit = explicit_laws(spec, &m)?;
    // d/dt fᵢ = Σ_d J_id q̇_d − bᵢ, bᵢ the free rates' part with its sign changed.
    let mut derivatives = Vec::new();
    let mut linear = Vec::new();
    for r in &rows {
        let d = r.dt();
        derivatives.push(d.clone());
        linear.push(d);
    }
    let mut rolling = Vec::new();
    for (i, (r, node)) in spec.rolling.iter().zip(&resolved.rolling).enumerate() {
        let (law, rs) = rolling_rows(&m, i, r, node)?;
        rolling.push(law);
        linear.extend(rs);
    }
    let mut helical = Vec::new();
    for (h, lead) in helices.iter().zip(&leads) {
        let (law, row) = helical_row(&m, h, lead)?;
        helical.push(law);
        linear.push(row);
    }
    let mut jac: Vec<Vec<Expr>> = Vec::new();
    let mut rhs: Vec<Expr> = Vec::new();
    for d in &linear {
        let js: Vec<Expr> = ids.iter().map(|&q| d.partial_rate(q, 1)).collect();
        let mut b = -d;
        for (q, j) in ids.iter().zip(&js) {
            b = &b + &(j * &reg.dot(*q));
        }
        jac.push(js);
        rhs.push(b);
    }
    let names: Vec<&str> = dependent.iter().map(|d| d.0.as_str()).collect();
    let (d, divided) = determinant((spec, &helices), &jac, &zero, &names)?;
    let mut rates = Vec::new();
    for (col, (_, k)) in dependent.iter().enumerate() {
        let replaced: Vec<Vec<Expr>> = jac
            .iter()
            .zip(&rhs)
            .map(|(row, b)| {
                let mut r = row.clone();
                r[col] = b.clone();
                r
            })
            .collect();
        rates.push((*k, det(&replaced, &zero)));
    }
    let divisors = (rates.iter())
        .map(|(k, n)| (*k, written_divisors(n, &d)))
        .collect();
    let Divisors {
        secants,
        cosecants,
        inverses,
    } = divided;
    Ok(Some(Solved {
        rates,
        secants,
        cosecants,
        inverses,
        divisors,
        dependent: dependent
            .into_iter()
            .map(|d| d.0)
            .filter(|d| spec.closures.iter().any(|c| c.dependent.contains(d)))
            .collect(),
        derivatives,
        rolling,
        helical,
        determinant: d,
        explicit,
    }))
}

/// The loop laws in explicit form (« loi entrée–sortie explicite »): for each dependent
/// length x of a closure V = 0 and each term T of V whose direction, once eliminated
/// (|V − T|² = |T|², that is V·(V − 2T) = 0), leaves a relation free of the closure's other
/// dependent coordinates and quadratic in x, x = m ± √P (the slider–crank's
/// x = R cos θ ± √(L² − R² sin²θ)); the first such term, per length. Over the geometry's
/// registry, the branch left to the mechanism (numeric, at the closure solver's
/// configurations).
fn explicit_laws(spec: &SpecFile, m: &Mechanism) -> Result<Vec<SolvedExplicit>, SpecError> {
    let reg = &m.reg;
    let bv = |s: &str| m.frames.basis_vector(s).map(|(f, a)| (f, a.index()));
    let mut out = Vec::new();
    for (i, c) in spec.closures.iter().enumerate() {
        let parts = reg
            .parse_vector(&c.vector, &bv)
            .map_err(|e| expr_err(&format!("closures[{i}].vector"), e))?;
        let mut v = Vector::zero();
        for (f, comps) in parts {
            v.add_part(f, comps);
        }
        let dependent: Vec<CoordId> = (c.dependent.iter()).filter_map(|n| reg.coord(n)).collect();
        let whole = v.dot(&m.frames, &v);
        for &x in &dependent {
            let Some(xv) = reg.index_of(VarRole::Value(x)) else {
                continue;
            };
            for (f, comps) in v.parts() {
                let t = Vector::new(f, comps.clone());
                let g = &whole - &(&reg.integer(2) * &v.dot(&m.frames, &t));
                let others = dependent.iter().filter(|&&q| q != x).any(|&q| {
                    reg.var_ids().any(|w| {
                        g.contains_var(w)
                            && matches!(reg.role(w), VarRole::Cos(p) | VarRole::Sin(p) | VarRole::Value(p) if p == q)
                    })
                });
                if others {
                    continue;
                }
                if let Some((center, radicand)) = g.quadratic_roots(xv) {
                    out.push(SolvedExplicit {
                        coordinate: reg.coord_info(x).name.clone(),
                        closure: i,
                        eliminated: m.frame_name(f).to_string(),
                        center,
                        radicand,
                    });
                    break;
                }
            }
        }
    }
    Ok(out)
}

/// An error of the geometry at one of the aliases it adds for the helical links' pitches
/// (after the spec's own), said at the link's pitch; any other error as it is.
fn at_pitch(spec: &SpecFile, helices: &[&HelixNode], e: SpecError) -> SpecError {
    let SpecError::Invalid { path, .. } = &e else {
        return e;
    };
    let k = (path.strip_prefix("aliases["))
        .and_then(|r| r.strip_suffix("].value"))
        .and_then(|k| k.parse::<usize>().ok())
        .and_then(|k| k.checked_sub(spec.aliases.len()));
    let Some(h) = k.and_then(|k| helices.get(k)) else {
        return e;
    };
    let text = spec.links[h.link].pitch.as_deref().unwrap_or_default();
    let why = format!(
        "the pitch `{}` is not a constant of the parameters (a length: no coordinate, rate, \
         time or unknown)",
        crate::excerpt::excerpt(text)
    );
    at(format!("links[{}].pitch", h.link), why)
}

/// A helical link's relation V(P ∈ b/a)·u − p/(2π) Ω(b/a)·u = 0 (linear in the rates), read
/// on the geometry whose alias `lead` is p/(2π), and how the key writes it.
fn helical_row(m: &Mechanism, h: &HelixNode, lead: &str) -> Result<(HelicalLaw, Expr), SpecError> {
    let path = format!("links[{}]", h.link);
    let k = m
        .reg
        .parse(lead)
        .map_err(|e| expr_err(&format!("{path}.pitch"), e))?;
    let (p, [fa, fb]) = (PointId(h.point), h.motion.map(FrameId));
    let axis = (FrameId(h.axis.0), Axis::ALL[h.axis.1]);
    let u = Vector::along(axis.0, axis.1, m.reg.one());
    let v = crate::kinematics::velocity(m, p, fb, fa).dot(&m.frames, &u);
    let w = crate::kinematics::omega(m, fb, fa).dot(&m.frames, &u);
    let screw = &k * &w;
    let row = &v - &screw;
    if row.is_zero() {
        let why = "the link's relation holds whatever the rates: name no coordinate it determines";
        return Err(at(format!("{path}.dependent"), why));
    }
    let law = HelicalLaw {
        link: h.link,
        point: p,
        motion: [fa, fb],
        axis,
        velocity: v,
        rotation: w,
        screw,
    };
    Ok((law, row))
}

/// The scalar relations of the closures: each one's nonzero components on the ground's
/// basis, as many as its dependent coordinates, each holding a coordinate.
fn closure_rows(spec: &SpecFile, m: &Mechanism) -> Result<Vec<Expr>, SpecError> {
    let reg = &m.reg;
    let bv = |s: &str| m.frames.basis_vector(s).map(|(f, a)| (f, a.index()));
    let ground = m.frames.ground();
    let axes = ["x", "y", "z"];
    let mut rows: Vec<Expr> = Vec::new();
    for (i, c) in spec.closures.iter().enumerate() {
        let path = format!("closures[{i}].vector");
        let parts = reg
            .parse_vector(&c.vector, &bv)
            .map_err(|e| expr_err(&path, e))?;
        let mut v = Vector::zero();
        for (f, comps) in parts {
            v.add_part(f, comps);
        }
        let comps = v.express_in(&m.frames, ground);
        let mut n = 0;
        for (k, e) in comps.into_iter().enumerate() {
            if e.is_zero() {
                continue;
            }
            if e.is_time_independent() {
                return Err(at(
                    &path,
                    format!(
                        "its component on {}{}, `{}`, holds no coordinate: the loop does not \
                         close",
                        axes[k],
                        m.frame_name(ground),
                        crate::excerpt::excerpt(&e.to_string())
                    ),
                ));
            }
            rows.push(e);
            n += 1;
        }
        if n != c.dependent.len() {
            return Err(at(
                &path,
                format!(
                    "it gives {n} scalar relation{} on the ground's basis, for {} dependent \
                     coordinate{}: as many relations as dependent coordinates",
                    if n == 1 { "" } else { "s" },
                    c.dependent.len(),
                    if c.dependent.len() == 1 { "" } else { "s" },
                ),
            ));
        }
    }
    Ok(rows)
}

/// The determinant of the relations' derivative in the dependent rates (`jac`) and its
/// factors, refused when a rate is missing from them, when it is 0, and when the canonical
/// form cannot divide by it.
fn determinant(
    (spec, helices): (&SpecFile, &[&HelixNode]),
    jac: &[Vec<Expr>],
    zero: &Expr,
    names: &[&str],
) -> Result<(Expr, Divisors), SpecError> {
    let (place, noun) = constraints_place(spec, helices);
    let (place, noun) = (place.as_str(), noun.as_str());
    // A dependent coordinate whose rate no relation holds cannot be determined by them.
    if let Some(col) = (0..names.len()).find(|&c| jac.iter().all(|row| row[c].is_zero())) {
        return Err(at(
            place,
            format!(
                "the {noun} do not hold the rate of `{}`: they cannot determine it (name \
                 the coordinates whose rates they hold)",
                names[col]
            ),
        ));
    }
    let d = det(jac, zero);
    if d.is_zero() {
        return Err(at(
            place,
            format!(
                "the {noun} do not determine {}: their relations are redundant (the \
                 derivative's determinant in these rates is 0)",
                names.join(", ")
            ),
        ));
    }
    let Some(divided) = divisors(zero.registry(), &d) else {
        return Err(at(
            place,
            format!(
                "solving the {noun} for {} divides by `{}`, which is not a product of \
                 parameters and of a cosine or a sine of each coordinate: not supported yet \
                 (measure the angles so that it is one: L cos φ for a crank–slider's rod, \
                 L2 L3 sin ψ for a four-bar whose rocker turns by ψ from its coupler)",
                names.join(", "),
                crate::excerpt::excerpt(&d.to_string())
            ),
        ));
    };
    Ok((d, divided))
}

/// Where the constraints that determine coordinates are (a JSON path, for a refusal) and what
/// they are called: `closures`, `rolling`, a helical link's `links[i].dependent`, or those
/// of several.
fn constraints_place(spec: &SpecFile, helices: &[&HelixNode]) -> (String, String) {
    let mut parts: Vec<(String, &str)> = Vec::new();
    if !spec.closures.is_empty() {
        parts.push(("closures".into(), "closures"));
    }
    if !spec.rolling.is_empty() {
        parts.push(("rolling".into(), "rolling conditions"));
    }
    if let Some(h) = helices.first() {
        let noun = if helices.len() == 1 {
            "helical link"
        } else {
            "helical links"
        };
        parts.push((format!("links[{}].dependent", h.link), noun));
    }
    match parts.as_slice() {
        [(place, noun)] => (place.clone(), noun.to_string()),
        _ => {
            let all = |f: &dyn Fn(&(String, &str)) -> String| {
                parts.iter().map(f).collect::<Vec<_>>().join(" and ")
            };
            (all(&|p| p.0.clone()), all(&|p| p.1.to_string()))
        }
    }
}

/// What the rates divide by, named for the registry.
struct Divisors {
    /// The angles whose cosine.
    secants: Vec<String>,
    /// The angles whose sine.
    cosecants: Vec<String>,
    /// The parameters.
    inverses: Vec<String>,
}

/// The factors of the determinant `d` when the canonical form can invert it: a number times
/// parameters and cosines or sines of coordinates, never both of one angle (1/cos q and
/// 1/sin q would tie the two reductions of sin² and cos²); `None` otherwise.
fn divisors(reg: &Registry, d: &Expr) -> Option<Divisors> {
    let mut secants = Vec::new();
    let mut cosecants = Vec::new();
    let mut inverses = Vec::new();
    let monomial = d.nterms() == 1
        && reg.var_ids().all(|v| {
            if !d.contains_var(v) {
                return true;
            }
            match reg.role(v) {
                VarRole::Parameter(p) if !reg.is_unknown(p) => {
                    inverses.push(reg.scalar_name(p).to_string());
                    true
                }
                VarRole::Inverse(_) => true,
                VarRole::Cos(q) if q.index() < reg.coordinates().len() => {
                    secants.push(reg.coord_info(q).name.clone());
                    true
                }
                VarRole::Sin(q) if q.index() < reg.coordinates().len() => {
                    cosecants.push(reg.coord_info(q).name.clone());
                    true
                }
                _ => false,
            }
        });
    let both = secants.iter().any(|n| cosecants.contains(n));
    (monomial && !both).then_some(Divisors {
        secants,
        cosecants,
        inverses,
    })
}

/// A rolling condition's scalar relations (linear in the rates) and how the key writes them.
fn rolling_rows(
    m: &Mechanism,
    i: usize,
    r: &RollingSpec,
    node: &RollingNode,
) -> Result<(RollingLaw, Vec<Expr>), SpecError> {
    let path = format!("rolling[{i}].velocity");
    let (p, [fi, fj]) = (PointId(node.point), node.motion.map(FrameId));
    let v = crate::kinematics::velocity(m, p, fi, fj);
    let n = r.dependent.len();
    let ground = m.frames.ground();
    let (basis, rows) = if r.on.is_empty() {
        let candidates = std::iter::once(ground).chain(m.frames.ids().filter(|&f| f != ground));
        let mut counts = Vec::new();
        let mut found = None;
        for f in candidates {
            let rows: Vec<Expr> = v
                .express_in(&m.frames, f)
                .into_iter()
                .filter(|e| !e.is_zero())
                .collect();
            if rows.is_empty() {
                return Err(at(
                    &path,
                    format!(
                        "{} is zero whatever the rates: it imposes nothing",
                        r.velocity
                    ),
                ));
            }
            if rows.len() == n {
                found = Some((Some(m.frame_name(f).to_string()), rows));
                break;
            }
            counts.push(rows.len());
        }
        found.ok_or_else(|| {
            at(
                &path,
                format!(
                    "it has {} nonzero components on every basis, for {n} dependent \
                     coordinate{}: name as many dependent coordinates, or the directions it \
                     is zero along (`on`)",
                    counts.iter().min().copied().unwrap_or(0),
                    if n == 1 { "" } else { "s" }
                ),
            )
        })?
    } else {
        let mut rows = Vec::new();
        for (k, (u, &(f, a))) in r.on.iter().zip(&node.on).enumerate() {
            let e = v.express_in(&m.frames, FrameId(f))[a].clone();
            if e.is_zero() {
                return Err(at(
                    format!("rolling[{i}].on[{k}]"),
                    format!("{} has no component on {u} whatever the rates", r.velocity),
                ));
            }
            rows.push(e);
        }
        (None, rows)
    };
    let law = RollingLaw {
        velocity: node.velocity.clone(),
        written: r.velocity.clone(),
        point: p,
        motion: [fi, fj],
        on: (node.on.iter())
            .map(|&(f, a)| (FrameId(f), Axis::ALL[a]))
            .collect(),
        basis,
        rows: rows.clone(),
    };
    Ok((law, rows))
}

/// The names the rate `n / d` writes below a division line: the determinant's parameters
/// (π among them) and those it divides by, then those the numerator divides by, each once.
fn written_divisors(n: &Expr, d: &Expr) -> Vec<String> {
    let reg = d.registry();
    let mut out: Vec<String> = Vec::new();
    let names = |e: &Expr, whole: bool| -> Vec<String> {
        (reg.var_ids().filter(|&v| e.contains_var(v)))
            .filter_map(|v| match reg.role(v) {
                VarRole::Parameter(p) if whole => Some(reg.scalar_name(p).to_string()),
                VarRole::Inverse(p) => Some(reg.scalar_name(p).to_string()),
                _ => None,
            })
            .collect()
    };
    for name in names(d, true).into_iter().chain(names(n, false)) {
        if !out.contains(&name) {
            out.push(name);
        }
    }
    out
}
