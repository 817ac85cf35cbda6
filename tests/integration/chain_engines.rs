//! Chains of rods on both engines: rapier's multibody chain of N links
//! keeps a free chain's energy, the two engines follow the same trajectory
//! of a chain under a follower force and under the roller, and a massless
//! roller at the end of a chain moves it as the follower force does.

use crate::common;

use common::model;
use zieglerlab::model::Model;
use zieglerlab::sim::{
    DEFAULT_STEP_SECS, EngineKind, Observables, Simulation, Status, initial_state,
};

/// The angles of every rod at each step of a run from a `kick_rad` kick.
fn angles(model: &Model, engine: EngineKind, kick_rad: f64, duration_secs: f64) -> Vec<Vec<f64>> {
    let mut sim = Simulation::new(
        *model,
        engine,
        initial_state(model, kick_rad),
        DEFAULT_STEP_SECS,
    )
    .unwrap();
    let mut out = vec![sim.observe().angles_rad];
    let status = sim.run(duration_secs, |o: &Observables| {
        out.push(o.angles_rad.clone());
    });
    assert_eq!(status, Status::Running, "the run stopped early");
    out
}

/// The largest difference of any rod's angle between rapier's run and the
/// reference engine's over 30 s from a `kick_rad` kick, relative to the
/// reference's largest angle; printed (run with --nocapture).
fn rapier_gap(model: &Model, label: &str, kick_rad: f64) -> f64 {
    let reference = angles(model, EngineKind::Reference, kick_rad, 30.0);
    let rapier = angles(model, EngineKind::Rapier, kick_rad, 30.0);
    let gap = largest_gap(&reference, &rapier);
    println!(
        "{label}: rapier within {:.3}% of the reference",
        100.0 * gap
    );
    gap
}

/// The largest difference of any rod's angle between two runs, relative to
/// the largest angle of the first.
fn largest_gap(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    let mut gap: f64 = 0.0;
    let mut amplitude: f64 = 0.0;
    for (x, y) in a.iter().zip(b) {
        for (u, v) in x.iter().zip(y) {
            gap = gap.max((u - v).abs());
            amplitude = amplitude.max(u.abs());
        }
    }
    gap / amplitude
}

/// rapier's multibody chain of 8 links, unloaded, from a 0.3 rad kick:
/// its energy drifts by less than 1% over 50 s (f32, symplectic Euler; the
/// drift is printed), as the two-rod column's does.
#[test]
fn rapier_keeps_a_free_chain_s_energy() {
    let chain = model("uniform-rods", &["rods=8", "load=0"]);
    let mut sim = Simulation::new(
        chain,
        EngineKind::Rapier,
        initial_state(&chain, 0.3),
        DEFAULT_STEP_SECS,
    )
    .unwrap();
    let start = sim.observe().energy_j();
    let mut worst: f64 = 0.0;
    let mut swing: f64 = 0.0;
    sim.run(50.0, |o| {
        worst = worst.max((o.energy_j() - start).abs());
        swing = swing.max(o.kinetic_j);
    });
    println!(
        "rapier, 8 free rods: energy drift over 50 s {:.4}%",
        100.0 * worst / start
    );
    // The chain does move: its kinetic energy reaches a good part of the total.
    assert!(swing > 0.2 * start, "{swing} of {start}");
    assert!(worst < 0.01 * start, "drift {worst:e} of {start:e}");
}

/// A chain of 4 rods below flutter (p = 0.5), past it (p = 1.1; the onset
/// is 0.9371) and at large amplitude unloaded: rapier's trajectory is the
/// reference engine's to within 1% of the swing over 30 s.
#[test]
fn the_engines_agree_on_a_chain_of_four() {
    for (sets, kick_rad) in [
        (&["rods=4", "load=0.5"][..], 1e-3),
        (&["rods=4", "load=1.1"][..], 1e-3),
        (&["rods=4", "load=0", "c2=0.02"][..], 0.3),
    ] {
        let gap = rapier_gap(&model("uniform-rods", sets), &format!("{sets:?}"), kick_rad);
        assert!(gap < 0.01, "{sets:?}: {gap}");
    }
}

/// The roller at the end of a chain of 4 rods, on both engines: the same
/// trajectory to within 2% of the swing over 30 s, below the roller
/// chain's first flutter load and past it.
#[test]
fn the_engines_agree_on_a_roller_at_the_end_of_a_chain() {
    for load in ["load=0.5", "load=1.5"] {
        let chain = model("roller", &["rods=4", load]);
        let gap = rapier_gap(&chain, &format!("roller, 4 rods, {load}"), 1e-3);
        assert!(gap < 0.02, "{load}: {gap}");
    }
}

/// A massless roller's friction is the ideal follower force `P = mu R`
/// while the band slips forward: on a chain of 4 rods both engines move
/// the chain as the follower force does.
#[test]
fn a_massless_roller_moves_a_chain_as_the_follower_force() {
    let follower = model("uniform-rods", &["rods=4", "load=1.1"]);
    let roller = model("roller", &["rods=4", "load=1.1", "m3=0"]);
    for (engine, tolerance) in [(EngineKind::Reference, 1e-7), (EngineKind::Rapier, 1e-4)] {
        let a = angles(&follower, engine, 1e-3, 20.0);
        let b = angles(&roller, engine, 1e-3, 20.0);
        let gap = largest_gap(&a, &b);
        assert!(gap < tolerance, "{engine:?}: {gap:e}");
    }
}
