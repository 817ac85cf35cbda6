//! Lessons driven as a presenter drives them (`egui_kittest`): Page Down and
//! Page Up through the steps, a lesson file typed into the window and read
//! off the UI thread.

use crate::common::message_line;
use eframe::egui;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use zieglerlab::app::{Settings, ZieglerApp};

use crate::app_input::{harness, type_into};

/// The default app's window at 1280x900, with its keys read each frame as
/// the real window reads them.
pub(crate) fn keyed_harness() -> Harness<'static, ZieglerApp> {
    keyed_harness_with([1280.0, 900.0], Settings::default())
}

/// The window of `settings` at `size`, its keys read as in
/// [`keyed_harness`].
fn keyed_harness_with(size: [f32; 2], settings: Settings) -> Harness<'static, ZieglerApp> {
    Harness::builder().with_size(size).build_ui_state(
        |ui, app: &mut ZieglerApp| {
            app.take_keys(ui.ctx());
            app.contents_ui(ui);
        },
        ZieglerApp::new(settings).unwrap(),
    )
}

/// The 1024x768 projector's window.
fn projector_harness() -> Harness<'static, ZieglerApp> {
    keyed_harness_with(
        [1024.0, 768.0],
        Settings {
            projector: true,
            ..Settings::default()
        },
    )
}

/// A presenter's remote sends Page Down and Page Up: they move through the
/// lesson's steps, carrying each out, and do nothing without a lesson.
#[test]
fn page_down_and_page_up_step_through_a_lesson() {
    let mut harness = keyed_harness();
    harness.run();
    harness.key_press(egui::Key::PageDown);
    harness.run();
    assert!(harness.state().state().lesson().is_none());
    let (_, text) = zieglerlab::lesson::BUILT_IN[0];
    let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    harness
        .state_mut()
        .apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
    harness.run();
    let step = |h: &Harness<'_, ZieglerApp>| h.state().state().lesson().unwrap().step;
    assert_eq!(step(&harness), 0);
    harness.key_press(egui::Key::PageDown);
    harness.run();
    assert_eq!(step(&harness), 1);
    harness.key_press(egui::Key::PageDown);
    harness.run();
    assert_eq!(step(&harness), 2);
    assert!(
        harness.state().state().ramp().is_some(),
        "step 3 starts its ramp"
    );
    harness.key_press(egui::Key::PageUp);
    harness.run();
    assert_eq!(step(&harness), 1);
}

