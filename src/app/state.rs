//! The app's state with no egui in it: the settings, the running
//! simulation, the analysis of the current parameters, the overlay and the
//! notices, with the only ways to change them.

mod analysis;
mod apply;
mod classroom;
mod lesson;
mod overlay;
mod ramp;
mod run;
mod startup;

use std::collections::VecDeque;

use crate::analysis::{AnalysisError, C64, Spectrum};
use crate::i18n::{self, Language, Words};
use crate::model::{
    Assignment, Axis, Key, Model, ModelError, PresetId, ValidModel, apply_assignments,
};
use crate::sim::{DEFAULT_STEP_SECS, EngineKind, Observables, SimError, Simulation, initial_state};

pub use lesson::LessonRun;
pub use overlay::Overlay;
pub use ramp::{RampRun, VISIBLE_FRACTION};

use super::action::Refusal;
use super::analysis_cache::Analysis;
use super::history::History;
use super::notice::Notice;
use super::pace::Pace;
pub use super::settings::Settings;

/// How long the tip's trail lasts, in simulated seconds.
pub const TRAIL_SECS: f64 = 6.0;

/// Keeps the trail to its duration.
fn push_trail(trail: &mut VecDeque<(f64, [f64; 2])>, now: &Observables) {
    trail.push_back((now.t_secs, now.tip_m));
    while trail
        .front()
        .is_some_and(|(t, _)| now.t_secs - t > TRAIL_SECS)
    {
        trail.pop_front();
    }
}

/// What the user is told when rapier cannot integrate the column.
pub(crate) const SWITCHED_TO_REFERENCE: &str = "notice-switched-to-reference";

/// A run of the settings' model from the standard kick. When rapier cannot
/// integrate it the reference engine runs instead, the settings say so, and
/// so does the returned notice.
fn start(
    settings: &mut Settings,
    words: &'static Words,
) -> Result<(Simulation, Option<Notice>), SimError> {
    let model = settings.model;
    let x0 = initial_state(&model, 1e-3);
    match Simulation::new(model, settings.engine, x0.clone(), DEFAULT_STEP_SECS) {
        Ok(sim) => Ok((sim, None)),
        Err(SimError::TooStiffForRapier { .. }) => {
            settings.engine = EngineKind::Reference;
            Simulation::new(model, EngineKind::Reference, x0, DEFAULT_STEP_SECS).map(|sim| {
                let notice = Notice::warning(crate::tr!(words, SWITCHED_TO_REFERENCE));
                (sim, Some(notice))
            })
        }
        Err(error) => Err(error),
    }
}

/// What a first launch shows, each until it is dismissed.
#[derive(Clone, Copy, Debug, Default)]
struct FirstLaunch {
    /// The one-line hint in the status line, until the first kick.
    hint: bool,
    /// The welcome, until it is closed or its lesson started.
    welcome: bool,
}

/// Everything the window shows, and the only ways to change it.
pub struct AppState {
    settings: Settings,
    sim: Simulation,
    running: bool,
    trail: VecDeque<(f64, [f64; 2])>,
    analysis: Option<Analysis>,
    /// Why there is no analysis, and the parameters (at p = 0) it is for.
    analysis_failure: Option<(ValidModel, AnalysisError)>,
    /// The thread that analyses new parameters (none: they are analysed
    /// inline, as pictures and tests want), and the parameters asked of it.
    worker: Option<analysis::AnalysisJobs>,
    pending: Option<ValidModel>,
    /// Simulated time against wall-clock time.
    pace: Pace,
    /// The spectrum at the current load and the model it is for.
    current: Option<(Model, Spectrum)>,
    /// The last thing to tell the user.
    notice: Option<Notice>,
    /// Each field's refused value: why, by key, until a value for it is
    /// taken (kept as data: worded in the language of the moment).
    refused: Vec<(Key, Refusal)>,
    history: History,
    /// The column's eigenvalues measured from the run, refreshed about once a
    /// simulated second.
    measured: Option<Vec<C64>>,
    /// Each measured eigenvalue's uncertainty (real and imaginary parts),
    /// where the run tells it ([`crate::app::history::History::uncertainty`]).
    measured_uncertainty: Vec<Option<C64>>,
    measured_at_secs: f64,
    /// A second model's locus drawn behind the current one (Fig. 8).
    overlay: Option<Overlay>,
    /// The overlay chosen (preset and `a`), and the jobs computing it.
    overlay_wanted: Option<overlay::OverlayKey>,
    overlay_jobs: Option<overlay::OverlayJobs>,
    /// The quasi-static load ramp, under way or finished.
    ramp: Option<RampRun>,
    /// What a first launch shows until it is dismissed.
    first_launch: FirstLaunch,
    /// Whom the frames are drawn for: a picture (the command line's, the
    /// frames of a recording) has no hints for the hand.
    drawn_for: DrawnFor,
    /// Counts "reset all": the views go back to their defaults when it moves.
    view_generation: u64,
    /// The column is held by the mouse: time stands still until released.
    held: bool,
    /// The lesson under way.
    lesson: Option<LessonRun>,
    /// The language the window speaks, and whether it was chosen (in the
    /// menu, or stored from a choice) rather than the system's.
    language: Language,
    language_chosen: bool,
}

