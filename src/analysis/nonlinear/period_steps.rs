//! How many Gauss-Legendre steps the flow over a cycle's period takes:
//! the fewest for the field's fastest mode, raised where the half-step
//! estimate of a converged cycle's flow error says they are too coarse.

use nalgebra::DVector;

use crate::analysis::field::Field;

/// Fewest steps per period: with the Gauss-Legendre method's order 8, the
/// period and the amplitudes (read off the quintic between steps, see
/// `peaks`) of a cycle of moderate amplitude to about 1e-10 of themselves.
/// A cycle of large amplitude, rich in harmonics, takes more (see
/// [`DISCRETIZATION_TOLERANCE`]).
const MIN_STEPS: u32 = 100;
/// A converged cycle whose flow is off by more than this fraction of its
/// state's largest entry (see [`coarseness`]) is solved again
/// with the steps its error asks for (see [`STEPS_MARGIN`]), up to
/// [`MAX_STEPS_SCALE`] times [`steps_for`]'s.
pub(super) const DISCRETIZATION_TOLERANCE: f64 = 1e-10;
/// The most the steps per period are raised above [`steps_for`]'s.
const MAX_STEPS_SCALE: f64 = 16.0;
/// A flow too coarse by a factor `e` of [`DISCRETIZATION_TOLERANCE`] is
/// taken again with its steps times `e^(1/8)` (the method's order is 8)
/// times this: its error then `1.25^8 = 6` times within the tolerance, so
/// that the cycles after it on a branch, whose amplitude grows, keep the
/// steps for a while. (Doubling the steps instead, as before, took up to
/// twice the steps needed.)
const STEPS_MARGIN: f64 = 1.25;
/// The step times the spectral radius of the Jacobian at rest stays below
/// this. The method is stable at any step (see `gauss`); the bound keeps
/// the stage equations' Newton iterations, which start from the last
/// step's stages, in their quick range where a mode is far faster than the
/// flutter (the roller's spin as its slip slows).
const FAST_MODE_STEP: f64 = 100.0;

/// Steps for one period of `period` of a field whose Jacobian
/// at rest has spectral radius `fastest_per_s`.
pub(in crate::analysis) fn steps_for(period: f64, fastest_per_s: f64) -> usize {
    let needed = (period * fastest_per_s / FAST_MODE_STEP)
        .ceil()
        .clamp(f64::from(MIN_STEPS), 1e7);
    if needed.is_finite() {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a positive step count below 1e7"
        )]
        let steps = needed as usize;
        steps
    } else {
        MIN_STEPS as usize
    }
}

/// `steps` times `scale` (at least 1), rounded up to an even count: the
/// half-step estimate of the flow's error (see `shooting`'s `discretization_error`)
/// takes exactly half of them.
pub(super) fn scaled_steps(steps: usize, scale: f64) -> usize {
    if scale <= 1.0 {
        return steps;
    }
    #[expect(clippy::cast_precision_loss, reason = "a step count below 1e7")]
    let raised = (steps as f64 * scale / 2.0).ceil();
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a positive step count below 1.6e8"
    )]
    let half = raised as usize;
    2 * half
}

/// The spectral radius of the field's Jacobian at rest, 1/s.
pub(in crate::analysis) fn fastest_rate(field: &Field) -> f64 {
    let d = field.dimension();
    field
        .jacobian(&DVector::zeros(d), 1e-6)
        .complex_eigenvalues()
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max)
}

/// The scale of the steps per period for a flow taken at `scale` whose
/// [`coarseness`] (computed only when the scale may still be raised) is
/// above 1: its steps times `coarseness^(1/8)` times [`STEPS_MARGIN`], at
/// most [`MAX_STEPS_SCALE`]. `None` where the flow is fine enough or the
/// scale is at its most.
pub(super) fn raised_scale(scale: f64, coarseness: impl FnOnce() -> f64) -> Option<f64> {
    if scale >= MAX_STEPS_SCALE {
        return None;
    }
    let coarseness = coarseness();
    (coarseness > 1.0)
        .then(|| (scale * coarseness.powf(1.0 / 8.0) * STEPS_MARGIN).min(MAX_STEPS_SCALE))
}

/// How far off a flow whose error (see `shooting`'s half-step estimate)
/// is `error` is, in [`DISCRETIZATION_TOLERANCE`]s of `state`, its state's
/// largest entry: too coarse above 1.
pub(super) fn coarseness(error: f64, state: f64) -> f64 {
    error / (DISCRETIZATION_TOLERANCE * state)
}
