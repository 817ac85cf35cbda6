//! Everything a person, a lesson, a test or the bench can ask of the app,
//! as values, and the named ones (buttons and keys) with their labels, keys
//! and tooltips. Views read the state and push actions; the app applies
//! them in one place before the next frame is drawn, so every panel of a
//! frame shows the same state.

use std::path::PathBuf;

use eframe::egui;

use super::notice::Notice;
use super::speak::Speak as _;
use super::tab::Tab;
use crate::i18n::{Language, Words};
use crate::lesson::Lesson;
use crate::model::{Axis, Key, Model, PresetId};
use crate::sim::{EngineKind, Ramp};
use crate::tr;

/// One thing asked of the app.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// A named button or key: play/pause, step, kick, reset, reset all,
    /// load up/down, projector mode, the lesson's next and back.
    Command(Command),
    /// Another preset at the current load (its own beyond its load bar).
    Preset(PresetId),
    /// A value typed, dragged or slid for a parameter; a refused one is
    /// shown beside its field until a value for it is taken.
    Enter {
        key: Key,
        value: f64,
    },
    /// A value typed for a parameter that was not taken, and why.
    Refuse {
        key: Key,
        why: Refusal,
    },
    /// The field went back to the applied value: its refusal is dropped.
    ClearRefusal(Key),
    /// Preset `preset` with `model` (a lesson's column): a fresh run when
    /// the preset changes, a change of parameters otherwise.
    Column {
        preset: PresetId,
        model: Model,
    },
    Engine(EngineKind),
    /// Simulated seconds per wall-clock second.
    Speed(f64),
    Projector(bool),
    /// The window speaks this language.
    Language(Language),
    /// The mouse holds the column at rest with its rods at these angles.
    Hold {
        angles_rad: Vec<f64>,
    },
    Release,
    /// Every rod turned by `angle_rad` (a lesson's kick of its own size).
    KickBy {
        angle_rad: f64,
    },
    RampStart(Ramp),
    RampPauseResume,
    RampStop,
    /// Another model's locus behind the current one, or none.
    Overlay(Option<PresetId>),
    Tab(Tab),
    /// A click on the stability map: its load and second parameter.
    MapPick {
        axis: Axis,
        load: f64,
        value: f64,
    },
    /// Settings as shared text, taken in place of the current ones.
    Paste(String),
    LessonOpen(Box<Lesson>),
    /// The student's predicted load, and chosen answer (from 0).
    LessonPredict(f64),
    LessonChoose(usize),
    LessonClose,
    /// Records the next `secs` seconds of the window into `folder`.
    Record {
        folder: PathBuf,
        secs: f64,
    },
    /// Saves a table as the command line writes it, to a file chosen in
    /// the desktop's dialog.
    SaveCsv(Table),
    /// Saves the open tab's plots as a PNG, to a file chosen in the
    /// desktop's dialog.
    SavePicture,
    /// Something to tell the user (a view's own failure: a copy, a file).
    Say(Notice),
    DismissNotice,
    DismissHint,
    /// Closes the first launch's welcome for good.
    CloseWelcome,
}

/// Why a value typed in a field was not taken: kept as data, worded in the
/// language of the moment beside the field.
#[derive(Debug, Clone, PartialEq)]
pub enum Refusal {
    /// The text reads as no number.
    NotANumber(String),
    /// The model refuses the number.
    Model(crate::model::ModelError),
}

impl Refusal {
    /// The refusal in `words`' language.
    #[must_use]
    pub fn words(&self, words: &'static crate::i18n::Words) -> String {
        match self {
            Self::NotANumber(text) => {
                crate::tr!(words, "refused-not-a-number", text = text.as_str())
            }
            Self::Model(error) => crate::i18n::model_error(words, error),
        }
    }
}

/// A table the window can save.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Table {
    /// The run's recent past, as `zieglerlab simulate` writes it.
    History,
    /// The root locus shown, as `zieglerlab locus` writes it.
    Locus,
}

