//! The load slider, the stability ranges drawn under it, the critical
//! loads in words, and a ramp's onsets (seen and predicted).

use eframe::egui::{self, RichText, Sense, Stroke, pos2, vec2};

use super::number_field::{NumberFields, refusal_ui};
use crate::app::View;
use crate::app::state::{AppState, LOAD_MAX_P, VISIBLE_FRACTION};
use crate::app::theme::Theme;
use crate::format::load_text;
use crate::model::Key;

/// The load's number field (the slider beside it applies live).
#[derive(Default)]
pub struct LoadSection {
    field: NumberFields,
}

impl View for LoadSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        self.field.prune(ui, state);
        let mut p = state.model().load_p();
        ui.label("load p = P l/k");
        ui.horizontal(|ui| {
            // The slider applies while dragged; the field beside it takes a
            // typed load, also beyond the slider's range (not clamped).
            let slider = ui
                .add(
                    egui::Slider::new(&mut p, 0.0..=LOAD_MAX_P)
                        .clamping(egui::SliderClamping::Never)
                        .show_value(false),
                )
                .accessible_name("load slider");
            if slider.changed() {
                state.enter_parameter(Key::Load, p);
            }
            self.field.show(ui, state, theme, Key::Load);
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
        if p > LOAD_MAX_P {
            ui.colored_label(
                theme.warning,
                format!("p = {p} is beyond the plotted range (0 to {LOAD_MAX_P}); the status below is at p"),
            );
        }
        let Some(analysis) = state.analysis() else {
            return;
        };
        let (rect, _) = ui.allocate_exact_size(vec2(ui.available_width(), 14.0), Sense::hover());
        let painter = ui.painter_at(rect);
        #[expect(clippy::cast_possible_truncation, reason = "pixels")]
        let x_of = |load: f64| rect.left() + rect.width() * (load / LOAD_MAX_P) as f32;
        for &(start, end, range_state) in &analysis.ranges {
            let r = egui::Rect::from_min_max(
                pos2(x_of(start), rect.top()),
                pos2(x_of(end), rect.bottom()),
            );
            painter.rect_filled(r, 0.0, theme.state_color(range_state));
        }
        let x = x_of(p);
        painter.line_segment(
            [pos2(x, rect.top() - 2.0), pos2(x, rect.bottom() + 2.0)],
            Stroke::new(3.0, theme.now),
        );
        let onset = analysis.first_instability();
        let ramp = state.ramp();
        // With a ramp: where the theory puts the onset and where the
        // motion was seen, marked on the bar and said below it.
        let marks = [
            (onset.filter(|_| ramp.is_some()), theme.text),
            (ramp.and_then(|run| run.seen_at_p), theme.measured),
        ];
        for (load, color) in marks {
            if let Some(load) = load.filter(|&l| l <= LOAD_MAX_P) {
                let x = x_of(load);
                painter.line_segment(
                    [pos2(x, rect.top()), pos2(x, rect.bottom())],
                    Stroke::new(2.0, color),
                );
            }
        }
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
