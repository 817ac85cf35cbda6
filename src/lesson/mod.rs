//! Predict-then-observe lessons as small text files (RON): a title and a
//! sequence of steps, each showing text and able to set the preset, the
//! parameters, the load, the speed, the open tab and an overlay, start a kick or a
//! ramp, ask for a prediction and reveal the result. Reading and checking
//! only: what the app does with a step is the app's business.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::model::{Assignment, Key, Model, PresetId, apply_assignments};
use crate::sim::{Ramp, SPEED_RANGE};

/// The lessons built into the program: (file name, text).
pub const BUILT_IN: [(&str, &str); 3] = [
    (
        "where-flutter-starts.ron",
        include_str!("../../assets/lessons/where-flutter-starts.ron"),
    ),
    (
        "is-the-roller-a-follower.ron",
        include_str!("../../assets/lessons/is-the-roller-a-follower.ron"),
    ),
    (
        "damping-paradox.ron",
        include_str!("../../assets/lessons/damping-paradox.ron"),
    ),
];

/// A lesson: its title and its steps, shown in turn.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lesson {
    pub title: String,
    pub steps: Vec<Step>,
}

/// One step: its text, and what it sets, starts, asks and reveals (each
/// optional).
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct Step {
    pub text: String,
    /// The model to switch to, by preset name.
    pub preset: Option<PresetId>,
    /// Parameters, as `--set` names them, e.g. `{"load": 1.0, "nu": 0.1}`.
    pub set: BTreeMap<Key, f64>,
    /// Simulated seconds per wall second.
    pub speed: Option<f64>,
    /// The tab to open.
    pub tab: Option<LessonTab>,
    /// Another preset's root locus to draw behind the current one.
    pub overlay: Option<PresetId>,
    /// Something to start.
    pub run: Option<Run>,
    /// A prediction to ask for.
    pub predict: Option<Predict>,
    /// The result to show beside the prediction.
    pub reveal: Option<Reveal>,
}

impl Step {
    /// The step's parameters as `--set` assignments.
    #[must_use]
    pub fn assignments(&self) -> Vec<Assignment> {
        self.set
            .iter()
            .map(|(&key, &value)| Assignment { key, value })
            .collect()
    }
}

/// The app's tabs, by the names a lesson uses: "locus", "histories",
/// "map", "paradox".
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(try_from = "String")]
pub enum LessonTab {
    Locus,
    Histories,
    Map,
    Paradox,
}

impl TryFrom<String> for LessonTab {
    type Error = String;

    fn try_from(name: String) -> Result<Self, String> {
        match name.as_str() {
            "locus" => Ok(Self::Locus),
            "histories" => Ok(Self::Histories),
            "map" => Ok(Self::Map),
            "paradox" => Ok(Self::Paradox),
            _ => Err(format!(
                "unknown tab '{name}': expected locus, histories, map or paradox"
            )),
        }
    }
}

/// What a step starts.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
pub enum Run {
    /// Both angles disturbed by a small kick.
    Kick,
    /// The load moving from `from` to `to` at `rate` per simulated second.
    Ramp { from: f64, to: f64, rate: f64 },
}

/// A prediction the student makes.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub enum Predict {
    /// A load, marked on the load bar, with this prompt.
    Load(String),
    /// One of `answers`.
    Choice {
        prompt: String,
        answers: Vec<String>,
    },
}

/// What a step shows next to the prediction.
#[derive(Clone, Debug, PartialEq, Deserialize)]
pub enum Reveal {
    /// The load at which the current model first loses stability.
    FirstInstability,
    /// The right answer of the last choice, by its place (from 0).
    Answer(usize),
    /// A text.
    Text(String),
}

/// Why a lesson cannot be used: where (a line of the file, from 1) and what
/// was expected.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("line {line}: {message}")]
pub struct LessonError {
    pub line: usize,
    pub message: String,
}

impl Lesson {
    /// Reads and checks a lesson's text: its syntax and field names, then
    /// every step against the model it would act on.
    ///
    /// # Errors
    /// The first problem, with its line.
    pub fn read(text: &str) -> Result<Self, LessonError> {
        // Optional fields are written bare (`preset: "tabletop"`), not
        // wrapped in `Some(..)`.
        let options = ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        let lesson: Self = options.from_str(text).map_err(|e| LessonError {
            line: e.span.start.line,
            message: e.code.to_string(),
        })?;
        lesson.check(text)?;
        Ok(lesson)
    }

