//! Hopf criticality at a flutter onset: the normal form's cycle amplitude
//! agrees with the cycle the nonlinear simulation settles on, closer as the
//! load nears the onset; the first Lyapunov coefficient does not depend on
//! the difference steps; undamped columns are said to be reversible.

use crate::common::{model, transitions};
use zieglerlab::analysis::{Hopf, HopfKind, HopfSteps, NoHopf, hopf_at, is_hopf};
use zieglerlab::model::Model;
use zieglerlab::sim::{EngineKind, Simulation, initial_state};

/// The first flutter onset of `model` below p = 10 and its Hopf point.
fn onset(model: &Model, steps: HopfSteps) -> Result<Hopf, NoHopf> {
    let t = transitions(model, 10.0)
        .into_iter()
        .find(|t| is_hopf(t.from, t.to))
        .expect("a flutter onset");
    hopf_at(model, t.load, steps).expect("an analysis")
}

/// The largest |phi1| over two periods after the run has settled.
fn settled_amplitude(model: &Model, load: f64, start_rad: f64, secs: f64, period: f64) -> f64 {
    let at = model.at_load(load);
    let x0 = initial_state(&at, start_rad);
    let mut sim = Simulation::new(at, EngineKind::Reference, x0, 1.0 / 60.0).unwrap();
    sim.run(secs, |_| ());
    let mut most: f64 = 0.0;
    sim.run(2.0 * period, |o| most = most.max(o.angles_rad[0].abs()));
    most
}

#[test]
fn the_normal_form_s_amplitude_is_the_simulated_cycle_s_near_the_onset() {
    let m = model("ziegler-1952", &["c1=0.3", "c2=0.3"]);
    let hopf = onset(&m, HopfSteps::DEFAULT).unwrap();
    assert_eq!(hopf.kind, HopfKind::Supercritical);
    let period = std::f64::consts::TAU / hopf.frequency_rad_per_s;
    let mut errors = Vec::new();
    for fraction in [0.02, 0.005] {
        let above = fraction * hopf.load;
        let predicted = hopf.amplitude_per_sqrt_load_rad[0] * above.sqrt();
        // Eight e-foldings of the radial approach from half the amplitude.
        let secs = 8.0 / (hopf.growth_per_load * above);
        let simulated = settled_amplitude(&m, hopf.load + above, 0.5 * predicted, secs, period);
        let ratio = simulated / predicted;
        errors.push((ratio - 1.0).abs());
        assert!((ratio - 1.0).abs() < 0.02, "{fraction}: ratio {ratio}");
    }
    assert!(errors[1] < errors[0], "the ratio tends to 1: {errors:?}");
    // Below the onset the column comes to rest: no cycle there.
    let below = settled_amplitude(&m, 0.99 * hopf.load, 0.05, 4000.0, period);
    assert!(below < 0.01, "{below}");
}

#[test]
fn the_first_lyapunov_coefficient_does_not_depend_on_the_difference_steps() {
    let doubled = HopfSteps {
        jacobian: 2.0 * HopfSteps::DEFAULT.jacobian,
        second: 2.0 * HopfSteps::DEFAULT.second,
        third: 2.0 * HopfSteps::DEFAULT.third,
    };
    for (name, sets) in [
        ("ziegler-1952", ["c1=0.01", "c2=0.01"]),
        ("uniform-rods", ["c1=0.01", "c2=0.02"]),
        ("midpoint-masses", ["c1=0.02", "c2=0.01"]),
        ("ziegler-1952", ["c_ext=0.01", "c1=0"]),
    ] {
        let m = model(name, &sets);
        let (a, b) = (
            onset(&m, HopfSteps::DEFAULT).unwrap(),
            onset(&m, doubled).unwrap(),
        );
        let relative = (a.first_lyapunov - b.first_lyapunov).abs() / a.first_lyapunov.abs();
        assert!(relative < 2e-3, "{name} {sets:?}: {a:?} vs {b:?}");
        assert_eq!(a.kind, b.kind);
        assert!(a.frequency_rad_per_s > 0.0 && a.growth_per_load > 0.0);
    }
}