impl Table {
    /// The file name the dialog proposes.
    #[must_use]
    pub fn file_name(self) -> &'static str {
        match self {
            Self::History => "zieglerlab-history.csv",
            Self::Locus => "zieglerlab-locus.csv",
        }
    }
}

impl From<Command> for Action {
    fn from(command: Command) -> Self {
        Self::Command(command)
    }
}

/// The actions asked for during a frame, in order.
#[derive(Debug, Default)]
pub struct Actions(Vec<Action>);

impl Actions {
    pub fn push(&mut self, action: impl Into<Action>) {
        self.0.push(action.into());
    }

    /// Pushes `action` unless it was already asked for this frame.
    pub fn push_once(&mut self, action: Action) {
        if !self.0.contains(&action) {
            self.0.push(action);
        }
    }

    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Every action, oldest first, leaving none.
    pub fn take(&mut self) -> Vec<Action> {
        std::mem::take(&mut self.0)
    }
}

/// A named action of the user, in the order the keys help lists them (the
/// order of [`COMMANDS`], checked when the program is compiled: a command
/// without its row, or a row too many, does not compile).
#[derive(Clone, Copy, Debug, PartialEq, Eq, strum::EnumCount)]
pub enum Command {
    PlayPause,
    LoadUp,
    LoadDown,
    Kick,
    Reset,
    ResetAll,
    Projector,
    LessonNext,
    LessonBack,
    FullScreen,
    Step,
}

/// One row of the commands' table: a command, its button's text (and
/// while the run goes, where it differs), what it does (tooltips and the
/// keys help) and the keys that ask for it (none: a button only).
pub struct CommandSpec {
    pub command: Command,
    /// Its words are the message `command-ID`: the button's label, with
    /// `.tooltip` what it does and (play) `.running` the label while the
    /// run goes.
    pub id: &'static str,
    pub keys: &'static [egui::Key],
}

const fn row(command: Command, id: &'static str, keys: &'static [egui::Key]) -> CommandSpec {
    CommandSpec { command, id, keys }
}

/// The tabs Ctrl+Tab (1) and Ctrl+Shift+Tab (-1) move by this frame, but
/// while a text field is edited (0).
#[must_use]
pub fn tab_steps(ctx: &egui::Context) -> isize {
    if ctx.text_edit_focused() {
        return 0;
    }
    ctx.input(|input| match input.modifiers {
        m if m.ctrl && input.key_pressed(egui::Key::Tab) => {
            if m.shift {
                -1
            } else {
                1
            }
        }
        _ => 0,
    })
}

/// Scrolls the control that has just taken the focus into view, called
/// first in a scroll area's contents (egui does not: Tab reached controls
/// scrolled out of a projector's sidebar). Its rect is the last frame's,
/// at the offset the area still has.
pub fn scroll_to_new_focus(ui: &egui::Ui) {
    let ctx = ui.ctx();
    let key = ui.scope_id().with("the focus scrolled to");
    let focused = ctx.memory(egui::Memory::focused);
    let last: Option<egui::Id> = ctx.data(|data| data.get_temp(key)).flatten();
    if focused != last {
        // Only a control this area hides: one clipped (scrolled out of
        // view) and across its width. A control below the area (the
        // projector's sidebar foot) is in view already.
        let hidden = focused
            .and_then(|id| ctx.read_response(id))
            .filter(|r| r.interact_rect != r.rect)
            .filter(|r| ui.max_rect().x_range().contains(r.rect.center().x));
        if let Some(response) = hidden {
            ui.scroll_to_rect(response.rect, None);
        }
        ctx.data_mut(|data| data.insert_temp(key, focused));
    }
}

/// What has the keyboard's focus, as far as the shortcuts care.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Focus {
    /// Nothing: every key is a shortcut.
    Nothing,
    /// A text field: it takes every key while it is edited.
    Text,
    /// A slider (the load bar, a parameter's, the prediction's): it takes
    /// left and right for its own steps.
    Slider,
    /// A button, checkbox, radio button or tab: space and Enter press it,
    /// as on every desktop.
    Control,
    /// A plot: the arrows pan it, + and - zoom it, Enter picks its centre.
    Plot,
}

