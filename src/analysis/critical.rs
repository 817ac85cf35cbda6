//! Critical loads: every change of stability along the load axis, located to
//! near machine precision.

use serde::Serialize;

use super::AnalysisError;
use super::C64;
use super::locus::{Locus, eigenvalues_near, load_resolution, locus_until};
use super::pencil::AffinePencil;
use super::stability::{Stability, State, classify};
use crate::format::load_text;

/// Default upper end of the load range searched, `p = 10` (twice the ideal
/// columns' divergence loads).
pub const DEFAULT_LOAD_MAX: f64 = 10.0;

/// The column's own load range searched by default, `[0, natural_load_max]`:
/// p to [`DEFAULT_LOAD_MAX`] for two rods, the same range of `P L^2/EI` for
/// a chain (see `Column::load_range_scale`).
#[must_use]
pub fn natural_load_max(model: &crate::model::Model) -> f64 {
    DEFAULT_LOAD_MAX * model.column.load_range_scale()
}

/// Samples of the locus that brackets the transitions before they are refined.
pub const BRACKET_SAMPLES: usize = 1000;

/// Transitions are located to this relative width of the load bracket.
const RELATIVE_LOAD_TOLERANCE: f64 = 1e-14;

/// A change of stability at a load.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Transition {
    /// The load p at which the state changes.
    pub load: f64,
    pub from: State,
    pub to: State,
}

impl std::fmt::Display for Transition {
    /// "p = 0.0238: stable -> flutter".
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "p = {}: {} -> {}",
            load_text(self.load),
            self.from.name(),
            self.to.name()
        )
    }
}

/// The classification at load p, on the Schur path.
fn stability_at(pencil: &AffinePencil, p: f64) -> Result<Stability, AnalysisError> {
    let spectrum = pencil.spectrum(p)?;
    Ok(classify(&spectrum.eigenvalues, spectrum.scale_per_s))
}

fn state_at(pencil: &AffinePencil, p: f64) -> Result<State, AnalysisError> {
    stability_at(pencil, p).map(|s| s.state)
}

/// Largest real part of the moving eigenvalues at p, with the tolerance there.
fn max_real_part(pencil: &AffinePencil, p: f64) -> Result<(f64, f64), AnalysisError> {
    stability_at(pencil, p).map(|s| (s.dominant.re, s.tolerance_per_s))
}

fn width_tolerance(a: f64, b: f64) -> f64 {
    width_at(RELATIVE_LOAD_TOLERANCE, a, b)
}

/// `relative` of the larger of the loads `a`, `b` (never zero).
fn width_at(relative: f64, a: f64, b: f64) -> f64 {
    relative * a.abs().max(b.abs()).max(f64::MIN_POSITIVE)
}

/// The polynomial path bisects to this relative width of the load bracket,
/// far wider than the band around a double root where rounding decides the
/// state (about 1e-13 here), so both paths read the bracket's ends alike.
const RELATIVE_FAST_WIDTH: f64 = 1e-9;

/// A load bracket with different states at its ends.
#[derive(Clone, Copy, Debug)]
struct Bracket {
    a: f64,
    sa: State,
    b: f64,
    sb: State,
}

/// Every transition in `[a, b]` whose ends have states `sa != sb`, as
/// brackets no wider than `relative_width` of the loads, by bisection on the
/// state that `state_at` reads. Exact at square-root branch points
/// (eigenvalues meeting on an axis), where the state flips with no
/// tolerance band.
fn bisect(
    state_at: &mut impl FnMut(f64) -> Result<State, AnalysisError>,
    (a, sa): (f64, State),
    (b, sb): (f64, State),
    relative_width: f64,
    out: &mut Vec<Bracket>,
) -> Result<(), AnalysisError> {
    if b - a <= width_at(relative_width, a, b) {
        out.push(Bracket { a, sa, b, sb });
        return Ok(());
    }
    let m = 0.5 * (a + b);
    let sm = state_at(m)?;
    if sm != sa {
        bisect(state_at, (a, sa), (m, sm), relative_width, out)?;
    }
    if sm != sb {
        bisect(state_at, (m, sm), (b, sb), relative_width, out)?;
    }
    Ok(())
}

