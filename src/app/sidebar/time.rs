//! Time: play, step, kick and reset, the speed, and where the run is.

use eframe::egui;

use crate::app::View;
use crate::app::action::{Action, Actions, Command};
use crate::app::speak::Speak as _;
use crate::app::speak::status_words;
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::number_text;
use crate::sim::{SPEED_RANGE, Status};
use crate::tr;

/// The named speeds, as in classroom simulations: simulated seconds per
/// wall-clock second; Normal is real time. Each is named by its message
/// (with `.tooltip`).
pub const PACES: [(&str, f64); 3] = [
    ("pace-slow", 0.25),
    ("pace-normal", 1.0),
    ("pace-fast", 4.0),
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
        let words = ui.words();
        let sim = state.simulation();
        let shown = if !state.running() && sim.status() == Status::Running {
            tr!(words, "run-paused")
        } else {
            status_words(words, sim.status())
        };
        ui.label(tr!(
            words,
            "run-time",
            secs = format!("{:.2}", sim.time_secs()),
            status = shown
        ));
        if let Some(achieved) = state.lagging() {
            ui.colored_label(
                color(theme.palette.warning),
                tr!(
                    words,
                    "run-lagging",
                    achieved = number_text(achieved),
                    asked = number_text(state.settings().speed)
                ),
            );
        }
    }
}

/// The named speeds and the speed factor.
pub fn speed_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let words = ui.words();
    ui.horizontal(|ui| {
        for (id, speed) in PACES {
            let chosen = state.settings().speed == speed;
            if ui
                .selectable_label(chosen, words.get(id))
                .on_hover_text(words.get(&format!("{id}.tooltip")))
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
                .text(tr!(words, "speed-factor")),
        )
        .on_hover_text(tr!(words, "speed-factor.tooltip"));
    if response.changed() {
        actions.push(Action::Speed(speed));
    }
}
