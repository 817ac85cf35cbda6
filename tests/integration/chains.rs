//! Chains of N rigid rods (rod 1, then copies of rod 2, a spring k at every
//! joint): the classical discretization of a uniform beam of stiffness
//! `EI = k l` and length `L = N l`. Two rods are today's column exactly; as
//! N grows the chain's loads in the beam's units `P L^2 / EI = N^2 p` and
//! its frequencies approach the continuous columns' (Beck's flutter load
//! 20.05, Euler's cantilever buckling pi^2/4, the cantilever's modes).

use crate::common;

use common::{assert_close, eigenvalues, model, transitions};
use zieglerlab::analysis::{
    AffinePencil, State, bracketing_locus, critical_loads, critical_loads_along, first_instability,
};
use zieglerlab::model::{
    Model, StateVec, apply_assignments, chain_derivative, chain_energy_j, chain_mass_matrix,
    parse_assignment, state_derivative,
};
use zieglerlab::sim::{EngineKind, Simulation, initial_state};

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
    let mut kinetic: f64 = (0..3)
        .map(|rod| {
            0.5 * densities[rod] * common::simpson(|s| velocity(rod, s).powi(2), lengths[rod])
        })
        .sum();
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

/// Unloaded, a chain of 8 rods on the reference engine keeps its energy
/// over 20 s from a 0.3 rad kick (large amplitude: the nonlinear terms).
#[test]
fn the_reference_engine_keeps_a_free_chain_s_energy() {
    let chain = model("uniform-rods", &["rods=8", "load=0", "a=1"]);
    let mut sim = Simulation::new(
        chain,
        EngineKind::Reference,
        initial_state(&chain, 0.3),
        1.0 / 240.0,
    )
    .unwrap();
    let start = sim.observe().energy_j();
    let mut worst: f64 = 0.0;
    sim.run(20.0, |o| worst = worst.max((o.energy_j() - start).abs()));
    assert!(worst < 1e-8 * start, "drift {worst:e} of {start:e}");
}

/// Two rods: the chain's equations are the closed-form 2x2 column's, with
/// every force and every load (partial follower, roller with and without
/// mass, the printed spin inertia).
#[test]
fn the_two_rod_chain_moves_as_the_column() {
    let follower = &[
        "load=2.2",
        "eta=0.6",
        "c1=0.02",
        "c2=0.05",
        "c_ext=0.03",
        "l2=0.7",
    ][..];
    let cases = [
        ("uniform-rods", follower),
        ("roller", &["load=2.2", "c2=0.05", "c_ext=0.03"][..]),
        ("roller", &["load=1.7", "m3=0", "c1=0.02"][..]),
        ("roller-as-printed", &["load=3.1"][..]),
    ];
    for (name, sets) in cases {
        let column = model(name, sets);
        for x in common::states() {
            let closed_form = state_derivative(&column, &x);
            let chain = chain_derivative(&column, &x).unwrap();
            for (a, b) in chain.iter().zip(closed_form.iter()) {
                assert!(
                    (a - b).abs() <= 1e-12 * b.abs().max(1.0),
                    "{name}: {a} vs {b}"
                );
            }
        }
    }
}

/// A large-amplitude state of `rods` rods, every angle and rate different
/// (the spin at rest).
fn wild_state(rods: u32) -> StateVec {
    let wave = |i: u32, a: f64, b: f64| a * (b * (f64::from(i) + 1.0)).sin();
    let angles = (0..rods).map(|i| wave(i, 0.9, 1.3));
    let rates = (0..rods).map(|i| wave(i, 1.7, 2.1));
    StateVec::from_iterator(
        2 * rods as usize + 2,
        angles.chain([0.0]).chain(rates).chain([0.0]),
    )
}

/// dE/dt along the flow of a chain, by central differences.
fn chain_energy_rate(model: &Model, x: &StateVec) -> f64 {
    let derivative = chain_derivative(model, x).unwrap();
    let h = 1e-6;
    let step = |sign: f64| {
        let (kinetic, spring) = chain_energy_j(model, &(x + sign * h * &derivative));
        kinetic + spring
    };
    (step(1.0) - step(-1.0)) / (2.0 * h)
}