/// A lesson path typed into the window is read off the UI thread: a device
/// that never ends is refused by name (the window froze at 2.2 GB on it),
/// and a lesson file then opens at its first step.
#[test]
fn a_lesson_file_is_read_off_the_ui_thread_and_checked() {
    let folder = tempfile::tempdir().unwrap();
    let good = folder.path().join("mine.ron");
    std::fs::write(
        &good,
        "\u{feff}Lesson(title: \"Mine\", steps: [Step(text: \"look\", preset: \"tabletop\")])",
    )
    .unwrap();
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut harness = harness(&mut app);
    harness.get_by_label("lessons").click();
    harness.run();
    let open = |harness: &mut Harness<'_>, path: &str| {
        type_into(harness, "lesson file", path);
        harness.get_by_label("open").click();
        // Frames until the reading thread has answered (a fixed number each
        // time: the thread's answer may ask for frames while `run` waits
        // for the window to settle, and on a busy machine `run` gave up).
        for _ in 0..200 {
            harness.run_steps(3);
            if harness.query_by_label_contains("reading ").is_none() {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        harness.run();
    };
    open(&mut harness, "/dev/zero");
    assert!(
        harness
            .query_by_label_contains("cannot read /dev/zero: it is a device, a pipe or a socket")
            .is_some()
    );
    open(&mut harness, good.to_str().unwrap());
    assert!(harness.query_by_label_contains("step 1 of 1").is_some());
    drop(harness);
    assert_eq!(app.settings().preset, zieglerlab::model::PresetId::Tabletop);
}

/// Every step of every built-in lesson on a 1024x768 projector: the scene,
/// the load bar and the tab bar stay in their rows (a step that hides the
/// root locus once pulled the load bar and the tabs up over the column),
/// and the step's preset and load are those the lesson sets there.
#[test]
fn every_lesson_step_keeps_the_projector_layout() {
    use egui_kittest::kittest::Queryable as _;
    for &(name, text) in &zieglerlab::lesson::BUILT_IN {
        let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
        let steps = lesson.steps.len();
        let start = zieglerlab::lesson::Column {
            preset: zieglerlab::model::PresetId::Roller,
            model: zieglerlab::model::PresetId::Roller.model(),
        };
        let mut harness = projector_harness();
        harness
            .state_mut()
            .apply(zieglerlab::app::Action::LessonOpen(Box::new(
                lesson.clone(),
            )));
        let asked = lesson.steps.iter().position(|s| s.predict.is_some());
        let revealed = lesson.steps.iter().position(|s| s.reveal.is_some());
        let mut tab = zieglerlab::app::Tab::Locus;
        for step in 0..steps {
            if step > 0 {
                harness.state_mut().apply(zieglerlab::app::Action::Command(
                    zieglerlab::app::Command::LessonNext,
                ));
            }
            harness.run_steps(3);
            let at = format!("{name} step {}", step + 1);
            // The tab the lesson last opened is the one shown.
            if let Some(id) = &lesson.steps[step].tab {
                tab = zieglerlab::app::Tab::named(id).unwrap();
            }
            assert_eq!(harness.state().layout().tab, tab, "{at}");
            // Hidden from the prediction to the reveal: no critical load
            // on the screen then, and the verdict's words instead.
            let hidden = asked.is_some_and(|a| step >= a && revealed.is_none_or(|r| step < r));
            assert_eq!(harness.state().state().answer_hidden(), hidden, "{at}");
            let critical_shown = harness.query_by_label_contains("-> flutter").is_some();
            assert_eq!(
                critical_shown, !hidden,
                "{at}: a critical load on the screen"
            );
            assert_eq!(
                harness.query_by_label("stable or not?").is_some(),
                hidden,
                "{at}: the card's verdict hidden"
            );
            // The lesson's buttons, time's and the card stay in view at the
            // sidebar's foot, above the status line, however long the
            // step's text (it scrolls above them).
            let in_view = 768.0 - 1.6 * 22.0;
            let card = if hidden {
                harness.get_by_label("stable or not?")
            } else {
                harness.get_by_label_contains("growth rate")
            };
            for (what, rect) in [
                ("kick", harness.get_by_label("kick").rect()),
                ("close lesson", harness.get_by_label("close lesson").rect()),
                ("the card", card.rect()),
            ] {
                assert!(
                    rect.top() > 0.0 && rect.bottom() < in_view,
                    "{at}: {what} at {rect:?}"
                );
            }
            let tab_top = harness.get_by_label("time histories").rect().top();
            assert!(
                tab_top > 0.55 * 768.0,
                "{name} step {}: the tab bar is at y = {tab_top}, over the scene",
                step + 1
            );
            // A step that opens the paradox tab shows its curves on the
            // screen (on the projector they were "need a taller window").
            if lesson.steps[step].tab.as_deref() == Some("paradox") {
                let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1024.0, 768.0));
                let controls = harness
                    .get_by_label_contains("damping that vanishes")
                    .rect();
                assert!(
                    screen.contains_rect(controls),
                    "{name} step {}: the paradox tab at {controls:?}",
                    step + 1
                );
            }
            if lesson.steps[step].sets_column() {
                let column = lesson.column_at(start, step).unwrap();
                let settings = harness.state().settings();
                assert_eq!(settings.preset, column.preset, "{name} step {}", step + 1);
                assert!(
                    (settings.model.load_p() - column.model.load_p()).abs() < 1e-12,
                    "{name} step {}",
                    step + 1
                );
            }
        }
    }
}

