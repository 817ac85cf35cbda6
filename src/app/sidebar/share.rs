//! Settings as text: copy them to share a setup, paste text to load one.

use eframe::egui;

use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::state::AppState;
use crate::app::theme::Theme;

/// The text box's contents.
#[derive(Default)]
pub struct ShareSection {
    text: String,
}

impl View for ShareSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, _theme: &Theme) {
        egui::CollapsingHeader::new("share settings").show(ui, |ui| {
            ui.horizontal(|ui| {
                if ui
                    .button("copy settings")
                    .on_hover_text(
                        "the model, load, engine and speed as text, to the clipboard and below",
                    )
                    .clicked()
                {
                    let text = state.settings().to_text();
                    ui.ctx().copy_text(text.clone());
                    self.text = text;
                }
                if ui
                    .button("paste settings")
                    .on_hover_text("paste the text below first")
                    .clicked()
                {
                    actions.push(Action::Paste(self.text.clone()));
                }
            });
            ui.add(
                egui::TextEdit::multiline(&mut self.text)
                    .desired_rows(3)
                    .hint_text("paste settings text here"),
            );
        });
    }
}
