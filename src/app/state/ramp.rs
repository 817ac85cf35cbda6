//! The app's quasi-static load ramp: the load moving by itself at a set rate
//! in simulated time, paused and resumed, and the load at which the column's
//! motion became visible on the way (to set beside the theory's onset).

use super::AppState;
use crate::app::notice::Notice;
use crate::i18n;
use crate::model::{Key, Model};
use crate::sim::{Observables, Ramp};
use crate::tr;

/// The motion is called visible when the tip is off its straight position
/// by this fraction of the column's length, all its rods (5%: 25 px of a
/// 500 px column).
pub const VISIBLE_FRACTION: f64 = 0.05;

/// Whether the column's motion in `now` is visible (see [`VISIBLE_FRACTION`]).
#[must_use]
pub fn visible(model: &Model, now: &Observables) -> bool {
    let reach_m = model.column.reach_m();
    let [x, y] = now.tip_m;
    (x - reach_m).hypot(y) > VISIBLE_FRACTION * reach_m
}

/// A ramp under way.
#[derive(Clone, Debug, PartialEq)]
pub struct RampRun {
    pub ramp: Ramp,
    /// Simulated time the ramp has moved (pauses left out).
    elapsed_secs: f64,
    pub paused: bool,
    /// The load at which the motion first became visible during the ramp.
    pub seen_at_p: Option<f64>,
    /// The motion was visible when the ramp started: no onset to record.
    visible_at_start: bool,
}

impl RampRun {
    /// A ramp starting now, with the motion `visible_now` or not.
    #[must_use]
    pub fn new(ramp: Ramp, visible_now: bool) -> Self {
        Self {
            ramp,
            elapsed_secs: 0.0,
            paused: false,
            seen_at_p: None,
            visible_at_start: visible_now,
        }
    }

    /// The ramp's load now.
    #[must_use]
    pub fn load(&self) -> f64 {
        self.ramp.load_at(self.elapsed_secs)
    }

    /// Moves the ramp on by `dt_secs` of simulated time (not while paused).
    pub fn advance(&mut self, dt_secs: f64) {
        if !self.paused {
            self.elapsed_secs += dt_secs.max(0.0);
        }
    }

    /// Whether the load has reached the ramp's end.
    #[must_use]
    pub fn finished(&self) -> bool {
        self.elapsed_secs >= self.ramp.duration_secs()
    }

    /// Notes whether the motion is visible at `load`: the first load at
    /// which it is, unless it already was when the ramp started.
    pub fn observe(&mut self, visible: bool, load: f64) {
        if visible && !self.visible_at_start && self.seen_at_p.is_none() {
            self.seen_at_p = Some(load);
        }
    }
}

impl AppState {
    /// Starts `ramp`: the load goes to its start and moves on as the run
    /// does; the run starts if it was paused.
    pub(super) fn start_ramp(&mut self, ramp: Ramp) {
        let words = self.words();
        if let Err(why) = ramp.check_for(&self.settings.model) {
            let why = i18n::ramp_error(words, &why);
            self.say(Notice::error(tr!(words, "notice-ramp-refused", why = why)));
            return;
        }
        if let Err(why) = self.set_parameter(Key::Load, ramp.from_p) {
            let why = i18n::model_error(words, &why);
            self.say(Notice::error(tr!(words, "notice-ramp-refused", why = why)));
            return;
        }
        let visible_now = visible(&self.settings.model, &self.sim.observe());
        self.ramp = Some(RampRun::new(ramp, visible_now));
        self.running = true;
    }

    /// Holds the ramp's load (the run goes on), or lets it move again.
    pub(super) fn toggle_ramp_pause(&mut self) {
        if let Some(run) = &mut self.ramp {
            run.paused = !run.paused;
        }
    }

    /// The ramp, under way or finished.
    #[must_use]
    pub fn ramp(&self) -> Option<&RampRun> {
        self.ramp.as_ref()
    }

    /// After a frame's steps of `dt_secs` in all: the ramp notes whether
    /// the motion has become visible, moves on, and sets the load for the
    /// next frame's steps. The load moves once a frame (1/60 s of wall
    /// time), a staircase far finer than the motion it drives. A load the
    /// run cannot take ends the ramp.
    pub(super) fn follow_ramp(&mut self, dt_secs: f64) {
        let visible_now = visible(&self.settings.model, &self.sim.observe());
        let load_now = self.settings.model.load_p();
        let Some(run) = &mut self.ramp else {
            return;
        };
        run.observe(visible_now, load_now);
        if run.finished() {
            // Done: its marks stay, and the load is no longer its to set.
            return;
        }
        run.advance(dt_secs);
        let next = run.load();
        if next != load_now
            && let Err(why) = self.set_parameter(Key::Load, next)
        {
            self.ramp = None;
            let why = i18n::model_error(self.words(), &why);
            self.say(Notice::error(tr!(
                self.words(),
                "notice-ramp-stopped",
                why = why
            )));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ramp_moves_with_simulated_time_holds_while_paused_and_notes_the_onset_once() {
        let mut run = RampRun::new(Ramp::new(1.0, 2.0, 0.5).unwrap(), false);
        run.advance(1.0);
        assert_eq!(run.load(), 1.5);
        run.paused = true;
        run.advance(1.0);
        assert_eq!(run.load(), 1.5, "a pause holds the load");
        run.paused = false;
        run.observe(false, run.load());
        assert_eq!(run.seen_at_p, None);
        run.advance(0.5);
        run.observe(true, run.load());
        run.advance(0.5);
        run.observe(true, run.load());
        assert_eq!(run.seen_at_p, Some(1.75), "the first visible load");
        assert!(run.finished());
        let mut late = RampRun::new(Ramp::new(1.0, 2.0, 0.5).unwrap(), true);
        late.observe(true, 1.2);
        assert_eq!(late.seen_at_p, None, "visible from the start: no onset");
    }

    /// A chain at rest is not "visible motion": its reach is all its rods
    /// (measured against two rods, a straight 16-rod column was always
    /// "visible", so a ramp on it never noted an onset); bent by more than
    /// 5% of that reach, it is.
    #[test]
    fn a_chain_at_rest_is_still_and_bent_it_moves() {
        let model = crate::model::PresetId::Beck.model();
        assert_eq!(model.column.rods, 16);
        let rest = crate::sim::observe(&model, 0.0, &crate::sim::initial_state(&model, 1e-3));
        assert!(!visible(&model, &rest));
        let mut bent = rest.clone();
        let reach_m = model.column.reach_m();
        bent.tip_m = [reach_m, 0.06 * reach_m];
        assert!(visible(&model, &bent));
    }
}
