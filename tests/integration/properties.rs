//! Properties over the whole valid parameter space (proptest): the eigen
//! analysis never panics and gives 2n finite eigenvalues, the critical
//! loads are finite and ordered, and 10 s of simulation never produce a
//! non-finite state, whatever the run's status.

use proptest::prelude::*;
use zieglerlab::analysis::{AffinePencil, critical_loads};
use zieglerlab::model::{Assignment, Model, apply_assignments, preset};
use zieglerlab::sim::{EngineKind, SimError, Simulation, initial_state};

/// A value spread evenly in log10 over `[10^lo, 10^hi]`.
fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..=hi).prop_map(|e: f64| 10f64.powf(e))
}

fn with(name: &str, sets: &[(&str, f64)]) -> Model {
    let mut model = preset(name).unwrap().model();
    let assignments: Vec<Assignment> = sets
        .iter()
        .map(|&(key, value)| Assignment {
            key: key.parse().unwrap(),
            value,
        })
        .collect();
    apply_assignments(&mut model, &assignments).unwrap();
    model
}

/// The roller over its groups: a, the mass ratio nu from 1e-9 to 1e3 (and
/// 0), rho, mu, the band speed V, the load, and joint dampers.
fn roller() -> impl Strategy<Value = Model> {
    (
        log_uniform(-2.0, 2.0),
        prop_oneof![Just(0.0), log_uniform(-9.0, 3.0)],
        (0.01..=1.0f64),
        log_uniform(-3.0, 0.0),
        log_uniform(-6.0, 2.0),
        (0.0..=1e3f64),
        (0.0..=1.0f64, 0.0..=1.0f64),
    )
        .prop_map(|(a, nu, rho, mu, v, load, (c1, c2))| {
            with(
                "roller",
                &[
                    ("a", a),
                    ("nu", nu),
                    ("rho", rho),
                    ("mu", mu),
                    ("V", v),
                    ("c1", c1),
                    ("c2", c2),
                    ("load", load),
                ],
            )
        })
}

/// The 2-DOF presets over SI masses and springs spread over `decades` either
/// side of 1, lengths, dampers and the load.
fn column(decades: f64) -> impl Strategy<Value = Model> {
    let spread = || log_uniform(-decades, decades);
    (
        prop::sample::select(vec!["ziegler-1952", "uniform-rods", "midpoint-masses"]),
        (log_uniform(-2.0, 2.0), log_uniform(-2.0, 2.0)),
        (spread(), spread()),
        (spread(), spread()),
        (0.0..=10.0f64, 0.0..=10.0f64),
        (0.0..=1e3f64),
    )
        .prop_map(|(name, (l1, l2), (m1, m2), (k1, k2), (c1, c2), load)| {
            let mut model = with(name, &[("l1", l1), ("l2", l2), ("k1", k1), ("k2", k2)]);
            // Masses where the preset has them (ziegler-1952 has point masses).
            for (key, value) in [
                ("m1", m1),
                ("m2", m2),
                ("c1", c1),
                ("c2", c2),
                ("load", load),
            ] {
                let set = [Assignment {
                    key: key.parse().unwrap(),
                    value,
                }];
                let mut candidate = model;
                if apply_assignments(&mut candidate, &set).is_ok() {
                    model = candidate;
                }
            }
            model
        })
}

fn check_analysis(model: &Model) -> Result<(), TestCaseError> {
    let pencil = AffinePencil::new(model).unwrap();
    let spectrum = pencil.spectrum(model.load_p()).unwrap();
    // 2n eigenvalues, n the degrees of freedom; a massless roller's spin has
    // no inertia (its rate is slaved to the column), so its mass matrix is
    // singular and one of the 2n is infinite: 2n - 1 finite ones.
    let massless = model.roller().is_some_and(|r| r.mass_kg == 0.0);
    let expected = 2 * model.dof() - usize::from(massless);
    prop_assert_eq!(
        spectrum.eigenvalues.len() + spectrum.structural_zeros,
        expected
    );
    prop_assert_eq!(spectrum.all().count(), expected);
    prop_assert!(spectrum.all().all(|z| z.re.is_finite() && z.im.is_finite()));
    let transitions = critical_loads(&pencil, 0.0, 10.0).unwrap();
    prop_assert!(transitions.iter().all(|t| t.load.is_finite()));
    prop_assert!(transitions.windows(2).all(|w| w[0].load <= w[1].load));
    Ok(())
}

