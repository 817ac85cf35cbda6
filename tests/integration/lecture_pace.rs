//! The lecture-pace presets: flutter a class can watch grow. At 1.2 times
//! the flutter load the unstable pair must have a period of at most 2 s and
//! an e-folding time of at most 5 s. The tabletop column is the uniform rods
//! at `a = 10 1/s^2`, so its loads are the uniform rods' closed forms and
//! its eigenvalues those of the paper's uniform rods (`a = 0.1 1/s^2`) times
//! `sqrt(10 / 0.1) = 10`: a scaling law, checked here, not assumed.

use crate::common;

use common::{assert_close, eigenvalues, model, set_distance, transitions};
use zieglerlab::analysis::{C64, State};
use zieglerlab::model::Model;

/// The eigenvalue with the largest real part.
fn fastest(model: &Model) -> C64 {
    eigenvalues(model)
        .into_iter()
        .max_by(|a, b| a.re.total_cmp(&b.re))
        .unwrap()
}

/// Period and e-folding time of the growing pair, in s.
fn period_and_efold_secs(lambda: C64) -> (f64, f64) {
    (std::f64::consts::TAU / lambda.im.abs(), 1.0 / lambda.re)
}

/// The ideal uniform rods' flutter load, `2 (9 - sqrt 7) / 5`.
fn uniform_flutter_p() -> f64 {
    2.0 * (9.0 - 7f64.sqrt()) / 5.0
}

#[test]
fn the_tabletop_column_flutters_at_the_uniform_rods_load_ten_times_faster() {
    let t = transitions(&model("tabletop", &[]), 10.0);
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Flutter));
    assert_close(t[0].load, uniform_flutter_p(), 1e-9);
    assert_close(t[1].load, 2.0 * (9.0 + 7f64.sqrt()) / 5.0, 1e-9);
    for p in [1.0, 2.0, 1.2 * uniform_flutter_p(), 6.0] {
        let load = format!("load={p}");
        let desk = eigenvalues(&model("tabletop", &[&load]));
        let paper: Vec<C64> = eigenvalues(&model("uniform-rods", &[&load]))
            .into_iter()
            .map(|z| 10.0 * z)
            .collect();
        assert!(
            set_distance(&desk, &paper) < 1e-9,
            "p = {p}: {desk:?} against {paper:?}"
        );
    }
}

#[test]
fn at_1_2_times_the_flutter_load_the_tabletop_column_grows_within_seconds() {
    let load = format!("load={}", 1.2 * uniform_flutter_p());
    let (period, efold) = period_and_efold_secs(fastest(&model("tabletop", &[&load])));
    assert!(period <= 2.0, "period {period} s");
    assert!(efold <= 5.0, "e-folding time {efold} s");
}

/// The roller version flutters (weakly) from a far lower load, the
/// roller's mass-induced instability, whose growth takes minutes there; at
/// 1.2 times the ideal column's flutter load its unstable pair grows within
/// seconds, as the ideal column's does.
#[test]
fn the_tabletop_roller_grows_within_seconds_past_the_ideal_column_s_load() {
    let t = transitions(&model("tabletop-roller", &[]), 10.0);
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Flutter));
    assert!(t[0].load < 0.1 * uniform_flutter_p(), "{t:?}");
    let near_onset = format!("load={}", 1.2 * t[0].load);
    let (_, slow_efold) = period_and_efold_secs(fastest(&model("tabletop-roller", &[&near_onset])));
    assert!(
        slow_efold > 60.0,
        "e-folding time near the weak onset {slow_efold} s"
    );
    let load = format!("load={}", 1.2 * uniform_flutter_p());
    let (period, efold) = period_and_efold_secs(fastest(&model("tabletop-roller", &[&load])));
    assert!(period <= 2.0, "period {period} s");
    assert!(efold <= 5.0, "e-folding time {efold} s");
}
