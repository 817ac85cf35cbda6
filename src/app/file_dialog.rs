//! The desktop's file and folder dialogs, opened off the UI thread (the
//! window keeps drawing while one is open), the answer handed to the frame
//! that asks.

use std::path::{Path, PathBuf};
use std::sync::mpsc;

use eframe::egui;

/// How a dialog closed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Closed {
    /// The folder or file chosen.
    Chosen(PathBuf),
    /// Cancelled, or no dialog could open on this desktop.
    NoneChosen,
}

/// What a save dialog closed with no file chosen says.
pub const NOT_SAVED: &str =
    "not saved: no file chosen (where no dialog opened, this desktop offers none)";

/// A dialog that may be open.
#[derive(Default)]
pub struct FileDialog {
    answer: Option<mpsc::Receiver<Option<PathBuf>>>,
}

impl FileDialog {
    /// Opens the desktop's folder dialog at `start` (unless a dialog is
    /// open); the window is woken when it closes.
    pub fn pick_folder(&mut self, title: &str, start: &Path, ctx: &egui::Context) {
        let dialog = rfd::FileDialog::new().set_title(title).set_directory(start);
        self.open(ctx, move || dialog.pick_folder());
    }

    /// Opens the desktop's dialog to save a file, proposing `name` (unless a
    /// dialog is open); the window is woken when it closes.
    pub fn save_file(&mut self, title: &str, name: &str, ctx: &egui::Context) {
        let dialog = rfd::FileDialog::new().set_title(title).set_file_name(name);
        self.open(ctx, move || dialog.save_file());
    }

    fn open(
        &mut self,
        ctx: &egui::Context,
        ask: impl FnOnce() -> Option<PathBuf> + Send + 'static,
    ) {
        if self.is_open() {
            return;
        }
        let (send, answer) = mpsc::channel();
        let ctx = ctx.clone();
        let spawned = std::thread::Builder::new()
            .name("file dialog".to_owned())
            .spawn(move || {
                // A window closed meanwhile has dropped the receiver.
                let _ = send.send(ask());
                ctx.request_repaint();
            });
        if spawned.is_ok() {
            self.answer = Some(answer);
        }
    }

    /// Whether a dialog is open.
    #[must_use]
    pub fn is_open(&self) -> bool {
        self.answer.is_some()
    }

    /// How the dialog closed, once it has (`None` while it is open or when
    /// none was opened).
    pub fn answer(&mut self) -> Option<Closed> {
        let receiver = self.answer.as_ref()?;
        let closed = match receiver.try_recv() {
            Ok(Some(folder)) => Closed::Chosen(folder),
            Ok(None) | Err(mpsc::TryRecvError::Disconnected) => Closed::NoneChosen,
            Err(mpsc::TryRecvError::Empty) => return None,
        };
        self.answer = None;
        Some(closed)
    }

    /// A dialog that answers `chosen` at once (for tests of what the window
    /// does with an answer).
    #[cfg(test)]
    #[must_use]
    pub(crate) fn answered(chosen: Option<PathBuf>) -> Self {
        let (send, answer) = mpsc::channel();
        let _ = send.send(chosen);
        Self {
            answer: Some(answer),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The answer is handed over once, and a dialog whose thread ended
    /// without one (no desktop dialog at all) answers "none chosen".
    #[test]
    fn the_answer_is_handed_over_once() {
        let mut dialog = FileDialog::answered(Some(PathBuf::from("/tmp")));
        assert!(dialog.is_open());
        assert_eq!(dialog.answer(), Some(Closed::Chosen(PathBuf::from("/tmp"))));
        assert!(!dialog.is_open());
        assert_eq!(dialog.answer(), None);
        let (send, answer) = mpsc::channel::<Option<PathBuf>>();
        drop(send);
        let mut gone = FileDialog {
            answer: Some(answer),
        };
        assert_eq!(gone.answer(), Some(Closed::NoneChosen));
    }
}