/// 10 s of `engine`: refused up front (a step too long for rapier) or run
/// to the end or to a status, with every state finite.
fn check_run(model: &Model, engine: EngineKind) -> Result<(), TestCaseError> {
    let x0 = initial_state(model, 1e-3);
    let mut sim = match Simulation::new(*model, engine, x0, 1.0 / 240.0) {
        Ok(sim) => sim,
        Err(SimError::TooStiffForRapier { .. }) => return Ok(()),
        Err(error) => return Err(TestCaseError::fail(error.to_string())),
    };
    let mut finite = true;
    sim.run(10.0, |o| {
        finite &= [o.phi1_rad, o.phi2_rad, o.psi_rad, o.delta_rad, o.energy_j()]
            .iter()
            .all(|v| v.is_finite());
    });
    prop_assert!(finite);
    prop_assert!(sim.state().iter().all(|v| v.is_finite()));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn roller_analysis_is_finite(model in roller()) {
        check_analysis(&model)?;
    }

    #[test]
    fn column_analysis_is_finite(model in column(3.0)) {
        check_analysis(&model)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// rapier, the app's engine, over the whole space.
    #[test]
    fn rapier_runs_stay_finite(model in prop_oneof![roller(), column(3.0)]) {
        check_run(&model, EngineKind::Rapier)?;
    }

    /// The reference engine where it is not stiff (masses and springs within
    /// a decade of 1, no roller): its explicit adaptive steps take minutes
    /// of CPU on stiff columns in a debug build (its step budget then stops
    /// the run with a status, as `bad_input` shows for nu = 1e-9).
    #[test]
    fn reference_runs_stay_finite(model in column(1.0)) {
        check_run(&model, EngineKind::Reference)?;
    }
}

/// Chains of 2 to 64 rods with a partial follower (`eta`) and drag along
/// the rods (`c_ext`), the values drawn also beyond what they may be: each
/// case is analysed (2n finite eigenvalues; the critical loads, finite and
/// ordered, up to 12 rods, where a debug build takes seconds) or refused
/// naming the key that was wrong. How many cases each answer took is
/// printed and must show every kind.
#[test]
fn chains_with_eta_and_drag_are_analysed_or_refused_by_name() {
    use proptest::test_runner::{Config, TestRunner};
    use std::cell::RefCell;
    use std::collections::BTreeMap;
    let counts = RefCell::new(BTreeMap::<String, usize>::new());
    let count = |what: &str| *counts.borrow_mut().entry(what.to_owned()).or_default() += 1;
    let cases = (
        prop::sample::select(vec!["beck", "pflueger"]),
        prop_oneof![3 => (2.0..=64.0f64).prop_map(f64::round), 1 => -4.0..=80.0f64],
        prop_oneof![3 => 0.0..=1.0f64, 1 => -1.0..=2.0f64],
        prop_oneof![
            Just(0.0),
            log_uniform(-3.0, 2.0),
            Just(-1.0),
            log_uniform(150.0, 200.0)
        ],
        0.0..=1.0f64,
    );
    let mut runner = TestRunner::new(Config::with_cases(96));
    runner
        .run(&cases, |(name, rods, eta, c_ext, load_share)| {
            let mut model = preset(name).unwrap().model();
            let sets: Vec<Assignment> = [("rods", rods), ("eta", eta), ("c_ext", c_ext)]
                .into_iter()
                .map(|(key, value)| Assignment {
                    key: key.parse().unwrap(),
                    value,
                })
                .collect();
            if let Err(error) = apply_assignments(&mut model, &sets) {
                let text = error.to_string();
                let named = ["rods", "eta", "c_ext"]
                    .into_iter()
                    .find(|key| text.starts_with(&format!("{key} = ")));
                prop_assert!(named.is_some(), "{name} {rods} {eta} {c_ext}: {text}");
                count(&format!("refused: {}", named.unwrap_or_default()));
                return Ok(());
            }
            let load = load_share * model.load_bar_max_p();
            let set_load = [Assignment {
                key: "load".parse().unwrap(),
                value: load,
            }];
            apply_assignments(&mut model, &set_load).unwrap();
            let pencil = AffinePencil::new(&model).unwrap();
            let spectrum = pencil.spectrum(load).unwrap();
            prop_assert_eq!(spectrum.all().count(), 2 * model.dof());
            prop_assert!(spectrum.all().all(|z| z.re.is_finite() && z.im.is_finite()));
            if model.column.rods <= 12 {
                let most = model.load_bar_max_p();
                let transitions = critical_loads(&pencil, 0.0, most).unwrap();
                prop_assert!(transitions.iter().all(|t| t.load.is_finite()));
                prop_assert!(transitions.windows(2).all(|w| w[0].load <= w[1].load));
            }
            count("analysed");
            Ok(())
        })
        .unwrap();
    let counts = counts.into_inner();
    eprintln!("cases by answer: {counts:?}");
    for answer in [
        "analysed",
        "refused: rods",
        "refused: eta",
        "refused: c_ext",
    ] {
        assert!(
            counts.get(answer).is_some_and(|&n| n > 0),
            "{answer}: {counts:?}"
        );
    }
}
