//! The asymmetric cycles born where the hard onset's large cycles break
//! their mirror symmetry: found, followed, and checked by an independent
//! integrator and by the reference engine.

use zieglerlab::analysis::{Cycle, CycleBifurcationKind, cycles_at};
use zieglerlab::model::Model;
use zieglerlab::sim::{EngineKind, Simulation};

use crate::common::{diagram_said, flow_derivative, half_period_map, hard_onset_branch, rk4};

/// The largest and the least value of each rod's angle over `secs` of
/// a run of the reference engine of `at` from `x0`, after `settle_secs`.
fn extremes(at: &Model, x0: nalgebra::DVector<f64>, settle_secs: f64, secs: f64) -> Vec<[f64; 2]> {
    let mut sim = Simulation::new(*at, EngineKind::Reference, x0, 1.0 / 240.0).expect("a run");
    sim.run(settle_secs, |_| ());
    let mut seen = vec![[f64::NEG_INFINITY, f64::INFINITY]; 2];
    sim.run(secs, |o| {
        for (range, angle) in seen.iter_mut().zip(&o.angles_rad) {
            range[0] = range[0].max(*angle);
            range[1] = range[1].min(*angle);
        }
    });
    seen
}

/// Where the large cycles' symmetry breaks (p = 2.297, their BPC) a branch
/// of asymmetric cycles is born, named after its parent, and followed up
/// to where the column swings round. Every cycle on it is checked by a
/// plain Runge-Kutta run of the equations of motion: it closes after its
/// period (to 1e-8), so does its mirror image `-x(t)` (the other branch,
/// drawn as one: its amplitudes are the same), and it is not its own
/// mirror image half a period on (`|x(T/2) + x(0)|` above 0.02, where the
/// symmetric cycles have it below 1e-7). Next to the break the load grows
/// with the square of that asymmetry, as a pitchfork's normal form has it
/// (the ratio the same to 2 % at its first two cycles, 8.8 there), on the
/// side where the symmetric cycles are unstable, and the asymmetric ones
/// there are stable: they take over the stability the symmetric ones
/// lose. They lose it in turn at a torus bifurcation, solved for, and a
/// period doubling follows, both ringed on the diagram and named to a
/// screen reader.
#[test]
fn asymmetric_cycles_branch_off_where_the_large_cycles_break_their_symmetry() {
    let (m, branch) = hard_onset_branch();
    let bp = *branch
        .bifurcations
        .iter()
        .find(|b| b.kind == CycleBifurcationKind::SymmetryBreaking)
        .expect("the break of symmetry");
    let [offshoot] = &branch.offshoots[..] else {
        panic!("{} offshoots", branch.offshoots.len())
    };
    assert_eq!(offshoot.name(), "cycle-1-asymmetric");
    assert_eq!(offshoot.born, bp);
    assert!(offshoot.cycles.len() > 10, "{}", offshoot.cycles.len());
    let asymmetry = |cycle: &Cycle| half_period_map(m, cycle).1;
    for cycle in &offshoot.cycles {
        let at = m.at_load(cycle.load);
        let x0 = cycle.start_state(&at);
        let closed = (rk4(&at, x0.clone(), cycle.period_secs, 8000) - &x0).amax();
        let mirrored = (rk4(&at, -x0.clone(), cycle.period_secs, 8000) + &x0).amax();
        assert!(
            closed < 1e-8 && mirrored < 1e-8,
            "p = {}: {closed:e} {mirrored:e}",
            cycle.load
        );
        assert!(asymmetry(cycle) > 0.02, "p = {}", cycle.load);
        assert!((cycle.trivial_multiplier() - 1.0).norm() < 1e-8);
    }
    let [first, second, ..] = &offshoot.cycles[..] else {
        unreachable!()
    };
    let ratio = |c: &Cycle| (c.load - bp.load) / asymmetry(c).powi(2);
    let (r1, r2) = (ratio(first), ratio(second));
    assert!(r1 > 0.0 && (r2 / r1 - 1.0).abs() < 0.02, "{r1} {r2}");
    assert!(first.stable && second.stable);
    let torus = offshoot
        .bifurcations
        .first()
        .expect("a bifurcation on the branch");
    assert_eq!(torus.kind, CycleBifurcationKind::NeimarkSacker);
    assert!(
        torus.refined && (2.30..2.40).contains(&torus.load),
        "{torus:?}"
    );
    // The diagram draws the branch from the break and rings its torus (the
    // parent branch has none), and a screen reader hears it.
    // Past the torus the complex pair meets on the negative real axis
    // outside the circle and one of the two goes in through -1 (between
    // two cycles of the branch: found by solving the cycles between them):
    // a period doubling, solved for, where a plain Runge-Kutta run's
    // monodromy has a multiplier -1 too.
    let doubling = offshoot.bifurcations[1];
    assert_eq!(doubling.kind, CycleBifurcationKind::PeriodDoubling);
    assert!(
        doubling.refined && (2.44..2.46).contains(&doubling.load),
        "{doubling:?}"
    );
    let at_doubling = offshoot.cycles_at(m, doubling.load).remove(0);
    let (monodromy, _) = flow_derivative(m, &at_doubling, at_doubling.period_secs);
    let flips: Vec<f64> = monodromy
        .complex_eigenvalues()
        .iter()
        .filter(|mu| mu.im.abs() < 1e-9 && mu.re < 0.0)
        .map(|mu| mu.re)
        .collect();
    assert!(
        flips.iter().any(|mu| (mu + 1.0).abs() < 1e-4),
        "{flips:?} {:?}",
        at_doubling.multipliers
    );
    let (said, _) = diagram_said(branch);
    assert!(said.contains("NS at") && said.contains("PD at"), "{said}");
}