/// A first launch greets a student in plain words and offers the first
/// lesson: one click starts it, or closes the welcome for good; a launch
/// with stored settings and a picture show no welcome.
#[test]
fn a_first_launch_welcomes_and_offers_the_first_lesson() {
    use egui_kittest::kittest::Queryable as _;
    let shown = |app: ZieglerApp| {
        let mut harness = Harness::builder()
            .with_size([1024.0, 768.0])
            .build_ui_state(|ui, app: &mut ZieglerApp| app.contents_ui(ui), app);
        harness.run_steps(2);
        harness
            .query_by_label_contains("Welcome to zieglerlab")
            .is_some()
    };
    assert!(shown(ZieglerApp::from_stored_text(None)));
    let stored = Settings::default().to_text();
    assert!(!shown(ZieglerApp::from_stored_text(Some(&stored))));
    let mut picture = ZieglerApp::from_stored_text(None);
    picture.draw_for_pictures();
    assert!(!shown(picture));

    for (button, lesson_open) in [
        ("start the first lesson", true),
        ("explore on my own", false),
    ] {
        let mut harness = Harness::builder()
            .with_size([1024.0, 768.0])
            .build_ui_state(
                |ui, app: &mut ZieglerApp| app.contents_ui(ui),
                ZieglerApp::from_stored_text(None),
            );
        harness.run_steps(2);
        harness.get_by_label(button).click();
        harness.run_steps(3);
        assert!(
            harness
                .query_by_label_contains("Welcome to zieglerlab")
                .is_none(),
            "{button}"
        );
        assert_eq!(
            harness.state().state().lesson().is_some(),
            lesson_open,
            "{button}"
        );
    }
}

/// F11 (the full-screen key a presenter reaches for) asks the window to
/// fill the screen, once per press; the keys help lists it. (Leaving reads
/// the window's own report of full screen, which a headless harness does
/// not give. The harness runs a frame per key event, so the command is
/// applied as the key's action and its frame's output read.)
#[test]
fn f11_asks_for_full_screen() {
    use zieglerlab::app::{Action, Command};
    let full_screen = Command::ALL
        .into_iter()
        .find(|c| c.keys() == [egui::Key::F11])
        .expect("a command on F11");
    assert_eq!(full_screen, Command::FullScreen);
    let mut harness = Harness::builder()
        .with_size([1024.0, 768.0])
        .build_ui_state(
            |ui, app: &mut ZieglerApp| app.contents_ui(ui),
            ZieglerApp::new(Settings::default()).unwrap(),
        );
    harness.run();
    harness
        .state_mut()
        .apply(Action::Command(Command::FullScreen));
    harness.step();
    let asked: Vec<bool> = harness
        .output()
        .viewport_output
        .values()
        .flat_map(|output| &output.commands)
        .filter_map(|command| match command {
            egui::ViewportCommand::Fullscreen(on) => Some(*on),
            _ => None,
        })
        .collect();
    assert_eq!(asked, vec![true]);
    harness.step();
    assert!(
        harness
            .output()
            .viewport_output
            .values()
            .all(|output| output.commands.is_empty()),
        "asked once per press"
    );
}

