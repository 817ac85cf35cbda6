//! Limit cycles by shooting: near the onset they are the normal form's
//! (their amplitudes imply the first Lyapunov coefficient Kuznetsov's
//! formula gives); each is a periodic orbit of the independent reference
//! integrator and the attractor a long run settles on, on both engines; the
//! trivial Floquet multiplier is 1; over one cycle the load feeds in what
//! the dampers take out; the roller's branch stops before stick-slip; a
//! hard onset's unstable cycles fold back into stable ones, and a sweep
//! over it shows hysteresis.

use crate::common::{eigenvalues, model, settled};
use zieglerlab::analysis::{Branch, BranchEnd, Cycle, HopfKind, cycle_branches, cycles_at};
use zieglerlab::model::{Model, StateVec};
use zieglerlab::sim::{EngineKind, Simulation, initial_state};

/// The first branch of cycles of `m` over loads `[lo, hi]`.
fn first_branch(m: &Model, lo: f64, hi: f64) -> Branch {
    let never = std::sync::atomic::AtomicBool::new(false);
    let branches = cycle_branches(m, lo, hi, &never).expect("an analysis");
    let onset = branches.into_iter().next().expect("a flutter onset");
    onset.branch.expect("a branch of cycles")
}

fn damped_ziegler() -> Model {
    model("ziegler-1952", &["c1=0.3", "c2=0.3"])
}

/// `bifurcation` of [`damped_ziegler`] with `args` after the model: stdout.
fn damped_ziegler_bifurcation(args: &[&str]) -> String {
    let model = [
        "bifurcation",
        "--preset",
        "ziegler-1952",
        "--set",
        "c1=0.3",
        "--set",
        "c2=0.3",
    ];
    crate::cli::stdout(&[&model[..], args].concat())
}

#[test]
fn near_the_onset_the_cycles_are_the_normal_form_s() {
    // Joint dampers, drag along the rods, and the roller's slipping spin.
    for (m, hi) in [
        (damped_ziegler(), 2.2),
        (model("ziegler-1952", &["c_ext=0.05"]), 2.4),
        (model("roller", &[]), 0.04),
    ] {
        let branch = first_branch(&m, 0.0, hi);
        let hopf = branch.hopf().clone();
        assert_eq!(hopf.kind, HopfKind::Supercritical);
        let per_sqrt = hopf.amplitude_per_sqrt_load_rad[0];
        let mut errors = Vec::new();
        // Cycles whose phi1 the normal form puts at 0.04 to 0.0013 rad.
        for amplitude in [0.04, 0.013, 0.004, 0.0013] {
            let above = (amplitude / per_sqrt).powi(2);
            let p = hopf.load + above;
            let cycles = cycles_at(&m, &branch, p);
            assert_eq!(cycles.len(), 1, "one cycle at p = {p}");
            let cycle = &cycles[0];
            assert!(cycle.stable);
            // The amplitudes imply l1, with no derivative of the equations:
            // r^2 = mu' eps / (omega |l1|) and amplitude = 2 |q_i| r, so l1
            // scales as (predicted / computed)^2.
            let ratio = cycle.amplitude_rad[0] / amplitude;
            let implied_l1 = hopf.first_lyapunov * ratio.powi(-2);
            errors.push((implied_l1 / hopf.first_lyapunov - 1.0).abs());
            // The period tends to the onset's 2 pi / omega.
            let period = std::f64::consts::TAU / hopf.frequency_rad_per_s;
            assert!(
                (cycle.period_secs / period - 1.0).abs() < 10.0 * amplitude,
                "{cycle:?}"
            );
        }
        // The error falls with the amplitude until it meets the accuracy
        // of l1 and of the shooting (seen: 3e-6 to 4e-4 at 0.0013 rad).
        assert!(errors[1..].iter().all(|e| *e < errors[0]), "{errors:?}");
        assert!(errors[3] < 1e-3, "{errors:?}");
    }
}

