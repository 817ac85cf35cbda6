//! The lesson panel: choose a built-in lesson or open one from a file;
//! then the step's text, the prediction (a load, or a choice), the result
//! beside it, back and next.

use crate::app::speak::Speak as _;
use crate::tr;
use eframe::egui::{self, RichText};

use crate::app::action::{Action, Actions, Command};
use crate::app::jobs::{Jobs, Reply};
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::app::{Notice, View};
use crate::format::load_text;
use crate::i18n::Language;
use crate::lesson::{Lesson, LessonError, LessonFileError, Predict, Reveal, built_in};

/// The built-in lessons (read and checked once), the path typed to open a
/// lesson file, and the file being read.
/// A built-in lesson's file name and what reading it gave.
type BuiltIn = (&'static str, Result<Lesson, LessonError>);

#[derive(Default)]
pub struct LessonSection {
    built_in: Option<(Language, Vec<BuiltIn>)>,
    path: String,
    /// The lesson file being read and checked off the UI thread (a slow
    /// disk or a large file never holds the window), by its path.
    reading: Option<Jobs<String, Result<Lesson, LessonFileError>>>,
    /// The step whose reveal is shown (the lesson's title and the step's
    /// index), and for how many frames.
    revealed: Option<((String, usize), u32)>,
}

/// The frames a reveal is shown before it is brought into view: by then
/// the sidebar's foot has its new height (it changes with a lesson), and
/// the scroll goes no further than needed.
const SETTLED_FRAMES: u32 = 2;

impl LessonSection {
    /// Opens the file read, or says why not, once the reading is done.
    fn take_reading(&mut self, ctx: &egui::Context, actions: &mut Actions) {
        let Some(reading) = &self.reading else {
            return;
        };
        match reading.reply() {
            Reply::Sent(Ok(lesson)) => actions.push(Action::LessonOpen(Box::new(lesson))),
            Reply::Sent(Err(error)) => actions.push(Action::Say(Notice::error(tr!(
                ctx.words(),
                "notice-lesson-not-opened",
                why = error.to_string()
            )))),
            Reply::Pending => {
                ctx.request_repaint_after(std::time::Duration::from_millis(50));
                return;
            }
            Reply::Ended => {
                let path = reading.key().cloned().unwrap_or_default();
                actions.push(Action::Say(Notice::error(tr!(
                    ctx.words(),
                    "lesson-reading-stopped",
                    path = path
                ))));
            }
        }
        self.reading = None;
    }
}

/// The lesson file at `path` read and checked on a job of its own.
///
/// # Errors
/// The system gives no thread.
fn start_reading(path: &str) -> std::io::Result<Jobs<String, Result<Lesson, LessonFileError>>> {
    let mut reading = Jobs::new("lesson file");
    reading.request(path.to_owned(), |path, _, send| {
        send(Lesson::read_file(
            std::path::Path::new(path),
            &crate::app::Tab::ids(),
        ));
    })?;
    Ok(reading)
}

impl View for LessonSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        self.take_reading(ui.ctx(), actions);
        if let Some(run) = state.lesson() {
            // A step's reveal is brought into view once, where the step's
            // text is longer than the sidebar shows (a projector): the
            // title scrolls away before the result does.
            if let Some(reveal) = step_ui(ui, state, actions, theme) {
                let this = (run.lesson.title.clone(), run.step);
                let frames = match &mut self.revealed {
                    Some((at, frames)) if *at == this => {
                        *frames = frames.saturating_add(1);
                        *frames
                    }
                    _ => {
                        self.revealed = Some((this, 0));
                        0
                    }
                };
                if frames == SETTLED_FRAMES {
                    reveal.scroll_to_me(None);
                }
            }
            // On a projector the buttons stay in view at the sidebar's
            // foot (`step_buttons_ui`), under the text, which may scroll.
            if !state.settings().projector {
                step_buttons_ui(ui, state, actions);
            }
            return;
        }
        // Read again when the language changes.
        let language = state.language();
        if self
            .built_in
            .as_ref()
            .is_none_or(|(read, _)| *read != language)
        {
            let read = built_in(language)
                .iter()
                .map(|&(name, text)| (name, Lesson::read(text, &crate::app::Tab::ids())))
                .collect();
            self.built_in = Some((language, read));
        }
        let Some((_, built_in)) = &self.built_in else {
            return;
        };
        let words = ui.words();
        egui::CollapsingHeader::new(tr!(words, "lessons")).show(ui, |ui| {
            for (name, read) in built_in {
                match read {
                    Ok(lesson) => {
                        if ui
                            .button(lesson.title.as_str())
                            .on_hover_text(tr!(words, "lessons-built-in", name = *name))
                            .clicked()
                        {
                            actions.push(Action::LessonOpen(Box::new(lesson.clone())));
                        }
                    }
                    Err(error) => {
                        ui.colored_label(color(theme.palette.error), format!("{name}: {error}"));
                    }
                }
            }
            ui.horizontal(|ui| {
                ui.add(
                    egui::TextEdit::singleline(&mut self.path)
                        .hint_text(tr!(words, "lesson-file.hint"))
                        .desired_width(180.0),
                )
                .accessible_name(tr!(words, "lesson-file"))
                .on_hover_text(tr!(words, "lesson-file.tooltip"));
                if let Some(path) = self.reading.as_ref().and_then(Jobs::key) {
                    ui.weak(tr!(words, "lesson-reading", path = path.as_str()));
                } else if ui
                    .button(tr!(words, "lesson-open"))
                    .on_hover_text(tr!(words, "lesson-open.tooltip"))
                    .clicked()
                {
                    match start_reading(self.path.trim()) {
                        Ok(reading) => self.reading = Some(reading),
                        Err(error) => actions.push(Action::Say(Notice::error(tr!(
                            words,
                            "notice-lesson-not-opened",
                            why = error.to_string()
                        )))),
                    }
                }
            });
        });
    }
}

