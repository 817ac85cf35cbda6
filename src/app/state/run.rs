//! The run: advancing it with the wall clock's elapsed time at the chosen
//! speed, one step at a time, a kick, a fresh start, and the eigenvalues
//! measured from it.

use super::{AppState, push_trail, start};
use crate::app::notice::Notice;
use crate::sim::Status;

/// Exponentials fitted to the two-rod column's run: two per oscillating
/// mode.
const MEASURED_ORDER: usize = 4;

impl AppState {
    /// Advances the run by `wall_secs` of wall-clock time at the chosen speed
    /// (whole engine steps, the remainder carried; see [`Pace`]).
    pub fn advance(&mut self, wall_secs: f64) {
        if !self.running || self.held {
            self.pace.restart();
            return;
        }
        let steps = self
            .pace
            .steps(wall_secs, self.settings.speed, self.sim.step_secs());
        let mut taken = 0_u32;
        for _ in 0..steps {
            if !self.take_step() {
                break;
            }
            taken += 1;
        }
        self.follow_ramp(f64::from(taken) * self.sim.step_secs());
        self.refresh_measured();
    }

    /// One engine step, then paused (the step button).
    pub(super) fn step(&mut self) {
        self.running = false;
        self.pace.restart();
        self.take_step();
        self.refresh_measured();
    }

    /// One engine step with what follows it: the trail and the history; a
    /// run that ends stops. Whether it goes on.
    fn take_step(&mut self) -> bool {
        if self.sim.step() != Status::Running {
            self.running = false;
            self.pace.restart();
            return false;
        }
        let now = self.sim.observe();
        push_trail(&mut self.trail, &now);
        self.history.push(now);
        true
    }

    /// Measures afresh from now on: what was measured and the samples before
    /// now belong to another motion (another column, a kick, a release).
    pub(super) fn measure_afresh(&mut self) {
        self.history.restart_measurement(self.sim.time_secs());
        self.forget_measured();
    }

    /// Drops the measured eigenvalues; the next refit comes as soon as the
    /// history allows.
    pub(super) fn forget_measured(&mut self) {
        self.measured = None;
        self.measured_uncertainty.clear();
        self.measured_at_secs = f64::NEG_INFINITY;
    }

    /// The eigenvalues measured from the run, refitted about once a
    /// simulated second (not every step: at 10x a frame holds ten seconds).
    pub(super) fn refresh_measured(&mut self) {
        let t = self.sim.time_secs();
        if t - self.measured_at_secs >= 1.0 {
            // Two exponentials per oscillating mode of the two-rod column. A
            // chain's many modes, some with periods far beyond the history,
            // are not measured: a fit of a few would show made-up values.
            self.measured = (self.sim.model().column.rods == 2)
                .then(|| self.history.measured(MEASURED_ORDER))
                .flatten();
            self.measured_uncertainty = self
                .measured
                .as_deref()
                .map(|measured| self.history.uncertainty(MEASURED_ORDER, measured))
                .unwrap_or_default();
            self.measured_at_secs = t;
        }
    }

    /// Turns every rod by `angle_rad` (both of two, all of a chain: the
    /// column turns as a whole, with no kink at a joint) and runs on.
    pub(super) fn kick(&mut self, angle_rad: f64) {
        self.first_launch.hint = false;
        let mut x = self.sim.state();
        for angle in x.rows_mut(0, self.sim.model().column.rods).iter_mut() {
            *angle += angle_rad;
        }
        if let Err(error) = self.sim.restart_from(self.sim.engine(), x) {
            self.say(Notice::error(error.to_string()));
        }
        // The kick is a jump in the state, not motion of the column: the
        // fit starts after it, as after a release.
        self.measure_afresh();
        self.running = true;
    }

