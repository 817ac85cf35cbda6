//! Settings kept between runs and shared as text: the `name = value` form
//! read line by line, the earlier RON form read once, pasted text, the
//! window's layout, and stored values at the edge of what the analysis can
//! take. What reads is kept; what does not is named, never a failed start.

use zieglerlab::app::{Action, Settings, ZieglerApp};
use zieglerlab::model::{Key, PresetId};

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

/// Stored settings as a hand-edited, older or corrupted file leaves them:
/// what reads is kept, the rest is defaulted, and the message names it.
#[test]
fn stored_settings_keep_what_reads_and_name_the_rest() {
    let stiff_roller = {
        let mut settings = Settings::default();
        settings.model.column.k1_nm_per_rad = -1.0;
        ron::to_string(&settings).unwrap()
    };
    let dead_load = {
        let settings = Settings {
            preset: PresetId::Ziegler1952,
            model: zieglerlab::model::preset("roller").unwrap().model(),
            ..Settings::default()
        };
        ron::to_string(&settings).unwrap()
    };
    // A count of rods that is no whole number in range, named as `--set`
    // names it (it was reported as "rods = 0").
    let rods = |count: &str| {
        let settings = Settings {
            preset: PresetId::Beck,
            model: PresetId::Beck.model(),
            ..Settings::default()
        };
        ron::to_string(&settings)
            .unwrap()
            .replace("rods:16", &format!("rods:{count}"))
    };
    let (half, huge, negative) = (rods("2.5"), rods("1e300"), rods("-3"));
    assert_ne!(half, rods("16"), "the count is stored as rods:16");
    // (stored text, speed kept, message fragment; None: no message)
    let cases: &[(&str, f64, Option<&str>)] = &[
        // Saved by an editor that writes a byte-order mark.
        ("\u{feff}(speed: 3.0)", 3.0, None),
        (
            &half,
            1.0,
            Some("model.column.rods (rods = 2.5: must be a whole number from 2 to 64)"),
        ),
        (
            &huge,
            1.0,
            Some("model.column.rods (rods = 1e300: must be a whole number"),
        ),
        (
            &negative,
            1.0,
            Some("model.column.rods (rods = -3: must be a whole number"),
        ),
        // An older version that knew only the speed.
        ("(speed: 3.0)", 3.0, None),
        // A newer version's field.
        (
            "(speed: 3.0, colour: \"blue\")",
            3.0,
            Some("ignored colour (not a setting)"),
        ),
        // Wrong types, hand-edited.
        ("(speed: \"fast\")", 1.0, Some("ignored speed (")),
        (
            "(speed: 2.0, projector: 7)",
            2.0,
            Some("ignored projector ("),
        ),
        ("(model: 42)", 1.0, Some("ignored model (")),
        // Values out of range.
        (
            "(speed: 50.0)",
            1.0,
            Some("speed (50 is outside 0.1 to 10)"),
        ),
        (
            "(preset: \"nope\", speed: 2.0)",
            2.0,
            Some("preset (unknown preset 'nope'"),
        ),
        (
            &stiff_roller,
            1.0,
            Some("ignored model.column.k1_nm_per_rad (k1 = -1"),
        ),
        (
            &dead_load,
            1.0,
            Some("model.load (a Roller load; the preset's is Follower)"),
        ),
        // Corrupted.
        (
            "not ron at all",
            1.0,
            Some("stored settings ignored (not settings text"),
        ),
        (
            "(speed: 1.0,",
            1.0,
            Some("stored settings ignored (not settings text"),
        ),
    ];
    for &(text, speed, message) in cases {
        let app = ZieglerApp::from_stored_text(Some(text));
        assert_eq!(app.settings().speed, speed, "{text}");
        assert!(app.state().analysis().is_some(), "{text}");
        match message {
            None => assert_eq!(app.message(), None, "{text}"),
            Some(fragment) => {
                let shown = app.message().unwrap_or_default();
                assert!(shown.contains(fragment), "{text}: {shown}");
            }
        }
    }
}

