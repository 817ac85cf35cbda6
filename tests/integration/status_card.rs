//! The status card as the window shows it (`egui_kittest`; a label's text
//! is its accesskit value): the mode it describes, and the run's
//! measurement of that same mode.

use egui_kittest::kittest::{NodeT as _, Queryable as _};
use zieglerlab::analysis::classify;
use zieglerlab::app::{Action, Settings, ZieglerApp};
use zieglerlab::model::PresetId;

/// The tabletop column at p = 1, undamped, swings in two modes (2.1964 and
/// 10.3257 rad/s). The card names the mode it describes, and the
/// eigenvalue measured from the run beside it is of that mode, not the
/// other (it showed "frequency 2.1964 rad/s" beside "measured from the run
/// +0.00000 ± 10.3257i").
#[test]
fn the_card_measures_the_mode_it_describes() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Preset(PresetId::Tabletop));
    app.state_mut().settle_analysis();
    app.apply(Action::Speed(10.0));
    for _ in 0..30 {
        app.advance(0.1);
    }
    let spectrum = app.state().current_spectrum().unwrap().clone();
    let card = classify(&spectrum.eigenvalues, spectrum.scale_per_s).dominant;
    let measured = app
        .state()
        .measured()
        .expect("measured after 30 s")
        .to_vec();
    assert!(measured.len() >= 2, "{measured:?}");
    let harness = crate::app_input::harness(&mut app);
    let slower = card.im.abs() < 5.0;
    let mode = if slower { "mode 1 of 2" } else { "mode 2 of 2" };
    let frequency_line = harness
        .get_by_label_contains("(period ")
        .accesskit_node()
        .value()
        .unwrap_or_default();
    assert!(frequency_line.contains(mode), "{frequency_line}");
    // The card's line (the locus's legend says "measured from the run" too).
    let measured_line = harness
        .query_all_by_label_contains("measured from the run")
        .filter_map(|node| node.accesskit_node().value())
        .find(|text| text.contains("growth "))
        .expect("the card's measured line");
    assert!(
        measured_line.contains(&format!("({mode})")),
        "{measured_line}"
    );
    // "growth +0.00042 ± 0.00030 1/s, frequency 2.1964 ± 0.0002 rad/s".
    // or "(-1.33 ± 0.46)e-7", or "2.196425 ± <0.000001".
    let measurement = |name: &str| -> (f64, f64) {
        let after = measured_line.split(name).nth(1).expect(name);
        let text = after.split([',', '/']).next().expect(name);
        let (scale, text) = match text.split_once(")e") {
            Some((inner, exponent)) => {
                let exponent: i32 = exponent.split_whitespace().next().unwrap().parse().unwrap();
                (10f64.powi(exponent), inner.trim_start_matches('('))
            }
            None => (1.0, text),
        };
        let (value, uncertainty) = text.split_once('±').expect("±");
        let value: f64 = value.trim().parse().expect(name);
        let uncertainty = uncertainty.split_whitespace().next().unwrap();
        let uncertainty: f64 = uncertainty.trim_start_matches('<').parse().expect(name);
        (value * scale, uncertainty * scale)
    };
    // The value shown is the card's mode's, to the fit's accuracy, and its
    // uncertainty covers the prediction.
    let (frequency, frequency_uncertainty) = measurement("frequency ");
    let (growth, growth_uncertainty) = measurement("growth ");
    assert!(
        (frequency - card.im.abs()).abs() < 1e-3 * card.im.abs(),
        "{frequency} against {}",
        card.im.abs()
    );
    assert!(
        frequency_uncertainty < 1e-3 * card.im.abs(),
        "{measured_line}"
    );
    assert!(
        (growth - card.re).abs() <= 3.0 * growth_uncertainty + 1e-6,
        "{measured_line}: the prediction's growth is {}",
        card.re
    );
}

/// Past a damped column's flutter onset the card says the onset was soft
/// (the first Lyapunov coefficient is negative: a limit cycle grows from
/// zero, as the simulation shows); an undamped column's card says it has no
/// limit cycle to settle on.
#[test]
fn the_card_says_whether_flutter_set_in_softly() {
    use zieglerlab::analysis::{HopfKind, HopfSteps, hopf_at};
    use zieglerlab::model::Key;
    let line_of = |sets: &[(Key, f64)]| {
        let mut app = ZieglerApp::new(Settings::default()).unwrap();
        app.apply(Action::Preset(PresetId::Ziegler1952));
        for &(key, value) in sets {
            app.apply(Action::Enter { key, value });
        }
        app.state_mut().settle_analysis();
        let harness = crate::app_input::harness(&mut app);
        harness
            .query_all_by_label_contains("onset")
            .chain(harness.query_all_by_label_contains("no damping"))
            .find_map(|node| node.accesskit_node().value())
            .unwrap_or_default()
    };
    let damped = [(Key::C1, 0.3), (Key::C2, 0.3), (Key::Load, 2.5)];
    let line = line_of(&damped);
    let mut model = PresetId::Ziegler1952.model();
    model.column.c1_nms_per_rad = 0.3;
    model.column.c2_nms_per_rad = 0.3;
    let onset = crate::common::transitions(&model, 10.0)[0].load;
    let hopf = hopf_at(&model, onset, HopfSteps::DEFAULT).unwrap().unwrap();
    assert_eq!(hopf.kind, HopfKind::Supercritical);
    assert!(
        line.starts_with(&format!("soft onset at p = {onset:.4}")),
        "{line}"
    );
    let undamped = line_of(&[(Key::Load, 3.0)]);
    assert!(
        undamped.starts_with("no damping: no limit cycle"),
        "{undamped}"
    );
    assert!(!line.contains("sticking"), "{line}");
}

/// The roller's card, past its (soft) onset, says that the cycle holds only
/// until the contact nears sticking on the band: stick-slip, which the
/// smooth analysis does not follow, sets in within a few hundredths of the
/// load past the onset.
#[test]
fn the_roller_s_card_says_where_the_smooth_cycle_ends() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Preset(PresetId::Roller));
    app.apply(Action::Enter {
        key: zieglerlab::model::Key::Load,
        value: 1.0,
    });
    app.state_mut().settle_analysis();
    let harness = crate::app_input::harness(&mut app);
    let line = harness
        .query_all_by_label_contains("onset")
        .find_map(|node| node.accesskit_node().value())
        .unwrap_or_default();
    assert!(line.starts_with("soft onset at p = 0.0238"), "{line}");
    assert!(line.contains("until the roller nears sticking"), "{line}");
}
