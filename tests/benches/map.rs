//! Speed of a stability map: 256 x 256 cells of `roller` (nu against the
//! load), every row with its critical loads, on every core, as `zieglerlab
//! map` and the app's map tab compute it (the spec `zieglerlab bench` times as
//! `map_ms`). Target: <= 300 ms on 2 cores.

#![expect(
    clippy::unwrap_used,
    reason = "benchmark fixtures: a bad preset should panic"
)]

use std::sync::atomic::{AtomicBool, AtomicUsize};

use criterion::{Criterion, criterion_group, criterion_main};
use zieglerlab::analysis::compute_map;
use zieglerlab::bench::roller_map_spec;

fn benches(c: &mut Criterion) {
    let spec = roller_map_spec();
    let threads = zieglerlab::machine_threads();
    let mut group = c.benchmark_group("map");
    group.sample_size(10);
    group.bench_function("roller 256x256 nu against load, all cores", |b| {
        b.iter(|| {
            let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
            compute_map(&spec, threads, &cancel, &done, &|_, row| {
                std::hint::black_box(row).unwrap();
            })
            .unwrap();
        });
    });
    group.finish();
}

criterion_group!(map_benches, benches);
criterion_main!(map_benches);
