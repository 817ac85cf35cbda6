//! The controls on the left: a lesson, the model, the load,
//! the load ramp, the parameters, time, the status card, the overlay and the settings to
//! share, each a section in a file of its own.

mod lesson;
mod load;
mod model;
mod number_field;
mod parameters;
mod ramp;
mod share;
mod status;
mod time;

use eframe::egui;

use super::View;
use super::action::{Action, Actions, Command};
use super::state::AppState;
use super::theme::Theme;
use crate::model::{PRESETS, PresetId};

/// The sidebar and the sections that keep something of their own.
#[derive(Default)]
pub struct Sidebar {
    lesson: lesson::LessonSection,
    load: load::LoadSection,
    parameters: parameters::ParametersSection,
    ramp: ramp::RampSection,
    share: share::ShareSection,
}

impl Sidebar {
    /// Takes the clipboard's text when a paste from it is on its way: before
    /// any widget of the frame reads the input.
    pub fn take_clipboard(&mut self, ctx: &egui::Context, actions: &mut Actions) {
        self.share.take_clipboard(ctx, actions);
    }

    /// The heading, with the tools that a small window would otherwise
    /// leave below the fold as menus on its right: share settings, record
    /// (drawn by `record`) and the keys.
    pub fn header_ui(
        &mut self,
        ui: &mut egui::Ui,
        state: &AppState,
        actions: &mut Actions,
        record: impl FnOnce(&mut egui::Ui, &mut Actions),
    ) {
        let keep_open = egui::containers::menu::MenuConfig::new()
            .close_behavior(egui::PopupCloseBehavior::CloseOnClickOutside);
        // The menus beside the heading, on a row of their own when the
        // text is large (a projector).
        ui.horizontal_wrapped(|ui| {
            ui.heading("zieglerlab");
            if state.settings().projector {
                ui.end_row();
            } else {
                ui.add_space(8.0);
            }
            egui::containers::menu::MenuButton::new("share")
                .config(keep_open.clone())
                .ui(ui, |ui| self.share.ui(ui, state, actions))
                .0
                .on_hover_text("the settings as text: copy them, or paste some");
            egui::containers::menu::MenuButton::new("record")
                .config(keep_open)
                .ui(ui, |ui| record(ui, actions))
                .0
                .on_hover_text("record the window to a GIF");
            egui::containers::menu::MenuButton::new("keys")
                .ui(ui, Command::keys_help_ui)
                .0
                .on_hover_text("the keyboard's commands");
        });
    }
}

impl View for Sidebar {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.lesson.ui(ui, state, actions, theme);
        ui.separator();
        model::ModelSection.ui(ui, state, actions, theme);
        ui.separator();
        if state.settings().projector {
            // In front of a class: time and the status card at the foot
            // (`foot_ui`), always in view; here the load typed, and the
            // parameters folded, so that all fits a 1024x768 projector.
            if state.lesson().is_some() {
                time::speed_ui(ui, state, actions);
                ui.separator();
            }
            self.load.ui(ui, state, actions, theme);
            self.ramp.ui(ui, state, actions, theme);
            egui::CollapsingHeader::new("parameters")
                .show(ui, |ui| self.parameters.ui(ui, state, actions, theme));
        } else {
            self.load.ui(ui, state, actions, theme);
            self.ramp.ui(ui, state, actions, theme);
            ui.separator();
            self.parameters.ui(ui, state, actions, theme);
            ui.separator();
            time::TimeSection { lesson_foot: false }.ui(ui, state, actions, theme);
            ui.separator();
            status::StatusSection { compact: false }.ui(ui, state, actions, theme);
        }
        ui.separator();
        // Wrapped: on a projector's sidebar the two do not fit one row.
        ui.horizontal_wrapped(|ui| {
            overlay_ui(ui, state, actions);
            let mut projector = state.settings().projector;
            if ui
                .checkbox(&mut projector, "projector (P)")
                .on_hover_text(Command::Projector.tooltip())
                .changed()
            {
                actions.push(Action::Projector(projector));
            }
        });
    }
}

/// On a projector, the sidebar's foot, kept in view under what scrolls:
/// a lesson's buttons, time's controls and the status card (both cut to
/// their essentials during a lesson, whose step text fills the rest).
pub fn foot_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
    let lesson = state.lesson().is_some();
    ui.separator();
    if lesson {
        lesson::step_buttons_ui(ui, state, actions);
        ui.separator();
    }
    time::TimeSection {
        lesson_foot: lesson,
    }
    .ui(ui, state, actions, theme);
    ui.separator();
    status::StatusSection { compact: lesson }.ui(ui, state, actions, theme);
}

/// Another preset's locus behind the current one.
fn overlay_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let current = state.overlay_choice();
    let mut chosen = current;
    egui::ComboBox::from_label("overlay")
        .selected_text(chosen.map_or("none", PresetId::name))
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut chosen, None, "none");
            for p in &PRESETS {
                ui.selectable_value(&mut chosen, Some(p.id), p.id.name());
            }
        })
        .response
        .on_hover_text("another model's locus in grey, at the same a (as Fig. 8 sets the ideal column beside the roller)");
    if chosen != current {
        actions.push(Action::Overlay(chosen));
    }
}

/// The status line at the foot of the window: the latest notice (with a
/// button to dismiss it) or the first launch's hint, always in this one
/// place, so that a message never moves a control. A picture (the command
/// line's, a recording's frames) shows no message: it is for the person at
/// the window, not for the class.
pub fn status_line_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
    ui.horizontal(|ui| {
        let notice = state.notice().cloned().filter(|_| !state.for_picture());
        if let Some(notice) = notice {
            if ui
                .small_button("dismiss")
                .on_hover_text("clear this message")
                .clicked()
            {
                actions.push(Action::DismissNotice);
            }
            let line = ui
                .add(
                    egui::Label::new(
                        egui::RichText::new(notice.text).color(theme.notice_color(notice.level)),
                    )
                    .truncate(),
                )
                .on_hover_text("the latest message (the whole text)");
            // A live region: a screen reader says each new message.
            ui.ctx().accesskit_node_builder(line.id, |node| {
                node.set_live(egui::accesskit::Live::Polite);
            });
        } else if let Some(hint) = state.hint() {
            if ui
                .small_button("got it")
                .on_hover_text("hide the hint")
                .clicked()
            {
                actions.push(Action::DismissHint);
            }
            ui.label(hint);
        } else {
            ui.weak("ready");
        }
    });
}
