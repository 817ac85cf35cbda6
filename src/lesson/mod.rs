//! Predict-then-observe lessons as small text files (RON): a title and a
//! sequence of steps, each showing text and able to set the preset, the
//! parameters, the load, the speed, the open tab and an overlay, start a kick or a
//! ramp, ask for a prediction and reveal the result. Reading, checking, and
//! the column each step leaves (the one rule the app and the checker share).

mod languages;

pub use languages::built_in;

use std::collections::BTreeMap;
use std::path::Path;

use serde::Deserialize;

use crate::format::Shown;
use crate::model::{Assignment, Key, Model, ModelError, PresetId, apply_assignments};
use crate::sim::{Ramp, SPEED_RANGE};

/// The largest lesson file read, in bytes: far more than any lesson needs,
/// small enough to read and check at once.
pub const MOST_BYTES: u64 = 1 << 20;

/// The longest title, in characters: one line on the screen.
const MOST_TITLE_CHARS: usize = 200;

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
    /// Parameters, as `--set` names them, e.g. `{"load": 1.0, "nu": 0.1}`;
    /// a key written twice is refused, not silently overwritten.
    #[serde(deserialize_with = "keys_once")]
    pub set: BTreeMap<Key, f64>,
    /// Simulated seconds per wall second.
    pub speed: Option<f64>,
    /// The tab to open, by its name (one of those the reader was given).
    pub tab: Option<String>,
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

    /// Whether the step changes the column (its preset or parameters).
    #[must_use]
    pub fn sets_column(&self) -> bool {
        self.preset.is_some() || !self.set.is_empty()
    }

    /// The column after this step, from `column`: its preset switched to
    /// (the load carried over as [`PresetId::switched_from`] does), then its
    /// parameters set.
    ///
    /// # Errors
    /// A parameter the column refuses, named.
    pub fn column_after(&self, column: Column) -> Result<Column, ModelError> {
        let Column {
            mut preset,
            mut model,
        } = column;
        if let Some(id) = self.preset {
            preset = id;
            model = id.switched_from(&model);
        }
        apply_assignments(&mut model, &self.assignments())?;
        Ok(Column { preset, model })
    }
}

/// A column a lesson acts on: the preset it came from and its model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    pub preset: PresetId,
    pub model: Model,
}

/// A `set` map whose keys are each written once.
fn keys_once<'de, D: serde::Deserializer<'de>>(
    deserializer: D,
) -> Result<BTreeMap<Key, f64>, D::Error> {
    struct Once;
    impl<'de> serde::de::Visitor<'de> for Once {
        type Value = BTreeMap<Key, f64>;

        fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("a map of parameters, e.g. {\"load\": 1.0}")
        }

        fn visit_map<A: serde::de::MapAccess<'de>>(
            self,
            mut map: A,
        ) -> Result<Self::Value, A::Error> {
            let mut set = BTreeMap::new();
            while let Some((key, value)) = map.next_entry::<Key, f64>()? {
                if set.insert(key, value).is_some() {
                    return Err(serde::de::Error::custom(format!(
                        "the key '{}' is written twice in `set`",
                        key.name()
                    )));
                }
            }
            Ok(set)
        }
    }
    deserializer.deserialize_map(Once)
}

/// The standard kick, in rad on every rod's angle: what the K key gives.
/// Large enough to be seen on a 1024x768 projector (0.01 rad moved the tip
/// by 2 px there), small enough that the run stays below the 0.05 rad in
/// which its eigenvalues are measured against the linear theory.
pub const KICK_RAD: f64 = 0.03;

/// The largest kick a lesson may give, in rad on every rod: beyond it the
/// column is thrown, not nudged, and nothing linear describes its motion.
pub const KICK_MOST_RAD: f64 = 0.2;

/// What a step starts.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize)]
pub enum Run {
    /// Every rod turned by the standard kick, [`KICK_RAD`].
    Kick,
    /// Every rod turned by this angle in rad (up to [`KICK_MOST_RAD`]): a
    /// swing a projector shows, e.g. `KickBy(0.05)`.
    KickBy(f64),
    /// The load moving from `from` to `to` at `rate` per simulated second.
    Ramp { from: f64, to: f64, rate: f64 },
}

