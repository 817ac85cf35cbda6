//! The fold of cycles followed in a second parameter: along it a second
//! Floquet multiplier is 1; it lies below the flutter onset (the band of
//! hysteresis) and meets it at the Bautin point where the onset turns
//! hard; at one value its load is where the branch of cycles that
//! `bifurcation` follows turns back; that branch is resolved up to where
//! the column swings round, and its large stable cycles are attractors of
//! the reference integrator.

use zieglerlab::analysis::{
    AffinePencil, FoldEnd, Kick, SpecialKind, State, critical_loads, cycle_branches,
};

use crate::common::{
    diagram_said, drag_column_boundaries, half_period_map, hard_onset_branch, model, settled,
};

/// The first flutter onset of the drag column with first rod `m1`.
fn onset(m1: f64) -> f64 {
    let m = model("ziegler-1952", &["c_ext=0.05", &format!("m1={m1}")]);
    let pencil = AffinePencil::new(&m).unwrap();
    critical_loads(&pencil, 0.0, 8.0)
        .unwrap()
        .into_iter()
        .find(|t| t.to == State::Flutter)
        .expect("a flutter onset")
        .load
}

/// Drag along the rods, m1 from 0.2 to 2 (the README's example): the
/// onset is hard for a light first rod, and the fold of cycles runs from
/// m1 = 0.2 to the Bautin point. Every point has a second multiplier
/// within 1e-4 of 1 (seen 2.5e-5: a double multiplier is found to the
/// square root of the monodromy's accuracy) and lies below the onset at
/// its m1 (to 1e-8 where its amplitude is below 0.01 rad); the fold's end where its cycles shrink is within 1e-3 of the
/// range of the Bautin point and within 1e-6 of the onset there (seen
/// 1.6e-4 and 1.1e-8; the gap shrinks as the square of the distance from
/// the Bautin point). At m1 = 0.2 its load is the fold of cycles solved
/// for on the branch `bifurcation` follows there (pseudo-arclength in the
/// load, its own cycles) to 1e-10 (seen 2e-16), below every cycle of that
/// branch, its amplitude between the neighbours' of the least of them
/// (how near that cycle comes is the continuation's step: 6.6e-7 of the
/// load once, 8.9e-5 now that the branch steps past the fold faster).
#[test]
fn the_fold_of_cycles_runs_from_the_bautin_point_below_the_onset() {
    let (_, found) = drag_column_boundaries();
    assert_eq!(found.folds.len(), 1, "{:?}", found.folds.len());
    let fold = &found.folds[0];
    assert_eq!(fold.ends, [FoldEnd::SmallAmplitude, FoldEnd::ParameterEdge]);
    for point in &fold.points {
        let off = (point.second_multiplier - 1.0).norm();
        assert!(
            off < 1e-4,
            "m1 = {}: {}",
            point.value,
            point.second_multiplier
        );
        // Near the Bautin point the gap is below the fold's accuracy
        // there (a shallow fold in the amplitude: a few 1e-9).
        let hopf = onset(point.value);
        let below = if point.amplitude_rad < 0.01 {
            1e-8
        } else {
            0.0
        };
        assert!(
            point.load < hopf + below,
            "m1 = {}: {} {hopf}",
            point.value,
            point.load
        );
    }
    let bautin = found
        .special_points
        .iter()
        .find(|s| s.kind == SpecialKind::Bautin)
        .expect("a Bautin point");
    let first = &fold.points[0];
    assert!(
        (first.value - bautin.value).abs() < 1e-3 * 1.8,
        "{} {}",
        first.value,
        bautin.value
    );
    let gap = onset(first.value) - first.load;
    assert!(gap < 1e-6, "{gap}");
    let last = fold.points.last().unwrap();
    assert_eq!(last.value, 0.2);
    let light = model("ziegler-1952", &["c_ext=0.05", "m1=0.2"]);
    let never = std::sync::atomic::AtomicBool::new(false);
    let branches = cycle_branches(&light, 2.1, 2.2, &never).unwrap();
    let branch = branches[0].branch.as_ref().expect("a branch");
    // The fold is the least load of the branch's cycles, below every
    // computed one (each to about 1e-9) and near the least of them.
    let (turn, least) = branch
        .cycles
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.load.total_cmp(&b.1.load))
        .map(|(i, c)| (i, c.load))
        .unwrap();
    assert!(last.load <= least + 1e-9, "{} {least}", last.load);
    let solved: Vec<f64> = branch
        .bifurcations
        .iter()
        .filter(|b| b.refined)
        .map(|b| b.load)
        .collect();
    assert!(
        matches!(solved[..], [fold] if (fold - last.load).abs() < 1e-10 * fold),
        "{} {solved:?}",
        last.load
    );
    let amplitude = |i: usize| branch.cycles[i].amplitude_rad[0];
    assert!(
        amplitude(turn - 1) < last.amplitude_rad && last.amplitude_rad < amplitude(turn + 1),
        "{} {} {}",
        amplitude(turn - 1),
        last.amplitude_rad,
        amplitude(turn + 1)
    );
}

