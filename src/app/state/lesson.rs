//! A lesson under way: which step is shown, what the student predicted,
//! and each step as the list of actions it asks for (preset, parameters,
//! speed, overlay, tab, a kick or a ramp).

use super::{AppState, Settings};
use crate::app::action::{Action, Command};
use crate::app::notice::Notice;
use crate::app::tab::Tab;
use crate::i18n::{Language, Words};
use crate::lesson::{Column, Lesson, Predict, Reveal, Run};
use crate::sim::Ramp;
use crate::tr;

/// A lesson and where the class is in it.
#[derive(Clone, Debug, PartialEq)]
pub struct LessonRun {
    pub lesson: Lesson,
    /// The step shown (from 0).
    pub step: usize,
    /// The load the student marked, for a `Load` prediction.
    pub predicted_load: Option<f64>,
    /// The answer the student chose (from 0), for a `Choice`.
    pub chosen: Option<usize>,
    /// The last choice asked, to set its answer beside the reveal.
    last_choice: Option<Vec<String>>,
    /// The column the lesson was opened on: each step's column is made
    /// from it, the same going forward and back.
    start: Column,
}

impl LessonRun {
    /// The step shown.
    #[must_use]
    pub fn current(&self) -> &crate::lesson::Step {
        &self.lesson.steps[self.step.min(self.lesson.steps.len() - 1)]
    }

    /// Whether the answer is kept from the class: from a step that asks for
    /// a prediction until a step that reveals. The critical loads, the
    /// stability's colours and verdict and the plots that show them are
    /// hidden meanwhile; what the class observes (the column, the time
    /// histories, the motion seen during a ramp) is not.
    #[must_use]
    pub fn answer_hidden(&self) -> bool {
        let shown = self.step.min(self.lesson.steps.len() - 1);
        let steps = &self.lesson.steps[..=shown];
        steps
            .iter()
            .rposition(|s| s.predict.is_some())
            .is_some_and(|asked| !steps[asked..].iter().any(|s| s.reveal.is_some()))
    }

    /// Whether the choice made was the answer the step shown reveals:
    /// `None` where it reveals no answer or none was chosen.
    #[must_use]
    pub fn verdict(&self) -> Option<bool> {
        match self.current().reveal {
            Some(Reveal::Answer(right)) => self.chosen.map(|i| i == right),
            _ => None,
        }
    }

    /// The revealed result of the step shown, in words, beside what was
    /// predicted; `first_instability` (searched up to `bar_max_p`, the load
    /// bar's top) and `seen_at_p` come from the state.
    #[must_use]
    pub fn reveal_text(
        &self,
        first_instability: Option<f64>,
        bar_max_p: f64,
        seen_at_p: Option<f64>,
        here: Option<(f64, &crate::analysis::Stability)>,
        words: &'static Words,
    ) -> Option<String> {
        let load = |p: f64| crate::format::load_text(p);
        let text = match self.current().reveal.as_ref()? {
            Reveal::FirstInstability => {
                let theory = first_instability.map_or_else(
                    || tr!(words, "reveal-never", load = load(bar_max_p)),
                    |p| tr!(words, "reveal-theory", load = load(p)),
                );
                let seen = seen_at_p
                    .map(|p| tr!(words, "reveal-seen", load = load(p)))
                    .unwrap_or_default();
                let predicted = self
                    .predicted_load
                    .map(|p| tr!(words, "reveal-predicted", load = load(p)))
                    .unwrap_or_default();
                tr!(
                    words,
                    "reveal-first-instability",
                    predicted = predicted,
                    theory = theory,
                    seen = seen
                )
            }
            Reveal::Answer(right) => {
                let answers = self.last_choice.as_deref().unwrap_or_default();
                let name = |i: usize| answers.get(i).cloned().unwrap_or_default();
                // Right and wrong read differently in words, not only in
                // colour.
                match self.chosen {
                    Some(i) if i == *right => tr!(words, "reveal-right", chosen = name(i)),
                    Some(i) => tr!(
                        words,
                        "reveal-wrong",
                        chosen = name(i),
                        answer = name(*right)
                    ),
                    None => tr!(words, "reveal-answer", answer = name(*right)),
                }
            }
            Reveal::StabilityHere => match here {
                Some((p, stability)) => stability_words(p, stability, words),
                None => tr!(words, "reveal-no-answer"),
            },
            Reveal::Text(text) => text.clone(),
        };
        Some(text)
    }
}

