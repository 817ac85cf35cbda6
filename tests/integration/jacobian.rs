//! The analytic linearization (physics.md section 4) against a central
//! finite-difference Jacobian of the nonlinear equations of motion at the
//! straight column, for every preset at several loads, with and without
//! joint dampers. The simulation integrates the nonlinear function and the
//! root locus uses the matrices: this is what ties the two together.

use crate::common;

use nalgebra::DMatrix;
use zieglerlab::model::{Model, StateVec, linearize, state_derivative};

/// `[[0, I], [-M^-1 K, -M^-1 D]]` over the model's state entries.
fn analytic(model: &Model) -> DMatrix<f64> {
    let lin = linearize(model).unwrap();
    let n = lin.mass.nrows();
    let minv = lin.mass.clone().try_inverse().unwrap();
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    a.view_mut((0, n), (n, n))
        .copy_from(&DMatrix::identity(n, n));
    a.view_mut((n, 0), (n, n))
        .copy_from(&(-&minv * &lin.stiffness));
    a.view_mut((n, n), (n, n))
        .copy_from(&(-&minv * &lin.damping));
    a
}

/// Central differences of `state_derivative` at rest, over the state entries
/// the model uses (positions then rates, as in the companion form).
fn finite_difference(model: &Model) -> DMatrix<f64> {
    let n = model.dof();
    let entries: Vec<usize> = (0..n).chain(3..3 + n).collect();
    let h = 1e-6;
    let mut j = DMatrix::zeros(2 * n, 2 * n);
    for (col, &e) in entries.iter().enumerate() {
        let mut plus = StateVec::zeros(6);
        let mut minus = StateVec::zeros(6);
        plus[e] = h;
        minus[e] = -h;
        let df = (state_derivative(model, &plus) - state_derivative(model, &minus)) / (2.0 * h);
        for (row, &r) in entries.iter().enumerate() {
            j[(row, col)] = df[r];
        }
    }
    j
}

#[test]
fn analytic_linearization_matches_finite_differences() {
    let presets = [
        "ziegler-1952",
        "uniform-rods",
        "midpoint-masses",
        "roller",
        "roller-as-printed",
    ];
    for name in presets {
        for dampers in [&[][..], &["c1=0.03", "c2=0.011"][..]] {
            for load in [0.0, 0.7, 2.5, 6.0] {
                let model = common::model(name, dampers).at_load(load);
                let analytic = analytic(&model);
                let numeric = finite_difference(&model);
                let error = (&analytic - &numeric).abs().max() / analytic.abs().max();
                assert!(
                    error < 1e-7,
                    "{name} {dampers:?} p={load}: relative error {error:e}\n{analytic}{numeric}"
                );
            }
        }
    }
}

/// The dead load is in the model too; its linearization is symmetric.
#[test]
fn dead_load_linearization_matches_finite_differences() {
    let mut model = common::model("uniform-rods", &["load=1.5"]);
    model.load = zieglerlab::model::Load::dead(model.follower_force_n());
    let error = (analytic(&model) - finite_difference(&model)).abs().max();
    assert!(error < 1e-7, "{error:e}");
    let lin = linearize(&model).unwrap();
    assert_eq!(lin.stiffness, lin.stiffness.transpose());
}

/// A partially tangential force: its stiffness `P l_i` off the diagonal
/// by `eta` (physics.md section 2) is the nonlinear equations' Jacobian.
#[test]
fn partial_follower_linearization_matches_finite_differences() {
    for eta in ["eta=0.25", "eta=0.7"] {
        let model = common::model("uniform-rods", &[eta, "load=2.2", "c2=0.02"]);
        let error = (analytic(&model) - finite_difference(&model)).abs().max();
        assert!(error < 1e-7, "{eta}: {error:e}");
    }
}

/// The external drag's damping matrix is the nonlinear drag's Jacobian, on
/// every preset (the roller's included) with unequal rods.
#[test]
fn external_drag_linearization_matches_finite_differences() {
    for name in ["ziegler-1952", "uniform-rods", "midpoint-masses", "roller"] {
        let model = common::model(name, &["c_ext=0.05", "l2=0.7", "load=1.3"]);
        let analytic = analytic(&model);
        let error = (&analytic - finite_difference(&model)).abs().max() / analytic.abs().max();
        assert!(error < 1e-7, "{name}: {error:e}");
    }
}