/// What a kick does, read off the same boundaries (the map tab's readout):
/// at m1 = 0.25 below the fold it dies out, between the fold and the hard
/// onset it may leave the column swinging, past the onset it jumps; at
/// m1 = 1.5, past the soft onset, it grows softly. The map drawn with the
/// boundaries has the band (load along x), names the fold in its key and
/// tells a screen reader of the band.
#[test]
fn a_kick_settles_below_the_fold_and_jumps_past_a_hard_onset() {
    use zieglerlab::analysis::{MapSpec, RowResult};
    use zieglerlab::plot::map::StabilityMap;
    use zieglerlab::plot::spec::{CellGrid, Mark};
    let (spec, found) = drag_column_boundaries();
    let fold_at = |m1: f64| {
        found.folds[0]
            .points
            .windows(2)
            .find_map(|w| {
                let (a, b) = (&w[0], &w[1]);
                ((a.value.min(b.value)..=a.value.max(b.value)).contains(&m1))
                    .then(|| a.load + (m1 - a.value) / (b.value - a.value) * (b.load - a.load))
            })
            .unwrap()
    };
    let (fold, hopf) = (fold_at(0.25), onset(0.25));
    let kick = |m1: f64, load: f64, state: State| found.kick_at(m1, load, state);
    assert_eq!(kick(0.25, fold - 0.01, State::Stable), Some(Kick::Settles));
    let between = 0.5 * (fold + hopf);
    assert_eq!(kick(0.25, between, State::Stable), Some(Kick::Hysteresis));
    assert_eq!(kick(0.25, hopf + 0.01, State::Flutter), Some(Kick::Jumps));
    assert_eq!(
        kick(1.5, onset(1.5) + 0.01, State::Flutter),
        Some(Kick::GrowsSoftly)
    );
    assert_eq!(
        kick(1.5, onset(1.5) - 0.01, State::Stable),
        Some(Kick::Settles)
    );
    let map = MapSpec {
        model: spec.model,
        axis: spec.axis.clone(),
        load_range: (0.0, 8.0),
        loads: 3,
        axis_range: (0.2, 2.0),
        values: 2,
    };
    let rows: Vec<Option<RowResult>> = vec![None, None];
    let sheet = StabilityMap {
        spec: &map,
        rows: &rows,
        grid: std::sync::Arc::new(CellGrid::new(&map, &rows)),
        now: None,
        followed: Some(found),
        words: zieglerlab::i18n::words(zieglerlab::i18n::Language::English),
    }
    .sheet();
    let band = sheet.plots[0].marks.iter().find_map(|mark| match mark {
        Mark::Band { lower, upper, .. } => Some((lower.clone(), upper.clone())),
        _ => None,
    });
    let (lower, upper) = band.expect("a band of hysteresis");
    for (low, high) in lower.iter().zip(&upper) {
        assert_eq!(low[1], high[1], "the band's sides at one m1");
        assert!(
            low[0] <= high[0] + 1e-8,
            "the fold's load below the onset's"
        );
    }
    assert!(
        sheet
            .legend
            .iter()
            .any(|e| e.text.starts_with("fold of cycles")),
        "{:?}",
        sheet.legend
    );
    // A screen reader is told of the band too.
    let words = zieglerlab::i18n::words(zieglerlab::i18n::Language::English);
    let said = zieglerlab::plot::describe::describe(&sheet.plots[0], words);
    assert!(said.contains("the band of hysteresis"), "{said}");
}