impl Run {
    /// Whether `model` can take this run: a ramp's loads, a kick's size.
    ///
    /// # Errors
    /// What is wrong, in words.
    pub fn check_for(self, model: &Model) -> Result<(), String> {
        match self {
            Self::Kick => Ok(()),
            Self::KickBy(angle_rad) => {
                if angle_rad.is_finite() && angle_rad != 0.0 && angle_rad.abs() <= KICK_MOST_RAD {
                    Ok(())
                } else {
                    Err(format!(
                        "kick of {} rad: expected a turn of each rod other than 0, at most {KICK_MOST_RAD} rad either way",
                        Shown(angle_rad)
                    ))
                }
            }
            Self::Ramp { from, to, rate } => Ramp::new(from, to, rate)
                .and_then(|ramp| ramp.check_for(model))
                .map_err(|e| e.to_string()),
        }
    }
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
    /// What the theory says of the column at the load shown: its state, and
    /// how fast a kick grows or dies away.
    StabilityHere,
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

/// Why a lesson file cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum LessonFileError {
    #[error(transparent)]
    Read(#[from] crate::files::ReadError),
    #[error("{path}: {error}")]
    Lesson { path: String, error: LessonError },
}

impl Lesson {
    /// Reads and checks the lesson file at `path`: a regular file of at most
    /// [`MOST_BYTES`] (a device, a pipe or a huge file is refused unread).
    ///
    /// # Errors
    /// The file cannot be read, or the lesson's first problem.
    pub fn read_file(path: &Path, tabs: &[&str]) -> Result<Self, LessonFileError> {
        let text = crate::files::read_text(path, MOST_BYTES)?;
        Self::read(&text, tabs).map_err(|error| LessonFileError::Lesson {
            path: path.display().to_string(),
            error,
        })
    }

    /// Reads and checks a lesson's text: its syntax and field names, every
    /// step against the column it would act on, whichever preset the lesson
    /// is opened on, and each tab it opens among `tabs` (the app's, by name).
    ///
    /// # Errors
    /// The first problem, with its line.
    pub fn read(text: &str, tabs: &[&str]) -> Result<Self, LessonError> {
        // Optional fields are written bare (`preset: "tabletop"`), not
        // wrapped in `Some(..)`.
        let options = ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        let lesson: Self = options.from_str(text).map_err(|e| LessonError {
            line: e.span.start.line,
            message: e.code.to_string(),
        })?;
        lesson.check(text, tabs)?;
        Ok(lesson)
    }

    /// The column the lesson has made when step `index` is shown, opened on
    /// `start`: every step up to it applied in turn. Going back to a step
    /// gives the same column as reaching it forward.
    ///
    /// # Errors
    /// The first step whose parameters the column refuses: (its index, why).
    pub fn column_at(&self, start: Column, index: usize) -> Result<Column, (usize, ModelError)> {
        self.steps
            .iter()
            .enumerate()
            .take(index + 1)
            .try_fold(start, |column, (i, step)| {
                step.column_after(column).map_err(|e| (i, e))
            })
    }