/// Whom the window's frames are drawn for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum DrawnFor {
    /// A person at the window: hints for the hand.
    Window,
    /// A picture: none.
    Picture,
}

impl AppState {
    /// The state with `settings`, its run started from the standard kick.
    ///
    /// # Errors
    /// Settings that make no valid simulation.
    pub fn new(settings: Settings) -> Result<Self, SimError> {
        Self::started(settings, None, Language::default())
    }

    /// [`AppState::new`] with the analysis computed off the UI thread from
    /// the start: a stored 64-rod chain opens at once, its plots following
    /// (the window stayed black for seconds while the first was computed).
    ///
    /// # Errors
    /// Settings that make no valid simulation.
    pub fn new_analysing_in_background(
        settings: Settings,
        language: Language,
    ) -> Result<Self, SimError> {
        let worker = crate::app::jobs::Jobs::new("analysis");
        Self::started(settings, Some(worker), language)
    }

    /// The state with `settings`, its analysis asked of `worker` (computed
    /// here without one), speaking `language` (what starting says, too).
    fn started(
        mut settings: Settings,
        worker: Option<analysis::AnalysisJobs>,
        language: Language,
    ) -> Result<Self, SimError> {
        let (sim, notice) = start(&mut settings, i18n::words(language))?;
        let mut state = Self {
            settings,
            sim,
            running: true,
            trail: VecDeque::new(),
            analysis: None,
            analysis_failure: None,
            worker,
            pending: None,
            pace: Pace::default(),
            current: None,
            notice,
            refused: Vec::new(),
            history: History::default(),
            measured: None,
            measured_uncertainty: Vec::new(),
            measured_at_secs: f64::NEG_INFINITY,
            overlay: None,
            overlay_wanted: None,
            overlay_jobs: None,
            ramp: None,
            first_launch: FirstLaunch::default(),
            drawn_for: DrawnFor::Window,
            view_generation: 0,
            held: false,
            lesson: None,
            language,
            language_chosen: false,
        };
        state.refresh_analysis();
        Ok(state)
    }

    #[must_use]
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    #[must_use]
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    #[must_use]
    pub fn model(&self) -> &Model {
        &self.settings.model
    }

    #[must_use]
    pub fn running(&self) -> bool {
        self.running
    }

    #[must_use]
    pub fn trail(&self) -> &VecDeque<(f64, [f64; 2])> {
        &self.trail
    }

    #[must_use]
    pub fn history(&self) -> &History {
        &self.history
    }

    #[must_use]
    pub fn measured(&self) -> Option<&[C64]> {
        self.measured.as_deref()
    }

    /// The uncertainty of the `k`-th of [`Self::measured`] (in its real and
    /// imaginary parts), where the run tells it.
    #[must_use]
    pub fn measured_uncertainty(&self, k: usize) -> Option<C64> {
        self.measured_uncertainty.get(k).copied().flatten()
    }

    #[must_use]
    pub fn analysis(&self) -> Option<&Analysis> {
        self.analysis.as_ref()
    }

    /// Why the current parameters have no analysis, when they have none.
    #[must_use]
    pub fn analysis_failure(&self) -> Option<&AnalysisError> {
        self.analysis_failure.as_ref().map(|(_, error)| error)
    }

    #[must_use]
    pub fn overlay(&self) -> Option<&Overlay> {
        self.overlay.as_ref()
    }

    #[must_use]
    pub fn notice(&self) -> Option<&Notice> {
        self.notice.as_ref()
    }

    /// The language the window speaks.
    #[must_use]
    pub fn language(&self) -> Language {
        self.language
    }

    /// Speaks `language` without its being a choice (the system's).
    pub fn speak(&mut self, language: Language) {
        self.language = language;
    }

    /// The language chosen rather than the system's, if one was.
    #[must_use]
    pub fn language_choice(&self) -> Option<Language> {
        self.language_chosen.then_some(self.language)
    }

