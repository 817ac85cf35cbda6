//! A field for every parameter of the current model: the paper's groups
//! first, the SI values below.

use eframe::egui;

use crate::app::View;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{KEYS, Key, KeySpec};

pub struct ParametersSection;

impl View for ParametersSection {
    /// Values go through the same validation as `--set`: a refused value
    /// leaves the model as it was and says why.
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        let model = *state.model();
        let applicable: Vec<&'static KeySpec> = KEYS
            .iter()
            .filter(|k| k.applies_to(&model) && k.key != Key::Load)
            .collect();
        let (groups, si): (Vec<_>, Vec<_>) = applicable.into_iter().partition(|k| k.is_group);
        ui.label("dimensionless groups");
        for spec in groups {
            parameter_field(ui, state, theme, spec);
        }
        egui::CollapsingHeader::new("SI parameters").show(ui, |ui| {
            for spec in si {
                parameter_field(ui, state, theme, spec);
            }
        });
    }
}

fn parameter_field(ui: &mut egui::Ui, state: &mut AppState, theme: &Theme, spec: &'static KeySpec) {
    let mut value = spec.get(state.model());
    let response = ui
        .horizontal(|ui| {
            let speed = (value.abs() * 0.01).max(1e-4);
            let r = ui
                .add(
                    egui::DragValue::new(&mut value)
                        .speed(speed)
                        .custom_formatter(|v, _| number_text(v)),
                )
                .accessible_name(spec.key.name());
            // Only mu R enters the equations: the mu field keeps R and so
            // moves the load, and says so.
            let note = if spec.key == Key::Mu {
                "  (R held: moves p)"
            } else {
                ""
            };
            ui.label(format!("{} {}{note}", spec.key, spec.unit));
            r
        })
        .inner
        .on_hover_text(format!("{} (allowed: {})", spec.description, spec.range));
    if response.changed() {
        state.enter_parameter(spec.key, value);
    }
    if let Some(why) = state.refusal(spec.key) {
        ui.colored_label(theme.error, format!("refused: {why}"));
    }
}
