//! `roller-as-printed` reproduces the paper's printed linear system (39)
//! entry by entry, and it equals the consistent model with the spin inertia
//! multiplied by r/l2 (physics.md, erratum): the paper's third row is the
//! consistent one divided by rho, except its inertia.

use crate::common;

use common::{eigenvalues, model, set_distance};
use nalgebra::{DMatrix, dmatrix};
use zieglerlab::analysis::spectrum;
use zieglerlab::model::{LinearModel, linearize};

/// Eq. (39) per unit m l^2 with the paper's q = R l/k = p/mu.
fn printed_39(p: f64, nu: f64, rho: f64, mu: f64, a: f64, l: f64, v: f64) -> LinearModel {
    let q = p / mu;
    let g = q * mu * a * l / v;
    LinearModel {
        mass: dmatrix![
            4.0 / 3.0 + nu, 0.5 + nu, 0.0;
            0.5 + nu, 1.0 / 3.0 + nu * (1.0 + rho * rho / 4.0), 0.0;
            0.0, 0.0, 0.5 * nu * rho * rho
        ],
        damping: g * dmatrix![1.0, 1.0, -rho; 1.0, 1.0, -rho; -1.0, -1.0, rho],
        stiffness: a * dmatrix![
            2.0 - q * mu, -1.0, 0.0;
            -1.0, 1.0 - q * mu, 0.0;
            0.0, q * mu, 0.0
        ],
        extra_zero_roots: 0,
    }
}

#[test]
fn as_printed_matches_equation_39() {
    for (nu, rho, mu, a, v) in [(0.1, 0.1, 0.1, 0.1, 0.1), (0.3, 0.2, 0.4, 0.5, 0.05)] {
        for p in [0.2, 1.0, 2.6, 4.0, 5.0] {
            let sets: Vec<String> = [
                ("nu", nu),
                ("rho", rho),
                ("mu", mu),
                ("a", a),
                ("V", v),
                ("load", p),
            ]
            .iter()
            .map(|(k, x)| format!("{k}={x}"))
            .collect();
            let sets: Vec<&str> = sets.iter().map(String::as_str).collect();
            let ours = eigenvalues(&model("roller-as-printed", &sets));
            let paper = spectrum(&printed_39(p, nu, rho, mu, a, 1.0, v), p)
                .unwrap()
                .eigenvalues;
            let scale = paper.iter().map(|z| z.norm()).fold(0.0, f64::max);
            assert!(
                set_distance(&ours, &paper) < 1e-10 * scale,
                "p={p}: {ours:?} vs {paper:?}"
            );
        }
    }
}

#[test]
fn as_printed_is_consistent_model_with_scaled_spin_inertia() {
    for p in [0.5, 2.0, 3.0, 4.5] {
        let load = format!("load={p}");
        let consistent = model("roller", &[&load, "rho=0.2"]);
        let mut lin = linearize(&consistent).unwrap();
        let rho = 0.2;
        lin.mass[(2, 2)] *= rho;
        let scaled = spectrum(&lin, p).unwrap().eigenvalues;
        let printed = eigenvalues(&model("roller-as-printed", &[&load, "rho=0.2"]));
        assert!(set_distance(&scaled, &printed) < 1e-12, "p={p}");
        // And the erratum matters: the consistent model is different.
        assert!(
            set_distance(&eigenvalues(&consistent), &printed) > 1e-3,
            "p={p}"
        );
    }
}

#[test]
fn printed_damping_is_not_symmetric_but_consistent_is() {
    let lin = linearize(&model("roller", &[])).unwrap();
    assert_eq!(lin.damping, lin.damping.transpose());
    let paper = printed_39(1.0, 0.1, 0.1, 0.1, 0.1, 1.0, 0.1);
    assert_ne!(paper.damping, paper.damping.transpose());
    let _: &DMatrix<f64> = &paper.mass;
}
