//! The app driven as a user drives it (`egui_kittest`, no window, no GPU):
//! real key sequences typed into the parameter fields (select all, one
//! character at a time, Enter, Escape, Tab), with the model and the field's
//! text checked after each.

use crate::common::message_line;
use eframe::egui;
use eframe::egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Settings, ZieglerApp};
use zieglerlab::model::Key;

/// Clicks into the field labelled `key`, selects its text and types `text`
/// one character at a time, a frame after each (as a person at a keyboard).
pub(crate) fn type_into(harness: &mut Harness<'_>, key: &str, text: &str) {
    harness.get_by_role_and_label(Role::TextInput, key).click();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.run();
    for c in text.chars() {
        harness
            .get_by_role_and_label(Role::TextInput, key)
            .type_text(&c.to_string());
        harness.run();
    }
}

/// The text the field labelled `key` shows.
fn shown(harness: &Harness<'_>, key: &str) -> String {
    harness
        .get_by_role_and_label(Role::TextInput, key)
        .value()
        .unwrap_or_default()
}

fn press(harness: &mut Harness<'_>, key: egui::Key) {
    harness.key_press(key);
    harness.run();
}

pub(crate) fn harness(app: &mut ZieglerApp) -> Harness<'_> {
    harness_at(app, [1280.0, 800.0])
}

/// The whole window of `app` at `size`, its first frames run.
pub(crate) fn harness_at(app: &mut ZieglerApp, size: [f32; 2]) -> Harness<'_> {
    let mut harness = Harness::builder()
        .with_size(size)
        .build_ui(|ui| app.contents_ui(ui));
    harness.run();
    harness
}

/// "0.2" into mu (0.1): every intermediate text ("0", "0.") is the user's,
/// nothing is applied until Enter, and then exactly 0.2.
#[test]
fn a_value_starting_with_zero_point_is_taken_as_typed_on_enter() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let load_before = app.settings().model.load_p();
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "mu", "0.2");
        assert_eq!(shown(&harness, "mu"), "0.2");
        assert!(harness.query_by_label_contains("refused:").is_none());
        press(&mut harness, egui::Key::Enter);
        assert_eq!(shown(&harness, "mu"), "0.2");
        assert!(harness.query_by_label_contains("refused:").is_none());
    }
    let model = app.settings().model;
    assert_eq!(Key::Mu.get(&model), 0.2);
    // mu moves the load with R held: p = mu R l / k doubles.
    assert!((model.load_p() - 2.0 * load_before).abs() < 1e-12);
}

/// Two digits typed into a: nothing moves in between, 78 is taken whole.
#[test]
fn several_digits_are_one_value() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "a", "78");
        assert_eq!(shown(&harness, "a"), "78");
        press(&mut harness, egui::Key::Enter);
        assert_eq!(shown(&harness, "a"), "78");
    }
    assert_eq!(Key::A.get(&app.settings().model), 78.0);
}

/// Escape restores the applied value and applies nothing; Tab commits.
#[test]
fn escape_restores_and_tab_commits() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "rho", "0.35");
        press(&mut harness, egui::Key::Escape);
        assert_eq!(shown(&harness, "rho"), "0.1");
        type_into(&mut harness, "V", "0.3");
        press(&mut harness, egui::Key::Tab);
        assert_eq!(shown(&harness, "V"), "0.3");
    }
    let model = app.settings().model;
    assert_eq!(Key::Rho.get(&model), 0.1);
    assert_eq!(Key::V.get(&model), 0.3);
}

