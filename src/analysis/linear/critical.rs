//! Critical loads: every change of stability along the load axis, located to
//! near machine precision.

use crate::analysis::AnalysisError;
use crate::analysis::C64;
use crate::analysis::crossing::{Transition, refine, state_at};
use crate::analysis::locus::{
    Crossings, LARGEST_LOAD, Locus, check_largest_load, load_grid, load_resolution, locus_until,
    max_samples,
};
use crate::analysis::pencil::AffinePencil;
use crate::analysis::stability::{State, classify};

/// Samples of the locus that brackets the transitions before they are refined.
pub const BRACKET_SAMPLES: usize = 1000;

/// Every change of stability for loads in `[load_min, load_max]`, in
/// increasing load: [`critical_loads_along`] the [`bracketing_locus`].
///
/// # Errors
/// A bad range or a failed eigenvalue computation.
pub fn critical_loads(
    pencil: &AffinePencil,
    load_min: f64,
    load_max: f64,
) -> Result<Vec<Transition>, AnalysisError> {
    critical_loads_along(pencil, &bracketing_locus(pencil, load_min, load_max)?)
}

/// A bracketing locus whose evenly spaced loads include `cells` evenly
/// spaced loads of the same range, at every `stride`-th: at least
/// [`BRACKET_SAMPLES`] of them, as fine as [`bracketing_locus`]'s, so a
/// stability map's row has its critical loads and its cells from one locus.
/// `None` where [`bracketing_locus`] brackets in sections (a range beyond
/// ten times the natural one) or the range cannot hold so many distinct
/// loads: the row then takes a locus of its own for the cells.
///
/// # Errors
/// A failed eigenvalue computation.
pub(crate) fn bracketing_locus_through(
    pencil: &AffinePencil,
    (load_min, load_max): (f64, f64),
    cells: usize,
) -> Result<Option<(Locus, usize)>, AnalysisError> {
    if cells < 2 || load_max > LARGEST_LOAD || !within_natural_decade(pencil, load_min, load_max) {
        return Ok(None);
    }
    let stride = (BRACKET_SAMPLES - 1).div_ceil(cells - 1);
    let samples = (cells - 1) * stride + 1;
    if samples > max_samples(pencil) || load_grid(load_min, load_max, samples).is_err() {
        return Ok(None);
    }
    let bracket = locus_until(
        pencil,
        (load_min, load_max, samples),
        Crossings::Bracketed,
        |_, _| false,
    )?;
    Ok(Some((bracket, stride)))
}

/// Whether `[load_min, load_max]` ends within ten times the column's
/// natural range (from `load_min` on): bracketed by evenly spaced loads
/// alone, not in sections.
fn within_natural_decade(pencil: &AffinePencil, load_min: f64, load_max: f64) -> bool {
    load_max <= 10.0 * natural_end(pencil, load_min)
}

/// The end of the column's natural range, or `load_min` past it.
fn natural_end(pencil: &AffinePencil, load_min: f64) -> f64 {
    pencil.natural_load_max().max(load_min)
}

/// Samples of each decade of load in a wide range (see [`bracketing_locus`]).
const DECADE_SAMPLES: usize = 4000;

/// Beyond this many times the load that matches the column's stiffness, the
/// column's own stiffness changes the pencil by less than the
/// classification's tolerance (1e-10 of the frequency scale, see
/// [`RELATIVE_TOLERANCE`](crate::analysis::RELATIVE_TOLERANCE)) and below rounding
/// 1e5 times further: the pencil changes in scale only.
const ROUNDED_AWAY: f64 = 1e12;

/// Samples of the range beyond [`ROUNDED_AWAY`].
const ROUNDED_AWAY_SAMPLES: usize = 100;

/// The tracked locus that brackets every change of stability over
/// `[load_min, load_max]`. Up to ten times the column's natural range
/// ([`AffinePencil::natural_load_max`]), [`BRACKET_SAMPLES`] evenly spaced
/// loads (fewer when the range holds fewer distinct loads in f64, one when it
/// is a point). A wider range is bracketed in sections: the natural range
/// as above, then [`DECADE_SAMPLES`] per decade of load, so that `--load-max
/// 1e6` resolves the same windows as the natural range, up to where the
/// column's stiffness is rounded away ([`ROUNDED_AWAY`]); beyond that, where
/// nothing but the scale changes, [`ROUNDED_AWAY_SAMPLES`].
///
/// # Errors
/// A bad range (also one too narrow to hold two distinct loads, or one
/// reaching beyond [`LARGEST_LOAD`]) or a failed eigenvalue computation.
pub fn bracketing_locus(
    pencil: &AffinePencil,
    load_min: f64,
    load_max: f64,
) -> Result<Locus, AnalysisError> {
    bracketing_locus_reporting(pencil, load_min, load_max, &mut |_, _| {})
}

