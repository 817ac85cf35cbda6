//! The window as a screen reader reads it (the AccessKit tree that egui
//! builds and kittest exposes): every control named, the load bar's range,
//! value and the state at the load, the scene's words following the
//! column from stable to flutter, the plots described, the messages in a
//! live region.

use eframe::egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use zieglerlab::app::{Action, ZieglerApp};
use zieglerlab::model::Key;

/// The default window, its keys read as the real window reads them, its
/// first frames run.
fn app_harness() -> Harness<'static, ZieglerApp> {
    let mut harness = crate::app_lessons::keyed_harness();
    harness.run_steps(3);
    harness
}

/// The roles a person acts on.
const INTERACTIVE: [Role; 8] = [
    Role::Button,
    Role::CheckBox,
    Role::RadioButton,
    Role::Slider,
    Role::TextInput,
    Role::ComboBox,
    Role::SpinButton,
    Role::Tab,
];

#[test]
fn every_control_has_a_name() {
    let harness = app_harness();
    let mut seen = 0;
    for node in harness.query_all_by(|node| INTERACTIVE.contains(&node.role())) {
        let node = node.accesskit_node();
        let name = node.label().unwrap_or_default();
        assert!(
            !name.trim().is_empty(),
            "a {:?} without a name at {:?}",
            node.role(),
            node.bounding_box()
        );
        seen += 1;
    }
    assert!(seen > 20, "only {seen} controls found");
    // The scene and the plots are named images with a description.
    let scene = harness.get_by_role_and_label(Role::Image, "the column");
    assert!(
        !scene
            .accesskit_node()
            .description()
            .unwrap_or_default()
            .is_empty()
    );
    let plots: Vec<_> = harness
        .query_all_by(|node| {
            node.role() == Role::Image && node.label().is_some_and(|l| l.starts_with("plot: "))
        })
        .collect();
    assert!(!plots.is_empty());
    for plot in plots {
        let words = plot.accesskit_node().description().unwrap_or_default();
        assert!(words.contains(" against "), "{words}");
    }
}

/// The load bar says its range (0 to the bar's end, not ±1.8e308), its
/// value, and the state at the load with that state's range, as the
/// command line's critical loads give them.
#[test]
fn the_load_bar_reports_its_range_value_and_state() {
    let mut harness = app_harness();
    harness.state_mut().apply(Action::Enter {
        key: Key::Load,
        value: 2.5,
    });
    harness.run_steps(3);
    let load_max = harness.state().state().load_max();
    let bar = harness.get_by_role_and_label(Role::Slider, "load slider");
    let node = bar.accesskit_node();
    assert_eq!(node.min_numeric_value(), Some(0.0));
    assert_eq!(node.max_numeric_value(), Some(load_max));
    assert_eq!(node.numeric_value(), Some(2.5));
    let words = node.value().unwrap_or_default();
    // The roller's flutter from p = 0.0238 to 4.2641 (`critical`'s loads).
    let analysis = harness.state().state().analysis().unwrap();
    let flutter = analysis
        .ranges
        .iter()
        .find(|r| r.0 <= 2.5 && 2.5 <= r.1)
        .copied()
        .unwrap();
    assert_eq!(flutter.2, zieglerlab::analysis::State::Flutter);
    let expected = format!(
        "load p = 2.5 of 0 to 8: flutter, from p = {} to {}",
        zieglerlab::format::load_text(flutter.0),
        zieglerlab::format::load_text(flutter.1)
    );
    assert_eq!(words, expected);
    // A screen reader's increment moves it by a hundredth of the bar.
    bar.increment_accesskit();
    harness.run_steps(2);
    let p = harness.state().settings().model.load_p();
    assert!((p - (2.5 + 0.01 * load_max)).abs() < 1e-12, "{p}");
}

