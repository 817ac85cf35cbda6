//! The actions with a name of their own, asked for by button or key, in
//! one list: each one's label, keys and tooltip. The buttons, the keyboard
//! and the keys help all read it; the state carries them out
//! ([`super::action::Action::Command`]).

use eframe::egui;

use super::action::Actions;
use super::state::AppState;

/// A named action of the user.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Command {
    PlayPause,
    Step,
    Kick,
    Reset,
    ResetAll,
    LoadUp,
    LoadDown,
    Projector,
    LessonNext,
    LessonBack,
}

impl Command {
    /// Every command, in the order the keys help lists them.
    pub const ALL: [Self; 10] = [
        Self::PlayPause,
        Self::LoadUp,
        Self::LoadDown,
        Self::Kick,
        Self::Reset,
        Self::ResetAll,
        Self::Projector,
        Self::LessonNext,
        Self::LessonBack,
        Self::Step,
    ];

    /// The button's text in `state`.
    #[must_use]
    pub fn label(self, state: &AppState) -> &'static str {
        match self {
            Self::PlayPause if state.running() => "pause",
            Self::PlayPause => "play",
            Self::Step => "step",
            Self::Kick => "kick",
            Self::Reset => "reset",
            Self::ResetAll => "reset all",
            Self::LoadUp => "load up",
            Self::LoadDown => "load down",
            Self::Projector => "projector mode",
            Self::LessonNext => "next",
            Self::LessonBack => "back",
        }
    }

    /// What it does, for tooltips and the keys help.
    #[must_use]
    pub fn tooltip(self) -> &'static str {
        match self {
            Self::PlayPause => "play / pause",
            Self::Step => "one engine step (1/240 s), then paused",
            Self::Kick => "kick: both angles by 0.01 rad",
            Self::Reset => "reset: a fresh run from the standard perturbation",
            Self::ResetAll => {
                "reset all: the preset's parameters and load, normal speed, a fresh run, the default views"
            }
            Self::LoadUp => "load up by a hundredth of the load bar",
            Self::LoadDown => "load down by a hundredth of the load bar",
            Self::Projector => "projector mode: high contrast, large text",
            Self::LessonNext => "the lesson's next step (a presenter's remote sends Page Down)",
            Self::LessonBack => "the lesson's previous step (Page Up)",
        }
    }

    /// The keys that ask for it (none: a button only).
    #[must_use]
    pub fn keys(self) -> &'static [egui::Key] {
        use egui::Key;
        match self {
            Self::PlayPause => &[Key::Space],
            Self::Step | Self::ResetAll => &[],
            Self::Kick => &[Key::K],
            Self::Reset => &[Key::R],
            Self::LoadUp => &[Key::ArrowRight, Key::ArrowUp],
            Self::LoadDown => &[Key::ArrowLeft, Key::ArrowDown],
            Self::Projector => &[Key::P],
            Self::LessonNext => &[Key::PageDown],
            Self::LessonBack => &[Key::PageUp],
        }
    }

    /// The keys as the keys help names them.
    #[must_use]
    pub fn key_names(self) -> String {
        self.keys()
            .iter()
            .map(|key| match key {
                egui::Key::Space => "space",
                egui::Key::ArrowRight => "right",
                egui::Key::ArrowUp => "up",
                egui::Key::ArrowLeft => "left",
                egui::Key::ArrowDown => "down",
                egui::Key::PageDown => "page down",
                egui::Key::PageUp => "page up",
                other => other.name(),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Its button: the label, the tooltip with the keys; a click asks for it.
    pub fn button(self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
        let keys = self.key_names();
        let tooltip = if keys.is_empty() {
            self.tooltip().to_owned()
        } else {
            format!("{} ({keys})", self.tooltip())
        };
        if ui
            .button(self.label(state))
            .on_hover_text(tooltip)
            .clicked()
        {
            actions.push(self);
        }
    }

    /// The commands whose keys were pressed this frame, unless a text field
    /// has the keyboard.
    #[must_use]
    pub fn pressed(ctx: &egui::Context) -> Vec<Self> {
        if ctx.egui_wants_keyboard_input() {
            return Vec::new();
        }
        ctx.input(|input| {
            Self::ALL
                .into_iter()
                .filter(|command| command.keys().iter().any(|&key| input.key_pressed(key)))
                .collect()
        })
    }

    /// The keys help: one row per command that has keys.
    pub fn keys_help_ui(ui: &mut egui::Ui) {
        for command in Self::ALL {
            let keys = command.key_names();
            if keys.is_empty() {
                continue;
            }
            ui.horizontal(|ui| {
                ui.monospace(format!("{keys:>11}"));
                ui.label(command.tooltip());
            });
        }
    }
}
