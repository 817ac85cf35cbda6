//! The time histories tab: the angles and delta against time, the energies
//! and a phase portrait of rod 2, over the run's recent past.

use eframe::egui;

use crate::app::View;
use crate::app::plots::histories_ui;
use crate::app::state::AppState;
use crate::app::theme::Theme;

#[derive(Default)]
pub struct HistoriesTab;

impl View for HistoriesTab {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        histories_ui(ui, state.history(), theme);
    }
}
