//! Pseudo-arclength continuation of a branch of limit cycles from two of
//! its cycles (see `cycles`, whose module notes give the equations): the
//! step along the secant in scaled unknowns, Broyden's method from the
//! last cycle's monodromy, shorter steps where a solve fails or the branch
//! turns sharply, and the reasons a branch ends; and what is read off a
//! followed path: its runs of equal stability and its cycles at a load.
//! Shared by the branches born at Hopf points and those born where the
//! mirror symmetry breaks (`offshoot`). Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{DMatrix, DVector};

use super::cycle::Cycle;
use super::cycle_bifurcations::CycleBifurcation;
use super::shooting::{Constraint, Shooting, Update};
use crate::format::load_text;

/// Why a branch's continuation stopped.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum BranchEnd {
    /// The branch left the load range asked for.
    LeftRange,
    /// An angle's amplitude passed [`MAX_AMPLITUDE_RAD`].
    LargeAmplitude,
    /// The period grew past [`MAX_PERIOD_GROWTH`] times the Hopf period.
    LongPeriod,
    /// Newton's method failed even at the smallest step, at this load.
    Lost { load: f64 },
    /// The roller's contact came within [`STICK_FRACTION`] of the band
    /// speed of sticking on the next cycle, past this load: the dry
    /// friction turns non-smooth there (stick-slip), which shooting on
    /// smooth equations does not follow.
    StickSlip { load: f64 },
    /// The next cycle's trivial multiplier was further than
    /// [`TRIVIAL_TOLERANCE`] from 1, past this load: not resolved.
    Unresolved { load: f64 },
    /// [`MAX_POINTS`] cycles were computed.
    PointLimit,
    /// The caller asked to stop.
    Cancelled,
}

impl std::fmt::Display for BranchEnd {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::LeftRange => write!(f, "left the load range"),
            Self::LargeAmplitude => write!(
                f,
                "an angle's amplitude passed {MAX_AMPLITUDE_RAD} rad (the column swings round)"
            ),
            Self::LongPeriod => write!(
                f,
                "the period grew past {MAX_PERIOD_GROWTH} times the onset's"
            ),
            Self::Lost { load } => write!(
                f,
                "the shooting did not converge past p = {}",
                load_text(*load)
            ),
            Self::StickSlip { load } => write!(
                f,
                "the roller's contact nears sticking on the band past p = {} (stick-slip: the friction is not smooth there)",
                load_text(*load)
            ),
            Self::Unresolved { load } => write!(
                f,
                "the cycles past p = {} are not resolved (trivial multiplier off 1 by more than {TRIVIAL_TOLERANCE:e})",
                load_text(*load)
            ),
            Self::PointLimit => write!(f, "{MAX_POINTS} cycles computed"),
            Self::Cancelled => write!(f, "stopped on request"),
        }
    }
}

/// A branch stops where an angle's amplitude passes this (rad): the column
/// swings round and the cycle is no longer a flutter of the straight column.
pub const MAX_AMPLITUDE_RAD: f64 = 3.0;
/// A branch stops where its period grows past this many times the onset's
/// (a cycle approaching a homoclinic orbit).
pub const MAX_PERIOD_GROWTH: f64 = 20.0;
/// Most cycles on one branch.
pub const MAX_POINTS: usize = 400;
/// A roller's branch stops before a cycle whose slip speed falls below
/// this fraction of the band speed (see [`BranchEnd::StickSlip`]).
pub const STICK_FRACTION: f64 = 0.1;
/// The cycle that ends a roller's branch has a slip speed between this
/// fraction of [`STICK_FRACTION`] of the band speed and that bound.
const STICK_END_FRACTION: f64 = 0.9;
/// A cycle is resolved when its trivial multiplier is within this of 1.
pub const TRIVIAL_TOLERANCE: f64 = 1e-6;

