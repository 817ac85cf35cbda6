//! The time histories tab: the angles and delta against time, the energies
//! and a phase portrait of rod 2, over the run's recent past.

use eframe::egui;

use super::{TabSpec, TabView, save_buttons};
use crate::app::View;
use crate::app::action::{Actions, Table};
use crate::app::plot_frame::Fit;
use crate::app::plots::histories_ui;
use crate::app::state::AppState;
use crate::app::theme::Theme;

pub const TAB: TabSpec = TabSpec {
    tab: super::Tab::Histories,
    id: "histories",
    background: false,
    make: || Box::new(HistoriesTab::default()),
};

/// The plots follow the run until they are zoomed or panned; "fit" (or a
/// double-click) makes them follow it again.
#[derive(Default)]
pub struct HistoriesTab {
    fit: Fit<u64>,
}

impl TabView for HistoriesTab {}

impl View for HistoriesTab {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.fit.bar_ui(ui, state.for_picture(), |ui| {
            save_buttons(ui, Some(Table::History), actions);
        });
        let refit = self.fit.refit(state.view_generation());
        let band = state.model().roller().is_some();
        histories_ui(ui, state.history(), band, refit, theme);
    }
}
