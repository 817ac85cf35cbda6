//! The root locus tab: the eigenvalues in the complex plane beside their
//! real and imaginary parts against the load, the current load marked, and
//! the overlay's critical loads when one is drawn.

use eframe::egui::{self, vec2};

use super::{TabSpec, TabView, save_buttons};
use crate::analysis::Locus;
use crate::app::View;
use crate::app::action::{Actions, Table};
use crate::app::plot_frame::{Fit, Swatch, legend_row};
use crate::app::plots::{root_locus_ui, versus_load_ui};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::app::theme::load_color;
use crate::format::number_text;
use crate::model::{Model, PresetId};

pub const TAB: TabSpec = TabSpec {
    id: "locus",
    title: "root locus",
    tooltip: "the root locus: the column's eigenvalues in the complex plane and against the load. Left of the vertical axis a motion dies away, right of it it grows; the height is the frequency. Flutter starts where a pair crosses the axis",
    background: false,
    make: || Box::new(LocusTab::default()),
};

/// The plots refit when the analysis drawn (of other parameters) or the
/// overlay changes, and on "reset all".
#[derive(Default)]
pub struct LocusTab {
    fit: Fit<(u64, Model, Option<PresetId>)>,
}

impl TabView for LocusTab {}

impl View for LocusTab {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        let Some(analysis) = state.analysis() else {
            if state.analysis_pending() {
                // A long chain's first analysis takes seconds, off this thread.
                ui.horizontal(|ui| {
                    ui.spinner();
                    ui.label("Computing the root locus of these parameters...");
                });
                return;
            }
            let why = state
                .analysis_failure()
                .map_or_else(String::new, |error| format!(": {error}"));
            ui.colored_label(
                theme.warning,
                format!("No root locus for these parameters{why}."),
            );
            return;
        };
        self.fit.bar_ui(ui, state.for_picture(), |ui| {
            save_buttons(ui, Some(Table::Locus), actions);
        });
        let overlay = state.overlay();
        legend_ui(ui, state, &analysis.locus, theme);
        // The analysis drawn (it may come in a frame after the parameters).
        let refit = self.fit.refit((
            state.view_generation(),
            *analysis.key,
            overlay.map(|o| o.preset),
        ));
        let load = state.model().load_p();
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
                    refit,
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
                            refit,
                            theme,
                        );
                    });
                }
            });
        });
    }
}

impl LocusTab {
    /// The root locus in the complex plane alone (beside the scene on a
    /// projector too small for the tab's plots), refitted as the tab's are.
    pub fn complex_plane_ui(&mut self, ui: &mut egui::Ui, state: &AppState, theme: &Theme) {
        let Some(analysis) = state.analysis() else {
            return;
        };
        let overlay = state.overlay();
        let refit = self.fit.refit((
            state.view_generation(),
            *analysis.key,
            overlay.map(|o| o.preset),
        ));
        let loads = &analysis.locus.loads;
        ui.label(format!(
            "root locus, p = {} to {}",
            number_text(loads.first().copied().unwrap_or(0.0)),
            number_text(loads.last().copied().unwrap_or(0.0))
        ));
        root_locus_ui(
            ui,
            &analysis.locus,
            overlay,
            &state.current_eigenvalues(),
            state.measured(),
            refit,
            theme,
        );
    }
}

/// The legend of the tab's plots, above them: what the colours, markers
/// and lines are, and the overlay's own critical loads.
fn legend_ui(ui: &mut egui::Ui, state: &AppState, locus: &Locus, theme: &Theme) {
    let (min, max) = (
        locus.loads.first().copied().unwrap_or(0.0),
        locus.loads.last().copied().unwrap_or(1.0),
    );
    let scale = (0..8)
        .map(|i| load_color(min + (max - min) * f64::from(i) / 7.0, min, max))
        .collect();
    let mut entries = vec![
        (
            Swatch::Scale(scale),
            format!(
                "branch colour: the load, p = {} to {}",
                number_text(min),
                number_text(max)
            ),
        ),
        (
            Swatch::Dot(theme.now),
            "eigenvalues at the current load".to_owned(),
        ),
    ];
    if state.measured().is_some() {
        entries.push((
            Swatch::Ring(theme.measured),
            "measured from the run".to_owned(),
        ));
    }
    entries.push((Swatch::Line(theme.load_line), "current load".to_owned()));
    if let Some(overlay) = state.overlay() {
        let loads = if overlay.transitions.is_empty() {
            "no change of stability up to the slider's end".to_owned()
        } else {
            overlay
                .transitions
                .iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(";  ")
        };
        entries.push((
            Swatch::Line(theme.overlay),
            format!("overlay {}: {loads}", overlay.preset),
        ));
    }
    legend_row(ui, &entries);
}
