//! The window in every language: each screen holds its text at 1024x768,
//! normal and projector, in each language and in the pseudo-language (40%
//! longer than English); the command line's pictures speak the language
//! asked for, or the system's.

use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use zieglerlab::app::{Action, Settings, Tab, ZieglerApp};
use zieglerlab::i18n::{Language, words};

use crate::common::output_within;

/// The languages a layout test goes through: every one offered, and the
/// pseudo-language.
fn every_language() -> impl Iterator<Item = Language> {
    Language::CHOSEN_FROM.into_iter().chain([Language::Pseudo])
}

/// What text in `harness` is out of place: a widget of the sidebar that
/// reaches into the central panel, or anything past the window's left or
/// right edge.
fn text_out_of_place(harness: &Harness<'_>, size: [f32; 2], language: Language) -> Vec<String> {
    // The central panel starts where the tab bar's first tab does.
    let central_left = harness
        .get_by_label(&Tab::Locus.title(words(language)))
        .rect()
        .left();
    let mut out = Vec::new();
    for node in harness.root().children_recursive() {
        if node.accesskit_node().bounding_box().is_none() {
            continue;
        }
        let rect = node.rect();
        let text = node.accesskit_node().label().or_else(|| node.value());
        let Some(text) = text.filter(|t| !t.trim().is_empty()) else {
            continue;
        };
        let in_sidebar = rect.left() < central_left;
        // Across only: what the sidebar and the tabs hold below the fold
        // is scrolled to.
        if rect.left() < 0.0 || rect.right() > size[0] + 0.5 {
            out.push(format!("{text:?} at {rect:?}: past the window's edge"));
        } else if in_sidebar && rect.right() > central_left + 0.5 {
            out.push(format!(
                "{text:?} at {rect:?}: from the sidebar into the central panel"
            ));
        }
    }
    out
}

