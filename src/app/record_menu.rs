//! The record menu: how long to record, into which folder (typed, or
//! chosen in the desktop's dialog), the button, and the recording's
//! progress.

use super::speak::Speak as _;
use crate::tr;
use std::path::{Path, PathBuf};

use eframe::egui;

use super::action::{Action, Actions};
use super::file_dialog::{Closed, FileDialog};
use super::notice::Notice;
use super::recorder::Recorder;

/// What the next recording will be: its length and its folder (typed, or
/// chosen in the desktop's dialog).
pub struct RecordChoice {
    pub secs: f64,
    pub folder: String,
    pub dialog: FileDialog,
}

impl Default for RecordChoice {
    fn default() -> Self {
        Self {
            secs: 10.0,
            // The user's videos or pictures folder, not the program's
            // working folder.
            folder: crate::app::file_dialog::user_folder(&["Videos", "Pictures"])
                .display()
                .to_string(),
            dialog: FileDialog::default(),
        }
    }
}

impl RecordChoice {
    /// Takes the folder dialog's answer once it has closed: the folder
    /// chosen, or what to tell the user when none was.
    pub fn take_dialog_answer(&mut self) -> Option<Notice> {
        match self.dialog.answer()? {
            Closed::Chosen(folder) => {
                self.folder = folder.display().to_string();
                None
            }
            Closed::NoneChosen => Some(Notice::info(
                "no folder chosen (where no dialog opened, this desktop offers none: type the folder's path)",
            )),
        }
    }
}

/// The record controls (the contents of the record menu): seconds, folder,
/// the button, and the progress. The menu closes as the recording starts,
/// so that it is not in the pictures.
pub fn record_ui(
    ui: &mut egui::Ui,
    choice: &mut RecordChoice,
    recorder: &Recorder,
    actions: &mut Actions,
) {
    let words = ui.words();
    ui.horizontal(|ui| {
        ui.label(tr!(words, "record-next"));
        ui.add(
            egui::DragValue::new(&mut choice.secs)
                .range(1.0..=60.0)
                .speed(0.5),
        )
        .accessible_name(tr!(words, "record-secs.name"))
        .on_hover_text(tr!(words, "record-secs.tooltip"));
        ui.label(tr!(words, "record-secs"));
    });
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut choice.folder).desired_width(200.0))
            .accessible_name(tr!(words, "record-folder.name"))
            .on_hover_text(tr!(words, "record-folder.tooltip"));
        if choice.dialog.is_open() {
            ui.label(tr!(words, "record-choosing"));
        } else if ui
            .button(tr!(words, "record-choose"))
            .on_hover_text(tr!(words, "record-choose.tooltip"))
            .clicked()
        {
            choice.dialog.pick_folder(
                &tr!(words, "record-choose.title"),
                Path::new(choice.folder.trim()),
                ui.ctx(),
            );
        }
    });
    if recorder.is_capturing() {
        // Nothing here that the pictures would show: the window's
        // title counts down.
        return;
    }
    if let Some(progress) = recorder.progress_text(words) {
        ui.label(progress);
        return;
    }
    let folder = PathBuf::from(choice.folder.trim());
    let ready = folder.is_dir();
    if ui
        .add_enabled(ready, egui::Button::new(tr!(words, "record-start")))
        .on_hover_text(tr!(words, "record-start.tooltip"))
        .on_disabled_hover_text(tr!(words, "record-start.no-folder"))
        .clicked()
    {
        actions.push(Action::Record {
            folder,
            secs: choice.secs,
        });
        ui.close();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A folder chosen in the dialog becomes the recording's folder; a
    /// dialog closed with none chosen leaves the typed one and says so.
    #[test]
    fn the_folder_dialogs_answer_is_the_recordings_folder() {
        let mut choice = RecordChoice {
            dialog: FileDialog::answered(Some(PathBuf::from("/tmp/lecture"))),
            ..RecordChoice::default()
        };
        assert_eq!(choice.take_dialog_answer(), None);
        assert_eq!(choice.folder, "/tmp/lecture");
        choice.dialog = FileDialog::answered(None);
        let told = choice.take_dialog_answer().expect("a notice");
        assert!(told.text.contains("no folder chosen"), "{}", told.text);
        assert_eq!(choice.folder, "/tmp/lecture");
        assert_eq!(choice.take_dialog_answer(), None, "answered once");
    }
}
