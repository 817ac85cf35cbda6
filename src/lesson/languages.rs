//! The built-in lessons in each language: English in `assets/lessons/`,
//! each translation under `assets/lessons/CODE/`, the same steps with
//! their words translated (a test holds every step's actions equal).

use super::BUILT_IN;
use crate::i18n::Language;

/// The translations, in `BUILT_IN`'s order.
const TRANSLATED: [(Language, [&str; 3]); 5] = [
    (
        Language::German,
        [
            include_str!("../../assets/lessons/de/where-flutter-starts.ron"),
            include_str!("../../assets/lessons/de/is-the-roller-a-follower.ron"),
            include_str!("../../assets/lessons/de/damping-paradox.ron"),
        ],
    ),
    (
        Language::Italian,
        [
            include_str!("../../assets/lessons/it/where-flutter-starts.ron"),
            include_str!("../../assets/lessons/it/is-the-roller-a-follower.ron"),
            include_str!("../../assets/lessons/it/damping-paradox.ron"),
        ],
    ),
    (
        Language::Polish,
        [
            include_str!("../../assets/lessons/pl/where-flutter-starts.ron"),
            include_str!("../../assets/lessons/pl/is-the-roller-a-follower.ron"),
            include_str!("../../assets/lessons/pl/damping-paradox.ron"),
        ],
    ),
    (
        Language::Spanish,
        [
            include_str!("../../assets/lessons/es/where-flutter-starts.ron"),
            include_str!("../../assets/lessons/es/is-the-roller-a-follower.ron"),
            include_str!("../../assets/lessons/es/damping-paradox.ron"),
        ],
    ),
    (
        Language::French,
        [
            include_str!("../../assets/lessons/fr/where-flutter-starts.ron"),
            include_str!("../../assets/lessons/fr/is-the-roller-a-follower.ron"),
            include_str!("../../assets/lessons/fr/damping-paradox.ron"),
        ],
    ),
];

/// The built-in lessons in `language`, (file name, text), in the order of
/// [`BUILT_IN`]: English for English and the pseudo-language.
#[must_use]
pub fn built_in(language: Language) -> [(&'static str, &'static str); 3] {
    let Some((_, texts)) = TRANSLATED.iter().find(|(l, _)| *l == language) else {
        return BUILT_IN;
    };
    let mut lessons = BUILT_IN;
    for (lesson, text) in lessons.iter_mut().zip(texts) {
        lesson.1 = text;
    }
    lessons
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lesson::{Lesson, Predict, Reveal};

    /// A lesson with every word taken out: what it does, step by step.
    fn actions(mut lesson: Lesson) -> Lesson {
        lesson.title.clear();
        for step in &mut lesson.steps {
            step.text.clear();
            step.predict = match step.predict.take() {
                Some(Predict::Load(_)) => Some(Predict::Load(String::new())),
                Some(Predict::Choice { answers, .. }) => Some(Predict::Choice {
                    prompt: String::new(),
                    answers: vec![String::new(); answers.len()],
                }),
                None => None,
            };
            if let Some(Reveal::Text(text)) = &mut step.reveal {
                text.clear();
            }
        }
        lesson
    }

    /// Every translation reads and does what the English lesson does, step
    /// for step: only its words differ, and they do differ.
    #[test]
    fn every_translated_lesson_does_what_the_english_one_does() {
        let tabs = crate::app::Tab::ids();
        for language in Language::CHOSEN_FROM {
            for ((name, english), (_, translated)) in BUILT_IN.iter().zip(built_in(language)) {
                let english = Lesson::read(english, &tabs).unwrap();
                let translated = Lesson::read(translated, &tabs)
                    .unwrap_or_else(|e| panic!("{language} {name}: {e}"));
                if language != Language::English {
                    assert_ne!(translated.title, english.title, "{language} {name}");
                }
                assert_eq!(actions(translated), actions(english), "{language} {name}");
            }
        }
        assert_eq!(built_in(Language::Pseudo), BUILT_IN);
    }
}