impl Focus {
    /// The focus in `ctx` now.
    #[must_use]
    pub fn of(ctx: &egui::Context) -> Self {
        let Some(id) = ctx.memory(egui::Memory::focused) else {
            return Self::Nothing;
        };
        if ctx.text_edit_focused() {
            Self::Text
        } else if super::plot_keys::is_plot(ctx, id) {
            Self::Plot
        } else if ctx
            .read_response(id)
            .is_some_and(|response| response.sense.senses_drag())
        {
            Self::Slider
        } else {
            Self::Control
        }
    }

    /// Whether the focused control uses `key` itself (so it is no shortcut).
    #[must_use]
    pub fn takes(self, key: egui::Key) -> bool {
        use egui::Key;
        match self {
            Self::Nothing => false,
            Self::Text => true,
            Self::Slider => matches!(key, Key::ArrowLeft | Key::ArrowRight),
            Self::Control => matches!(key, Key::Space | Key::Enter),
            Self::Plot => matches!(
                key,
                Key::ArrowLeft | Key::ArrowRight | Key::ArrowUp | Key::ArrowDown | Key::Enter
            ),
        }
    }
}

/// The keys of the focus, after the commands' in the keys help: only a
/// text field being edited holds the shortcuts back. Each is a message
/// (`focus-keys-ID`: what they do, `.keys`: the keys).
pub const FOCUS_KEYS: [&str; 9] = [
    "focus-keys-tab",
    "focus-keys-ctrl-tab",
    "focus-keys-press",
    "focus-keys-slider",
    "focus-keys-column",
    "focus-keys-ends",
    "focus-keys-plot",
    "focus-keys-escape",
    "focus-keys-others",
];

/// Every command, one row each, in the keys help's order.
pub const COMMANDS: [CommandSpec; <Command as strum::EnumCount>::COUNT] = {
    use egui::Key;
    [
        row(Command::PlayPause, "play", &[Key::Space]),
        row(Command::LoadUp, "load-up", &[Key::ArrowRight, Key::ArrowUp]),
        row(
            Command::LoadDown,
            "load-down",
            &[Key::ArrowLeft, Key::ArrowDown],
        ),
        row(Command::Kick, "kick", &[Key::K]),
        row(Command::Reset, "reset", &[Key::R]),
        row(Command::ResetAll, "reset-all", &[]),
        row(Command::Projector, "projector", &[Key::P]),
        row(Command::LessonNext, "next", &[Key::PageDown]),
        row(Command::LessonBack, "back", &[Key::PageUp]),
        row(Command::FullScreen, "full-screen", &[Key::F11]),
        row(Command::Step, "step", &[]),
    ]
};

// Each row sits at its command's place: `Command::spec` indexes the table.
const _: () = {
    let mut i = 0;
    while i < COMMANDS.len() {
        assert!(COMMANDS[i].command as usize == i, "COMMANDS out of order");
        i += 1;
    }
};

impl Command {
    /// Every command, in the order the keys help lists them.
    pub const ALL: [Self; COMMANDS.len()] = {
        let mut all = [Self::PlayPause; COMMANDS.len()];
        let mut i = 0;
        while i < COMMANDS.len() {
            all[i] = COMMANDS[i].command;
            i += 1;
        }
        all
    };

