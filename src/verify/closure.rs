//! Relations between the coordinates that hold because a loop closes (issue 37): the
//! coordinates of a closed chain are tied at position level (R cos θ + L cos φ = x for a
//! slider–crank), which the canonical form does not know, so such a relation is not zero as a
//! polynomial, and without this check `verify` called the spec's own closure « NOT
//! equivalent ».
//!
//! The exact proof: lhs − rhs is a multiple (by a factor made of parameters, or else by any
//! polynomial that divides it exactly) of one of the loop's relations as a teacher writes them — the closure vector projected on a basis vector
//! of any frame, or the elimination of one of its terms' directions (isolate L x⃗2 and square:
//! |V − L x⃗2|² = L², that is V·(V − 2 L x⃗2) = 0 for the closure vector V). Otherwise the
//! float backend draws closed configurations (its own Newton solve of the loop): lhs − rhs
//! away from zero at one of them is a counterexample, and the relation is not equivalent;
//! zero at every one without an exact proof, the question is out of reach (exit 2), never
//! answered « not equivalent ».
//!
//! With a square root s = √P in it (an explicit loop law, x = R cos θ + √(L² − R² sin²θ)),
//! e = a + b s is multiplied by its conjugate a − b s: e (a − b s) = a² − b² P holds no root,
//! and is proven a multiple of a relation as above. Then at every closed configuration e = 0
//! or a − b s = 0, one branch or the other: e is zero on the branch of the configurations the
//! float backend draws iff it vanishes at each of them (else one is a counterexample, the
//! other branch's law).

use super::reader::Reader;
use super::{Factor, VerifyError};
use crate::expr::{Expr, VarRole};
use crate::frame::Axis;
use crate::vector::Vector;

/// How many closed configurations are drawn for a counterexample.
const SAMPLES: usize = 12;

/// Relative size of lhs − rhs, against the sum of its terms' magnitudes, above which a closed
/// configuration is a counterexample (a closed configuration is solved to about 1e-12).
const WITNESS: f64 = 1e-6;

/// What the loop closures say of e = lhs − rhs.
pub(super) enum Closed {
    /// e = k × g for the loop's relation g, described in words.
    Proven {
        /// « the loop closure projected on y0 », « the loop closure with the direction of
        /// B2 eliminated ».
        relation: String,
        /// k.
        factor: Factor,
    },
    /// e is not zero at this closed configuration (coordinates, then the value of e).
    Counterexample(String),
    /// e vanished at every configuration drawn, but no exact proof was found.
    Undecided,
}

/// The loop's relations as written by hand: (words, polynomial), under the reader's
/// hypothesis.
fn relations(reader: &Reader) -> Vec<(String, Expr)> {
    let m = reader.m;
    let frames = &m.frames;
    let reg = &m.reg;
    let mut out = Vec::new();
    let loops = m.closure_vectors();
    for (k, v) in loops.iter().enumerate() {
        let which = match loops.len() {
            1 => "the loop closure".to_string(),
            _ => format!("loop closure {}", k + 1),
        };
        for f in frames.ids() {
            for axis in Axis::ALL {
                let mut c = [reg.zero(), reg.zero(), reg.zero()];
                c[axis.index()] = reg.one();
                let g = reader.under(v.dot(frames, &Vector::new(f, c)));
                let name = frames.vector_name(f, axis);
                out.push((format!("{which} projected on {name}"), g));
            }
        }
        // Each term's direction eliminated: V·(V − 2 T) = |V − T|² − |T|².
        let whole = v.dot(frames, v);
        for (f, comps) in v.parts() {
            let t = Vector::new(f, comps.clone());
            let g = &whole - &(&reg.integer(2) * &v.dot(frames, &t));
            let basis = frames.get(f).name.clone();
            out.push((
                format!("{which} with the direction of its term in B{basis} eliminated"),
                reader.under(g),
            ));
        }
    }
    out.retain(|(_, g)| !g.is_zero());
    out
}

/// What the spec's loop closures say of e = lhs − rhs (times the denominators typed, which
/// are parameters): `None` when the spec has none.
pub(super) fn modulo_closure(reader: &Reader, e: &Expr) -> Result<Option<Closed>, VerifyError> {
    let m = reader.m;
    if m.closures.is_empty() {
        return Ok(None);
    }
    let all = relations(reader);
    if let [r] = e.roots_held().as_slice() {
        return Ok(Some(with_root(reader, e, *r, &all)));
    }
    if let Some((relation, factor)) = proven(e, &all) {
        return Ok(Some(Closed::Proven { relation, factor }));
    }
    Ok(Some(match sampled(reader, e) {
        Sampled::Counterexample(at) => Closed::Counterexample(at),
        Sampled::Vanishes | Sampled::Unavailable => Closed::Undecided,
    }))
}