/// The theory's word on the column at load `p`: its state and how a kick
/// grows or dies away, in doubling or halving times and the period.
fn stability_words(
    p: f64,
    stability: &crate::analysis::Stability,
    words: &'static Words,
) -> String {
    use crate::analysis::State;
    use crate::format::{load_text, secs_text};
    let rate = stability.growth_rate_per_s();
    let frequency = stability.frequency_rad_per_s();
    let period = if frequency > stability.tolerance_per_s {
        tr!(
            words,
            "reveal-period",
            secs = secs_text(std::f64::consts::TAU / frequency)
        )
    } else {
        String::new()
    };
    let times = |rate: f64| secs_text(std::f64::consts::LN_2 / rate.abs());
    let how = match stability.state {
        State::Flutter => tr!(words, "reveal-flutter", secs = times(rate), period = period),
        State::Divergence => tr!(words, "reveal-divergence", secs = times(rate)),
        State::Stable if rate < -stability.tolerance_per_s => {
            tr!(words, "reveal-stable", secs = times(rate), period = period)
        }
        State::Stable => tr!(words, "reveal-undamped", period = period),
    };
    tr!(words, "reveal-here", load = load_text(p), how = how)
}

/// The built-in lessons in `language`, read once (the sidebar asks for
/// the next one every frame of a last step).
fn built_in_lessons(language: Language) -> &'static [Lesson] {
    static READ: [std::sync::OnceLock<Vec<Lesson>>; Language::COUNT] =
        [const { std::sync::OnceLock::new() }; Language::COUNT];
    READ[language as usize].get_or_init(|| {
        let tabs = Tab::ids();
        crate::lesson::built_in(language)
            .iter()
            .filter_map(|(_, text)| Lesson::read(text, &tabs).ok())
            .collect()
    })
}

impl AppState {
    /// Opens `lesson` at its first step, from the lesson's own state
    /// whatever ran before: no ramp, no overlay and the normal speed unless
    /// the step sets them; that step's actions follow.
    pub(super) fn open_lesson(&mut self, lesson: Lesson) -> Vec<Action> {
        self.lesson = Some(LessonRun {
            lesson,
            step: 0,
            predicted_load: None,
            chosen: None,
            last_choice: None,
            start: Column {
                preset: self.settings.preset,
                model: self.settings.model,
            },
        });
        let mut actions = vec![
            Action::RampStop,
            Action::Overlay(None),
            Action::Speed(Settings::default().speed),
        ];
        actions.extend(self.step_actions());
        actions
    }

    /// The lesson under way.
    #[must_use]
    pub fn lesson(&self) -> Option<&LessonRun> {
        self.lesson.as_ref()
    }

    /// Whether a lesson keeps the answer from the class now (see
    /// [`LessonRun::answer_hidden`]).
    #[must_use]
    pub fn answer_hidden(&self) -> bool {
        self.lesson.as_ref().is_some_and(LessonRun::answer_hidden)
    }

    /// Moves to the next step (or back, `forward` false); its actions follow.
    pub(super) fn lesson_step(&mut self, forward: bool) -> Vec<Action> {
        let Some(run) = &mut self.lesson else {
            return Vec::new();
        };
        let last = run.lesson.steps.len() - 1;
        if forward && run.step == last {
            // Past the last step: the next built-in lesson, or a word on
            // how to go on (Page Down did nothing, and nothing said so).
            if let Some(next) = self.next_lesson() {
                return vec![Action::LessonOpen(Box::new(next))];
            }
            self.say(Notice::info(tr!(self.words(), "notice-lesson-last-step")));
            return Vec::new();
        }
        let step = if forward {
            (run.step + 1).min(last)
        } else {
            run.step.saturating_sub(1)
        };
        if step == run.step {
            return Vec::new();
        }
        run.step = step;
        self.step_actions()
    }

