//! The app's logic without a window: the simulation follows the wall clock
//! at the chosen speed with a cap per frame, engines switch when they must,
//! the analysis follows the newest parameters, map picks and lessons set
//! the column they say. (Stored and pasted settings: `stored_settings.rs`.)

use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Action, Command, MAX_FRAME_SECS, Settings, ZieglerApp};
use zieglerlab::model::{Axis, Key, PresetId};
use zieglerlab::sim::{DEFAULT_STEP_SECS, EngineKind, Status};

#[test]
fn simulation_follows_the_clock_at_the_chosen_speed() {
    let mut app = ZieglerApp::new(Settings {
        speed: 4.0,
        ..Settings::default()
    })
    .unwrap();
    for _ in 0..60 {
        app.advance(1.0 / 60.0);
    }
    let t = app.simulation().time_secs();
    assert!((t - 4.0).abs() <= 2.0 * DEFAULT_STEP_SECS, "{t}");
}

#[test]
fn a_stalled_frame_advances_at_most_the_cap() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.advance(5.0);
    let t = app.simulation().time_secs();
    assert!(
        (MAX_FRAME_SECS - 2.0 * DEFAULT_STEP_SECS..=MAX_FRAME_SECS + DEFAULT_STEP_SECS)
            .contains(&t),
        "{t}"
    );
}

/// The clock, with injected frame times: at "1.00 x speed" the run keeps
/// the wall clock's time whatever the frame rate, to within one step.
#[test]
fn the_run_keeps_real_time_at_any_frame_rate() {
    for (fps, frames) in [(240.0, 2400), (60.0, 600), (23.0, 230), (7.0, 70)] {
        let mut app = ZieglerApp::new(Settings::default()).unwrap();
        for _ in 0..frames {
            app.advance(1.0 / fps);
        }
        let wall = f64::from(frames) / fps;
        let t = app.simulation().time_secs();
        assert!(
            (t - wall).abs() <= DEFAULT_STEP_SECS,
            "{fps} fps: t = {t} after {wall} s"
        );
    }
}

/// A column too stiff for rapier's step runs on the reference engine, and
/// the app says so; the model change is not refused.
#[test]
fn a_column_too_stiff_for_rapier_switches_engines_and_says_so() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    assert_eq!(app.simulation().engine(), EngineKind::Rapier);
    crate::common::enter(&mut app, Key::C1, 1e6);
    assert_eq!(app.simulation().engine(), EngineKind::Reference);
    assert_eq!(app.settings().engine, EngineKind::Reference);
    assert_eq!(app.settings().model.column.c1_nms_per_rad, 1e6);
    assert!(
        app.message()
            .unwrap()
            .contains("switched to the reference engine")
    );
    for _ in 0..30 {
        app.advance(1.0 / 60.0);
    }
    assert!(app.simulation().time_secs() > 0.45);
    assert_eq!(app.simulation().status(), Status::Running);
}

/// A run that blows up stops with a status and keeps its last finite state.
#[test]
fn a_blow_up_stops_with_a_status_and_finite_data() {
    let mut app = ZieglerApp::new(Settings {
        preset: PresetId::Ziegler1952,
        model: PresetId::Ziegler1952.model(),
        ..Settings::default()
    })
    .unwrap();
    crate::common::enter(&mut app, Key::Load, 1e6);
    for _ in 0..120 {
        app.advance(1.0 / 60.0);
    }
    let sim = app.simulation();
    assert_ne!(sim.status(), Status::Running);
    assert!(sim.state().iter().all(|v| v.is_finite()));
    assert!(sim.time_secs() < 2.0);
}

#[test]
fn a_model_without_analysis_shows_no_stale_locus() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    assert!(app.state().analysis().is_some());
    // The band stops: the simulation goes on, the linear analysis cannot.
    crate::common::enter(&mut app, Key::V, 0.0);
    assert!(app.state().analysis().is_none());
    assert!(
        app.message().unwrap().contains("V = 0"),
        "{:?}",
        app.message()
    );
    app.advance(0.05);
    assert!(app.simulation().time_secs() > 0.0);
    {
        // The empty panel and the status card say why, where they are.
        let mut harness = egui_kittest::Harness::builder()
            .with_size([1280.0, 800.0])
            .build_ui(|ui| app.contents_ui(ui));
        harness.run();
        harness.get_by_label_contains("No root locus for these parameters: V = 0: must be > 0");
        harness.get_by_label_contains("no stability figures: V = 0");
    }
    // Moving the load at V = 0 is not a new failure each frame.
    app.apply(Action::DismissNotice);
    crate::common::enter(&mut app, Key::Load, 2.0);
    assert_eq!(app.message(), None);
    crate::common::enter(&mut app, Key::V, 0.1);
    assert!(app.state().analysis().is_some());
    assert!(app.state().analysis_failure().is_none());
}

