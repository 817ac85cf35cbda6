//! The interactive visualiser: the window's layout (the sidebar, the
//! animated scene, the tabs of plots), its keyboard and eframe's hooks. What
//! it shows lives in [`state::AppState`]; every part of the window is a
//! [`View`] of it in a file of its own.

mod action;
mod analysis_cache;
mod arrows;
mod camera;
mod exports;
mod file_dialog;
mod grab;
mod history;
mod jobs;
mod layout;
mod legend;
mod load_bar;
mod notice;
mod pace;
mod panel;
mod panel_picture;
mod panels;
mod plot_draw;
mod plot_frame;
mod plot_keys;
mod plots;
mod record_menu;
mod recorder;
mod scene;
mod scene_access;
mod scene_words;
mod settings;
mod settings_text;
mod sidebar;
mod speak;
mod state;
mod store_check;
mod tab;
mod tabs;
mod theme;
mod welcome;
mod window;
mod zoom;

use eframe::egui::{self, RichText, vec2};

use crate::i18n::Language;
use crate::sim::{SimError, Simulation};
use crate::tr;
use action::Actions;
use speak::Speak as _;

pub use crate::plot::view::{EdgeMark, Side, ViewRect};
pub use action::{Action, Command};
pub use analysis_cache::{Analysis, window_locus};
pub use layout::Layout;
pub use notice::{Level, Notice};
pub use pace::{MAX_FRAME_SECS, MAX_STEPS_PER_FRAME};
pub use panel::{Panel, SMALLEST_WINDOW_POINTS};
pub use plot_draw::{LOCUS_SHOWN_ID, LocusShown};
pub use plot_frame::VIEW_HINT;
pub use state::{AppState, Settings};
pub use tabs::Tab;
pub use theme::Theme;
use theme::color;
pub use window::{Renderer, WindowFrames, run, time_window_frames};

/// The key the settings are stored under.
const SETTINGS_KEY: &str = "zieglerlab-settings";
/// The key the window's layout is stored under.
const LAYOUT_KEY: &str = "zieglerlab-layout";
/// Below this height (in points, at the normal text size) the tab's plots
/// would be unreadable and are not drawn.
const MIN_PLOT_HEIGHT: f32 = 170.0;
/// eframe's name for the app (its storage folder).
const APP_ID: &str = "zieglerlab";

/// One part of the window, drawn from the app's state: a sidebar section or
/// a tab. It reads the state and asks for changes in `actions`; they are
/// applied before the next frame is drawn.
pub trait View {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme);
}

/// The app: its state and the views that draw it.
pub struct ZieglerApp {
    state: AppState,
    sidebar: sidebar::Sidebar,
    /// What the lower half shows.
    tab: Tab,
    tabs: tabs::Tabs,
    /// The theme applied to the context (None: not yet).
    applied_projector: Option<bool>,
    /// The record button's choice and its work.
    record_choice: record_menu::RecordChoice,
    recorder: recorder::Recorder,
    /// Tables saved to files.
    exports: exports::Exports,
    /// The open tab's plots saved as a picture, and where the tab was drawn
    /// in the last frame.
    picture: panel_picture::PanelPicture,
    tab_rect: egui::Rect,
    /// How the scene frames the column, and what the mouse holds.
    scene: scene::SceneView,
    /// The state's "reset all" count this view last followed.
    view_generation: u64,
    /// When the window's last frame began (the headless paths never set it:
    /// their frames advance by fixed, given times).
    last_frame: Option<std::time::Instant>,
    /// What the views asked for while the last frame was drawn.
    actions: Actions,
    /// The input's clock at the last frame (a recording starts by it).
    input_secs: f64,
    /// Full screen was asked for (F11): the window is told at the next
    /// `apply_pending`, which has its context.
    full_screen_asked: bool,
    /// Whether what draws the frames clears them to the panels' colour
    /// first (the window; a headless picture starts transparent).
    cleared_to_panel_fill: bool,
    /// Every frame is drawn for a picture (the command line's).
    for_pictures: bool,
    /// Where paths to save to are asked (see [`Self::type_paths`]).
    paths_asked: file_dialog::PathsAsked,
}