/// A continuation step that converged in at most this many iterations
/// makes the next one longer.
const GROW_ITERATIONS: usize = 8;
/// The cosine of the largest turn between a step of the continuation and
/// the last one (in the scaled unknowns) that is kept: 25 degrees.
const MAX_TURN_COS: f64 = 0.9;

/// Where a branch whose last cycle is `cycles`' last stops for a reason
/// of its own (not the shooting's): it left `[load_min, load_max]`, grew
/// too large or too slow, has too many cycles, or the caller asked.
fn stop_reason(
    cycles: &[Cycle],
    (load_min, load_max): (f64, f64),
    hopf_period: f64,
    cancel: &AtomicBool,
) -> Option<BranchEnd> {
    let last = cycles.last()?;
    if !(load_min..=load_max).contains(&last.load) {
        Some(BranchEnd::LeftRange)
    } else if last.largest_amplitude_rad() > MAX_AMPLITUDE_RAD {
        Some(BranchEnd::LargeAmplitude)
    } else if last.period_secs > MAX_PERIOD_GROWTH * hopf_period {
        Some(BranchEnd::LongPeriod)
    } else if cycles.len() >= MAX_POINTS {
        Some(BranchEnd::PointLimit)
    } else if cancel.load(Ordering::Relaxed) {
        Some(BranchEnd::Cancelled)
    } else {
        None
    }
}

/// Where a branch's continuation goes: its column, the scales its
/// steps are measured in (the state as it is, the period in Hopf periods,
/// the load in Hopf loads: see `cycles`), the load range it stays in, the
/// Hopf period its period is measured against, and the caller's `cancel`.
pub(super) struct Course<'a> {
    pub(super) shooting: &'a Shooting,
    pub(super) scales: DVector<f64>,
    pub(super) range: (f64, f64),
    pub(super) hopf_period: f64,
    pub(super) cancel: &'a AtomicBool,
}

/// The branch through `cycles` (at least two, in the order of the
/// continuation; `monodromy` the last one's) followed by pseudo-arclength
/// continuation along `course`, and why it ended; `None` with fewer than
/// two cycles.
pub(super) fn follow(
    course: &Course,
    mut cycles: Vec<Cycle>,
    mut monodromy: DMatrix<f64>,
) -> Option<(Vec<Cycle>, BranchEnd)> {
    let Course {
        shooting, scales, ..
    } = course;
    let (load_min, load_max) = course.range;
    let load_step_most = (load_max - load_min) / 40.0;
    let scaled = |u: &DVector<f64>| u.component_div(scales);
    let mut distance = {
        let [.., a, b] = cycles.as_slice() else {
            return None;
        };
        scaled(&(b.unknowns() - a.unknowns())).norm()
    };
    let end = loop {
        let [.., before, last] = cycles.as_slice() else {
            return None;
        };
        if let Some(end) = stop_reason(&cycles, course.range, course.hopf_period, course.cancel) {
            break end;
        }
        // The step along the secant, in the scaled unknowns; the arclength
        // equation `direction . (u - predicted) / scales = 0`.
        let (u, previous) = (last.unknowns(), before.unknowns());
        let secant = scaled(&(&u - &previous));
        let direction = &secant / secant.norm();
        let load_rate = (direction[direction.len() - 1] * scales[scales.len() - 1]).abs();
        if load_rate * distance > load_step_most {
            distance = load_step_most / load_rate;
        }
        let predicted = &u + direction.component_mul(scales) * distance;
        let tangent = direction.component_div(scales);
        let constraint = Constraint::Arclength {
            tangent: &tangent,
            predicted: &predicted,
        };
        // Broyden's method from the last cycle's monodromy; where it fails,
        // a shorter step, and at the shortest the whole of `solve`.
        let shortest = distance <= 1e-6 * scaled(&u).norm().max(1.0);
        let solved =
            match shooting.newton(&predicted, &constraint, Update::Broyden(Some(&monodromy))) {
                None if !shortest => {
                    distance /= 3.0;
                    continue;
                }
                None => shooting.solve(&predicted, &constraint),
                solved => solved,
            };
        match solved {
            // A step far past the stick-slip bound is taken again shorter,
            // so that the branch ends next to the bound whatever the step.
            Some(solved)
                if !shortest
                    && shooting
                        .near_sticking(&solved.cycle, STICK_END_FRACTION * STICK_FRACTION) =>
            {
                distance /= 3.0;
            }
            Some(solved) if shooting.near_sticking(&solved.cycle, STICK_FRACTION) => {
                break BranchEnd::StickSlip { load: last.load };
            }
            // A step that turns the branch sharply may have jumped to
            // another part of it (or back along it): taken again shorter.
            Some(solved)
                if !shortest && {
                    let next = scaled(&(solved.cycle.unknowns() - &u));
                    next.dot(&direction) < MAX_TURN_COS * next.norm()
                } =>
            {
                distance /= 3.0;
            }
            Some(solved)
                if (solved.cycle.trivial_multiplier() - 1.0).norm() > TRIVIAL_TOLERANCE =>
            {
                break BranchEnd::Unresolved { load: last.load };
            }
            Some(solved) => {
                cycles.push(solved.cycle);
                monodromy = solved.monodromy;
                if solved.iterations <= GROW_ITERATIONS {
                    distance *= 1.5;
                }
            }
            None => break BranchEnd::Lost { load: last.load },
        }
    };
    Some((cycles, end))
}

