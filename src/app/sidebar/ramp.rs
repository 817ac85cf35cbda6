//! The quasi-static ramp: where the load starts and ends and how fast it
//! moves, start, pause and resume, stop.

use crate::app::speak::Speak as _;
use crate::tr;
use eframe::egui;

use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::{load_text, number_text};
use crate::sim::Ramp;

/// The ramp the next start uses.
pub struct RampSection {
    from_p: f64,
    to_p: f64,
    rate_p_per_s: f64,
    /// The top of the load bar these values were made for.
    bar_max_p: f64,
}

impl RampSection {
    /// Simulated seconds the default ramp takes over the whole bar: slow
    /// enough to stay quasi-static.
    const DEFAULT_RAMP_SECS: f64 = 80.0;

    /// The whole load bar, `0` to `bar_max_p`, in [`Self::DEFAULT_RAMP_SECS`].
    fn over_bar(bar_max_p: f64) -> Self {
        Self {
            from_p: 0.0,
            to_p: bar_max_p,
            rate_p_per_s: bar_max_p / Self::DEFAULT_RAMP_SECS,
            bar_max_p,
        }
    }
}

impl Default for RampSection {
    fn default() -> Self {
        Self::over_bar(crate::model::LOAD_BAR_MAX_P)
    }
}

impl View for RampSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        // Another column's bar (a chain's is shorter): its whole range.
        let bar_max_p = state.load_max();
        if bar_max_p != self.bar_max_p {
            *self = Self::over_bar(bar_max_p);
        }
        let words = ui.words();
        egui::CollapsingHeader::new(tr!(words, "ramp")).show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.label(tr!(words, "ramp-from"));
                ui.add(load_field(&mut self.from_p, 0.01))
                    .accessible_name(tr!(words, "ramp-from.name"))
                    .on_hover_text(tr!(words, "ramp-from.tooltip"));
                ui.label(tr!(words, "ramp-to"));
                ui.add(load_field(&mut self.to_p, 0.01))
                    .accessible_name(tr!(words, "ramp-to.name"))
                    .on_hover_text(tr!(words, "ramp-to.tooltip"));
                ui.label(tr!(words, "ramp-rate"));
                ui.add(load_field(&mut self.rate_p_per_s, 0.001))
                    .accessible_name(tr!(words, "ramp-rate.name"))
                    .on_hover_text(tr!(words, "ramp-rate.tooltip"));
                ui.label("/s");
            });
            let ramp = Ramp::new(self.from_p, self.to_p, self.rate_p_per_s);
            ui.horizontal(|ui| {
                let start = ui
                    .add_enabled(ramp.is_ok(), egui::Button::new(tr!(words, "ramp-start")))
                    .on_hover_text(tr!(words, "ramp-start.tooltip"));
                if start.clicked()
                    && let Ok(ramp) = &ramp
                {
                    actions.push(Action::RampStart(*ramp));
                }
                if let Some(run) = state.ramp() {
                    let label = if run.paused {
                        tr!(words, "ramp-resume")
                    } else {
                        tr!(words, "ramp-pause")
                    };
                    if ui
                        .button(label)
                        .on_hover_text(tr!(words, "ramp-pause.tooltip"))
                        .clicked()
                    {
                        actions.push(Action::RampPauseResume);
                    }
                    if ui
                        .button(tr!(words, "ramp-stop"))
                        .on_hover_text(tr!(words, "ramp-stop.tooltip"))
                        .clicked()
                    {
                        actions.push(Action::RampStop);
                    }
                }
            });
            if let Err(why) = &ramp {
                ui.colored_label(
                    color(theme.palette.error),
                    crate::i18n::ramp_error(words, why),
                );
            }
            if let Some(run) = state.ramp() {
                let doing = if run.finished() {
                    tr!(words, "ramp-done")
                } else if run.paused {
                    tr!(words, "ramp-paused")
                } else {
                    tr!(words, "ramp-moving")
                };
                ui.label(tr!(
                    words,
                    "ramp-progress",
                    load = load_text(run.load()),
                    to = number_text(run.ramp.to_p),
                    rate = number_text(run.ramp.rate_p_per_s),
                    doing = doing
                ));
            }
        });
    }
}

/// A number field for a load or a rate (typed or dragged; not clamped: a
/// value the ramp cannot take is named under the fields).
fn load_field(value: &mut f64, speed: f64) -> egui::DragValue<'_> {
    egui::DragValue::new(value)
        .speed(speed)
        .custom_formatter(|v, _| number_text(v))
}
