//! The model picker (the presets, each with its source) and the engine picker.

use eframe::egui::{self, RichText};

use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::speak::Speak as _;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::model::{PRESETS, PresetId};
use crate::sim::EngineKind;
use crate::tr;

pub struct ModelSection;

impl View for ModelSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, _theme: &Theme) {
        let words = ui.words();
        let current = state.settings().preset;
        let mut chosen = current;
        let source = |id: PresetId| words.get(&format!("preset-{}", id.name()));
        let description = |id: PresetId| words.get(&format!("preset-{}.description", id.name()));
        let shown = |id: PresetId| format!("{} ({})", id.name(), source(id));
        // The label first and the name cut to the panel's width, so that a
        // long name in projector mode does not squeeze the label.
        ui.horizontal(|ui| {
            let label = ui.label(tr!(words, "model"));
            egui::ComboBox::from_id_salt("model")
                .selected_text(shown(chosen))
                .width(ui.available_width() - ui.spacing().icon_width)
                .truncate()
                .show_ui(ui, |ui| {
                    for p in &PRESETS {
                        ui.selectable_value(&mut chosen, p.id, shown(p.id))
                            .on_hover_text(description(p.id));
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(format!(
                    "{}\n\n{}",
                    description(chosen),
                    tr!(words, "model.source", source = source(chosen))
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
            ui.label(RichText::new(description(state.settings().preset)).small());
        }
        match eta {
            Some(0.0) => {
                ui.label(tr!(words, "tip-force-dead"));
            }
            Some(eta) => {
                ui.label(tr!(
                    words,
                    "tip-force-partial",
                    eta = crate::format::Shown(eta).to_string()
                ));
            }
            None => {}
        }
        let mut engine = state.settings().engine;
        let engine_name = |engine| match engine {
            EngineKind::Rapier => tr!(words, "engine-rapier"),
            EngineKind::Reference => tr!(words, "engine-reference"),
        };
        egui::ComboBox::from_label(tr!(words, "engine"))
            .selected_text(engine_name(engine))
            .show_ui(ui, |ui| {
                ui.selectable_value(
                    &mut engine,
                    EngineKind::Rapier,
                    engine_name(EngineKind::Rapier),
                )
                .on_hover_text(tr!(words, "engine-rapier.tooltip"));
                ui.selectable_value(
                    &mut engine,
                    EngineKind::Reference,
                    engine_name(EngineKind::Reference),
                )
                .on_hover_text(tr!(words, "engine-reference.tooltip"));
            })
            .response
            .on_hover_text(tr!(words, "engine.tooltip"));
        if engine != state.settings().engine {
            actions.push(Action::Engine(engine));
        }
    }
}