/// A refused value stays in the field with the reason beside it until it
/// is corrected; text that is no number says so; the model keeps its value.
#[test]
fn a_refused_value_stays_with_its_reason_until_corrected() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let nu_before = app.settings().model.roller().unwrap().mass_kg;
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "nu", "-1");
        press(&mut harness, egui::Key::Enter);
        harness.get_by_label_contains("refused: nu = -1: must be");
        assert_eq!(shown(&harness, "nu"), "-1");
        // Still there a few frames later.
        harness.run();
        assert_eq!(shown(&harness, "nu"), "-1");
        type_into(&mut harness, "nu", "0.5x");
        press(&mut harness, egui::Key::Enter);
        harness.get_by_label_contains("refused: '0.5x' is not a number");
        // Corrected: taken, and the refusal goes.
        type_into(&mut harness, "nu", "0.5");
        press(&mut harness, egui::Key::Enter);
        assert!(harness.query_by_label_contains("refused:").is_none());
        assert_eq!(shown(&harness, "nu"), "0.5");
    }
    let nu_after = app.settings().model.roller().unwrap().mass_kg;
    assert!(
        (nu_after - 5.0 * nu_before).abs() < 1e-12,
        "{nu_before} -> {nu_after}"
    );
}

#[test]
fn a_huge_typed_load_is_taken_as_typed_and_said_to_be_off_the_plots() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "load", "1e6");
        press(&mut harness, egui::Key::Enter);
        harness.get_by_label_contains("is beyond the plotted range");
    }
    assert_eq!(app.settings().model.load_p(), 1e6);
}

/// A refusal stays while another field is edited and abandoned.
#[test]
fn a_refusal_outlives_an_edit_escaped_elsewhere() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut harness = harness(&mut app);
    type_into(&mut harness, "nu", "-5");
    press(&mut harness, egui::Key::Enter);
    harness.get_by_label_contains("refused: nu = -5");
    harness.get_by_role_and_label(Role::TextInput, "a").click();
    harness.run();
    assert_eq!(shown(&harness, "nu"), "-5", "after the click");
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.run();
    assert_eq!(shown(&harness, "nu"), "-5", "after select all");
    type_into(&mut harness, "a", "21");
    assert_eq!(shown(&harness, "nu"), "-5", "after typing");
    press(&mut harness, egui::Key::Escape);
    assert_eq!(shown(&harness, "a"), "0.1");
    assert_eq!(shown(&harness, "nu"), "-5");
    harness.get_by_label_contains("refused: nu = -5");
}

/// "3.5" typed into the load field one character a frame is one value:
/// the "3" on the way is not applied, Enter applies 3.5; Escape restores.
#[test]
fn the_load_field_applies_what_is_typed_on_enter() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    {
        let mut harness = harness(&mut app);
        type_into(&mut harness, "load", "3.5");
        assert_eq!(shown(&harness, "load"), "3.5");
        harness.get_by_label_contains("q = R l/k = p/μ = 10.000");
        press(&mut harness, egui::Key::Enter);
        harness.get_by_label_contains("q = R l/k = p/μ = 35.000");
        type_into(&mut harness, "load", "6");
        press(&mut harness, egui::Key::Escape);
        assert_eq!(shown(&harness, "load"), "3.5");
        harness.get_by_label_contains("q = R l/k = p/μ = 35.000");
    }
    assert_eq!(app.settings().model.load_p(), 3.5);
}

/// The named speeds set the factor (simulated seconds per wall second);
/// Normal is real time.
#[test]
fn slow_normal_and_fast_set_the_speed() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    for (name, speed) in [("Fast", 4.0), ("Slow", 0.25), ("Normal", 1.0)] {
        {
            let mut harness = harness(&mut app);
            harness.get_by_label(name).click();
            harness.run();
        }
        assert_eq!(app.settings().speed, speed, "{name}");
    }
}

/// The wide load bar is the slider: a click at its middle sets the load to
/// the middle of its range (0 to 8).
#[test]
fn a_click_on_the_load_bar_sets_the_load() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    {
        let mut harness = harness(&mut app);
        harness.get_by_label("load slider").click();
        harness.run();
    }
    let load = app.settings().model.load_p();
    assert!((load - 4.0).abs() < 0.02, "{load}");
}

