//! Everything a person, a lesson, a test or the bench can ask of the app,
//! as values. Views read the state and push actions; the app applies them
//! in one place before the next frame is drawn, so every panel of a frame
//! shows the same state.

use std::path::PathBuf;

use super::command::Command;
use super::notice::Notice;
use super::tabs::Tab;
use crate::lesson::Lesson;
use crate::model::{Axis, Key, Model, PresetId};
use crate::sim::{EngineKind, Ramp};

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
    /// Text typed for a parameter that is not a value, and why.
    Refuse {
        key: Key,
        why: String,
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
    /// The mouse holds the column at these angles (the two-rod scene).
    Hold {
        phi1_rad: f64,
        phi2_rad: f64,
    },
    Release,
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
    /// Something to tell the user (a view's own failure: a copy, a file).
    Say(Notice),
    DismissNotice,
    DismissHint,
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
