//! Speed of the two engines: simulated seconds per wall second at the app's
//! step, for the default launch (roller, p = 1, weak flutter) and a growing
//! flutter (p = 3). Each iteration simulates 10 s; real-time factor =
//! 10 s / time per iteration.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use zieglerlab::model::preset;
use zieglerlab::sim::{DEFAULT_STEP_SECS, EngineKind, Simulation, initial_state};

const SIMULATED_SECS: f64 = 10.0;

fn benches(c: &mut Criterion) {
    for (engine, name) in [
        (EngineKind::Reference, "reference"),
        (EngineKind::Rapier, "rapier"),
    ] {
        for load in [1.0, 3.0] {
            let model = preset("roller").unwrap().model().at_load(load);
            c.bench_function(&format!("{name} roller p={load} 10 s at dt=1/240"), |b| {
                b.iter(|| {
                    let mut sim = Simulation::new(
                        model,
                        engine,
                        initial_state(&model, 1e-3),
                        DEFAULT_STEP_SECS,
                    )
                    .unwrap();
                    black_box(sim.run(SIMULATED_SECS, |_| ()))
                });
            });
        }
    }
}

criterion_group!(sim_benches, benches);
criterion_main!(sim_benches);
