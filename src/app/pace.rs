//! Keeps simulated time in step with wall-clock time: whole engine steps per
//! frame at the chosen speed, the remainder carried to the next frame, a cap
//! on steps per frame so a slow machine never freezes, and the speed the run
//! actually achieved.

/// A gap between frames longer than this is a stall (a hidden window, a
/// debugger), not a slow frame: the run does not jump to make it up.
pub const MAX_FRAME_SECS: f64 = 0.5;
/// At most this many engine steps per frame (10 s of motion at the default
/// step): beyond it the frame would take longer than the motion it shows.
pub const MAX_STEPS_PER_FRAME: usize = 2400;
/// The achieved speed is measured over this much wall time.
const WINDOW_SECS: f64 = 1.0;
/// Below this fraction of the chosen speed the run is said to lag.
const KEEPS_UP: f64 = 0.85;

/// The pacing of a run.
#[derive(Clone, Debug, Default)]
pub struct Pace {
    /// Simulated time owed to the clock, less than one step after a frame
    /// that kept up.
    owed_secs: f64,
    window_wall_secs: f64,
    window_sim_secs: f64,
    /// Simulated seconds per wall second over the last full window.
    achieved: Option<f64>,
}

impl Pace {
    /// The number of engine steps of `step_secs` this frame owes after
    /// `wall_secs` of wall-clock time at `speed` simulated seconds per wall
    /// second. What the cap leaves undone is dropped, not carried: a machine
    /// that cannot keep up runs slower, it does not fall ever further behind.
    pub fn steps(&mut self, wall_secs: f64, speed: f64, step_secs: f64) -> usize {
        if !(step_secs > 0.0 && speed.is_finite() && speed > 0.0) {
            return 0;
        }
        let wall_secs = if wall_secs.is_finite() {
            wall_secs.clamp(0.0, MAX_FRAME_SECS)
        } else {
            0.0
        };
        self.owed_secs += wall_secs * speed;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            clippy::cast_precision_loss,
            reason = "a non-negative count, capped at MAX_STEPS_PER_FRAME"
        )]
        let steps = (self.owed_secs / step_secs)
            .floor()
            .clamp(0.0, MAX_STEPS_PER_FRAME as f64) as usize;
        #[expect(clippy::cast_precision_loss, reason = "steps <= MAX_STEPS_PER_FRAME")]
        let advanced_secs = steps as f64 * step_secs;
        self.owed_secs = (self.owed_secs - advanced_secs).clamp(0.0, step_secs);
        self.window_wall_secs += wall_secs;
        self.window_sim_secs += advanced_secs;
        if self.window_wall_secs >= WINDOW_SECS {
            self.achieved = Some(self.window_sim_secs / self.window_wall_secs);
            self.window_wall_secs = 0.0;
            self.window_sim_secs = 0.0;
        }
        steps
    }

    /// The achieved speed when it falls short of `speed` by more than 15%.
    #[must_use]
    pub fn lagging(&self, speed: f64) -> Option<f64> {
        self.achieved
            .filter(|&achieved| achieved < KEEPS_UP * speed)
    }

    /// Forgets the debt and the measurement (after a pause, a reset or an
    /// engine stop, the next frame starts afresh).
    pub fn restart(&mut self) {
        *self = Self::default();
    }
}

#[cfg(test)]
#[expect(
    clippy::cast_precision_loss,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "frame and step counts in the tests are small"
)]
mod tests {
    use super::*;

    const STEP: f64 = 1.0 / 240.0;

    /// Simulated time after `frames` frames of `wall_secs` at `speed`.
    fn run(pace: &mut Pace, frames: usize, wall_secs: f64, speed: f64) -> f64 {
        let steps: usize = (0..frames)
            .map(|_| pace.steps(wall_secs, speed, STEP))
            .sum();
        steps as f64 * STEP
    }

    #[test]
    fn real_time_is_kept_at_any_frame_rate() {
        for fps in [144.0, 60.0, 37.0, 13.0, 2.5] {
            let mut pace = Pace::default();
            let frames = (10.0 * fps) as usize;
            let simulated = run(&mut pace, frames, 1.0 / fps, 1.0);
            let wall = frames as f64 / fps;
            // Within one step: the remainder is carried, never lost.
            assert!(
                (simulated - wall).abs() <= STEP,
                "{fps} fps: {simulated} s in {wall} s"
            );
            assert!(pace.lagging(1.0).is_none(), "{fps} fps");
        }
    }

    #[test]
    fn the_speed_factor_scales_simulated_time() {
        let mut pace = Pace::default();
        let simulated = run(&mut pace, 600, 1.0 / 60.0, 10.0);
        assert!((simulated - 100.0).abs() <= STEP);
        let achieved = pace.achieved.unwrap();
        assert!((achieved - 10.0).abs() < 0.01, "{achieved}");
    }

    #[test]
    fn a_slow_machine_is_capped_and_says_by_how_much() {
        let mut pace = Pace::default();
        // 4 fps at 100x owes 25 s of motion a frame: 6000 steps, capped.
        let steps = pace.steps(0.25, 100.0, STEP);
        assert_eq!(steps, MAX_STEPS_PER_FRAME);
        run(&mut pace, 8, 0.25, 100.0);
        let achieved = pace.lagging(100.0).unwrap();
        let capped = MAX_STEPS_PER_FRAME as f64 * STEP / 0.25;
        assert!((achieved - capped).abs() < 1e-9, "{achieved} vs {capped}");
        // The undone part is not carried: the next fast frame is not a burst.
        assert!(pace.steps(1.0 / 60.0, 1.0, STEP) <= 5);
    }

    #[test]
    fn a_stall_is_not_made_up_and_bad_times_advance_nothing() {
        let mut pace = Pace::default();
        let steps = pace.steps(30.0, 1.0, STEP) as f64;
        assert!((steps - MAX_FRAME_SECS / STEP).abs() <= 1.0, "{steps}");
        for wall in [f64::NAN, f64::INFINITY, -1.0] {
            assert_eq!(pace.steps(wall, 1.0, STEP), 0, "{wall}");
        }
        assert_eq!(pace.steps(1.0, f64::NAN, STEP), 0);
    }
}