/// The stored model is read number by number: one bad number (hand-edited,
/// out of range, or of an older layout) costs that number only, named with
/// its reason; the others are kept, also when they only fit together (a
/// centre of mass beyond the preset's rod, on a longer stored rod).
#[test]
fn a_bad_number_in_the_stored_model_costs_only_that_number() {
    let mut settings = Settings::default();
    settings.model.column.k1_nm_per_rad = -1.0;
    settings.model.column.rod2.length_m = 2.0;
    settings.model.column.rod2.com_m = 1.5;
    settings.model.column.c2_nms_per_rad = 0.01;
    if let zieglerlab::model::Load::Roller(roller) = &mut settings.model.load {
        roller.mu = 0.2;
    }
    let text = ron::to_string(&settings)
        .unwrap()
        .replace("tip_mass_kg:", "colour:1.0,tip_mass_kg:")
        .replace("band_speed_m_per_s:0.1", "band_speed_m_per_s:\"fast\"");
    let app = ZieglerApp::from_stored_text(Some(&text));
    let model = app.settings().model;
    let defaults = Settings::default().model;
    // Kept: the good numbers, including the pair that fits only together.
    assert_eq!(model.column.rod2.length_m, 2.0);
    assert_eq!(model.column.rod2.com_m, 1.5);
    assert_eq!(model.column.c2_nms_per_rad, 0.01);
    assert_eq!(model.roller().unwrap().mu, 0.2);
    // Defaulted: the bad ones.
    assert_eq!(model.column.k1_nm_per_rad, defaults.column.k1_nm_per_rad);
    assert_eq!(
        model.roller().unwrap().band_speed_m_per_s,
        defaults.roller().unwrap().band_speed_m_per_s
    );
    let said = app.message().unwrap();
    for fragment in [
        "model.column.k1_nm_per_rad (k1 = -1",
        "model.column.colour (not a field)",
        "model.load.band_speed_m_per_s (",
    ] {
        assert!(said.contains(fragment), "{fragment}: {said}");
    }
    assert!(!said.contains("model.load.mu"), "{said}");
    assert!(app.state().analysis().is_some());
}

#[test]
fn pasted_garbage_changes_nothing_and_says_so() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.advance(0.05);
    let before = (app.settings().clone(), app.simulation().time_secs());
    app.apply(Action::Paste("{{ this is not a setup }}".to_owned()));
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
    app.apply(Action::Paste(ron::to_string(&bad).unwrap()));
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
    app.apply(Action::Paste(ron::to_string(&good).unwrap()));
    assert_eq!(app.settings(), &good);
    // An empty box says what to do, not "Expected opening `(`".
    app.apply(Action::Paste("  ".to_owned()));
    assert!(
        app.message().unwrap().starts_with("nothing to paste"),
        "{:?}",
        app.message()
    );
    // Another preset pasted keeps the lesson open and the overlay chosen
    // in it (opening a lesson clears the one chosen before).
    app.apply(Action::LessonOpen(Box::new(
        zieglerlab::lesson::Lesson::read(
            zieglerlab::lesson::BUILT_IN[0].1,
            &zieglerlab::app::Tab::ids(),
        )
        .unwrap(),
    )));
    app.apply(Action::Overlay(Some(PresetId::UniformRods)));
    let tabletop = Settings {
        preset: PresetId::Tabletop,
        model: PresetId::Tabletop.model(),
        ..Settings::default()
    };
    app.apply(Action::Paste(ron::to_string(&tabletop).unwrap()));
    assert_eq!(app.settings(), &tabletop);
    assert_eq!(
        app.state().overlay().map(|o| o.preset),
        Some(PresetId::UniformRods)
    );
    assert!(app.state().lesson().is_some());
}

/// The open tab, the overlay and the map's axis come back at the next
/// launch; what does not fit the stored model is left out and said.
#[test]
fn the_window_layout_comes_back_and_a_misfit_is_said() {
    use zieglerlab::app::{Layout, Tab};
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let arranged = Layout {
        tab: Tab::Map,
        overlay: Some("ziegler-1952".to_owned()),
        map_axis: Some(("V".to_owned(), 0.05, 0.5)),
        language: Some("it".to_owned()),
    };
    app.arrange(&arranged);
    assert_eq!(app.layout(), arranged);
    let text = ron::to_string(&app.layout()).unwrap();
    let mut next = ZieglerApp::new(Settings::default()).unwrap();
    let (read, note) = Layout::read(&text);
    assert_eq!(note, None);
    next.arrange(&read);
    assert_eq!(next.layout(), arranged);
    assert_eq!(next.message(), None);

    // The 1952 column has no roller mass to map, and no preset is named so.
    let column = Settings {
        preset: PresetId::Ziegler1952,
        model: zieglerlab::model::preset("ziegler-1952").unwrap().model(),
        ..Settings::default()
    };
    let mut other = ZieglerApp::new(column).unwrap();
    other.arrange(&Layout {
        tab: Tab::Paradox,
        overlay: Some("no-such-preset".to_owned()),
        map_axis: Some(("nu".to_owned(), 0.01, 1.0)),
        language: Some("klingon".to_owned()),
    });
    let layout = other.layout();
    assert_eq!(layout.tab, Tab::Paradox);
    assert_eq!(layout.overlay, None);
    assert_eq!(
        layout.map_axis, None,
        "the map's own default comes when shown"
    );
    let said = other.message().unwrap();
    assert!(said.contains("no-such-preset"), "{said}");
    assert!(said.contains("stored map axis is not used"), "{said}");
    assert!(said.contains("unknown language 'klingon'"), "{said}");
    assert_eq!(layout.language, None, "the system's language, not a choice");

    let (garbage, note) = Layout::read("{{ not a layout");
    assert_eq!(garbage, Layout::default());
    assert!(!note.unwrap().is_empty());
}