    /// Its row of the table.
    #[must_use]
    pub fn spec(self) -> &'static CommandSpec {
        &COMMANDS[self as usize]
    }

    /// The button's text, `running` or not.
    #[must_use]
    pub fn label(self, words: &'static Words, running: bool) -> String {
        let id = format!("command-{}", self.spec().id);
        let running_id = format!("{id}.running");
        if running && words.has(&running_id) {
            words.get(&running_id).into_owned()
        } else {
            words.get(&id).into_owned()
        }
    }

    /// What it does, for tooltips and the keys help.
    #[must_use]
    pub fn tooltip(self, words: &'static Words) -> String {
        words
            .get(&format!("command-{}.tooltip", self.spec().id))
            .into_owned()
    }

    /// The keys that ask for it (none: a button only).
    #[must_use]
    pub fn keys(self) -> &'static [egui::Key] {
        self.spec().keys
    }

    /// The keys as the keys help names them (a letter as itself, the
    /// others in `words`' language: messages `key-NAME`).
    #[must_use]
    pub fn key_names(self, words: &'static Words) -> String {
        self.keys()
            .iter()
            .map(|key| match key {
                egui::Key::Space => tr!(words, "key-space"),
                egui::Key::ArrowRight => tr!(words, "key-right"),
                egui::Key::ArrowUp => tr!(words, "key-up"),
                egui::Key::ArrowLeft => tr!(words, "key-left"),
                egui::Key::ArrowDown => tr!(words, "key-down"),
                egui::Key::PageDown => tr!(words, "key-page-down"),
                egui::Key::PageUp => tr!(words, "key-page-up"),
                other => other.name().to_owned(),
            })
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// Its button: the label, the tooltip with the keys; a click asks for it.
    pub fn button(self, ui: &mut egui::Ui, running: bool, actions: &mut Actions) {
        let words = ui.words();
        let keys = self.key_names(words);
        let tooltip = if keys.is_empty() {
            self.tooltip(words)
        } else {
            format!("{} ({keys})", self.tooltip(words))
        };
        if ui
            .button(self.label(words, running))
            .on_hover_text(tooltip)
            .clicked()
        {
            actions.push(self);
        }
    }

    /// The commands whose keys were pressed this frame. Only a text field
    /// being edited holds every key back; a focused control keeps the keys
    /// it uses itself (see [`Focus::takes`]) and lets the others through, so
    /// Page Down from a presenter's remote always moves the lesson on.
    #[must_use]
    pub fn pressed(ctx: &egui::Context) -> Vec<Self> {
        let focus = Focus::of(ctx);
        if focus == Focus::Text {
            return Vec::new();
        }
        let commands: Vec<Self> = ctx.input(|input| {
            Self::ALL
                .into_iter()
                .filter(|command| {
                    command
                        .keys()
                        .iter()
                        .any(|&key| input.key_pressed(key) && !focus.takes(key))
                })
                .collect()
        });
        // An arrow that moves the load does not also move the focus to the
        // next control (egui's arrow navigation); Tab still does.
        let arrows_taken = commands
            .iter()
            .any(|c| matches!(c, Self::LoadUp | Self::LoadDown));
        if arrows_taken && !ctx.input(|input| input.key_pressed(egui::Key::Tab)) {
            ctx.memory_mut(|memory| memory.move_focus(egui::FocusDirection::None));
        }
        commands
    }

    /// The keys help: one row per command that has keys, then the keys of
    /// the focus; the words wrap within the window (a projector's large
    /// text ran them past its edge).
    pub fn keys_help_ui(ui: &mut egui::Ui) {
        let width = (ui.ctx().content_rect().width() - 40.0).clamp(300.0, 760.0);
        ui.set_max_width(width);
        let words = ui.words();
        let rows = Self::ALL
            .into_iter()
            .filter(|command| !command.keys().is_empty())
            .map(|command| (command.key_names(words), command.tooltip(words)))
            .chain(FOCUS_KEYS.iter().map(|id| {
                (
                    words.get(&format!("{id}.keys")).into_owned(),
                    words.get(id).into_owned(),
                )
            }));
        let keys_width = 9.0 * ui.text_style_height(&egui::TextStyle::Monospace);
        for (keys, what) in rows {
            ui.horizontal_top(|ui| {
                ui.add_sized(
                    [keys_width, ui.text_style_height(&egui::TextStyle::Body)],
                    egui::Label::new(egui::RichText::new(keys).monospace()),
                );
                ui.add(egui::Label::new(what).wrap());
            });
        }
    }
}