/// Unloaded and undamped, a chain of 8 rods keeps its energy at large
/// amplitude (the mass matrix and the velocity-squared terms); with drag it
/// loses the drag's integral over the rods, summed point by point.
#[test]
fn a_free_chain_keeps_its_energy_and_drag_takes_its_integral() {
    let free = model("uniform-rods", &["rods=8", "load=0", "m_tip=0.3"]);
    let x = wild_state(8);
    let (kinetic, spring) = chain_energy_j(&free, &x);
    let rate = chain_energy_rate(&free, &x);
    assert!(rate.abs() < 1e-7 * (kinetic + spring), "{rate}");

    let c = 0.04;
    let dragged = model("uniform-rods", &["rods=5", "load=0", "c_ext=0.04"]);
    let x = wild_state(5);
    // Velocity across rod i at s: sum_{j<i} l_j cos(phi_i - phi_j) phi_j' + s phi_i'.
    let dissipated: f64 = (0..5)
        .map(|i| {
            let across: f64 = (0..i).map(|j| (x[i] - x[j]).cos() * x[6 + j]).sum();
            c * common::simpson(|s| (across + s * x[6 + i]).powi(2), 1.0)
        })
        .sum();
    let rate = chain_energy_rate(&dragged, &x);
    assert!(
        (rate + dissipated).abs() < 1e-6 * dissipated,
        "{rate} vs {dissipated}"
    );
}

/// At rest, the Jacobian of the chain's equations is the linearization's
/// `[[0, I], [-M^-1 K, -M^-1 D]]` on its coordinates: the rods' angles,
/// and the roller's spin when it has mass.
fn assert_jacobian_is_linearization(chain: &Model) {
    let n = chain.column.rods;
    let lin = zieglerlab::model::linearize(chain).unwrap();
    let dof = lin.mass.nrows();
    let minv = lin.mass.clone().try_inverse().unwrap();
    let (k, d) = (-&minv * &lin.stiffness, -&minv * &lin.damping);
    // The state is (phi_1 .. phi_N, psi, their rates); without a spin
    // coordinate the linearization skips psi.
    let (position, rate) = (|j: usize| j, |j: usize| n + 1 + j);
    let h = 1e-7;
    for column in 0..2 * dof {
        let at = |sign: f64| {
            let mut x = StateVec::zeros(2 * n + 2);
            x[if column < dof {
                position(column)
            } else {
                rate(column - dof)
            }] = sign * h;
            chain_derivative(chain, &x).unwrap()
        };
        let (plus, minus) = (at(1.0), at(-1.0));
        for row in 0..dof {
            let numeric = (plus[rate(row)] - minus[rate(row)]) / (2.0 * h);
            let analytic = if column < dof {
                k[(row, column)]
            } else {
                d[(row, column - dof)]
            };
            assert!(
                (numeric - analytic).abs() < 1e-6 * analytic.abs().max(1e-3),
                "row {row} column {column}: {numeric} vs {analytic}"
            );
        }
    }
}

/// 4 rods with a partial follower force, dampers, drag and a tip mass; and
/// 4 rods with the roller (its spin a coordinate) and dampers.
#[test]
fn the_chain_s_jacobian_at_rest_is_its_linearization() {
    assert_jacobian_is_linearization(&model(
        "uniform-rods",
        &[
            "rods=4",
            "load=0.7",
            "eta=0.8",
            "c2=0.03",
            "c1=0.01",
            "c_ext=0.02",
            "m_tip=0.2",
        ],
    ));
    assert_jacobian_is_linearization(&model(
        "roller",
        &["rods=4", "load=0.7", "c2=0.03", "m_tip=0.2"],
    ));
}

/// The band's friction on a roller at the end of a chain of 4 rods changes
/// the energy (rods and spin) by exactly its power `sum Q_j q_j'` (the
/// spin's `Q_psi = -(r/l_N) Q_N` included), for a roller with and without
/// mass, in large-amplitude states with the roller spinning.
#[test]
fn a_roller_chain_s_energy_changes_by_the_friction_s_power() {
    for roller_mass in ["m3=0.1", "m3=0"] {
        let chain = model("roller", &["rods=4", "load=2.0", roller_mass]);
        let Some(roller) = chain.roller() else {
            panic!("no roller")
        };
        let mut x = wild_state(4);
        x[4] = 0.3;
        x[9] = -1.4;
        let q = zieglerlab::model::friction(&chain.column, roller, &x).generalized_n_m;
        let power: f64 = (0..5).map(|j| q[j] * x[5 + j]).sum();
        let rate = chain_energy_rate(&chain, &x);
        assert!(
            (rate - power).abs() < 1e-6 * power.abs().max(1e-3),
            "{roller_mass}: {rate} vs {power}"
        );
    }
}

