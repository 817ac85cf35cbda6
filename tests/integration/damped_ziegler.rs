//! The Ziegler destabilization paradox: joint dampers lower the flutter load,
//! and the limit as damping vanishes is not the undamped value. Checked
//! against Semler et al.'s closed form for the 1952 column (the Routh-Hurwitz
//! boundary) and the published vanishing-damping limits for all three ideal
//! columns (physics.md section 7). A damped crossing is a transversal one, so
//! this also exercises the Brent polishing of the critical load.

use crate::common;

use common::{assert_close, model, transitions};
use zieglerlab::analysis::State;

/// Flutter load of a preset with dampers `g_i = c_i / sqrt(k m l^2)`; here
/// k = 0.1, m = 1, l = 1, so `c_i = g_i sqrt(0.1)`.
fn damped_flutter_load(preset: &str, g1: f64, g2: f64) -> f64 {
    let scale = 0.1f64.sqrt();
    let c1 = format!("c1={}", g1 * scale);
    let c2 = format!("c2={}", g2 * scale);
    let t = transitions(&model(preset, &[&c1, &c2]), 10.0);
    assert_eq!(
        (t[0].from, t[0].to),
        (State::Stable, State::Flutter),
        "{t:?}"
    );
    t[0].load
}

fn semler(g1: f64, g2: f64) -> f64 {
    (4.0 * g1 * g1 + 33.0 * g1 * g2 + 4.0 * g2 * g2)
        / (2.0 * (g1 * g1 + 7.0 * g1 * g2 + 6.0 * g2 * g2))
        + g1 * g2 / 2.0
}

#[test]
fn semler_formula_at_several_dampers() {
    for (g1, g2) in [
        (0.1, 0.1),
        (0.02, 0.3),
        (0.5, 0.05),
        (1.0, 1.0),
        (0.3, 0.7),
        (1e-3, 2e-3),
    ] {
        assert_close(
            damped_flutter_load("ziegler-1952", g1, g2),
            semler(g1, g2),
            1e-9,
        );
    }
}

#[test]
fn vanishing_equal_damping_limits() {
    // The boundary moves as g^2 (Semler: 41/28 + g^2/2), so g = 1e-5 is within 1e-10.
    let g = 1e-5;
    assert_close(damped_flutter_load("ziegler-1952", g, g), 41.0 / 28.0, 1e-9);
    assert_close(damped_flutter_load("uniform-rods", g, g), 74.0 / 45.0, 1e-9);
    assert_close(
        damped_flutter_load("midpoint-masses", g, g),
        39.0 / 22.0,
        1e-9,
    );
}

#[test]
fn vanishing_damping_limit_spans_one_third_to_two_over_the_ratio() {
    let g = 1e-4;
    // Damping almost only at the joint A: the limit tends to 1/3.
    let low = damped_flutter_load("ziegler-1952", g * 1e-3, g);
    assert_close(low, semler(g * 1e-3, g), 1e-9);
    assert!((low - 1.0 / 3.0).abs() < 1e-2, "{low}");
    // Almost only at the clamp O: the limit tends to 2, below the undamped 2.0858.
    let high = damped_flutter_load("ziegler-1952", g, g * 1e-3);
    assert_close(high, semler(g, g * 1e-3), 1e-9);
    assert!((high - 2.0).abs() < 1e-2, "{high}");
}
