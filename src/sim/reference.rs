//! The reference engine: adaptive Dormand-Prince 5(4) on the core's exact
//! nonlinear equations of motion, in f64.

use crate::model::{Model, StateVec, state_derivative};

/// Relative tolerance of the local error per step.
pub const RELATIVE_TOLERANCE: f64 = 1e-11;
/// Absolute tolerance, in rad and rad/s: 1e-9 of the standard 1e-3 rad kick.
pub const ABSOLUTE_TOLERANCE: f64 = 1e-12;

// Dormand and Prince (1980), RK5(4)7FM; the system is autonomous, so the
// nodes c_i are not needed.
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Fifth-order weights (the last row of A: first same as last).
const B5: [f64; 7] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
    0.0,
];
/// Fourth-order weights of the embedded error estimate.
const B4: [f64; 7] = [
    5179.0 / 57600.0,
    0.0,
    7571.0 / 16695.0,
    393.0 / 640.0,
    -92097.0 / 339_200.0,
    187.0 / 2100.0,
    1.0 / 40.0,
];

/// Most internal steps for one call of [`Reference::advance_to`]: an explicit
/// integrator that needs more is facing a stiff problem (a very light roller,
/// a stopped band, a huge load) and would freeze its caller.
pub const MAX_STEPS_PER_ADVANCE: u64 = 20_000;

/// How a call of [`Reference::advance_to`] ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Advance {
    /// The end time was reached.
    Reached,
    /// The step size collapsed: the solution left finite values, or the
    /// problem is so stiff that no step resolves it (the caller tells the
    /// two apart by the state, which stays the last accepted one).
    Collapsed,
    /// [`MAX_STEPS_PER_ADVANCE`] steps did not reach the end: too stiff.
    TooStiff,
}

/// Adaptive integrator state: time, state, and the next step size to try.
#[derive(Clone, Debug)]
pub struct Reference {
    pub(crate) t_secs: f64,
    pub(crate) x: StateVec,
    next_step_secs: f64,
    /// Steps taken (accepted and rejected), for benchmarks.
    pub steps: u64,
}

impl Reference {
    #[must_use]
    pub fn new(x: StateVec) -> Self {
        Self {
            t_secs: 0.0,
            x,
            next_step_secs: 1e-3,
            steps: 0,
        }
    }

    /// Integrates up to time `end` exactly. On `Collapsed` or `TooStiff` the
    /// state is the last accepted one (finite).
    pub fn advance_to(&mut self, model: &Model, end: f64) -> Advance {
        let budget_end = self.steps + MAX_STEPS_PER_ADVANCE;
        // Below this a step is lost in the rounding of the time itself.
        let resolution = 1e-14 * end.abs().max(1.0);
        while self.t_secs < end {
            let remaining = end - self.t_secs;
            if remaining <= resolution {
                // A sliver left by the rounding of earlier steps: nothing to
                // integrate, and no reason to call the run diverged.
                self.t_secs = end;
                break;
            }
            let h = self.next_step_secs.min(remaining);
            if h <= resolution {
                return Advance::Collapsed;
            }
            if self.steps >= budget_end {
                return Advance::TooStiff;
            }
            let (x_new, error) = dormand_prince_step(model, &self.x, h);
            self.steps += 1;
            let factor = if error.is_finite() {
                (0.9 * error.powf(-0.2)).clamp(0.2, 5.0)
            } else {
                0.2
            };
            if error <= 1.0 {
                self.x = x_new;
                self.t_secs = if h == remaining { end } else { self.t_secs + h };
                // A step shortened to land on `end` says little about the
                // size the solution allows: keep the longer proposal.
                if h == self.next_step_secs || factor < 1.0 {
                    self.next_step_secs = h * factor;
                }
            } else {
                self.next_step_secs = h * factor.min(1.0);
            }
        }
        Advance::Reached
    }
}

/// One Dormand-Prince step: the fifth-order solution and the scaled error norm.
fn dormand_prince_step(model: &Model, x: &StateVec, h: f64) -> (StateVec, f64) {
    let n = x.len();
    let mut k: Vec<StateVec> = Vec::with_capacity(7);
    k.push(state_derivative(model, x));
    // One buffer for every stage's point, then the solution.
    let mut y = x.clone();
    for row in &A[1..] {
        y.copy_from(x);
        for (a, kj) in row.iter().zip(&k) {
            y.axpy(h * a, kj, 1.0);
        }
        k.push(state_derivative(model, &y));
    }
    let mut x5 = y;
    x5.copy_from(x);
    let mut err = StateVec::zeros(n);
    for (i, ki) in k.iter().enumerate() {
        x5.axpy(h * B5[i], ki, 1.0);
        err.axpy(h * (B5[i] - B4[i]), ki, 1.0);
    }
    let mut sum = 0.0;
    for i in 0..n {
        let scale = ABSOLUTE_TOLERANCE + RELATIVE_TOLERANCE * x[i].abs().max(x5[i].abs());
        sum += (err[i] / scale).powi(2);
    }
    #[expect(clippy::cast_precision_loss, reason = "a state's length")]
    let mean = sum / n as f64;
    (x5, mean.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;
    use crate::sim::initial_state;

    /// Late in a long run the rounding of earlier steps can leave a sliver
    /// of time below the step-size floor: the run goes on, not "diverged".
    #[test]
    fn a_sliver_of_time_left_by_rounding_is_not_a_collapse() {
        let model = PresetId::Ziegler1952.model().at_load(1.0);
        let mut engine = Reference::new(initial_state(&model, 1e-3));
        let end = 4.0e4;
        engine.t_secs = end - 1e-12;
        assert_eq!(engine.advance_to(&model, end), Advance::Reached);
        assert_eq!(engine.t_secs, end);
        assert!(engine.x.iter().all(|v| v.is_finite()));
    }
}
