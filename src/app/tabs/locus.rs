//! The root locus tab: the eigenvalues in the complex plane beside their
//! real and imaginary parts against the load, the current load marked.

use eframe::egui::{self, vec2};

use crate::app::View;
use crate::app::plots::{root_locus_ui, versus_load_ui};
use crate::app::state::AppState;
use crate::app::theme::Theme;

#[derive(Default)]
pub struct LocusTab;

impl View for LocusTab {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        let Some(analysis) = state.analysis() else {
            let why = state
                .analysis_failure()
                .map_or_else(String::new, |error| format!(": {error}"));
            ui.colored_label(
                theme.warning,
                format!("No root locus for these parameters{why}."),
            );
            return;
        };
        let load = state.model().load_p();
        let overlay = state.overlay().map(|o| &o.locus);
        let current = state.current_eigenvalues();
        let width = ui.available_width();
        let height = ui.available_height();
        ui.horizontal(|ui| {
            ui.allocate_ui(vec2(0.42 * width, height), |ui| {
                root_locus_ui(
                    ui,
                    &analysis.locus,
                    overlay,
                    &current,
                    state.measured(),
                    theme,
                );
            });
            ui.vertical(|ui| {
                for imaginary in [false, true] {
                    ui.allocate_ui(vec2(ui.available_width(), 0.5 * height - 4.0), |ui| {
                        versus_load_ui(
                            ui,
                            &analysis.locus,
                            overlay,
                            &analysis.ranges,
                            load,
                            imaginary,
                            theme,
                        );
                    });
                }
            });
        });
    }
}
