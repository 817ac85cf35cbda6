//! Tables saved from the window: the run's recent past and the root locus,
//! in the command line's columns, to a file chosen in the desktop's dialog
//! and written whole or not at all, off the window's thread (a slow disk or
//! a stalled mount never freezes the window).

use super::speak::Speak as _;
use crate::tr;
use std::path::{Path, PathBuf};

use eframe::egui;

use super::action::Table;
use super::file_dialog::{Closed, FileDialog, NOT_SAVED};
use super::jobs::Jobs;
use super::notice::Notice;
use super::state::AppState;
use crate::export::{history_csv, locus_csv};

/// A table asked for, the dialog that chooses its file, and its writing.
pub struct Exports {
    dialog: FileDialog,
    /// Asked for, the dialog not opened yet (it needs the frame's context).
    asked: Option<Table>,
    /// The table the open dialog is for.
    open_for: Option<Table>,
    /// The files being written, each saying how it went.
    writes: Jobs<PathBuf, Notice>,
}

impl Default for Exports {
    fn default() -> Self {
        Self {
            dialog: FileDialog::default(),
            asked: None,
            open_for: None,
            writes: Jobs::new("save table"),
        }
    }
}

impl Exports {
    /// Saves `table` once a file is chosen (one dialog at a time).
    pub fn ask(&mut self, table: Table) {
        if !self.dialog.is_open() {
            self.asked = Some(table);
        }
    }

    /// Opens the dialog asked for, and writes the table once its file is
    /// chosen: what to tell the user then.
    pub fn frame(&mut self, ctx: &egui::Context, state: &AppState) -> Option<Notice> {
        if let Some(table) = self.asked.take() {
            self.dialog
                .save_file("zieglerlab: save the table", table.file_name(), ctx);
            self.open_for = Some(table);
        }
        self.dialog
            .typed_path_ui(ctx, &tr!(ctx.words(), "save-as-what-table"));
        if let Some((_, written)) = self.writes.drain().last() {
            return Some(written);
        }
        let closed = self.dialog.answer()?;
        let table = self.open_for.take()?;
        match closed {
            Closed::Chosen(path) => self.save(table, state, path, ctx),
            Closed::NoneChosen => Some(Notice::info(tr!(ctx.words(), NOT_SAVED))),
        }
    }

    /// Writes `table` to `path` on a thread of its own; what is said at once
    /// if it cannot start.
    fn save(
        &mut self,
        table: Table,
        state: &AppState,
        path: PathBuf,
        ctx: &egui::Context,
    ) -> Option<Notice> {
        let words = state.words();
        let Some(text) = table_csv(table, state) else {
            let why = tr!(words, "notice-no-locus");
            return Some(Notice::error(tr!(
                words,
                "notice-table-not-saved",
                why = why
            )));
        };
        let ctx = ctx.clone();
        let started = self.writes.request(path, move |path, _, send| {
            send(write(&text, path, words));
            ctx.request_repaint();
        });
        started
            .err()
            .map(|error| Notice::error(tr!(words, "notice-no-thread", why = error.to_string())))
    }

    /// Waits for the file being written (tests).
    #[cfg(test)]
    fn wait(&mut self) {
        self.writes.wait();
    }
}

/// The table's text as the window shows it now; `None` when it is the
/// root locus and these parameters have none.
#[must_use]
pub fn table_csv(table: Table, state: &AppState) -> Option<String> {
    match table {
        Table::History => Some(history_csv(
            state.model().column.rods,
            state.history().samples(),
        )),
        Table::Locus => state.analysis().map(|analysis| locus_csv(&analysis.locus)),
    }
}

/// Writes `text` to `path`, and says how it went in `words`' language (the
/// file system's own reason as it gives it).
fn write(text: &str, path: &Path, words: &'static crate::i18n::Words) -> Notice {
    match crate::files::write_atomically(path, |w| w.write_all(text.as_bytes())) {
        Ok(()) => Notice::info(tr!(
            words,
            "notice-saved-lines",
            count = text.lines().count(),
            path = path.display().to_string()
        )),
        Err(error) => Notice::error(tr!(words, "notice-write-failed", why = error.to_string())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::state::Settings;

    /// A file chosen for the locus gets the command line's table: its
    /// header and a row per branch at every sample of the locus shown.
    #[test]
    fn the_locus_table_goes_to_the_file_chosen() {
        let mut state = AppState::new(Settings::default()).unwrap();
        state.settle_analysis();
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("locus.csv");
        let mut exports = Exports {
            dialog: FileDialog::answered(Some(path.clone())),
            open_for: Some(Table::Locus),
            ..Exports::default()
        };
        // Written off the window's thread: said in a later frame.
        assert!(exports.frame(&egui::Context::default(), &state).is_none());
        exports.wait();
        let told = exports.frame(&egui::Context::default(), &state).unwrap();
        assert!(told.text.starts_with("saved "), "{}", told.text);
        let text = std::fs::read_to_string(&path).unwrap();
        let locus = &state.analysis().unwrap().locus;
        assert!(text.starts_with("load,branch,re,im\n"));
        assert_eq!(
            text.lines().count(),
            1 + locus.loads.len() * locus.branches.len()
        );
        // None chosen: nothing written, and said.
        exports.dialog = FileDialog::answered(None);
        exports.open_for = Some(Table::History);
        let told = exports.frame(&egui::Context::default(), &state).unwrap();
        assert!(told.text.starts_with("not saved"), "{}", told.text);
    }

    /// The history table has the command line's header for the model's rods
    /// and a row per sample.
    #[test]
    fn the_history_table_has_the_command_lines_columns() {
        let mut state = AppState::new(Settings::default()).unwrap();
        state.advance(0.5);
        let text = table_csv(Table::History, &state).unwrap();
        let mut lines = text.lines();
        assert_eq!(
            lines.next(),
            Some("t,phi1,phi2,psi,phi1_dot,phi2_dot,psi_dot,delta,energy")
        );
        assert_eq!(lines.count(), state.history().samples().count());
    }
}
