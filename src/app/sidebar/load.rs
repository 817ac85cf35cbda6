//! The load typed, the critical loads in words, and a ramp's onsets (seen
//! and predicted); the slider is the wide load bar under the scene.

use eframe::egui::{self, RichText};

use super::number_field::{NumberFields, refusal_ui};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::state::{AppState, VISIBLE_FRACTION};
use crate::app::theme::Theme;
use crate::format::{load_text, number_text};
use crate::model::Key;

/// The load's number field.
#[derive(Default)]
pub struct LoadSection {
    field: NumberFields,
}

impl View for LoadSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.field.prune(ui, state);
        ui.horizontal(|ui| {
            // The wide bar under the scene is the slider; this field takes a
            // typed load, also beyond the bar's range (not clamped).
            self.field
                .show(ui, state, actions, theme, Key::Load)
                .on_hover_text(
                    "type a load (Enter applies, Escape restores); beyond the bar's end too",
                );
            ui.label("load p = P l/k");
        });
        refusal_ui(ui, state, theme, Key::Load);
        let p = state.model().load_p();
        if let Some(roller) = state.model().roller() {
            ui.label(format!(
                "roller: q = R l/k = p/μ = {:.3}   (μ = {})",
                p / roller.mu,
                roller.mu
            ));
        }
        if p > state.load_max() {
            ui.colored_label(
                theme.warning,
                format!(
                    "p = {p} is beyond the plotted range (0 to {}); the status below is at p",
                    number_text(state.load_max())
                ),
            );
        }
        if state.answer_hidden() {
            ui.weak("The critical loads are hidden until the lesson reveals them.");
            if let Some(run) = state.ramp() {
                ramp_onset_ui(ui, run.seen_at_p, None, theme);
            }
            return;
        }
        let Some(analysis) = state.analysis() else {
            return;
        };
        let onset = analysis.first_instability();
        let ramp = state.ramp();
        for t in &analysis.transitions {
            ui.label(RichText::new(t.to_string()).color(theme.state_color(t.to)));
        }
        if let Some(run) = ramp {
            ramp_onset_ui(ui, run.seen_at_p, onset, theme);
        }
        if let Some(warning) = &analysis.warning {
            ui.colored_label(
                theme.warning,
                "the stability is not resolved here (hover for why)",
            )
            .on_hover_text(warning);
        }
    }
}

/// The ramp's onsets in words: where the motion was seen against where the
/// theory puts it, and why the first lags.
fn ramp_onset_ui(ui: &mut egui::Ui, seen: Option<f64>, theory: Option<f64>, theme: &Theme) {
    let visible = format!(
        "the tip off by {:.0}% of the length",
        100.0 * VISIBLE_FRACTION
    );
    if let Some(theory) = theory {
        ui.label(
            RichText::new(format!(
                "theory (white mark): unstable from p = {}",
                load_text(theory)
            ))
            .color(theme.text),
        );
    }
    match seen {
        Some(seen) => {
            ui.label(
                RichText::new(format!(
                    "seen (mark): motion visible at p = {} ({visible})",
                    load_text(seen)
                ))
                .color(theme.measured),
            );
            if theory.is_some_and(|theory| seen > theory) {
                ui.label(
                    "It shows late: past the onset the motion needs time to grow to a visible size, and the ramp moves on meanwhile. A slower ramp shows it closer to the theory.",
                );
            }
        }
        None => {
            ui.label(format!(
                "watching for the motion to become visible ({visible})"
            ));
        }
    }
}
