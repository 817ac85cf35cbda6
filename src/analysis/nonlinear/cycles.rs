//! Limit cycles past a flutter onset: periodic orbits of the nonlinear
//! equations found by shooting, continued in the load from each Hopf point,
//! with their period, the amplitude of every angle and their Floquet
//! multipliers (stability).
//!
//! A cycle is a start `x0` on the reduced state (see `field`) and a period
//! `T` with `phi_T(x0) = x0`, `phi_T` the flow of the equations of motion.
//! The flow and its Jacobian (the monodromy matrix) are integrated together
//! by the two-stage Gauss-Legendre method at a fixed number of steps per
//! period (`gauss`: implicit and A-stable, so a chain's fast modes do not
//! set the step), the monodromy as the exact derivative of the computed
//! flow for the multipliers. Newton solves
//!
//! ```text
//! phi_T(x0; p) - x0 = 0                (d equations)
//! f(x_ref) . (x0 - x_ref) = 0          (phase: x0 on the plane through the
//!                                       last cycle, across its flow)
//! p = p_target  or  t . (u - u_pred) = 0   (fixed load, or pseudo-arclength)
//! ```
//!
//! for `u = (x0, T, p)`, by Broyden's method: Newton's matrix once (from
//! the last cycle's monodromy along a branch, else from a flow with each
//! step's Jacobian held over its stages), then rank-one corrections from
//! each iteration's change of the residual, so that a later iteration is
//! one flow without the monodromy; where that fails, by Newton's method
//! proper. A branch starts at the normal form's cycle near its
//! Hopf point (`hopf`) and is followed by pseudo-arclength continuation
//! (distances in unknowns scaled by the Hopf period and load), which passes
//! folds (a hard onset's unstable cycle turning into the large
//! stable one). The multipliers are the monodromy's eigenvalues: one is 1
//! (the shift along the orbit); the cycle is stable when every other one
//! lies inside the unit circle. Pure: no UI, no clock.

use std::sync::atomic::{AtomicBool, Ordering};

use nalgebra::{DMatrix, DVector};

use crate::analysis::hopf::{HopfPoint, Steps as HopfSteps, hopf_point};
use crate::analysis::{AffinePencil, AnalysisError, Hopf, HopfKind, critical_loads, is_hopf};
use crate::format::load_text;
use crate::model::Model;

pub use super::cycle::Cycle;
use super::cycle::LOAD_SCALE_FLOOR;
use super::cycle_bifurcations::{CycleBifurcation, cycle_bifurcations};
use super::shooting::{Constraint, Shooting, Update};

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

/// The cycles born at one Hopf point.
#[derive(Clone, Debug)]
pub struct Branch {
    onset: HopfPoint,
    /// `cycle-1`, `cycle-2`, ... in the order of the onsets' loads.
    name: String,
    /// In the order of the continuation, starting next to the Hopf point.
    pub cycles: Vec<Cycle>,
    /// The cycles' own bifurcations, in the order of the continuation.
    pub bifurcations: Vec<CycleBifurcation>,
    pub end: BranchEnd,
}

impl Branch {
    /// The Hopf point the branch is born at.
    #[must_use]
    pub fn hopf(&self) -> &Hopf {
        &self.onset.hopf
    }

