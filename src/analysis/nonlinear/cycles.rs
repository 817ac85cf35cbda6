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
use crate::model::Model;

pub use super::continuation::{
    BranchEnd, MAX_AMPLITUDE_RAD, MAX_PERIOD_GROWTH, MAX_POINTS, STICK_FRACTION, TRIVIAL_TOLERANCE,
};
use super::continuation::{Course, cycles_along, follow, opening_at, runs_from};
pub use super::cycle::Cycle;
use super::cycle::LOAD_SCALE_FLOOR;
use super::cycle_bifurcations::{CycleBifurcation, cycle_bifurcations};
pub use super::offshoot::Offshoot;
use super::offshoot::offshoot;
use super::shooting::Shooting;

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
    /// The asymmetric cycles born at each break of the mirror symmetry
    /// solved for on the branch.
    pub offshoots: Vec<Offshoot>,
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
        runs_from([self.hopf().load, 0.0], &self.cycles, &self.bifurcations)
    }

    /// Every cycle of the branch, then those of the asymmetric branches
    /// born on it.
    pub fn every_cycle(&self) -> impl Iterator<Item = &Cycle> {
        let offshoots = self.offshoots.iter().flat_map(|o| o.cycles.iter());
        self.cycles.iter().chain(offshoots)
    }

    /// Which way the branch opens at its bifurcation `at`: 1 at a fold
    /// where its cycles on both sides have higher loads (the least load
    /// along it), -1 at one where they have lower, 0 elsewhere.
    #[must_use]
    pub fn opening(&self, at: &CycleBifurcation) -> f64 {
        opening_at(&self.cycles, at)
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

/// The branch of cycles born at the Hopf point `point` of `model`,
/// continued while its loads stay within `[load_min, load_max]`.
fn branch(
    model: &Model,
    point: &HopfPoint,
    name: String,
    range: (f64, f64),
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
    let course = Course {
        shooting: &shooting,
        scales: unknown_scales(point, shooting.field.dimension()),
        range,
        hopf_period: std::f64::consts::TAU / point.hopf.frequency_rad_per_s,
        cancel,
    };
    let (cycles, end) = follow(&course, cycles, monodromy)?;
    let (bifurcations, breaks) = cycle_bifurcations(&shooting, &cycles, &course.scales, cancel);
    let offshoots = breaks
        .iter()
        .enumerate()
        .filter_map(|(k, at)| {
            let born = bifurcations[at.index];
            let name = match k {
                0 => format!("{name}-asymmetric"),
                k => format!("{name}-asymmetric-{}", k + 1),
            };
            offshoot(&course, name, born, &at.unknowns)
        })
        .collect();
    Some(Branch {
        onset: point.clone(),
        name,
        cycles,
        bifurcations,
        end,
        offshoots,
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
    near_onset
        .into_iter()
        .chain(cycles_along(&shooting, &branch.cycles, p))
        .collect()
}