    /// Checks what the syntax cannot: a title of one short printable line, a
    /// step with text, parameters and ramps that the column of that moment
    /// takes (from every preset the lesson may be opened on), a speed in
    /// range, a choice of two answers or more, and a revealed answer among
    /// them.
    fn check(&self, text: &str, tabs: &[&str]) -> Result<(), LessonError> {
        let at_step = |index: usize, message: String| LessonError {
            line: step_line(text, index),
            message: format!("step {}: {message}", index + 1),
        };
        check_title(&self.title).map_err(|message| LessonError {
            line: code_find(text, "title").map_or(1, |at| line_at(text, at)),
            message,
        })?;
        if self.steps.is_empty() {
            return Err(LessonError {
                line: 1,
                message: "expected at least one step in `steps`".to_owned(),
            });
        }
        for &start in PresetId::all() {
            let opened_on = |message: String| {
                if self.steps[0].preset.is_some() {
                    message
                } else {
                    format!("{message} (the lesson opened on the {start} preset)")
                }
            };
            let mut column = Column {
                preset: start,
                model: start.model(),
            };
            for (index, step) in self.steps.iter().enumerate() {
                column = step
                    .column_after(column)
                    .map_err(|e| at_step(index, opened_on(e.to_string())))?;
                if let Some(run) = step.run {
                    run.check_for(&column.model)
                        .map_err(|message| at_step(index, opened_on(message)))?;
                }
            }
        }
        let mut answers: Option<usize> = None;
        for (index, step) in self.steps.iter().enumerate() {
            if step.text.trim().is_empty() {
                return Err(at_step(index, "expected a `text` to show".to_owned()));
            }
            if let Some(tab) = &step.tab
                && !tabs.contains(&tab.as_str())
            {
                return Err(at_step(
                    index,
                    format!("unknown tab '{tab}': expected one of {}", tabs.join(", ")),
                ));
            }
            if let Some(speed) = step.speed
                && !SPEED_RANGE.contains(&speed)
            {
                return Err(at_step(
                    index,
                    format!(
                        "speed = {}: expected {} to {} simulated seconds per second",
                        Shown(speed),
                        SPEED_RANGE.start(),
                        SPEED_RANGE.end()
                    ),
                ));
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

/// A title is one line of at most [`MOST_TITLE_CHARS`] printable
/// characters: it is printed on terminals, where a control character
/// (an escape sequence) could rewrite the screen.
fn check_title(title: &str) -> Result<(), String> {
    if title.trim().is_empty() {
        return Err("expected a `title`".to_owned());
    }
    let chars = title.chars().count();
    if chars > MOST_TITLE_CHARS {
        return Err(format!(
            "the title has {chars} characters; at most {MOST_TITLE_CHARS}"
        ));
    }
    if let Some(control) = title.chars().find(|c| c.is_control()) {
        return Err(format!(
            "the title holds the control character U+{:04X}; expected printable text on one line",
            u32::from(control)
        ));
    }
    Ok(())
}

/// The line (from 1) where step `index` (from 0) of `text` begins: the
/// `index`-th `Step(` after `steps:` outside strings and comments, or 1
/// when it cannot be found.
fn step_line(text: &str, index: usize) -> usize {
    let start = code_find(text, "steps").unwrap_or(0);
    code_offsets(&text[start..])
        .filter(|&offset| text[start + offset..].starts_with("Step("))
        .nth(index)
        .map_or(1, |offset| line_at(text, start + offset))
}

/// The first offset of `word` in `text` outside strings and comments (a
/// title may hold the word "steps").
fn code_find(text: &str, word: &str) -> Option<usize> {
    code_offsets(text).find(|&offset| text[offset..].starts_with(word))
}

/// The line (from 1) holding byte `offset` of `text`.
fn line_at(text: &str, offset: usize) -> usize {
    text[..offset].matches('\n').count() + 1
}

/// The byte offsets of `text` that are code: outside string literals
/// (with their escapes) and `//` or `/* */` comments.
fn code_offsets(text: &str) -> impl Iterator<Item = usize> + '_ {
    #[derive(Clone, Copy)]
    enum In {
        Code,
        Text,
        Escape,
        LineComment,
        BlockComment,
    }
    let bytes = text.as_bytes();
    let mut state = In::Code;
    (0..bytes.len()).filter(move |&i| {
        let (next, code) = match (state, bytes[i]) {
            (In::Code, b'"') | (In::Escape, _) => (In::Text, false),
            (In::Code, b'/') if bytes.get(i + 1) == Some(&b'/') => (In::LineComment, false),
            (In::Code, b'/') if bytes.get(i + 1) == Some(&b'*') => (In::BlockComment, false),
            (In::Code, _) => (In::Code, true),
            (In::Text, b'\\') => (In::Escape, false),
            (In::Text, b'"') | (In::LineComment, b'\n') => (In::Code, false),
            (In::BlockComment, b'/') if i > 0 && bytes[i - 1] == b'*' => (In::Code, false),
            (other, _) => (other, false),
        };
        state = next;
        code
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_lesson_reads_and_checks() {
        for (name, text) in BUILT_IN {
            let lesson = Lesson::read(text, &crate::app::Tab::ids())
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            assert!(lesson.steps.len() >= 3, "{name}");
            assert!(
                lesson.steps.iter().any(|s| s.predict.is_some())
                    && lesson.steps.iter().any(|s| s.reveal.is_some()),
                "{name}: predict, then reveal"
            );
        }
    }

    /// A step's column is the lesson's start with every step up to it
    /// applied: reached forward or by going back, the same.
    #[test]
    fn a_step_gives_the_same_column_forward_and_back() {
        let lesson = Lesson::read(
            "Lesson(title: \"t\", steps: [\n Step(text: \"a\", preset: \"tabletop\", set: {\"eta\": 0.5, \"load\": 1.0}),\n Step(text: \"b\", preset: \"roller\"),\n Step(text: \"c\", set: {\"load\": 2.0}),\n])",
&crate::app::Tab::ids(),
)
        .unwrap();
        let start = Column {
            preset: PresetId::Beck,
            model: PresetId::Beck.model(),
        };
        let first = lesson.column_at(start, 0).unwrap();
        assert_eq!(first.preset, PresetId::Tabletop);
        let mut expected = PresetId::Tabletop.model();
        apply_assignments(
            &mut expected,
            &[
                Assignment {
                    key: Key::Eta,
                    value: 0.5,
                },
                Assignment {
                    key: Key::Load,
                    value: 1.0,
                },
            ],
        )
        .unwrap();
        assert_eq!(first.model, expected);
        let last = lesson.column_at(start, 2).unwrap();
        assert_eq!(last.preset, PresetId::Roller);
        assert_eq!(last.model.load_p(), 2.0);
        // The roller's load 1 carried over from step 1, then step 3's own.
        assert_eq!(lesson.column_at(start, 1).unwrap().model.load_p(), 1.0);
        assert_eq!(lesson.column_at(start, 0).unwrap(), first, "back to step 1");
    }
}
