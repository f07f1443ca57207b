//! The structured form (`pfd::structured`): each nested set's dynamic resultant and moment
//! named once and moved by the change of point, δ(A, E) = δ(B, E) + AB ∧ Rd(E). Expanded back,
//! every value must be the engine's own expanded route (each solid's torsor moved to the point
//! and summed, the equations through the linear solve), which shares no step of the recursion;
//! the names evaluated in order must give the expansion's number; and the split M q̈ + h = Q
//! over the names must expand to [`EquationsOfMotion`]'s entries.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use torseur::derivation::{Value, derive_values};
use torseur::expr::{Trig, VarRole};
use torseur::pfd::EquationsOfMotion;
use torseur::pfd::named::lin_value;
use torseur::pfd::structured::Structured;
use torseur::quantity::QuantityKind;

/// The chains small enough to expand in a test: planar up to 12 links, spatial up to 5.
fn small_enough(path: &std::path::Path) -> bool {
    let name = path.file_stem().unwrap().to_string_lossy().to_string();
    let size = |prefix: &str| {
        name.strip_prefix(prefix)
            .and_then(|n| n.parse::<usize>().ok())
    };
    match (size("planar_"), size("chain_")) {
        (Some(n), _) => n <= 12,
        (_, Some(n)) => n <= 5,
        _ => true,
    }
}

/// A registry point where cos q and sin q are those of one angle and 1/p is the inverse of p:
/// the canonical form is reduced by these identities, so the names must be evaluated there.
fn consistent_point(m: &torseur::Mechanism, rng: &mut ChaCha8Rng) -> Vec<f64> {
    let reg = m.reg();
    let mut params = std::collections::BTreeMap::new();
    let mut param = |p: usize, rng: &mut ChaCha8Rng| {
        *params
            .entry(p)
            .or_insert_with(|| rng.random_range(0.5..2.0))
    };
    // An angle by coordinate (or constant angle) index.
    let angles: Vec<f64> = (0..reg.nvars())
        .map(|_| rng.random_range(-1.5..1.5))
        .collect();
    let vars: Vec<_> = reg.var_ids().collect();
    let mut point: Vec<f64> = vars
        .into_iter()
        .map(|v| match reg.role(v) {
            VarRole::Parameter(p) => param(p.index(), rng),
            VarRole::Inverse(p) => 1.0 / param(p.index(), rng),
            VarRole::Cos(q) => angles[q.index()].cos(),
            VarRole::Sin(q) => angles[q.index()].sin(),
            VarRole::Reciprocal(q, Trig::Cos) => 1.0 / angles[q.index()].cos(),
            VarRole::Reciprocal(q, Trig::Sin) => 1.0 / angles[q.index()].sin(),
            VarRole::Value(q) => angles[q.index()],
            VarRole::Rate(..) => rng.random_range(-1.0..1.0),
            // Filled from its radicand below.
            VarRole::Root(_) => f64::NAN,
        })
        .collect();
    reg.fill_roots(&mut point);
    point
}

/// Every library spec and small chain, loaded, with the structured form of its quantities.
fn library() -> Vec<(std::path::PathBuf, torseur::Mechanism, Structured)> {
    crate::specs_in(&["derivations", "derivations/chain"])
        .into_iter()
        .filter(|p| small_enough(p))
        .map(|path| {
            let m = torseur::spec::load(&path).unwrap();
            let s = Structured::of(&m, m.quantities()).unwrap();
            (path, m, s)
        })
        .collect()
}

#[test]
fn every_structured_value_expands_to_the_engines() {
    let mut held = 0;
    let mut rng = ChaCha8Rng::seed_from_u64(36);
    for (path, m, s) in library() {
        let qs: Vec<_> = s.values.iter().map(|(q, _)| q.clone()).collect();
        let ds = derive_values(&m, &qs).unwrap();
        let point = consistent_point(&m, &mut rng);
        let names = s.program.evaluate(&point);
        let mut memo = Vec::new();
        for ((q, v), d) in s.values.iter().zip(&ds) {
            let Value::Scalar(engine) = &d.value else {
                panic!("{}: {q} is not a scalar", path.display());
            };
            let expanded = s.program.expand(v, &mut memo);
            assert_eq!(&expanded, engine, "{}: {q}", path.display());
            let (a, b) = (lin_value(v, &point, &names), engine.eval(&point));
            assert!(
                (a - b).abs() <= 1e-9 * (1.0 + b.abs()),
                "{}: {q}: {a} against {b}",
                path.display()
            );
            held += 1;
        }
    }
    // The chains' dynamic moments and equations, the pendulums', the regulator's …
    assert!(held >= 100, "only {held} structured values");
}