    /// The branch as runs of equal stability, each a polyline of
    /// `[load, largest angle's amplitude]` from the Hopf point on (each run
    /// starts where the one before ended, so the curve is unbroken). Where
    /// the stability changes at a bifurcation of the cycles, the runs meet
    /// there (on the curve between the two cycles it lies between), else
    /// at the last cycle before the change.
    #[must_use]
    pub fn runs(&self) -> Vec<(Vec<[f64; 2]>, bool)> {
        let mut runs: Vec<(Vec<[f64; 2]>, bool)> = Vec::new();
        let mut last = [self.hopf().load, 0.0];
        for (i, cycle) in self.cycles.iter().enumerate() {
            let point = [cycle.load, cycle.largest_amplitude_rad()];
            match runs.last_mut() {
                Some(run) if run.1 == cycle.stable => run.0.push(point),
                before => {
                    let between = self
                        .bifurcations
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

    /// Which way the branch opens at its bifurcation `at`: 1 at a fold
    /// where its cycles on both sides have higher loads (the least load
    /// along it), -1 at one where they have lower, 0 elsewhere.
    #[must_use]
    pub fn opening(&self, at: &CycleBifurcation) -> f64 {
        let sides = (self.cycles.get(at.after), self.cycles.get(at.after + 1));
        match sides {
            (Some(a), Some(b)) if a.load > at.load && b.load > at.load => 1.0,
            (Some(a), Some(b)) if a.load < at.load && b.load < at.load => -1.0,
            _ => 0.0,
        }
    }

    /// "soft" or "hard": how flutter sets in at the branch's onset.
    #[must_use]
    pub fn onset_word(&self) -> &'static str {
        if self.soft() { "soft" } else { "hard" }
    }

    /// Whether the onset is soft (a negative first Lyapunov coefficient:
    /// the cycles grow from zero), not hard.
    #[must_use]
    pub fn soft(&self) -> bool {
        self.hopf().first_lyapunov < 0.0
    }

    /// The branch's name in tables: `cycle-1`, `cycle-2`, ... in the
    /// order of the onsets.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
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
/// The first cycles' amplitudes, rad: small enough for the normal form to be
/// a good first guess, large enough for a well conditioned shooting.
const START_AMPLITUDES_RAD: [f64; 3] = [0.003, 0.006, 0.012];

/// The size of each unknown `u = (x0, T, p)` that the continuation
/// measures its steps in: the state as it is (rad, rad/s), the period in
/// Hopf periods and the load in Hopf loads (at least [`LOAD_SCALE_FLOOR`]).
/// In plain units a long chain's cycle near the onset (angles of 0.01 rad,
/// a period of 1000 s) weighs a change of its period by a second as much as
/// a change of its angles by a radian: the arclength equation all but
/// repeated the others (Newton's matrix had a singular value of 2e-7
/// against 51 at 16 rods), and the branch was lost there.
fn unknown_scales(point: &HopfPoint, d: usize) -> DVector<f64> {
    let hopf = &point.hopf;
    DVector::from_fn(d + 2, |i, _| match i {
        i if i < d => 1.0,
        i if i == d => std::f64::consts::TAU / hopf.frequency_rad_per_s,
        _ => hopf.load.abs().max(LOAD_SCALE_FLOOR),
    })
}

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

/// The branch of cycles born at the Hopf point `point` of `model`,
/// continued while its loads stay within `[load_min, load_max]`.
fn branch(
    model: &Model,
    point: &HopfPoint,
    name: String,
    (load_min, load_max): (f64, f64),
    cancel: &AtomicBool,
) -> Option<Branch> {
    let shooting = Shooting::of(&model.at_load(point.hopf.load));
    let mut cycles = Vec::new();
    let mut monodromy = DMatrix::zeros(0, 0);
    for amplitude in START_AMPLITUDES_RAD {
        let solved = shooting.near_onset(point, amplitude)?;
        cycles.push(solved.cycle);
        monodromy = solved.monodromy;
    }
    let load_step_most = (load_max - load_min) / 40.0;
    let hopf_period = std::f64::consts::TAU / point.hopf.frequency_rad_per_s;
    let scales = unknown_scales(point, shooting.field.dimension());
    let scaled = |u: &DVector<f64>| u.component_div(&scales);
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
        if let Some(end) = stop_reason(&cycles, (load_min, load_max), hopf_period, cancel) {
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
        let predicted = &u + direction.component_mul(&scales) * distance;
        let tangent = direction.component_div(&scales);
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
    let bifurcations = cycle_bifurcations(&shooting, &cycles, &scales, cancel);
    Some(Branch {
        onset: point.clone(),
        name,
        cycles,
        bifurcations,
        end,
    })
}

/// Why no cycles were computed at a flutter onset (in words, as the
/// command line and the window say it after "flutter onset at p = ...: ").
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NoBranch {
    /// The column is undamped (see [`crate::analysis::NoHopf`]).
    #[error("no damping, a reversible column: no limit cycle to follow")]
    Reversible,
    /// The first Lyapunov coefficient is zero within its accuracy.
    #[error("the first Lyapunov coefficient is zero within its accuracy; cycles not followed")]
    Degenerate,
    /// The shooting did not converge next to the onset.
    #[error("the shooting did not converge next to the onset; no cycles")]
    NotConverged,
}

/// A flutter onset or end and the cycles born there.
#[derive(Clone, Debug)]
pub struct Onset {
    pub load: f64,
    pub branch: Result<Branch, NoBranch>,
}

/// The cycles born at every flutter onset or end of `model` with a load in
/// `[load_min, load_max]`, each followed while its loads stay in that range.
/// Setting `cancel` ends the work early (the branches so far end
/// [`BranchEnd::Cancelled`]).
///
/// # Errors
/// A model that cannot be analysed.
pub fn cycle_branches(
    model: &Model,
    load_min: f64,
    load_max: f64,
    cancel: &AtomicBool,
) -> Result<Vec<Onset>, AnalysisError> {
    let pencil = AffinePencil::new(model)?;
    let mut branches = Vec::new();
    for t in critical_loads(&pencil, load_min, load_max)? {
        if !is_hopf(t.from, t.to) || cancel.load(Ordering::Relaxed) {
            continue;
        }
        let found = match hopf_point(model, t.load, HopfSteps::DEFAULT.into())? {
            Err(_) => Err(NoBranch::Reversible),
            Ok(point) if point.hopf.kind == HopfKind::Degenerate => Err(NoBranch::Degenerate),
            Ok(point) => {
                let name = format!("cycle-{}", branches.len() + 1);
                branch(model, &point, name, (load_min, load_max), cancel)
                    .ok_or(NoBranch::NotConverged)
            }
        };
        branches.push(Onset {
            load: t.load,
            branch: found,
        });
    }
    Ok(branches)
}

/// The cycles of `branch` at load `p`: one where each of its segments
/// crosses `p` (two where it folds back), each solved at exactly `p`;
/// between the Hopf point and the first computed cycle, from the normal
/// form's.
#[must_use]
pub fn cycles_at(model: &Model, branch: &Branch, p: f64) -> Vec<Cycle> {
    let shooting = Shooting::of(&model.at_load(branch.hopf().load));
    let onset = branch.hopf().load;
    let near = branch.cycles.first().filter(|first| {
        let (lo, hi) = (onset.min(first.load), onset.max(first.load));
        lo < p && p < hi
    });
    let near_onset = near
        .and_then(|_| shooting.normal_form_cycle(&branch.onset, p))
        .map(|solved| solved.cycle);
    let along = branch.cycles.windows(2).filter_map(|pair| {
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
    });
    near_onset.into_iter().chain(along).collect()
}