/// One period of `cycle` (at load `p` of `m`) on the reference integrator
/// from the cycle's start in `steps` steps: the start, the state it returns
/// to, and the largest `|phi_i|` the run's samples see.
fn one_period(m: &Model, cycle: &Cycle, p: f64, steps: f64) -> (StateVec, StateVec, Vec<f64>) {
    let at = m.at_load(p);
    let x0 = cycle.start_state(&at);
    let mut sim = Simulation::new(
        at,
        EngineKind::Reference,
        x0.clone(),
        cycle.period_secs / steps,
    )
    .expect("a run");
    let mut largest = vec![0.0_f64; m.column.rods];
    sim.run(cycle.period_secs, |o| {
        for (most, angle) in largest.iter_mut().zip(&o.angles_rad) {
            *most = most.max(angle.abs());
        }
    });
    (x0, sim.state(), largest)
}

/// The largest difference of two states.
fn gap(a: &StateVec, b: &StateVec) -> f64 {
    (0..a.len())
        .map(|i| (a[i] - b[i]).abs())
        .fold(0.0, f64::max)
}

/// Asserts that `cycle` (at load `p` of `m`) is a periodic orbit of the
/// reference integrator: one period in 2000 steps comes back to within
/// `gap_most` of its start, and its samples see each computed amplitude to
/// `amplitude_most` of itself (2000 samples a period miss a peak by at most
/// (pi/2000)^2/2 of it). The run's largest angles.
fn assert_reference_orbit(
    m: &Model,
    cycle: &Cycle,
    p: f64,
    gap_most: f64,
    amplitude_most: f64,
) -> Vec<f64> {
    let (x0, back, largest) = one_period(m, cycle, p, 2000.0);
    let gap = gap(&x0, &back);
    assert!(
        gap < gap_most,
        "after one period the run is {gap} from its start"
    );
    for (seen, computed) in largest.iter().zip(&cycle.amplitude_rad) {
        assert!(
            (seen / computed - 1.0).abs() < amplitude_most,
            "{seen} vs {computed}"
        );
    }
    largest
}

#[test]
fn a_cycle_is_a_periodic_orbit_of_the_reference_integrator() {
    let m = damped_ziegler();
    let branch = first_branch(&m, 1.8, 2.4);
    let cycle = cycles_at(&m, &branch, 2.2).remove(0);
    assert_reference_orbit(&m, &cycle, 2.2, 1e-7, 2e-6);
}

#[test]
fn a_long_run_on_either_engine_settles_on_the_stable_cycle() {
    let m = damped_ziegler();
    let branch = first_branch(&m, 1.8, 2.4);
    let cycle = cycles_at(&m, &branch, 2.2).remove(0);
    let at = m.at_load(2.2);
    // The reference integrator from the standard kick, 60 periods on (the
    // cycle's next multiplier is about 0.7: the start is forgotten).
    let seen = settled(
        &at,
        EngineKind::Reference,
        initial_state(&at, 1e-3),
        cycle.period_secs,
    );
    for (seen, computed) in seen.iter().zip(&cycle.amplitude_rad) {
        assert!((seen / computed - 1.0).abs() < 1e-5, "{seen} vs {computed}");
    }
    // rapier from the cycle's start: its orbit stays on the cycle to the
    // accuracy of its fixed step (1/240 s of a 35 s period).
    let seen = settled(
        &at,
        EngineKind::Rapier,
        cycle.start_state(&at),
        cycle.period_secs,
    );
    for (seen, computed) in seen.iter().zip(&cycle.amplitude_rad) {
        assert!((seen / computed - 1.0).abs() < 1e-3, "{seen} vs {computed}");
    }
}

#[test]
fn the_trivial_multiplier_is_one_along_every_branch() {
    for (name, sets, hi) in [
        ("ziegler-1952", &["c1=0.3", "c2=0.3"][..], 3.0),
        ("uniform-rods", &["c1=0.05", "c2=0.05"][..], 3.0),
        ("roller", &[][..], 0.1),
    ] {
        let branch = first_branch(&model(name, sets), 0.0, hi);
        assert!(branch.cycles.len() > 10, "{name}: {:?}", branch.end);
        for cycle in &branch.cycles {
            let off = (cycle.trivial_multiplier() - 1.0).norm();
            assert!(off < 1e-8, "{name} at p = {}: {off}", cycle.load);
        }
    }
}

