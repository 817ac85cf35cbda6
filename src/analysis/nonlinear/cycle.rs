//! A limit cycle as the continuation finds it: its load, period, start,
//! amplitudes and Floquet multipliers. A leaf below both the shooting that
//! computes one and the continuation that follows a branch of them.

use nalgebra::DVector;

use crate::analysis::C64;
use crate::analysis::field::Field;
use crate::model::{Model, StateVec};

/// A multiplier is real when its imaginary part is at most this share of
/// its modulus.
pub(super) const REAL: f64 = 1e-8;

/// The smallest load the load's step is measured against.
pub(in crate::analysis) const LOAD_SCALE_FLOOR: f64 = 1e-3;

/// One periodic orbit.
#[derive(Clone, Debug, PartialEq)]
pub struct Cycle {
    /// The load p.
    pub load: f64,
    pub period_secs: f64,
    /// A point of the orbit, on the reduced state.
    pub start: DVector<f64>,
    /// The largest `|phi_i|` over the cycle, for each rod, in rad.
    pub amplitude_rad: Vec<f64>,
    /// The Floquet multipliers, largest modulus first.
    pub multipliers: Vec<C64>,
    /// Every multiplier but the trivial one inside the unit circle.
    pub stable: bool,
    /// The roller's smallest slip speed on the band over the cycle, m/s
    /// (none without a roller).
    pub closest_slip_m_per_s: Option<f64>,
}

impl Cycle {
    /// The multiplier nearest 1 (the shift along the orbit): 1 to the
    /// accuracy of the monodromy.
    #[must_use]
    pub fn trivial_multiplier(&self) -> C64 {
        trivial_index(&self.multipliers).map_or(C64::new(f64::NAN, 0.0), |i| self.multipliers[i])
    }

    /// The multipliers but the trivial one.
    pub(in crate::analysis) fn nontrivial_multipliers(&self) -> impl Iterator<Item = C64> + '_ {
        let trivial = trivial_index(&self.multipliers);
        self.multipliers
            .iter()
            .enumerate()
            .filter(move |(i, _)| Some(*i) != trivial)
            .map(|(_, m)| *m)
    }

    /// The cycle's start as a full state of `model` (the spin angle zero;
    /// a massless roller's spin rate, which follows the rods, too).
    #[must_use]
    pub fn start_state(&self, model: &Model) -> StateVec {
        Field::new(model).full_state(&self.start)
    }

    /// The largest amplitude of any rod's angle, rad.
    #[must_use]
    pub fn largest_amplitude_rad(&self) -> f64 {
        self.amplitude_rad.iter().copied().fold(0.0, f64::max)
    }

    pub(super) fn unknowns(&self) -> DVector<f64> {
        let d = self.start.len();
        DVector::from_fn(d + 2, |i, _| match i {
            i if i < d => self.start[i],
            i if i == d => self.period_secs,
            _ => self.load,
        })
    }
}

/// Where the multiplier nearest 1 (the shift along the orbit) stands.
pub(in crate::analysis) fn trivial_index(multipliers: &[C64]) -> Option<usize> {
    multipliers
        .iter()
        .enumerate()
        .min_by(|a, b| (a.1 - 1.0).norm().total_cmp(&(b.1 - 1.0).norm()))
        .map(|(i, _)| i)
}