/// e = a + b s, s the root `r`: proven through its conjugate, e (a − b s) = k g, and zero
/// at every closed configuration drawn (the branch).
fn with_root(reader: &Reader, e: &Expr, r: crate::expr::RootId, all: &[(String, Expr)]) -> Closed {
    let reg = e.registry();
    let (a, b) = e.split_root(r);
    let conjugate = &a - &(&b * &reg.root(r));
    let product = &(&a * &a) - &(&(&b * &b) * &reg.radicand(r));
    let Some((relation, k)) = proven(&product, all) else {
        return match sampled(reader, e) {
            Sampled::Counterexample(at) => Closed::Counterexample(at),
            Sampled::Vanishes | Sampled::Unavailable => Closed::Undecided,
        };
    };
    // The branch: at the spec's assembly configuration, where the loop closes (e times its
    // conjugate is zero) away from a dead point (where both are), e must vanish.
    let small = |x: &Expr, p: &[f64]| x.eval(p).abs() <= WITNESS * x.eval_magnitude(p);
    let closed = |p: &[f64]| small(&product, p) && !(small(e, p) && small(&conjugate, p));
    let m = reader.m;
    let Some((point, at)) = crate::derivation::at_assembly(m, &[e, &product, &conjugate], &closed)
    else {
        return Closed::Undecided;
    };
    if !small(e, &point) {
        return Closed::Counterexample(format!(
            "at {at}, where the loop closes, lhs − rhs = {:.4}: the law of the other branch",
            e.eval(&point)
        ));
    }
    // e = k g / (a − b s), where a − b s ≠ 0: the branch through the assembly configuration.
    Closed::Proven {
        relation: format!(
            "{relation} (lhs − rhs times its conjugate is a multiple of it), on the branch of \
             {at}"
        ),
        factor: Factor {
            numerator: k.numerator,
            denominator: &k.denominator * &conjugate,
        },
    }
}

/// e = k g for one of the loop's relations g, with k made of parameters, or else any
/// polynomial that divides exactly: the relation in words and k.
fn proven(e: &Expr, all: &[(String, Expr)]) -> Option<(String, Factor)> {
    for (relation, g) in all {
        if let Some((numerator, denominator)) = g.parameter_ratio(e) {
            // e · numerator = g · denominator: e = (denominator / numerator) g.
            let factor = Factor {
                numerator: denominator,
                denominator: numerator,
            };
            return Some((relation.clone(), factor));
        }
    }
    // A multiple by any polynomial (a rate, cos θ): e = q g exactly.
    for (relation, g) in all {
        if let Some(q) = e.exact_div(g) {
            let one = e.registry().one();
            let factor = Factor {
                numerator: q,
                denominator: one,
            };
            return Some((relation.clone(), factor));
        }
    }
    None
}

/// What the closed configurations drawn by the float backend say of e.
enum Sampled {
    /// e is away from zero at this one (coordinates, then the value of e).
    Counterexample(String),
    /// e vanished at every one.
    Vanishes,
    /// None could be drawn or evaluated.
    Unavailable,
}

/// A closed configuration, drawn by the float backend, where e is away from zero; else
/// whether it vanished at every one drawn.
fn sampled(reader: &Reader, e: &Expr) -> Sampled {
    let m = reader.m;
    if reader.hypothesis.is_some_and(|h| !h.first_order.is_empty()) {
        return Sampled::Unavailable;
    }
    let Ok(model) = crate::numeric::NumericModel::new(&m.spec) else {
        return Sampled::Unavailable;
    };
    let mut rng = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(1);
    for _ in 0..SAMPLES {
        let s = match reader.hypothesis {
            Some(h) => model.sample_under(&mut rng, &h.name),
            None => model.sample(&mut rng),
        };
        let Ok(s) = s else {
            return Sampled::Unavailable;
        };
        let values = crate::output::Values {
            parameters: s.parameters.clone(),
            coordinates: s.coordinates.clone(),
            unknowns: Default::default(),
            time: Some(s.time),
        };
        let Ok(point) = crate::output::numeric_point_for(m, &values, &[e]) else {
            return Sampled::Unavailable;
        };
        let (value, size) = (e.eval(&point), e.eval_magnitude(&point));
        if value.is_finite() && size > 0.0 && value.abs() > WITNESS * size {
            let at: Vec<String> = (s.coordinates.iter())
                .map(|(q, [x, _, _])| format!("{q} = {x:.4}"))
                .collect();
            let params: Vec<String> = (s.parameters.iter())
                .filter(|(p, _)| {
                    let reg = e.registry();
                    (reg.param_id(p)
                        .and_then(|id| reg.index_of(VarRole::Parameter(id))))
                    .is_some_and(|v| e.contains_var(v))
                })
                .map(|(p, x)| format!("{p} = {x:.4}"))
                .collect();
            return Sampled::Counterexample(format!(
                "at the closed configuration {} ({}), lhs − rhs = {value:.4}",
                at.join(", "),
                params.join(", ")
            ));
        }
    }
    Sampled::Vanishes
}