#[test]
fn over_one_cycle_the_load_feeds_in_what_the_dampers_take_out() {
    let m = damped_ziegler();
    let branch = first_branch(&m, 1.8, 2.4);
    let cycle = cycles_at(&m, &branch, 2.2).remove(0);
    let at = m.at_load(2.2);
    let (c1, c2) = (at.column.c1_nms_per_rad, at.column.c2_nms_per_rad);
    let steps = 4000.0;
    let dt = cycle.period_secs / steps;
    let mut sim =
        Simulation::new(at, EngineKind::Reference, cycle.start_state(&at), dt).expect("a run");
    let start = sim.observe();
    let dissipated = |o: &zieglerlab::sim::Observables| {
        let r = &o.rates_rad_per_s;
        c1 * r[0] * r[0] + c2 * (r[1] - r[0]).powi(2)
    };
    // Trapezoids of the load's power and of the dampers'.
    let (mut fed, mut taken) = (0.0, 0.0);
    let mut last = start.clone();
    sim.run(cycle.period_secs, |o| {
        fed += 0.5 * dt * (last.band_power_w + o.band_power_w);
        taken += 0.5 * dt * (dissipated(&last) + dissipated(o));
        last = o.clone();
    });
    assert!(taken > 0.01, "the dampers work: {taken} J");
    assert!(
        (fed / taken - 1.0).abs() < 1e-6,
        "fed {fed} J, taken {taken} J"
    );
    assert!((last.energy_j() - start.energy_j()).abs() < 1e-8 * start.energy_j());
}

#[test]
fn the_roller_s_branch_stops_before_its_contact_sticks() {
    let m = model("roller", &[]);
    let branch = first_branch(&m, 0.0, 1.0);
    assert_eq!(branch.hopf().kind, HopfKind::Supercritical);
    assert!(
        matches!(branch.end, BranchEnd::StickSlip { .. }),
        "{:?}",
        branch.end
    );
    let band = m.roller().expect("a roller").band_speed_m_per_s;
    for cycle in &branch.cycles {
        let slip = cycle.closest_slip_m_per_s.expect("a roller's slip");
        assert!(slip >= 0.1 * band, "p = {}: slip {slip}", cycle.load);
    }
    // It ends next to that bound, at the same load whatever the range
    // (which sets the continuation's longest step).
    let last_slip = branch.cycles.last().and_then(|c| c.closest_slip_m_per_s);
    assert!(
        last_slip.is_some_and(|slip| slip < 0.2 * band),
        "{last_slip:?}"
    );
    let end = |b: &Branch| match b.end {
        BranchEnd::StickSlip { load } => load,
        other => panic!("{other:?}"),
    };
    let narrow = first_branch(&m, 0.0, 0.06);
    assert!(
        (end(&narrow) / end(&branch) - 1.0).abs() < 0.01,
        "{} vs {}",
        end(&narrow),
        end(&branch)
    );
    // The last smooth cycle is a periodic orbit of the reference integrator.
    let last = branch.cycles.last().expect("cycles");
    let (x0, back, _) = one_period(&m, last, last.load, 1000.0);
    let n = m.column.rods;
    // The angles and rates return (the spin angle advances with the band).
    for i in (0..n).chain((n + 1)..=(2 * n)) {
        assert!(
            (back[i] - x0[i]).abs() < 1e-6,
            "entry {i}: {} vs {}",
            back[i],
            x0[i]
        );
    }
}

#[test]
fn bifurcation_csv_lists_the_equilibrium_and_the_cycles() {
    let text = damped_ziegler_bifurcation(&["--x", "load:1.8:2.2:5"]);
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("load,branch,stable,period_s,amp_phi1_rad,amp_phi2_rad,bifurcation")
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    let onset = 1.914_285_714_285_7;
    let equilibrium: Vec<_> = rows.iter().filter(|r| r[1] == "equilibrium").collect();
    assert_eq!(equilibrium.len(), 5);
    for row in &equilibrium {
        let p: f64 = row[0].parse().expect("a load");
        assert_eq!(row[2] == "true", p < onset, "{row:?}");
    }
    let cycles: Vec<_> = rows.iter().filter(|r| r[1] == "cycle-1").collect();
    let loads: Vec<&str> = cycles.iter().map(|r| r[0]).collect();
    assert_eq!(loads, ["2", "2.1", "2.2"]);
    let m = damped_ziegler();
    let branch = first_branch(&m, 1.8, 2.2);
    let computed = cycles_at(&m, &branch, 2.2).remove(0);
    let last = cycles.last().expect("a row");
    assert_eq!(last[2], "true");
    assert_eq!(last[3].parse::<f64>().ok(), Some(computed.period_secs));
    assert_eq!(last[5].parse::<f64>().ok(), Some(computed.amplitude_rad[1]));
}

