//! The window's words in every language it speaks: the message files under
//! `assets/locales/` (Project Fluent), compiled in, looked up by id, with
//! English behind every other language for an id a translation lacks.
//!
//! Numbers reach a message already written (`format`'s text, a decimal
//! point): the window shows measurements to compare with the command line,
//! so they read the same in every language. Counts are passed as numbers,
//! so that Fluent picks each language's plural form (Polish has three).

mod language;
mod pseudo;
mod refusals;
mod terms;

use std::borrow::Cow;
use std::sync::OnceLock;

use fluent_bundle::concurrent::FluentBundle;
use fluent_bundle::{FluentArgs, FluentResource};

pub use fluent_bundle::FluentValue;
pub use language::{Language, UnknownLanguage};
pub use refusals::{
    allowed_words, analysis_error, model_error, not_resolved_words, quantity_words, ramp_error,
    sim_error,
};
pub use terms::{duration_words, state_name, transition_in, transition_text};

/// The message file of each language, as shipped: English is the source.
const SOURCES: [(Language, &str); 6] = [
    (
        Language::English,
        include_str!("../../assets/locales/en.ftl"),
    ),
    (
        Language::German,
        include_str!("../../assets/locales/de.ftl"),
    ),
    (
        Language::Italian,
        include_str!("../../assets/locales/it.ftl"),
    ),
    (
        Language::Polish,
        include_str!("../../assets/locales/pl.ftl"),
    ),
    (
        Language::Spanish,
        include_str!("../../assets/locales/es.ftl"),
    ),
    (
        Language::French,
        include_str!("../../assets/locales/fr.ftl"),
    ),
];

/// The message file `language` is read from (the pseudo-language's is the
/// English one, transformed as it is read).
#[must_use]
pub fn source(language: Language) -> &'static str {
    let read_as = if language == Language::Pseudo {
        Language::English
    } else {
        language
    };
    SOURCES
        .iter()
        .find(|(l, _)| *l == read_as)
        .map_or(SOURCES[0].1, |(_, text)| text)
}

/// One language's messages.
pub struct Words {
    language: Language,
    bundle: FluentBundle<FluentResource>,
    /// What the file said that Fluent could not read (none in a shipped
    /// file: the tests read every one).
    problems: Vec<String>,
}

impl std::fmt::Debug for Words {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Words({})", self.language)
    }
}

/// The words of `language`, read once for the life of the process.
#[must_use]
pub fn words(language: Language) -> &'static Words {
    static READ: [OnceLock<Words>; Language::COUNT] = [const { OnceLock::new() }; Language::COUNT];
    READ[language as usize].get_or_init(|| Words::read(language))
}

impl Words {
    fn read(language: Language) -> Self {
        let mut problems = Vec::new();
        let resource = match FluentResource::try_new(source(language).to_owned()) {
            Ok(resource) => resource,
            Err((resource, errors)) => {
                problems.extend(errors.iter().map(|e| format!("{e:?}")));
                resource
            }
        };
        let mut bundle = FluentBundle::new_concurrent(vec![language.identifier()]);
        // Unicode isolation marks around placeables show as boxes in egui's
        // fonts; every placeable here is a number or a name in the same script.
        bundle.set_use_isolating(false);
        if language == Language::Pseudo {
            bundle.set_transform(Some(pseudo::transform));
        }
        if let Err(errors) = bundle.add_resource(resource) {
            problems.extend(errors.iter().map(|e| format!("{e:?}")));
        }
        Self {
            language,
            bundle,
            problems,
        }
    }

    /// The language these words are in.
    #[must_use]
    pub fn language(&self) -> Language {
        self.language
    }

    /// What could not be read from the language's file.
    #[must_use]
    pub fn problems(&self) -> &[String] {
        &self.problems
    }

    /// The message `id` (`id.attribute` for an attribute), without
    /// arguments.
    #[must_use]
    pub fn get(&'static self, id: &str) -> Cow<'static, str> {
        self.format(id, None)
    }

    /// The message `id` with its arguments: `args` pairs each placeable's
    /// name with its value.
    #[must_use]
    pub fn with(&'static self, id: &str, args: &[(&str, FluentValue<'_>)]) -> String {
        let mut fluent_args = FluentArgs::with_capacity(args.len());
        for (name, value) in args {
            fluent_args.set(*name, value.clone());
        }
        self.format(id, Some(&fluent_args)).into_owned()
    }

    /// Whether this language's own file has the message `id`.
    #[must_use]
    pub fn has(&self, id: &str) -> bool {
        self.pattern(id).is_some()
    }

    fn pattern(&self, id: &str) -> Option<&fluent_syntax::ast::Pattern<&str>> {
        let (message, attribute) = match id.split_once('.') {
            Some((message, attribute)) => (message, Some(attribute)),
            None => (id, None),
        };
        let message = self.bundle.get_message(message)?;
        match attribute {
            Some(name) => message.get_attribute(name).map(|a| a.value()),
            None => message.value(),
        }
    }

    /// The message formatted, from this language's file or else English's;
    /// an id in neither is shown as itself (the tests see that none is).
    fn format(&'static self, id: &str, args: Option<&FluentArgs>) -> Cow<'static, str> {
        let english = words(Language::English);
        let found = match self.pattern(id) {
            Some(pattern) => Some((self, pattern)),
            None => english.pattern(id).map(|pattern| (english, pattern)),
        };
        match found {
            Some((from, pattern)) => {
                let mut errors = Vec::new();
                from.bundle.format_pattern(pattern, args, &mut errors)
            }
            None => Cow::Owned(id.to_owned()),
        }
    }
}

/// `tr!(words, "status-ready")`, or `tr!(words, "rods-count", count = 3)`
/// with each placeable's name and value: the
/// message (a count as a number, a measurement as its text).
#[macro_export]
macro_rules! tr {
    ($words:expr, $id:expr) => {
        $words.get($id).into_owned()
    };
    ($words:expr, $id:expr, $($name:ident = $value:expr),+ $(,)?) => {
        $words.with(
            $id,
            &[$((stringify!($name), $crate::i18n::FluentValue::from($value))),+],
        )
    };
}

#[cfg(test)]
mod tests;
