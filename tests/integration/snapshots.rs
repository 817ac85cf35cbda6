//! What the app shows, as images: the whole window where its layout is the
//! point (the first launch, a refused field, the classroom's two screens),
//! the scene panel in each state of the motion, every tab of the registry.
//! These test
//! the pictures; the physics behind them is pinned by numeric tests. A run
//! before a picture uses the reference engine (f64, the same motion on
//! every machine), no wall clock is read, and `kittest.toml` allows a few
//! pixels to differ (antialiasing), not a moved curve or a changed colour.
//! Update with `UPDATE_SNAPSHOTS=1` and look at every new image before
//! committing it.

use egui_kittest::{Harness, SnapshotResults};
use zieglerlab::app::{Action, Panel, Settings, Tab, ZieglerApp};
use zieglerlab::model::{Key, PRESETS, preset};

/// The app in `settings`, at `load`, after `secs` whole seconds simulated
/// from the standard kick on the reference engine, in 1/60 s frames.
fn app_at(mut settings: Settings, load: f64, secs: u32) -> ZieglerApp {
    if secs > 0 {
        settings.engine = zieglerlab::sim::EngineKind::Reference;
    }
    let mut app = ZieglerApp::new(settings).unwrap();
    crate::common::enter(&mut app, Key::Load, load);
    for _ in 0..secs * 60 {
        app.advance(1.0 / 60.0);
    }
    app
}

fn window_snapshot(name: &str, mut app: ZieglerApp) {
    let mut harness = Harness::builder()
        .wgpu()
        .with_size([1280.0, 800.0])
        .build_ui(|ui| app.contents_ui(ui));
    harness.run_steps(4);
    harness.snapshot(name);
}

/// One panel of `app` alone, at a small size: a picture of that panel's
/// state, not of the window's layout.
fn panel_snapshot(name: &str, mut app: ZieglerApp, panel: Panel) {
    let mut harness = Harness::builder()
        .wgpu()
        .with_size([640.0, 480.0])
        .build_ui(|ui| app.panel_ui(ui, panel));
    harness.run_steps(4);
    harness.snapshot(name);
}

fn preset_settings(name: &str) -> Settings {
    Settings {
        preset: name.parse().unwrap(),
        model: preset(name).unwrap().model(),
        ..Settings::default()
    }
}

#[test]
fn default_launch() {
    window_snapshot("default_launch", app_at(Settings::default(), 1.0, 0));
}

#[test]
fn roller_in_flutter() {
    panel_snapshot(
        "scene_roller_flutter",
        app_at(Settings::default(), 3.0, 25),
        Panel::Scene,
    );
}

#[test]
fn roller_in_divergence() {
    panel_snapshot(
        "scene_roller_divergence",
        app_at(Settings::default(), 5.4, 12),
        Panel::Scene,
    );
}

#[test]
fn midpoint_masses_stable() {
    panel_snapshot(
        "scene_midpoint_masses_stable",
        app_at(preset_settings("midpoint-masses"), 1.5, 10),
        Panel::Scene,
    );
}

#[test]
fn projector_mode() {
    let settings = Settings {
        projector: true,
        ..Settings::default()
    };
    panel_snapshot("scene_projector", app_at(settings, 3.0, 25), Panel::Scene);
}

/// Every preset's root-locus panel is drawn over the column's own load
/// bar: one picture per panel and state is kept (the registry's tabs below,
/// the overlay); each preset's numbers are pinned by the numeric tests, not
/// by eleven images of the same panel.
#[test]
fn root_locus_panel_of_each_preset() {
    use egui_kittest::kittest::Queryable as _;
    for p in &PRESETS {
        let mut app = app_at(preset_settings(p.id.name()), 1.0, 0);
        let mut harness = Harness::builder()
            .with_size([960.0, 520.0])
            .build_ui(|ui| app.panel_ui(ui, Panel::Tab(Tab::Locus)));
        harness.run_steps(4);
        assert!(
            harness.query_by_label_contains("No root locus").is_none(),
            "{}",
            p.id
        );
        // The locus spans the column's own load bar (a chain's is shorter).
        harness.get_by_label_contains(&format!(
            "branch colour: the load, p = 0 to {}",
            zieglerlab::format::number_text(p.model().load_bar_max_p())
        ));
    }
}

