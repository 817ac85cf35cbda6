//! Settings as text: copy them to share a setup, paste text (from the
//! system clipboard or typed into the box) to load one.

use crate::app::speak::Speak as _;
use crate::tr;
use eframe::egui;

use crate::app::action::{Action, Actions};
use crate::app::notice::Notice;
use crate::app::settings_text::MOST_SETTINGS_BYTES;
use crate::app::state::AppState;

/// Frames to wait for the clipboard's text after asking the window for it:
/// the window answers in the next frame, or not at all when the clipboard
/// holds no text.
const CLIPBOARD_FRAMES: u32 = 3;

/// Takes out of the frame's input every paste longer than settings text
/// can be, before any text field lays it out (a 10 MB paste froze the
/// window), and says what was refused.
fn refuse_long_pastes(ctx: &egui::Context, actions: &mut Actions) -> bool {
    let refused = ctx.input_mut(|input| {
        let mut refused = Vec::new();
        input.events.retain(|event| match event {
            egui::Event::Paste(text) if text.len() > MOST_SETTINGS_BYTES => {
                refused.push(text.len());
                false
            }
            _ => true,
        });
        refused
    });
    for &bytes in &refused {
        actions.push(Action::Say(Notice::error(tr!(
            ctx.words(),
            "paste-too-long",
            bytes = bytes,
            most = MOST_SETTINGS_BYTES
        ))));
    }
    !refused.is_empty()
}

/// The text box's contents, and whether a paste from the clipboard is on
/// its way.
#[derive(Default)]
pub struct ShareSection {
    text: String,
    /// Frames left to wait for the clipboard's text.
    awaiting_clipboard: Option<u32>,
}

/// The most of the window's height the settings box takes before it
/// scrolls.
const BOX_SHARE: f32 = 0.35;

impl ShareSection {
    /// The clipboard's text, when it has come: taken out of the frame's
    /// input (no text field receives it) and pasted as settings. Called
    /// every frame, before any widget reads the input.
    pub fn take_clipboard(&mut self, ctx: &egui::Context, actions: &mut Actions) {
        if refuse_long_pastes(ctx, actions) {
            // The clipboard's answer was that text: already said.
            self.awaiting_clipboard = None;
        }
        let Some(frames_left) = self.awaiting_clipboard else {
            return;
        };
        let pasted = ctx.input_mut(|input| {
            let at = input
                .events
                .iter()
                .position(|e| matches!(e, egui::Event::Paste(_)))?;
            match input.events.remove(at) {
                egui::Event::Paste(text) => Some(text),
                _ => None,
            }
        });
        if let Some(text) = pasted {
            self.awaiting_clipboard = None;
            self.text.clone_from(&text);
            actions.push(Action::Paste(text));
        } else if frames_left == 0 {
            self.awaiting_clipboard = None;
            actions.push(Action::Say(Notice::error(tr!(
                ctx.words(),
                "paste-no-text"
            ))));
        } else {
            self.awaiting_clipboard = Some(frames_left - 1);
            ctx.request_repaint();
        }
    }

    /// The menu's contents: copy, paste from the clipboard, and the box.
    pub fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
        let words = ui.words();
        ui.horizontal(|ui| {
            if ui
                .button(tr!(words, "share-copy"))
                .on_hover_text(tr!(words, "share-copy.tooltip"))
                .clicked()
            {
                let text = state.settings().to_text();
                ui.ctx().copy_text(text.clone());
                self.text = text;
            }
            if ui
                .button(tr!(words, "share-paste"))
                .on_hover_text(tr!(words, "share-paste.tooltip"))
                .clicked()
            {
                ui.ctx()
                    .send_viewport_cmd(egui::ViewportCommand::RequestPaste);
                self.awaiting_clipboard = Some(CLIPBOARD_FRAMES);
            }
        });
        // A long paste scrolls inside the box's area rather than pushing
        // the menu past the window's foot.
        let most_height =
            (ui.ctx().content_rect().height() * BOX_SHARE).max(ui.spacing().interact_size.y * 4.0);
        egui::ScrollArea::vertical()
            .id_salt("settings text")
            .max_height(most_height)
            .show(ui, |ui| {
                ui.add(
                    egui::TextEdit::multiline(&mut self.text)
                        .desired_rows(4)
                        .desired_width(300.0)
                        .hint_text(tr!(words, "share-box")),
                );
            });
        if ui
            .button(tr!(words, "share-take"))
            .on_hover_text(tr!(words, "share-take.tooltip"))
            .clicked()
        {
            actions.push(Action::Paste(self.text.clone()));
        }
    }
}