/// Drag to perturb: the tip of the straight roller column, pressed and
/// moved up in the scene, is held there at rest (time stands still); let go,
/// the column moves on from the displaced shape.
#[test]
fn dragging_the_tip_displaces_the_column_and_letting_go_releases_it() {
    use zieglerlab::app::Panel;
    let app = ZieglerApp::new(Settings::default()).unwrap();
    let t = app.simulation().time_secs();
    let mut harness = Harness::builder().with_size([800.0, 400.0]).build_ui_state(
        |ui, app: &mut ZieglerApp| app.panel_ui(ui, Panel::Scene),
        app,
    );
    harness.run();
    // The camera frames the straight column, x from -0.12 to 1.12 lengths
    // in the 784 x 384 panel: the tip is at x = 400 + 0.5 * 784 / 1.24, on
    // the middle line.
    let tip = egui::pos2(400.0 + 0.5 * 784.0 / 1.24, 200.0);
    harness.drag_at(tip);
    harness.run();
    let up = tip - egui::vec2(0.0, 80.0);
    for step in 1..=8_u8 {
        harness.hover_at(tip - egui::vec2(0.0, 10.0 * f32::from(step)));
        harness.run();
    }
    let app = harness.state_mut();
    assert!(app.state().held(), "the column is held");
    let x = app.simulation().state();
    assert!(x[1] > 0.1, "rod 2 turned up: phi2 = {}", x[1]);
    assert_eq!((x[3], x[4]), (0.0, 0.0), "at rest while held");
    app.advance(0.5);
    assert_eq!(
        app.simulation().time_secs(),
        t,
        "time stands still while held"
    );
    harness.drop_at(up);
    harness.run();
    let app = harness.state_mut();
    assert!(!app.state().held(), "let go");
    for _ in 0..30 {
        app.advance(1.0 / 60.0);
    }
    assert!(app.simulation().time_secs() > t + 0.4, "the run goes on");
}

/// A lesson walked through as a class would: open the built-in "where does
/// the column start to flutter" (it switches to the tabletop column at
/// p = 1), go on to the prediction and click the predicted load on its
/// slider, go on to the ramp and let it run, and read the result beside
/// the prediction: the theory's onset (the closed form 2 (9 - sqrt 7) / 5)
/// and where the motion showed, past it.
#[test]
fn a_lesson_walked_through_predict_run_reveal() {
    let app = ZieglerApp::new(Settings::default()).unwrap();
    let mut harness = Harness::builder()
        .with_size([1280.0, 900.0])
        .build_ui_state(|ui, app: &mut ZieglerApp| app.contents_ui(ui), app);
    harness.run();
    harness.get_by_label("lessons").click();
    harness.run();
    harness
        .get_by_label("Where does the column start to flutter?")
        .click();
    harness.run();
    let model = harness.state().settings().model;
    assert_eq!(harness.state().settings().preset.name(), "tabletop");
    assert_eq!(model.load_p(), 1.0);
    harness.get_by_label("next").click();
    harness.run();
    harness.get_by_label("predicted load").click();
    harness.run();
    let predicted = harness.state().state().lesson().unwrap().predicted_load;
    assert!(
        predicted.is_some_and(|p| (p - 4.0).abs() < 0.3),
        "{predicted:?}"
    );
    // While the class predicts, nothing on the screen gives the answer: no
    // critical load in the sidebar, no verdict on the card, no locus.
    let onset_text = format!(
        "p = {}: stable -> flutter",
        zieglerlab::format::load_text(2.0 * (9.0 - 7f64.sqrt()) / 5.0)
    );
    assert!(harness.query_by_label_contains(&onset_text).is_none());
    assert!(
        harness
            .query_by_label_contains("stable -> flutter")
            .is_none()
    );
    assert!(
        harness
            .query_by_label_contains("hidden until the lesson reveals them")
            .is_some()
    );
    assert!(harness.query_by_label_contains("neutral").is_none());
    assert!(
        harness
            .query_by_label_contains("This plot shows the answer")
            .is_some()
    );
    harness.get_by_label("next").click();
    harness.run();
    assert!(
        harness.state().state().ramp().is_some(),
        "the step starts its ramp"
    );
    for _ in 0..60 * 40 {
        harness.state_mut().advance(1.0 / 60.0);
    }
    harness.run();
    harness.get_by_label("next").click();
    harness.run();
    let onset = 2.0 * (9.0 - 7f64.sqrt()) / 5.0;
    let seen = harness.state().state().ramp().unwrap().seen_at_p.unwrap();
    assert!(seen > onset, "seen at {seen}, onset {onset}");
    let said = format!(
        "the theory: unstable from p = {}; the motion showed at p = {}",
        zieglerlab::format::load_text(onset),
        zieglerlab::format::load_text(seen)
    );
    assert!(harness.query_by_label_contains(&said).is_some(), "{said}");
    // Revealed: the critical loads and the plots are back.
    assert!(harness.query_by_label_contains(&onset_text).is_some());
    assert!(
        harness
            .query_by_label_contains("This plot shows the answer")
            .is_none()
    );
}

