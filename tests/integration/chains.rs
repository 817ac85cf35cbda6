//! Chains of N rigid rods (rod 1, then copies of rod 2, a spring k at every
//! joint): the classical discretization of a uniform beam of stiffness
//! `EI = k l` and length `L = N l`. Two rods are today's column exactly; as
//! N grows the chain's loads in the beam's units `P L^2 / EI = N^2 p` and
//! its frequencies approach the continuous columns' (Beck's flutter load
//! 20.05, Euler's cantilever buckling pi^2/4, the cantilever's modes).

use crate::common;

use common::{assert_close, eigenvalues, model, transitions};
use zieglerlab::analysis::{State, first_instability};
use zieglerlab::model::{StateVec, apply_assignments, chain_mass_matrix, parse_assignment};
use zieglerlab::sim::{EngineKind, SimError, Simulation, initial_state};

/// The uniform-rod chain of `rods` rods and its first loss of stability in
/// the beam's units, searched over the same range of them (0 to 40).
fn beck(rods: u32, extra: &[&str]) -> (f64, State) {
    let rods_set = format!("rods={rods}");
    let mut sets = vec![rods_set.as_str()];
    sets.extend_from_slice(extra);
    let chain = model("uniform-rods", &sets);
    let n2 = f64::from(rods * rods);
    let first = transitions(&chain, 40.0 / n2)[0];
    (n2 * first.load, first.to)
}

/// Beck's column: the chain's flutter load rises toward 20.05 as N doubles,
/// its error halving (a first-order discretization; the README's table
/// goes on to 64 rods).
#[test]
fn the_chain_s_flutter_load_approaches_beck_s() {
    let loads: Vec<f64> = [2, 4, 8, 16]
        .iter()
        .map(|&n| {
            let (load, state) = beck(n, &[]);
            assert_eq!(state, State::Flutter, "N = {n}");
            load
        })
        .collect();
    // Two rods: the uniform rods' closed form, 4 * 2 (9 - sqrt 7) / 5.
    assert_close(loads[0], 8.0 * (9.0 - 7f64.sqrt()) / 5.0, 1e-9);
    let errors: Vec<f64> = loads.iter().map(|p| 20.05 - p).collect();
    for pair in errors.windows(2) {
        assert!(pair[1] > 0.0 && pair[1] < pair[0], "{loads:?}");
        let ratio = pair[0] / pair[1];
        assert!(
            (1.8..=2.2).contains(&ratio),
            "error ratio {ratio}: {loads:?}"
        );
    }
    assert!(errors[3] < 0.07 * 20.05, "{loads:?}");
}

/// Under a dead load (eta = 0) the chain buckles by divergence, toward
/// Euler's cantilever, pi^2/4 = 2.4674 in the beam's units.
#[test]
fn under_a_dead_load_the_chain_buckles_toward_euler_s_cantilever() {
    let euler = std::f64::consts::PI.powi(2) / 4.0;
    let mut errors = Vec::new();
    for n in [2, 4, 8, 16] {
        let (load, state) = beck(n, &["eta=0"]);
        assert_eq!(state, State::Divergence);
        errors.push(euler - load);
    }
    // First order: the error halves as N doubles (1.75, 1.87, 1.93).
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!(pair[1] > 0.0 && (1.7..=2.2).contains(&ratio), "{errors:?}");
    }
    assert!(errors[3] < 0.07 * euler, "{errors:?}");
    // Two rods: (3 - sqrt 5)/2 in p, times 4.
    assert_close(beck(2, &["eta=0"]).0, 2.0 * (3.0 - 5f64.sqrt()), 1e-9);
}

/// Unloaded, a long chain vibrates as a uniform cantilever: its first two
/// frequencies `omega sqrt(m_total L^3 / EI)` tend to 3.5160 and 22.0345
/// (beta L = 1.8751, 4.6941), the error halving from 32 to 64 rods.
#[test]
fn the_unloaded_chain_vibrates_as_a_cantilever_beam() {
    let beam = [3.5160, 22.0345];
    let errors = |rods: u32| -> [f64; 2] {
        let chain = model("uniform-rods", &[&format!("rods={rods}"), "load=0"]);
        // m = 1 kg, l = 1 m, k = 0.1 N m/rad per rod.
        let (total_m, length, ei) = (f64::from(rods), f64::from(rods), 0.1);
        let unit = (ei / (total_m * length.powi(3))).sqrt();
        let mut omegas: Vec<f64> = eigenvalues(&chain)
            .iter()
            .filter(|z| z.im > 0.0)
            .map(|z| z.im / unit)
            .collect();
        omegas.sort_by(f64::total_cmp);
        [beam[0] - omegas[0], beam[1] - omegas[1]]
    };
    let (coarse, fine) = (errors(32), errors(64));
    for mode in 0..2 {
        assert!(
            fine[mode] > 0.0 && fine[mode] < 0.02 * beam[mode],
            "{fine:?}"
        );
        let ratio = coarse[mode] / fine[mode];
        assert!((1.8..=2.2).contains(&ratio), "{coarse:?} {fine:?}");
    }
}