/// The runs of equal stability of the path `cycles` (with its
/// `bifurcations`) from `start` (see [`Branch::runs`](super::cycles::Branch::runs)).
pub(super) fn runs_from(
    start: [f64; 2],
    cycles: &[Cycle],
    bifurcations: &[CycleBifurcation],
) -> Vec<(Vec<[f64; 2]>, bool)> {
    let mut runs: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
    let mut last = start;
    for (i, cycle) in cycles.iter().enumerate() {
        let point = [cycle.load, cycle.largest_amplitude_rad()];
        match runs.last_mut() {
            Some(run) if run.1 == cycle.stable => run.0.push(point),
            before => {
                let between = bifurcations
                    .iter()
                    .find(|b| b.after + 1 == i)
                    .map(|b| [b.load, b.amplitude_rad]);
                let start = match (between, before) {
                    (Some(at), Some(run)) => {
                        run.0.push(at);
                        at
                    }
                    _ => last,
                };
                runs.push((vec![start, point], cycle.stable));
            }
        }
        last = point;
    }
    runs
}

/// Which way the path `cycles` opens at its bifurcation `at` (see
/// [`Branch::opening`](super::cycles::Branch::opening)).
pub(super) fn opening_at(cycles: &[Cycle], at: &CycleBifurcation) -> f64 {
    let sides = (cycles.get(at.after), cycles.get(at.after + 1));
    match sides {
        (Some(a), Some(b)) if a.load > at.load && b.load > at.load => 1.0,
        (Some(a), Some(b)) if a.load < at.load && b.load < at.load => -1.0,
        _ => 0.0,
    }
}

/// The cycles of the path `cycles` of `shooting`'s column at load `p`: one
/// where each of its segments crosses `p`, each solved at exactly `p`.
pub(super) fn cycles_along(shooting: &Shooting, cycles: &[Cycle], p: f64) -> Vec<Cycle> {
    cycles
        .windows(2)
        .filter_map(|pair| {
            let (a, b) = (&pair[0], &pair[1]);
            let (lo, hi) = (a.load.min(b.load), a.load.max(b.load));
            if !(lo..hi).contains(&p) {
                return None;
            }
            let t = if b.load == a.load {
                0.0
            } else {
                (p - a.load) / (b.load - a.load)
            };
            let guess = a.unknowns() * (1.0 - t) + b.unknowns() * t;
            shooting
                .solve(&guess, &Constraint::Load(p))
                .map(|solved| solved.cycle)
        })
        .collect()
}
