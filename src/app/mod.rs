//! The interactive visualiser: the animated column, the load slider with its
//! stability ranges, time controls and live root-locus plots. Reads the
//! model, the analysis and the simulation; owns only what it shows.

mod history;
mod map;
mod pace;
mod paradox;
mod plots;
mod scene;
mod store_check;
mod stored;
mod theme;

use std::collections::VecDeque;

use eframe::egui::{self, Color32, RichText, Sense, Stroke, pos2, vec2};

use crate::analysis::{
    AffinePencil, BRACKET_SAMPLES, C64, Locus, Spectrum, State, Transition, classify,
    critical_loads_along, load_label, locus, resolution_warning,
};
use crate::model::{Assignment, Axis, KEYS, KeySpec, Model, PRESETS, apply_assignments, preset};
use crate::sim::{DEFAULT_STEP_SECS, EngineKind, SimError, Simulation, Status, initial_state};
use theme::Theme;

pub use map::map_picture;
pub use pace::{MAX_FRAME_SECS, MAX_STEPS_PER_FRAME};

/// The load slider's range and the locus's, on the common axis p.
pub const LOAD_MAX_P: f64 = 8.0;
/// Evenly spaced loads of the plotted locus (plus the refinement). The same
/// locus brackets the critical loads, with the sample count `critical` uses.
const LOCUS_SAMPLES: usize = BRACKET_SAMPLES;
/// The size of a kick, in rad on both angles.
const KICK_RAD: f64 = 0.01;
/// The key the settings are stored under.
const SETTINGS_KEY: &str = "zieglerlab-settings";
/// eframe's name for the app (its storage folder).
const APP_ID: &str = "zieglerlab";

/// What persists between runs of the app.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    pub preset: String,
    pub model: Model,
    pub engine: EngineKind,
    /// Simulated seconds per wall second.
    pub speed: f64,
    pub projector: bool,
}

impl Default for Settings {
    fn default() -> Self {
        let roller = PRESETS
            .iter()
            .find(|p| p.name == "roller")
            .unwrap_or(&PRESETS[0]);
        Self {
            preset: roller.name.to_owned(),
            model: roller.model(),
            engine: EngineKind::Rapier,
            speed: 1.0,
            projector: false,
        }
    }
}

/// The linear analysis of the current parameters, over the slider's range.
struct Analysis {
    /// The model at p = 0: the locus depends on everything but the load.
    key: Model,
    pencil: AffinePencil,
    locus: Locus,
    transitions: Vec<Transition>,
    /// Why the transitions cannot be trusted, when they cannot.
    warning: Option<String>,
    /// The state at p = 0, where the first range starts.
    first: State,
}

impl Analysis {
    fn new(model: &Model) -> Result<Self, String> {
        let key = model.at_load(0.0);
        let pencil = AffinePencil::new(&key).map_err(|e| e.to_string())?;
        let locus = locus(&pencil, 0.0, LOAD_MAX_P, LOCUS_SAMPLES).map_err(|e| e.to_string())?;
        let transitions = critical_loads_along(&pencil, &locus).map_err(|e| e.to_string())?;
        let warning = resolution_warning(&pencil, &locus).map_err(|e| e.to_string())?;
        let at_zero = pencil.spectrum(0.0).map_err(|e| e.to_string())?;
        let first = classify(&at_zero.eigenvalues, at_zero.scale_per_s).state;
        Ok(Self {
            key,
            pencil,
            locus,
            transitions,
            warning,
            first,
        })
    }
}

