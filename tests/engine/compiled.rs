//! The compiled evaluator (`Registry::compile`, symbolica's instruction lists from the
//! presentation form), which every simulation integrates with, against the exact expressions
//! evaluated term by term (`Expr::eval`, in double-double), on the equations of motion of every
//! spec of the library and of the small planar chains.

use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::collections::BTreeMap;
use std::f64::consts::PI;
use torseur::expr::{CoordId, Expr, Registry, Trig, VarRole};
use torseur::spec::wire::CoordinateKind;

/// Agreement demanded, relative.
const TOL: f64 = 1e-9;

/// States drawn per spec.
const STATES: u64 = 4;

/// A registry point of a random, consistent state: parameters (and the PFD's unknowns) in
/// [0.5, 2], angles in [−π, π], lengths in [0.5, 2], rates in [−2, 2]; cos q, sin q, 1/cos q,
/// 1/sin q and 1/p taken from the same q and p, so any identity the compiled form relies on
/// (cos² + sin² = 1, p · 1/p = 1) holds.
fn state(reg: &Registry, rng: &mut ChaCha8Rng) -> Vec<f64> {
    let mut params: BTreeMap<&str, f64> = BTreeMap::new();
    for p in reg.parameters().iter().chain(reg.unknowns()) {
        params.insert(p, rng.random_range(0.5..2.0));
    }
    // Each coordinate or constant angle parameter (whose value is the parameter's) drawn once.
    let mut coords: BTreeMap<CoordId, [f64; 4]> = BTreeMap::new();
    let mut coord = |c: CoordId| -> [f64; 4] {
        *coords.entry(c).or_insert_with(|| {
            let info = reg.coord_info(c);
            let q = match (
                info.is_constant(),
                params.get(info.name.as_str()),
                &info.kind,
            ) {
                (true, Some(&v), _) => v,
                (_, _, CoordinateKind::Angle) => rng.random_range(-PI..PI),
                (_, _, CoordinateKind::Length) => rng.random_range(0.5..2.0),
            };
            let mut r = || rng.random_range(-2.0..2.0);
            [q, r(), r(), r()]
        })
    };
    let mut point: Vec<f64> = reg
        .var_ids()
        .map(|v| match reg.role(v) {
            // π is the registry's constant, no drawn parameter.
            VarRole::Parameter(k) => reg
                .constant_value(k)
                .unwrap_or_else(|| params[reg.scalar_name(k)]),
            VarRole::Inverse(k) => {
                1.0 / reg
                    .constant_value(k)
                    .unwrap_or_else(|| params[reg.scalar_name(k)])
            }
            VarRole::Cos(c) => coord(c)[0].cos(),
            VarRole::Sin(c) => coord(c)[0].sin(),
            VarRole::Value(c) => coord(c)[0],
            VarRole::Rate(c, order) => coord(c)[usize::from(order)],
            VarRole::Reciprocal(c, Trig::Cos) => 1.0 / coord(c)[0].cos(),
            VarRole::Reciprocal(c, Trig::Sin) => 1.0 / coord(c)[0].sin(),
            // From the radicand, once every other variable is set.
            VarRole::Root(_) => f64::NAN,
        })
        .collect();
    reg.fill_roots(&mut point);
    point
}

/// Every output of `compiled` at `point` agrees with its expression evaluated exactly.
#[track_caller]
fn agree(what: &str, exprs: &[&Expr], point: &[f64], reg: &Registry) -> f64 {
    let mut compiled = reg.compile(exprs).unwrap();
    assert_eq!(compiled.outputs(), exprs.len());
    let mut out = vec![f64::NAN; exprs.len()];
    compiled.evaluate(point, &mut out);
    let mut worst = 0.0f64;
    for (k, (e, c)) in exprs.iter().zip(&out).enumerate() {
        let exact = e.eval(point);
        let err = (c - exact).abs() / exact.abs().max(f64::MIN_POSITIVE);
        assert!(
            err <= TOL || (c - exact).abs() == 0.0,
            "{what}, output {k}: compiled {c:e}, exact {exact:e} (relative {err:e})\n{e}"
        );
        worst = worst.max(err);
    }
    worst
}

/// The specs compared: the library's, and the planar chains small enough to derive quickly.
fn specs() -> Vec<std::path::PathBuf> {
    let mut out = super::specs_in(&["derivations"]);
    out.extend(
        super::specs_in(&["derivations/chain"])
            .into_iter()
            .filter(|p| {
                let stem = p.file_stem().unwrap().to_str().unwrap();
                ["planar_1", "planar_2", "planar_3", "planar_4"].contains(&stem)
            }),
    );
    out
}

