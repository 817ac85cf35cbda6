//! Limit cycles held at an amplitude of the first rod's angle, with the
//! load among the unknowns, and the load's rate along their branch: zero at
//! a fold of cycles, where the load turns back while the amplitude goes on.
//!
//! The start `x0` is where the first angle peaks. Newton solves
//!
//! ```text
//! phi_T(x0; p) - x0 = 0     (d equations)
//! x0[N] = 0                 (the first angle's rate: its peak)
//! x0[0] - a = 0             (its amplitude)
//! ```
//!
//! for `u = (x0, T, p)`. A branch of cycles is smooth in `a` through its
//! folds in `p`, so Newton's matrix `J` stays regular there, and the
//! branch's rate `du/da = J⁻¹ e` (`e` the last unit vector) has its load
//! entry `dp/da` zero exactly at a fold. Pure: no UI, no clock.

use nalgebra::{DMatrix, DVector};

use super::hopf::HopfPoint;
use super::shooting::{Constraint, Phase, Shooting, Solved, Update};

/// A cycle at a held amplitude and the load's rate along its branch.
pub(in crate::analysis) struct AtAmplitude {
    pub solved: Solved,
    /// Newton's matrix at the cycle (from its exact monodromy): a good
    /// first matrix for a cycle near it.
    pub matrix: DMatrix<f64>,
    /// `dp/da` along the branch, per rad of the first angle's amplitude.
    pub load_per_rad: f64,
}

/// The unit vector `e_k` of length `n`.
fn unit(n: usize, k: usize) -> DVector<f64> {
    DVector::from_fn(n, |i, _| if i == k { 1.0 } else { 0.0 })
}

impl Shooting {
    /// The cycle whose first angle peaks at `amplitude_rad`, from the
    /// unknowns `guess = (x0, T, p)` of a cycle near it (and its Newton
    /// matrix, when known); `None` where Newton's method fails.
    pub(in crate::analysis) fn at_amplitude(
        &self,
        (guess, known): (&DVector<f64>, Option<&DMatrix<f64>>),
        amplitude_rad: f64,
    ) -> Option<AtAmplitude> {
        let d = self.field.dimension();
        let rods = self.field.rods();
        let phase = Phase {
            normal: unit(d, rods),
            point: DVector::zeros(d),
        };
        let tangent = unit(d + 2, 0);
        let predicted = &tangent * amplitude_rad;
        let constraint = Constraint::Arclength {
            tangent: &tangent,
            predicted: &predicted,
        };
        let mut start = guess.clone();
        start[0] = amplitude_rad;
        start[rods] = 0.0;
        let solved = self.solve_on(&start, &constraint, &phase, known.map(Update::Matrix))?;
        let cycle = &solved.cycle;
        let matrix = self.newton_matrix(
            (&cycle.start, cycle.period_secs, cycle.load),
            solved.steps,
            (&cycle.start, &solved.monodromy),
            &phase.normal,
            &constraint,
        )?;
        let rate = matrix.clone().lu().solve(&unit(d + 2, d + 1))?;
        Some(AtAmplitude {
            load_per_rad: rate[d + 1],
            matrix,
            solved,
        })
    }
}

/// The unknowns `(x0, T, p)` of the normal form's cycle of `point` whose
/// first angle peaks at `amplitude_rad`, to leading order:
/// `x0 = a Re(q conj(q_0)) / |q_0|^2`, the Hopf period and load.
pub(in crate::analysis) fn normal_form_start(
    point: &HopfPoint,
    amplitude_rad: f64,
) -> DVector<f64> {
    let q = &point.eigenvector;
    let q0 = q[0];
    let d = q.len();
    DVector::from_fn(d + 2, |i, _| match i {
        i if i < d => amplitude_rad * (q[i] * q0.conj()).re / q0.norm_sqr(),
        i if i == d => std::f64::consts::TAU / point.hopf.frequency_rad_per_s,
        _ => point.hopf.load,
    })
}