impl ZieglerApp {
    /// The app with `settings`, its run started from the standard kick.
    ///
    /// # Errors
    /// Settings that make no valid simulation.
    pub fn new(settings: Settings) -> Result<Self, SimError> {
        AppState::new(settings).map(Self::with_state)
    }

    fn with_state(state: AppState) -> Self {
        Self {
            state,
            sidebar: sidebar::Sidebar::default(),
            tab: Tab::default(),
            tabs: tabs::Tabs::default(),
            applied_projector: None,
            view_generation: 0,
            scene: scene::SceneView::default(),
            record_choice: record_menu::RecordChoice::default(),
            recorder: recorder::Recorder::default(),
            exports: exports::Exports::default(),
            picture: panel_picture::PanelPicture::default(),
            tab_rect: egui::Rect::NOTHING,
            last_frame: None,
            actions: Actions::default(),
            input_secs: 0.0,
            full_screen_asked: false,
            cleared_to_panel_fill: false,
            for_pictures: false,
            paths_asked: file_dialog::PathsAsked::OfTheDesktop,
        }
    }

    /// Paths to save to are typed in the window's own field, never asked of
    /// the desktop's dialog (which may not exist, or may block a test on
    /// a desktop that has one): as where no dialog opens.
    pub fn type_paths(&mut self) {
        self.paths_asked = file_dialog::PathsAsked::Typed;
    }

    /// The app from eframe's stored settings, or the defaults (saying what
    /// was ignored).
    #[must_use]
    pub fn from_storage(storage: Option<&dyn eframe::Storage>) -> Self {
        let text = |key| storage.and_then(|s| s.get_string(key));
        let layout = text(LAYOUT_KEY).map(|layout| Layout::read(&layout));
        // The language chosen in the menu, else the system's: what starting
        // says is said in it.
        let language = layout
            .as_ref()
            .and_then(|(layout, _)| layout.language.as_deref())
            .and_then(|code| Language::from_code(code).ok())
            .unwrap_or_else(Language::system);
        // The stored column's analysis off the UI thread: a long chain
        // opens at once.
        let mut app = Self::with_state(AppState::from_stored_text_analysed(
            text(SETTINGS_KEY).as_deref(),
            true,
            language,
        ));
        if let Some((layout, why)) = layout {
            if let Some(why) = why {
                let note = tr!(app.state.words(), "layout-ignored", why = why);
                app.state.tell(Notice::warning(note));
            }
            app.arrange(&layout);
        }
        app
    }

    /// The app from settings stored as text (see [`AppState::from_stored_text`]).
    #[must_use]
    pub fn from_stored_text(text: Option<&str>) -> Self {
        Self::with_state(AppState::from_stored_text(text))
    }

    /// Draws every frame for a picture: no hints for the hand (how to drag,
    /// pan or zoom, the first launch's hint, the fit buttons).
    pub fn draw_for_pictures(&mut self) {
        self.for_pictures = true;
    }

    /// The state the window shows.
    #[must_use]
    pub fn state(&self) -> &AppState {
        &self.state
    }

    /// The state, for what is not an action: the clock, the background
    /// analysis, notices of the app's own.
    pub fn state_mut(&mut self) -> &mut AppState {
        &mut self.state
    }

    /// Carries out `action` now, and all that follows from it (a lesson
    /// step's actions, in order): the one place the app changes at a
    /// person's request. Views' actions come here before the next frame.
    pub fn apply(&mut self, action: Action) {
        let mut queue = std::collections::VecDeque::from([action]);
        while let Some(action) = queue.pop_front() {
            match action {
                Action::Tab(tab) => self.tab = tab,
                Action::Command(Command::FullScreen) => self.full_screen_asked = true,
                Action::Record { folder, secs } => {
                    self.recorder.start(folder, secs, self.input_secs);
                }
                Action::SaveCsv(table) => self.exports.ask(table),
                Action::SavePicture => self.picture.ask(self.tab.id()),
                action => {
                    for (i, next) in self.state.apply(action).into_iter().enumerate() {
                        queue.insert(i, next);
                    }
                }
            }
        }
    }

