//! In-process timing of the regulator's derivations (no process start).

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;

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
                .quantities
                .iter()
                .map(|q| torseur::derive(&m, q).unwrap())
                .collect();
            torseur::output::derive_text(&m, &ds).len()
        })
    });
}

criterion_group!(benches, regulator);
criterion_main!(benches);
