//! The flutter and divergence loads of the ideal (follower-loaded) two-rod
//! columns against their closed forms (physics.md section 7), to 1e-9: the
//! three presets, and a column with unequal rods, masses and springs through
//! the general two-degree-of-freedom formula. These are the numbers a lecture
//! quotes; the app's load slider shades its ranges from them.

use crate::common;

use common::{assert_close, model, transitions};
use zieglerlab::analysis::State;
use zieglerlab::model::Model;

fn flutter_and_divergence(model: &Model) -> (f64, f64) {
    let t = transitions(model, 20.0);
    assert_eq!(t.len(), 2, "{t:?}");
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Flutter));
    assert_eq!((t[1].from, t[1].to), (State::Flutter, State::Divergence));
    (t[0].load, t[1].load)
}

#[test]
fn ziegler_1952() {
    let (flutter, divergence) = flutter_and_divergence(&model("ziegler-1952", &[]));
    assert_close(flutter, 3.5 - 2f64.sqrt(), 1e-9);
    assert_close(divergence, 3.5 + 2f64.sqrt(), 1e-9);
}

#[test]
fn uniform_rods() {
    let (flutter, divergence) = flutter_and_divergence(&model("uniform-rods", &[]));
    assert_close(flutter, 2.0 * (9.0 - 7f64.sqrt()) / 5.0, 1e-9);
    assert_close(divergence, 2.0 * (9.0 + 7f64.sqrt()) / 5.0, 1e-9);
}

#[test]
fn midpoint_masses() {
    let (flutter, divergence) = flutter_and_divergence(&model("midpoint-masses", &[]));
    assert_close(flutter, 3.0, 1e-9);
    assert_close(divergence, 13.0 / 3.0, 1e-9);
}

/// `P = (beta0 -/+ 2 sqrt((a c - b^2) k1 k2)) / (l1 (b + c))` with
/// `beta0 = a k2 + c (k1 + k2) + 2 b k2`, on the common axis `p = P l1 / k1`.
#[test]
fn general_two_dof_formula_unequal_rods() {
    let m = model(
        "uniform-rods",
        &[
            "l1=1.3",
            "l2=0.7",
            "m1=0.8",
            "m2=2.1",
            "m_tip=0.4",
            "k1=0.25",
            "k2=0.1",
            "s2=0.2",
        ],
    );
    let inertia = m.inertia();
    let (a, b, c) = (inertia.a_kg_m2, inertia.b_kg_m2, inertia.c_kg_m2);
    let (k1, k2, l1) = (0.25, 0.1, 1.3);
    let beta0 = a * k2 + c * (k1 + k2) + 2.0 * b * k2;
    let root = 2.0 * ((a * c - b * b) * k1 * k2).sqrt();
    let to_p = |force_n: f64| force_n * l1 / k1;
    let (flutter, divergence) = flutter_and_divergence(&m);
    assert_close(flutter, to_p((beta0 - root) / (l1 * (b + c))), 1e-9);
    assert_close(divergence, to_p((beta0 + root) / (l1 * (b + c))), 1e-9);

    // At the onset the two pairs meet at omega^4 = k1 k2 / det M. A double
    // eigenvalue is only resolved to about sqrt(machine epsilon).
    let omega = (k1 * k2 / (a * c - b * b)).powf(0.25);
    for z in common::eigenvalues(&m.at_load(flutter)) {
        assert_close(z.im.abs(), omega, 1e-6);
        assert!(z.re.abs() < 1e-6 * omega, "{z}");
    }
}

/// Whatever the search range (and so wherever the samples fall relative to
/// the double root), the flutter load is found, to the same precision.
#[test]
fn found_for_every_search_range() {
    use zieglerlab::analysis::{AffinePencil, critical_loads};
    for (name, flutter) in [
        ("midpoint-masses", 3.0),
        ("ziegler-1952", 3.5 - 2f64.sqrt()),
    ] {
        let pencil = AffinePencil::new(&model(name, &[])).unwrap();
        for i in 0..40 {
            let load_max = 3.2 + 0.137 * f64::from(i);
            let t = critical_loads(&pencil, 0.0, load_max).unwrap();
            assert_eq!(
                (t[0].from, t[0].to),
                (State::Stable, State::Flutter),
                "{name} {load_max}"
            );
            assert_close(t[0].load, flutter, 1e-9);
        }
    }
}

/// A range as wide as the load allows (1e150) is bracketed decade by decade
/// beyond the column's own range: the closed-form pair near p = 2 is found
/// as on the range 0 to 20 (a 1000-load grid over the whole range once
/// stepped past it and answered "none").
#[test]
fn the_widest_load_range_keeps_the_closed_form_loads() {
    let column = model("ziegler-1952", &[]);
    let t = transitions(&column, 1e150);
    assert!(t.len() >= 2, "{t:?}");
    assert_eq!((t[0].from, t[0].to), (State::Stable, State::Flutter));
    assert_eq!((t[1].from, t[1].to), (State::Flutter, State::Divergence));
    assert_close(t[0].load, 3.5 - 2f64.sqrt(), 1e-9);
    assert_close(t[1].load, 3.5 + 2f64.sqrt(), 1e-9);
}
