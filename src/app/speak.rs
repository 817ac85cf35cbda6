//! The window's language as its views reach it: the app puts it in egui's
//! context at the start of each frame, and any code with a `Ui` or the
//! context reads the words from there.

use eframe::egui;

use crate::i18n::{self, Language, Words};

/// Where the language is kept in the context's memory.
fn language_id() -> egui::Id {
    egui::Id::unique("zieglerlab-language")
}

/// The window speaks `language` from this frame on.
pub fn install(ctx: &egui::Context, language: Language) {
    ctx.data_mut(|d| d.insert_temp(language_id(), language));
}

/// What has the window's words: its context, and every `Ui` in it.
pub trait Speak {
    /// The words of the window's language (English before any is set).
    fn words(&self) -> &'static Words;
}

impl Speak for egui::Context {
    fn words(&self) -> &'static Words {
        i18n::words(self.data(|d| d.get_temp(language_id())).unwrap_or_default())
    }
}

impl Speak for egui::Ui {
    fn words(&self) -> &'static Words {
        self.ctx().words()
    }
}
