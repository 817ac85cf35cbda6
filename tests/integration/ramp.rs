//! The quasi-static ramp in the app: the load rises at the set rate in
//! simulated time, a pause holds it, and the motion becomes visible past the
//! theory's onset, later the faster the ramp (growth takes time).

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Settings, ZieglerApp};
use zieglerlab::model::PresetId;
use zieglerlab::sim::Ramp;

fn tabletop() -> ZieglerApp {
    ZieglerApp::new(Settings {
        preset: PresetId::Tabletop,
        model: PresetId::Tabletop.model(),
        ..Settings::default()
    })
    .unwrap()
}

/// Started from its panel (0 to 8 at 0.1 per second by default): after one
/// simulated second the load is 0.1; paused, it holds while the run goes on;
/// resumed, it moves again.
#[test]
fn the_ramp_raises_the_load_at_its_rate_and_a_pause_holds_it() {
    let mut app = tabletop();
    let frame = 1.0 / 60.0;
    let click = |app: &mut ZieglerApp, labels: &[&str]| {
        let mut harness = Harness::builder()
            .with_size([1280.0, 800.0])
            .build_ui(|ui| app.contents_ui(ui));
        harness.run();
        for label in labels {
            harness.get_by_label(label).click();
            harness.run();
        }
    };
    click(&mut app, &["ramp the load", "start ramp"]);
    assert_eq!(app.settings().model.load_p(), 0.0);
    for _ in 0..60 {
        app.advance(frame);
    }
    let load = app.settings().model.load_p();
    assert!((load - 0.1).abs() < 1e-9, "after 1 s: {load}");
    click(&mut app, &["ramp the load", "pause ramp"]);
    let t = app.simulation().time_secs();
    for _ in 0..60 {
        app.advance(frame);
    }
    assert!(app.simulation().time_secs() > t + 0.9, "the run goes on");
    assert!(
        (app.settings().model.load_p() - load).abs() < 1e-12,
        "paused"
    );
    click(&mut app, &["ramp the load", "resume"]);
    for _ in 0..60 {
        app.advance(frame);
    }
    let resumed = app.settings().model.load_p();
    assert!((resumed - 0.2).abs() < 1e-9, "resumed: {resumed}");
}

/// The load at which the tabletop column's motion became visible on a ramp
/// from 2 at `rate` per simulated second.
fn seen_at(rate: f64) -> f64 {
    let mut app = tabletop();
    app.apply(zieglerlab::app::Action::RampStart(
        Ramp::new(2.0, 8.0, rate).unwrap(),
    ));
    for _ in 0..60 * 60 {
        app.advance(1.0 / 60.0);
        if let Some(seen) = app.state().ramp().unwrap().seen_at_p {
            return seen;
        }
    }
    panic!("no visible motion within a minute at rate {rate}");
}

/// The theory puts the onset at the flutter load 2 (9 - sqrt 7) / 5; the
/// motion, grown from the standard 1e-3 rad start, shows later, and the lag
/// grows with the rate.
#[test]
fn the_motion_shows_past_the_theory_s_onset_and_later_on_a_faster_ramp() {
    let onset = 2.0 * (9.0 - 7f64.sqrt()) / 5.0;
    let (slow, fast) = (seen_at(0.05), seen_at(0.4));
    assert!(slow > onset, "slow ramp: seen at {slow}, onset {onset}");
    assert!(fast > slow, "fast ramp: seen at {fast}, slow at {slow}");
}
