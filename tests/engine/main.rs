//! Integration tests of the engine; modules mirror `src/`.
#![allow(clippy::needless_range_loop)]
//!
//! Expected values come from routes that do not share the code under test: hand derivations
//! from the course, a second theorem, or the definitions.

mod action_sources;
mod actions;
mod bilan;
mod budget;
mod carried;
mod chain;
mod check;
mod closures;
mod compiled;
mod corpus;
mod coulomb;
mod derivation;
mod derivative;
mod energy;
mod eval;
mod figures;
mod first_order;
mod fourier;
mod free_texts;
mod friction;
mod golden;
mod helical;
mod hyperstatic;
mod hypotheses;
mod inverse;
mod kinematics;
mod latex;
mod latex_safe;
mod layers;
mod library;
mod links;
mod loop_verify;
mod massless;
mod messages;
mod motion;
mod parity;
mod parity_sections;
mod pfd;
mod power;
mod printed;
mod printed_names;
mod properties;
mod rates;
mod regulator;
mod rolling;
mod sets;
mod simulate;
mod spec_errors;
mod spec_schema;
mod structured;
mod threads;
mod trial;
mod units;
mod verify;

use torseur::expr::Expr;
use torseur::frame::FrameId;
use torseur::mechanism::Mechanism;
use torseur::vector::Vector;

/// The course's Application 1.
pub fn regulator() -> Mechanism {
    torseur::spec::load(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    ))
    .expect("the regulator spec loads")
}

/// The spec files (`*.json`) of the repository's folders `dirs`, each folder sorted by name.
pub fn specs_in(dirs: &[&str]) -> Vec<std::path::PathBuf> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = Vec::new();
    for dir in dirs {
        let mut v: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap_or_else(|e| panic!("{dir}: {e}"))
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "json"))
            .collect();
        v.sort();
        out.extend(v);
    }
    out
}

/// Parses an expression of the spec syntax in the mechanism.
pub fn ex(m: &Mechanism, s: &str) -> Expr {
    m.reg().parse(s).unwrap_or_else(|e| panic!("{s}: {e}"))
}

/// Frame by name.
pub fn frame(m: &Mechanism, n: &str) -> FrameId {
    m.frames().find(n).unwrap()
}

/// Asserts two vectors are exactly equal (compared in basis `b`).
pub fn assert_vec_eq(m: &Mechanism, a: &Vector, b: &Vector, what: &str) {
    let f = m.frames().ground();
    let (x, y) = (a.express_in(m.frames(), f), b.express_in(m.frames(), f));
    for k in 0..3 {
        assert_eq!(
            x[k], y[k],
            "{what}: component {k} differs: {} vs {}",
            x[k], y[k]
        );
    }
}

/// Asserts a vector has the given components (strings) in basis `b`.
pub fn assert_components(m: &Mechanism, v: &Vector, b: &str, expected: [&str; 3], what: &str) {
    let c = v.express_in(m.frames(), frame(m, b));
    for k in 0..3 {
        let e = ex(m, expected[k]);
        assert_eq!(
            c[k], e,
            "{what}: component {k} is {} but the hand derivation gives {}",
            c[k], e
        );
    }
}

/// Both sides' verdicts: the exact side's error, and whether the float backend refuses too.
pub fn refused_by_both(v: &serde_json::Value) -> (String, String) {
    let file = torseur::spec::parse_spec(&v.to_string()).unwrap();
    let exact = torseur::spec::build(&file).expect_err("the exact side accepted it");
    let float =
        torseur::numeric::NumericModel::new(&file).expect_err("the float backend accepted it");
    (exact.to_string(), float.to_string())
}

/// One classical Runge–Kutta step of length `h` on (q, q̇)' = f(q, q̇): the hand integrations
/// the simulations are compared with.
pub fn rk4_step(f: &dyn Fn([f64; 2]) -> [f64; 2], y: &mut [f64; 2], h: f64) {
    let k1 = f(*y);
    let k2 = f([y[0] + h / 2.0 * k1[0], y[1] + h / 2.0 * k1[1]]);
    let k3 = f([y[0] + h / 2.0 * k2[0], y[1] + h / 2.0 * k2[1]]);
    let k4 = f([y[0] + h * k3[0], y[1] + h * k3[1]]);
    for i in 0..2 {
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
}