/// Every transition in `[a, b]` (states `sa != sb` on the Schur path), as
/// brackets of [`RELATIVE_LOAD_TOLERANCE`]. The first halvings, down to
/// [`RELATIVE_FAST_WIDTH`], read the state on the polynomial path (Aberth
/// refined from the nearest load's roots, a few times cheaper than a Schur
/// decomposition); the Schur path confirms both ends of each narrowed
/// bracket and does the last halvings. Where the paths disagree the whole
/// bisection is done again on the Schur path, so the answer is always the
/// Schur path's.
fn bisect_confirmed(
    pencil: &AffinePencil,
    near_a: &[C64],
    (a, sa): (f64, State),
    (b, sb): (f64, State),
) -> Result<Vec<Bracket>, AnalysisError> {
    let mut roots = near_a.to_vec();
    let mut fast_state = |p: f64| -> Result<State, AnalysisError> {
        eigenvalues_near(pencil, p, &mut roots)?;
        Ok(classify(&roots, pencil.scale_per_s(p)).state)
    };
    let mut schur_state = |p: f64| state_at(pencil, p);
    let mut narrowed = Vec::new();
    bisect(
        &mut fast_state,
        (a, sa),
        (b, sb),
        RELATIVE_FAST_WIDTH,
        &mut narrowed,
    )?;
    let mut found = Vec::new();
    for bracket in narrowed {
        if schur_state(bracket.a)? != bracket.sa || schur_state(bracket.b)? != bracket.sb {
            found.clear();
            bisect(
                &mut schur_state,
                (a, sa),
                (b, sb),
                RELATIVE_LOAD_TOLERANCE,
                &mut found,
            )?;
            return Ok(found);
        }
        bisect(
            &mut schur_state,
            (bracket.a, bracket.sa),
            (bracket.b, bracket.sb),
            RELATIVE_LOAD_TOLERANCE,
            &mut found,
        )?;
    }
    Ok(found)
}

/// The root of `f` in `[a, b]` with `f(a) < 0 < f(b)` by Brent's method.
fn brent(
    mut f: impl FnMut(f64) -> Result<f64, AnalysisError>,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
) -> Result<f64, AnalysisError> {
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for _ in 0..200 {
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa) = (b, fb);
            (b, fb) = (c, fc);
            (c, fc) = (a, fa);
        }
        let tol = 0.5 * width_tolerance(b, c);
        let half = 0.5 * (c - b);
        if half.abs() <= tol || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * half * s, 1.0 - s)
            } else {
                let (q, r) = (fa / fc, fb / fc);
                (
                    s * (2.0 * half * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * half * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = half;
                e = d;
            }
        } else {
            d = half;
            e = d;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol { d } else { tol.copysign(half) };
        fb = f(b)?;
    }
    Ok(b)
}

/// Every transition between the bracket's ends ([`bisect_confirmed`]), each
/// loss (or gain) of stability polished by [`polish_crossing`]. `near_a`:
/// the moving eigenvalues at a load near `a`.
fn refine(
    pencil: &AffinePencil,
    near_a: &[C64],
    (a, sa): (f64, State),
    (b, sb): (f64, State),
    range: (f64, f64),
    out: &mut Vec<Transition>,
) -> Result<(), AnalysisError> {
    for bracket in bisect_confirmed(pencil, near_a, (a, sa), (b, sb))? {
        let mut transition = Transition {
            load: 0.5 * (bracket.a + bracket.b),
            from: bracket.sa,
            to: bracket.sb,
        };
        if let Some(root) = polish_crossing(pencil, &transition, range)? {
            transition.load = root;
        }
        out.push(transition);
    }
    Ok(())
}

