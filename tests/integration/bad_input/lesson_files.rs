//! Lesson files that are broken, each refused by `lesson --check` with
//! status 2 and one line naming the line of the problem.

use super::run_limited;

/// Broken lessons: the text, the line of the problem and what is said.
const BROKEN: &[(&str, usize, &str)] = &[
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
    // A key written twice is refused, not overwritten.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", set: {\"load\": 1.0, \"load\": 2.0}),\n ],\n)",
        4,
        "the key 'load' is written twice in `set`",
    ),
    // A title that would reach a terminal as an escape sequence.
    (
        "Lesson(\n title: \"t\\u{1b}[2J\",\n steps: [\n  Step(text: \"a\"),\n ],\n)",
        2,
        "control character U+001B",
    ),
    // `Step(` inside a string or a comment is not a step.
    (
        "Lesson(\n title: \"Step(\",\n // Step( here\n steps: [\n  Step(text: \"Step(, Step(\"),\n  Step(text: \"b\", speed: 50.0),\n ],\n)",
        6,
        "step 2: speed = 50",
    ),
    // A title holding the word "steps" (it was named as line 1).
    (
        "Lesson(\n title: \"The steps to flutter\",\n steps: [\n  Step(text: \"a\"),\n  Step(text: \"b\", speed: 50.0),\n ],\n)",
        5,
        "step 2: speed = 50",
    ),
    // A ramp so slow that it would never move the load (1e-320 is a
    // subnormal number: the load would not change in a lifetime).
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", preset: \"tabletop\",\n   run: Ramp(from: 0.0, to: 4.0, rate: 1e-320)),\n ],\n)",
        4,
        "ramp rate = 1e-320",
    ),
    // A first step's parameter that one preset lacks: refused,
    // naming the preset the window would fail on.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", set: {\"nu\": 0.2}),\n ],\n)",
        4,
        "(the lesson opened on the ziegler-1952 preset)",
    ),
    // A ramp to a load the column cannot take, as the window refuses it.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", preset: \"tabletop\",\n   run: Ramp(from: 1e300, to: 1.0, rate: 1.0)),\n ],\n)",
        4,
        "ramp from = 1e300",
    ),
    // A kick that throws the column, and one of nothing.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", run: KickBy(0.5)),\n ],\n)",
        4,
        "step 1: kick of 0.5 rad: expected a turn of each rod other than 0, at most 0.2 rad either way",
    ),
    // A number far from 1 in exponent form, not in 301 digits.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\", run: KickBy(1e300)),\n ],\n)",
        4,
        "step 1: kick of 1e300 rad: expected",
    ),
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\"),\n  Step(text: \"b\", run: KickBy(0.0)),\n ],\n)",
        5,
        "step 2: kick of 0 rad",
    ),
    // A tab the app has not, with the names it has.
    (
        "Lesson(\n title: \"t\",\n steps: [\n  Step(text: \"a\"),\n  Step(text: \"b\", tab: \"plots\"),\n ],\n)",
        5,
        "step 2: unknown tab 'plots': expected one of locus, histories, map, paradox",
    ),
];

/// A lesson file `lesson --check` refuses, as the window does: status 2
/// and one line naming the file, the line of the problem and what was
/// expected. Syntax and unknown fields, presets, keys and tabs; values the
/// column refuses at the step that sets them, from any preset the lesson
/// may be opened on; ramps the column cannot take; a key written twice; a
/// title that would reach a terminal as an escape sequence; `Step(` in a
/// string or comment.
#[test]
fn a_broken_lesson_file_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    for (i, &(text, line, says)) in BROKEN.iter().enumerate() {
        let path = dir.path().join(format!("case{i}.ron"));
        std::fs::write(&path, text).unwrap();
        let out = run_limited(&["lesson", "--check", path.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{text}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{text}: {stderr}");
        assert!(
            stderr.contains(&format!("line {line}: ")) && stderr.contains(says),
            "{text}: {stderr}"
        );
    }
}
