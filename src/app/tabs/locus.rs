//! The root locus tab: the eigenvalues in the complex plane beside their
//! real and imaginary parts against the load, the current load marked, and
//! the overlay's critical loads when one is drawn.

use crate::app::speak::Speak as _;
use crate::tr;
use eframe::egui::{self, vec2};

use super::{TabSpec, TabView, save_buttons};
use crate::app::View;
use crate::app::action::{Actions, Table};
use crate::app::plot_draw::{legend_ui, plot_ui};
use crate::app::plot_frame::Fit;
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::number_text;
use crate::i18n::Language;
use crate::model::{Model, PresetId};
use crate::plot::locus::{Layer, Loci, Part, Present};
use crate::plot::spec::{Medium, Sheet};

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
    /// The sheet without the present, and what it was built for.
    sheet: Option<(SheetKey, Sheet)>,
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
                color(theme.palette.warning),
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
        let Some(sheet) = self.sheet(state) else {
            return;
        };
        legend_ui(ui, &sheet.legend, theme);
        let width = ui.available_width();
        let height = ui.available_height();
        let [plane, re, im] = &sheet.plots[..] else {
            return;
        };
        ui.horizontal(|ui| {
            ui.allocate_ui(vec2(0.42 * width, height), |ui| {
                plot_ui(ui, plane, refit, theme);
            });
            ui.vertical(|ui| {
                for plot in [re, im] {
                    ui.allocate_ui(vec2(ui.available_width(), 0.5 * height - 4.0), |ui| {
                        plot_ui(ui, plot, refit, theme);
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
        if let Some(sheet) = self.sheet(state)
            && let Some(plane) = sheet.plots.first()
        {
            plot_ui(ui, plane, refit, theme);
        }
    }

    /// The locus plots of `state`'s analysis with the overlay behind it and
    /// the present marked; `None` without an analysis. What depends on the
    /// analysis alone (up to 30,000 points for a long chain) is built once
    /// per analysis, overlay and language and kept; each frame adds the
    /// present to a copy.
    fn sheet(&mut self, state: &AppState) -> Option<Sheet> {
        let analysis = state.analysis()?;
        let overlay = state.overlay();
        let key = SheetKey {
            model: *analysis.key,
            overlay: overlay.map(|o| (o.preset, o.a())),
            language: state.language(),
        };
        if self.sheet.as_ref().is_none_or(|(k, _)| *k != key) {
            let name = overlay.map(|o| o.preset.to_string());
            let main = Layer {
                name: "",
                locus: &analysis.locus,
                transitions: &analysis.transitions,
                ranges: &analysis.ranges,
                at_transitions: &[],
            };
            let others = overlay
                .zip(name.as_deref())
                .map(|(o, name)| Layer {
                    name,
                    locus: &o.locus,
                    transitions: &o.transitions,
                    ranges: &[],
                    at_transitions: &[],
                })
                .into_iter()
                .collect();
            let loci = Loci {
                main,
                others,
                medium: Medium::Window,
                words: state.words(),
            };
            self.sheet = Some((key, loci.sheet(Part::All)));
        }
        let mut sheet = self.sheet.as_ref()?.1.clone();
        let current = state.current_eigenvalues();
        Present {
            load: state.model().load_p(),
            eigenvalues: &current,
            measured: state.measured(),
        }
        .mark(&mut sheet, state.words());
        Some(sheet)
    }
}

/// What the kept sheet was built for: the analysis (of the model at load
/// 0), the overlay (its preset and group `a`) and the language.
#[derive(Clone, Copy, Debug, PartialEq)]
struct SheetKey {
    model: Model,
    overlay: Option<(PresetId, f64)>,
    language: Language,
}
