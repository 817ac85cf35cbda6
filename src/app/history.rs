//! The recent past of the run: its observables over a sliding window, and
//! the eigenvalues measured from it (matrix pencil), to set beside the
//! predicted ones.

use std::collections::VecDeque;

use crate::analysis::C64;
use crate::sim::{Observables, identify};

/// How far back the history reaches, in simulated seconds.
pub const HISTORY_SECS: f64 = 60.0;
/// The measurement needs at least this much history...
const MIN_WINDOW_SECS: f64 = 20.0;
/// ... with angles this small, where the run is linear and comparable with
/// the linearization.
const LINEAR_AMPLITUDE_RAD: f64 = 0.05;
/// Samples the measurement uses (decimated from the steps).
const MEASURE_SAMPLES: usize = 400;

/// The observables over the last [`HISTORY_SECS`].
#[derive(Default)]
pub struct History {
    samples: VecDeque<Observables>,
    /// The measurement uses the samples from this time on: the parameters
    /// changed then, and older samples belong to another column.
    measure_from_secs: f64,
}

impl History {
    pub fn clear(&mut self) {
        self.samples.clear();
        self.measure_from_secs = 0.0;
    }

    /// Measures from `t_secs` on (the parameters changed then); the samples
    /// before stay for the plots.
    pub fn restart_measurement(&mut self, t_secs: f64) {
        self.measure_from_secs = t_secs;
    }

    pub fn push(&mut self, now: Observables) {
        let t_secs = now.t_secs;
        self.samples.push_back(now);
        while self
            .samples
            .front()
            .is_some_and(|o| t_secs - o.t_secs > HISTORY_SECS)
        {
            self.samples.pop_front();
        }
    }

    /// Every sample, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &Observables> {
        self.samples.iter()
    }

    /// At most `count` evenly picked samples, oldest first, for drawing.
    pub fn thinned(&self, count: usize) -> impl Iterator<Item = &Observables> {
        let every = self.samples.len().div_ceil(count.max(1)).max(1);
        self.samples.iter().step_by(every)
    }

    /// The eigenvalues of the column's modes measured from the history, when
    /// it is long enough and small enough to be linear; `order` counts the
    /// exponentials to fit (two per oscillating mode).
    #[must_use]
    pub fn measured(&self, order: usize) -> Option<Vec<C64>> {
        let window = self.window();
        let (first, last) = (window.first()?, window.last()?);
        if last.t_secs - first.t_secs < MIN_WINDOW_SECS {
            return None;
        }
        let amplitude = window
            .iter()
            .map(|o| o.phi1_rad.abs().max(o.phi2_rad.abs()))
            .fold(0.0, f64::max);
        if !(amplitude < LINEAR_AMPLITUDE_RAD && amplitude > 0.0) {
            return None;
        }
        fit(&window, order)
    }

    /// How uncertain each of `measured` (the fit over the whole window) is:
    /// the fits over the window's first and its last [`PART_OF_WINDOW`]
    /// each give the nearest eigenvalue, and the larger distance of the
    /// two, in the real and the imaginary part, is the uncertainty. `None`
    /// for an eigenvalue a part cannot fit (a swing slower than the part).
    #[must_use]
    pub fn uncertainty(&self, order: usize, measured: &[C64]) -> Vec<Option<C64>> {
        let window = self.window();
        let parts = window.first().zip(window.last()).map(|(first, last)| {
            let part_secs = PART_OF_WINDOW * (last.t_secs - first.t_secs);
            let early: Vec<&Observables> = window
                .iter()
                .copied()
                .filter(|o| o.t_secs <= first.t_secs + part_secs)
                .collect();
            let late: Vec<&Observables> = window
                .iter()
                .copied()
                .filter(|o| o.t_secs >= last.t_secs - part_secs)
                .collect();
            [fit(&early, order), fit(&late, order)]
        });
        measured
            .iter()
            .map(|&z| {
                let parts = parts.as_ref()?;
                let mut worst = C64::new(0.0, 0.0);
                for part in parts {
                    let nearest = part
                        .as_deref()?
                        .iter()
                        .map(|&w| C64::new(w.re, w.im.abs() * z.im.signum()))
                        .filter(|w| (w.im == 0.0) == (z.im == 0.0))
                        .min_by(|a, b| (a - z).norm().total_cmp(&(b - z).norm()))?;
                    worst.re = worst.re.max((nearest.re - z.re).abs());
                    worst.im = worst.im.max((nearest.im - z.im).abs());
                }
                Some(worst)
            })
            .collect()
    }

    /// The samples the measurement may use: those since the last change.
    fn window(&self) -> Vec<&Observables> {
        self.samples
            .iter()
            .filter(|o| o.t_secs >= self.measure_from_secs)
            .collect()
    }
}

/// The share of the window that each of the two fits of
/// [`History::uncertainty`] takes: the first and the last three quarters.
const PART_OF_WINDOW: f64 = 0.75;

/// The eigenvalues fitted to `window` (at most [`MEASURE_SAMPLES`] of it),
/// each oscillating one only if the window holds a whole period of it.
fn fit(window: &[&Observables], order: usize) -> Option<Vec<C64>> {
    let (first, last) = (window.first()?, window.last()?);
    let window_secs = last.t_secs - first.t_secs;
    let every = window.len().div_ceil(MEASURE_SAMPLES).max(1);
    let picked: Vec<&Observables> = window.iter().copied().step_by(every).collect();
    let dt_secs = picked.get(1)?.t_secs - picked.first()?.t_secs;
    let phi1: Vec<f64> = picked.iter().map(|o| o.phi1_rad).collect();
    let phi2: Vec<f64> = picked.iter().map(|o| o.phi2_rad).collect();
    // A swing slower than the window is not measured from it: less
    // than one period fits a made-up frequency and growth (the
    // 42 s mode of ziegler-1952 at p = 1 came out as +0.006 ± 0.171i
    // from 25 s).
    let measured: Vec<C64> = identify(&[&phi1, &phi2], dt_secs, order)?
        .into_iter()
        .filter(|z| z.im == 0.0 || std::f64::consts::TAU / z.im.abs() <= window_secs)
        .collect();
    (!measured.is_empty()).then_some(measured)
}