/// The scene's words follow the column: stable below the onset of
/// flutter, fluttering above, with the doubling time the growth rate
/// gives (ln 2 / Re λ).
#[test]
fn the_scene_says_stable_then_flutter_across_the_onset() {
    let mut harness = app_harness();
    let words = |h: &Harness<'_, ZieglerApp>| {
        h.get_by_role_and_label(Role::Image, "the column")
            .accesskit_node()
            .description()
            .unwrap_or_default()
    };
    for (load, expected) in [
        (0.01, "stable: a kick dies away"),
        (1.0, "the column flutters"),
    ] {
        harness.state_mut().apply(Action::Enter {
            key: Key::Load,
            value: load,
        });
        // Past the half second the words are kept for.
        harness.run_steps(40);
        let said = words(&harness);
        assert!(said.starts_with(expected), "p = {load}: {said}");
    }
    let rate =
        harness.state().state().current_spectrum().map(|s| {
            zieglerlab::analysis::classify(&s.eigenvalues, s.scale_per_s).growth_rate_per_s()
        });
    let doubling = 2f64.ln() / rate.unwrap();
    let said = words(&harness);
    let digits = 1.0 - doubling.log10().floor();
    let rounded = (doubling * 10f64.powf(digits)).round() / 10f64.powf(digits);
    assert!(
        said.contains(&format!(
            "doubling every {} s",
            zieglerlab::format::number_text(rounded)
        )),
        "{said} (doubling in {doubling} s)"
    );
}

/// A zoom past 200% or below 75% (Ctrl+Plus held, or a stored one) is
/// brought back into range, and the message line says so.
#[test]
fn the_zoom_stays_from_75_to_200_percent() {
    let mut harness = app_harness();
    for (asked, held, said) in [(3.0, 2.0, "zoom 300%"), (0.5, 0.75, "zoom 50%")] {
        harness.ctx.set_zoom_factor(asked);
        harness.run_steps(2);
        assert_eq!(harness.ctx.zoom_factor(), held);
        let line = crate::common::message_line(harness.state());
        assert!(
            line.contains(said) && line.contains("outside 75% to 200%"),
            "{line}"
        );
    }
}

/// At 200% on a 1280x800 screen the window shows 640x400 points: the
/// layout stays the smallest window's (1024x700), scrolled, so the
/// scene, the load bar and the card keep their sizes and the plots their
/// ticks, where they were squeezed and cut.
#[test]
fn a_window_zoomed_past_its_size_scrolls_its_layout() {
    let rects = |size: [f32; 2]| {
        let mut harness = Harness::builder().with_size(size).build_ui_state(
            |ui, app: &mut ZieglerApp| app.contents_ui(ui),
            ZieglerApp::new(zieglerlab::app::Settings::default()).unwrap(),
        );
        harness.run_steps(3);
        ["the column", "load slider"].map(|name| {
            harness
                .get_by(|node| node.label().as_deref() == Some(name))
                .rect()
        })
    };
    let zoomed = rects([640.0, 400.0]);
    let smallest = rects(zieglerlab::app::SMALLEST_WINDOW_POINTS);
    for (zoomed, smallest) in zoomed.iter().zip(&smallest) {
        assert!(
            (zoomed.size() - smallest.size()).length() < 1.0,
            "{zoomed:?} against {smallest:?}"
        );
    }
}

/// The post-critical diagram tells a screen reader where the cycles'
/// bifurcations are, not only that there are words on it: on the hard
/// onset (`ziegler-1952`, `c_ext = 0.05`, `m1 = 0.2`) its two folds of
/// cycles, at the loads and amplitudes `bifurcation` gives (p = 2.1303849
/// and 2.6903797, largest angles 0.3517 and 1.9298 rad).
#[test]
fn the_diagram_names_its_folds_with_their_loads() {
    use zieglerlab::app::Tab;
    use zieglerlab::model::PresetId;
    let mut harness = app_harness();
    let app = harness.state_mut();
    app.apply(Action::Preset(PresetId::Ziegler1952));
    app.apply(Action::Enter {
        key: Key::CExt,
        value: 0.05,
    });
    app.apply(Action::Enter {
        key: Key::M1,
        value: 0.2,
    });
    app.apply(Action::Tab(Tab::PostCritical));
    let mut said = String::new();
    // The branches are computed off the UI thread: frames until they are in.
    for _ in 0..1500 {
        harness.run_steps(1);
        said = harness
            .query_all_by(|node| {
                node.role() == Role::Image && node.label().is_some_and(|l| l.starts_with("plot: "))
            })
            .map(|plot| plot.accesskit_node().description().unwrap_or_default())
            .collect::<Vec<_>>()
            .join(" | ");
        if said.contains("named:") {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    assert!(
        said.contains("named: LPC at (2.13038, 0.351688); LPC at (2.69038, 1.92983)"),
        "{said}"
    );
}
