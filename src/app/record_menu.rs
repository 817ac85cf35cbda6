//! The record menu: how long to record, into which folder (typed, or
//! chosen in the desktop's dialog), the button, and the recording's
//! progress.

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
    ui.horizontal(|ui| {
        ui.label("the next");
        ui.add(
            egui::DragValue::new(&mut choice.secs)
                .range(1.0..=60.0)
                .speed(0.5),
        )
        .accessible_name("record seconds")
        .on_hover_text("seconds of the window to record (1 to 60)");
        ui.label("s into");
    });
    ui.horizontal(|ui| {
        ui.add(egui::TextEdit::singleline(&mut choice.folder).desired_width(200.0))
            .accessible_name("record folder")
            .on_hover_text("the folder the GIF goes in");
        if choice.dialog.is_open() {
            ui.label("choosing...");
        } else if ui
            .button("choose...")
            .on_hover_text("choose the folder in the desktop's dialog")
            .clicked()
        {
            choice.dialog.pick_folder(
                "zieglerlab: the folder for recordings",
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
    if let Some(progress) = recorder.progress_text() {
        ui.label(progress);
        return;
    }
    let folder = PathBuf::from(choice.folder.trim());
    let ready = folder.is_dir();
    if ui
        .add_enabled(ready, egui::Button::new("record"))
        .on_hover_text("record what the window shows, 10 frames a second, to a GIF")
        .on_disabled_hover_text("the folder does not exist")
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
