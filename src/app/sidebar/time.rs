//! Time: play, step, kick and reset, the speed, and where the run is.

use eframe::egui;

use crate::app::View;
use crate::app::action::{Action, Actions, Command};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::sim::{SPEED_RANGE, Status};

/// The named speeds, as in classroom simulations: simulated seconds per
/// wall-clock second; Normal is real time.
pub const PACES: [(&str, f64, &str); 3] = [
    ("Slow", 0.25, "a quarter of real time"),
    ("Normal", 1.0, "real time: one simulated second per second"),
    ("Fast", 4.0, "four times real time"),
];

/// Time's buttons, in their row's order.
const TIME_COMMANDS: [Command; 5] = [
    Command::PlayPause,
    Command::Step,
    Command::Kick,
    Command::Reset,
    Command::ResetAll,
];

/// Time's controls. `lesson_foot`: the few a lesson on a projector keeps
/// in view at the sidebar's foot, on one row (the speeds are set by the
/// lesson's steps and stay above, and "reset all" ends the lesson).
pub struct TimeSection {
    pub lesson_foot: bool,
}

impl View for TimeSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        // At a lesson's foot, all but the last ("reset all" ends a lesson).
        let shown = if self.lesson_foot {
            TIME_COMMANDS.len() - 1
        } else {
            TIME_COMMANDS.len()
        };
        let commands = &TIME_COMMANDS[..shown];
        ui.horizontal_wrapped(|ui| {
            for command in commands {
                command.button(ui, state.running(), actions);
            }
        });
        if !self.lesson_foot {
            speed_ui(ui, state, actions);
        }
        let sim = state.simulation();
        let shown = if !state.running() && sim.status() == Status::Running {
            "paused".to_owned()
        } else {
            sim.status().to_string()
        };
        ui.label(format!("t = {:.2} s   ({shown})", sim.time_secs()));
        if let Some(achieved) = state.lagging() {
            ui.colored_label(
                theme.warning,
                format!(
                    "running at {}x: this computer cannot keep up at {}x",
                    number_text(achieved),
                    number_text(state.settings().speed)
                ),
            );
        }
    }
}

/// The named speeds and the speed factor.
pub fn speed_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    ui.horizontal(|ui| {
        for (name, speed, tip) in PACES {
            let chosen = state.settings().speed == speed;
            if ui
                .selectable_label(chosen, name)
                .on_hover_text(tip)
                .clicked()
            {
                actions.push(Action::Speed(speed));
            }
        }
    });
    let mut speed = state.settings().speed;
    let response = ui
        .add(
            egui::Slider::new(&mut speed, SPEED_RANGE)
                .logarithmic(true)
                .text("× speed"),
        )
        .on_hover_text("simulated seconds per second of wall-clock time");
    if response.changed() {
        actions.push(Action::Speed(speed));
    }
}