    /// Checks what the syntax cannot: a step with text, parameters that the
    /// model of that moment takes, a speed in range, a ramp that is one, a
    /// choice of two answers or more, and a revealed answer among them.
    fn check(&self, text: &str) -> Result<(), LessonError> {
        let at_step = |index: usize, message: String| LessonError {
            line: step_line(text, index),
            message: format!("step {}: {message}", index + 1),
        };
        if self.steps.is_empty() {
            return Err(LessonError {
                line: 1,
                message: "expected at least one step in `steps`".to_owned(),
            });
        }
        let mut model: Model = PresetId::Roller.model();
        let mut answers: Option<usize> = None;
        for (index, step) in self.steps.iter().enumerate() {
            if step.text.trim().is_empty() {
                return Err(at_step(index, "expected a `text` to show".to_owned()));
            }
            if let Some(preset) = step.preset {
                model = preset.model().at_load(model.load_p());
            }
            apply_assignments(&mut model, &step.assignments())
                .map_err(|e| at_step(index, e.to_string()))?;
            if let Some(speed) = step.speed
                && !SPEED_RANGE.contains(&speed)
            {
                return Err(at_step(
                    index,
                    format!(
                        "speed = {speed}: expected {} to {} simulated seconds per second",
                        SPEED_RANGE.start(),
                        SPEED_RANGE.end()
                    ),
                ));
            }
            if let Some(Run::Ramp { from, to, rate }) = step.run {
                Ramp::new(from, to, rate).map_err(|e| at_step(index, e))?;
            }
            if let Some(Predict::Choice { answers: given, .. }) = &step.predict {
                if given.len() < 2 {
                    return Err(at_step(
                        index,
                        "expected a choice of two answers or more".to_owned(),
                    ));
                }
                answers = Some(given.len());
            }
            if let Some(Reveal::Answer(answer)) = step.reveal {
                match answers {
                    Some(count) if answer < count => {}
                    Some(count) => {
                        return Err(at_step(
                            index,
                            format!(
                                "Answer({answer}): expected 0 to {} (the last choice's answers)",
                                count - 1
                            ),
                        ));
                    }
                    None => {
                        return Err(at_step(
                            index,
                            "Answer(..) reveals a choice, but no step before asks one".to_owned(),
                        ));
                    }
                }
            }
        }
        Ok(())
    }
}

/// The line (from 1) where step `index` (from 0) of `text` begins: the
/// `index`-th `Step(` after `steps:`, or 1 when it cannot be found.
fn step_line(text: &str, index: usize) -> usize {
    let start = text.find("steps").unwrap_or(0);
    text[start..]
        .match_indices("Step(")
        .nth(index)
        .map_or(1, |(offset, _)| {
            text[..start + offset].lines().count().max(1)
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_lesson_reads_and_checks() {
        for (name, text) in BUILT_IN {
            let lesson = Lesson::read(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(lesson.steps.len() >= 3, "{name}");
            assert!(
                lesson.steps.iter().any(|s| s.predict.is_some())
                    && lesson.steps.iter().any(|s| s.reveal.is_some()),
                "{name}: predict, then reveal"
            );
        }
    }

    /// A broken lesson is refused at its line, saying what was expected.
    #[test]
    fn a_broken_lesson_is_refused_at_its_line() {
        let cases = [
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", presett: \"tabletop\"),\n ],\n)",
                4,
                "presett",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", preset: \"nope\"),\n ],\n)",
                4,
                "unknown preset 'nope'",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\"),\n  Step(text: \"b\",\n   set: {\"load\": -1.0}),\n ],\n)",
                5,
                "step 2: load = -1",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", set: {\"zeta\": 1.0}),\n ],\n)",
                4,
                "unknown key 'zeta'",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", predict: Choice(prompt: \"?\", answers: [\"x\", \"y\"])),\n  Step(text: \"b\", reveal: Answer(2)),\n ],\n)",
                5,
                "expected 0 to 1",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", run: Ramp(from: 0.0, to: 4.0, rate: 0.0)),\n ],\n)",
                4,
                "ramp rate = 0",
            ),
            (
                "Lesson(\n title: \"t\",\n steps: [],\n)",
                1,
                "at least one step",
            ),
        ];
        for (text, line, says) in cases {
            let error = Lesson::read(text).unwrap_err();
            assert_eq!(error.line, line, "{text}: {error}");
            assert!(error.message.contains(says), "{text}: {error}");
        }
    }
}