    /// Applies every action the views asked for while the last frame was
    /// drawn, before anything of this one is: every panel of a frame shows
    /// the same state.
    fn apply_pending(&mut self, ctx: &egui::Context) {
        self.input_secs = ctx.input(|i| i.time);
        for action in self.actions.take() {
            self.apply(action);
        }
        speak::install(ctx, self.state.language());
        file_dialog::install(ctx, self.paths_asked);
        if std::mem::take(&mut self.full_screen_asked) {
            let now = ctx.input(|i| i.viewport().fullscreen.unwrap_or(false));
            ctx.send_viewport_cmd(egui::ViewportCommand::Fullscreen(!now));
        }
    }

    /// The settings in use.
    #[must_use]
    pub fn settings(&self) -> &Settings {
        self.state.settings()
    }

    /// The running simulation.
    #[must_use]
    pub fn simulation(&self) -> &Simulation {
        self.state.simulation()
    }

    /// The text of what the user is told now, if anything.
    #[must_use]
    pub fn message(&self) -> Option<&str> {
        self.state.notice().map(|n| n.text.as_str())
    }

    /// Shows `tab` in the lower half of the window.
    pub fn show_tab(&mut self, tab: Tab) {
        self.apply(Action::Tab(tab));
    }

    /// Advances the run by `wall_secs` of wall-clock time at the chosen speed.
    pub fn advance(&mut self, wall_secs: f64) {
        self.state.advance(wall_secs);
    }

    /// Computes the analysis of the current parameters and `tab`'s own
    /// background work (the map's rows, the paradox curves, the limit
    /// cycles) and waits until they are complete (for pictures and tests;
    /// the window never waits).
    pub fn complete_background_work(&mut self, tab: Tab) {
        self.state.settle_analysis();
        self.tabs.complete_background_work(&self.state, tab);
    }

    /// The current theme, applied to the context when it changed.
    fn applied_theme(&mut self, ctx: &egui::Context) -> Theme {
        let projector = self.state.settings().projector;
        let theme = if projector {
            Theme::PROJECTOR
        } else {
            Theme::NORMAL
        };
        if self.applied_projector != Some(projector) {
            theme.apply(ctx);
            self.applied_projector = Some(projector);
        }
        theme
    }

    /// Carries out the commands whose keys were pressed this frame (the
    /// window's logic calls it first; tests that type keys call it too).
    pub fn take_keys(&mut self, ctx: &egui::Context) {
        for command in Command::pressed(ctx) {
            self.apply(command.into());
        }
        let steps = action::tab_steps(ctx);
        if steps != 0 {
            self.apply(Action::Tab(self.tab.cycled(steps)));
        }
    }

    /// `frame` without its fill where the window has already cleared to the
    /// panels' colour (each fill would cover the window once more: on a
    /// CPU renderer that is a third of the frame's pixels).
    fn panel_frame(&self, frame: egui::Frame) -> egui::Frame {
        if self.cleared_to_panel_fill {
            frame.fill(egui::Color32::TRANSPARENT)
        } else {
            frame
        }
    }

