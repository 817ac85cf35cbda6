//! The window's layout at the smallest screen it is made for, 1024x768,
//! normal and projector: every tab keeps within the window's width (a
//! hint row once widened the time histories past the right edge, cutting
//! the phase portrait, the load bar's end and the tabs).

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Action, Command, Settings, Tab, ZieglerApp};
use zieglerlab::model::PresetId;

/// Every tab of the ziegler-1952 column kicked and run for 25 s (the
/// measured eigenvalue has joined the legends by then), at 1024x768: the
/// load bar and the tab bar end inside the window.
#[test]
fn every_tab_keeps_within_a_1024_window() {
    for projector in [false, true] {
        for tab in Tab::all() {
            let mut settings = Settings {
                projector,
                preset: PresetId::Ziegler1952,
                ..Settings::default()
            };
            settings.model = PresetId::Ziegler1952.model().at_load(1.0);
            let mut app = ZieglerApp::new(settings).unwrap();
            app.apply(Action::Command(Command::Kick));
            app.advance(25.0);
            app.show_tab(tab);
            app.complete_background_work(tab);
            let mut harness = Harness::builder()
                .with_size([1024.0, 768.0])
                .build_ui(|ui| app.contents_ui(ui));
            harness.run_steps(4);
            let at = format!("{} (projector {projector})", tab.spec().id);
            for label in ["load slider", "post-critical", "root locus"] {
                let rect = harness.get_by_label(label).rect();
                assert!(
                    rect.left() >= 0.0 && rect.right() <= 1024.0,
                    "{at}: {label} at {rect:?}"
                );
            }
        }
    }
}
