//! The lesson panel: choose a built-in lesson or open one from a file;
//! then the step's text, the prediction (a load, or a choice), the result
//! beside it, back and next.

use eframe::egui::{self, RichText};

use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::app::{Notice, View};
use crate::format::load_text;
use crate::lesson::{BUILT_IN, Lesson, Predict};

/// The path typed to open a lesson file.
#[derive(Default)]
pub struct LessonSection {
    path: String,
}

impl View for LessonSection {
    fn ui(&mut self, ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
        if state.lesson().is_some() {
            step_ui(ui, state, theme);
            return;
        }
        egui::CollapsingHeader::new("lessons").show(ui, |ui| {
            for (name, text) in BUILT_IN {
                match Lesson::read(text) {
                    Ok(lesson) => {
                        if ui
                            .button(lesson.title.as_str())
                            .on_hover_text(format!("the built-in lesson {name}"))
                            .clicked()
                        {
                            state.open_lesson(lesson);
                        }
                    }
                    Err(error) => {
                        ui.colored_label(theme.error, format!("{name}: {error}"));
                    }
                }
            }
            ui.horizontal(|ui| {
                ui.add(
                    egui::TextEdit::singleline(&mut self.path)
                        .hint_text("a lesson file (.ron)")
                        .desired_width(180.0),
                )
                .accessible_name("lesson file")
                .on_hover_text("the path of your own lesson file (see the README for the format)");
                if ui
                    .button("open")
                    .on_hover_text("read and check the file, then start it")
                    .clicked()
                {
                    open_file(self.path.trim(), state);
                }
            });
        });
    }
}

/// Reads, checks and starts the lesson at `path`; says why not otherwise.
fn open_file(path: &str, state: &mut AppState) {
    let read = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the lesson: {e}"))
        .and_then(|text| Lesson::read(&text).map_err(|e| e.to_string()));
    match read {
        Ok(lesson) => state.open_lesson(lesson),
        Err(why) => state.say(Notice::error(format!("{path}: {why}"))),
    }
}

/// The step shown, its prediction and its result.
fn step_ui(ui: &mut egui::Ui, state: &mut AppState, theme: &Theme) {
    let Some(run) = state.lesson().cloned() else {
        return;
    };
    let step = run.current().clone();
    ui.label(RichText::new(&run.lesson.title).strong());
    ui.weak(format!(
        "step {} of {}",
        run.step + 1,
        run.lesson.steps.len()
    ));
    ui.label(&step.text);
    match &step.predict {
        Some(Predict::Load(prompt)) => {
            ui.label(RichText::new(prompt).color(theme.info));
            let mut load = run.predicted_load.unwrap_or(0.0);
            let response = ui
                .add(egui::Slider::new(&mut load, 0.0..=state.load_max()).text("your prediction p"))
                .accessible_name("predicted load")
                .on_hover_text("where you expect it; the load bar marks it");
            if response.changed() {
                state.predict_load(load);
            }
        }
        Some(Predict::Choice { prompt, answers }) => {
            ui.label(RichText::new(prompt).color(theme.info));
            for (i, answer) in answers.iter().enumerate() {
                if ui.radio(run.chosen == Some(i), answer.as_str()).clicked() {
                    state.choose(i);
                }
            }
        }
        None => {}
    }
    let first = state
        .analysis()
        .and_then(crate::app::analysis_cache::Analysis::first_instability);
    let seen = state.ramp().and_then(|r| r.seen_at_p);
    if let Some(result) = run.reveal_text(first, seen) {
        ui.label(RichText::new(result).color(theme.measured));
    }
    if let Some(p) = run.predicted_load
        && step.predict.is_none()
    {
        ui.weak(format!("your prediction: p = {}", load_text(p)));
    }
    ui.horizontal(|ui| {
        let last = run.step + 1 == run.lesson.steps.len();
        if ui
            .add_enabled(run.step > 0, egui::Button::new("back"))
            .on_hover_text("the previous step (Page Up)")
            .clicked()
        {
            state.lesson_step(false);
        }
        if ui
            .add_enabled(!last, egui::Button::new("next"))
            .on_hover_text("the next step: it sets and starts what it says (Page Down, as a presenter's remote sends)")
            .clicked()
        {
            state.lesson_step(true);
        }
        if ui
            .button("close lesson")
            .on_hover_text("leave the lesson; the model stays as it is")
            .clicked()
        {
            state.close_lesson();
        }
    });
}
