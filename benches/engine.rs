//! In-process timings on the regulator: loading, deriving every quantity, and evaluating
//! δ(O2,2/0) numerically: compiled (symbolica's evaluator), flat (`FlatEval`), the canonical
//! polynomial, and the float backend.

use criterion::{Criterion, criterion_group, criterion_main};
use rand::SeedableRng;
use std::hint::black_box;
use torseur::derivation::derive;
use torseur::numeric::NumericModel;
use torseur::output::{Values, numeric_point};
use torseur::quantity::Quantity;

fn regulator(c: &mut Criterion) {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    );
    let m = torseur::spec::load(path).unwrap();
    c.bench_function("load regulator spec", |b| {
        b.iter(|| torseur::spec::load(black_box(path)).unwrap())
    });
    c.bench_function("derive all regulator quantities + presentation", |b| {
        b.iter(|| {
            let ds: Vec<_> = m
                .quantities()
                .iter()
                .map(|q| derive(&m, q).unwrap())
                .collect();
            torseur::output::derive_text(&m, &ds).len()
        })
    });

    // δ(O2,2/0) in B2 at many points: compiled once, evaluated per point.
    let q = Quantity::parse("delta(O2,2/0) in B2").unwrap();
    let v = derive(&m, &q).unwrap().value;
    let exprs = v.exprs();
    let mut compiled = m.reg().compile(&exprs).unwrap();
    let model = NumericModel::new(m.spec()).unwrap();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(1);
    let sample = model.sample(&mut rng).unwrap();
    let values = Values {
        parameters: sample.parameters.clone(),
        coordinates: sample.coordinates.clone(),
        ..Default::default()
    };
    let point = numeric_point(&m, &values).unwrap();
    let mut out = [0.0; 3];
    compiled.evaluate(&point, &mut out);
    let reference = model.evaluate(&q, &sample, "0").unwrap().numbers();
    for k in 0..3 {
        assert!((out[k] - reference[k]).abs() <= 1e-9 * (1.0 + reference[k].abs()));
    }
    c.bench_function("delta(O2,2/0) compiled evaluation (per point)", |b| {
        b.iter(|| {
            compiled.evaluate(black_box(&point), &mut out);
            out[0]
        })
    });
    let mut flat = torseur::expr::FlatEval::new(&exprs).unwrap();
    let mut out_flat = [0.0; 3];
    flat.evaluate(&point, &mut out_flat);
    for k in 0..3 {
        assert!((out_flat[k] - reference[k]).abs() <= 1e-9 * (1.0 + reference[k].abs()));
    }
    c.bench_function("delta(O2,2/0) flat evaluation (per point)", |b| {
        b.iter(|| {
            flat.evaluate(black_box(&point), &mut out_flat);
            out_flat[0]
        })
    });
    c.bench_function(
        "delta(O2,2/0) canonical polynomial evaluation (per point)",
        |b| b.iter(|| exprs.iter().map(|e| e.eval(black_box(&point))).sum::<f64>()),
    );
    c.bench_function(
        "delta(O2,2/0) float backend from definitions (per point)",
        |b| b.iter(|| model.evaluate(black_box(&q), &sample, "0").unwrap()),
    );
}

criterion_group!(benches, regulator);
criterion_main!(benches);
