//! When Newton's (or Broyden's) iterations on a cycle's unknowns
//! `u = (x0, T, p)` are done, and Broyden's update of their matrix.

use nalgebra::{DMatrix, DVector};

use super::cycle::LOAD_SCALE_FLOOR;

/// Newton's iterations end when each part of the step is this fraction of
/// its part of the unknowns (see [`converged`]).
const NEWTON_TOLERANCE: f64 = 1e-9;
/// A periodicity residual this fraction of the state is the flows'
/// rounding (a hundred steps of a few units in the last place each).
const ROUNDING_RESIDUAL: f64 = 1e-13;
/// Newton's steps up to this fraction of each part of the unknowns are
/// taken for rounding magnified where the residual is at rounding (see
/// [`periodic_to_rounding`]).
const NOISE_STEP: f64 = 1e-6;

/// Broyden's ("good") rank-one update of the inverse `h` of Newton's
/// matrix after a step `s` changed the residual by `y`, by the formula of
/// Sherman and Morrison: `h += (s - h y) (s^T h) / (s^T h y)`. The updated
/// matrix maps `y` to `s`, and is unchanged across `s`. Left as it is
/// where `s^T h y` vanishes.
pub(in crate::analysis) fn broyden_update(
    h: &mut DMatrix<f64>,
    s: &DVector<f64>,
    y: &DVector<f64>,
) {
    let hy = &*h * y;
    let denominator = s.dot(&hy);
    if denominator.abs() > f64::MIN_POSITIVE && denominator.is_finite() {
        let st_h = s.transpose() * &*h;
        *h += (s - hy) * st_h / denominator;
    }
}

/// Whether the cycle is periodic to the flows' rounding though Newton's
/// step has not shrunk to [`NEWTON_TOLERANCE`]: the periodicity residual
/// is within [`ROUNDING_RESIDUAL`] of the state's largest entry and the
/// step within [`NOISE_STEP`] of each part. Where the periodicity hardly
/// depends on a direction of the start (a slowly relaxing coordinate, such
/// as a heavy roller's spin, whose multiplier is near 1), Newton's matrix
/// is nearly singular and its steps are the flows' rounding magnified: a
/// 16-rod chain on a roller next to its onset had residuals of 1e-17
/// against a state of 3e-3 and steps of 3e-11 to 1e-10, one
/// iteration after another, while its period moved by 1e-12 of itself.
pub(in crate::analysis) fn periodic_to_rounding(
    residual: &DVector<f64>,
    step: &DVector<f64>,
    u: &DVector<f64>,
    d: usize,
) -> bool {
    let state = u.rows(0, d).amax();
    residual.rows(0, d).amax() <= ROUNDING_RESIDUAL * state
        && step.rows(0, d).amax() <= NOISE_STEP * state
        && step[d].abs() <= NOISE_STEP * u[d].abs()
        && step[d + 1].abs() <= NOISE_STEP * u[d + 1].abs().max(LOAD_SCALE_FLOOR)
}

/// Whether Newton's `step` at the unknowns `u = (x0, T, p)` (the state's
/// length `d`) is down to [`NEWTON_TOLERANCE`] of each part's own size: the
/// state's largest entry, the period, the load (at least
/// [`LOAD_SCALE_FLOOR`]). Measured by one size for all, a cycle of small
/// amplitude and long period (a long chain's near its onset) would ask its
/// period to more digits than the state determines it to.
pub(in crate::analysis) fn converged(step: &DVector<f64>, u: &DVector<f64>, d: usize) -> bool {
    let state = u.rows(0, d).amax();
    step.rows(0, d).amax() <= NEWTON_TOLERANCE * state
        && step[d].abs() <= NEWTON_TOLERANCE * u[d].abs()
        && step[d + 1].abs() <= NEWTON_TOLERANCE * u[d + 1].abs().max(LOAD_SCALE_FLOOR)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 16-rod chain on its roller next to the onset (from the trace
    /// that stalled): a residual at rounding with Newton's steps of noise
    /// is periodic; the same step with a residual above rounding is not,
    /// and neither is a step that is more than noise.
    #[test]
    fn a_residual_at_rounding_ends_newton_s_iterations() {
        let d = 2;
        let u = DVector::from_vec(vec![2.98e-3, -1.0e-3, 1563.5, 9.6e-5]);
        let step = DVector::from_vec(vec![3.3e-11, 1e-11, 2.2e-12, 0.0]);
        let at_rounding = DVector::from_vec(vec![1.3e-17, 8e-18, 0.0, 0.0]);
        assert!(!converged(&step, &u, d));
        assert!(periodic_to_rounding(&at_rounding, &step, &u, d));
        let above = &at_rounding * 1e5;
        assert!(!periodic_to_rounding(&above, &step, &u, d));
        let large_step = &step * 1e5;
        assert!(!periodic_to_rounding(&at_rounding, &large_step, &u, d));
    }
}