/// With the drag's Jacobian in closed form the hard onset's cycles are
/// resolved along the whole branch over the window's loads: every trivial
/// multiplier is within 1e-8 of 1 (by differences of the equations they
/// strayed 1e-7 to 1.2e-6 from it past the second fold, noise that more
/// steps did not cut, and the branch ended "not resolved" at p = 2.1475),
/// and the branch goes on until an angle passes 3 rad. Its three folds
/// are solved for; past the third (at 2.0 rad) the branch has large
/// stable cycles, and a run of the reference integrator from the one whose
/// perturbations die fastest, every coordinate 1 % larger, settles back
/// onto it after 60 periods: the multipliers' verdict and the branch's
/// amplitudes, checked by an independent integrator.
#[test]
fn the_hard_onset_s_branch_is_resolved_up_to_where_the_column_swings_round() {
    use zieglerlab::analysis::{BranchEnd, CycleBifurcationKind};
    use zieglerlab::sim::EngineKind;
    let (m, branch) = hard_onset_branch();
    assert_eq!(branch.end, BranchEnd::LargeAmplitude, "{}", branch.end);
    for cycle in &branch.cycles {
        let off = (cycle.trivial_multiplier() - 1.0).norm();
        assert!(
            off < 1e-8,
            "p = {}: trivial multiplier off by {off}",
            cycle.load
        );
    }
    let folds: Vec<_> = branch
        .bifurcations
        .iter()
        .filter(|b| b.kind == CycleBifurcationKind::Fold)
        .collect();
    assert_eq!(folds.len(), 3, "{folds:?}");
    assert!(folds.iter().all(|f| f.refined), "{folds:?}");
    let third = folds[2];
    assert!((third.amplitude_rad - 2.0).abs() < 0.05, "{third:?}");
    // The slowest decay of a perturbation over a period: the largest
    // nontrivial multiplier's modulus.
    let decay = |cycle: &zieglerlab::analysis::Cycle| {
        let trivial = cycle.trivial_multiplier();
        cycle
            .multipliers
            .iter()
            .filter(|z| **z != trivial)
            .map(|z| z.norm())
            .fold(0.0, f64::max)
    };
    let cycle = branch
        .cycles
        .iter()
        .filter(|c| c.stable && c.largest_amplitude_rad() > third.amplitude_rad)
        .min_by(|a, b| decay(a).total_cmp(&decay(b)))
        .expect("large stable cycles past the third fold");
    assert!(decay(cycle) < 0.9, "{:?}", cycle.multipliers);
    let at = m.at_load(cycle.load);
    let x0 = cycle.start_state(&at) * 1.01;
    let largest = settled(&at, EngineKind::Reference, x0, cycle.period_secs);
    for (seen, computed) in largest.iter().zip(&cycle.amplitude_rad) {
        assert!(
            (seen / computed - 1.0).abs() < 1e-3,
            "p = {}: {seen} vs {computed}",
            cycle.load
        );
    }
}

