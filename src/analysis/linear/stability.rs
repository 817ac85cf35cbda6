//! What to call a spectrum: stable, flutter or divergence (physics.md section 6),
//! with the growth rate and frequency of the most unstable mode.

use serde::Serialize;

use crate::analysis::C64;

/// Tolerance on real and imaginary parts, relative to the spectrum's frequency
/// scale: well above rounding (about 1e-15 of the scale after balancing),
/// well below the roller's weak flutter (growth rates of order 1e-3 of the scale).
pub const RELATIVE_TOLERANCE: f64 = 1e-10;

/// The stability of the straight column.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum State {
    /// Every eigenvalue has `Re <= tolerance`.
    Stable,
    /// The most unstable eigenvalue is one of a complex pair.
    Flutter,
    /// The most unstable eigenvalue is real.
    Divergence,
}

impl State {
    /// The lowercase name used in the CLI's output.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Stable => "stable",
            Self::Flutter => "flutter",
            Self::Divergence => "divergence",
        }
    }
}

/// The classification of one spectrum.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stability {
    pub state: State,
    /// The eigenvalue with the largest real part (the most unstable mode, or
    /// the least damped one when stable).
    pub dominant: C64,
    /// The absolute tolerance used, in 1/s.
    pub tolerance_per_s: f64,
}

impl Stability {
    /// Growth rate of the dominant mode, `Re(lambda)` in 1/s (negative: decay).
    #[must_use]
    pub fn growth_rate_per_s(&self) -> f64 {
        self.dominant.re
    }

    /// Angular frequency of the dominant mode, `|Im(lambda)|` in rad/s.
    #[must_use]
    pub fn frequency_rad_per_s(&self) -> f64 {
        self.dominant.im.abs()
    }

    /// Time for the dominant mode to grow by e, when it grows.
    #[must_use]
    pub fn e_folding_secs(&self) -> Option<f64> {
        (self.state != State::Stable).then(|| 1.0 / self.dominant.re)
    }
}

/// Classifies the moving eigenvalues (structural zeros excluded) with the
/// tolerance [`RELATIVE_TOLERANCE`] times `scale_per_s`. Flutter or divergence
/// is named after the most unstable eigenvalue.
#[must_use]
pub fn classify(eigenvalues: &[C64], scale_per_s: f64) -> Stability {
    classify_with(eigenvalues, scale_per_s, RELATIVE_TOLERANCE)
}

/// [`classify`] with another relative tolerance (the resolution check
/// compares two).
#[must_use]
pub fn classify_with(eigenvalues: &[C64], scale_per_s: f64, relative_tolerance: f64) -> Stability {
    let tolerance_per_s = relative_tolerance * scale_per_s;
    let dominant = eigenvalues
        .iter()
        .copied()
        .max_by(|a, b| a.re.total_cmp(&b.re))
        .unwrap_or_default();
    let state = if dominant.re <= tolerance_per_s {
        State::Stable
    } else if dominant.im.abs() > tolerance_per_s {
        State::Flutter
    } else {
        State::Divergence
    };
    Stability {
        state,
        dominant,
        tolerance_per_s,
    }
}

/// Beyond this ratio of the fastest to the slowest mode, rounding of the
/// fast one (about 1e-16 of it) reaches the slow ones' growth rates.
pub const LARGEST_MODE_SPAN: f64 = 1e12;

/// The largest and the smallest nonzero size of `eigenvalues`, in 1/s.
pub(crate) fn mode_span(eigenvalues: &[C64]) -> (f64, f64) {
    let sizes = || eigenvalues.iter().map(|z| z.norm());
    (
        sizes().fold(0.0, f64::max),
        sizes().filter(|&r| r > 0.0).fold(f64::INFINITY, f64::min),
    )
}

/// Whether the modes of `eigenvalues` span more than
/// [`LARGEST_MODE_SPAN`]: the slow modes' growth rates are then rounding
/// of the fast ones.
pub(crate) fn beyond_resolution(eigenvalues: &[C64]) -> bool {
    let (fastest, slowest) = mode_span(eigenvalues);
    slowest.is_finite() && fastest > LARGEST_MODE_SPAN * slowest
}