/// A number for people and for editing: plain with up to six significant
/// digits from 1e-3 to 1e6, in exponent form outside (so 1e-6 is not shown
/// as 0.0000), "0" for zero.
pub(crate) fn number_text(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 || !value.is_finite() {
        format!("{value}")
    } else if (1e-3..1e6).contains(&magnitude) {
        // Six significant digits, trailing zeros dropped.
        #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
        let decimals = (5 - magnitude.log10().floor() as i32).max(0);
        let text = format!("{value:.*}", decimals.unsigned_abs() as usize);
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    } else {
        let text = format!("{value:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

/// A rate for people: five decimals, or four significant digits when small.
fn rate_text(rate: f64) -> String {
    if rate == 0.0 || rate.abs() >= 1e-3 {
        format!("{rate:+.5}")
    } else {
        format!("{rate:+.3e}")
    }
}

/// A time for people: one decimal from 10 s, three significant digits below.
fn secs_label(secs: f64) -> String {
    if secs >= 10.0 {
        format!("{secs:.1}")
    } else if secs >= 1e-3 {
        format!("{secs:.3}")
    } else {
        format!("{secs:.2e}")
    }
}

/// What the user is told when rapier cannot integrate the column.
const SWITCHED_TO_REFERENCE: &str = "the column is too stiff for the rapier engine at its 1/240 s step (huge damping or stiffness against little mass); switched to the reference engine";

/// A run of the settings' model from the standard kick. When rapier cannot
/// integrate it the reference engine runs instead, the settings say so, and
/// so does the returned message.
fn start(settings: &mut Settings) -> Result<(Simulation, Option<String>), String> {
    let model = settings.model;
    let x0 = initial_state(&model, 1e-3);
    match Simulation::new(model, settings.engine, x0, DEFAULT_STEP_SECS) {
        Ok(sim) => Ok((sim, None)),
        Err(SimError::TooStiffForRapier { .. }) => {
            settings.engine = EngineKind::Reference;
            Simulation::new(model, EngineKind::Reference, x0, DEFAULT_STEP_SECS)
                .map(|sim| (sim, Some(SWITCHED_TO_REFERENCE.to_owned())))
                .map_err(|e| e.to_string())
        }
        Err(error) => Err(error.to_string()),
    }
}

/// The app.
pub struct ZieglerApp {
    settings: Settings,
    sim: Simulation,
    running: bool,
    trail: VecDeque<(f64, [f64; 2])>,
    analysis: Option<Analysis>,
    /// Simulated time against wall-clock time.
    pace: pace::Pace,
    /// When the window's last frame began (the headless paths never set it:
    /// their frames advance by fixed, given times).
    last_frame: Option<std::time::Instant>,
    /// The spectrum at the current load and the model it is for.
    current: Option<(Model, Spectrum)>,
    /// The last problem to tell the user about.
    message: Option<String>,
    /// The theme applied to the context (None: not yet).
    applied_projector: Option<bool>,
    /// The last refused parameter value: its key and why.
    refused: Option<(&'static str, String)>,
    history: history::History,
    /// The column's eigenvalues measured from the run, refreshed about once a
    /// simulated second.
    measured: Option<Vec<C64>>,
    measured_at_secs: f64,
    /// What the lower half shows.
    lower: Tab,
    /// A second model's locus drawn behind the current one (Fig. 8).
    overlay: Option<Overlay>,
    /// The text box for sharing settings.
    shared_text: String,
    /// The stability map (computed while its tab is shown).
    map: map::MapPanel,
    /// The paradox explorer (computed while its tab is shown).
    paradox: paradox::ParadoxPanel,
}

/// Another preset's root locus, at the current model's `a`.
struct Overlay {
    preset: &'static str,
    /// The group `a` the locus was computed with.
    a: f64,
    locus: Locus,
}

/// What a headless picture shows: the whole window or one panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    Window,
    Locus,
    Scene,
    Histories,
    Map,
    Paradox,
}

/// The choice of plots in the lower half of the window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tab {
    Locus,
    Histories,
    Map,
    Paradox,
}

impl ZieglerApp {
    /// The app with `settings`, its run started from the standard kick.
    ///
    /// # Errors
    /// Settings that make no valid model or simulation.
    pub fn new(mut settings: Settings) -> Result<Self, String> {
        let (sim, message) = start(&mut settings)?;
        let mut app = Self {
            settings,
            sim,
            running: true,
            trail: VecDeque::new(),
            analysis: None,
            pace: pace::Pace::default(),
            current: None,
            last_frame: None,
            message,
            applied_projector: None,
            refused: None,
            history: history::History::default(),
            measured: None,
            measured_at_secs: f64::NEG_INFINITY,
            lower: Tab::Locus,
            overlay: None,
            shared_text: String::new(),
            map: map::MapPanel::default(),
            paradox: paradox::ParadoxPanel::default(),
        };
        app.refresh_analysis();
        Ok(app)
    }

    /// The app from eframe's stored settings, or the defaults (saying what
    /// was ignored).
    #[must_use]
    pub fn from_storage(storage: Option<&dyn eframe::Storage>) -> Self {
        let text = storage.and_then(|s| s.get_string(SETTINGS_KEY));
        Self::from_stored_text(text.as_deref())
    }

    /// The app from settings stored as text (RON, as eframe writes them):
    /// every field that reads and makes sense is kept, the others take their
    /// defaults, and a message names them.
    #[must_use]
    pub fn from_stored_text(text: Option<&str>) -> Self {
        let Some(text) = text else {
            return Self::defaults();
        };
        let (read, note) = match stored::read(text) {
            Ok(read) if read.ignored.is_empty() => (read.settings, None),
            Ok(read) => {
                let note = format!(
                    "stored settings: ignored {}; kept the rest",
                    read.ignored.join(", ")
                );
                (read.settings, Some(note))
            }
            Err(error) => (
                Settings::default(),
                Some(format!(
                    "stored settings ignored ({error}); starting from the defaults"
                )),
            ),
        };
        let mut app = match Self::new(read) {
            Ok(app) => app,
            Err(error) => {
                let mut app = Self::defaults();
                app.message = Some(format!(
                    "stored settings ignored ({error}); starting from the defaults"
                ));
                return app;
            }
        };
        if let Some(note) = note {
            app.message = Some(match app.message.take() {
                Some(started) => format!("{note}; {started}"),
                None => note,
            });
        }
        app
    }

    fn defaults() -> Self {
        // The roller preset is valid by construction; this cannot fail.
        match Self::new(Settings::default()) {
            Ok(app) => app,
            Err(error) => unreachable!("the default settings are valid: {error}"),
        }
    }

    /// The settings in use.
    #[must_use]
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Sets one parameter by its key (as `--set` does): the model changes for
    /// the running simulation and the analysis follows; a refused value
    /// changes nothing and the error says why.
    ///
    /// # Errors
    /// The key's or the model's validation message.
    pub fn set_parameter(&mut self, key: &str, value: f64) -> Result<(), String> {
        let mut candidate = self.settings.model;
        let assignment = Assignment {
            key: key.to_owned(),
            value,
        };
        apply_assignments(&mut candidate, &self.settings.preset, &[assignment])
            .map_err(|e| e.to_string())?;
        self.set_model(candidate);
        Ok(())
    }

    /// Whether a root locus and critical loads exist for the current parameters.
    #[must_use]
    pub fn has_analysis(&self) -> bool {
        self.analysis.is_some()
    }

    /// The last message for the user, if any.
    #[must_use]
    pub fn message(&self) -> Option<&str> {
        self.message.as_deref()
    }

    /// Adds `text` to what the message line tells the user.
    pub fn tell(&mut self, text: String) {
        self.message = Some(match self.message.take() {
            Some(earlier) => format!("{earlier}; {text}"),
            None => text,
        });
    }

    /// Shows `tab` in the lower half of the window.
    pub fn show_tab(&mut self, tab: Tab) {
        self.lower = tab;
    }

    /// The running simulation.
    #[must_use]
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    /// Advances the run by `wall_secs` of wall-clock time at the chosen speed
    /// (whole engine steps, the remainder carried; see [`pace::Pace`]).
    pub fn advance(&mut self, wall_secs: f64) {
        if !self.running {
            self.pace.restart();
            return;
        }
        let steps = self
            .pace
            .steps(wall_secs, self.settings.speed, self.sim.step_secs());
        for _ in 0..steps {
            if self.sim.step() != Status::Running {
                self.running = false;
                self.pace.restart();
                break;
            }
            let now = self.sim.observe();
            scene::push_trail(&mut self.trail, &now);
            self.history.push(now);
        }
        let t = self.sim.time_secs();
        if t - self.measured_at_secs >= 1.0 {
            // Two exponentials per oscillating mode of the column.
            self.measured = self.history.measured(4);
            self.measured_at_secs = t;
        }
    }

    /// Recomputes the locus and the critical loads when the parameters
    /// (anything but the load) changed; keeps them otherwise.
    fn refresh_analysis(&mut self) {
        let key = self.settings.model.at_load(0.0);
        if self.analysis.as_ref().is_some_and(|a| a.key == key) {
            return;
        }
        match Analysis::new(&self.settings.model) {
            Ok(analysis) => self.analysis = Some(analysis),
            Err(error) => {
                // No stale plots: the old locus belongs to other parameters.
                self.analysis = None;
                self.message = Some(format!("analysis unavailable: {error}"));
            }
        }
    }

    /// The current model's `a = k/(m l^2)`.
    fn group_a(&self) -> f64 {
        KEYS.iter()
            .find(|k| k.key == "a")
            .map_or(f64::NAN, |k| k.get(&self.settings.model))
    }

    /// Shows `name`'s locus behind the current one, at the current `a`.
    fn set_overlay(&mut self, name: Option<&'static str>) {
        let Some(name) = name else {
            self.overlay = None;
            return;
        };
        let a = self.group_a();
        let build = || -> Result<Locus, String> {
            let mut model = preset(name).map_err(|e| e.to_string())?.model();
            let set_a = Assignment {
                key: "a".to_owned(),
                value: a,
            };
            apply_assignments(&mut model, name, &[set_a]).map_err(|e| e.to_string())?;
            let pencil = AffinePencil::new(&model).map_err(|e| e.to_string())?;
            locus(&pencil, 0.0, LOAD_MAX_P, LOCUS_SAMPLES).map_err(|e| e.to_string())
        };
        match build() {
            Ok(locus) => {
                self.overlay = Some(Overlay {
                    preset: name,
                    a,
                    locus,
                });
            }
            Err(error) => self.message = Some(format!("overlay unavailable: {error}")),
        }
    }

    /// Applies a changed model to the running simulation.
    fn set_model(&mut self, model: Model) {
        let result = match self.sim.set_model(model) {
            Err(SimError::TooStiffForRapier { .. }) => {
                // rapier cannot follow: the reference engine takes over, and says so.
                let state = self.sim.state();
                let switched = self
                    .sim
                    .restart_from(EngineKind::Reference, state)
                    .and_then(|()| self.sim.set_model(model));
                if switched.is_ok() {
                    self.settings.engine = EngineKind::Reference;
                    self.message = Some(SWITCHED_TO_REFERENCE.to_owned());
                }
                switched
            }
            other => other,
        };
        match result {
            Ok(()) => {
                self.settings.model = model;
                self.refresh_analysis();
                if let Some(overlay) = &self.overlay
                    && overlay.a != self.group_a()
                {
                    self.set_overlay(Some(overlay.preset));
                }
            }
            Err(error) => self.message = Some(error.to_string()),
        }
    }

    fn reset(&mut self) {
        match start(&mut self.settings) {
            Ok((sim, message)) => {
                if message.is_some() {
                    self.message = message;
                }
                self.sim = sim;
                self.trail.clear();
                self.history.clear();
                self.measured = None;
                self.pace.restart();
                self.running = true;
            }
            Err(error) => self.message = Some(error),
        }
    }

    fn kick(&mut self) {
        let mut x = self.sim.state();
        x[0] += KICK_RAD;
        x[1] += KICK_RAD;
        if let Err(error) = self.sim.restart_from(self.sim.engine(), x) {
            self.message = Some(error.to_string());
        }
        self.running = true;
    }

    /// Sets the load as typed or dragged: any valid p, also beyond the
    /// slider's range; a refused value (negative, not finite) says why.
    fn set_load(&mut self, p: f64) {
        match self.set_parameter("load", p) {
            Ok(()) => self.refused = None,
            Err(error) => self.refused = Some(("load", error)),
        }
    }

    fn keyboard(&mut self, ctx: &egui::Context) {
        let step = 0.01 * LOAD_MAX_P;
        let (space, up, down, kick, reset, projector) = ctx.input(|i| {
            (
                i.key_pressed(egui::Key::Space),
                i.key_pressed(egui::Key::ArrowRight) || i.key_pressed(egui::Key::ArrowUp),
                i.key_pressed(egui::Key::ArrowLeft) || i.key_pressed(egui::Key::ArrowDown),
                i.key_pressed(egui::Key::K),
                i.key_pressed(egui::Key::R),
                i.key_pressed(egui::Key::P),
            )
        });
        if ctx.egui_wants_keyboard_input() {
            return;
        }
        if space {
            self.running = !self.running;
        }
        // The arrows move the load within the slider's range.
        let p = self.settings.model.load_p();
        if up {
            self.set_load((p + step).min(LOAD_MAX_P.max(p)));
        }
        if down {
            self.set_load((p - step).max(0.0));
        }
        if kick {
            self.kick();
        }
        if reset {
            self.reset();
        }
        if projector {
            self.settings.projector = !self.settings.projector;
        }
    }

    /// The current theme, applied to the context when it changed.
    fn applied_theme(&mut self, ctx: &egui::Context) -> Theme {
        let theme = self.theme();
        if self.applied_projector != Some(self.settings.projector) {
            theme.apply(ctx);
            self.applied_projector = Some(self.settings.projector);
        }
        theme
    }

    fn theme(&self) -> Theme {
        if self.settings.projector {
            Theme::PROJECTOR
        } else {
            Theme::NORMAL
        }
    }

    /// The whole window's contents. Reads the state; the simulation advances
    /// only in [`ZieglerApp::advance`], so a picture depends on the state alone.
    pub fn contents_ui(&mut self, ui: &mut egui::Ui) {
        self.refresh_current_spectrum();
        let theme = self.applied_theme(ui.ctx());
        egui::Panel::left("controls")
            .resizable(false)
            .exact_size(320.0)
            .show(ui, |ui| {
                egui::ScrollArea::vertical().show(ui, |ui| self.controls_ui(ui, &theme));
            });
        egui::CentralPanel::default().show(ui, |ui| {
            let height = ui.available_height();
            let now = self.sim.observe();
            ui.allocate_ui(vec2(ui.available_width(), 0.55 * height), |ui| {
                scene::scene_ui(
                    ui,
                    &scene::SceneInput {
                        model: &self.settings.model,
                        now: &now,
                        trail: &self.trail,
                        status: self.sim.status(),
                        theme: &theme,
                    },
                );
            });
            self.plots_ui(ui, &theme);
        });
    }

    /// One panel alone (for snapshots and figures).
    pub fn panel_ui(&mut self, ui: &mut egui::Ui, panel: Panel) {
        self.refresh_current_spectrum();
        let theme = self.applied_theme(ui.ctx());
        match panel {
            Panel::Window => self.contents_ui(ui),
            Panel::Locus => self.locus_panel_ui(ui, &theme),
            Panel::Scene => {
                let now = self.sim.observe();
                let input = scene::SceneInput {
                    model: &self.settings.model,
                    now: &now,
                    trail: &self.trail,
                    status: self.sim.status(),
                    theme: &theme,
                };
                egui::CentralPanel::default().show(ui, |ui| scene::scene_ui(ui, &input));
            }
            Panel::Histories => {
                egui::CentralPanel::default()
                    .show(ui, |ui| plots::histories_ui(ui, &self.history, &theme));
            }
            Panel::Map => {
                egui::CentralPanel::default().show(ui, |ui| self.map_ui(ui, &theme));
            }
            Panel::Paradox => {
                let preset = self.settings.preset.clone();
                egui::CentralPanel::default().show(ui, |ui| {
                    self.paradox.ui(ui, &self.settings.model, &preset, &theme);
                });
            }
        }
    }

    /// The stability map of the current parameters; a click on it sets the
    /// load and the map's second parameter.
    fn map_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        let preset = self.settings.preset.clone();
        self.map.follow(&self.settings.model, &preset, LOAD_MAX_P);
        if let Some(pick) = self.map.ui(ui, &self.settings.model, &preset, theme) {
            self.set_map_point(&pick.axis, pick.load, pick.value);
        }
    }

    /// What a click on the map does: the load and the map's second
    /// parameter are set (the run goes on with them); a refused value says why.
    pub fn set_map_point(&mut self, axis: &Axis, load: f64, value: f64) {
        match axis.apply(&self.settings.model, &self.settings.preset, value) {
            Ok(model) => self.set_model(model.at_load(load)),
            Err(error) => self.message = Some(format!("map: {error}")),
        }
    }

    /// Computes the stability map and the paradox curves of the current
    /// parameters and waits until they are complete (for pictures and tests;
    /// the window never waits).
    pub fn complete_background_work(&mut self) {
        let preset = self.settings.preset.clone();
        self.map.follow(&self.settings.model, &preset, LOAD_MAX_P);
        self.map.wait();
        self.paradox.wait(&self.settings.model, &preset);
    }

    /// The root locus of the current analysis with the current, overlaid
    /// and measured eigenvalues.
    fn root_locus_ui(&self, ui: &mut egui::Ui, analysis: &Analysis, theme: &Theme) {
        let overlay = self.overlay.as_ref().map(|o| &o.locus);
        let current = self.current_eigenvalues();
        plots::root_locus_ui(
            ui,
            &analysis.locus,
            overlay,
            &current,
            self.measured.as_deref(),
            theme,
        );
    }

    fn locus_panel_ui(&self, ui: &mut egui::Ui, theme: &Theme) {
        egui::CentralPanel::default().show(ui, |ui| match &self.analysis {
            Some(analysis) => self.root_locus_ui(ui, analysis, theme),
            None => {
                ui.label("No root locus for these parameters.");
            }
        });
    }

    fn current_eigenvalues(&self) -> Vec<C64> {
        self.current_spectrum()
            .map(|s| s.all().collect())
            .unwrap_or_default()
    }

    /// The spectrum at the current load, computed once per change of the
    /// model (the status card and the plots' markers read it).
    fn refresh_current_spectrum(&mut self) {
        let model = self.settings.model;
        if self.current.as_ref().is_some_and(|(m, _)| *m == model) {
            return;
        }
        self.current = self
            .analysis
            .as_ref()
            .and_then(|a| a.pencil.spectrum(model.load_p()).ok())
            .map(|spectrum| (model, spectrum));
    }

    /// The spectrum at the current load, if the current model has one.
    fn current_spectrum(&self) -> Option<&Spectrum> {
        self.current
            .as_ref()
            .filter(|(m, _)| *m == self.settings.model && self.analysis.is_some())
            .map(|(_, spectrum)| spectrum)
    }

    fn plots_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        ui.horizontal(|ui| {
            ui.selectable_value(&mut self.lower, Tab::Locus, "root locus");
            ui.selectable_value(&mut self.lower, Tab::Histories, "time histories");
            ui.selectable_value(&mut self.lower, Tab::Map, "stability map");
            ui.selectable_value(&mut self.lower, Tab::Paradox, "paradox");
        });
        match self.lower {
            Tab::Histories => {
                plots::histories_ui(ui, &self.history, theme);
                return;
            }
            Tab::Map => {
                self.map_ui(ui, theme);
                return;
            }
            Tab::Paradox => {
                let preset = self.settings.preset.clone();
                self.paradox.ui(ui, &self.settings.model, &preset, theme);
                return;
            }
            Tab::Locus => {}
        }
        let Some(analysis) = &self.analysis else {
            ui.label("No root locus for these parameters.");
            return;
        };
        let load = self.settings.model.load_p();
        let ranges = plots::ranges(&analysis.transitions, analysis.first, LOAD_MAX_P);
        let overlay = self.overlay.as_ref().map(|o| &o.locus);
        let width = ui.available_width();
        let height = ui.available_height();
        ui.horizontal(|ui| {
            ui.allocate_ui(vec2(0.42 * width, height), |ui| {
                self.root_locus_ui(ui, analysis, theme);
            });
            ui.vertical(|ui| {
                ui.allocate_ui(vec2(ui.available_width(), 0.5 * height - 4.0), |ui| {
                    plots::versus_load_ui(
                        ui,
                        &analysis.locus,
                        overlay,
                        &ranges,
                        load,
                        false,
                        theme,
                    );
                });
                ui.allocate_ui(vec2(ui.available_width(), 0.5 * height - 4.0), |ui| {
                    plots::versus_load_ui(ui, &analysis.locus, overlay, &ranges, load, true, theme);
                });
            });
        });
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        ui.heading("zieglerlab");
        if let Some(message) = self.message.clone() {
            ui.horizontal_wrapped(|ui| {
                ui.colored_label(theme.divergence, message);
                if ui.small_button("dismiss").clicked() {
                    self.message = None;
                }
            });
        }
        ui.separator();
        // The model.
        let mut chosen = self.settings.preset.clone();
        let shown = |name: &str| {
            preset(name).map_or_else(
                |_| name.to_owned(),
                |p| format!("{} ({})", p.name, p.source),
            )
        };
        // The label first and the name cut to the panel's width, so that a
        // long name in projector mode does not squeeze the label.
        ui.horizontal(|ui| {
            let label = ui.label("model");
            egui::ComboBox::from_id_salt("model")
                .selected_text(shown(&chosen))
                .width(ui.available_width() - ui.spacing().icon_width)
                .truncate()
                .show_ui(ui, |ui| {
                    for p in &PRESETS {
                        ui.selectable_value(&mut chosen, p.name.to_owned(), shown(p.name))
                            .on_hover_text(p.description);
                    }
                })
                .response
                .labelled_by(label.id);
        });
        if chosen != self.settings.preset
            && let Ok(preset) = preset(&chosen)
        {
            self.settings.preset = chosen;
            self.settings.model = preset.model().at_load(self.settings.model.load_p());
            self.refresh_analysis();
            self.reset();
        }
        if let Ok(p) = preset(&self.settings.preset) {
            ui.label(RichText::new(p.description).small());
        }
        let mut engine = self.settings.engine;
        egui::ComboBox::from_label("engine")
            .selected_text(format!("{engine:?}").to_lowercase())
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut engine, EngineKind::Rapier, "rapier")
                    .on_hover_text("rapier2d multibody, the roller's spin implicit");
                ui.selectable_value(&mut engine, EngineKind::Reference, "reference")
                    .on_hover_text("adaptive Dormand-Prince 5(4) on the exact equations");
            });
        if engine != self.settings.engine {
            match self.sim.restart_from(engine, self.sim.state()) {
                Ok(()) => self.settings.engine = engine,
                Err(error) => self.message = Some(error.to_string()),
            }
        }
        ui.separator();
        self.load_ui(ui, theme);
        ui.separator();
        self.parameters_ui(ui, theme);
        ui.separator();
        self.time_ui(ui, theme);
        ui.separator();
        self.status_ui(ui, theme);
        ui.separator();
        self.overlay_ui(ui);
        ui.checkbox(&mut self.settings.projector, "projector mode (P)");
        self.share_ui(ui);
        egui::CollapsingHeader::new("keys").show(ui, |ui| {
            for (key, what) in [
                ("space", "play / pause"),
                ("left, right", "load down / up by 0.08"),
                ("K", "kick (0.01 rad)"),
                ("R", "reset"),
                ("P", "projector mode"),
            ] {
                ui.horizontal(|ui| {
                    ui.monospace(format!("{key:>5}"));
                    ui.label(what);
                });
            }
        });
    }

    fn overlay_ui(&mut self, ui: &mut egui::Ui) {
        let current = self.overlay.as_ref().map(|o| o.preset);
        let mut chosen = current;
        egui::ComboBox::from_label("overlay")
            .selected_text(chosen.unwrap_or("none"))
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut chosen, None, "none");
                for p in &PRESETS {
                    ui.selectable_value(&mut chosen, Some(p.name), p.name);
                }
            })
            .response
            .on_hover_text("another model's locus in grey, at the same a (as Fig. 8 sets the ideal column beside the roller)");
        if chosen != current {
            self.set_overlay(chosen);
        }
    }

    /// Copy the settings as text to share a setup; paste text to load one.
    fn share_ui(&mut self, ui: &mut egui::Ui) {
        egui::CollapsingHeader::new("share settings").show(ui, |ui| {
            ui.horizontal(|ui| {
                if ui.button("copy settings").clicked() {
                    match ron::to_string(&self.settings) {
                        Ok(text) => {
                            ui.ctx().copy_text(text.clone());
                            self.shared_text = text;
                        }
                        Err(error) => self.message = Some(format!("settings not copied: {error}")),
                    }
                }
                if ui
                    .button("paste settings")
                    .on_hover_text("paste the text below first")
                    .clicked()
                {
                    self.paste_settings(&self.shared_text.clone());
                }
            });
            ui.add(
                egui::TextEdit::multiline(&mut self.shared_text)
                    .desired_rows(3)
                    .hint_text("paste settings text here"),
            );
        });
    }

    /// Loads settings from shared text; garbage leaves everything as it was
    /// and says why.
    pub fn paste_settings(&mut self, text: &str) {
        let settings = match stored::read(text) {
            Ok(read) if read.ignored.is_empty() => read.settings,
            Ok(read) => {
                self.message = Some(format!(
                    "pasted settings refused, nothing changed: {} not understood",
                    read.ignored.join(", ")
                ));
                return;
            }
            Err(error) => {
                self.message = Some(format!(
                    "pasted settings not understood, nothing changed: {error}"
                ));
                return;
            }
        };
        match Self::new(settings) {
            Ok(app) => {
                let message = Some("settings pasted".to_owned());
                *self = Self { message, ..app };
            }
            Err(error) => {
                self.message = Some(format!("pasted settings refused, nothing changed: {error}"));
            }
        }
    }

    /// A field for every parameter of the current model: the paper's groups
    /// first, the SI values below. Values go through the same validation as
    /// `--set`: a refused value leaves the model as it was and says why.
    fn parameters_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        let model = self.settings.model;
        let applicable: Vec<&'static KeySpec> = KEYS
            .iter()
            .filter(|k| k.applies_to(&model) && k.key != "load")
            .collect();
        let (groups, si): (Vec<_>, Vec<_>) = applicable.into_iter().partition(|k| k.is_group);
        ui.label("dimensionless groups");
        for spec in groups {
            self.parameter_field(ui, theme, spec);
        }
        egui::CollapsingHeader::new("SI parameters").show(ui, |ui| {
            for spec in si {
                self.parameter_field(ui, theme, spec);
            }
        });
    }

    fn parameter_field(&mut self, ui: &mut egui::Ui, theme: &Theme, spec: &'static KeySpec) {
        let mut value = spec.get(&self.settings.model);
        let response = ui
            .horizontal(|ui| {
                let speed = (value.abs() * 0.01).max(1e-4);
                let r = ui
                    .add(
                        egui::DragValue::new(&mut value)
                            .speed(speed)
                            .custom_formatter(|v, _| number_text(v)),
                    )
                    .accessible_name(spec.key);
                // Only mu R enters the equations (physics.md section 5): the
                // mu field keeps R and so moves the load, and says so.
                let note = if spec.key == "mu" {
                    "  (R held: moves p)"
                } else {
                    ""
                };
                ui.label(format!("{} {}{note}", spec.key, spec.unit));
                r
            })
            .inner
            .on_hover_text(format!("{} (allowed: {})", spec.description, spec.range));
        if response.changed() {
            self.refused = self
                .set_parameter(spec.key, value)
                .err()
                .map(|why| (spec.key, why));
        }
        if let Some((key, why)) = &self.refused
            && *key == spec.key
        {
            ui.colored_label(theme.divergence, format!("refused: {why}"));
        }
    }

    /// The load slider with the stability ranges drawn under it.
    fn load_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        let mut p = self.settings.model.load_p();
        // A typed load beyond the slider's range is taken as typed, not clamped.
        let response = ui.add(
            egui::Slider::new(&mut p, 0.0..=LOAD_MAX_P)
                .clamping(egui::SliderClamping::Never)
                .text("load p = P l/k"),
        );
        if response.changed() {
            self.set_load(p);
        }
        if let Some((key, why)) = &self.refused
            && *key == "load"
        {
            ui.colored_label(theme.divergence, format!("refused: {why}"));
        }
        let p = self.settings.model.load_p();
        if let Some(roller) = self.settings.model.roller() {
            ui.label(format!(
                "roller: q = R l/k = p/μ = {:.3}   (μ = {})",
                p / roller.mu,
                roller.mu
            ));
        }
        if p > LOAD_MAX_P {
            ui.colored_label(
                theme.flutter,
                format!("p = {p} is beyond the plotted range (0 to {LOAD_MAX_P}); the status below is at p"),
            );
        }
        let Some(analysis) = &self.analysis else {
            return;
        };
        let ranges = plots::ranges(&analysis.transitions, analysis.first, LOAD_MAX_P);
        let (rect, _) = ui.allocate_exact_size(vec2(ui.available_width(), 14.0), Sense::hover());
        let painter = ui.painter_at(rect);
        #[expect(clippy::cast_possible_truncation, reason = "pixels")]
        let x_of = |load: f64| rect.left() + rect.width() * (load / LOAD_MAX_P) as f32;
        for &(start, end, state) in &ranges {
            let r = egui::Rect::from_min_max(
                pos2(x_of(start), rect.top()),
                pos2(x_of(end), rect.bottom()),
            );
            painter.rect_filled(r, 0.0, theme.state_color(state));
        }
        let x = x_of(self.settings.model.load_p());
        painter.line_segment(
            [pos2(x, rect.top() - 2.0), pos2(x, rect.bottom() + 2.0)],
            Stroke::new(3.0, Color32::WHITE),
        );
        for t in &analysis.transitions {
            ui.label(
                RichText::new(format!(
                    "p = {}: {} -> {}",
                    load_label(t.load),
                    t.from.name(),
                    t.to.name()
                ))
                .color(theme.state_color(t.to)),
            );
        }
        if let Some(warning) = &analysis.warning {
            ui.colored_label(
                theme.flutter,
                "the stability is not resolved here (hover for why)",
            )
            .on_hover_text(warning);
        }
    }

    fn time_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        ui.horizontal(|ui| {
            if ui
                .button(if self.running { "pause" } else { "play" })
                .clicked()
            {
                self.running = !self.running;
            }
            if ui.button("step").clicked() {
                self.running = false;
                self.sim.step();
                scene::push_trail(&mut self.trail, &self.sim.observe());
            }
            if ui.button("kick").clicked() {
                self.kick();
            }
            if ui.button("reset").clicked() {
                self.reset();
            }
        });
        ui.add(
            egui::Slider::new(&mut self.settings.speed, stored::SPEED_RANGE)
                .logarithmic(true)
                .text("× speed"),
        );
        let state = if !self.running && self.sim.status() == Status::Running {
            "paused".to_owned()
        } else {
            self.sim.status().to_string()
        };
        ui.label(format!("t = {:.2} s   ({state})", self.sim.time_secs()));
        if self.running
            && let Some(achieved) = self.pace.lagging(self.settings.speed)
        {
            ui.colored_label(
                theme.flutter,
                format!(
                    "running at {}x: this computer cannot keep up at {}x",
                    number_text(achieved),
                    number_text(self.settings.speed)
                ),
            );
        }
    }

    /// The stability of the current load in words and numbers.
    fn status_ui(&self, ui: &mut egui::Ui, theme: &Theme) {
        let (Some(analysis), Some(spectrum)) = (&self.analysis, self.current_spectrum()) else {
            return;
        };
        let s = classify(&spectrum.eigenvalues, spectrum.scale_per_s);
        let growth = s.growth_rate_per_s();
        let frequency = s.frequency_rad_per_s();
        let weak = s.state == State::Flutter && growth < 0.01 * frequency;
        let title = match (s.state, weak) {
            (State::Flutter, true) => "weak flutter".to_owned(),
            (state, _) => state.name().to_owned(),
        };
        ui.label(
            RichText::new(title)
                .heading()
                .color(theme.state_color(s.state)),
        );
        if growth.abs() <= s.tolerance_per_s {
            // Rounding's share of the real part: say zero, and to what accuracy.
            ui.label(format!(
                "growth rate  0 (to within {:.0e} 1/s)",
                s.tolerance_per_s
            ));
        } else {
            ui.label(format!("growth rate  {} 1/s", rate_text(growth)));
        }
        if analysis.warning.is_some() {
            ui.colored_label(
                theme.flutter,
                "not resolved at these parameters: see the warning under the load",
            );
        }
        match s.e_folding_secs() {
            Some(secs) => ui.label(format!("e-folding time  {} s", secs_label(secs))),
            None if growth < 0.0 => {
                ui.label(format!("decay time  {} s", secs_label(-1.0 / growth)))
            }
            None => ui.label("neutral: no growth, no decay"),
        };
        if frequency > s.tolerance_per_s {
            let period = std::f64::consts::TAU / frequency;
            ui.label(format!(
                "frequency  {frequency:.4} rad/s  (period {} s)",
                secs_label(period)
            ));
        } else {
            ui.label("non-oscillatory: the dominant eigenvalue is real");
        }
        match self.measured.as_ref().and_then(|m| m.first()) {
            Some(z) => ui.label(format!(
                "measured from the run  {:+.5} ± {:.4}i 1/s",
                z.re,
                z.im.abs()
            )),
            None => ui.label(
                RichText::new("measured: after 20 s of small-amplitude motion (|φ| < 0.05 rad)")
                    .small(),
            ),
        };
        if weak {
            ui.label(
                RichText::new(format!(
                    "grows by {:.2}% per period: watch for minutes, not seconds",
                    100.0 * (growth * std::f64::consts::TAU / frequency).exp_m1()
                ))
                .small(),
            );
        }
    }
}

