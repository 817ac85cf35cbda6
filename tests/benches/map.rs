//! Speed of a stability map: 256 x 256 cells of `roller` (nu against the
//! load), every row with its critical loads, on every core, as `zieglerlab
//! map` and the app's map tab compute it. Target: <= 1 s on 2 cores.

#![expect(
    clippy::unwrap_used,
    reason = "benchmark fixtures: a bad preset should panic"
)]

use std::sync::atomic::{AtomicBool, AtomicUsize};

use criterion::{Criterion, criterion_group, criterion_main};
use zieglerlab::analysis::{MapSpec, compute_map};
use zieglerlab::model::{Axis, preset};

fn benches(c: &mut Criterion) {
    let model = preset("roller").unwrap().model();
    let spec = MapSpec {
        axis: Axis::parse("nu", &model, "roller").unwrap(),
        model,
        preset: "roller".to_owned(),
        load_range: (0.0, 8.0),
        loads: 256,
        axis_range: (0.005, 1.0),
        values: 256,
    };
    let threads = std::thread::available_parallelism().map_or(2, std::num::NonZero::get);
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