/// The last step of "Is the roller a follower force?" shows the strong
/// flutter at p = 3, and its reveal says that, from the theory at the load
/// shown (it revealed "unstable from p = 0.0238", the weak onset of the
/// step before): flutter, and the swing's doubling time, ln 2 over the
/// growth rate of the spectrum at p = 3.
#[test]
fn the_roller_lesson_s_last_reveal_says_what_the_step_shows() {
    let (_, text) = zieglerlab::lesson::BUILT_IN
        .iter()
        .find(|(name, _)| *name == "is-the-roller-a-follower.ron")
        .expect("the lesson");
    let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    let steps = lesson.steps.len();
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
    for _ in 1..steps {
        app.apply(zieglerlab::app::Action::Command(
            zieglerlab::app::Command::LessonNext,
        ));
    }
    let state = app.state();
    assert!((state.model().load_p() - 3.0).abs() < 1e-12);
    let spectrum = state.current_spectrum().unwrap();
    let stability = zieglerlab::analysis::classify(&spectrum.eigenvalues, spectrum.scale_per_s);
    assert_eq!(stability.state, zieglerlab::analysis::State::Flutter);
    let doubling = std::f64::consts::LN_2 / stability.growth_rate_per_s();
    let said = state
        .lesson()
        .unwrap()
        .reveal_text(
            None,
            state.load_max(),
            None,
            Some((3.0, &stability)),
            zieglerlab::i18n::words(zieglerlab::i18n::Language::English),
        )
        .unwrap();
    let expected = format!(
        "The theory at p = {}: flutter: the swing doubles every {} s",
        zieglerlab::format::load_text(3.0),
        zieglerlab::format::secs_text(doubling)
    );
    assert!(said.starts_with(&expected), "{said} / {expected}");
    assert!(!said.contains("0.0238"), "{said}");
    // And the window shows the same words at that step.
    let mut harness = harness(&mut app);
    harness.run();
    harness.get_by_label_contains(&expected);
}

/// A choice's reveal reads differently for a right and a wrong answer, in
/// words as well as in colour (it was the same red sentence for both).
#[test]
fn a_right_and_a_wrong_answer_are_revealed_differently() {
    let (_, text) = zieglerlab::lesson::BUILT_IN
        .iter()
        .find(|(name, _)| *name == "is-the-roller-a-follower.ron")
        .expect("the lesson");
    let mut said = Vec::new();
    for (choice, verdict) in [(2, true), (0, false)] {
        let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
        let mut app = ZieglerApp::new(Settings::default()).unwrap();
        app.apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
        app.apply(zieglerlab::app::Action::Command(
            zieglerlab::app::Command::LessonNext,
        ));
        app.apply(zieglerlab::app::Action::LessonChoose(choice));
        app.apply(zieglerlab::app::Action::Command(
            zieglerlab::app::Command::LessonNext,
        ));
        let run = app.state().lesson().unwrap();
        assert_eq!(run.verdict(), Some(verdict));
        let text = run
            .reveal_text(
                None,
                8.0,
                None,
                None,
                zieglerlab::i18n::words(zieglerlab::i18n::Language::English),
            )
            .unwrap();
        let mut harness = harness(&mut app);
        harness.run();
        harness.get_by_label(&text);
        said.push(text);
    }
    assert!(
        said[0].starts_with("Right: you chose \"at a much lower load\""),
        "{}",
        said[0]
    );
    assert!(
        said[1].starts_with("Not this one: you chose \"at a higher load"),
        "{}",
        said[1]
    );
}

/// "reset all" during a lesson's ramp step ends the lesson, and says so:
/// it left the step saying "watch the load rise" with the ramp gone.
#[test]
fn reset_all_during_a_ramp_step_closes_the_lesson() {
    let (_, text) = zieglerlab::lesson::BUILT_IN[0];
    let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    let title = lesson.title.clone();
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
    for _ in 0..2 {
        app.apply(zieglerlab::app::Action::Command(
            zieglerlab::app::Command::LessonNext,
        ));
    }
    assert!(app.state().ramp().is_some(), "the ramp step");
    let mut harness = harness(&mut app);
    assert!(
        harness
            .query_by_label_contains("as the load rises")
            .is_some()
    );
    harness.get_by_label("reset all").click();
    harness.run();
    assert!(
        harness
            .query_by_label_contains("as the load rises")
            .is_none()
    );
    drop(harness);
    assert!(app.state().lesson().is_none());
    assert!(app.state().ramp().is_none());
    let said = message_line(&app);
    assert!(
        said.contains(&format!("the lesson \"{title}\" is closed")),
        "{said}"
    );
}

