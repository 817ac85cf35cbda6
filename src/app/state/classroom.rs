//! What a class needs of the state: "reset all" (the preset's parameters
//! and load, a fresh run at normal speed, the views at their defaults) and
//! the one-line hint of a first launch.

use super::AppState;

/// The hint a first launch shows in the status line.
pub const FIRST_LAUNCH_HINT: &str =
    "Drag the load bar to about 3 and press K to kick the column (space pauses).";

impl AppState {
    /// The default state with the first launch's hint.
    #[must_use]
    pub fn first_launch() -> Self {
        let mut state = Self::defaults();
        state.hint = true;
        state
    }

    /// The hint to show, if any.
    #[must_use]
    pub fn hint(&self) -> Option<&'static str> {
        self.hint.then_some(FIRST_LAUNCH_HINT)
    }

    pub fn dismiss_hint(&mut self) {
        self.hint = false;
    }

    /// Everything back to the preset: its parameters and load, no ramp, no
    /// overlay, no refusals, normal speed, a fresh run, and the views at
    /// their defaults.
    pub fn reset_all(&mut self) {
        let preset = self.settings.preset;
        self.ramp = None;
        self.overlay = None;
        self.refused.clear();
        self.settings.speed = 1.0;
        self.set_model(preset.model());
        self.reset();
        self.view_generation += 1;
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
        state.kick();
        assert!(state.hint().is_none(), "a kick ends the hint");
        let generation = state.view_generation();
        state.reset_all();
        assert_eq!(state.settings().model, preset);
        assert_eq!(state.settings().speed, 1.0);
        assert!(state.ramp().is_none());
        assert_eq!(state.simulation().time_secs(), 0.0);
        assert_eq!(state.view_generation(), generation + 1);
    }
}