/// A click on the stability map sets the load and the map's parameter, and
/// the running simulation follows; a value the model refuses says why.
#[test]
fn a_map_point_sets_both_parameters_and_the_run_follows() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::MapPick {
        axis: Axis::Key(Key::Nu),
        load: 3.0,
        value: 0.4,
    });
    let model = app.settings().model;
    assert!((model.load_p() - 3.0).abs() < 1e-12);
    assert!((Axis::Key(Key::Nu).get(&model) - 0.4).abs() < 1e-12);
    assert_eq!(app.simulation().model(), &model);
    app.apply(Action::MapPick {
        axis: Axis::Key(Key::Nu),
        load: 2.0,
        value: -1.0,
    });
    assert_eq!(app.settings().model, model);
    assert!(app.message().unwrap().contains("nu = -1"));
}

/// The inline analysis of the default parameters with nu set to `nu`.
fn inline_app(nu: f64) -> ZieglerApp {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    crate::common::enter(&mut app, Key::Nu, nu);
    app
}

/// The analysis thread gives what the inline analysis gives; parameters
/// dragged past are overtaken by the newest; the spectrum at the current
/// load is exact at once, before the locus is in.
#[test]
fn the_analysis_thread_follows_the_newest_parameters() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.state_mut().analyse_in_background();
    for nu in [0.2, 0.3] {
        crate::common::enter(&mut app, Key::Nu, nu);
    }
    let expected = inline_app(0.3);
    // Not waited for: the spectrum is already the new parameters'.
    assert_eq!(
        app.state().current_eigenvalues(),
        expected.state().current_eigenvalues()
    );
    app.state_mut().settle_analysis();
    assert!(!app.state().analysis_pending());
    let (got, want) = (app.state().analysis(), expected.state().analysis());
    assert_eq!(got.unwrap().transitions, want.unwrap().transitions);
    assert_ne!(
        want.unwrap().transitions,
        inline_app(0.2).state().analysis().unwrap().transitions,
        "nu must move the critical loads for this test to mean anything"
    );
}

/// Dragged away and back before the thread answers: its late answer for the
/// parameters left behind does not replace the analysis already shown.
#[test]
fn a_late_analysis_of_parameters_left_behind_is_dropped() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.state_mut().analyse_in_background();
    crate::common::enter(&mut app, Key::Nu, 0.2);
    app.state_mut().settle_analysis();
    crate::common::enter(&mut app, Key::Nu, 0.3);
    crate::common::enter(&mut app, Key::Nu, 0.2);
    app.state_mut().settle_analysis();
    assert_eq!(
        app.state().analysis().unwrap().transitions,
        inline_app(0.2).state().analysis().unwrap().transitions
    );
}

/// The built-in lesson in the file `name`, read as the window reads it.
fn lesson(name: &str) -> zieglerlab::lesson::Lesson {
    let (_, text) = zieglerlab::lesson::BUILT_IN
        .iter()
        .find(|(n, _)| *n == name)
        .unwrap();
    zieglerlab::lesson::Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap()
}

/// A lesson after a finished ramp: the ramp of "where flutter starts" runs
/// to its end (the tabletop held at p = 4), then "is the roller a
/// follower?" opens. Its first step's load of 1 holds (the finished ramp
/// used to set its own end again every frame), and the tabletop ramp's
/// marks are gone from the roller's bar.
#[test]
fn a_finished_ramp_leaves_the_next_lesson_its_load() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::LessonOpen(Box::new(lesson(
        "where-flutter-starts.ron",
    ))));
    // To the ramp's step, then its 60 s of simulated time and more.
    while app.state().ramp().is_none() {
        let before = app.state().lesson().unwrap().step;
        app.apply(Command::LessonNext.into());
        assert_ne!(
            app.state().lesson().unwrap().step,
            before,
            "a ramp step exists"
        );
    }
    app.apply(Action::Speed(10.0));
    for _ in 0..900 {
        app.advance(0.1);
    }
    let ramp = app.state().ramp().expect("a finished ramp keeps its marks");
    assert_eq!(ramp.load(), 4.0);
    assert_eq!(app.state().model().load_p(), 4.0);
    app.apply(Action::LessonOpen(Box::new(lesson(
        "is-the-roller-a-follower.ron",
    ))));
    for _ in 0..10 {
        app.advance(1.0 / 60.0);
    }
    let state = app.state();
    assert_eq!(state.settings().preset, PresetId::Roller);
    assert_eq!(state.model().load_p(), 1.0);
    assert!(state.ramp().is_none(), "the tabletop's ramp marks are gone");
}

