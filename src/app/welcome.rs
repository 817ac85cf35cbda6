//! The first launch's welcome: what the column, the follower force, flutter,
//! divergence and the root locus are, in plain words, and an offer to start
//! the first lesson. Closed for good with one click.

use eframe::egui;

use super::action::{Action, Actions};
use super::speak::Speak as _;
use super::state::AppState;
use super::tab::Tab;
use super::theme::Theme;
use crate::i18n::Language;
use crate::lesson::{Lesson, built_in};
use crate::tr;

/// What a student reads first, paragraph by paragraph (message ids).
const WELCOME: [&str; 4] = [
    "welcome-column",
    "welcome-states",
    "welcome-locus",
    "welcome-try",
];

/// The welcome's text size on a projector: a desk screen's, a little
/// larger than the normal theme's.
const DESK_TEXT_SIZE: f32 = 16.0;

/// The welcome as a window over the app, while the state shows it.
pub fn welcome_ui(ctx: &egui::Context, state: &AppState, actions: &mut Actions, theme: &Theme) {
    if !state.welcome() {
        return;
    }
    // Over the running column without dimming it: a translucent layer over
    // the whole window costs a CPU renderer (Mesa's llvmpipe) a fifth of
    // its frame, and the class sees the column move behind the text.
    let id = egui::Id::unique("welcome");
    // On a projector the scene is narrow and the text large: the card, in
    // the text size of a desk's screen (it is for the person at the
    // computer, not the class), sits in the window's lower left corner,
    // over the sidebar and the tabs, and leaves the column in view.
    let (area, text_size) = if state.settings().projector {
        let corner = egui::Modal::default_area(id).anchor(
            egui::Align2::LEFT_BOTTOM,
            egui::vec2(8.0, -(1.6 * theme.text_size + 16.0)),
        );
        (corner, DESK_TEXT_SIZE)
    } else {
        (egui::Modal::default_area(id), theme.text_size)
    };
    let modal = egui::Modal::new(id)
        .area(area)
        .backdrop_color(egui::Color32::TRANSPARENT)
        .show(ctx, |ui| {
            if text_size < theme.text_size {
                let style = ui.style_mut();
                for font in style.text_styles.values_mut() {
                    font.size *= text_size / theme.text_size;
                }
            }
            ui.set_max_width(34.0 * text_size);
            let words = ui.words();
            ui.heading(tr!(words, "welcome-title"));
            // The languages first: the card is modal, the status line's
            // menu out of reach until it closes.
            ui.horizontal_wrapped(|ui| {
                for language in Language::CHOSEN_FROM {
                    if ui
                        .selectable_label(state.language() == language, language.endonym())
                        .on_hover_text(tr!(words, "menu-language"))
                        .clicked()
                    {
                        actions.push(Action::Language(language));
                    }
                }
            });
            for paragraph in WELCOME {
                ui.add_space(0.4 * theme.text_size);
                ui.label(tr!(words, paragraph));
            }
            ui.add_space(0.8 * theme.text_size);
            ui.horizontal(|ui| {
                let (name, text) = built_in(state.language())[0];
                if ui
                    .button(tr!(words, "welcome-first-lesson"))
                    .on_hover_text(tr!(words, "welcome-first-lesson.tooltip"))
                    .clicked()
                {
                    match Lesson::read(text, &Tab::ids()) {
                        Ok(lesson) => actions.push(Action::LessonOpen(Box::new(lesson))),
                        Err(error) => actions.push(Action::Say(super::notice::Notice::error(tr!(
                            words,
                            "notice-lesson-refused",
                            name = name,
                            why = error.to_string()
                        )))),
                    }
                    actions.push(Action::CloseWelcome);
                }
                if ui
                    .button(tr!(words, "welcome-explore"))
                    .on_hover_text(tr!(words, "welcome-explore.tooltip"))
                    .clicked()
                {
                    actions.push(Action::CloseWelcome);
                }
            });
        });
    if modal.should_close() {
        actions.push(Action::CloseWelcome);
    }
}