#[test]
fn the_named_split_expands_to_the_equations_of_motion() {
    let mut seen = 0;
    for (path, m, s) in library() {
        let Some(named) = &s.motion else { continue };
        let eq = EquationsOfMotion::of(&m).unwrap();
        let ids: Vec<_> = (0..eq.coordinates().len())
            .map(|i| eq.coordinate(i))
            .collect();
        assert_eq!(named.coordinates, ids, "{}", path.display());
        let mut memo = Vec::new();
        let mut ex = |l| s.program.expand(l, &mut memo);
        for i in 0..ids.len() {
            for j in 0..ids.len() {
                assert_eq!(
                    ex(&named.mass[i][j]),
                    eq.mass[i][j],
                    "{}: M{i}{j}",
                    path.display()
                );
            }
            assert_eq!(
                ex(&named.velocity_terms[i]),
                eq.velocity_terms[i],
                "{}: h{i}",
                path.display()
            );
            assert_eq!(
                ex(&named.forces[i]),
                eq.forces[i],
                "{}: Q{i}",
                path.display()
            );
        }
        seen += 1;
    }
    assert!(seen >= 10, "only {seen} specs with the named split");
}

#[test]
fn a_chain_grows_with_its_structure_not_its_expansion() {
    // planar 12: the expanded equations hold thousands of terms; the named form's
    // definitions and entries stay a small multiple of the links.
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/chain/planar_12.json"
    );
    let m = torseur::spec::load(path).unwrap();
    let s = Structured::of(&m, m.quantities()).unwrap();
    let named: usize = s
        .program
        .definitions()
        .iter()
        .map(|d| d.value.nterms())
        .sum::<usize>()
        + s.values.iter().map(|(_, v)| v.nterms()).sum::<usize>();
    let mut memo = Vec::new();
    let expanded: usize = s
        .values
        .iter()
        .map(|(_, v)| s.program.expand(v, &mut memo).nterms())
        .sum();
    assert!(
        s.values
            .iter()
            .all(|(q, _)| matches!(q.kind, QuantityKind::Eom(_)))
    );
    assert_eq!(s.values.len(), 13);
    eprintln!("planar 12: {named} terms named, {expanded} expanded");
    assert!(
        named * 4 < expanded,
        "{named} named against {expanded} expanded"
    );
}

#[test]
fn the_compiled_named_equations_give_the_expanded_accelerations() {
    // The reference: the expanded entries of EquationsOfMotion evaluated term by term
    // (Expr::eval, double-double), solved by nalgebra; against the names compiled.
    let mut seen = 0;
    let mut rng = ChaCha8Rng::seed_from_u64(48);
    for (path, m, s) in library() {
        let Some(named) = &s.motion else { continue };
        let eq = EquationsOfMotion::of(&m).unwrap();
        let mut compiled = named.compile(&s.program).unwrap();
        let n = named.coordinates.len();
        for _ in 0..3 {
            let point = consistent_point(&m, &mut rng);
            let mass = nalgebra::DMatrix::from_fn(n, n, |i, j| eq.mass[i][j].eval(&point));
            let rhs = nalgebra::DVector::from_fn(n, |i, _| {
                eq.forces[i].eval(&point) - eq.velocity_terms[i].eval(&point)
            });
            let (Some(want), Some(got)) = (mass.lu().solve(&rhs), compiled.accelerations(&point))
            else {
                continue;
            };
            for i in 0..n {
                let scale = 1.0 + want[i].abs();
                assert!(
                    (got[i] - want[i]).abs() <= 1e-9 * scale,
                    "{}: q̈{i} {} against {}",
                    path.display(),
                    got[i],
                    want[i]
                );
            }
        }
        seen += 1;
    }
    assert!(seen >= 10, "only {seen} specs compiled");
}