#[test]
fn bifurcation_json_names_each_onset_and_an_undamped_column_has_no_cycles() {
    let text = damped_ziegler_bifurcation(&["--x", "load:1.8:2.0:3", "--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&text).expect("json");
    let onset = &value["onsets"][0];
    assert_eq!(onset["branch"], "cycle-1");
    assert_eq!(onset["hopf"]["kind"], "supercritical");
    let rows = value["rows"].as_array().expect("rows");
    let cycle = rows
        .iter()
        .find(|r| r["branch"] == "cycle-1")
        .expect("a cycle");
    let multipliers = cycle["floquet_multipliers"]
        .as_array()
        .expect("multipliers");
    assert_eq!(multipliers.len(), 4);
    let out = crate::cli::run(&[
        "bifurcation",
        "--preset",
        "ziegler-1952",
        "--x",
        "load:1:3:3",
    ]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("reversible"), "{stderr}");
    assert!(!String::from_utf8_lossy(&out.stdout).contains("cycle-"));
}

#[test]
fn a_sweep_down_follows_the_stable_cycle_and_comes_to_rest_below_the_onset() {
    let text = damped_ziegler_bifurcation(&["--x", "load:1.8:2.4:4", "--sweep"]);
    let rows = csv_rows(&text);
    let amplitude = |branch: &str, load: &str| -> f64 {
        let row = rows
            .iter()
            .find(|r| r[1] == branch && r[0] == load)
            .unwrap_or_else(|| panic!("{branch} at {load}: {text}"));
        row[5].parse().expect("a number")
    };
    let up: Vec<_> = rows.iter().filter(|r| r[1] == "sweep-up").collect();
    let down: Vec<_> = rows.iter().filter(|r| r[1] == "sweep-down").collect();
    assert_eq!((up.len(), down.len()), (4, 3));
    assert!(up.iter().chain(&down).all(|r| r[2].is_empty()));
    // Soft flutter: no hysteresis; going down, each step settles on the
    // cycle the shooting finds.
    for load in ["2.2", "2"] {
        let (seen, cycle) = (amplitude("sweep-down", load), amplitude("cycle-1", load));
        assert!(
            (seen / cycle - 1.0).abs() < 1e-4,
            "p = {load}: {seen} vs {cycle}"
        );
    }
    assert!(amplitude("sweep-down", "1.8") < 1e-2);
}

#[test]
fn the_diagram_figure_draws_each_cycle_at_its_amplitude() {
    use zieglerlab::figure::{Format, Page, render};
    use zieglerlab::plot::bifurcation::BifurcationData;
    let m = damped_ziegler();
    let branch = first_branch(&m, 1.6, 3.0);
    let onset = branch.hopf().load;
    let data = BifurcationData {
        load_range: (1.6, 3.0),
        equilibrium: vec![(1.6, onset, true), (onset, 3.0, false)],
        branches: vec![branch.clone()],
        sweep: Vec::new(),
    };
    let sheet = data.sheet(zieglerlab::i18n::words(zieglerlab::i18n::Language::English));
    let rendered = render(&sheet, &Page::default(), Format::Png).expect("a figure");
    let image = image::load_from_memory(&rendered.bytes)
        .expect("a PNG")
        .to_rgb8();
    let panel = &rendered.panels[0];
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let pixel = |(x, y): (f64, f64)| image.get_pixel(x.round() as u32, y.round() as u32).0;
    // The app's flutter orange where each solved cycle lies.
    for p in [2.2, 2.6] {
        let cycle = cycles_at(&m, &branch, p).remove(0);
        let [r, g, b] = pixel(panel.page_point(p, cycle.largest_amplitude_rad())).map(i32::from);
        assert!(r > g + 10 && g > b + 10, "p = {p}: {:?}", [r, g, b]);
        // ... and nothing a tenth of a radian above it.
        let above = pixel(panel.page_point(p, cycle.largest_amplitude_rad() + 0.1));
        assert_eq!(above, [255, 255, 255], "p = {p}");
    }
    // The straight column in black along the load axis below the onset.
    assert!(pixel(panel.page_point(1.7, 0.0)).iter().all(|&c| c < 80));
}

/// Drag along the rods with a light first rod (`c_ext = 0.05`, `m1 = 0.2`
/// on Ziegler's column): a hard onset (l1 > 0). From the Hopf point the
/// cycles are unstable and lie below the onset, with the normal form's
/// amplitudes; the branch folds back at a lower load, where the cycles turn
/// stable (one change of stability along the branch, at its fold: the
/// diagram's unstable and stable runs meet there), and the large stable
/// cycles go on past the onset.
#[test]
fn a_hard_onset_s_unstable_cycles_fold_back_into_large_stable_ones() {
    let m = hard_onset_column();
    let branch = first_branch(&m, 2.0, 2.3);
    let hopf = branch.hopf().clone();
    assert_eq!(hopf.kind, HopfKind::Subcritical);
    assert!(hopf.first_lyapunov > 0.0);
    let first = &branch.cycles[0];
    assert!(!first.stable && first.load < hopf.load, "{first:?}");
    // The fold: the branch's least load, below the onset.
    let (fold, fold_load) = branch
        .cycles
        .iter()
        .enumerate()
        .map(|(i, c)| (i, c.load))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    assert!(fold_load < hopf.load - 1e-4, "fold at {fold_load}");
    // One change of stability, from unstable to stable, next to the fold.
    let runs = branch.runs();
    assert_eq!(runs.iter().map(|r| r.1).collect::<Vec<_>>(), [false, true]);
    let first_stable = branch.cycles.iter().position(|c| c.stable).unwrap();
    assert!(first_stable.abs_diff(fold) <= 1, "{first_stable} vs {fold}");
    // The two runs meet at the fold of cycles solved for between two
    // cycles, not at either of them.
    let [turn] = branch.bifurcations[..] else {
        panic!("{:?}", branch.bifurcations)
    };
    let at = [turn.load, turn.amplitude_rad];
    assert_eq!(
        (runs[0].0.last(), runs[1].0.first()),
        (Some(&at), Some(&at))
    );
    assert!(branch.cycles.iter().all(|c| c.load > turn.load));
    assert!(branch.cycles.last().unwrap().load > hopf.load);
    // Near the onset the unstable cycles are the normal form's, below it.
    let per_sqrt = hopf.amplitude_per_sqrt_load_rad[0];
    let mut errors = Vec::new();
    for amplitude in [0.004, 0.0013] {
        let p = hopf.load - (amplitude / per_sqrt).powi(2);
        let cycles = cycles_at(&m, &branch, p);
        let small = cycles
            .iter()
            .min_by(|a, b| a.amplitude_rad[0].total_cmp(&b.amplitude_rad[0]))
            .unwrap_or_else(|| panic!("no cycle at p = {p}"));
        assert!(!small.stable);
        errors.push((small.amplitude_rad[0] / amplitude - 1.0).abs());
    }
    // Seen: 2.6e-4 and 2.1e-4, the accuracy of l1 by differences with drag.
    assert!(errors.iter().all(|e| *e < 1e-3), "{errors:?}");
}

/// The experiment's way on the same column: stepping the load up, the
/// column stays at rest between the fold and the onset; stepping it down
/// from the large cycle, it stays on that cycle there, as the shooting
/// finds it: hysteresis, the mark of a hard onset.
#[test]
fn a_sweep_over_a_hard_onset_shows_hysteresis() {
    let text = hard_onset_bifurcation(&["--x", "load:2.125:2.145:5", "--sweep"]);
    let rows = csv_rows(&text);
    let amplitudes = |branch: &str, load: &str| -> Vec<(f64, &str)> {
        rows.iter()
            .filter(|r| r[1] == branch && r[0] == load)
            .map(|r| (r[5].parse().expect("a number"), r[2]))
            .collect()
    };
    // Between the fold and the onset: an unstable and a stable cycle.
    let cycles = amplitudes("cycle-1", "2.135");
    assert_eq!(cycles.len(), 2, "{text}");
    let large = cycles.iter().find(|c| c.1 == "true").unwrap().0;
    let small = cycles.iter().find(|c| c.1 == "false").unwrap().0;
    assert!(small < 0.2 * large);
    let up = amplitudes("sweep-up", "2.135")[0].0;
    let down = amplitudes("sweep-down", "2.135")[0].0;
    assert!(up < 1e-3, "up: {up}");
    assert!((down / large - 1.0).abs() < 1e-4, "down: {down} vs {large}");
    // Just past the onset the way down is on the cycle too.
    let large = amplitudes("cycle-1", "2.14")[0].0;
    let down = amplitudes("sweep-down", "2.14")[0].0;
    assert!((down / large - 1.0).abs() < 1e-4, "down: {down} vs {large}");
}

/// The rows of `bifurcation`'s CSV after its header, split at the commas.
fn csv_rows(text: &str) -> Vec<Vec<&str>> {
    text.lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect()
}

/// `bifurcation` of [`hard_onset_column`] with `args` after the model: stdout.
fn hard_onset_bifurcation(args: &[&str]) -> String {
    let mut all = vec![
        "bifurcation",
        "--preset",
        "ziegler-1952",
        "--set",
        "c_ext=0.05",
        "--set",
        "m1=0.2",
    ];
    all.extend(args);
    crate::cli::stdout(&all)
}

fn hard_onset_column() -> Model {
    model("ziegler-1952", &["c_ext=0.05", "m1=0.2"])
}

/// A chain of four rods with joint dampers: its cycles come from the same
/// shooting (the implicit steps that keep a chain's fast modes from setting
/// the step), and one of them is a periodic orbit of the reference
/// integrator, with its trivial multiplier 1 and its amplitudes those the
/// run sees.
#[test]
fn a_chain_s_cycle_is_a_periodic_orbit_of_the_reference_integrator() {
    let m = model("uniform-rods", &["rods=4", "c1=0.05", "c2=0.05"]);
    let branch = first_branch(&m, 0.5, 0.6);
    assert_eq!(branch.hopf().kind, HopfKind::Supercritical);
    let cycle = cycles_at(&m, &branch, 0.58).remove(0);
    assert!(cycle.stable);
    assert!((cycle.trivial_multiplier() - 1.0).norm() < 1e-8);
    let largest = assert_reference_orbit(&m, &cycle, 0.58, 1e-7, 2e-6);
    for (seen, computed) in largest.iter().zip(&cycle.amplitude_rad) {
        // The samples never see more than the cycle's peaks.
        assert!(*seen <= computed * (1.0 + 1e-8), "{seen} vs {computed}");
    }
}

/// A chain of 16 rods: a small first Lyapunov coefficient (-1.3e-4) and a
/// period near 1000 s, so that next to the onset the cycles grow by
/// hundredths of a radian while the load moves by millionths. The branch is
/// followed past there (it was lost at p = 0.0401 while the continuation
/// weighed a second of the period as much as a radian of the angles), every
/// cycle on it is stable and larger than the last with its trivial
/// multiplier 1 to 1e-8 (5e-8 before the monodromy's Jacobians were
/// extrapolated), and the last one is a periodic orbit of the reference
/// integrator.
#[test]
fn a_long_chain_s_branch_is_followed_past_its_onset() {
    let m = model("uniform-rods", &["rods=16", "c1=0.05", "c2=0.05"]);
    let branch = first_branch(&m, 0.0395, 0.0402);
    assert_eq!(branch.hopf().kind, HopfKind::Supercritical);
    assert_eq!(branch.end, BranchEnd::LeftRange, "{}", branch.end);
    let onset = branch.hopf().load;
    assert!((0.0401..0.0402).contains(&onset), "onset at {onset}");
    for pair in branch.cycles.windows(2) {
        let (a, b) = (&pair[0], &pair[1]);
        assert!(b.load > a.load && b.largest_amplitude_rad() > a.largest_amplitude_rad());
    }
    for cycle in &branch.cycles {
        assert!(cycle.stable, "unstable at p = {}", cycle.load);
        let trivial = (cycle.trivial_multiplier() - 1.0).norm();
        assert!(trivial < 1e-8, "trivial multiplier off by {trivial}");
    }
    let last = branch.cycles.last().expect("cycles");
    assert!(
        last.largest_amplitude_rad() > 0.05,
        "{}",
        last.largest_amplitude_rad()
    );
    assert_reference_orbit(&m, last, last.load, 1e-6, 1e-5);
}

/// Past a chain's onset its swing grows and slows until three times its
/// frequency meets the second mode's: there the swing's third harmonic
/// (from the cubic terms) drives that mode at resonance, and the largest
/// amplitude stops growing and dips before it grows on (6 rods near
/// p = 0.3; 16 rods at p = 0.046, where it falls from 0.54 to 0.26 rad).
/// The dip's load is read off the branch, the second mode's frequency off
/// the linear pencil there: independent of each other.
#[test]
fn a_chain_s_amplitude_dips_where_its_third_harmonic_meets_the_second_mode() {
    let m = model("uniform-rods", &["rods=6", "c1=0.05", "c2=0.05"]);
    let branch = first_branch(&m, 0.25, 0.36);
    let amplitudes: Vec<f64> = branch
        .cycles
        .iter()
        .map(Cycle::largest_amplitude_rad)
        .collect();
    let dip = (1..amplitudes.len() - 1)
        .find(|&i| amplitudes[i] < amplitudes[i - 1] && amplitudes[i] <= amplitudes[i + 1])
        .expect("a dip in the largest amplitude");
    let cycle = &branch.cycles[dip];
    let mut frequencies: Vec<f64> = eigenvalues(&m.at_load(cycle.load))
        .iter()
        .filter(|z| z.im > 0.0)
        .map(|z| z.im)
        .collect();
    frequencies.sort_by(f64::total_cmp);
    let cycle_rad_per_s = std::f64::consts::TAU / cycle.period_secs;
    let ratio = frequencies[1] / cycle_rad_per_s;
    assert!(
        (ratio - 3.0).abs() < 0.05,
        "at the dip (p = {}) the second mode is {ratio} times the cycle's frequency",
        cycle.load
    );
}

/// One load (`--x load:L:L:1`) gives the cycles there, followed from the
/// onset below it: the same cycle as the row at L of a range of loads
/// that starts below the onset, and only L.
#[test]
fn one_load_gives_the_cycle_a_range_gives_there() {
    let csv = |x: &str| damped_ziegler_bifurcation(&["--x", x]);
    let row = |text: &str, branch: &str| -> Vec<String> {
        text.lines()
            .filter(|line| line.split(',').nth(1) == Some(branch))
            .map(str::to_owned)
            .collect()
    };
    let one = csv("load:2.2:2.2:1");
    let cycles = row(&one, "cycle-1");
    assert_eq!(cycles.len(), 1, "{one}");
    assert_eq!(row(&one, "equilibrium").len(), 1, "{one}");
    let range = csv("load:1.8:2.2:5");
    let at_end: Vec<String> = row(&range, "cycle-1")
        .into_iter()
        .filter(|line| line.starts_with("2.2,"))
        .collect();
    assert_eq!(at_end.len(), 1, "{range}");
    let numbers = |line: &str| -> Vec<f64> {
        line.split(',')
            .filter_map(|field| field.parse::<f64>().ok())
            .collect()
    };
    let (a, b) = (numbers(&cycles[0]), numbers(&at_end[0]));
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(&b) {
        assert!(
            (x - y).abs() <= 1e-8 * x.abs().max(1e-3),
            "{} against {}",
            cycles[0],
            at_end[0]
        );
    }
    let refused = crate::cli::run(&[
        "bifurcation",
        "--preset",
        "ziegler-1952",
        "--x",
        "load:2.2:2.2:1",
        "--sweep",
    ]);
    assert_eq!(refused.status.code(), Some(2));
}

/// The hard onset's branch folds back: its multipliers say so where its
/// loads turn. The fold of cycles read from a real multiplier through +1
/// is solved for between the two cycles it lies between: at a load below
/// every cycle's of the branch (it is the least the branch reaches) and
/// within 1e-4 of the least of them. The cycle nearest it has one
/// multiplier outside the unit circle, real and within 0.1 of 1 besides
/// the trivial one (seen 0.059: the continuation's step passes the fold
/// 0.04 rad of amplitude from it; 0.0072 when it stepped nearer), the
/// other two 0.3 or more from 1, and the cycle after the fold none: one
/// real multiplier has gone through +1. The branch has no period doubling
/// and no torus.
#[test]
fn the_fold_of_cycles_is_where_the_branch_turns_and_a_multiplier_is_one() {
    use zieglerlab::analysis::CycleBifurcationKind;
    let m = hard_onset_column();
    let branch = first_branch(&m, 2.1, 2.2);
    let found = &branch.bifurcations;
    let folds: Vec<_> = found
        .iter()
        .filter(|f| f.kind == CycleBifurcationKind::Fold)
        .collect();
    assert_eq!(folds.len(), 1, "{found:?}");
    assert_eq!(found.len(), 1, "no period doubling, no torus: {found:?}");
    let (turn, at) = branch
        .cycles
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.load.total_cmp(&b.1.load))
        .map(|(i, c)| (c.load, i))
        .unwrap();
    let fold = folds[0].load;
    assert!(folds[0].refined);
    assert!(
        fold <= turn && turn - fold <= 1e-4 * turn,
        "fold at p = {fold}, the branch turns at p = {turn}"
    );
    let nontrivial = |cycle: &Cycle| -> Vec<_> {
        let trivial = cycle.trivial_multiplier();
        let mut others: Vec<_> = cycle
            .multipliers
            .iter()
            .copied()
            .filter(|m| *m != trivial)
            .collect();
        others.sort_by(|a, b| (a - 1.0).norm().total_cmp(&(b - 1.0).norm()));
        others
    };
    let (nearest, after) = (
        nontrivial(&branch.cycles[at]),
        nontrivial(&branch.cycles[at + 1]),
    );
    let crossing = nearest[0];
    assert!(
        crossing.im == 0.0 && crossing.re > 1.0 && crossing.re < 1.1,
        "{nearest:?}"
    );
    assert!(
        nearest[1..]
            .iter()
            .all(|m| (m - 1.0).norm() > 0.3 && m.norm() < 1.0)
    );
    assert!(after.iter().all(|m| m.norm() < 1.0), "{after:?}");
    // The diagram rings it there and names it beside the ring, on the
    // side away from the branch (a name above would hide the turn), and
    // its legend says what the name means.
    let sheet = zieglerlab::plot::bifurcation::Diagram {
        load_range: (2.1, 2.2),
        equilibrium: &[],
        branches: vec![&branch],
        sweep: &[],
        present: None,
        words: zieglerlab::i18n::words(zieglerlab::i18n::Language::English),
    }
    .sheet();
    let named = sheet.plots[0].marks.iter().any(|mark| {
        matches!(mark, zieglerlab::plot::spec::Mark::Label { at, text, .. }
            if text == "LPC" && at[0] < fold && at[1] == folds[0].amplitude_rad)
    });
    assert!(named, "{:?}", sheet.plots[0].marks.len());
    assert!(
        sheet
            .legend
            .iter()
            .any(|e| e.text.starts_with("LPC: fold of cycles"))
    );
}

/// `bifurcation`'s CSV lists the cycles' own bifurcations as rows of their
/// own: the hard onset's fold of cycles, at the load and on the branch the
/// JSON gives, its kind in the last column, nothing measured beside it.
#[test]
fn bifurcation_csv_lists_the_fold_of_cycles() {
    let run = |format: &str| hard_onset_bifurcation(&["--x", "load:2.1:2.2:3", "--format", format]);
    let csv = run("csv");
    let folds: Vec<&str> = csv.lines().filter(|l| l.ends_with(",fold")).collect();
    assert_eq!(folds.len(), 1, "{csv}");
    let fields: Vec<&str> = folds[0].split(',').collect();
    assert_eq!(fields[1..], ["cycle-1", "", "", "", "", "fold"]);
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    let fold = &json["onsets"][0]["cycle_bifurcations"][0];
    assert_eq!(fold["kind"], "fold");
    assert_eq!(
        fields[0].parse::<f64>().unwrap(),
        fold["load"].as_f64().unwrap()
    );
}