    /// The whole window's contents. Reads the state; the simulation advances
    /// only in [`ZieglerApp::advance`], so a picture depends on the state alone.
    pub fn contents_ui(&mut self, ui: &mut egui::Ui) {
        if let Some(notice) = zoom::hold(ui.ctx()) {
            self.state.say(notice);
        }
        self.apply_pending(ui.ctx());
        let theme = self.applied_theme(ui.ctx());
        if let Some(notice) = self.picture.frame_start(ui.ctx()) {
            self.state.say(notice);
        }
        // A recording's frames are pictures too, and a saved tab's.
        self.state.set_for_picture(
            self.for_pictures || self.recorder.is_capturing() || self.picture.capturing(),
        );
        match self.recorder.frame(ui.ctx()) {
            Some(Ok(recorded)) => {
                let text = recorded.text(self.state.words());
                self.state.say(Notice::info(text));
            }
            Some(Err(why)) => self.state.say(Notice::error(tr!(
                self.state.words(),
                "notice-recording-failed",
                why = why.to_string()
            ))),
            None => {}
        }
        if self.view_generation != self.state.view_generation() {
            self.view_generation = self.state.view_generation();
            self.tab = Tab::default();
            self.scene = scene::SceneView::default();
        }
        self.sidebar.take_clipboard(ui.ctx(), &mut self.actions);
        if let Some(notice) = self.record_choice.take_dialog_answer() {
            self.state.say(notice);
        }
        if let Some(notice) = self.exports.frame(ui.ctx(), &self.state) {
            self.state.say(notice);
        }
        self.window_ui(ui, &theme);
        welcome::welcome_ui(ui.ctx(), &self.state, &mut self.actions, &theme);
        self.picture.frame_end(ui.ctx(), self.tab_rect);
        self.ask_for_a_frame_if_asked(ui.ctx());
    }

    /// Another frame soon when the views asked for something: it is applied
    /// before that frame is drawn.
    fn ask_for_a_frame_if_asked(&self, ctx: &egui::Context) {
        if !self.actions.is_empty() {
            ctx.request_repaint();
        }
    }