/// A picture shows no hints for the hand and no messages: the plots' view
/// hint and fit button, the first launch's hint and a notice are in the
/// window, not in what the command line draws (nor in a recording's frames).
#[test]
fn pictures_carry_no_hints_for_the_hand() {
    // The status line holds the first launch's hint or, once said, a notice.
    let hints = |for_pictures: bool, said: bool| {
        let mut app = ZieglerApp::from_stored_text(None);
        if said {
            app.state_mut().say(zieglerlab::app::Notice::info(
                "a message for the person at the window",
            ));
        }
        if for_pictures {
            app.draw_for_pictures();
        }
        let mut harness = Harness::builder()
            .with_size([1280.0, 800.0])
            .build_ui_state(|ui, app: &mut ZieglerApp| app.contents_ui(ui), app);
        harness.run();
        [
            harness
                .query_by_label_contains(
                    &zieglerlab::i18n::words(zieglerlab::i18n::Language::English)
                        .get(zieglerlab::app::VIEW_HINT),
                )
                .is_some(),
            harness.query_by_label("fit").is_some(),
            harness
                .query_by_label_contains("Drag the load bar to about 3")
                .is_some()
                || harness
                    .query_by_label_contains("a message for the person")
                    .is_some(),
        ]
    };
    for said in [false, true] {
        assert_eq!(
            hints(false, said),
            [true, true, true],
            "the window shows them"
        );
        assert_eq!(
            hints(true, said),
            [false, false, false],
            "a picture does not"
        );
    }
}

/// Words per column: the band's angle and power are plotted only where
/// there is a band, and a growth rate zero within the resolution is called
/// neutral, with no decay time of millions of years beside it.
#[test]
fn the_words_fit_the_column() {
    use zieglerlab::app::Tab;
    use zieglerlab::model::PRESETS;
    let mut neutral_seen = 0;
    for preset in PRESETS {
        let mut app = ZieglerApp::new(Settings {
            preset: preset.id,
            model: preset
                .model()
                .at_load(0.5 * preset.model().load_bar_max_p() / 8.0),
            ..Settings::default()
        })
        .unwrap();
        app.show_tab(Tab::Histories);
        // The analysis alone: the map's and paradox's work is not shown.
        app.state_mut().settle_analysis();
        let mut harness = Harness::builder()
            .with_size([1280.0, 900.0])
            .build_ui_state(|ui, app: &mut ZieglerApp| app.contents_ui(ui), app);
        harness.run();
        let band = preset.model().roller().is_some();
        let shown = |text: &str| harness.query_by_label_contains(text).is_some();
        assert_eq!(shown("power from the band"), band, "{}", preset.id);
        assert_eq!(shown("the band force's angle"), band, "{}", preset.id);
        if shown("growth rate  0 (to within") {
            neutral_seen += 1;
            assert!(shown("neutral: no growth, no decay"), "{}", preset.id);
            assert!(!shown("decay time"), "{}", preset.id);
        }
    }
    assert!(
        neutral_seen > 0,
        "some undamped column is neutral at its load"
    );
}

