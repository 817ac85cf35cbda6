//! Speed of the analysis core: the tracked, refined root locus over 1000
//! loads (the app recomputes it whenever a slider moves), the critical loads,
//! and one eigenvalue solve on the robust Schur path for comparison.

#![expect(
    clippy::unwrap_used,
    reason = "benchmark fixtures: a bad preset should panic"
)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use zieglerlab::analysis::{AffinePencil, critical_loads, locus};
use zieglerlab::model::preset;

const LOADS: usize = 1000;

fn pencil(name: &str) -> AffinePencil {
    AffinePencil::new(&preset(name).unwrap().model())
        .unwrap()
        .with_threads(zieglerlab::machine_threads())
}

fn benches(c: &mut Criterion) {
    for name in ["roller", "midpoint-masses"] {
        let pencil = pencil(name);
        c.bench_function(&format!("locus {name} 1000 loads p in [0, 10]"), |b| {
            b.iter(|| locus(black_box(&pencil), 0.0, 10.0, LOADS));
        });
    }
    let roller = pencil("roller");
    c.bench_function("critical loads roller p in [0, 10]", |b| {
        b.iter(|| critical_loads(black_box(&roller), 0.0, 10.0));
    });
    c.bench_function("schur spectrum roller (one load)", |b| {
        b.iter(|| roller.spectrum(black_box(2.0)));
    });
}

criterion_group!(locus_benches, benches);
criterion_main!(locus_benches);