impl eframe::App for ZieglerApp {
    fn logic(&mut self, ctx: &egui::Context, _frame: &mut eframe::Frame) {
        self.keyboard(ctx);
        // The wall clock, read here and only here: everything below takes the
        // elapsed time as a number, so tests and pictures can give their own.
        let now = std::time::Instant::now();
        let wall_secs = self
            .last_frame
            .map_or(0.0, |last| now.duration_since(last).as_secs_f64());
        self.last_frame = Some(now);
        self.advance(wall_secs);
        if self.running {
            ctx.request_repaint();
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.contents_ui(ui);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        match ron::to_string(&self.settings) {
            Ok(text) => storage.set_string(SETTINGS_KEY, text),
            Err(error) => self.message = Some(format!("settings not saved: {error}")),
        }
    }
}

/// Opens the app window.
///
/// # Errors
/// When no window or graphics context can be created.
pub fn run() -> eframe::Result {
    // eframe restores its own entries (zoom, window) before any of ours runs:
    // they are checked first, so a bad one cannot crash every launch.
    let notice = eframe::storage_dir(APP_ID)
        .map(|dir| dir.join("app.ron"))
        .and_then(|path| store_check::check_stored_file(&path));
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("zieglerlab")
            .with_inner_size([1280.0, 800.0])
            .with_min_inner_size([1024.0, 700.0]),
        ..Default::default()
    };
    eframe::run_native(
        APP_ID,
        options,
        Box::new(move |cc| {
            let mut app = ZieglerApp::from_storage(cc.storage);
            if let Some(notice) = notice {
                app.tell(notice);
            }
            Ok(Box::new(app))
        }),
    )
}

#[cfg(test)]
mod tests {
    use super::number_text;

    #[test]
    fn numbers_keep_their_significant_digits() {
        for (value, text) in [
            (0.0, "0"),
            (0.1, "0.1"),
            (0.123_456_789, "0.123457"),
            (1234.5, "1234.5"),
            (-0.001, "-0.001"),
            (1e-6, "1e-6"),
            (2.5e6, "2.5e6"),
            (3.0, "3"),
        ] {
            assert_eq!(number_text(value), text, "{value}");
            let read: f64 = text.parse().unwrap();
            assert!((read - value).abs() <= 5e-6 * value.abs(), "{value}");
        }
    }
}