/// Past the third fold the stable large cycles lose their stability where
/// a real multiplier goes through +1 while the load goes on growing (the
/// cycles' loads rise through it): no fold but a break of the mirror
/// symmetry, named so and solved for. Checked by an independent
/// integrator: the cycles on either side are their own mirror images half
/// a period on (`x(T/2) = -x(0)` to 1e-7), so the monodromy is the square
/// of the half-period map `R`; on the cycle after the break `R` has a real
/// multiplier below -1 whose square is the shooting's multiplier above 1
/// (to 1e-4), and on the cycle before it none: `rho` went through -1, the
/// signature of a pitchfork of symmetric cycles (through +1 it would be a
/// fold). Solved for on the symmetric cycles, its load is the same to
/// 1e-10 on another load range.
#[test]
fn the_hard_onset_s_large_cycles_break_their_symmetry_where_no_fold_is() {
    use zieglerlab::analysis::CycleBifurcationKind;
    let (m, branch) = hard_onset_branch();
    let broken: Vec<_> = branch
        .bifurcations
        .iter()
        .filter(|b| b.kind == CycleBifurcationKind::SymmetryBreaking)
        .collect();
    let [bp] = broken[..] else {
        panic!("{:?}", branch.bifurcations)
    };
    assert!(bp.refined, "{bp:?}");
    assert!((2.29..2.30).contains(&bp.load), "{bp:?}");
    // Solved for on the symmetric cycles, it does not move with the
    // continuation's steps: a narrower load range (steps of a fifth the
    // load) puts it at the same load (seen 3e-14 apart).
    let never = std::sync::atomic::AtomicBool::new(false);
    let narrower = cycle_branches(m, 2.0, 2.8, &never).unwrap().remove(0);
    let again = narrower
        .branch
        .expect("a branch")
        .bifurcations
        .into_iter()
        .find(|b| b.kind == CycleBifurcationKind::SymmetryBreaking)
        .expect("the break of symmetry again");
    assert!(
        again.refined && (again.load - bp.load).abs() < 1e-10 * bp.load,
        "{again:?} {bp:?}"
    );
    // The cycles of the branch next to it, by load, among those of its
    // amplitude.
    let near: Vec<_> = branch
        .cycles
        .iter()
        .filter(|c| (c.largest_amplitude_rad() - bp.amplitude_rad).abs() < 0.1)
        .collect();
    let before = near
        .iter()
        .filter(|c| c.load < bp.load)
        .max_by(|a, b| a.load.total_cmp(&b.load))
        .expect("a cycle before");
    let after = near
        .iter()
        .filter(|c| c.load > bp.load)
        .min_by(|a, b| a.load.total_cmp(&b.load))
        .expect("a cycle after");
    assert!(before.stable && !after.stable);
    assert!(before.largest_amplitude_rad() < bp.amplitude_rad);
    assert!(bp.amplitude_rad < after.largest_amplitude_rad());
    let below_minus_one = |map: &nalgebra::DMatrix<f64>| -> Vec<f64> {
        map.complex_eigenvalues()
            .iter()
            .filter(|rho| rho.im.abs() < 1e-9 && rho.re < -1.0)
            .map(|rho| rho.re)
            .collect()
    };
    let (map_before, mirror_before) = half_period_map(m, before);
    let (map_after, mirror_after) = half_period_map(m, after);
    assert!(
        mirror_before < 1e-7 && mirror_after < 1e-7,
        "{mirror_before} {mirror_after}"
    );
    assert!(below_minus_one(&map_before).is_empty(), "{map_before}");
    let [rho] = below_minus_one(&map_after)[..] else {
        panic!("{map_after}")
    };
    let mu = after.multipliers[0];
    assert!(mu.im == 0.0 && mu.re > 1.0, "{:?}", after.multipliers);
    assert!((rho * rho / mu.re - 1.0).abs() < 1e-4, "{rho} {mu}");
    // The diagram names it BPC, its key spells that out, and a screen
    // reader hears it among the named points.
    let (said, legend) = diagram_said(branch);
    assert!(
        legend
            .iter()
            .any(|text| text.contains("BPC: symmetry breaks (branch point of cycles)")),
        "{legend:?}"
    );
    assert!(said.contains("BPC at"), "{said}");
}
