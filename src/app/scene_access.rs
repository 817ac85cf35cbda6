//! The scene as a control: a name for a screen reader with its words
//! (what the column does), and the keys that turn the column while it has
//! the focus (the keyboard's drag).

use super::speak::Speak as _;
use crate::tr;
use eframe::egui;

use super::action::{Action, Actions};
use super::arrows::{keep_arrows, net_presses};
use super::scene_words;
use super::state::AppState;
use super::theme::Theme;

/// The angle the scene's keys turn the column by, per press, in radians
/// (with shift: [`TURN_COARSE_RAD`]).
const TURN_RAD: f64 = 0.02;
const TURN_COARSE_RAD: f64 = 0.1;

/// The scene for the keyboard and a screen reader: its name and what the
/// column does in words; focused (Tab), left and right turn every rod by
/// [`TURN_RAD`] (the keyboard's drag: counter-clockwise and clockwise),
/// and a ring shows it has the keys.
pub fn keys_ui(ui: &egui::Ui, drag: &egui::Response, actions: &mut Actions, theme: &Theme) {
    let name = tr!(ui.words(), "scene-name");
    drag.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
    if !drag.has_focus() {
        return;
    }
    keep_arrows(ui.ctx(), drag.id, false);
    let turn_rad = ui.input(|input| {
        let step = if input.modifiers.shift {
            TURN_COARSE_RAD
        } else {
            TURN_RAD
        };
        step * net_presses(input, egui::Key::ArrowLeft, egui::Key::ArrowRight)
    });
    if turn_rad != 0.0 {
        actions.push(Action::KickBy {
            angle_rad: turn_rad,
        });
    }
    ui.painter().rect_stroke(
        drag.rect.shrink(1.5 * theme.stroke_scale),
        4.0,
        theme.focus_stroke(),
        egui::StrokeKind::Inside,
    );
}

/// The scene's words for a screen reader, at most twice a second.
pub fn describe_ui(ui: &egui::Ui, id: egui::Id, state: &AppState) {
    let words = scene_words::throttled(ui.ctx(), id, || scene_words::scene_text(state));
    ui.ctx()
        .accesskit_node_builder(id, |node| node.set_description(words));
}
