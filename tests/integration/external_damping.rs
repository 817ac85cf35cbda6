//! External viscous drag along the rods (air drag): its power is the drag's
//! integral over the rods, its linearization is the nonlinear equations'
//! Jacobian, both engines damp at the rates the eigenvalues give, and as
//! damping vanishes the flutter load of Ziegler's column tends to the
//! limits the Routh-Hurwitz conditions give (`src/model/physics.md`
//! section 7): external damping destabilizes too.

use crate::common;

use common::{assert_close, model};
use zieglerlab::analysis::{first_instability, flutter_load_external};
use zieglerlab::model::StateVec;

/// The drag's power `-c_ext sum_i int_0^l_i v_perp(s)^2 ds` by Simpson's
/// rule from the rods' velocity field, not from the code's resultants.
fn drag_power_by_quadrature(model: &zieglerlab::model::Model, x: &StateVec) -> f64 {
    let c = model.column.drag_ns_per_m2;
    let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
    let (p1, p2, w1, w2) = (x[0], x[1], x[3], x[4]);
    let across = |angle: f64, v: [f64; 2]| -angle.sin() * v[0] + angle.cos() * v[1];
    // Velocity of a point at s along rod 1, and along rod 2.
    let on_rod1 = |s: f64| across(p1, [-s * w1 * p1.sin(), s * w1 * p1.cos()]);
    let on_rod2 = |s: f64| {
        let v = [
            -l1 * w1 * p1.sin() - s * w2 * p2.sin(),
            l1 * w1 * p1.cos() + s * w2 * p2.cos(),
        ];
        across(p2, v)
    };
    -c * (common::simpson(|s| on_rod1(s).powi(2), l1) + common::simpson(|s| on_rod2(s).powi(2), l2))
}

/// Along the flow, dE/dt = the drag's power plus the joint dampers' at
/// large amplitude, on every column (the load off, so nothing else works).
#[test]
fn the_drag_dissipates_its_integral_over_the_rods() {
    for preset in ["ziegler-1952", "uniform-rods", "midpoint-masses"] {
        let model = model(preset, &["load=0", "c_ext=0.07", "c2=0.01", "l2=0.6"]);
        for x in common::states() {
            let x = StateVec::from_row_slice(&[x[0], x[1], 0.0, x[3], x[4], 0.0]);
            let rate = common::energy_rate(&model, &x, |_| 0.0);
            let joints = -0.01 * (x[4] - x[3]).powi(2);
            let power = drag_power_by_quadrature(&model, &x) + joints;
            assert!(power < 0.0);
            assert!(
                (rate - power).abs() <= 1e-6 * power.abs(),
                "{preset}: dE/dt {rate} vs power {power}"
            );
        }
    }
}

/// As the damping vanishes with external drag and equal joint dampers in
/// the ratio `r = c_ext l^3 / c`, Ziegler's column first flutters at the
/// smaller root of
/// `(15 r^2 + 210 r) p^2 - (104 r^2 + 1467 r + 504) p + 148 r^2 + 2214 r + 738 = 0`:
/// 41/28 for internal damping alone, 2 for external alone; both below the
/// undamped 7/2 - sqrt 2.
#[test]
fn vanishing_external_and_internal_damping_give_the_routh_hurwitz_limits() {
    let column = model("ziegler-1952", &[]);
    let limit = |r: f64| {
        let (a, b, c) = (
            15.0 * r * r + 210.0 * r,
            -(104.0 * r * r + 1467.0 * r + 504.0),
            148.0 * r * r + 2214.0 * r + 738.0,
        );
        if a == 0.0 {
            -c / b
        } else {
            (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)
        }
    };
    assert_close(limit(0.0), 41.0 / 28.0, 1e-12);
    for r in [0.0, 0.1, 1.0, 10.0] {
        let load = flutter_load_external(&column, r, 1e-5, 10.0)
            .unwrap()
            .unwrap();
        assert_close(load, limit(r), 1e-6);
    }
    // External drag alone, vanishing: flutter at p = 2.
    let drag_only = model("ziegler-1952", &["c_ext=1e-6"]);
    let load = first_instability(&drag_only, 10.0).unwrap().unwrap();
    assert_close(load, 2.0, 1e-6);
    assert!(2.0 < 3.5 - 2f64.sqrt());
}