/// [`bracketing_locus`], telling `progress(done, total)` the evenly spaced
/// loads computed of all it will compute (refinements not counted), after
/// each: a wide range on a long chain takes minutes.
///
/// # Errors
/// As [`bracketing_locus`].
pub fn bracketing_locus_reporting(
    pencil: &AffinePencil,
    load_min: f64,
    load_max: f64,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Locus, AnalysisError> {
    sectioned_locus(pencil, (load_min, load_max), Crossings::Bracketed, progress)
}

/// The locus a figure draws over `[load_min, load_max]`: the loads of
/// [`bracketing_locus`] (so a wide range finds the windows `critical`
/// finds, and a range past [`LARGEST_LOAD`] is refused as there), with
/// every crossing of an axis refined as a plot shows it.
///
/// # Errors
/// As [`bracketing_locus`].
pub fn plotted_locus(
    pencil: &AffinePencil,
    load_min: f64,
    load_max: f64,
) -> Result<Locus, AnalysisError> {
    sectioned_locus(
        pencil,
        (load_min, load_max),
        Crossings::Refined,
        &mut |_, _| {},
    )
}

/// [`bracketing_locus_reporting`], refining `crossings`.
fn sectioned_locus(
    pencil: &AffinePencil,
    (load_min, load_max): (f64, f64),
    crossings: Crossings,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<Locus, AnalysisError> {
    check_largest_load(load_max)?;
    if within_natural_decade(pencil, load_min, load_max) {
        return evenly_bracketed_until(
            pencil,
            (load_min, load_max),
            crossings,
            counting(0, BRACKET_SAMPLES - 1, progress),
        );
    }
    // The sections beyond the natural range, planned first to know the total.
    let natural = natural_end(pencil, load_min);
    let rounded_away = ROUNDED_AWAY * pencil.stiffness_matching_load().max(natural);
    let mut sections = Vec::new();
    let mut start = natural;
    while start < load_max {
        let (end, samples) = if start >= rounded_away {
            (load_max, ROUNDED_AWAY_SAMPLES)
        } else {
            ((10.0 * start).min(load_max), DECADE_SAMPLES)
        };
        sections.push((start, end, samples));
        start = end;
    }
    // Each section's first load is the one before's last: the steps count.
    let total = BRACKET_SAMPLES - 1 + sections.iter().map(|&(_, _, n)| n - 1).sum::<usize>();
    let mut whole = evenly_bracketed_until(
        pencil,
        (load_min, natural),
        crossings,
        counting(0, total, progress),
    )?;
    let mut done = BRACKET_SAMPLES - 1;
    for (start, end, samples) in sections {
        whole.extend_with(&locus_until(
            pencil,
            (start, end, samples),
            crossings,
            counting(done, total, progress),
        )?);
        done += samples - 1;
    }
    Ok(whole)
}

/// A `stop` for [`locus_until`] that never stops and tells `progress` each
/// load done after a section's first, counted on from `done` of `total`.
fn counting(
    mut done: usize,
    total: usize,
    progress: &mut dyn FnMut(usize, usize),
) -> impl FnMut(f64, &[C64]) -> bool + '_ {
    move |_, _| {
        done += 1;
        progress(done, total);
        false
    }
}

/// Evenly spaced loads past the first unstable one that the bracketing
/// locus of [`first_loss_within`] goes on to: room to widen the bracket
/// where the tracked roots and the Schur path read a double root apart.
const PAST_FIRST_LOSS: usize = 8;

/// The first change from stable to unstable in `[0, load_max]`, as
/// [`critical_loads`] finds it, with the bracketing locus ended a few
/// samples past the first unstable one (the whole range when the column
/// starts unstable or stays stable).
///
/// # Errors
/// A bad range or a failed eigenvalue computation.
pub(in crate::analysis) fn first_loss_within(
    pencil: &AffinePencil,
    load_max: f64,
) -> Result<Option<Transition>, AnalysisError> {
    let mut seen_stable = false;
    let mut past = None;
    let bracket = evenly_bracketed_until(
        pencil,
        (0.0, load_max),
        Crossings::Bracketed,
        |p, eigenvalues| {
            let stable = classify(eigenvalues, pencil.scale_per_s(p)).state == State::Stable;
            seen_stable |= stable;
            if seen_stable && !stable && past.is_none() {
                past = Some(0);
            }
            past = past.map(|n: usize| n + 1);
            past.is_some_and(|n| n > PAST_FIRST_LOSS)
        },
    )?;
    Ok(transitions_along(pencil, &bracket, (0.0, load_max))?
        .into_iter()
        .find(|t| t.from == State::Stable))
}

/// The tracked locus of [`BRACKET_SAMPLES`] evenly spaced loads (fewer
/// when the range holds fewer distinct loads), ended where `stop` says (see
/// [`locus_until`]).
fn evenly_bracketed_until(
    pencil: &AffinePencil,
    (load_min, load_max): (f64, f64),
    crossings: Crossings,
    stop: impl FnMut(f64, &[C64]) -> bool,
) -> Result<Locus, AnalysisError> {
    // A range only a few units in the last place wide holds fewer distinct loads.
    let resolution = load_resolution(load_max);
    let samples = if load_max > load_min {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a non-negative count, capped at BRACKET_SAMPLES"
        )]
        let distinct = ((load_max - load_min) / resolution).floor().min(1e9) as usize + 1;
        if distinct < 2 {
            return Err(AnalysisError::BadRange {
                what: "load-max",
                value: load_max,
                allowed: "must exceed load-min by more than the resolution of double precision there (or equal it, for a single load)",
            });
        }
        distinct.min(BRACKET_SAMPLES)
    } else {
        1
    };
    locus_until(pencil, (load_min, load_max, samples), crossings, stop)
}