/// Bisection on the state finds where the growth rate exceeds the
/// classification's tolerance. Where an eigenvalue crosses Re = 0
/// transversally (a damped column), that is off by tolerance / slope; the
/// root of the smooth, signed `max Re(lambda)` is then found by Brent's method
/// in the smallest bracket around the bisection's answer where it changes
/// sign. That bracket may reach beyond the locus samples that bracketed the
/// flip (for weak damping the offset is large), but not beyond the load
/// range. An undamped column never has a strictly damped side (its stable
/// eigenvalues sit on the axis); the bisection's answer is exact there
/// (square-root branch point) and is kept.
fn polish_crossing(
    pencil: &AffinePencil,
    transition: &Transition,
    (load_min, load_max): (f64, f64),
) -> Result<Option<f64>, AnalysisError> {
    let toward_unstable = match (transition.from, transition.to) {
        (State::Stable, State::Stable) => return Ok(None),
        (State::Stable, _) => 1.0,
        (_, State::Stable) => -1.0,
        _ => return Ok(None),
    };
    let growth = |p| max_real_part(pencil, p).map(|(re, _)| re);
    let p = transition.load;
    let unstable_p = (p + toward_unstable * width_tolerance(p, p)).clamp(load_min, load_max);
    let unstable_growth = growth(unstable_p)?;
    if unstable_growth <= 0.0 {
        return Ok(None);
    }
    let mut width = 2.0 * width_tolerance(p, p);
    loop {
        let stable_p = p - toward_unstable * width;
        if !(load_min..=load_max).contains(&stable_p) {
            return Ok(None);
        }
        let (stable_growth, tolerance) = max_real_part(pencil, stable_p)?;
        if stable_growth > 2.0 * tolerance {
            // Clearly unstable again (near the flip itself the growth equals
            // the tolerance up to rounding): not a lone crossing.
            return Ok(None);
        }
        // Strictly damped: the sign is the crossing's, not rounding's.
        if stable_growth < -tolerance {
            let (lo, hi) = if toward_unstable > 0.0 {
                ((stable_p, stable_growth), (unstable_p, unstable_growth))
            } else {
                ((unstable_p, -unstable_growth), (stable_p, -stable_growth))
            };
            let sign = toward_unstable;
            return brent(|q| growth(q).map(|g| sign * g), lo, hi).map(Some);
        }
        width *= 2.0;
    }
}

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

/// Samples of each decade of load in a wide range (see [`bracketing_locus`]).
const DECADE_SAMPLES: usize = 4000;

/// Beyond this many times the load that matches the column's stiffness, the
/// column's own stiffness changes the pencil by less than the
/// classification's tolerance (1e-10 of the frequency scale, see
/// [`RELATIVE_TOLERANCE`](super::RELATIVE_TOLERANCE)) and below rounding
/// 1e5 times further: the pencil changes in scale only.
const ROUNDED_AWAY: f64 = 1e12;

/// Samples of the range beyond [`ROUNDED_AWAY`].
const ROUNDED_AWAY_SAMPLES: usize = 100;