    /// A built-in lesson open in `from`'s words goes on in `to`'s, at the
    /// same step (a lesson of the user's own keeps its words).
    pub(super) fn translate_lesson(&mut self, from: Language, to: Language) {
        let Some(run) = &mut self.lesson else {
            return;
        };
        let Some(k) = built_in_lessons(from)
            .iter()
            .position(|lesson| lesson.title == run.lesson.title)
        else {
            return;
        };
        if let Some(lesson) = built_in_lessons(to).get(k) {
            run.lesson = lesson.clone();
        }
    }

    /// The built-in lesson after the open one, when the open one is built
    /// in and not the last.
    #[must_use]
    pub fn next_lesson(&self) -> Option<Lesson> {
        let title = &self.lesson.as_ref()?.lesson.title;
        let mut built_in = built_in_lessons(self.language()).iter();
        built_in.find(|lesson| &lesson.title == title)?;
        built_in.next().cloned()
    }

    /// The student's predicted load.
    pub(super) fn predict_load(&mut self, load: f64) {
        if let Some(run) = &mut self.lesson {
            run.predicted_load = Some(load);
        }
    }

    /// The student's answer to the choice shown.
    pub(super) fn choose(&mut self, answer: usize) {
        if let Some(run) = &mut self.lesson {
            run.chosen = Some(answer);
        }
    }

    /// What the step shown asks for, in order: its column (taking it over
    /// from any ramp, a finished one too), speed, overlay, tab and run. A
    /// step that only reveals keeps the ramp and its marks.
    fn step_actions(&mut self) -> Vec<Action> {
        let words = self.words();
        let Some(run) = &mut self.lesson else {
            return Vec::new();
        };
        let step = run.current().clone();
        if let Some(Predict::Choice { answers, .. }) = &step.predict {
            run.last_choice = Some(answers.clone());
        }
        let mut actions = Vec::new();
        if step.sets_column() {
            actions.push(Action::RampStop);
            actions.push(match run.lesson.column_at(run.start, run.step) {
                Ok(column) => Action::Column {
                    preset: column.preset,
                    model: column.model,
                },
                Err((index, error)) => Action::Say(Notice::error(crate::tr!(
                    words,
                    "notice-lesson-step",
                    step = index + 1,
                    why = crate::i18n::model_error(words, &error)
                ))),
            });
        }
        actions.extend(step.speed.map(Action::Speed));
        actions.extend(step.overlay.map(|id| Action::Overlay(Some(id))));
        if let Some(name) = &step.tab {
            // Read against the registry: a name it has not was refused then.
            actions.push(Tab::named(name).map_or_else(
                |why| {
                    let why = why.to_string();
                    Action::Say(Notice::error(crate::tr!(words, "notice-lesson", why = why)))
                },
                Action::Tab,
            ));
        }
        match step.run {
            Some(Run::Kick) => actions.push(Command::Kick.into()),
            Some(Run::KickBy(angle_rad)) => actions.push(Action::KickBy { angle_rad }),
            // A ramp starts from a quiet column: a fresh run from the
            // standard small disturbance, whatever the class did before.
            Some(Run::Ramp { from, to, rate }) => match Ramp::new(from, to, rate) {
                Ok(ramp) => actions.extend([Command::Reset.into(), Action::RampStart(ramp)]),
                Err(error) => actions.push(Action::Say(Notice::error(crate::tr!(
                    words,
                    "notice-lesson",
                    why = crate::i18n::ramp_error(words, &error)
                )))),
            },
            None => {}
        }
        actions
    }
}
