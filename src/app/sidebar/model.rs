//! The model picker (the presets, each with its source) and the engine picker.

use eframe::egui::{self, RichText};

use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::model::{PRESETS, PresetId};
use crate::sim::EngineKind;

pub struct ModelSection;

impl View for ModelSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, _theme: &Theme) {
        let current = state.settings().preset;
        let mut chosen = current;
        let shown = |id: PresetId| format!("{} ({})", id.name(), id.preset().source);
        // The label first and the name cut to the panel's width, so that a
        // long name in projector mode does not squeeze the label.
        ui.horizontal(|ui| {
            let label = ui.label("model");
            egui::ComboBox::from_id_salt("model")
                .selected_text(shown(chosen))
                .width(ui.available_width() - ui.spacing().icon_width)
                .truncate()
                .show_ui(ui, |ui| {
                    for p in &PRESETS {
                        ui.selectable_value(&mut chosen, p.id, shown(p.id))
                            .on_hover_text(p.description);
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(format!(
                    "{}\n\n{}: where the model is in the study this program follows (its figure and equations)",
                    chosen.preset().description,
                    chosen.preset().source
                ));
        });
        if chosen != current {
            actions.push(Action::Preset(chosen));
        }
        // In front of a class the picker's tooltip holds the description;
        // while a lesson keeps the answer it is not shown (some name their
        // critical loads).
        // The preset's words name its force; a changed eta changes that
        // force, and then they are not shown above words that contradict
        // them ("ideal follower force" over "a dead load").
        let eta = state.model().load.eta().filter(|&eta| eta < 1.0);
        if !state.settings().projector && !state.answer_hidden() && eta.is_none() {
            ui.label(RichText::new(state.settings().preset.preset().description).small());
        }
        match eta {
            Some(0.0) => {
                ui.label("tip force: a dead load (eta = 0), fixed in direction, in place of the preset's follower force");
            }
            Some(eta) => {
                ui.label(format!(
                    "tip force: partly tangential, turned by eta = {} of the last rod's angle (the preset's follower force has eta = 1)",
                    crate::format::Shown(eta)
                ));
            }
            None => {}
        }
        let mut engine = state.settings().engine;
        egui::ComboBox::from_label("engine")
            .selected_text(format!("{engine:?}").to_lowercase())
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut engine, EngineKind::Rapier, "rapier")
                    .on_hover_text("rapier: the rapier2d physics engine, rods as rigid bodies joined by hinges (a multibody), the roller's spin implicit");
                ui.selectable_value(&mut engine, EngineKind::Reference, "reference")
                    .on_hover_text("adaptive Dormand-Prince 5(4) on the exact equations");
            })
            .response
            .on_hover_text("what integrates the motion: the run goes on from where it is");
        if engine != state.settings().engine {
            actions.push(Action::Engine(engine));
        }
    }
}
