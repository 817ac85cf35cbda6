//! The quasi-static ramp: where the load starts and ends and how fast it
//! moves, start, pause and resume, stop.

use eframe::egui;

use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::state::AppState;
use crate::app::theme::Theme;
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
        egui::CollapsingHeader::new("ramp the load").show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.label("from");
                ui.add(load_field(&mut self.from_p, 0.01))
                    .accessible_name("ramp from")
                    .on_hover_text("the load the ramp starts at");
                ui.label("to");
                ui.add(load_field(&mut self.to_p, 0.01))
                    .accessible_name("ramp to")
                    .on_hover_text("the load the ramp stops at");
                ui.label("at");
                ui.add(load_field(&mut self.rate_p_per_s, 0.001))
                    .accessible_name("ramp rate")
                    .on_hover_text("how fast the load moves, per simulated second");
                ui.label("/s");
            });
            let ramp = Ramp::new(self.from_p, self.to_p, self.rate_p_per_s);
            ui.horizontal(|ui| {
                let start = ui
                    .add_enabled(ramp.is_ok(), egui::Button::new("start ramp"))
                    .on_hover_text("the load goes to 'from' and moves to 'to' at the rate, as the run goes on (setting the load by hand ends it)");
                if start.clicked()
                    && let Ok(ramp) = &ramp
                {
                    actions.push(Action::RampStart(*ramp));
                }
                if let Some(run) = state.ramp() {
                    let label = if run.paused { "resume" } else { "pause ramp" };
                    if ui
                        .button(label)
                        .on_hover_text("hold the load where it is; the run goes on")
                        .clicked()
                    {
                        actions.push(Action::RampPauseResume);
                    }
                    if ui.button("stop").on_hover_text("end the ramp").clicked() {
                        actions.push(Action::RampStop);
                    }
                }
            });
            if let Err(why) = &ramp {
                ui.colored_label(theme.error, why.to_string());
            }
            if let Some(run) = state.ramp() {
                let doing = if run.finished() {
                    "done"
                } else if run.paused {
                    "paused"
                } else {
                    "moving"
                };
                ui.label(format!(
                    "p = {} toward {} at {}/s ({doing})",
                    load_text(run.load()),
                    number_text(run.ramp.to_p),
                    number_text(run.ramp.rate_p_per_s)
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