/// The step shown, its prediction and its result; returns the result's
/// place when there is one.
fn step_ui(
    ui: &mut egui::Ui,
    state: &AppState,
    actions: &mut Actions,
    theme: &Theme,
) -> Option<egui::Response> {
    let words = ui.words();
    let run = state.lesson()?.clone();
    let step = run.current().clone();
    ui.label(RichText::new(&run.lesson.title).strong());
    ui.weak(tr!(
        words,
        "lesson-step",
        k = run.step + 1,
        n = run.lesson.steps.len()
    ));
    ui.label(&step.text);
    match &step.predict {
        Some(Predict::Load(prompt)) => {
            ui.label(RichText::new(prompt).color(color(theme.palette.info)));
            let mut load = run.predicted_load.unwrap_or(0.0);
            // The words and the value above the slider, the slider the
            // sidebar's width: beside it they ran past the sidebar's edge
            // on a projector ("your predictio").
            ui.label(tr!(
                words,
                "lesson-prediction",
                load = run.predicted_load.map_or("?".to_owned(), load_text)
            ));
            let response = ui
                .scope(|ui| {
                    ui.spacing_mut().slider_width = ui.available_width();
                    ui.add(egui::Slider::new(&mut load, 0.0..=state.load_max()).show_value(false))
                })
                .inner
                .accessible_name(tr!(words, "lesson-predicted-load"))
                .on_hover_text(tr!(words, "lesson-predicted-load.tooltip"));
            // The keys step as the load bar's do, not by egui's point.
            let keyed = if response.has_focus() {
                let from = run.predicted_load.unwrap_or(0.0);
                crate::app::load_bar::keyed_load(ui, response.id, from, state.load_max())
            } else {
                None
            };
            if let Some(load) = keyed.or_else(|| response.changed().then_some(load)) {
                actions.push(Action::LessonPredict(load));
            }
        }
        Some(Predict::Choice { prompt, answers }) => {
            ui.label(RichText::new(prompt).color(color(theme.palette.info)));
            for (i, answer) in answers.iter().enumerate() {
                if ui.radio(run.chosen == Some(i), answer.as_str()).clicked() {
                    actions.push(Action::LessonChoose(i));
                }
            }
        }
        None => {}
    }
    let first = state
        .analysis()
        .and_then(crate::app::analysis_cache::Analysis::first_instability);
    let seen = state.ramp().and_then(|r| r.seen_at_p);
    let spectrum = state.current_spectrum();
    let here = spectrum.map(|s| crate::analysis::classify(&s.eigenvalues, s.scale_per_s));
    let here = here.as_ref().map(|s| (state.model().load_p(), s));
    let revealed = run
        .reveal_text(first, state.load_max(), seen, here, words)
        .map(|result| {
            // Right in the stable colour and strong, wrong in the warning
            // colour, a result of the theory in the text's: the words differ too.
            let text = RichText::new(result);
            ui.label(match run.verdict() {
                Some(true) => text.color(color(theme.palette.stable)).strong(),
                Some(false) => text.color(color(theme.palette.warning)),
                None => text.color(color(theme.palette.text)),
            })
        });
    // The prediction beside the steps after it, but for the reveal of the
    // first instability, which says it itself.
    if let Some(p) = run.predicted_load
        && step.predict.is_none()
        && step.reveal != Some(Reveal::FirstInstability)
    {
        ui.weak(tr!(words, "lesson-prediction", load = load_text(p)));
    }
    revealed
}

/// A lesson's way through its steps: back, next and close, and at its
/// last step the next lesson.
pub fn step_buttons_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let Some(run) = state.lesson() else {
        return;
    };
    let last = run.step + 1 == run.lesson.steps.len();
    let words = ui.words();
    // Wrapped: in German on a projector the three do not fit one row.
    ui.horizontal_wrapped(|ui| {
        if ui
            .add_enabled(run.step > 0, egui::Button::new(tr!(words, "lesson-back")))
            .on_hover_text(tr!(words, "lesson-back.tooltip"))
            .clicked()
        {
            actions.push(Command::LessonBack);
        }
        if !last
            && ui
                .button(tr!(words, "lesson-next"))
                .on_hover_text(tr!(words, "lesson-next.tooltip"))
                .clicked()
        {
            actions.push(Command::LessonNext);
        }
        if ui
            .button(tr!(words, "lesson-close"))
            .on_hover_text(tr!(words, "lesson-close.tooltip"))
            .clicked()
        {
            actions.push(Action::LessonClose);
        }
    });
    if last {
        next_lesson_ui(ui, state, actions);
    }
}

/// The way on from a lesson's last step, on a row of its own and cut to
/// the sidebar's width (a long title pushed the rows past its edge): the
/// next lesson (Page Down), its whole title on hover.
fn next_lesson_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions) {
    let words = ui.words();
    if let Some(next) = state.next_lesson() {
        if ui
            .add(
                egui::Button::new(tr!(words, "lesson-next-lesson", title = next.title.clone()))
                    .truncate(),
            )
            .on_hover_text(tr!(
                words,
                "lesson-next-lesson.tooltip",
                title = next.title.clone()
            ))
            .clicked()
        {
            actions.push(Command::LessonNext);
        }
    } else {
        ui.weak(tr!(words, "lesson-last"));
    }
}