/// Past a lesson's last step, Page Down opens the next built-in lesson at
/// its first step, and the sidebar offers it by name; after the last
/// lesson, Page Down says how to go on.
#[test]
fn page_down_after_the_last_step_opens_the_next_lesson() {
    let tabs = zieglerlab::app::Tab::ids();
    let lessons: Vec<zieglerlab::lesson::Lesson> = zieglerlab::lesson::BUILT_IN
        .iter()
        .map(|(_, text)| zieglerlab::lesson::Lesson::read(text, &tabs).unwrap())
        .collect();
    let mut harness = keyed_harness();
    harness.run_steps(8);
    harness
        .state_mut()
        .apply(zieglerlab::app::Action::LessonOpen(Box::new(
            lessons[0].clone(),
        )));
    harness.run_steps(8);
    for _ in 1..lessons[0].steps.len() {
        harness.key_press(egui::Key::PageDown);
        harness.run_steps(8);
    }
    let run = |h: &Harness<'_, ZieglerApp>| {
        let run = h.state().state().lesson().unwrap();
        (run.lesson.title.clone(), run.step)
    };
    assert_eq!(
        run(&harness),
        (lessons[0].title.clone(), lessons[0].steps.len() - 1)
    );
    harness.get_by_label(&format!("next lesson: {}", lessons[1].title));
    harness.key_press(egui::Key::PageDown);
    harness.run_steps(8);
    assert_eq!(run(&harness), (lessons[1].title.clone(), 0));
    // The last lesson's last step: Page Down stays and says how to go on.
    let last = lessons.last().unwrap();
    harness
        .state_mut()
        .apply(zieglerlab::app::Action::LessonOpen(Box::new(last.clone())));
    for _ in 1..last.steps.len() {
        harness.key_press(egui::Key::PageDown);
        harness.run_steps(8);
    }
    harness.key_press(egui::Key::PageDown);
    harness.run_steps(8);
    assert_eq!(run(&harness), (last.title.clone(), last.steps.len() - 1));
    let said = message_line(harness.state());
    assert!(said.contains("this was the lesson's last step"), "{said}");
}

/// Under the tab bar, one reason a line: during a lesson's predict step in
/// projector mode at 1024x768 with the time histories open (shown in the
/// column's place, not hidden), the note says where the tab is, and not
/// that "the plots are hidden ...; they need a taller window".
#[test]
fn the_note_under_the_tabs_gives_one_reason() {
    let (_, text) = zieglerlab::lesson::BUILT_IN[0];
    let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    let mut app = ZieglerApp::new(Settings {
        projector: true,
        ..Settings::default()
    })
    .unwrap();
    app.apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
    app.apply(zieglerlab::app::Action::Command(
        zieglerlab::app::Command::LessonNext,
    ));
    assert!(
        app.state().answer_hidden(),
        "the predict step hides the answer"
    );
    app.apply(zieglerlab::app::Action::Tab(
        zieglerlab::app::Tab::Histories,
    ));
    let harness = crate::app_input::harness_at(&mut app, [1024.0, 768.0]);
    harness.get_by_label_contains("The time histories tab shows in the column's place");
    assert!(
        harness
            .query_by_label_contains("they need a taller window")
            .is_none()
    );
    assert!(
        harness
            .query_by_label_contains("The plots are hidden")
            .is_none()
    );
}

/// Presses Tab until the focused node is one `wanted` picks, a frame after
/// each press (as xdotool types); fails naming `at` if none comes within a
/// round of the whole window.
fn tab_to(
    harness: &mut Harness<'static, ZieglerApp>,
    wanted: impl Fn(&egui::accesskit::Role, &str) -> bool,
    at: &str,
) {
    for _ in 0..300 {
        harness.key_press(egui::Key::Tab);
        harness.run_steps(2);
        let found = harness
            .query_by(|node| {
                node.is_focused() && wanted(&node.role(), &node.label().unwrap_or_default())
            })
            .is_some();
        if found {
            return;
        }
    }
    panic!("{at}: Tab never reached the control");
}

