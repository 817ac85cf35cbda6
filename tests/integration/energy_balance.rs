//! The nonlinear equations of motion at large amplitude: along the flow,
//! the rate of change of the mechanical energy must equal the power of the
//! non-conservative forces (the load's, minus the dampers' dissipation).
//! This checks the mass matrix and the velocity-squared terms of section 3,
//! which the linearization test cannot see.

use crate::common;

use common::{energy_rate, states};
use zieglerlab::model::{Load, Model, StateVec, friction};

fn damper_power(model: &Model, x: &StateVec) -> f64 {
    let c = &model.column;
    -(c.c1_nms_per_rad * x[3] * x[3] + c.c2_nms_per_rad * (x[4] - x[3]).powi(2))
}

fn assert_balance(rate: f64, power: f64) {
    let error = (rate - power).abs() / power.abs().max(1e-3);
    assert!(error < 1e-6, "dE/dt {rate} vs power {power}: {error:e}");
}

#[test]
fn dead_load_is_conservative() {
    for preset in ["ziegler-1952", "uniform-rods", "midpoint-masses"] {
        let mut model = common::model(preset, &["load=2.2", "c1=0.02", "c2=0.05"]);
        let force_n = model.follower_force_n();
        model.load = Load::dead(force_n);
        let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
        // The force -P x has the potential P x_tip.
        let potential = |y: &StateVec| force_n * (l1 * y[0].cos() + l2 * y[1].cos());
        for x in states() {
            let x = StateVec::from_row_slice(&[x[0], x[1], 0.0, x[3], x[4], 0.0]);
            assert_balance(energy_rate(&model, &x, potential), damper_power(&model, &x));
        }
    }
}

#[test]
fn follower_force_power() {
    for preset in ["ziegler-1952", "uniform-rods", "midpoint-masses"] {
        let model = common::model(preset, &["load=3.1", "c1=0.01"]);
        let l1 = model.column.rod1.length_m;
        for x in states() {
            let x = StateVec::from_row_slice(&[x[0], x[1], 0.0, x[3], x[4], 0.0]);
            let load_power = -model.follower_force_n() * l1 * (x[1] - x[0]).sin() * x[3];
            let power = load_power + damper_power(&model, &x);
            assert_balance(energy_rate(&model, &x, |_| 0.0), power);
        }
    }
}

#[test]
fn roller_friction_power() {
    for preset in ["roller", "roller-as-printed"] {
        let model = common::model(preset, &["load=2.0", "c2=0.01"]);
        let Some(roller) = model.roller() else {
            panic!("no roller")
        };
        for x in states() {
            let q = friction(&model.column, roller, &x).generalized_n_m;
            let load_power = q[0] * x[3] + q[1] * x[4] + q[2] * x[5];
            let power = load_power + damper_power(&model, &x);
            assert_balance(energy_rate(&model, &x, |_| 0.0), power);
        }
    }
}