/// The chain's mass matrix against its kinetic energy summed point by point
/// along the rods (Simpson's rule on each rod's velocity field, the tip mass
/// at the end), for three rods with a tip mass and a rate on every rod.
#[test]
fn the_chain_mass_matrix_is_its_kinetic_energy() {
    let chain = model("uniform-rods", &["rods=3", "m_tip=0.7", "l2=0.6", "m2=0.4"]);
    let rates = [0.3, -1.1, 0.8];
    let lengths = [1.0, 0.6, 0.6];
    let densities = [1.0, 0.4 / 0.6, 0.4 / 0.6];
    // Straight column: every rod along x, velocities along y.
    let velocity = |rod: usize, s: f64| -> f64 {
        (0..rod).map(|j| lengths[j] * rates[j]).sum::<f64>() + s * rates[rod]
    };
    let steps = 200;
    let mut kinetic = 0.0;
    for rod in 0..3 {
        let h = lengths[rod] / f64::from(steps);
        for i in 0..=steps {
            let w = if i == 0 || i == steps {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            kinetic += 0.5 * densities[rod] * w * h / 3.0 * velocity(rod, h * f64::from(i)).powi(2);
        }
    }
    kinetic += 0.5 * 0.7 * velocity(2, lengths[2]).powi(2);
    let mass = chain_mass_matrix(&chain);
    let q = nalgebra::DVector::from_column_slice(&rates);
    let quadratic = 0.5 * (q.transpose() * &mass * &q)[(0, 0)];
    assert_close(quadratic, kinetic, 1e-9);
}

/// A massless roller at the end of a chain is the ideal follower force on
/// it (the spin constraint eliminated), and a roller with mass is analysed
/// with its spin on the chain's last rod.
#[test]
fn a_massless_roller_on_a_chain_is_the_follower_chain() {
    let follower = model("uniform-rods", &["rods=5", "load=0"]);
    let roller = model("roller", &["rods=5", "nu=0", "load=0"]);
    let (a, b) = (
        first_instability(&follower, 2.0),
        first_instability(&roller, 2.0),
    );
    assert_close(a.unwrap().unwrap(), b.unwrap().unwrap(), 1e-9);
    let heavy = model("roller", &["rods=5"]);
    assert_eq!(eigenvalues(&heavy).len(), 2 * 5 + 1);
}

#[test]
fn rods_must_be_a_whole_number_from_2_to_64() {
    for text in ["rods=1", "rods=65", "rods=2.5", "rods=nan"] {
        let mut column = common::model("uniform-rods", &[]);
        let error = apply_assignments(&mut column, &[parse_assignment(text).unwrap()]);
        let error = error.unwrap_err().to_string();
        assert!(error.contains("whole number"), "{text}: {error}");
    }
    // Ziegler's column's rod 2 is massless: copies of it make no chain.
    let mut massless = common::model("ziegler-1952", &[]);
    let error = apply_assignments(&mut massless, &[parse_assignment("rods=3").unwrap()]);
    assert!(
        error
            .unwrap_err()
            .to_string()
            .contains("mass or inertia on every copy")
    );
}

/// The engines take two rods; a chain is refused with the reason, not run.
#[test]
fn a_chain_is_analysed_but_not_yet_simulated() {
    let chain = model("uniform-rods", &["rods=4"]);
    let x0: StateVec = initial_state(&model("uniform-rods", &[]), 1e-3);
    for engine in [EngineKind::Reference, EngineKind::Rapier] {
        let refused = Simulation::new(chain, engine, x0, 1.0 / 240.0);
        assert!(matches!(
            refused,
            Err(SimError::ChainNotSimulated { rods: 4 })
        ));
    }
}
