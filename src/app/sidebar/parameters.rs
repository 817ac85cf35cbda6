//! A field for every parameter of the current model: the paper's groups
//! first, the SI values below, each a number field that takes text as typed.

use eframe::egui;

use super::number_field::{NumberFields, refusal_ui};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::speak::Speak as _;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::model::{KEYS, Key, KeySpec};
use crate::tr;

/// The parameters' number fields.
#[derive(Default)]
pub struct ParametersSection {
    fields: NumberFields,
}

impl View for ParametersSection {
    /// Values go through the same validation as `--set`: a refused value
    /// leaves the model as it was and says why.
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.fields.prune(ui, state);
        let model = *state.model();
        let applicable: Vec<&'static KeySpec> = KEYS
            .iter()
            // The load has its own bar.
            .filter(|k| k.applies_to(&model) && k.key != Key::Load)
            .collect();
        let (groups, si): (Vec<_>, Vec<_>) = applicable.into_iter().partition(|k| k.is_group);
        let words = ui.words();
        ui.label(tr!(words, "groups"))
            .on_hover_text(tr!(words, "groups.tooltip"));
        for spec in groups {
            self.field(ui, state, actions, theme, spec);
        }
        egui::CollapsingHeader::new(tr!(words, "si-parameters")).show(ui, |ui| {
            for spec in si {
                self.field(ui, state, actions, theme, spec);
            }
        });
    }
}

impl ParametersSection {
    fn field(
        &mut self,
        ui: &mut egui::Ui,
        state: &AppState,
        actions: &mut Actions,
        theme: &Theme,
        spec: &'static KeySpec,
    ) {
        let key = spec.key;
        let words = ui.words();
        ui.horizontal(|ui| {
            self.fields.show(ui, state, actions, theme, key);
            // Only mu R enters the equations: the mu field keeps R and so
            // moves the load, and says so.
            let note = if key == Key::Mu {
                format!("  {}", tr!(words, "mu-moves-load"))
            } else {
                String::new()
            };
            ui.label(format!("{} {}{note}", key.name(), spec.unit));
        })
        .response
        .on_hover_text(tr!(
            words,
            "key-allowed",
            description = words.get(&format!("key-{}", key.name())),
            range = words.get(&format!("key-{}.range", key.name()))
        ));
        refusal_ui(ui, state, theme, key);
    }
}