/// Every change of stability over the loads of `locus` (a tracked, refined
/// root locus of `pencil`, e.g. the one a plot shows), in increasing load.
/// The locus only brackets: where branches cross an axis between its samples
/// the refinement has caught it. Each change is confirmed and refined on the
/// robust Schur path, so the loads do not depend on the locus's samples once
/// they bracket the change.
///
/// # Errors
/// A failed eigenvalue computation.
pub fn critical_loads_along(
    pencil: &AffinePencil,
    locus: &Locus,
) -> Result<Vec<Transition>, AnalysisError> {
    match (locus.loads.first(), locus.loads.last()) {
        (Some(&min), Some(&max)) => transitions_along(pencil, locus, (min, max)),
        _ => Ok(Vec::new()),
    }
}

/// [`critical_loads_along`] a locus that may cover only part of `range`,
/// the loads the crossings are polished within.
fn transitions_along(
    pencil: &AffinePencil,
    locus: &Locus,
    range: (f64, f64),
) -> Result<Vec<Transition>, AnalysisError> {
    let mut moving = Vec::with_capacity(locus.moving_branches().len());
    let tracked: Vec<State> = (0..locus.loads.len())
        .map(|i| {
            moving.clear();
            moving.extend(locus.moving_branches().iter().map(|branch| branch[i]));
            classify(&moving, pencil.scale_per_s(locus.loads[i])).state
        })
        .collect();
    // Whether the Schur path agrees with the tracked roots at sample j, and its state.
    let schur = |j: usize| state_at(pencil, locus.loads[j]).map(|s| (s == tracked[j], s));
    let mut transitions = Vec::new();
    let mut done_until = 0;
    for i in 1..locus.loads.len() {
        if tracked[i] == tracked[i - 1] || i <= done_until {
            continue;
        }
        // The tracked roots only bracket. Widen the bracket to the nearest
        // samples where the Schur path agrees with them: right at a double
        // root the two read rounding differently (Schur sees Re ~ sqrt(eps)).
        let (mut left, mut left_state) = (i - 1, schur(i - 1)?);
        while !left_state.0 && left > 0 {
            left -= 1;
            left_state = schur(left)?;
        }
        let (mut right, mut right_state) = (i, schur(i)?);
        while !right_state.0 && right + 1 < locus.loads.len() {
            right += 1;
            right_state = schur(right)?;
        }
        done_until = right;
        let (sa, sb) = (left_state.1, right_state.1);
        if sa != sb {
            let (a, b) = (locus.loads[left], locus.loads[right]);
            refine(
                pencil,
                &locus.moving_at(left),
                (a, sa),
                (b, sb),
                range,
                &mut transitions,
            )?;
        }
    }
    Ok(transitions)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    /// The progress of a wide bracket counts every evenly spaced load once,
    /// in order, to its total, and the locus is the one without progress.
    #[test]
    fn a_wide_bracket_reports_its_progress_to_the_end() {
        let pencil = AffinePencil::new(&PresetId::Ziegler1952.model()).unwrap();
        let mut seen = Vec::new();
        let reported = bracketing_locus_reporting(&pencil, 0.0, 1e6, &mut |done, total| {
            seen.push((done, total));
        })
        .unwrap();
        let total = seen[0].1;
        assert!(total > BRACKET_SAMPLES, "sections beyond the natural range");
        assert!(seen.iter().all(|&(_, t)| t == total));
        assert!(seen.windows(2).all(|w| w[1].0 > w[0].0), "in order");
        assert_eq!(seen.last().unwrap().0, total);
        assert_eq!(
            reported.loads,
            bracketing_locus(&pencil, 0.0, 1e6).unwrap().loads
        );
    }
}