/// For every spec with an equation of motion: (1) the compiled equations, the solved unknowns
/// (numerators and denominators: what a run records) agree with their exact values at random
/// states; (2) the accelerations the simulation takes, solved from the compiled mass matrix
/// and remainder (M q̈ + h = 0, M_ij = ∂eq_i/∂q̈_j), make the exact equations vanish.
#[test]
fn the_compiled_equations_of_motion_agree_with_the_exact_ones_on_every_spec() {
    let mut compared = Vec::new();
    let mut skipped = Vec::new();
    let mut worst = 0.0f64;
    for path in specs() {
        let stem = path.file_stem().unwrap().to_str().unwrap().to_string();
        let m = torseur::spec::load(&path).unwrap();
        let reg = m.reg();
        let sol = match torseur::pfd::solve(&m) {
            Ok(sol) if !sol.eom.is_empty() => sol,
            _ => {
                skipped.push(stem);
                continue;
            }
        };
        let free: Vec<CoordId> = sol.eom.keys().map(|n| reg.coord(n).unwrap()).collect();
        let eom: Vec<&Expr> = sol.eom.values().collect();
        let mut recorded: Vec<&Expr> = Vec::new();
        for f in sol.unknowns.values() {
            recorded.extend([&f.num, &f.den]);
        }
        // M q̈ + h: the mass matrix row by row, then the remainder.
        let n = free.len();
        let mass: Vec<Expr> = eom
            .iter()
            .flat_map(|e| free.iter().map(|&q| e.partial_rate(q, 2)))
            .collect();
        let rest: Vec<Expr> = eom
            .iter()
            .enumerate()
            .map(|(i, e)| {
                free.iter().enumerate().fold((*e).clone(), |h, (j, &q)| {
                    &h - &(&mass[i * n + j] * &reg.ddot(q))
                })
            })
            .collect();
        let split: Vec<&Expr> = mass.iter().chain(&rest).collect();
        let mut rng = ChaCha8Rng::seed_from_u64(33);
        for s in 0..STATES {
            let mut point = state(reg, &mut rng);
            let at = format!("{stem}, state {s}");
            worst = worst.max(agree(&format!("{at}, eom"), &eom, &point, reg));
            if !recorded.is_empty() {
                worst = worst.max(agree(&format!("{at}, unknowns"), &recorded, &point, reg));
            }
            let mut compiled = reg.compile(&split).unwrap();
            let mut out = vec![0.0; n * n + n];
            compiled.evaluate(&point, &mut out);
            let acc = DMatrix::from_row_slice(n, n, &out[..n * n])
                .lu()
                .solve(&-DVector::from_column_slice(&out[n * n..]))
                .unwrap_or_else(|| panic!("{at}: singular mass matrix"));
            for (j, &q) in free.iter().enumerate() {
                let slot = reg.index_of(VarRole::Rate(q, 2)).unwrap().index();
                point[slot] = acc[j];
            }
            for (i, e) in eom.iter().enumerate() {
                // The size of the terms that cancel: Σ |M_ij q̈_j| + |h_i|, exactly.
                let size = (0..n)
                    .map(|j| (mass[i * n + j].eval(&point) * acc[j]).abs())
                    .sum::<f64>()
                    + rest[i].eval(&point).abs();
                let residual = e.eval(&point);
                assert!(
                    residual.abs() <= TOL * size,
                    "{at}: equation {i} = {residual:e} at the compiled accelerations (terms of \
                     size {size:e})"
                );
            }
        }
        compared.push(stem);
    }
    eprintln!(
        "compared {}: {compared:?}; skipped {skipped:?}; worst relative {worst:e}",
        compared.len()
    );
    // The library's 22 specs with equations of motion and the 4 planar chains.
    assert_eq!(compared.len(), 26, "{compared:?}");
    assert_eq!(
        skipped,
        [
            // A shaft at an imposed speed on two ball joints: no equation of motion.
            "arbre_deux_rotules",
            "rotor_balourd",
            "rotor_deux_paliers",
            "rotor_vitesse_imposee",
            // The motor torque of a lift at a given acceleration: no equation of motion.
            "verin_a_vis"
        ]
    );
}