/// Every panel of a frame shows the same state: V = 0 typed into the
/// roller's band speed leaves no linear analysis, and frame by frame after
/// Enter the status line's message (drawn first), the status card and the
/// root-locus tab (drawn last) either all still show the old parameters
/// or all say why there is no analysis. The change is applied between
/// frames, never while one is drawn.
#[test]
fn every_panel_of_a_frame_shows_the_same_state() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut harness = harness(&mut app);
    type_into(&mut harness, "V", "0");
    harness.key_press(egui::Key::Enter);
    let mut changed_at = None;
    for frame in 0..4 {
        harness.step();
        let status_line = harness
            .query_by_label_contains("analysis unavailable: V = 0")
            .is_some();
        let card = harness
            .query_by_label_contains("no stability figures: V = 0")
            .is_some();
        let locus = harness
            .query_by_label_contains("No root locus for these parameters")
            .is_some();
        assert_eq!(
            [status_line, card],
            [locus, locus],
            "frame {frame}: the status line, the card and the locus disagree"
        );
        if locus && changed_at.is_none() {
            changed_at = Some(frame);
        }
    }
    assert!(changed_at.is_some(), "V = 0 was applied");
}

/// Any joint of a chain is grabbed as a person would grab it: on a straight
/// column of four rods, the middle joint (the end of rod 2) pressed and
/// moved up holds the column there at rest, rods 1 and 2 bent to reach the
/// pointer and rods 3 and 4 carried along with their directions kept; let
/// go, it moves on.
#[test]
fn dragging_a_joint_of_a_chain_bends_the_rods_before_it() {
    use zieglerlab::app::{Action, Panel};
    let mut app = ZieglerApp::new(Settings {
        preset: zieglerlab::model::PresetId::UniformRods,
        model: zieglerlab::model::PresetId::UniformRods.model(),
        ..Settings::default()
    })
    .unwrap();
    app.apply(Action::Enter {
        key: Key::Rods,
        value: 4.0,
    });
    assert_eq!(app.settings().model.column.rods, 4);
    let before: Vec<f64> = app.simulation().state().iter().take(4).copied().collect();
    let mut harness = Harness::builder().with_size([800.0, 400.0]).build_ui_state(
        |ui, app: &mut ZieglerApp| app.panel_ui(ui, Panel::Scene),
        app,
    );
    harness.run();
    // The camera frames the straight column as on two rods (x from -0.12
    // to 1.12 of its reach in the 784 x 384 panel): the middle joint is at
    // half the reach, the panel's middle.
    let joint = egui::pos2(400.0, 200.0);
    harness.drag_at(joint);
    harness.run();
    // Up and in, within the reach of rods 1 and 2.
    for step in 1..=6_u8 {
        let s = f32::from(step);
        harness.hover_at(joint + egui::vec2(-6.0 * s, -8.0 * s));
        harness.run();
    }
    let app = harness.state_mut();
    assert!(app.state().held(), "the column is held");
    let x = app.simulation().state();
    assert!(x[0] < -0.1 && x[1] > 0.1, "rods 1 and 2 bend: {x}");
    // (rapier keeps angles in f32: the same to its rounding)
    for i in [2, 3] {
        assert!(
            (x[i] - before[i]).abs() < 1e-6,
            "rod {} keeps its direction: {x}",
            i + 1
        );
    }
    // The joint went up and in, toward the pointer (the camera follows the
    // column as it bends, so screen points are not fixed world points).
    let reach = app.settings().model.column.reach_m();
    let at = app.simulation().joints_m()[2];
    assert!(at[1] > 0.02 * reach && at[0] < 0.5 * reach, "{at:?}");
    harness.drop_at(joint + egui::vec2(-36.0, -48.0));
    harness.run();
    assert!(!harness.state().state().held(), "let go");
}

