//! What a class needs of the state: "reset all" (the preset's parameters
//! and load, a fresh run at normal speed, the views at their defaults) and
//! the one-line hint of a first launch.

use super::AppState;
use crate::app::notice::Notice;
use crate::model::StateViewMut;

/// The hint a first launch shows in the status line (its message id).
pub const FIRST_LAUNCH_HINT: &str = "hint-first-launch";

impl AppState {
    /// The default state with the first launch's hint and welcome.
    #[must_use]
    pub fn first_launch() -> Self {
        let mut state = Self::defaults();
        state.first_launch.hint = true;
        state.first_launch.welcome = true;
        state
    }

    /// Whether the first launch's welcome is shown (never in a picture).
    #[must_use]
    pub fn welcome(&self) -> bool {
        self.first_launch.welcome && !self.for_picture()
    }

    /// The hint to show, if any (none in a picture): its message id.
    #[must_use]
    pub fn hint(&self) -> Option<&'static str> {
        (self.first_launch.hint && !self.for_picture()).then_some(FIRST_LAUNCH_HINT)
    }

    /// Whether the window is drawn for a picture: the command line's
    /// pictures and the frames of a recording show no hints for the hand
    /// (how to drag, pan or zoom, the first launch's hint, the fit button).
    #[must_use]
    pub fn for_picture(&self) -> bool {
        self.drawn_for == super::DrawnFor::Picture
    }

    pub fn set_for_picture(&mut self, on: bool) {
        self.drawn_for = if on {
            super::DrawnFor::Picture
        } else {
            super::DrawnFor::Window
        };
    }

    /// Everything back to the preset: its parameters and load, no ramp, no
    /// overlay, no refusals, normal speed, a fresh run, and the views at
    /// their defaults. A lesson ends too (its step would go on saying what
    /// no longer happens: "watch the load rise" with the ramp gone), and
    /// the message line says so.
    pub(super) fn reset_all(&mut self) {
        let preset = self.settings.preset;
        if let Some(run) = self.lesson.take() {
            self.say(Notice::info(crate::tr!(
                self.words(),
                "notice-reset-closed-lesson",
                title = run.lesson.title.as_str()
            )));
        }
        self.ramp = None;
        self.overlay = None;
        self.overlay_wanted = None;
        self.refused.clear();
        self.settings.speed = 1.0;
        self.check_and_set_model(preset.model());
        self.reset();
        self.view_generation += 1;
    }

    /// Holds the column at rest with its rods at `angles_rad` (a drag in
    /// the scene): time stands still until [`Self::release`]. The state is
    /// the N angles, the roller's spin, the N rates and the spin's rate; an
    /// angle list of another length (a chain changed under the mouse) is
    /// not taken.
    pub(super) fn hold(&mut self, angles_rad: &[f64]) {
        let rods = self.sim.model().column.rods;
        if angles_rad.len() != rods {
            return;
        }
        let mut x = self.sim.state();
        let mut write = StateViewMut::new(&mut x);
        write.angles_rad().copy_from_slice(angles_rad);
        write.rates_rad_per_s().fill(0.0);
        match self.sim.restart_from(self.sim.engine(), x) {
            Ok(()) => {
                self.held = true;
                self.first_launch.hint = false;
                // The tip was moved by hand: its path before is not motion,
                // nor is the held column measured.
                self.trail.clear();
                self.forget_measured();
            }
            Err(error) => self.say(Notice::error(error.to_string())),
        }
    }

    /// Lets a held column go: the run goes on from rest where it was left,
    /// and the growth measurement starts again there.
    pub(super) fn release(&mut self) {
        if self.held {
            self.held = false;
            self.running = true;
            self.measure_afresh();
        }
    }

    #[must_use]
    pub fn held(&self) -> bool {
        self.held
    }

    /// Moves on every "reset all": views that keep a zoom or a tab compare it.
    #[must_use]
    pub fn view_generation(&self) -> u64 {
        self.view_generation
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::KICK_RAD;
    use crate::model::Key;
    use crate::sim::Ramp;

    #[test]
    fn reset_all_restores_the_preset_its_load_and_normal_speed() {
        let mut state = AppState::first_launch();
        assert!(state.hint().is_some());
        let preset = state.settings().preset.model();
        state.set_parameter(Key::Nu, 0.5).unwrap();
        state.set_speed(4.0);
        state.start_ramp(Ramp::new(1.0, 3.0, 0.5).unwrap());
        state.advance(1.0 / 60.0);
        state.kick(KICK_RAD);
        assert!(state.hint().is_none(), "a kick ends the hint");
        let generation = state.view_generation();
        state.reset_all();
        assert_eq!(state.settings().model, preset);
        assert_eq!(state.settings().speed, 1.0);
        assert!(state.ramp().is_none());
        assert_eq!(state.simulation().time_secs(), 0.0);
        assert_eq!(state.view_generation(), generation + 1);
    }

    /// A held column stands still at the given angles, at rest; released,
    /// it moves on from there.
    #[test]
    fn a_held_column_stands_still_and_moves_on_when_released() {
        let mut state = AppState::defaults();
        state.hold(&[0.2, 0.5]);
        let t = state.simulation().time_secs();
        for _ in 0..30 {
            state.advance(1.0 / 60.0);
        }
        let x = state.simulation().state();
        assert_eq!(state.simulation().time_secs(), t);
        assert!((x[0] - 0.2).abs() < 1e-6 && (x[1] - 0.5).abs() < 1e-6);
        assert_eq!((x[3], x[4]), (0.0, 0.0));
        state.release();
        for _ in 0..30 {
            state.advance(1.0 / 60.0);
        }
        assert!(state.simulation().time_secs() > t + 0.4);
        assert!(
            (state.simulation().state()[1] - 0.5).abs() > 1e-4,
            "it moves"
        );
    }
}