/// A lesson's own kick: the first lesson's first step turns each rod of
/// the tabletop by 0.05 rad (five times the K key's 0.01 rad, a swing a
/// class sees), and the column, neutral there, keeps that swing: after
/// several periods the largest angle of rod 1 is still about the kick.
#[test]
fn a_lesson_kicks_by_its_own_size() {
    use zieglerlab::lesson::{BUILT_IN, Lesson, Run};
    let (_, text) = BUILT_IN[0];
    let lesson = Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
    let Some(Run::KickBy(kick_rad)) = lesson.steps[0].run else {
        panic!("the first step kicks by a size of its own");
    };
    assert_eq!(kick_rad, 0.05);
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let before: Vec<f64> = app
        .state()
        .simulation()
        .state()
        .iter()
        .take(2)
        .copied()
        .collect();
    app.apply(Action::LessonOpen(Box::new(lesson)));
    let after = app.state().simulation().state();
    assert_eq!(app.state().settings().preset, PresetId::Tabletop);
    // A new preset starts a fresh run from the standard small disturbance
    // (1e-3 rad at most), then the kick turns each rod by 0.05 rad.
    for i in 0..2 {
        assert!(
            (after[i] - kick_rad).abs() < 2e-3,
            "rod {}: {} (was {})",
            i + 1,
            after[i],
            before[i]
        );
    }
    let mut largest_rad: f64 = 0.0;
    for _ in 0..600 {
        app.advance(1.0 / 60.0);
        largest_rad = largest_rad.max(app.state().simulation().state()[0].abs());
    }
    assert!(
        (0.8 * kick_rad..1.5 * kick_rad).contains(&largest_rad),
        "rod 1 swings up to {largest_rad} rad after 10 s"
    );
}

/// A lesson opens from its own state whatever ran before: after the
/// roller lesson (its overlay of the ideal column) at 10x speed, the
/// damping lesson opens with no overlay and at the normal speed (the grey
/// locus of the lesson before stayed behind Ziegler's column).
#[test]
fn a_lesson_opens_without_the_last_ones_overlay_or_speed() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::LessonOpen(Box::new(lesson(
        "is-the-roller-a-follower.ron",
    ))));
    app.apply(Action::Speed(10.0));
    app.state_mut().settle_analysis();
    assert_eq!(app.state().overlay_choice(), Some(PresetId::UniformRods));
    app.apply(Action::LessonOpen(Box::new(lesson("damping-paradox.ron"))));
    assert_eq!(app.state().overlay_choice(), None);
    assert_eq!(app.state().settings().speed, 1.0);
    assert_eq!(app.state().settings().preset, PresetId::Ziegler1952);
}

/// The answer is hidden from the step that asks for a prediction up to the
/// step that reveals it, in each built-in lesson that asks for one.
#[test]
fn the_answer_is_hidden_from_the_prediction_to_the_reveal() {
    use zieglerlab::lesson::{BUILT_IN, Lesson};
    for (name, text) in BUILT_IN {
        let lesson = Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
        let asked = lesson.steps.iter().position(|s| s.predict.is_some());
        let revealed = lesson.steps.iter().position(|s| s.reveal.is_some());
        let mut app = ZieglerApp::new(Settings::default()).unwrap();
        app.apply(Action::LessonOpen(Box::new(lesson.clone())));
        for step in 0..lesson.steps.len() {
            assert_eq!(app.state().lesson().unwrap().step, step);
            let expected = asked.is_some_and(|a| step >= a && revealed.is_none_or(|r| step < r));
            assert_eq!(app.state().answer_hidden(), expected, "{name}, step {step}");
            app.apply(Command::LessonNext.into());
        }
        assert!(!app.state().answer_hidden(), "{name}: revealed at the end");
        app.apply(Action::LessonClose);
        assert!(!app.state().answer_hidden());
    }
}