/// The fields under the load keep their place while the notes above them
/// change (two critical loads, none when the band stops, a load beyond the
/// bar, a finished ramp's onsets): a click aimed at a field lands on it.
#[test]
fn the_fields_under_the_load_stay_put_as_the_notes_change() {
    let mut harness = Harness::builder()
        .with_size([1280.0, 800.0])
        .build_ui_state(
            |ui, app: &mut ZieglerApp| app.contents_ui(ui),
            ZieglerApp::new(Settings::default()).unwrap(),
        );
    harness.run_steps(2);
    let place = |harness: &Harness<'_, ZieglerApp>| {
        harness
            .get_by_role_and_label(Role::TextInput, "a")
            .rect()
            .top()
    };
    let first = place(&harness);
    let changes: [(&str, Key, f64); 4] = [
        ("the band stopped: no critical loads", Key::V, 0.0),
        ("the band moving again", Key::V, 0.1),
        ("a load beyond the bar", Key::Load, 9.0),
        ("a single divergence load", Key::Mu, 5.0),
    ];
    for (what, key, value) in changes {
        harness
            .state_mut()
            .apply(zieglerlab::app::Action::Enter { key, value });
        harness.run_steps(3);
        assert_eq!(place(&harness), first, "{what}");
    }
}

/// Typing 16 rods at p = 2 moves the load with the load bar, which scales
/// as (2/N)^2: p = 2 of the two-rod bar (0 to 8) becomes 1/32 of the
/// chain's (0 to 0.125), the same place and the same P L^2/EI, and the
/// message line says so (the load stayed 16 times past the chain's bar).
#[test]
fn typed_rods_move_the_load_with_the_bar() {
    let mut app = ZieglerApp::new(Settings {
        preset: zieglerlab::model::PresetId::UniformRods,
        model: zieglerlab::model::PresetId::UniformRods.model(),
        ..Settings::default()
    })
    .unwrap();
    app.apply(zieglerlab::app::Action::Enter {
        key: zieglerlab::model::Key::Load,
        value: 2.0,
    });
    let beck_before = app.settings().model.beck_load(2.0).unwrap();
    {
        let mut harness = harness(&mut app);
        harness.get_by_label("SI parameters").click();
        harness.run();
        type_into(&mut harness, "rods", "16");
        press(&mut harness, egui::Key::Enter);
    }
    let model = app.settings().model;
    assert_eq!(model.column.rods, 16);
    assert!(
        (model.load_p() - 2.0 / 64.0).abs() < 1e-15,
        "{}",
        model.load_p()
    );
    assert!(model.load_p() <= model.load_bar_max_p());
    let beck_after = model.beck_load(model.load_p()).unwrap();
    assert!((beck_after - beck_before).abs() < 1e-12 * beck_before);
    let said = message_line(&app);
    assert!(
        said.starts_with("rods = 16: the load bar is now 0 to 0.125"),
        "{said}"
    );
}

/// A dead load (eta = 0) is said in place of the preset's description,
/// which names a follower force: the two stood one above the other and
/// contradicted each other.
#[test]
fn a_changed_tip_force_replaces_the_preset_s_words() {
    let preset = zieglerlab::model::PresetId::Ziegler1952;
    let mut app = ZieglerApp::new(Settings {
        preset,
        model: preset.model(),
        ..Settings::default()
    })
    .unwrap();
    let description = preset.preset().description;
    {
        let harness = harness(&mut app);
        harness.get_by_label(description);
    }
    app.apply(zieglerlab::app::Action::Enter {
        key: zieglerlab::model::Key::Eta,
        value: 0.0,
    });
    let harness = harness(&mut app);
    assert!(harness.query_by_label(description).is_none());
    harness.get_by_label_contains("tip force: a dead load (eta = 0)");
}