/// Every tab of the app's registry, its background work complete: of the
/// roller (the map: nu against the load) and of the 1952 column (the map:
/// damping level against the load, the paradox in a picture), after 4 s
/// of the reference engine (f64, the same on every machine) from a kick.
#[test]
fn every_tab_of_the_registry() {
    let mut results = SnapshotResults::new();
    for name in ["roller", "ziegler-1952"] {
        for tab in Tab::all() {
            let panel = Panel::Tab(tab);
            let mut app = ZieglerApp::new(Settings {
                engine: zieglerlab::sim::EngineKind::Reference,
                ..preset_settings(name)
            })
            .unwrap();
            app.apply(Action::Command(zieglerlab::app::Command::Kick));
            for _ in 0..240 {
                app.advance(1.0 / 60.0);
            }
            app.complete_background_work(tab);
            let mut harness = Harness::builder()
                .wgpu()
                .with_size([900.0, 500.0])
                .build_ui(|ui| app.panel_ui(ui, panel));
            harness.run_steps(4);
            results.add(harness.try_snapshot(format!("tab_{}_{name}", tab.id())));
        }
    }
}

/// Two states a user must be able to read: a refused value typed into a
/// field (it stays, in red, with the reason under it), and the band stopped
/// (no linear analysis: the locus panel and the status card say why).
#[test]
fn a_refused_field_and_a_panel_without_analysis() {
    use eframe::egui;
    use egui_kittest::kittest::Queryable as _;
    let mut results = SnapshotResults::default();
    let mut refused = app_at(Settings::default(), 1.0, 0);
    let mut harness = Harness::builder()
        .wgpu()
        .with_size([1280.0, 800.0])
        .build_ui(|ui| refused.contents_ui(ui));
    harness.run();
    let field = || (egui::accesskit::Role::TextInput, "nu");
    harness.get_by_role_and_label(field().0, field().1).click();
    harness.run();
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness
        .get_by_role_and_label(field().0, field().1)
        .type_text("-1");
    harness.key_press(egui::Key::Enter);
    harness.run_steps(4);
    harness.snapshot("refused_field");
    results.extend(harness.take_snapshot_results());
    drop(harness);
    for (name, panel) in [
        ("band_stopped_scene", Panel::Scene),
        ("band_stopped_locus", Panel::Tab(Tab::Locus)),
    ] {
        let mut stopped = app_at(Settings::default(), 1.0, 0);
        crate::common::enter(&mut stopped, Key::V, 0.0);
        let mut harness = Harness::builder()
            .wgpu()
            .with_size([640.0, 480.0])
            .build_ui(|ui| stopped.panel_ui(ui, panel));
        harness.run_steps(4);
        results.add(harness.try_snapshot(name));
    }
    results.unwrap();
}

/// The roller's root locus with the ideal follower (uniform rods) drawn
/// behind it, as the paper's Fig. 8 compares them: the legend above the
/// plots names the overlay and lists its own critical loads, the uniform
/// rods' closed forms `2 (9 -/+ sqrt 7) / 5`.
#[test]
fn the_overlay_has_a_legend_with_its_own_critical_loads() {
    use zieglerlab::analysis::State;
    use zieglerlab::model::PresetId;
    let mut app = app_at(preset_settings("roller"), 1.0, 0);
    app.apply(Action::Overlay(Some(PresetId::UniformRods)));
    let overlay = app.state().overlay().unwrap();
    let closed_form = [
        (
            2.0 * (9.0 - 7f64.sqrt()) / 5.0,
            State::Stable,
            State::Flutter,
        ),
        (
            2.0 * (9.0 + 7f64.sqrt()) / 5.0,
            State::Flutter,
            State::Divergence,
        ),
    ];
    assert_eq!(overlay.transitions.len(), closed_form.len());
    for (shown, (load, from, to)) in overlay.transitions.iter().zip(closed_form) {
        assert!(
            (shown.load - load).abs() < 1e-9,
            "{shown} against p = {load}"
        );
        assert_eq!((shown.from, shown.to), (from, to));
    }
    let mut harness = Harness::builder()
        .wgpu()
        .with_size([960.0, 520.0])
        .build_ui(|ui| app.panel_ui(ui, Panel::Tab(Tab::Locus)));
    harness.run_steps(4);
    harness.snapshot("locus_roller_with_overlay");
}

/// The classroom's two screens: a 1024x768 projector in projector mode and
/// a 1920x1080 display, the tabletop column fluttering at p = 3 after 3 s
/// (the scene follows the motion; the load bar spans the window).
#[test]
fn classroom_screens() {
    let mut results = SnapshotResults::default();
    for (name, size, projector) in [
        ("tabletop_projector_1024x768", [1024.0, 768.0], true),
        ("tabletop_1920x1080", [1920.0, 1080.0], false),
    ] {
        let mut app = app_at(
            Settings {
                projector,
                ..preset_settings("tabletop")
            },
            3.0,
            3,
        );
        let mut harness = Harness::builder()
            .wgpu()
            .with_size(size)
            .build_ui(|ui| app.contents_ui(ui));
        harness.run_steps(4);
        results.add(harness.try_snapshot(name));
    }
}
