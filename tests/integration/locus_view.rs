//! The root locus's default view, drawn by the window at 1280x800 and
//! 1920x1080 (`egui_kittest`): it holds the eigenvalues that decide
//! stability (the status card's and the measured rings), and an eigenvalue
//! far off it is marked on its edge with its value instead of squeezing
//! the rest.

use eframe::egui;
use zieglerlab::analysis::C64;
use zieglerlab::app::{Action, LOCUS_SHOWN_ID, LocusShown, Settings, Side, ZieglerApp};
use zieglerlab::model::PresetId;

/// The view the locus tab drew in a window of `size` with `app`.
fn shown(app: &mut ZieglerApp, size: [f32; 2]) -> LocusShown {
    crate::app_input::harness_at(app, size)
        .ctx
        .data(|data| data.get_temp::<LocusShown>(egui::Id::unique(LOCUS_SHOWN_ID)))
        .expect("the locus tab drew its view")
}

/// The app on `preset`, its analysis done and run for `secs` simulated
/// seconds (at 10x, in frames of 0.1 s).
fn app_on(preset: PresetId, secs: usize) -> ZieglerApp {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Preset(preset));
    app.state_mut().settle_analysis();
    app.apply(Action::Speed(10.0));
    for _ in 0..secs {
        app.advance(0.1);
    }
    app
}

fn assert_holds(shown: &LocusShown, z: C64, what: &str) {
    assert!(
        shown.view.contains(z) && shown.view.contains(z.conj()),
        "{what} {z} outside the view {:?}",
        shown.view
    );
}

/// The roller at p = 1: its five moving eigenvalues at 0, +0.0017 ± 0.20i,
/// +0.0041 ± 0.92i (the pair the card reports) and the spin's settling
/// at -22.56. The four slow ones and the measured rings are in the view,
/// with room around the pair the card reports; the fast one is marked on
/// the left edge, at the real axis, with its value.
#[test]
fn the_rollers_view_holds_its_slow_pairs_and_marks_its_fast_root() {
    let mut app = app_on(PresetId::Roller, 30);
    let measured: Vec<C64> = app
        .state()
        .measured()
        .expect("measured after 30 s")
        .to_vec();
    let current = app.state().current_eigenvalues();
    let slow: Vec<C64> = current.iter().copied().filter(|z| z.norm() < 1.0).collect();
    assert_eq!(slow.len(), current.len() - 1, "{current:?}");
    let fast = current
        .iter()
        .copied()
        .find(|z| z.re < -20.0)
        .expect("the spin's settling");
    assert!((fast.re + 22.56).abs() < 0.01, "{fast}");
    for size in [[1280.0, 800.0], [1920.0, 1080.0]] {
        let shown = shown(&mut app, size);
        for &z in &slow {
            assert_holds(&shown, z, "eigenvalue");
        }
        for &z in &measured {
            assert_holds(&shown, z, "measured ring");
        }
        // Not cut at the edge: the card's pair with a fifth of its height to spare.
        assert!(shown.view.im.1 >= 1.2 * 0.92, "{size:?}: {:?}", shown.view);
        assert_eq!(shown.marks.len(), 1, "{size:?}: {:?}", shown.marks);
        let mark = &shown.marks[0];
        assert_eq!(mark.side, Side::Left);
        assert!(mark.at.im.abs() < 1e-9 && shown.view.contains(mark.at));
        assert!(mark.label.starts_with("-22.56"), "{}", mark.label);
        // The slow pairs are not squeezed to a point: the view is no
        // wider than a few times the largest of them.
        let width = shown.view.re.1 - shown.view.re.0;
        assert!(width < 10.0, "{size:?}: {:?}", shown.view);
    }
}

/// Ziegler's 1952 column at p = 1: undamped and stable, two pairs on the
/// imaginary axis, the faster at 0.4776i as the card says; both in the
/// view, nothing marked.
#[test]
fn ziegler_1952s_view_holds_both_pairs() {
    let mut app = app_on(PresetId::Ziegler1952, 30);
    let current = app.state().current_eigenvalues();
    let fastest = current.iter().map(|z| z.im).fold(0.0, f64::max);
    assert!((fastest - 0.4776).abs() < 1e-4, "{current:?}");
    let measured: Vec<C64> = app.state().measured().unwrap_or_default().to_vec();
    for size in [[1280.0, 800.0], [1920.0, 1080.0]] {
        let shown = shown(&mut app, size);
        for &z in current.iter().chain(&measured) {
            assert_holds(&shown, z, "eigenvalue");
        }
        assert!(
            shown.view.im.1 >= 1.2 * fastest,
            "{size:?}: {:?}",
            shown.view
        );
        assert!(shown.marks.is_empty(), "{:?}", shown.marks);
    }
}