/// The largest load a range may reach, as for the load itself (`--set load`).
pub const LARGEST_LOAD: f64 = crate::model::LARGEST_DERIVED;

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
    if load_max > LARGEST_LOAD {
        return Err(AnalysisError::BadRange {
            what: "load-max",
            value: load_max,
            allowed: "must be at most 1e150, the largest load the analysis resolves",
        });
    }
    let natural = pencil.natural_load_max().max(load_min);
    if load_max <= 10.0 * natural {
        return evenly_bracketed_until(
            pencil,
            load_min,
            load_max,
            counting(0, BRACKET_SAMPLES - 1, progress),
        );
    }
    // The sections beyond the natural range, planned first to know the total.
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
    let mut whole =
        evenly_bracketed_until(pencil, load_min, natural, counting(0, total, progress))?;
    let mut done = BRACKET_SAMPLES - 1;
    for (start, end, samples) in sections {
        whole.extend_with(&locus_until(
            pencil,
            start,
            end,
            samples,
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
pub(super) fn first_loss_within(
    pencil: &AffinePencil,
    load_max: f64,
) -> Result<Option<Transition>, AnalysisError> {
    let mut seen_stable = false;
    let mut past = None;
    let bracket = evenly_bracketed_until(pencil, 0.0, load_max, |p, eigenvalues| {
        let stable = classify(eigenvalues, pencil.scale_per_s(p)).state == State::Stable;
        seen_stable |= stable;
        if seen_stable && !stable && past.is_none() {
            past = Some(0);
        }
        past = past.map(|n: usize| n + 1);
        past.is_some_and(|n| n > PAST_FIRST_LOSS)
    })?;
    Ok(transitions_along(pencil, &bracket, (0.0, load_max))?
        .into_iter()
        .find(|t| t.from == State::Stable))
}

/// The tracked locus of [`BRACKET_SAMPLES`] evenly spaced loads (fewer
/// when the range holds fewer distinct loads), ended where `stop` says (see
/// [`locus_until`]).
fn evenly_bracketed_until(
    pencil: &AffinePencil,
    load_min: f64,
    load_max: f64,
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
    locus_until(pencil, load_min, load_max, samples, stop)
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
    let tracked: Vec<State> = (0..locus.loads.len())
        .map(|i| {
            let scale = pencil.scale_per_s(locus.loads[i]);
            classify(&locus.moving_at(i), scale).state
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
    use crate::model::{Axis, Key, Model, PRESETS, PresetId};

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

    /// Bisects every change of stability that the bracketing locus of
    /// `model` shows both ways and returns how many there were.
    fn assert_fast_bisection_matches_schur(name: &str, model: &Model) -> usize {
        let pencil = AffinePencil::new(model).unwrap();
        let bracket_locus = bracketing_locus(&pencil, 0.0, DEFAULT_LOAD_MAX).unwrap();
        let states: Vec<State> = bracket_locus
            .loads
            .iter()
            .map(|&q| state_at(&pencil, q).unwrap())
            .collect();
        let mut checked = 0;
        for i in 1..states.len() {
            if states[i] == states[i - 1] {
                continue;
            }
            let (a, b) = (bracket_locus.loads[i - 1], bracket_locus.loads[i]);
            let ends = ((a, states[i - 1]), (b, states[i]));
            let fast =
                bisect_confirmed(&pencil, &bracket_locus.moving_at(i - 1), ends.0, ends.1).unwrap();
            let mut schur = Vec::new();
            let mut schur_state = |q| state_at(&pencil, q);
            bisect(
                &mut schur_state,
                ends.0,
                ends.1,
                RELATIVE_LOAD_TOLERANCE,
                &mut schur,
            )
            .unwrap();
            let loads = |v: &[Bracket]| v.iter().map(|b| (b.a, b.b)).collect::<Vec<_>>();
            assert_eq!(loads(&fast), loads(&schur), "{name} near p = {a}");
            checked += 1;
        }
        checked
    }

    /// The polynomial path only speeds the bisection up: at every change of
    /// stability of every two-rod preset (a chain has no polynomial path),
    /// of a damped column and of a light roller,
    /// the brackets are those of the bisection on the Schur path alone.
    #[test]
    fn the_fast_bisection_gives_the_schur_paths_brackets() {
        let mut checked = 0;
        let two_rods = PRESETS.iter().filter(|p| p.model().column.rods == 2);
        for p in two_rods.clone() {
            checked += assert_fast_bisection_matches_schur(p.name, &p.model());
        }
        assert!(checked >= 2 * two_rods.count(), "{checked} changes checked");
        let column = PresetId::Ziegler1952.model();
        let damped = Axis::DampingLevel.apply(&column, 1e-3).unwrap();
        assert!(assert_fast_bisection_matches_schur("damped", &damped) >= 2);
        let roller = PresetId::Roller.model();
        let light = Axis::Key(Key::Nu).apply(&roller, 0.01).unwrap();
        assert!(assert_fast_bisection_matches_schur("light roller", &light) >= 2);
    }
}
