//! The field's terms put together in a language: a state's name, a
//! critical load, a duration.

use crate::analysis::{State, Transition};
use crate::format::{duration_text, load_text};
use crate::tr;

use super::Words;

/// A state's name in `words`' language (message `state-NAME`).
#[must_use]
pub fn state_name(words: &'static Words, state: State) -> String {
    words.get(&format!("state-{}", state.name())).into_owned()
}

/// A critical load in words: "p = 2.5417: stable -> flutter".
#[must_use]
pub fn transition_text(words: &'static Words, t: &Transition) -> String {
    transition_in(words, "transition", t)
}

/// A critical load in the message `id`, whose placeables are its `load`
/// and the states it goes `from` and `to`.
#[must_use]
pub fn transition_in(words: &'static Words, id: &str, t: &Transition) -> String {
    tr!(
        words,
        id,
        load = load_text(t.load),
        from = state_name(words, t.from),
        to = state_name(words, t.to)
    )
}

/// A duration in `words`' language: seconds, minutes and hours by their
/// symbols (as `format::duration_text` writes them), days and years in
/// words, each with the plural its number takes.
#[must_use]
pub fn duration_words(words: &'static Words, secs: f64) -> String {
    let text = duration_text(secs);
    let in_words = |unit: &str, id: &str| {
        let number = text.strip_suffix(unit)?;
        let count: f64 = number.parse().ok()?;
        Some(tr!(words, id, count = count, n = number.to_owned()))
    };
    if !secs.is_finite() {
        return tr!(words, "duration-forever");
    }
    in_words(" days", "duration-days")
        .or_else(|| in_words(" years", "duration-years"))
        .unwrap_or(text)
}
