//! The status card: the stability at the current load in words and numbers,
//! and the eigenvalue measured from the run.

use eframe::egui::{self, RichText};

use crate::analysis::{State, classify};
use crate::app::View;
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::{rate_text, secs_text};

pub struct StatusSection;

impl View for StatusSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        let (Some(analysis), Some(spectrum)) = (state.analysis(), state.current_spectrum()) else {
            return;
        };
        let s = classify(&spectrum.eigenvalues, spectrum.scale_per_s);
        let growth = s.growth_rate_per_s();
        let frequency = s.frequency_rad_per_s();
        let weak = s.state == State::Flutter && growth < 0.01 * frequency;
        let title = match (s.state, weak) {
            (State::Flutter, true) => "weak flutter".to_owned(),
            (stability, _) => stability.name().to_owned(),
        };
        ui.label(
            RichText::new(title)
                .heading()
                .color(theme.state_color(s.state)),
        );
        if growth.abs() <= s.tolerance_per_s {
            // Rounding's share of the real part: say zero, and to what accuracy.
            ui.label(format!(
                "growth rate  0 (to within {:.0e} 1/s)",
                s.tolerance_per_s
            ));
        } else {
            ui.label(format!("growth rate  {} 1/s", rate_text(growth)));
        }
        if analysis.warning.is_some() {
            ui.colored_label(
                theme.warning,
                "not resolved at these parameters: see the warning under the load",
            );
        }
        match s.e_folding_secs() {
            Some(secs) => ui.label(format!("e-folding time  {} s", secs_text(secs))),
            None if growth < 0.0 => ui.label(format!("decay time  {} s", secs_text(-1.0 / growth))),
            None => ui.label("neutral: no growth, no decay"),
        };
        if frequency > s.tolerance_per_s {
            let period = std::f64::consts::TAU / frequency;
            ui.label(format!(
                "frequency  {frequency:.4} rad/s  (period {} s)",
                secs_text(period)
            ));
        } else {
            ui.label("non-oscillatory: the dominant eigenvalue is real");
        }
        match state.measured().and_then(|m| m.first()) {
            Some(z) => ui.label(format!(
                "measured from the run  {:+.5} ± {:.4}i 1/s",
                z.re,
                z.im.abs()
            )),
            None => ui.label(
                RichText::new("measured: after 20 s of small-amplitude motion (|φ| < 0.05 rad)")
                    .small(),
            ),
        };
        if weak {
            ui.label(
                RichText::new(format!(
                    "grows by {:.2}% per period: watch for minutes, not seconds",
                    100.0 * (growth * std::f64::consts::TAU / frequency).exp_m1()
                ))
                .small(),
            );
        }
    }
}
