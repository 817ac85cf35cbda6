//! The window's layout at the smallest screen it is made for, 1024x768,
//! normal and projector: every tab keeps within the window's width (a
//! hint row once widened the time histories past the right edge, cutting
//! the phase portrait, the load bar's end and the tabs; a legend's last gap
//! widened the Re/Im plots under it).

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Action, Command, Settings, Tab, ZieglerApp};
use zieglerlab::model::PresetId;

/// Every tab of the ziegler-1952 column kicked, and of the roller left to
/// run, for 35 s (the measured eigenvalue has joined the legends by then),
/// at 1024x768 and at 1040x784 (a real 1024x768 window: the test's frame
/// has an 8-point margin): the load bar and the tab bar end inside the
/// window, and so does everything drawn.
#[test]
fn every_tab_keeps_within_a_1024_window() {
    for (preset, kick) in [(PresetId::Ziegler1952, true), (PresetId::Roller, false)] {
        for projector in [false, true] {
            for size in [[1024.0, 768.0], [1040.0, 784.0]] {
                for tab in Tab::all() {
                    let mut settings = Settings {
                        projector,
                        preset,
                        ..Settings::default()
                    };
                    settings.model = preset.model().at_load(1.0);
                    let mut app = ZieglerApp::new(settings).unwrap();
                    if kick {
                        app.apply(Action::Command(Command::Kick));
                    }
                    // In frames' steps: one long step is cut to the cap.
                    for _ in 0..70 {
                        app.advance(0.5);
                    }
                    app.show_tab(tab);
                    app.complete_background_work(tab);
                    let mut harness = Harness::builder()
                        .with_size(size)
                        .build_ui(|ui| app.contents_ui(ui));
                    harness.run_steps(4);
                    let at = format!(
                        "{} {} at {size:?} (projector {projector})",
                        preset.name(),
                        tab.spec().id
                    );
                    for label in ["load slider", "post-critical", "root locus"] {
                        let rect = harness.get_by_label(label).rect();
                        assert!(
                            rect.left() >= 0.0 && rect.right() <= size[0],
                            "{at}: {label} at {rect:?}"
                        );
                    }
                    let used = harness.ctx.globally_used_rect();
                    assert!(used.right() <= size[0], "{at}: drawn up to {used:?}");
                }
            }
        }
    }
}