    /// The window's words, in its language.
    #[must_use]
    pub fn words(&self) -> &'static Words {
        i18n::words(self.language)
    }

    /// Why the last value typed for `key` was refused, if it was, in the
    /// window's language.
    #[must_use]
    pub fn refusal(&self, key: Key) -> Option<String> {
        self.refused
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, why)| why.words(self.words()))
    }

    /// Whether the last value typed for `key` was refused (without wording
    /// why, as the fields ask every frame).
    #[must_use]
    pub fn is_refused(&self, key: Key) -> bool {
        self.refused.iter().any(|(k, _)| *k == key)
    }

    /// The achieved speed when the run falls behind the chosen one.
    #[must_use]
    pub fn lagging(&self) -> Option<f64> {
        self.running
            .then(|| self.pace.lagging(self.settings.speed))
            .flatten()
    }

    /// Tells the user `notice`, after what they were already told.
    pub fn tell(&mut self, notice: Notice) {
        self.notice = Some(match self.notice.take() {
            Some(earlier) => earlier.and(&notice),
            None => notice,
        });
    }

    /// Replaces what the user is told.
    pub fn say(&mut self, notice: Notice) {
        self.notice = Some(notice);
    }

    /// Sets one parameter by its key (as `--set` does): the model changes for
    /// the running simulation and the analysis follows; a refused value
    /// changes nothing and the error says why.
    ///
    /// # Errors
    /// The key's or the model's validation error.
    fn set_parameter(&mut self, key: Key, value: f64) -> Result<(), ModelError> {
        let mut candidate = self.settings.model;
        let valid = apply_assignments(&mut candidate, &[Assignment { key, value }])?;
        self.set_model(valid);
        Ok(())
    }

    /// [`Self::set_parameter`] as typed or dragged in a field: a refusal is
    /// kept to show beside the field until a value for it is taken (the
    /// other fields' refusals stay as they are).
    fn enter_parameter(&mut self, key: Key, value: f64) {
        if key == Key::Load {
            // The hand takes the load over from a ramp.
            self.ramp = None;
        }
        let (bar_before, load_before) = (self.load_max(), self.settings.model.load_p());
        match self.set_parameter(key, value) {
            Ok(()) => self.clear_refusal(key),
            Err(why) => self.refuse(key, Refusal::Model(why)),
        }
        if key == Key::Rods && self.load_max() != bar_before && load_before > 0.0 {
            self.scale_load_with_the_bar(bar_before, load_before);
        }
    }

    /// After a change of the rods typed by hand, the load moved as the
    /// load bar scales (`(2/N)^2`): the same place on the bar and the same
    /// `P L^2/EI` (typing 16 rods at p = 2 left the load 16 times past the
    /// chain's bar, the chain whipping under a stick-slip warning), and said.
    fn scale_load_with_the_bar(&mut self, bar_before: f64, load_before: f64) {
        let load = load_before * self.load_max() / bar_before;
        match self.set_parameter(Key::Load, load) {
            Ok(()) => self.say(Notice::info(crate::tr!(
                self.words(),
                "notice-rods-load-moved",
                rods = self.settings.model.column.rods,
                end = crate::format::number_text(self.load_max()),
                from = crate::format::load_text(load_before),
                to = crate::format::load_text(load)
            ))),
            Err(why) => self.say(Notice::warning(crate::tr!(
                self.words(),
                "notice-rods-load-kept",
                rods = self.settings.model.column.rods,
                load = crate::format::load_text(load_before),
                why = i18n::model_error(self.words(), &why)
            ))),
        }
    }

    /// Keeps why a value typed for `key` was refused, to say beside it.
    fn refuse(&mut self, key: Key, why: Refusal) {
        self.clear_refusal(key);
        self.refused.push((key, why));
    }

    /// Forgets a refusal of `key` (the user went back to the applied value).
    fn clear_refusal(&mut self, key: Key) {
        self.refused.retain(|(k, _)| *k != key);
    }

    /// The load slider's range for the current model (see [`Model::load_bar_max_p`]).
    #[must_use]
    pub fn load_max(&self) -> f64 {
        self.settings.model.load_bar_max_p()
    }

    /// Moves the load by `delta_p`, within the slider's range (or toward it
    /// from beyond).
    fn nudge_load(&mut self, delta_p: f64) {
        let p = self.settings.model.load_p();
        let moved = if delta_p > 0.0 {
            (p + delta_p).min(self.load_max().max(p))
        } else {
            (p + delta_p).max(0.0)
        };
        self.enter_parameter(Key::Load, moved);
    }

    /// Switches to the preset `id` at the current load (or, beyond its
    /// slider, its own): its parameters, a fresh run, the overlay at its `a`.
    fn set_preset(&mut self, id: PresetId) {
        self.switch_column(id, id.switched_from(&self.settings.model));
    }

    /// Shows `model` of preset `id`: as a switch of preset (a fresh run)
    /// when `id` is another, as a change of parameters otherwise.
    fn set_column(&mut self, id: PresetId, model: Model) {
        if id == self.settings.preset {
            self.check_and_set_model(model);
        } else {
            self.switch_column(id, model);
        }
    }

    /// All of `settings` in place of the current ones, on a fresh run: the
    /// lesson, the overlay, the open tab and the analysis thread stay.
    /// Nothing changes when they make no run.
    ///
    /// # Errors
    /// Settings that make no valid simulation.
    fn take_settings(&mut self, settings: Settings) -> Result<(), SimError> {
        // Would the run start? (Cheap: no analysis.) The engine it settles on.
        let mut trial = settings;
        start(&mut trial, self.words())?;
        self.switch_column(trial.preset, trial.model);
        if trial.engine != self.settings.engine {
            self.set_engine(trial.engine);
        }
        self.set_speed(trial.speed);
        self.settings.projector = trial.projector;
        Ok(())
    }

    /// Preset `id` with `model`, on a fresh run.
    fn switch_column(&mut self, id: PresetId, model: Model) {
        self.settings.preset = id;
        self.refused.clear();
        // A ramp and its marks belong to the column it ran on.
        self.ramp = None;
        self.check_and_set_model(model);
        self.reset();
    }

    /// Runs the simulation on `engine` from the current state.
    fn set_engine(&mut self, engine: EngineKind) {
        match self.sim.restart_from(engine, self.sim.state()) {
            Ok(()) => self.settings.engine = engine,
            Err(error) => self.say(Notice::error(i18n::sim_error(self.words(), &error))),
        }
    }

    /// Simulated seconds per wall second.
    fn set_speed(&mut self, speed: f64) {
        self.settings.speed = speed;
    }

    /// [`Self::set_model`] for a model made elsewhere (a preset, a map's
    /// point, pasted settings): checked here, once; a refusal is said.
    fn check_and_set_model(&mut self, model: Model) {
        match ValidModel::new(model) {
            Ok(valid) => self.set_model(valid),
            Err(error) => self.say(Notice::error(i18n::model_error(self.words(), &error))),
        }
    }

    /// Applies a changed model to the running simulation; the analysis and
    /// the overlay follow. The model was checked where it was made: nothing
    /// on the way checks it again.
    fn set_model(&mut self, valid: ValidModel) {
        let model = *valid;
        let rods_before = self.sim.model().column.rods;
        let result = match self.sim.set_model(valid) {
            Err(SimError::TooStiffForRapier { .. }) => {
                // rapier cannot follow: the reference engine takes over, and says so.
                let state = self.sim.state();
                let switched = self
                    .sim
                    .restart_from(EngineKind::Reference, state)
                    .and_then(|()| self.sim.set_model(valid));
                if switched.is_ok() {
                    self.settings.engine = EngineKind::Reference;
                    self.say(Notice::warning(crate::tr!(
                        self.words(),
                        SWITCHED_TO_REFERENCE
                    )));
                }
                switched
            }
            other => other,
        };
        match result {
            Ok(()) => {
                if model.column.rods != rods_before {
                    // Another chain started afresh: its trail and history too.
                    self.trail.clear();
                    self.history.clear();
                }
                if model != self.settings.model {
                    // The run goes on with another column: what was measured
                    // belongs to the old one, and so do the samples before now.
                    self.measure_afresh();
                }
                self.settings.model = model;
                self.refresh_analysis();
                if let Some((id, a)) = self.overlay_wanted
                    && a != self.group_a()
                {
                    self.set_overlay(Some(id));
                }
            }
            Err(error) => self.say(Notice::error(i18n::sim_error(self.words(), &error))),
        }
    }

    /// What a click on the map does: the load and the map's second
    /// parameter are set (the run goes on with them); a refused value says why.
    fn set_map_point(&mut self, axis: &Axis, load: f64, value: f64) {
        match axis.apply(&self.settings.model, value) {
            Ok(model) => self.check_and_set_model(model.at_load(load)),
            Err(error) => self.say(Notice::error(crate::tr!(
                self.words(),
                "notice-map-point-refused",
                why = i18n::model_error(self.words(), &error)
            ))),
        }
    }

    /// The current model's `a = k/(m l^2)`.
    fn group_a(&self) -> f64 {
        Key::A.get(&self.settings.model)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switching_preset_recomputes_the_overlay_and_clears_a_refusal() {
        let mut state = AppState::new(Settings::default()).unwrap();
        state.enter_parameter(Key::A, 21.0);
        state.enter_parameter(Key::Nu, -1.0);
        assert!(state.refusal(Key::Nu).is_some());
        state.set_overlay(Some(PresetId::Ziegler1952));
        assert_eq!(state.overlay().unwrap().a, 21.0);
        state.set_preset(PresetId::MidpointMasses);
        assert!(state.refusal(Key::Nu).is_none());
        let overlay = state.overlay().unwrap();
        assert_eq!(overlay.a, state.group_a());
        assert_ne!(overlay.a, 21.0, "the preset's own a");
    }
}
