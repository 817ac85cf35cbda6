//! The app driven as a user drives it (`egui_kittest`, no window, no GPU): a
//! bad value typed into a parameter field is refused on screen with the
//! reason, and the model keeps its value.

use eframe::egui;
use eframe::egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Settings, ZieglerApp};

/// Types `text` into the number field labelled `key` and presses Enter.
fn type_into(harness: &mut Harness<'_>, key: &str, text: &str) {
    harness.get_by_role_and_label(Role::SpinButton, key).focus();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness
        .get_by_role_and_label(Role::SpinButton, key)
        .type_text(text);
    harness.key_press(egui::Key::Enter);
    harness.run();
}

#[test]
fn a_bad_value_typed_into_a_field_is_refused_on_screen() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let nu_before = app.settings().model.roller().unwrap().mass_kg;
    {
        let mut harness = Harness::builder()
            .with_size([1280.0, 800.0])
            .build_ui(|ui| app.contents_ui(ui));
        harness.run();
        type_into(&mut harness, "nu", "-1");
        harness.get_by_label_contains("refused: nu = -1: must be");
        // A good value is taken, and the refusal goes away.
        type_into(&mut harness, "nu", "0.5");
        assert!(harness.query_by_label_contains("refused:").is_none());
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
        let mut harness = Harness::builder()
            .with_size([1280.0, 800.0])
            .build_ui(|ui| app.contents_ui(ui));
        harness.run();
        type_into(&mut harness, "load p = P l/k", "1e6");
        harness.get_by_label_contains("is beyond the plotted range");
    }
    assert_eq!(app.settings().model.load_p(), 1e6);
}