/// Every built-in lesson run start to end by keyboard alone, no pointer
/// event: Tab to the prediction slider or the choice, the arrows or space
/// to answer, and Page Down at once after (a focused control once held back
/// every shortcut until Escape).
#[test]
fn every_lesson_runs_by_keyboard_alone() {
    use egui::accesskit::Role;
    use zieglerlab::lesson::Predict;
    for &(name, text) in &zieglerlab::lesson::BUILT_IN {
        let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
        let mut harness = keyed_harness();
        harness.run_steps(2);
        harness
            .state_mut()
            .apply(zieglerlab::app::Action::LessonOpen(Box::new(
                lesson.clone(),
            )));
        harness.run_steps(2);
        let run = |h: &Harness<'_, ZieglerApp>| h.state().state().lesson().unwrap().clone();
        for (k, step) in lesson.steps.iter().enumerate() {
            let at = format!("{name} step {}", k + 1);
            assert_eq!(run(&harness).step, k, "{at}");
            match &step.predict {
                Some(Predict::Load(_)) => {
                    tab_to(
                        &mut harness,
                        |role, label| *role == Role::Slider && label == "predicted load",
                        &at,
                    );
                    let load_max = harness.state().state().load_max();
                    // Three coarse steps and one fine one back: 0.29 of the bar.
                    for _ in 0..3 {
                        harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::ArrowRight);
                        harness.run_steps(2);
                    }
                    harness.key_press(egui::Key::ArrowLeft);
                    harness.run_steps(2);
                    let predicted = run(&harness).predicted_load.expect("a prediction");
                    assert!(
                        (predicted - 0.29 * load_max).abs() < 1e-9 * load_max,
                        "{at}: {predicted} on a bar to {load_max}"
                    );
                }
                Some(Predict::Choice { answers, .. }) => {
                    let last = answers.last().unwrap().clone();
                    tab_to(
                        &mut harness,
                        |role, label| *role == Role::RadioButton && label == last,
                        &at,
                    );
                    harness.key_press(egui::Key::Space);
                    harness.run_steps(2);
                    assert_eq!(run(&harness).chosen, Some(answers.len() - 1), "{at}");
                }
                None => {
                    // Any control focused, used or not, lets Page Down by.
                    tab_to(&mut harness, |role, _| *role == Role::Button, &at);
                }
            }
            if k + 1 < lesson.steps.len() {
                harness.key_press(egui::Key::PageDown);
                harness.run_steps(2);
                assert_eq!(run(&harness).step, k + 1, "{at}: Page Down after a control");
            }
        }
    }
}

/// The load bar takes the focus and its keys: right and left by a hundredth
/// of the bar, shift for a tenth, home and end; up and down move the load
/// whatever is focused; space plays with the bar focused and presses a
/// focused button instead of playing.
#[test]
fn the_load_bar_is_a_control_of_the_keyboard() {
    use egui::accesskit::Role;
    let mut harness = keyed_harness();
    harness.run_steps(2);
    tab_to(
        &mut harness,
        |role, label| *role == Role::Slider && label == "load slider",
        "the load bar",
    );
    let load = |h: &Harness<'_, ZieglerApp>| h.state().settings().model.load_p();
    let load_max = harness.state().state().load_max();
    harness.key_press(egui::Key::Home);
    harness.run_steps(2);
    assert_eq!(load(&harness), 0.0);
    harness.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::ArrowRight);
    harness.run_steps(2);
    harness.key_press(egui::Key::ArrowRight);
    harness.run_steps(2);
    assert!((load(&harness) - 0.11 * load_max).abs() < 1e-9 * load_max);
    // Still focused: the arrows did not move the focus on.
    assert!(
        harness
            .get_by_role_and_label(Role::Slider, "load slider")
            .is_focused()
    );
    harness.key_press(egui::Key::ArrowUp);
    harness.run_steps(2);
    assert!((load(&harness) - 0.12 * load_max).abs() < 1e-9 * load_max);
    harness.key_press(egui::Key::End);
    harness.run_steps(2);
    assert_eq!(load(&harness), load_max);
    let running = harness.state().state().running();
    harness.key_press(egui::Key::Space);
    harness.run_steps(2);
    assert_ne!(harness.state().state().running(), running, "space plays");
}

