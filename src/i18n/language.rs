//! The languages the window speaks, their codes and names, and the one the
//! system asks for.

use fluent_langneg::{NegotiationStrategy, negotiate_languages};
use unic_langid::LanguageIdentifier;

/// A language of the window.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Language {
    /// The source language: every message is written in English first.
    #[default]
    English,
    German,
    Italian,
    Polish,
    Spanish,
    French,
    /// English made longer (40%) and accented, for layout tests: text that
    /// fits in it fits in the real languages. Not offered in the menu.
    Pseudo,
}

/// A code that names none of the languages.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown language '{0}': expected one of en, de, it, pl, es, fr")]
pub struct UnknownLanguage(pub String);

impl Language {
    /// How many there are, the pseudo-language included.
    pub const COUNT: usize = 7;

    /// The languages a person can choose, in the menu's order.
    pub const CHOSEN_FROM: [Self; 6] = [
        Self::English,
        Self::German,
        Self::Italian,
        Self::Polish,
        Self::Spanish,
        Self::French,
    ];

    /// Its code (ISO 639-1; `pseudo` for the pseudo-language).
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            Self::English => "en",
            Self::German => "de",
            Self::Italian => "it",
            Self::Polish => "pl",
            Self::Spanish => "es",
            Self::French => "fr",
            Self::Pseudo => "pseudo",
        }
    }

    /// Its name in itself, as the language menu lists it.
    #[must_use]
    pub fn endonym(self) -> &'static str {
        match self {
            Self::English => "English",
            Self::German => "Deutsch",
            Self::Italian => "Italiano",
            Self::Polish => "Polski",
            Self::Spanish => "Español",
            Self::French => "Français",
            Self::Pseudo => "Ƥšéúđó",
        }
    }

    /// The language a code names (`de`, `de-AT`, `de_DE.UTF-8` all name
    /// German), or the pseudo-language's `pseudo`.
    ///
    /// # Errors
    /// A code of none of them.
    pub fn from_code(code: &str) -> Result<Self, UnknownLanguage> {
        let trimmed = code.trim();
        if trimmed.eq_ignore_ascii_case("pseudo") {
            return Ok(Self::Pseudo);
        }
        Self::negotiate(&[trimmed]).ok_or_else(|| UnknownLanguage(code.to_owned()))
    }

    /// The language the system asks for: the first of `LANGUAGE`, `LC_ALL`,
    /// `LC_MESSAGES` and `LANG` that is set (as the C library reads them),
    /// English where that is none of ours or the plain C locale.
    #[must_use]
    pub fn system() -> Self {
        let asked: Vec<String> = sys_locale::get_locales().collect();
        Self::from_locales(&asked)
    }

    /// The language for locales in order of preference: the best of ours
    /// for them, English when the first is the C locale (which asks for no
    /// language) or none matches.
    #[must_use]
    pub fn from_locales<S: AsRef<str>>(locales: &[S]) -> Self {
        let Some(first) = locales.first() else {
            return Self::English;
        };
        if matches!(posix_language(first.as_ref()), "C" | "POSIX" | "") {
            return Self::English;
        }
        Self::negotiate(locales).unwrap_or(Self::English)
    }

    /// The best of ours for `locales`, matching by language alone.
    fn negotiate<S: AsRef<str>>(locales: &[S]) -> Option<Self> {
        let requested: Vec<LanguageIdentifier> = locales
            .iter()
            .filter_map(|l| posix_language(l.as_ref()).parse().ok())
            .collect();
        let available: Vec<LanguageIdentifier> =
            Self::CHOSEN_FROM.iter().map(|l| l.identifier()).collect();
        let best = negotiate_languages(&requested, &available, None, NegotiationStrategy::Lookup);
        let best = best.first()?;
        Self::CHOSEN_FROM
            .into_iter()
            .find(|l| l.identifier() == **best)
    }

    /// Its language identifier (the pseudo-language's is English's, whose
    /// plural rules it follows).
    #[must_use]
    pub fn identifier(self) -> LanguageIdentifier {
        let code = if self == Self::Pseudo {
            "en"
        } else {
            self.code()
        };
        code.parse().unwrap_or_default()
    }
}

/// A POSIX locale's language and region (`de_DE.UTF-8@euro` is `de_DE`),
/// with `-` for `_` as language identifiers write it.
fn posix_language(locale: &str) -> &str {
    let end = locale.find(['.', '@']).unwrap_or(locale.len());
    locale[..end].trim()
}

impl std::fmt::Display for Language {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.code())
    }
}

impl std::str::FromStr for Language {
    type Err = UnknownLanguage;

    fn from_str(code: &str) -> Result<Self, UnknownLanguage> {
        Self::from_code(code)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_system_s_locale_picks_the_language_as_the_c_library_would() {
        assert_eq!(Language::from_locales(&["de-DE"]), Language::German);
        assert_eq!(Language::from_locales(&["pl_PL.UTF-8"]), Language::Polish);
        assert_eq!(Language::from_locales(&["fr-CA", "en"]), Language::French);
        // LC_ALL=C overrides a German LANG, as it does for every program.
        assert_eq!(Language::from_locales(&["C", "de-DE"]), Language::English);
        assert_eq!(Language::from_locales(&["POSIX"]), Language::English);
        // A language of none of ours, then one of ours: the second.
        assert_eq!(
            Language::from_locales(&["pt-BR", "es-ES"]),
            Language::Spanish
        );
        assert_eq!(Language::from_locales(&["ja-JP"]), Language::English);
        assert_eq!(Language::from_locales::<&str>(&[]), Language::English);
    }

    #[test]
    fn codes_name_the_languages_and_nothing_else() {
        for language in Language::CHOSEN_FROM {
            assert_eq!(Language::from_code(language.code()), Ok(language));
        }
        assert_eq!(Language::from_code("de_AT"), Ok(Language::German));
        assert_eq!(Language::from_code("pseudo"), Ok(Language::Pseudo));
        assert!(Language::from_code("xx").is_err());
        assert!(Language::from_code("").is_err());
        assert_eq!(Language::CHOSEN_FROM.len() + 1, Language::COUNT);
    }
}
