//! The root locus tab: the eigenvalues in the complex plane beside their
//! real and imaginary parts against the load, the current load marked, and
//! the overlay's critical loads when one is drawn.

use crate::app::speak::Speak as _;
use crate::tr;
use eframe::egui::{self, vec2};

use super::{TabSpec, TabView, save_buttons};
use crate::analysis::C64;
use crate::app::View;
use crate::app::action::{Actions, Table};
use crate::app::plot_draw::{legend_ui, plot_ui};
use crate::app::plot_frame::Fit;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{Model, PresetId};
use crate::plot::locus::{Layer, Loci, Present};

pub const TAB: TabSpec = TabSpec {
    tab: super::Tab::Locus,
    id: "locus",
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
        let words = ui.words();
        let Some(analysis) = state.analysis() else {
            if state.analysis_pending() {
                // A long chain's first analysis takes seconds, off this thread.
                ui.horizontal(|ui| {
                    ui.spinner();
                    ui.label(tr!(words, "locus-computing"));
                });
                return;
            }
            ui.colored_label(
                theme.warning,
                match state.analysis_failure() {
                    Some(error) => tr!(
                        words,
                        "locus-none-why",
                        why = crate::i18n::analysis_error(words, error)
                    ),
                    None => tr!(words, "locus-none"),
                },
            );
            return;
        };
        self.fit.bar_ui(ui, state.for_picture(), |ui| {
            save_buttons(ui, Some(Table::Locus), actions);
        });
        let overlay = state.overlay();
        // The analysis drawn (it may come in a frame after the parameters).
        let refit = self.fit.refit((
            state.view_generation(),
            *analysis.key,
            overlay.map(|o| o.preset),
        ));
        let current = state.current_eigenvalues();
        let name = overlay_name(state);
        let loci = loci(state, &current, name.as_deref());
        let Some(loci) = loci else { return };
        legend_ui(ui, &loci.window_legend(), theme);
        let width = ui.available_width();
        let height = ui.available_height();
        ui.horizontal(|ui| {
            ui.allocate_ui(vec2(0.42 * width, height), |ui| {
                plot_ui(ui, &loci.plane(), refit, theme);
            });
            ui.vertical(|ui| {
                for imaginary in [false, true] {
                    ui.allocate_ui(vec2(ui.available_width(), 0.5 * height - 4.0), |ui| {
                        plot_ui(ui, &loci.versus_load(imaginary), refit, theme);
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
        ui.label(tr!(
            ui.words(),
            "locus-title",
            from = number_text(loads.first().copied().unwrap_or(0.0)),
            to = number_text(loads.last().copied().unwrap_or(0.0))
        ));
        let current = state.current_eigenvalues();
        let name = overlay_name(state);
        if let Some(loci) = loci(state, &current, name.as_deref()) {
            plot_ui(ui, &loci.plane(), refit, theme);
        }
    }
}

/// The overlay's name, if one is drawn.
fn overlay_name(state: &AppState) -> Option<String> {
    state.overlay().map(|o| o.preset.to_string())
}

/// The locus plots of `state`'s analysis, the overlay (named `overlay`)
/// behind it, the present marked; `None` without an analysis.
fn loci<'a>(state: &'a AppState, current: &'a [C64], overlay: Option<&'a str>) -> Option<Loci<'a>> {
    let analysis = state.analysis()?;
    let main = Layer {
        name: "",
        locus: &analysis.locus,
        transitions: &analysis.transitions,
        ranges: &analysis.ranges,
        at_transitions: &[],
    };
    let others = state
        .overlay()
        .zip(overlay)
        .map(|(o, name)| Layer {
            name,
            locus: &o.locus,
            transitions: &o.transitions,
            ranges: &[],
            at_transitions: &[],
        })
        .into_iter()
        .collect();
    Some(Loci {
        main,
        others,
        present: Some(Present {
            load: state.model().load_p(),
            eigenvalues: current,
            measured: state.measured(),
        }),
        words: state.words(),
    })
}