    /// The central panel: the scene (with the root locus beside it on a
    /// small projector), the load bar, the tab bar and the tab.
    fn central_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        let height = ui.available_height();
        let min_plot_height = MIN_PLOT_HEIGHT * theme.text_size / 14.0;
        let plots_fit = |scene_share: f32| {
            (1.0 - scene_share) * height - below_scene_height(theme) >= min_plot_height
        };
        // In front of a class the scene gets most of the height, or half
        // of it where that leaves the tab's plots room below (a full HD
        // projector) and most of it does not.
        let projector = self.state.settings().projector;
        let scene_share = if projector && (plots_fit(0.6) || !plots_fit(0.5)) {
            0.6
        } else {
            0.5
        };
        // On a projector too small for the tab's plots, the root
        // locus goes beside the scene: the class sees the column, the
        // load bar and the eigenvalues together.
        let locus_beside = projector && !plots_fit(scene_share);
        // While a lesson hides the answer, only the time histories show.
        let tab_hidden = self.state.answer_hidden() && self.tab != Tab::Histories;
        let (top, _) = ui.allocate_exact_size(
            vec2(ui.available_width(), scene_share * height),
            egui::Sense::hover(),
        );
        // On such a projector the top row holds the scene and the root
        // locus beside it, or, when another tab is open (a lesson step's
        // paradox curves, say), that tab's plots across the whole row: the
        // class sees what the step talks about.
        let tab_on_top = locus_beside && self.tab != Tab::Locus;
        let (scene_rect, locus_rect) = if locus_beside && !tab_on_top {
            let split = top.left() + 0.55 * top.width();
            let (left, right) = top.split_left_right_at_x(split);
            (left, Some(right.shrink2(vec2(6.0, 0.0))))
        } else {
            (top, None)
        };
        ui.scope_builder(egui::UiBuilder::new().max_rect(scene_rect), |ui| {
            if !tab_on_top {
                scene::scene_ui(ui, &self.state, &mut self.actions, &mut self.scene, theme);
            } else if tab_hidden {
                ui.colored_label(color(theme.palette.info), tr!(ui.words(), "answer-hidden"));
            } else {
                ui.set_clip_rect(scene_rect);
                self.tab_rect = scene_rect;
                self.tabs
                    .view(self.tab)
                    .ui(ui, &self.state, &mut self.actions, theme);
            }
        });
        if let Some(rect) = locus_rect {
            ui.scope_builder(egui::UiBuilder::new().max_rect(rect), |ui| {
                if self.state.answer_hidden() {
                    ui.colored_label(color(theme.palette.info), tr!(ui.words(), "answer-hidden"));
                } else if let Some(locus) = self.tabs.get_mut::<tabs::LocusTab>() {
                    locus.complex_plane_ui(ui, &self.state, theme);
                }
            });
        }
        // What follows goes below the whole top row: a scope that used less
        // than its rect (the hidden locus's one-line note) must not pull the
        // load bar up over the scene.
        ui.advance_cursor_after_rect(top);
        load_bar::load_bar_ui(ui, &self.state, &mut self.actions, theme);
        tabs::bar_ui(ui, self.tab, &mut self.actions);
        // With the root locus beside the scene, or the tab in its place, the
        // tab is on the screen already: never a second time below, whatever
        // room the estimate above left there.
        if locus_beside || ui.available_height() < min_plot_height {
            // One reason a line: where the tab is, or that it is hidden,
            // or that it needs room (they were mixed into one sentence).
            let words = ui.words();
            ui.weak(if tab_on_top {
                tr!(words, "tab-in-column-place", tab = self.tab.title(words))
            } else if locus_beside {
                tr!(words, "locus-beside-column")
            } else if tab_hidden {
                tr!(words, "answer-hidden")
            } else {
                tr!(words, "plots-need-room")
            });
        } else if tab_hidden {
            ui.label(
                RichText::new(tr!(ui.words(), "answer-hidden-histories"))
                    .size(theme.text_size * 1.2)
                    .color(color(theme.palette.info)),
            );
        } else {
            self.tab_rect = ui.available_rect_before_wrap();
            self.tabs
                .view(self.tab)
                .ui(ui, &self.state, &mut self.actions, theme);
        }
    }

    /// One panel alone (for snapshots and figures).
    pub fn panel_ui(&mut self, ui: &mut egui::Ui, panel: Panel) {
        let tab = match panel {
            // The whole window does its own frame's work.
            Panel::Window => return self.contents_ui(ui),
            Panel::Scene => None,
            Panel::Tab(tab) => Some(tab),
        };
        self.apply_pending(ui.ctx());
        let theme = self.applied_theme(ui.ctx());
        self.state.set_for_picture(self.for_pictures);
        egui::CentralPanel::default().show(ui, |ui| match tab {
            None => scene::scene_ui(ui, &self.state, &mut self.actions, &mut self.scene, &theme),
            Some(tab) => self
                .tabs
                .view(tab)
                .ui(ui, &self.state, &mut self.actions, &theme),
        });
        self.ask_for_a_frame_if_asked(ui.ctx());
    }
}

/// The height the load bar and the tab bar take under the scene, in
/// points (the load bar's three rows of text, the tab bar's one, spacing).
fn below_scene_height(theme: &Theme) -> f32 {
    3.4 * (theme.text_size + 4.0) + theme.text_size + 36.0
}

impl eframe::App for ZieglerApp {
    fn logic(&mut self, ctx: &egui::Context, _frame: &mut eframe::Frame) {
        self.take_keys(ctx);
        self.apply_pending(ctx);
        // The wall clock, read here and only here: everything below takes the
        // elapsed time as a number, so tests and pictures can give their own.
        let now = std::time::Instant::now();
        let wall_secs = self
            .last_frame
            .map_or(0.0, |last| now.duration_since(last).as_secs_f64());
        self.last_frame = Some(now);
        self.state.advance(wall_secs);
        self.state.receive_analysis();
        if self.state.running() || self.state.background_pending() {
            ctx.request_repaint();
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        self.contents_ui(ui);
    }

    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        visuals.panel_fill.to_normalized_gamma_f32()
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        storage.set_string(SETTINGS_KEY, self.state.settings().to_text());
        match ron::to_string(&self.layout()) {
            Ok(text) => storage.set_string(LAYOUT_KEY, text),
            Err(error) => self.state.say(Notice::error(tr!(
                self.state.words(),
                "notice-layout-not-saved",
                why = error.to_string()
            ))),
        }
    }
}