/// The Beck preset is the uniform-rod chain of 16 rods; Pflueger's, the
/// same with a tip mass of half the rods' mass, flutters at a lower load
/// (in the beam's units, 15.06 against 18.78).
#[test]
fn the_beck_and_pflueger_presets_are_the_chains_they_say() {
    let first = |name: &str| {
        let model = model(name, &[]);
        assert_eq!(model.column.rods, 16);
        let t = transitions(&model, 40.0 / 256.0)[0];
        assert_eq!(t.to, State::Flutter);
        model.beck_load(t.load).unwrap()
    };
    let (beck_load, pflueger_load) = (first("beck"), first("pflueger"));
    assert_close(beck_load, beck(16, &[]).0, 1e-9);
    assert!((pflueger_load - 15.06).abs() < 0.01, "{pflueger_load}");
    assert!((beck_load - 18.78).abs() < 0.01, "{beck_load}");
}

/// The roller versions of the Beck and Pflueger chains: the slip's damping
/// makes them flutter weakly from small loads (growth below 5e-4 1/s at 90%
/// of the follower chain's flutter load), and strongly just past the load
/// where the follower chain flutters (above 1e-3 1/s at 105% of it).
#[test]
fn the_roller_chains_flutter_strongly_where_the_follower_chains_do() {
    for (roller_name, follower_name) in [("beck-roller", "beck"), ("pflueger-roller", "pflueger")] {
        let roller = model(roller_name, &[]);
        let follower = model(follower_name, &[]);
        assert_eq!(roller.column, follower.column);
        assert!(roller.roller().is_some());
        let onset = transitions(&follower, 40.0 / 256.0)[0].load;
        let weak = transitions(&roller, 40.0 / 256.0)[0];
        assert_eq!(weak.to, State::Flutter);
        assert!(weak.load < 0.01 * onset, "{roller_name}: {}", weak.load);
        let growth = |factor: f64| {
            eigenvalues(&roller.at_load(factor * onset))
                .iter()
                .map(|z| z.re)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let (below, past) = (growth(0.9), growth(1.05));
        assert!(below > 0.0 && below < 5e-4, "{roller_name}: {below}");
        assert!(past > 1e-3, "{roller_name}: {past}");
    }
}

/// The characteristic determinant of the continuous column with a tip mass
/// (Pflueger's column) in the beam's units: `W'''' + p W'' - s W = 0` for
/// the mode `w = W(x/L) e^{i omega t}` with `s = m omega^2 L^4 / EI`,
/// clamped (`W = W' = 0` at 0), free of moment at the tip (`W'' = 0`), and
/// the tip mass `M = chi m L` answering the shear (`W''' = -chi s W`; the
/// follower force's transverse part cancels the axial force's there).
fn pflueger_determinant(p: f64, s: f64, chi: f64) -> f64 {
    let root = (p * p + 4.0 * s).sqrt();
    let (a, b) = (f64::midpoint(p, root).sqrt(), ((root - p) / 2.0).sqrt());
    let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cosh(), b.sinh());
    // W = A cos(a x) + B sin(a x) + C cosh(b x) + D sinh(b x).
    nalgebra::Matrix4::new(
        1.0,
        0.0,
        1.0,
        0.0,
        0.0,
        a,
        0.0,
        b,
        -a * a * ca,
        -a * a * sa,
        b * b * cb,
        b * b * sb,
        a.powi(3) * sa + chi * s * ca,
        -a.powi(3) * ca + chi * s * sa,
        b.powi(3) * sb + chi * s * cb,
        b.powi(3) * cb + chi * s * sb,
    )
    .determinant()
}

