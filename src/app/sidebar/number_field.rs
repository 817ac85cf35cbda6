//! Number fields that take text as typed: the text is the user's while the
//! field has focus, it is applied on Enter or when focus leaves, Escape
//! restores the value in use, and a refused value stays in the field, in
//! the error colour, until it is corrected (the reason is the caller's to
//! show beside it).

use crate::app::speak::Speak as _;
use crate::tr;
use std::collections::HashMap;

use eframe::egui;

use crate::app::action::{Action, Actions, Refusal};
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::number_text;
use crate::model::Key;

/// The width of a number field, in points.
const FIELD_WIDTH: f32 = 72.0;

/// The text of the fields being typed in, or holding a refused value.
#[derive(Default)]
pub struct NumberFields {
    drafts: HashMap<Key, String>,
}

/// The field of `key` (one id wherever it is drawn).
fn field_id(key: Key) -> egui::Id {
    egui::Id::unique(("number field", key.name()))
}

/// What the text of a field asks for when it is committed.
fn parse(text: &str) -> Result<f64, Refusal> {
    let trimmed = text.trim();
    trimmed
        .parse::<f64>()
        .map_err(|_| Refusal::NotANumber(trimmed.to_owned()))
}

impl NumberFields {
    /// Forgets the drafts of fields that neither have focus nor hold a
    /// refused value: a new preset or a value set elsewhere (the slider, a
    /// key, the map) shows the model's value again. Call once a frame.
    pub fn prune(&mut self, ui: &egui::Ui, state: &AppState) {
        let focused = ui.memory(egui::Memory::focused);
        self.drafts
            .retain(|&key, _| state.is_refused(key) || focused == Some(field_id(key)));
    }

    /// The field of `key`, named `key` for screen readers and tests.
    pub fn show(
        &mut self,
        ui: &mut egui::Ui,
        state: &AppState,
        actions: &mut Actions,
        theme: &Theme,
        key: Key,
    ) -> egui::Response {
        // Focus is reported lost on more than one pass (egui reruns a pass
        // whose layout changed, without the key events): only text that
        // differs from the value in use, or was refused, is applied.
        let applied_text = number_text(key.get(state.model()));
        let mut text = self
            .drafts
            .get(&key)
            .cloned()
            .unwrap_or_else(|| applied_text.clone());
        let refused = state.is_refused(key);
        let mut edit = egui::TextEdit::singleline(&mut text)
            .id(field_id(key))
            .desired_width(FIELD_WIDTH)
            // Wider for a long value than cut: "7.8125e-4" cut to "7.812"
            // on a projector read as another number.
            .clip_text(false);
        if refused {
            edit = edit.text_color(color(theme.palette.error));
        }
        // The load by its word (the others by their symbols, a, nu, k1...).
        let name = if key == Key::Load {
            tr!(ui.words(), "mark-load")
        } else {
            key.name().to_owned()
        };
        let response = ui.add(edit).accessible_name(name);
        let escaped = response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Escape));
        if escaped {
            self.drafts.remove(&key);
            actions.push(Action::ClearRefusal(key));
        } else if response.lost_focus() && (refused || text != applied_text) {
            // The text stays until the value is applied: a refused one stays
            // on (see `prune`). A pass egui reruns asks only once.
            actions.push_once(match parse(&text) {
                Ok(value) => Action::Enter { key, value },
                Err(why) => Action::Refuse { key, why },
            });
            self.drafts.insert(key, text);
        } else if response.has_focus() {
            self.drafts.insert(key, text);
        }
        response
    }
}

/// The reason a typed value for `key` was refused, under its field.
pub fn refusal_ui(ui: &mut egui::Ui, state: &AppState, theme: &Theme, key: Key) {
    if let Some(why) = state.refusal(key) {
        ui.colored_label(
            color(theme.palette.error),
            tr!(ui.words(), "refused", why = why),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::{Refusal, parse};
    use crate::i18n::{Language, words};

    #[test]
    fn typed_text_is_a_number_or_says_why_not() {
        assert_eq!(parse(" 0.2 "), Ok(0.2));
        assert_eq!(parse("1e-3"), Ok(1e-3));
        let en = words(Language::English);
        assert_eq!(
            parse("0.2.1").unwrap_err().words(en),
            "'0.2.1' is not a number"
        );
        assert_eq!(parse(""), Err(Refusal::NotANumber(String::new())));
    }
}
