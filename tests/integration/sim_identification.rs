//! A run at small amplitude is the linear column: the growth rate and the
//! frequency measured from each engine's trajectory (matrix pencil method)
//! agree with the eigenvalues of the linearization, in the stable, flutter
//! and divergence ranges. This is what makes the animation honest: the
//! column flutters at the load the root locus predicts.

use crate::common;

use common::{identified, model, predicted};
use zieglerlab::analysis::{C64, classify};
use zieglerlab::model::Model;
use zieglerlab::sim::{DEFAULT_STEP_SECS, EngineKind};

/// The window: long enough for the slowest mode, short enough that the
/// fastest-growing one stays small (below about 0.01 rad from 0.001 rad).
fn window_secs(predicted: &[C64]) -> f64 {
    let growth = predicted.iter().map(|z| z.re).fold(0.0, f64::max);
    let slowest = predicted
        .iter()
        .filter(|z| z.im.abs() > 0.0)
        .map(|z| z.im.abs())
        .fold(f64::INFINITY, f64::min);
    let periods = if slowest.is_finite() {
        12.0 * std::f64::consts::TAU / slowest
    } else {
        10.0
    };
    if growth > 0.0 {
        periods.min(10f64.ln() / growth)
    } else {
        periods
    }
}

/// Each predicted mode is found; the dominant one's growth rate, and every
/// mode's frequency, within `tolerance` (relative).
fn check(model: &Model, engine: EngineKind, tolerance: f64) {
    check_modes(model, engine, tolerance, Modes::All);
}

/// Which modes' frequencies are checked.
#[derive(Clone, Copy, PartialEq)]
enum Modes {
    All,
    /// Only the dominant one: beside a fast-growing pair, its decaying twin
    /// is gone from the trajectory before it can be measured.
    Dominant,
}

fn check_modes(model: &Model, engine: EngineKind, tolerance: f64, modes: Modes) {
    let predicted = predicted(model, 5.0);
    let window = window_secs(&predicted);
    let found = identified(model, engine, DEFAULT_STEP_SECS, window, predicted.len());
    let scale = predicted.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let dominant = classify(&predicted, scale).dominant;
    let checked: Vec<C64> = match modes {
        Modes::All => predicted.clone(),
        Modes::Dominant => vec![dominant],
    };
    for p in &checked {
        let m = found
            .iter()
            .min_by(|a, b| (*a - p).norm().total_cmp(&(*b - p).norm()))
            .unwrap();
        let label = format!(
            "p={} {engine:?}: predicted {p}, measured {m}",
            model.load_p()
        );
        assert!(
            (m.im - p.im).abs() <= tolerance * p.im.abs().max(0.01 * scale),
            "frequency {label}"
        );
    }
    let measured = found
        .iter()
        .min_by(|a, b| (*a - dominant).norm().total_cmp(&(*b - dominant).norm()))
        .unwrap();
    // A zero growth rate (undamped, stable) is matched to the same fraction of |lambda|.
    let allowed = tolerance * dominant.re.abs().max(0.01 * dominant.norm());
    assert!(
        (measured.re - dominant.re).abs() <= allowed,
        "growth p={}: predicted {dominant}, measured {measured}",
        model.load_p()
    );
}

#[test]
fn reference_midpoint_masses_stable_flutter_divergence() {
    for p in ["load=1.5", "load=3.6", "load=5"] {
        check(
            &model("midpoint-masses", &[p]),
            EngineKind::Reference,
            0.005,
        );
    }
}

#[test]
fn reference_roller_stable_weak_flutter_flutter_divergence() {
    for p in ["load=0.012", "load=1", "load=3", "load=5"] {
        check(&model("roller", &[p]), EngineKind::Reference, 0.005);
    }
}

#[test]
fn rapier_midpoint_masses_stable_flutter_divergence() {
    for p in ["load=1.5", "load=3.6", "load=5"] {
        check(&model("midpoint-masses", &[p]), EngineKind::Rapier, 0.03);
    }
}

#[test]
fn rapier_roller_stable_weak_flutter_flutter_divergence() {
    for p in ["load=0.012", "load=1", "load=3", "load=5"] {
        check(&model("roller", &[p]), EngineKind::Rapier, 0.03);
    }
}

/// A partially tangential force (eta = 0.6 on the midpoint masses: stable,
/// flutter from p = 2.328, divergence from p = 3.134) runs as its
/// linearization predicts on both engines.
#[test]
fn both_engines_run_a_partially_tangential_force() {
    for (p, modes) in [
        ("load=1.5", Modes::All),
        ("load=2.6", Modes::Dominant),
        ("load=4", Modes::All),
    ] {
        let column = model("midpoint-masses", &[p, "eta=0.6"]);
        check_modes(&column, EngineKind::Reference, 0.005, modes);
        check_modes(&column, EngineKind::Rapier, 0.03, modes);
    }
}

/// External drag on the uniform rods (stable and damped at p = 1.5, flutter
/// at p = 3.2) decays and grows on both engines at the eigenvalues' rates.
#[test]
fn both_engines_run_external_drag() {
    for p in ["load=1.5", "load=3.2"] {
        let column = model("uniform-rods", &[p, "c_ext=0.02"]);
        check(&column, EngineKind::Reference, 0.005);
        check(&column, EngineKind::Rapier, 0.03);
    }
}

/// A chain of 4 rods (flutter from p = 0.9371) on both engines: before the
/// onset its slowest mode, past it the growing one, at the eigenvalues'
/// frequency and growth rate. The same with the roller at the chain's end
/// (its first flutter at p = 0.0044 is weak, growing by 1e-3 1/s; at
/// p = 1 one mode grows at 0.055 1/s, a period of 41 s).
#[test]
fn both_engines_run_a_chain_as_its_eigenvalues_predict() {
    for (preset, p) in [
        ("uniform-rods", "load=0.5"),
        ("uniform-rods", "load=1.1"),
        ("roller", "load=1.0"),
    ] {
        let chain = model(preset, &[p, "rods=4"]);
        check_modes(&chain, EngineKind::Reference, 0.005, Modes::Dominant);
        check_modes(&chain, EngineKind::Rapier, 0.03, Modes::Dominant);
    }
}
