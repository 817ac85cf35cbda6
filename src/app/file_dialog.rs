//! The desktop's file and folder dialogs, opened off the UI thread (the
//! window keeps drawing while one is open), the answer handed to the frame
//! that asks; where a desktop has no save dialog, a path typed in the
//! window instead (the folder and a suggested name filled in).

use super::speak::Speak as _;
use crate::tr;
use std::path::{Path, PathBuf};

use eframe::egui;

use super::jobs::{Jobs, Reply};

/// How a dialog closed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Closed {
    /// The folder or file chosen.
    Chosen(PathBuf),
    /// Cancelled, or no dialog could open on this desktop.
    NoneChosen,
}

/// What a save dialog closed with no file chosen says (its message).
pub const NOT_SAVED: &str = "notice-not-saved";

/// A dialog that closes within this time without a file never opened: no
/// person cancels a dialog so fast (a desktop with neither a portal nor
/// zenity answers at once).
const NO_DIALOG_SECS: f64 = 0.5;

/// Where the window's [`PathsAsked`] is kept in egui's context.
fn paths_asked_id() -> egui::Id {
    egui::Id::unique("zieglerlab-paths-asked")
}

/// Where the window asks for a path to save to.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PathsAsked {
    /// Of the desktop's dialog; typed in the window where none opens.
    #[default]
    OfTheDesktop,
    /// Always typed in the window.
    Typed,
}

/// From this frame on, paths are asked as `asked` says.
pub fn install(ctx: &egui::Context, asked: PathsAsked) {
    ctx.data_mut(|d| d.insert_temp(paths_asked_id(), asked));
}

/// A dialog that may be open.
#[derive(Default)]
pub struct FileDialog {
    /// The dialog, on a job of its own: its answer, and whether it came
    /// too fast to be a person's.
    answer: Option<Jobs<(), (Option<PathBuf>, bool)>>,
    /// The file a save proposes (its folder and name), for a typed path.
    proposed: Option<PathBuf>,
    /// The path being typed where no save dialog opened.
    typing: Option<String>,
    /// The typed path's answer, once given.
    typed: Option<Closed>,
    /// An existing file the typed path names, asked whether to replace it.
    replacing: Option<PathBuf>,
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
        if self.is_open() {
            return;
        }
        let folder = user_folder(&["Pictures"]);
        self.proposed = Some(folder.join(name));
        let dialog = rfd::FileDialog::new()
            .set_title(title)
            .set_directory(&folder)
            .set_file_name(name);
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
        let typed = ctx.data(|d| d.get_temp(paths_asked_id())) == Some(PathsAsked::Typed);
        let ctx = ctx.clone();
        let mut dialog = Jobs::new("file dialog");
        let started = dialog.request((), move |(), _, send| {
            if typed {
                // As a desktop without a dialog answers: at once, nothing.
                send((None, true));
            } else {
                let asked = std::time::Instant::now();
                let chosen = ask();
                send((chosen, asked.elapsed().as_secs_f64() < NO_DIALOG_SECS));
            }
            ctx.request_repaint();
        });
        // No thread: no dialog, as where the desktop has none.
        if started.is_ok() {
            self.answer = Some(dialog);
        }
    }

    /// Whether a dialog is open (or a path is being typed in its place).
    #[must_use]
    pub fn is_open(&self) -> bool {
        self.answer.is_some() || self.typing.is_some()
    }

    /// How the dialog closed, once it has (`None` while it is open or when
    /// none was opened). A save whose dialog never opened is not closed:
    /// a path is typed in its place ([`Self::typed_path_ui`]).
    pub fn answer(&mut self) -> Option<Closed> {
        if let Some(typed) = self.typed.take() {
            return Some(typed);
        }
        let closed = match self.answer.as_ref()?.reply() {
            Reply::Pending => return None,
            Reply::Sent((Some(chosen), _)) => Closed::Chosen(chosen),
            Reply::Sent((None, true)) if self.proposed.is_some() => {
                self.answer = None;
                self.typing = self.proposed.take().map(|p| p.display().to_string());
                return None;
            }
            Reply::Sent((None, _)) | Reply::Ended => Closed::NoneChosen,
        };
        self.answer = None;
        self.proposed = None;
        Some(closed)
    }

    /// Where a save dialog did not open: a small window to type the file's
    /// path in, the folder and the suggested name filled in. Draw it every
    /// frame; it shows only while a path is being typed.
    pub fn typed_path_ui(&mut self, ctx: &egui::Context, what: &str) {
        let Some(path) = self.typing.as_mut() else {
            return;
        };
        let mut answer = None;
        let words = ctx.words();
        egui::Window::new(tr!(words, "save-as"))
            .id(egui::Id::unique("save as"))
            .collapsible(false)
            .resizable(false)
            .anchor(egui::Align2::CENTER_CENTER, egui::Vec2::ZERO)
            .show(ctx, |ui| {
                ui.label(tr!(words, "save-as-typed", what = what));
                let edit = ui
                    .add(egui::TextEdit::singleline(path).desired_width(360.0))
                    .accessible_name(tr!(words, "save-as.path"));
                let entered = edit.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
                let file = PathBuf::from(path.trim());
                let why_not = refusal(&file, path, words);
                if let Some(why) = &why_not {
                    ui.weak(why.as_str());
                }
                // An existing file: asked once before it is replaced, as the
                // desktop's dialog and `record` ask.
                let exists = std::fs::metadata(&file).is_ok_and(|m| m.is_file());
                let asked = self.replacing.as_ref() == Some(&file);
                if asked {
                    ui.label(tr!(
                        words,
                        "save-as-exists",
                        path = file.display().to_string()
                    ));
                } else {
                    self.replacing = None;
                }
                ui.horizontal(|ui| {
                    let label = if asked {
                        tr!(words, "save-as-replace")
                    } else {
                        tr!(words, "save-as-save")
                    };
                    let save = ui.add_enabled(why_not.is_none(), egui::Button::new(label));
                    if save.clicked() || (entered && why_not.is_none()) {
                        if exists && !asked {
                            self.replacing = Some(file.clone());
                        } else {
                            answer = Some(Closed::Chosen(file.clone()));
                        }
                    }
                    if ui.button(tr!(words, "save-as-cancel")).clicked() {
                        answer = Some(Closed::NoneChosen);
                    }
                });
                // Enter on a path that is refused, or asked about, keeps
                // the keys in the field: typing on must not reach the
                // window's shortcuts ("r" would reset the run to be saved).
                if entered && answer.is_none() {
                    edit.request_focus();
                }
            });
        if let Some(answer) = answer {
            self.typing = None;
            self.replacing = None;
            self.typed = Some(answer);
            ctx.request_repaint();
        }
    }

    /// A dialog that answers `chosen` at once (for tests of what the window
    /// does with an answer).
    #[cfg(test)]
    #[must_use]
    pub(crate) fn answered(chosen: Option<PathBuf>) -> Self {
        let mut dialog = Jobs::new("file dialog");
        dialog
            .request((), move |(), _, send| send((chosen, false)))
            .expect("a thread");
        dialog.wait();
        Self {
            answer: Some(dialog),
            ..Self::default()
        }
    }
}

