//! The controls on the left: the notice line, then the model, the load,
//! the load ramp, the parameters, time, the status card, the overlay and the settings to
//! share, each a section in a file of its own.

mod load;
mod model;
mod number_field;
mod parameters;
mod ramp;
mod share;
mod status;
mod time;

use eframe::egui;

use super::View;
use super::command::Command;
use super::state::AppState;
use super::theme::Theme;
use crate::model::{PRESETS, PresetId};

/// The sidebar and the sections that keep something of their own.
#[derive(Default)]
pub struct Sidebar {
    load: load::LoadSection,
    parameters: parameters::ParametersSection,
    ramp: ramp::RampSection,
    share: share::ShareSection,
}

impl View for Sidebar {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        ui.heading("zieglerlab");
        if let Some(notice) = state.notice().cloned() {
            ui.horizontal_wrapped(|ui| {
                ui.colored_label(theme.notice_color(notice.level), notice.text);
                if ui.small_button("dismiss").clicked() {
                    state.dismiss_notice();
                }
            });
        }
        ui.separator();
        model::ModelSection.ui(ui, state, theme);
        ui.separator();
        self.load.ui(ui, state, theme);
        self.ramp.ui(ui, state, theme);
        ui.separator();
        self.parameters.ui(ui, state, theme);
        ui.separator();
        time::TimeSection.ui(ui, state, theme);
        ui.separator();
        status::StatusSection.ui(ui, state, theme);
        ui.separator();
        overlay_ui(ui, state);
        let mut projector = state.settings().projector;
        if ui.checkbox(&mut projector, "projector mode (P)").changed() {
            state.set_projector(projector);
        }
        self.share.ui(ui, state, theme);
        egui::CollapsingHeader::new("keys").show(ui, Command::keys_help_ui);
    }
}

/// Another preset's locus behind the current one.
fn overlay_ui(ui: &mut egui::Ui, state: &mut AppState) {
    let current = state.overlay().map(|o| o.preset);
    let mut chosen = current;
    egui::ComboBox::from_label("overlay")
        .selected_text(chosen.map_or("none", PresetId::name))
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut chosen, None, "none");
            for p in &PRESETS {
                ui.selectable_value(&mut chosen, Some(p.id), p.name);
            }
        })
        .response
        .on_hover_text("another model's locus in grey, at the same a (as Fig. 8 sets the ideal column beside the roller)");
    if chosen != current {
        state.set_overlay(chosen);
    }
}
