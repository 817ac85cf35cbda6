//! The window's language as its views reach it: the app puts it in egui's
//! context at the start of each frame, and any code with a `Ui` or the
//! context reads the words from there.

use eframe::egui;

use crate::i18n::{self, Language, Words};
use crate::sim::{MAX_TURN_PER_STEP_RAD, Status};
use crate::tr;

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

/// Where the run is, in `words`' language.
#[must_use]
pub fn status_words(words: &'static Words, status: Status) -> String {
    match status {
        Status::Running => tr!(words, "run-running"),
        Status::Diverged { t_secs } => tr!(words, "run-diverged", secs = format!("{t_secs:.3}")),
        Status::TooStiff { t_secs } => tr!(words, "run-too-stiff", secs = format!("{t_secs:.3}")),
        Status::TooFast {
            t_secs,
            rate_rad_per_s,
        } => tr!(
            words,
            "run-too-fast",
            secs = format!("{t_secs:.3}"),
            rate = format!("{rate_rad_per_s:.0}"),
            most = MAX_TURN_PER_STEP_RAD.to_string()
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::State;
    use crate::app::action::{Command, FOCUS_KEYS};
    use crate::app::tab::Tab;
    use crate::model::{KEYS, PresetId};

    /// The ids the window makes from names (a preset's, a key's, a tab's, a
    /// state's, a command's) are every one in English's file: the ids
    /// written out in the code are checked by `i18n`'s own tests.
    #[test]
    fn every_id_made_from_a_name_is_in_english_s_file() {
        let english = i18n::words(Language::English);
        let mut ids: Vec<String> = Vec::new();
        for id in PresetId::all() {
            ids.push(format!("preset-{}", id.name()));
            ids.push(format!("preset-{}.description", id.name()));
        }
        for spec in &KEYS {
            ids.push(format!("key-{}", spec.key.name()));
            ids.push(format!("key-{}.range", spec.key.name()));
        }
        for tab in Tab::all() {
            ids.push(format!("tab-{}", tab.id()));
            ids.push(format!("tab-{}.tooltip", tab.id()));
        }
        for state in [State::Stable, State::Flutter, State::Divergence] {
            ids.push(format!("state-{}", state.name()));
            ids.push(format!("card-{}.meaning", state.name()));
            ids.push(format!("transition-meaning.to-{}", state.name()));
        }
        for command in Command::ALL {
            ids.push(format!("command-{}", command.spec().id));
            ids.push(format!("command-{}.tooltip", command.spec().id));
        }
        for id in FOCUS_KEYS {
            ids.push(id.to_owned());
            ids.push(format!("{id}.keys"));
        }
        for (id, _) in crate::app::sidebar::PACES {
            ids.push(id.to_owned());
            ids.push(format!("{id}.tooltip"));
        }
        // Ids kept in constants or chosen at run time.
        ids.extend(
            [
                crate::app::VIEW_HINT,
                crate::app::file_dialog::NOT_SAVED,
                crate::app::state::SWITCHED_TO_REFERENCE,
                "legend-now-below",
                "legend-now-above",
                "legend-sweep-up",
                "legend-sweep-down",
                "axis-re",
                "axis-im",
                "welcome-column",
                "welcome-states",
                "welcome-locus",
                "welcome-try",
                "hint-first-launch",
                "legend-transition",
                "paradox-ratio-joints",
                "paradox-ratio-external",
                "paradox-ratio-roller-mass",
                "paradox-reference-undamped",
                "paradox-reference-massless",
            ]
            .map(str::to_owned),
        );
        let missing: Vec<&String> = ids.iter().filter(|id| !english.has(id)).collect();
        assert!(missing.is_empty(), "not in en.ftl: {missing:?}");
    }

    #[test]
    fn durations_in_days_and_years_take_their_plurals() {
        use crate::i18n::duration_words;
        let polish = i18n::words(Language::Polish);
        let english = i18n::words(Language::English);
        assert_eq!(duration_words(english, 86_400.0), "1 day");
        assert_eq!(duration_words(english, 3.0 * 86_400.0), "3 days");
        assert_eq!(duration_words(english, 90.0), "1.5 min");
        assert_eq!(duration_words(english, f64::INFINITY), "forever");
        let years = duration_words(polish, 5.0 * 365.25 * 86_400.0);
        assert!(years.starts_with("5 ") && years != "5 years", "{years}");
    }
}