/// Between the break and the torus bifurcation the asymmetric cycles are
/// what the column does: the reference engine, started on the symmetric
/// cycle at the same load (unstable there) nudged by 1e-3 rad at the first
/// joint, leaves it and after 150 periods swings as the asymmetric cycle
/// does or as its mirror image: each angle's largest and least values to
/// 2e-3 rad, and unequal in size (the swing is lopsided), where the
/// symmetric cycle's are equal.
#[test]
fn past_the_break_the_column_settles_onto_an_asymmetric_cycle() {
    let (m, branch) = hard_onset_branch();
    let offshoot = &branch.offshoots[0];
    let p = 2.33;
    let asymmetric = offshoot.cycles_at(m, p).remove(0);
    assert!(asymmetric.stable, "{:?}", asymmetric.multipliers);
    let symmetric = cycles_at(m, branch, p)
        .into_iter()
        .find(|c| !c.stable && c.largest_amplitude_rad() > offshoot.born.amplitude_rad)
        .expect("the unstable symmetric cycle past the break");
    let at = m.at_load(p);
    // The asymmetric cycle's own extremes, over one period of it.
    let own = extremes(
        &at,
        asymmetric.start_state(&at),
        0.0,
        asymmetric.period_secs,
    );
    let mut nudged = symmetric.start_state(&at);
    nudged[0] += 1e-3;
    let seen = extremes(
        &at,
        nudged,
        150.0 * symmetric.period_secs,
        2.0 * symmetric.period_secs,
    );
    let close = |a: &[[f64; 2]], b: &[[f64; 2]]| {
        a.iter()
            .zip(b)
            .all(|(x, y)| (x[0] - y[0]).abs() < 2e-3 && (x[1] - y[1]).abs() < 2e-3)
    };
    let mirrored: Vec<[f64; 2]> = own.iter().map(|r| [-r[1], -r[0]]).collect();
    assert!(
        close(&seen, &own) || close(&seen, &mirrored),
        "{seen:?} vs {own:?}"
    );
    assert!(own.iter().any(|r| (r[0] + r[1]).abs() > 0.01), "{own:?}");
}