/// Every tab, normal and projector, at 1024x768, in every language, and
/// every step of the first lesson on a projector (its buttons and its
/// card at the sidebar's foot): no text past the window's edges, none from
/// the sidebar into the central panel.
#[test]
fn every_language_fits_a_1024_window() {
    use zieglerlab::lesson::{Lesson, built_in};
    let size = [1024.0, 768.0];
    let mut problems = Vec::new();
    // Each tab with no lesson open, then the lesson's steps (1 to 4).
    let cases = Tab::all()
        .map(|tab| (tab, 0))
        .chain((1..=4).map(|step| (Tab::Locus, step)))
        .collect::<Vec<_>>();
    for language in every_language() {
        for projector in [false, true] {
            for &(tab, lesson_step) in &cases {
                let mut app = ZieglerApp::new(Settings {
                    projector,
                    ..Settings::default()
                })
                .unwrap();
                app.apply(Action::Language(language));
                if lesson_step > 0 {
                    let (_, text) = built_in(language)[0];
                    let lesson = Lesson::read(text, &Tab::ids()).unwrap();
                    app.apply(Action::LessonOpen(Box::new(lesson)));
                    for _ in 1..lesson_step {
                        app.apply(Action::Command(zieglerlab::app::Command::LessonNext));
                    }
                }
                app.show_tab(tab);
                app.complete_background_work(tab);
                let mut harness = Harness::builder()
                    .with_size(size)
                    .build_ui(|ui| app.contents_ui(ui));
                harness.run_steps(4);
                let at = format!(
                    "{language} {} lesson step {lesson_step} (projector {projector})",
                    tab.id()
                );
                let used = harness.ctx.globally_used_rect();
                if used.right() > size[0] + 0.5 {
                    problems.push(format!("{at}: drawn up to {used:?}"));
                }
                problems.extend(
                    text_out_of_place(&harness, size, language)
                        .into_iter()
                        .map(|p| format!("{at}: {p}")),
                );
                // The tab bar speaks the language.
                let title = tab.title(words(language));
                assert!(
                    harness.query_by_label(&title).is_some(),
                    "{at}: no tab titled {title:?}"
                );
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// The language menu lists every language by its own name and switches
/// the window at once.
#[test]
fn the_language_menu_switches_the_window() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut harness = Harness::builder()
        .with_size([1024.0, 768.0])
        .build_ui(|ui| app.contents_ui(ui));
    harness.run_steps(2);
    harness.get_by_label("language: English").click();
    harness.run_steps(2);
    harness.get_by_label("Polski").click();
    harness.run_steps(3);
    let polish = words(Language::Polish);
    assert!(harness.query_by_label(&Tab::Map.title(polish)).is_some());
    assert!(
        harness
            .query_by_label(&Tab::Map.title(words(Language::English)))
            .is_none()
    );
    drop(harness);
    assert_eq!(app.state().language(), Language::Polish);
    assert_eq!(
        app.layout().language.as_deref(),
        Some("pl"),
        "the choice is stored"
    );
}

/// A value refused in a field is said in the window's language, and in
/// the new one once the language changes (the refusal is kept as data):
/// the same reason, word for word, as the library words it.
#[test]
fn a_refusal_beside_a_field_follows_the_language() {
    use zieglerlab::model::{Allowed, Key, ModelError, Subject};
    let refusal = |language| {
        let why = zieglerlab::i18n::model_error(
            words(language),
            &ModelError::Invalid {
                subject: Subject::Key(Key::Nu),
                value: -1.0,
                allowed: Allowed::KeyRange(Key::Nu),
            },
        );
        zieglerlab::i18n::words(language).with(
            "refused",
            &[("why", zieglerlab::i18n::FluentValue::from(why))],
        )
    };
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Language(Language::Polish));
    let mut harness = crate::app_input::harness_at(&mut app, [1024.0, 768.0]);
    crate::app_input::type_into(&mut harness, "nu", "-1");
    harness.key_press(eframe::egui::Key::Enter);
    harness.run_steps(2);
    let polish = refusal(Language::Polish);
    assert!(polish.contains("musi być"), "{polish}");
    harness.get_by_label(&polish);
    harness.get_by_label("język: Polski").click();
    harness.run_steps(2);
    harness.get_by_label("Deutsch").click();
    harness.run_steps(3);
    let german = refusal(Language::German);
    assert!(german.contains("muss"), "{german}");
    harness.get_by_label(&german);
    assert!(harness.query_by_label(&polish).is_none());
}

/// The binary run on `args`, then `--out DIR/NAME`, with the locale
/// variables `env` set and every other one unset: the file it wrote.
fn written_by(dir: &std::path::Path, name: &str, args: &[&str], env: &[(&str, &str)]) -> Vec<u8> {
    let out = dir.join(name);
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_zieglerlab"));
    command.args(args).arg("--out").arg(&out);
    for var in ["LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"] {
        command.env_remove(var);
    }
    command.envs(env.iter().copied());
    let output = output_within(
        &mut command,
        std::time::Duration::from_mins(5),
        name,
        "the binary runs",
    );
    assert!(output.status.success(), "{name}: {output:?}");
    std::fs::read(out).unwrap()
}

/// A picture from the command line: with `--lang`, or in the system's
/// language (`LANG` when `LC_ALL` is unset; English when `LC_ALL=C`
/// overrides it).
#[test]
fn pictures_speak_the_language_asked_for_or_the_system_s() {
    let dir = tempfile::tempdir().unwrap();
    let picture = |name: &str, lang: Option<&str>, env: &[(&str, &str)]| {
        let mut args = vec!["snapshot", "--preset", "tabletop", "--size", "1024x768"];
        if let Some(lang) = lang {
            args.extend(["--lang", lang]);
        }
        written_by(dir.path(), &format!("{name}.png"), &args, env)
    };
    let german = picture("de", Some("de"), &[]);
    let english = picture("en", Some("en"), &[]);
    assert_ne!(german, english);
    assert_eq!(picture("lang", None, &[("LANG", "de_DE.UTF-8")]), german);
    assert_eq!(
        picture("c", None, &[("LC_ALL", "C"), ("LANG", "de_DE.UTF-8")]),
        english
    );
    // --lang wins over the system's.
    assert_eq!(
        picture("over", Some("en"), &[("LANG", "de_DE.UTF-8")]),
        english
    );
}

/// A built-in lesson follows the window's language: opened in Italian it
/// reads in Italian, and a switch to French mid-lesson goes on in French
/// at the same step.
#[test]
fn a_lesson_speaks_the_window_s_language() {
    use zieglerlab::app::Command;
    use zieglerlab::lesson::{Lesson, built_in};
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Language(Language::Italian));
    let (_, text) = built_in(Language::Italian)[0];
    let lesson = Lesson::read(text, &Tab::ids()).unwrap();
    app.apply(Action::LessonOpen(Box::new(lesson)));
    app.apply(Action::Command(Command::LessonNext));
    let step = |app: &ZieglerApp| {
        let run = app.state().lesson().unwrap();
        (run.step, run.lesson.title.clone())
    };
    assert_eq!(step(&app).1, "Dove inizia il flutter della colonna?");
    app.apply(Action::Language(Language::French));
    assert_eq!(
        step(&app),
        (1, "Où la colonne commence-t-elle à flotter ?".to_owned())
    );
    let mut harness = Harness::builder()
        .with_size([1024.0, 768.0])
        .build_ui(|ui| app.contents_ui(ui));
    harness.run_steps(3);
    assert!(
        harness
            .query_by_label_contains("Nous allons augmenter la charge")
            .is_some(),
        "the French step's text"
    );
    let next = words(Language::French).get("lesson-next");
    assert!(
        harness.query_by_label(&next).is_some(),
        "the step buttons in French"
    );
}

/// A figure's axes and legend in the language asked for; English unless
/// asked, whatever the system's; so too a map's PNG.
#[test]
fn a_figure_speaks_the_language_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let figure = |lang: Option<&str>| {
        let mut args = vec!["figure", "--preset", "ziegler-1952", "--kind", "re-im"];
        if let Some(lang) = lang {
            args.extend(["--lang", lang]);
        }
        let name = format!("{}.svg", lang.unwrap_or("none"));
        let svg = written_by(dir.path(), &name, &args, &[("LANG", "de_DE.UTF-8")]);
        String::from_utf8(svg).unwrap()
    };
    let german = figure(Some("de"));
    assert!(
        german.contains("stabil zu Flattern"),
        "the legend in German"
    );
    assert!(!german.contains("stable to flutter"));
    let english = figure(None);
    assert!(english.contains("stable to flutter"), "English by default");
    // A map's PNG too.
    let map = |lang: &str| {
        let args = [
            "map",
            "--preset",
            "tabletop",
            "--x",
            "load:0:8:8",
            "--y",
            "c2:0:0.1:4",
            "--format",
            "png",
            "--lang",
            lang,
        ];
        written_by(dir.path(), &format!("map-{lang}.png"), &args, &[])
    };
    assert_ne!(map("de"), map("en"), "the map's key in German");
}

/// The first launch's welcome offers every language before anything else
/// (the card is modal: the status line's menu is out of reach behind it).
#[test]
fn the_welcome_offers_every_language() {
    let mut app = ZieglerApp::from_storage(None);
    let mut harness = Harness::builder()
        .with_size([1024.0, 768.0])
        .build_ui(|ui| app.contents_ui(ui));
    harness.run_steps(2);
    for language in Language::CHOSEN_FROM {
        assert!(
            harness.query_by_label(language.endonym()).is_some(),
            "{language}"
        );
    }
    harness.get_by_label("Deutsch").click();
    harness.run_steps(3);
    let title = words(Language::German).get("welcome-title");
    assert!(
        harness.query_by_label(&title).is_some(),
        "the welcome in German"
    );
    drop(harness);
    assert_eq!(app.layout().language.as_deref(), Some("de"));
}
