//! Whole-process timing of `torseur derive` on the regulator: process start, spec loading,
//! every requested quantity in canonical and presentation form, under every hypothesis.
//! This bench binary never uses symbolica itself (it only spawns the CLI).

use criterion::{Criterion, criterion_group, criterion_main};
use std::process::Command;

fn whole_process(c: &mut Criterion) {
    let spec = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/derivations/regulateur_centrifuge.json"
    );
    let json = std::env::temp_dir().join("torseur-bench-regulateur.json");
    c.bench_function("derive regulateur_centrifuge.json (whole process)", |b| {
        b.iter(|| {
            let o = Command::new(env!("CARGO_BIN_EXE_torseur"))
                .args(["derive", spec, "--json"])
                .arg(&json)
                .output()
                .expect("runs");
            assert!(o.status.success());
            o.stdout.len()
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(30);
    targets = whole_process
}
criterion_main!(benches);
