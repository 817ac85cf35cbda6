//! A field for every parameter of the current model: the paper's groups
//! first, the SI values below. A field takes text as typed: the text is the
//! user's while the field has focus, it is applied on Enter or when focus
//! leaves, Escape restores the applied value, and a refused value stays in
//! the field, with the reason beside it, until it is corrected.

use std::collections::HashMap;

use eframe::egui;

use crate::app::View;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{KEYS, Key, KeySpec};

/// The width of a number field, in points.
const FIELD_WIDTH: f32 = 72.0;

/// The text of the fields being typed in, or holding a refused value.
#[derive(Default)]
pub struct ParametersSection {
    drafts: HashMap<Key, String>,
}

impl View for ParametersSection {
    /// Values go through the same validation as `--set`: a refused value
    /// leaves the model as it was and says why.
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        // A draft lives while its field has focus or its value is refused: a
        // new preset or a value set elsewhere shows the model's value again.
        let focused = ui.memory(egui::Memory::focused);
        self.drafts
            .retain(|&key, _| state.refusal(key).is_some() || focused == Some(field_id(key)));
        let model = *state.model();
        let applicable: Vec<&'static KeySpec> = KEYS
            .iter()
            .filter(|k| k.applies_to(&model) && k.key != Key::Load)
            .collect();
        let (groups, si): (Vec<_>, Vec<_>) = applicable.into_iter().partition(|k| k.is_group);
        ui.label("dimensionless groups");
        for spec in groups {
            self.field(ui, state, theme, spec);
        }
        egui::CollapsingHeader::new("SI parameters").show(ui, |ui| {
            for spec in si {
                self.field(ui, state, theme, spec);
            }
        });
    }
}

/// The field of `key` (one id wherever the sidebar draws it).
fn field_id(key: Key) -> egui::Id {
    egui::Id::unique(("parameter field", key.name()))
}

/// What the text of a field asks for when it is committed.
fn parse(text: &str) -> Result<f64, String> {
    let trimmed = text.trim();
    trimmed
        .parse::<f64>()
        .map_err(|_| format!("'{trimmed}' is not a number"))
}

impl ParametersSection {
    fn field(
        &mut self,
        ui: &mut egui::Ui,
        state: &mut AppState,
        theme: &Theme,
        spec: &'static KeySpec,
    ) {
        let key = spec.key;
        // Focus is reported lost on more than one frame: only text that
        // differs from the value in use (or was refused) is applied.
        let applied_text = number_text(spec.get(state.model()));
        let mut text = self
            .drafts
            .get(&key)
            .cloned()
            .unwrap_or_else(|| applied_text.clone());
        let refused = state.refusal(key).is_some();
        let response = ui
            .horizontal(|ui| {
                let mut edit = egui::TextEdit::singleline(&mut text)
                    .id(field_id(key))
                    .desired_width(FIELD_WIDTH);
                if refused {
                    edit = edit.text_color(theme.error);
                }
                let r = ui.add(edit).accessible_name(key.name());
                // Only mu R enters the equations: the mu field keeps R and so
                // moves the load, and says so.
                let note = if key == Key::Mu {
                    "  (R held: moves p)"
                } else {
                    ""
                };
                ui.label(format!("{} {}{note}", key.name(), spec.unit));
                r
            })
            .inner
            .on_hover_text(format!("{} (allowed: {})", spec.description, spec.range));
        let escaped = response.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Escape));
        if escaped {
            // Back to the value in use.
            self.drafts.remove(&key);
            state.clear_refusal(key);
        } else if response.lost_focus() && (refused || text != applied_text) {
            match parse(&text) {
                Ok(value) => state.enter_parameter(key, value),
                Err(why) => state.refuse(key, why),
            }
            if state.refusal(key).is_some() {
                self.drafts.insert(key, text);
            } else {
                self.drafts.remove(&key);
            }
        } else if response.has_focus() {
            self.drafts.insert(key, text);
        }
        if let Some(why) = state.refusal(key) {
            ui.colored_label(theme.error, format!("refused: {why}"));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::parse;

    #[test]
    fn typed_text_is_a_number_or_says_why_not() {
        assert_eq!(parse(" 0.2 "), Ok(0.2));
        assert_eq!(parse("1e-3"), Ok(1e-3));
        assert_eq!(parse("0.2.1"), Err("'0.2.1' is not a number".to_owned()));
        assert_eq!(parse(""), Err("'' is not a number".to_owned()));
    }
}