/// Ctrl+Tab and Ctrl+Shift+Tab go round the tabs, whatever is focused
/// but a text field.
#[test]
fn ctrl_tab_goes_round_the_tabs() {
    use zieglerlab::app::Tab;
    let mut harness = keyed_harness();
    harness.run();
    let tab = |h: &Harness<'_, ZieglerApp>| h.state().layout().tab;
    assert_eq!(tab(&harness), Tab::Locus);
    harness.key_press_modifiers(egui::Modifiers::CTRL, egui::Key::Tab);
    harness.run_steps(2);
    assert_eq!(tab(&harness), Tab::Histories);
    let back = egui::Modifiers::CTRL | egui::Modifiers::SHIFT;
    for _ in 0..2 {
        harness.key_press_modifiers(back, egui::Key::Tab);
        harness.run_steps(2);
    }
    assert_eq!(tab(&harness), Tab::PostCritical, "round the first tab");
}

/// The stability map by keys alone: Tab to it, Enter takes the point under
/// the cross at the view's centre, an arrow pans the view by a tenth of
/// its width, so the next Enter takes a load that much larger.
#[test]
fn a_map_cell_is_picked_by_keys() {
    use egui::accesskit::Role;
    let mut harness = keyed_harness();
    harness
        .state_mut()
        .apply(zieglerlab::app::Action::Tab(zieglerlab::app::Tab::Map));
    harness.run_steps(3);
    tab_to(
        &mut harness,
        |role, label| {
            *role == Role::Image && label.starts_with("plot: ") && label.contains("against p")
        },
        "the map",
    );
    let load = |h: &Harness<'_, ZieglerApp>| h.state().settings().model.load_p();
    // Enter, then frames past egui's double-click wait (the map waits to
    // tell a click from a double click, which fits the view).
    let pick = |h: &mut Harness<'static, ZieglerApp>| {
        h.key_press(egui::Key::Enter);
        h.run_steps(40);
    };
    pick(&mut harness);
    let first = load(&harness);
    harness.key_press(egui::Key::ArrowRight);
    harness.run_steps(2);
    pick(&mut harness);
    let second = load(&harness);
    // The map's load axis runs 0 to 8 (a little margin around it).
    let moved = second - first;
    assert!((0.78..1.0).contains(&moved), "{first} -> {second}");
}

/// In a 1024x768 projector lesson, every control Tab reaches is on the
/// screen when it has the focus (twelve presses in a row once landed on
/// controls scrolled out of the sidebar's view).
#[test]
fn tab_keeps_the_focused_control_in_view() {
    let (_, text) = zieglerlab::lesson::BUILT_IN[0];
    let lesson = zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    let mut harness = projector_harness();
    harness
        .state_mut()
        .apply(zieglerlab::app::Action::LessonOpen(Box::new(lesson)));
    harness.run_steps(3);
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1024.0, 768.0));
    let mut seen = Vec::new();
    for press in 0..40 {
        harness.key_press(egui::Key::Tab);
        // Frames for the scroll's animation.
        harness.run_steps(20);
        #[expect(
            clippy::redundant_closure_for_method_calls,
            reason = "the method alone is not general enough over the node's lifetime"
        )]
        let Some(node) = harness.query_by(|node| node.is_focused()) else {
            continue;
        };
        let rect = node.rect();
        let name = format!("{:?}", node.accesskit_node().label());
        assert!(
            screen.expand(1.0).contains_rect(rect),
            "press {}: {name} at {rect:?}",
            press + 1
        );
        seen.push(name);
    }
    seen.dedup();
    assert!(seen.len() > 15, "Tab reached only {seen:?}");
    // In the order they are seen: the sidebar's controls, then its foot
    // (the foot came right after the heading, before the model).
    let first = |name: &str| {
        seen.iter()
            .position(|s| s == &format!("{:?}", Some(name)))
            .unwrap_or_else(|| panic!("{name} not reached: {seen:?}"))
    };
    assert!(first("model") < first("next"), "{seen:?}");
    assert!(first("next") < first("pause"), "{seen:?}");
    assert!(first("pause") < first("the column"), "{seen:?}");
}
