//! The experiment's way to a bifurcation diagram: the load stepped up, then
//! down, each step going on from the state the last one ended in, and the
//! attractor's amplitude measured after a settling time. Where flutter sets
//! in with a jump, the two legs disagree (hysteresis).

use super::{EngineKind, SimError, Simulation, Status, initial_state};
use crate::analysis::Peaks;
use crate::model::{AsValid, Model};

/// The kick the sweep starts from, rad (every angle), as the app's.
pub const START_KICK_RAD: f64 = 1e-3;
/// A step that starts closer to rest than this (every angle, rad; every
/// rate, rad/s) starts from this kick instead: the small disturbance an
/// experiment always has, so that flutter has something to grow from and a
/// settled column never decays into subnormal numbers.
pub const FLOOR_KICK_RAD: f64 = 1e-6;

/// What one step of the sweep settled on.
#[derive(Clone, Debug, PartialEq)]
pub struct SweepStep {
    pub load: f64,
    /// On the way up (else down).
    pub upward: bool,
    /// The largest `|phi_i|` over the measuring window, per rod, rad
    /// (samples' peaks refined by parabolas).
    pub amplitude_rad: Vec<f64>,
    /// The mean time between upward zero crossings of the largest swinging
    /// angle over the window, if it crossed at least twice.
    pub period_secs: Option<f64>,
}

/// How long each step runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SweepTimes {
    /// Run before measuring, s.
    pub settle_secs: f64,
    /// The measuring window after it, s.
    pub measure_secs: f64,
    /// Observation step, s.
    pub step_secs: f64,
}

/// The sweep over `loads` (taken up in the order given, then back down) on
/// the reference engine, from the standard kick. `each` hears every finished
/// step (for progress). A run that leaves finite bounds ends the sweep: the
/// steps before it and the status are returned.
///
/// # Errors
/// An invalid model or times.
pub fn sweep(
    model: &Model,
    loads: &[f64],
    times: SweepTimes,
    mut each: impl FnMut(&SweepStep),
) -> Result<(Vec<SweepStep>, Status), SimError> {
    let Some(&first) = loads.first() else {
        return Ok((Vec::new(), Status::Running));
    };
    let start = model.at_load(first).into_valid()?;
    let x0 = initial_state(&start, START_KICK_RAD);
    let mut sim = Simulation::new(start, EngineKind::Reference, x0, times.step_secs)?;
    let up = loads.iter().map(|&p| (p, true));
    let down = loads.iter().rev().skip(1).map(|&p| (p, false));
    let mut steps = Vec::new();
    for (load, upward) in up.chain(down) {
        let at = model.at_load(load);
        sim.set_model(at)?;
        let x = sim.state();
        let rest = crate::model::StateView::new(&x);
        let quiet = |v: &[f64]| v.iter().all(|v| v.abs() < FLOOR_KICK_RAD);
        if quiet(rest.angles_rad()) && quiet(rest.rates_rad_per_s()) {
            sim.restart_from(EngineKind::Reference, initial_state(&at, FLOOR_KICK_RAD))?;
        }
        if sim.run(times.settle_secs, |_| ()) != Status::Running {
            return Ok((steps, sim.status()));
        }
        let start = sim.observe();
        let mut peaks = Peaks::new(&start.angles_rad, &start.rates_rad_per_s);
        let mut trace = vec![(start.t_secs, start.angles_rad)];
        let mut last_secs = start.t_secs;
        let status = sim.run(times.measure_secs, |o| {
            peaks.push(&o.angles_rad, &o.rates_rad_per_s, o.t_secs - last_secs);
            last_secs = o.t_secs;
            trace.push((o.t_secs, o.angles_rad.clone()));
        });
        let amplitude_rad = peaks.largest().to_vec();
        if status != Status::Running {
            return Ok((steps, status));
        }
        let step = SweepStep {
            load,
            upward,
            period_secs: period_of(&trace, &amplitude_rad),
            amplitude_rad,
        };
        each(&step);
        steps.push(step);
    }
    Ok((steps, sim.status()))
}

/// The mean interval between upward zero crossings (linearly interpolated)
/// of the angle with the largest amplitude, if there are two or more.
fn period_of(trace: &[(f64, Vec<f64>)], amplitude_rad: &[f64]) -> Option<f64> {
    let index = amplitude_rad
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map(|(i, _)| i)?;
    let crossings: Vec<f64> = trace
        .windows(2)
        .filter_map(|w| {
            let ((t0, a0), (t1, a1)) = ((w[0].0, w[0].1[index]), (w[1].0, w[1].1[index]));
            (a0 < 0.0 && a1 >= 0.0).then(|| t0 + (t1 - t0) * (-a0) / (a1 - a0))
        })
        .collect();
    let (first, last) = (crossings.first()?, crossings.last()?);
    #[expect(clippy::cast_precision_loss, reason = "a count of crossings")]
    let intervals = (crossings.len() - 1) as f64;
    (crossings.len() >= 2).then(|| (last - first) / intervals)
}