/// The continuous column's flutter load: the smallest `p` at which its two
/// lowest frequencies meet and leave the real axis (fewer real roots `s`
/// of the determinant below the third mode's), by bisection.
fn continuous_flutter_load(chi: f64) -> f64 {
    let real_roots = |p: f64| {
        let samples: Vec<f64> = (1..=4000)
            .map(|i| pflueger_determinant(p, 0.4 * f64::from(i), chi))
            .collect();
        samples
            .windows(2)
            .filter(|w| w[0].signum() != w[1].signum())
            .count()
    };
    let unloaded = real_roots(0.0);
    let (mut lo, mut hi) = (1.0, 25.0);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if real_roots(mid) < unloaded {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The chains converge to the continuous columns, solved here from their
/// own characteristic equation: it gives Beck's 20.05 without a tip mass
/// (Beck 1952), and with a tip mass of half the column's mass the chains
/// of 16 and 32 rods (the error halving as N doubles) extrapolate to its
/// flutter load to 0.05%.
#[test]
fn pflueger_s_chain_approaches_the_continuous_column() {
    assert_close(continuous_flutter_load(0.0), 20.05, 1e-3);
    let continuous = continuous_flutter_load(0.5);
    let chain = |rods: u32| {
        let n = f64::from(rods);
        let (rods_set, tip_set) = (format!("rods={rods}"), format!("m_tip={}", 0.5 * n));
        let model = model("pflueger", &[&rods_set, &tip_set]);
        let first = transitions(&model, 40.0 / (n * n))[0];
        assert_eq!(first.to, State::Flutter);
        model.beck_load(first.load).unwrap()
    };
    let (coarse, fine) = (chain(16), chain(32));
    let extrapolated = 2.0 * fine - coarse;
    println!(
        "Pflueger, M = m L / 2: chains {coarse}, {fine} -> {extrapolated}; continuous {continuous}"
    );
    assert!(
        coarse < fine && fine < continuous,
        "{coarse} {fine} {continuous}"
    );
    assert_close(extrapolated, continuous, 5e-4);
}

/// Every change of stability on Beck's chain of 8 rods up to p = 7 (four:
/// the flutter, then a window of flutter between divergences) is found again
/// on a range up to 1e6, bracketed decade by decade beyond the
/// chain's own range (0 to 0.625), to the same loads. An evenly spaced
/// bracketing grid over 0 to 1e6 stepped over the window.
#[test]
fn a_wide_load_range_finds_the_narrow_windows_near_the_column_s_own() {
    let chain = model("beck", &["rods=8"]);
    let near = transitions(&chain, 7.0);
    assert_eq!(near.len(), 4, "{near:?}");
    let wide = transitions(&chain, 1e6);
    assert_eq!(wide.len(), near.len(), "{wide:?}");
    for (a, b) in near.iter().zip(&wide) {
        assert_eq!((a.from, a.to), (b.from, b.to));
        assert_close(b.load, a.load, 1e-9);
    }
}

/// A stiff first joint (k1 a million times the others) makes a mode that
/// the load cancels down to rounding: its eigenvalues flip between the
/// real and imaginary axes from load to load. The locus ignores those flips
/// (they are rounding, not crossings), so its refinement is not spent, and
/// the critical loads are those of narrow ranges around each of them.
#[test]
fn a_stiff_first_joint_does_not_send_the_locus_chasing_rounding() {
    let chain = model("beck", &["rods=8", "k1=1e6"]);
    let pencil = AffinePencil::new(&chain).unwrap();
    let range = pencil.natural_load_max();
    let bracket = bracketing_locus(&pencil, 0.0, range).unwrap();
    assert_eq!(bracket.refinement_cut_at, None);
    assert!(
        bracket.loads.len() < 4000,
        "{} samples",
        bracket.loads.len()
    );
    let found = critical_loads_along(&pencil, &bracket).unwrap();
    assert!(!found.is_empty());
    for t in &found {
        let around = critical_loads(&pencil, 0.5 * t.load, 2.0 * t.load).unwrap();
        assert!(
            around
                .iter()
                .any(|u| (u.from, u.to) == (t.from, t.to)
                    && (u.load - t.load).abs() <= 1e-9 * t.load),
            "{t:?} against {around:?}"
        );
    }
}

/// The equations of motion in four states side by side are each the same
/// to the bit as alone: a follower chain with drag, and the roller with
/// and without mass, at large amplitude.
#[test]
fn chains_side_by_side_move_as_alone() {
    for (preset, extra) in [
        ("uniform-rods", "c_ext=0.04"),
        ("roller", "m3=0"),
        ("roller", "load=1"),
    ] {
        let chain = model(preset, &["rods=6", extra]);
        let inertia = zieglerlab::model::chain_inertia(&chain);
        let states: Vec<StateVec> = (0..4)
            .map(|lane| wild_state(6) * (0.5 + 0.3 * f64::from(lane)))
            .collect();
        let side_by_side = zieglerlab::model::chain_derivatives_with(
            &chain,
            &inertia,
            [&states[0], &states[1], &states[2], &states[3]],
        );
        for (x, together) in states.iter().zip(side_by_side) {
            let alone = chain_derivative(&chain, x).unwrap();
            let bits = |v: &StateVec| v.iter().map(|a| a.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&together.unwrap()), bits(&alone), "{preset} {extra}");
        }
    }
}