/// The window runs a lesson as `lesson --check` does: opened on any
/// preset, every step that sets the column shows the column the lesson
/// defines there (`Lesson::column_at`), forward and back, with no error.
/// The built-in lessons each open with a preset of their own, so two
/// starts cover them; a lesson whose first step keeps the preset on screen
/// is walked from every two-rod preset and a chain (`lesson --check`
/// covers every preset; an app opened on a 16-rod roller chain takes 15 s
/// of a debug build).
#[test]
fn a_lesson_shows_the_same_column_forward_and_back_from_any_preset() {
    use zieglerlab::lesson::{BUILT_IN, Lesson};
    for (_, text) in BUILT_IN {
        let lesson = Lesson::read(text, &zieglerlab::app::Tab::ids()).unwrap();
        assert!(lesson.steps[0].preset.is_some());
        for start in [PresetId::Roller, PresetId::Beck] {
            walk_lesson(&lesson, start);
        }
    }
    // The load on any preset, then a switch between steps that set
    // parameters only one preset has (going back used to set the tabletop's
    // eta on the roller).
    let crossing = Lesson::read(
        "Lesson(title: \"t\", steps: [\n Step(text: \"a\", set: {\"load\": 0.5}),\n Step(text: \"b\", preset: \"tabletop\", set: {\"eta\": 0.5}),\n Step(text: \"c\", preset: \"roller\", set: {\"nu\": 0.2}),\n])",
&zieglerlab::app::Tab::ids(),
)
    .unwrap();
    for &start in PresetId::all() {
        if start.model().column.rods == 2 || start == PresetId::Beck {
            walk_lesson(&crossing, start);
        }
    }
}

/// Walks `lesson` opened on `start` to its end and back, checking each
/// step's column against `Lesson::column_at` and that no step is refused.
fn walk_lesson(lesson: &zieglerlab::lesson::Lesson, start: PresetId) {
    use zieglerlab::lesson::Column;
    let mut app = ZieglerApp::new(Settings {
        preset: start,
        model: start.model(),
        ..Settings::default()
    })
    .unwrap();
    app.apply(Action::LessonOpen(Box::new(lesson.clone())));
    let column = Column {
        preset: start,
        model: start.model(),
    };
    let last = lesson.steps.len() - 1;
    for (turn, step) in (0..=last).chain((0..last).rev()).enumerate() {
        if turn > 0 {
            app.apply(if turn <= last {
                Command::LessonNext.into()
            } else {
                Command::LessonBack.into()
            });
        }
        let state = app.state();
        assert_eq!(state.lesson().unwrap().step, step);
        if lesson.steps[step].sets_column() {
            let expected = lesson.column_at(column, step).unwrap();
            assert_eq!(
                state.settings().preset,
                expected.preset,
                "{start}, step {step}"
            );
            assert_eq!(*state.model(), expected.model, "{start}, step {step}");
        }
        assert!(
            state.notice().is_none_or(|n| !n.text.contains("lesson")),
            "{start}, step {step}: {:?}",
            state.notice()
        );
    }
}

/// The overlay is computed off the UI thread when the analysis is: chosen,
/// it is the preset's locus at the current `a` once in, the same as the
/// one computed inline; a change of `a` recomputes it and the choice stays.
#[test]
fn the_overlay_follows_on_the_analysis_thread() {
    let inline = |a: f64| {
        let mut app = ZieglerApp::new(Settings::default()).unwrap();
        crate::common::enter(&mut app, Key::A, a);
        app.apply(Action::Overlay(Some(PresetId::Ziegler1952)));
        app.state().overlay().unwrap().transitions.clone()
    };
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.state_mut().analyse_in_background();
    app.apply(Action::Overlay(Some(PresetId::Ziegler1952)));
    assert_eq!(app.state().overlay_choice(), Some(PresetId::Ziegler1952));
    app.state_mut().settle_analysis();
    assert!(!app.state().background_pending());
    let a_before = app.state().overlay().unwrap().transitions.clone();
    assert_eq!(a_before, inline(0.1));
    crate::common::enter(&mut app, Key::A, 0.3);
    assert_eq!(app.state().overlay_choice(), Some(PresetId::Ziegler1952));
    app.state_mut().settle_analysis();
    let after = app.state().overlay().unwrap().transitions.clone();
    assert_eq!(after, inline(0.3));
    assert_ne!(after, a_before, "a moves the overlay's critical loads");
}

/// The paradox tab finds the model's own point off the window's thread: in
/// a window that never waits for its background work (no picture's wait),
/// the legend names the point within frames, at the first critical load
/// the app's analysis gives.
#[test]
fn the_paradox_tab_finds_the_model_s_point_in_the_background() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.state_mut().settle_analysis();
    let expected = app
        .state()
        .analysis()
        .and_then(zieglerlab::app::Analysis::first_instability)
        .expect("the default column loses its stability");
    app.apply(Action::Tab(zieglerlab::app::Tab::Paradox));
    let label = format!(
        "this model: p = {}",
        zieglerlab::format::load_text(expected)
    );
    // Frames one by one: the curves' spinner repaints until they come, so
    // the suite's `harness_at` (which runs until the window settles) would
    // give up first.
    let mut harness = egui_kittest::Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui(|ui| app.contents_ui(ui));
    let start = std::time::Instant::now();
    while harness.query_by_label(&label).is_none() {
        assert!(
            start.elapsed() < std::time::Duration::from_mins(2),
            "no {label:?} after two minutes of frames"
        );
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
}