/// Extreme stored values (a tiny roller mass, a crawling or a vanishing
/// band) start the app with an answer or a refusal, never a hang: the value
/// the analysis cannot square is refused by name and defaulted, the one it
/// can is analysed with the resolution warning, and a frame is drawn.
#[test]
fn extreme_stored_values_start_the_app_with_an_answer_or_a_refusal() {
    let stored = |nu: f64, v: f64| {
        let mut settings = Settings::default();
        if let zieglerlab::model::Load::Roller(roller) = &mut settings.model.load {
            roller.mass_kg = nu * settings.model.column.rod2.mass_kg;
            roller.band_speed_m_per_s = v;
        }
        ron::to_string(&settings).unwrap()
    };
    let mut refused = ZieglerApp::from_stored_text(Some(&stored(1e-9, 1e-300)));
    let said = refused.message().unwrap().to_owned();
    assert!(
        said.contains("model.load.band_speed_m_per_s (the slip damping"),
        "{said}"
    );
    assert_eq!(
        refused
            .settings()
            .model
            .roller()
            .unwrap()
            .band_speed_m_per_s,
        Settings::default()
            .model
            .roller()
            .unwrap()
            .band_speed_m_per_s
    );
    let mut kept = ZieglerApp::from_stored_text(Some(&stored(1e-9, 1e-100)));
    assert_eq!(kept.message(), None);
    let analysis = kept.state().analysis().unwrap();
    assert!(
        analysis.warning.is_some(),
        "the spin mode outruns the others"
    );
    for app in [&mut refused, &mut kept] {
        let ctx = eframe::egui::Context::default();
        for _ in 0..3 {
            app.advance(1.0 / 60.0);
            let mut output = ctx.run_ui(eframe::egui::RawInput::default(), |ui| {
                app.contents_ui(ui);
            });
            // No renderer takes the font atlas here.
            output.textures_delta.clear();
        }
        assert!(app.simulation().state().iter().all(|x| x.is_finite()));
    }
}

/// What the window saves is the `name = value` text, and it starts the
/// next launch with the same settings and nothing to say; a parameter
/// changed by a group (`a` writes k1 and k2) comes back to the last bit.
#[test]
fn saved_text_starts_the_next_launch_as_it_was() {
    let mut app = ZieglerApp::new(Settings {
        preset: PresetId::Tabletop,
        model: PresetId::Tabletop.model(),
        speed: 0.5,
        ..Settings::default()
    })
    .unwrap();
    crate::common::enter(&mut app, Key::A, 3.7);
    crate::common::enter(&mut app, Key::C2, 0.002);
    crate::common::enter(&mut app, Key::Load, 2.2);
    let text = app.settings().to_text();
    assert!(text.starts_with("preset = tabletop\n"), "{text}");
    assert!(text.contains("c2 = 0.002\n"), "{text}");
    let next = ZieglerApp::from_stored_text(Some(&text));
    assert_eq!(next.message(), None, "{text}");
    assert_eq!(next.settings(), app.settings(), "{text}");
}

/// Text typed by hand in the vocabulary of `--set` is pasted whole; one
/// line the model refuses refuses the paste (nothing half-taken) and names
/// the line.
#[test]
fn hand_typed_text_is_pasted_and_a_bad_line_named() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Paste(
        "# the tabletop at p = 2\npreset = tabletop\nload = 2\n".to_owned(),
    ));
    assert_eq!(app.settings().preset, PresetId::Tabletop);
    assert!((app.settings().model.load_p() - 2.0).abs() < 1e-12);
    let before = app.settings().clone();
    app.apply(Action::Paste("preset = roller\nk1 = -3\n".to_owned()));
    assert_eq!(app.settings(), &before);
    let said = app.message().unwrap_or_default().to_owned();
    assert!(
        said.starts_with("pasted settings refused") && said.contains("k1 (k1 = -3"),
        "{said}"
    );
}
