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

#[cfg(test)]
pub use time::PACES;

use eframe::egui;

use super::View;
use super::action::{Action, Actions, Command};
use super::speak::Speak as _;
use super::state::AppState;
use super::theme::Theme;
use crate::i18n::{Language, Words};
use crate::model::PRESETS;
use crate::tr;

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
        let words = ui.words();
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
            egui::containers::menu::MenuButton::new(tr!(words, "menu-share"))
                .config(keep_open.clone())
                .ui(ui, |ui| self.share.ui(ui, state, actions))
                .0
                .on_hover_text(tr!(words, "menu-share.tooltip"));
            egui::containers::menu::MenuButton::new(tr!(words, "menu-record"))
                .config(keep_open)
                .ui(ui, |ui| record(ui, actions))
                .0
                .on_hover_text(tr!(words, "menu-record.tooltip"));
            egui::containers::menu::MenuButton::new(tr!(words, "menu-keys"))
                .ui(ui, Command::keys_help_ui)
                .0
                .on_hover_text(tr!(words, "menu-keys.tooltip"));
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
            egui::CollapsingHeader::new(tr!(ui.words(), "section-parameters"))
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
                .checkbox(&mut projector, tr!(ui.words(), "projector-toggle"))
                .on_hover_text(Command::Projector.tooltip(ui.words()))
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

/// The language menu: each language by its own name; the choice is
/// remembered with the window's layout.
fn language_menu_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let current = state.language();
    egui::containers::menu::MenuButton::new(current.endonym())
        .ui(ui, |ui| {
            for language in Language::CHOSEN_FROM {
                if ui
                    .selectable_label(language == current, language.endonym())
                    .clicked()
                {
                    actions.push(Action::Language(language));
                    ui.close();
                }
            }
        })
        .0
        .accessible_name(tr!(
            ui.words(),
            "menu-language.name",
            language = current.endonym()
        ))
        .on_hover_text(tr!(ui.words(), "menu-language"));
}

/// Another preset's locus behind the current one.
fn overlay_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let words = ui.words();
    let current = state.overlay_choice();
    let mut chosen = current;
    let none = tr!(words, "overlay.none");
    egui::ComboBox::from_label(tr!(words, "overlay"))
        .selected_text(chosen.map_or(none.clone(), |id| id.name().to_owned()))
        .show_ui(ui, |ui| {
            ui.selectable_value(&mut chosen, None, none);
            for p in &PRESETS {
                ui.selectable_value(&mut chosen, Some(p.id), p.id.name());
            }
        })
        .response
        .on_hover_text(tr!(words, "overlay.tooltip"));
    if chosen != current {
        actions.push(Action::Overlay(chosen));
    }
}

/// The status line at the foot of the window: the latest notice (with a
/// button to dismiss it) or the first launch's hint, always in this one
/// place, so that a message never moves a control; the language menu at
/// its right end. A picture (the command
/// line's, a recording's frames) shows no message: it is for the person at
/// the window, not for the class.
pub fn status_line_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
    let words = ui.words();
    ui.with_layout(egui::Layout::right_to_left(egui::Align::Center), |ui| {
        language_menu_ui(ui, state, actions);
        ui.with_layout(egui::Layout::left_to_right(egui::Align::Center), |ui| {
            message_ui(ui, state, actions, theme, words);
        });
    });
}

/// The latest notice, the first launch's hint or "ready".
fn message_ui(
    ui: &mut egui::Ui,
    state: &AppState,
    actions: &mut Actions,
    theme: &Theme,
    words: &'static Words,
) {
    let notice = state.notice().cloned().filter(|_| !state.for_picture());
    if let Some(notice) = notice {
        if ui
            .small_button(tr!(words, "status-dismiss"))
            .on_hover_text(tr!(words, "status-dismiss.tooltip"))
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
            .on_hover_text(tr!(words, "status-latest"));
        // A live region: a screen reader says each new message.
        ui.ctx().accesskit_node_builder(line.id, |node| {
            node.set_live(egui::accesskit::Live::Polite);
        });
    } else if let Some(hint) = state.hint() {
        if ui
            .small_button(tr!(words, "status-got-it"))
            .on_hover_text(tr!(words, "status-got-it.tooltip"))
            .clicked()
        {
            actions.push(Action::DismissHint);
        }
        ui.label(tr!(words, hint));
    } else {
        ui.weak(tr!(words, "status-ready"));
    }
}