    /// A fresh run of the current model from the standard kick.
    pub(super) fn reset(&mut self) {
        let words = self.words();
        match start(&mut self.settings, words) {
            Ok((sim, notice)) => {
                if let Some(notice) = notice {
                    self.say(notice);
                }
                self.sim = sim;
                self.trail.clear();
                self.history.clear();
                self.forget_measured();
                self.pace.restart();
                self.running = true;
            }
            Err(error) => self.say(Notice::error(error.to_string())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::state::Settings;
    use crate::lesson::KICK_RAD;
    use crate::model::Key;

    #[test]
    fn the_step_button_steps_through_advance_s_bookkeeping() {
        let mut state = AppState::new(Settings::default()).unwrap();
        let before = state.history().thinned(usize::MAX).count();
        state.step();
        assert!(!state.running());
        assert_eq!(state.history().thinned(usize::MAX).count(), before + 1);
        assert!(state.simulation().time_secs() > 0.0);
    }

    /// A chain's eigenvalues are not measured from the run: its many modes
    /// (the slowest with periods of minutes) are beyond a fit of two, and
    /// the same run on two rods is measured.
    #[test]
    fn a_chain_s_eigenvalues_are_not_made_up_from_the_run() {
        for (rods, measured) in [(2.0, true), (4.0, false)] {
            let mut state = AppState::new(Settings::default()).unwrap();
            state.set_parameter(Key::Rods, rods).unwrap();
            for _ in 0..(40 * 60) {
                state.advance(1.0 / 60.0);
            }
            assert_eq!(state.measured().is_some(), measured, "rods = {rods}");
        }
    }

    /// A change of load mid-run restarts the measurement: the eigenvalues
    /// measured before belong to the old column, and a window that
    /// straddled the change would mix the two.
    #[test]
    fn a_change_of_load_restarts_the_measurement() {
        let mut state = AppState::new(Settings::default()).unwrap();
        for _ in 0..(25 * 60) {
            state.advance(1.0 / 60.0);
        }
        assert!(state.measured().is_some(), "measured after 25 s");
        state.set_parameter(Key::Load, 1.24).unwrap();
        assert!(state.measured().is_none());
        for _ in 0..(15 * 60) {
            state.advance(1.0 / 60.0);
        }
        assert!(
            state.measured().is_none(),
            "15 s since the change: too short"
        );
        for _ in 0..(7 * 60) {
            state.advance(1.0 / 60.0);
        }
        let measured = state.measured().expect("22 s since the change");
        let predicted = state.current_spectrum().unwrap();
        let growth = crate::analysis::classify(&predicted.eigenvalues, predicted.scale_per_s)
            .growth_rate_per_s();
        let fastest = measured
            .iter()
            .map(|z| z.re)
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(
            (fastest - growth).abs() < 0.2 * growth.abs(),
            "measured {fastest} against predicted {growth}"
        );
    }

    /// A kick restarts the measurement: a fit across the jump in the state
    /// showed ziegler-1952 at p = 1, neutral, as growing (+0.089 ± 1.01i
    /// 5 s after the kick). Until the window after the kick is long enough
    /// nothing is measured; then the undamped column's eigenvalues are
    /// measured near the imaginary axis at the predicted frequencies, each
    /// mode once the window holds a period of it.
    #[test]
    fn a_kick_restarts_the_measurement() {
        for engine in [
            crate::sim::EngineKind::Reference,
            crate::sim::EngineKind::Rapier,
        ] {
            kick_then_measure(engine);
        }
    }

    fn kick_then_measure(engine: crate::sim::EngineKind) {
        let mut state = AppState::new(Settings {
            preset: crate::model::PresetId::Ziegler1952,
            model: crate::model::PresetId::Ziegler1952.model(),
            engine,
            ..Settings::default()
        })
        .unwrap();
        state.set_parameter(Key::Load, 1.0).unwrap();
        state.reset();
        let run = |state: &mut AppState, secs: u32| {
            for _ in 0..(secs * 60) {
                state.advance(1.0 / 60.0);
            }
        };
        run(&mut state, 25);
        assert!(state.measured().is_some(), "measured after 25 s");
        state.kick(KICK_RAD);
        assert!(state.measured().is_none(), "forgotten at the kick");
        run(&mut state, 5);
        assert!(state.measured().is_none(), "5 s after the kick: measuring");
        run(&mut state, 20);
        // Within the measurement's stated accuracy (the README: 0.005 1/s
        // in Re λ, 1% in Im λ), at 25 s and at 45 s, when the slow mode's
        // 42 s period fits in the window too.
        for (after_secs, modes) in [(25, 1), (45, 2)] {
            let measured = state.measured().expect("measured after the kick");
            let above: Vec<_> = measured.iter().filter(|z| z.im > 0.0).collect();
            assert_eq!(
                above.len(),
                modes,
                "{engine:?} {after_secs} s: {measured:?}"
            );
            let predicted = &state.current_spectrum().unwrap().eigenvalues;
            for z in above {
                assert!(
                    z.re.abs() < 5e-3,
                    "{engine:?} {after_secs} s: {z}: {measured:?}"
                );
                let nearest = predicted
                    .iter()
                    .map(|p| (p.im - z.im).abs())
                    .fold(f64::INFINITY, f64::min);
                assert!(nearest < 1e-2 * z.im, "{z} against {predicted:?}");
            }
            run(&mut state, 20);
        }
    }

    /// Holding the column (a drag) forgets what was measured: a held column
    /// is not the column's motion.
    #[test]
    fn holding_the_column_forgets_the_measurement() {
        let mut state = AppState::new(Settings::default()).unwrap();
        for _ in 0..(25 * 60) {
            state.advance(1.0 / 60.0);
        }
        assert!(state.measured().is_some());
        state.hold(&[0.02, 0.03]);
        assert!(state.measured().is_none());
        for _ in 0..60 {
            state.advance(1.0 / 60.0);
        }
        assert!(state.measured().is_none(), "held: nothing measured");
    }

    /// A kick turns every rod of a chain by the same angle: the column turns
    /// as a whole (it used to turn the first two rods only, a kink at the
    /// third joint).
    #[test]
    fn a_kick_turns_every_rod_of_a_chain() {
        let mut state = AppState::new(Settings::default()).unwrap();
        state.set_parameter(Key::Rods, 5.0).unwrap();
        let before: Vec<f64> = state.simulation().state().iter().take(5).copied().collect();
        state.kick(KICK_RAD);
        let after = state.simulation().state();
        for (i, angle) in before.iter().enumerate() {
            // (rapier keeps angles in f32)
            assert!(
                (after[i] - angle - KICK_RAD).abs() < 1e-6,
                "rod {}: {} -> {}",
                i + 1,
                angle,
                after[i]
            );
        }
    }
}