/// Why the typed `file` (typed as `text`) cannot be saved to, if it cannot:
/// no name, no folder, a folder, a pipe or a device (a FIFO froze the
/// window for good), or a file the user may not write.
fn refusal(file: &Path, text: &str, words: &'static crate::i18n::Words) -> Option<String> {
    if text.trim().is_empty() || file.file_name().is_none() {
        return Some(tr!(words, "save-as-no-path"));
    }
    if !crate::files::folder_of(file).is_dir() {
        return Some(tr!(words, "save-as-no-folder"));
    }
    match std::fs::metadata(file) {
        Ok(m) if m.is_dir() => Some(tr!(words, "save-as-folder")),
        Ok(m) if !m.is_file() => Some(tr!(words, "save-as-pipe")),
        _ => crate::files::protected_by(file)
            .map(|e| tr!(words, "save-as-protected", why = e.to_string())),
    }
}

/// The folder a save proposes: the first of the user's `preferred`
/// folders (`~/Videos`, `~/Pictures`) there is, else the home folder, else
/// the working folder.
#[must_use]
pub fn user_folder(preferred: &[&str]) -> PathBuf {
    let home = std::env::home_dir().filter(|h| h.is_dir());
    home.as_ref()
        .and_then(|h| {
            preferred
                .iter()
                .map(|name| h.join(name))
                .find(|p| p.is_dir())
        })
        .or(home)
        .unwrap_or_else(|| PathBuf::from("."))
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
        // A dialog's job that ended with nothing sent (it panicked).
        let mut ended = Jobs::new("file dialog");
        ended.request((), |(), _, _| {}).unwrap();
        ended.wait();
        let mut gone = FileDialog {
            answer: Some(ended),
            ..FileDialog::default()
        };
        assert_eq!(gone.answer(), Some(Closed::NoneChosen));
    }
}
