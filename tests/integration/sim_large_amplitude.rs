//! Far beyond the linear range, what does the column do? The roller's
//! friction dissipates, so its flutter settles on a limit cycle and its
//! divergence on a large swing; there rapier must land on the reference's
//! attractor. The ideal follower columns are undamped and not conservative:
//! they wander irregularly inside a bounded envelope with no attractor, so
//! only the envelope can be compared.

use crate::common;

use common::model;
use zieglerlab::model::Model;
use zieglerlab::sim::{DEFAULT_STEP_SECS, EngineKind, Simulation, Status, initial_state};

/// Ranges `[min, max]` of phi1 and phi2 over t in [100, 200] s.
fn ranges(model: &Model, engine: EngineKind) -> [[f64; 2]; 2] {
    let mut sim = Simulation::new(
        *model,
        engine,
        initial_state(model, 1e-3),
        DEFAULT_STEP_SECS,
    )
    .unwrap();
    assert_eq!(sim.run(100.0, |_| ()), Status::Running);
    let mut r = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
    let status = sim.run(100.0, |o| {
        for (range, angle) in r.iter_mut().zip([o.phi1_rad, o.phi2_rad]) {
            range[0] = range[0].min(angle);
            range[1] = range[1].max(angle);
        }
    });
    assert_eq!(status, Status::Running, "bounded: no blow-up");
    r
}

#[test]
fn roller_attractors_agree() {
    // Flutter (p = 3): an asymmetric limit cycle, phi2 in about [-1.65, 1.84].
    // Divergence (p = 5): a large swing, phi1 about +-1.41, phi2 +-2.76.
    for load in ["load=3", "load=5"] {
        let m = model("roller", &[load]);
        let (reference, rapier) = (
            ranges(&m, EngineKind::Reference),
            ranges(&m, EngineKind::Rapier),
        );
        for (a, b) in reference.iter().flatten().zip(rapier.iter().flatten()) {
            assert!((a - b).abs() < 0.05, "{load}: {reference:?} vs {rapier:?}");
        }
        assert!(
            reference[1][1] - reference[1][0] > 2.0,
            "large amplitude: {reference:?}"
        );
    }
}

#[test]
fn ideal_columns_stay_in_the_same_envelope() {
    for (name, load) in [
        ("midpoint-masses", "load=3.6"),
        ("ziegler-1952", "load=3"),
        ("midpoint-masses", "load=5"),
    ] {
        let m = model(name, &[load]);
        let (reference, rapier) = (
            ranges(&m, EngineKind::Reference),
            ranges(&m, EngineKind::Rapier),
        );
        let width = |r: [[f64; 2]; 2]| r[1][1] - r[1][0];
        let ratio = width(rapier) / width(reference);
        assert!(
            (0.75..1.33).contains(&ratio),
            "{name} {load}: {reference:?} vs {rapier:?}"
        );
    }
}
