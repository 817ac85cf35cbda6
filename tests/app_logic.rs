//! The app's logic without a window: the simulation follows the wall clock
//! at the chosen speed with a cap per frame, and stored settings that are
//! partial, from another version or garbage start the app anyway, saying
//! what was ignored.

use zieglerlab::app::{Settings, ZieglerApp};
use zieglerlab::sim::DEFAULT_STEP_SECS;

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
fn a_slow_frame_advances_at_most_the_cap() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.advance(5.0);
    let t = app.simulation().time_secs();
    assert!(
        (0.1 - 2.0 * DEFAULT_STEP_SECS..=0.1 + DEFAULT_STEP_SECS).contains(&t),
        "{t}"
    );
}

#[test]
fn stored_settings_round_trip() {
    let settings = Settings {
        speed: 2.5,
        projector: true,
        ..Settings::default()
    };
    let text = ron::to_string(&settings).unwrap();
    let app = ZieglerApp::from_stored_text(Some(&text));
    assert_eq!(app.settings(), &settings);
}

#[test]
fn partial_or_broken_settings_fall_back_to_defaults() {
    // An older version that knew only the speed: the rest is defaulted.
    let app = ZieglerApp::from_stored_text(Some("(speed: 3.0)"));
    assert_eq!(app.settings().speed, 3.0);
    assert_eq!(app.settings().preset, "roller");
    for garbage in ["not ron at all", "(speed: \"fast\")", "(model: 42)"] {
        let app = ZieglerApp::from_stored_text(Some(garbage));
        assert_eq!(app.settings(), &Settings::default(), "{garbage}");
    }
}

#[test]
fn pasted_garbage_changes_nothing_and_says_so() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.advance(0.05);
    let before = (app.settings().clone(), app.simulation().time_secs());
    app.paste_settings("{{ this is not a setup }}");
    assert_eq!(
        (app.settings().clone(), app.simulation().time_secs()),
        before
    );
    assert!(
        app.message()
            .unwrap()
            .starts_with("pasted settings not understood")
    );
    // Well-formed text with an invalid model is refused too.
    let mut bad = Settings::default();
    bad.model.column.k1_nm_per_rad = -1.0;
    app.paste_settings(&ron::to_string(&bad).unwrap());
    assert_eq!(app.settings(), &before.0);
    assert!(
        app.message().unwrap().contains("k1 = -1"),
        "{:?}",
        app.message()
    );
    // A good setup is taken whole.
    let good = Settings {
        speed: 0.5,
        ..Settings::default()
    };
    app.paste_settings(&ron::to_string(&good).unwrap());
    assert_eq!(app.settings(), &good);
}

#[test]
fn a_model_without_analysis_shows_no_stale_locus() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    assert!(app.has_analysis());
    // The band stops: the simulation goes on, the linear analysis cannot.
    app.set_parameter("V", 0.0).unwrap();
    assert!(!app.has_analysis());
    assert!(
        app.message().unwrap().contains("V = 0"),
        "{:?}",
        app.message()
    );
    app.advance(0.05);
    assert!(app.simulation().time_secs() > 0.0);
    app.set_parameter("V", 0.1).unwrap();
    assert!(app.has_analysis());
}
