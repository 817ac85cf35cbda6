//! The partially tangential tip force (Bolotin's, Reut's columns): its
//! direction turns by `eta` times the last rod's angle. Ziegler's 1952
//! column has closed forms for every `eta` (derived in `src/model/physics.md`):
//! the analysis must find them, both engines must run the linear column it
//! describes, and the roller, whose force the band sets, has no `eta`.

use crate::common;

use common::{assert_close, model, transitions};
use zieglerlab::analysis::State;
use zieglerlab::model::{Key, StateVec, apply_assignments, parse_assignment};

/// The smallest root of Ziegler's 1952 column's divergence condition
/// `p^2 - 3 p + 1/(1 - eta) = 0`, when it has real roots.
fn divergence_1952(eta: f64) -> Option<f64> {
    let disc = 9.0 - 4.0 / (1.0 - eta);
    (eta < 1.0 && disc >= 0.0).then(|| (3.0 - disc.sqrt()) / 2.0)
}

/// The smallest load where the two frequencies of Ziegler's 1952 column
/// merge: the discriminant `(4 eta^2 - 8 eta + 8) p^2 + (4 eta - 32) p + 41`
/// of `2 W^2 + (4 - 2 eta) p W - 7 W + (1 - eta)(p^2 - 3 p) + 1 = 0`, with
/// `W = omega^2 m l^2 / k`, vanishes.
fn flutter_1952(eta: f64) -> Option<f64> {
    let (a, b, c) = (4.0 * eta * eta - 8.0 * eta + 8.0, 4.0 * eta - 32.0, 41.0);
    let disc = b * b - 4.0 * a * c;
    (disc >= 0.0).then(|| (-b - disc.sqrt()) / (2.0 * a))
}

#[test]
fn a_dead_load_buckles_ziegler_s_column_by_divergence() {
    let t = transitions(&model("ziegler-1952", &["eta=0"]), 10.0);
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Divergence));
    assert_close(t[0].load, (3.0 - 5f64.sqrt()) / 2.0, 1e-9);
}

#[test]
fn half_tangency_diverges_at_one_restabilizes_at_two_then_flutters() {
    let t = transitions(&model("ziegler-1952", &["eta=0.5"]), 10.0);
    let states: Vec<_> = t.iter().map(|t| (t.from, t.to)).collect();
    assert_eq!(
        states,
        [
            (State::Stable, State::Divergence),
            (State::Divergence, State::Stable),
            (State::Stable, State::Flutter),
            (State::Flutter, State::Divergence),
        ]
    );
    assert_close(t[0].load, 1.0, 1e-9);
    assert_close(t[1].load, 2.0, 1e-9);
    // 5 p^2 - 30 p + 41 = 0.
    assert_close(t[2].load, 3.0 - 0.8f64.sqrt(), 1e-9);
    assert_close(t[3].load, 3.0 + 0.8f64.sqrt(), 1e-9);
}

#[test]
fn three_quarter_tangency_flutters_at_two() {
    let t = transitions(&model("ziegler-1952", &["eta=0.75"]), 10.0);
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Flutter));
    assert_close(t[0].load, 2.0, 1e-9);
    // 17 p^2 - 116 p + 164 = 0: the other root, 82/17.
    assert_eq!((t[1].from, t[1].to), (State::Flutter, State::Divergence));
    assert_close(t[1].load, 82.0 / 17.0, 1e-9);
}

/// From the dead load to the follower force, the first loss of stability is
/// the nearer of the two closed forms, of the kind that one says.
#[test]
fn the_first_instability_follows_the_closed_forms_for_every_eta() {
    for i in 0..=20 {
        let eta = f64::from(i) / 20.0;
        let column = model("ziegler-1952", &[&format!("eta={eta}")]);
        let first = transitions(&column, 10.0)[0];
        let divergence = divergence_1952(eta).unwrap_or(f64::INFINITY);
        let flutter = flutter_1952(eta).unwrap_or(f64::INFINITY);
        let (load, kind) = if divergence < flutter {
            (divergence, State::Divergence)
        } else {
            (flutter, State::Flutter)
        };
        assert_eq!(first.to, kind, "eta = {eta}");
        assert_close(first.load, load, 1e-9);
    }
    // Both ends are the classical columns.
    assert_close(flutter_1952(1.0).unwrap(), 3.5 - 2f64.sqrt(), 1e-12);
    assert_close(
        divergence_1952(0.0).unwrap(),
        (3.0 - 5f64.sqrt()) / 2.0,
        1e-12,
    );
}

/// Along the flow, dE/dt is the force's power
/// `P [l1 sin(phi1 - eta phi2) phi1' + l2 sin(phi2 - eta phi2) phi2']`
/// at large amplitude.
#[test]
fn the_partial_force_s_power_balances_the_energy() {
    for preset in ["ziegler-1952", "uniform-rods"] {
        let model = model(preset, &["load=2.7", "eta=0.4"]);
        let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
        let force_n = model.follower_force_n();
        for x in common::states() {
            let x = StateVec::from_row_slice(&[x[0], x[1], 0.0, x[3], x[4], 0.0]);
            let rate = common::energy_rate(&model, &x, |_| 0.0);
            let eta_phi2 = 0.4 * x[1];
            let power = force_n
                * (l1 * (x[0] - eta_phi2).sin() * x[3] + l2 * (x[1] - eta_phi2).sin() * x[4]);
            assert!(
                (rate - power).abs() <= 1e-6 * power.abs().max(1e-3),
                "{preset}: dE/dt {rate} vs power {power}"
            );
        }
    }
}

#[test]
fn eta_outside_zero_to_one_is_refused() {
    for text in ["eta=-0.1", "eta=1.5"] {
        let mut column = common::model("ziegler-1952", &[]);
        let error = apply_assignments(&mut column, &[parse_assignment(text).unwrap()]);
        let error = error.unwrap_err().to_string();
        assert!(error.starts_with("eta = "), "{error}");
    }
}

#[test]
fn the_roller_has_no_eta_and_says_why() {
    let mut roller = common::model("roller", &[]);
    let error = apply_assignments(&mut roller, &[parse_assignment("eta=0.5").unwrap()]);
    let error = error.unwrap_err().to_string();
    assert!(
        error.contains("the band's friction sets the force's direction"),
        "{error}"
    );
    assert!(Key::Eta.get(&roller).is_nan());
}