#[test]
fn an_undamped_column_is_reversible_and_the_roller_dissipates() {
    assert_eq!(
        onset(&model("ziegler-1952", &[]), HopfSteps::DEFAULT),
        Err(NoHopf::Reversible)
    );
    // A massless roller is exactly the ideal follower force: reversible.
    assert_eq!(
        onset(&model("roller", &["m3=0"]), HopfSteps::DEFAULT),
        Err(NoHopf::Reversible)
    );
    // With mass its spin slips on the band: soft flutter.
    let roller = onset(&model("roller", &[]), HopfSteps::DEFAULT).unwrap();
    assert_eq!(roller.kind, HopfKind::Supercritical);
}

#[test]
fn critical_json_gives_each_flutter_onset_its_criticality() {
    let printed = crate::cli::stdout(&[
        "critical",
        "--preset",
        "ziegler-1952",
        "--set",
        "c1=0.3",
        "--set",
        "c2=0.3",
        "--json",
    ]);
    let value: serde_json::Value = serde_json::from_str(&printed).unwrap();
    let first = &value["transitions"][0];
    assert_eq!(first["to"], "flutter");
    let hopf = onset(
        &model("ziegler-1952", &["c1=0.3", "c2=0.3"]),
        HopfSteps::DEFAULT,
    )
    .unwrap();
    assert_eq!(first["hopf"]["kind"], "supercritical");
    assert_eq!(
        first["hopf"]["first_lyapunov"].as_f64(),
        Some(hopf.first_lyapunov)
    );
    // Flutter to divergence is no Hopf point.
    assert!(value["transitions"][1].get("hopf").is_none());
    let undamped: serde_json::Value = serde_json::from_str(&crate::cli::stdout(&[
        "critical",
        "--preset",
        "ziegler-1952",
        "--json",
    ]))
    .unwrap();
    assert_eq!(undamped["transitions"][0]["hopf"]["kind"], "reversible");
}

#[test]
fn the_first_lyapunov_coefficient_is_the_same_by_differences_and_by_jets() {
    use zieglerlab::analysis::Derivatives;
    for (name, sets) in [
        ("ziegler-1952", &["c1=0.3", "c2=0.3"][..]),
        ("uniform-rods", &["c1=0.01", "c2=0.02"][..]),
        ("midpoint-masses", &["c1=0.02", "c2=0.01"][..]),
        ("ziegler-1952", &["c1=0.1", "c2=0.05", "eta=0.8"][..]),
        ("uniform-rods", &["rods=4", "c1=0.05", "c2=0.05"][..]),
    ] {
        let m = model(name, sets);
        let t = transitions(&m, 10.0)
            .into_iter()
            .find(|t| is_hopf(t.from, t.to))
            .expect("a flutter onset");
        let differences = hopf_at(&m, t.load, HopfSteps::DEFAULT).unwrap().unwrap();
        let jets = hopf_at(&m, t.load, Derivatives::Automatic)
            .unwrap()
            .unwrap();
        let relative =
            (differences.first_lyapunov - jets.first_lyapunov).abs() / jets.first_lyapunov.abs();
        // Seen: 4e-9 to 4.5e-8 (1.6e-7 to 4.1e-5 before the third
        // derivative's differences were extrapolated).
        assert!(
            relative < 1e-6,
            "{name} {sets:?}: {jets:?} vs {differences:?}"
        );
        assert_eq!(jets.kind, differences.kind);
        let amplitude = |h: &Hopf| h.amplitude_per_sqrt_load_rad[0];
        assert!((amplitude(&jets) / amplitude(&differences) - 1.0).abs() < 1e-6);
    }
    // Drag along the rods is not written over jets: said, not guessed.
    let dragged = model("ziegler-1952", &["c_ext=0.01"]);
    let t = transitions(&dragged, 10.0)
        .into_iter()
        .find(|t| is_hopf(t.from, t.to))
        .expect("a flutter onset");
    let error = hopf_at(&dragged, t.load, Derivatives::Automatic).unwrap_err();
    assert!(error.to_string().contains("without drag"), "{error}");
}
