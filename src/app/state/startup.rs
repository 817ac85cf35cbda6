//! The state's start from stored settings text (eframe's store) and the
//! taking of pasted settings: what reads is kept, what does not is named.

use super::AppState;
use crate::app::notice::Notice;
use crate::app::settings::Settings;
use crate::app::settings_text::read;
use crate::i18n::Language;
use crate::tr;

impl AppState {
    /// The state from settings stored as text (RON, as eframe writes them):
    /// every field that reads and makes sense is kept, the others take their
    /// defaults, and a notice names them.
    #[must_use]
    pub fn from_stored_text(text: Option<&str>) -> Self {
        Self::from_stored_text_analysed(text, false, Language::English)
    }

    /// [`AppState::from_stored_text`], the analysis of the stored column
    /// computed off the UI thread when `in_background` (the window's start),
    /// speaking `language` (what reading the settings says, too).
    #[must_use]
    pub fn from_stored_text_analysed(
        text: Option<&str>,
        in_background: bool,
        language: Language,
    ) -> Self {
        let Some(text) = text else {
            let mut state = Self::first_launch();
            state.speak(language);
            return state;
        };
        let words = crate::i18n::words(language);
        let (settings, note) = match read(text) {
            Ok(read) if read.ignored.is_empty() => (read.settings, None),
            Ok(read) => {
                let what = read.ignored.join(", ");
                let note = tr!(words, "store-settings-partly", what = what);
                (read.settings, Some(Notice::warning(note)))
            }
            Err(error) => (
                Settings::default(),
                Some(Notice::warning(tr!(
                    words,
                    "store-settings-ignored",
                    why = error.to_string()
                ))),
            ),
        };
        let started = if in_background {
            Self::new_analysing_in_background(settings, language)
        } else {
            Self::new(settings)
        };
        let mut state = match started {
            Ok(state) => state,
            Err(error) => {
                let mut state = Self::defaults();
                state.speak(language);
                state.say(Notice::warning(tr!(
                    words,
                    "store-settings-ignored",
                    why = crate::i18n::sim_error(words, &error)
                )));
                return state;
            }
        };
        state.speak(language);
        if let Some(note) = note {
            // The note first: what was read comes before what starting did.
            let started = state.notice().cloned();
            state.say(note);
            if let Some(started) = started {
                state.tell(started);
            }
        }
        state
    }

    /// The default settings' state.
    #[must_use]
    pub fn defaults() -> Self {
        // The roller preset is valid by construction; this cannot fail.
        match Self::new(Settings::default()) {
            Ok(state) => state,
            Err(error) => unreachable!("the default settings are valid: {error}"),
        }
    }

    /// Loads settings from shared text; garbage leaves everything as it was
    /// and says why.
    pub(super) fn paste_settings(&mut self, text: &str) {
        if text.trim().is_empty() {
            self.say(Notice::error(crate::tr!(
                self.words(),
                "notice-paste-nothing"
            )));
            return;
        }
        let settings = match read(text) {
            Ok(read) if read.ignored.is_empty() => read.settings,
            Ok(read) => {
                self.say(Notice::error(crate::tr!(
                    self.words(),
                    "notice-paste-not-understood",
                    what = read.ignored.join(", ")
                )));
                return;
            }
            Err(error) => {
                self.say(Notice::error(crate::tr!(
                    self.words(),
                    "notice-paste-unreadable",
                    why = error.to_string()
                )));
                return;
            }
        };
        // Taken in place: the analysis thread, the lesson, the overlay and
        // the tab stay (a new state dropped the thread, so every later change
        // was analysed on the UI thread).
        match self.take_settings(settings) {
            Ok(()) => self.say(Notice::info(crate::tr!(self.words(), "notice-pasted"))),
            Err(error) => {
                let why = crate::i18n::sim_error(self.words(), &error);
                self.say(Notice::error(crate::tr!(
                    self.words(),
                    "notice-paste-refused",
                    why = why
                )));
            }
        }
    }
}
