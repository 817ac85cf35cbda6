//! The massless-roller limit (physics.md section 3): as m3 -> 0 the roller's
//! friction becomes the ideal follower force P = mu R on the uniform-rod
//! column. At m3 = 0 it is exact, in the linear analysis and in the
//! nonlinear equations; as m3 -> 0 the roller's finite eigenvalues converge to
//! the follower column's while the spin's relaxation -2 mu R/(m3 V) runs off.

use crate::common;

use common::{eigenvalues, model, set_distance};
use zieglerlab::analysis::{AffinePencil, C64};
use zieglerlab::model::{StateVec, friction, state_derivative};

const LOADS: [f64; 4] = [0.5, 2.0, 3.5, 5.5];

#[test]
fn massless_roller_is_exactly_the_follower_column() {
    for load in LOADS {
        let p = format!("load={load}");
        let roller = AffinePencil::new(&model("roller", &[&p, "m3=0"])).unwrap();
        let follower = eigenvalues(&model("uniform-rods", &[&p]));
        let spectrum = roller.spectrum(load).unwrap();
        assert_eq!(spectrum.structural_zeros, 1, "the spin angle stays free");
        assert!(
            set_distance(&spectrum.eigenvalues, &follower) < 1e-12,
            "p={load}"
        );
    }
}

/// Equal while the contact slips forward along rod 2 (`w . e2 > 0`: the band
/// outruns the tip), which is the regime of the experiment.
#[test]
fn massless_roller_equations_of_motion_are_the_follower_column() {
    let follower = model("uniform-rods", &["load=2.7"]);
    let roller = model("roller", &["load=2.7", "m3=0"]);
    for x in [
        StateVec::from_row_slice(&[0.3, -0.4, 0.0, 0.02, -0.05, 0.0]),
        StateVec::from_row_slice(&[-0.8, 0.6, 1.0, -0.01, 0.03, 7.0]),
    ] {
        let a = state_derivative(&follower, &x);
        let b = state_derivative(&roller, &x);
        for i in [3, 4] {
            assert!((a[i] - b[i]).abs() < 1e-13 * a[i].abs().max(1.0), "{a} {b}");
        }
    }
}

/// When the tip runs back along rod 2 faster than the band brings it forward,
/// even a massless roller's friction turns tensile: F = +mu R e2. No ideal
/// follower force does that.
#[test]
fn massless_roller_friction_reverses_when_the_tip_outruns_the_band() {
    let roller = model("roller", &["load=2.7", "m3=0"]);
    let x = StateVec::from_row_slice(&[0.3, -0.4, 0.0, 0.2, -0.5, 0.0]);
    let f = friction(&roller.column, roller.roller().unwrap(), &x);
    let e2 = nalgebra::Vector2::new(x[1].cos(), x[1].sin());
    assert!(f.slip_m_per_s.dot(&e2) < 0.0);
    assert!((f.force_n - roller.follower_force_n() * e2).norm() < 1e-15);
    assert!((f.delta_rad.abs() - std::f64::consts::PI).abs() < 1e-12);
}

#[test]
fn finite_eigenvalues_converge_as_roller_mass_vanishes() {
    for load in LOADS {
        let p = format!("load={load}");
        let follower = eigenvalues(&model("uniform-rods", &[&p]));
        let mut previous = f64::INFINITY;
        for nu in [1e-2, 1e-3, 1e-4, 1e-5] {
            let nu_set = format!("nu={nu}");
            let roller = model("roller", &[&p, &nu_set]);
            let mut spectrum = eigenvalues(&roller);
            // The fastest eigenvalue is the spin's relaxation.
            spectrum.sort_by(|a, b| a.norm().total_cmp(&b.norm()));
            let spin = spectrum.pop().unwrap();
            let mu_r = roller.follower_force_n();
            let v = roller.roller().unwrap().band_speed_m_per_s;
            let expected = C64::new(-2.0 * mu_r / (nu * v), 0.0);
            assert!(
                (spin - expected).norm() < 0.05 * expected.norm(),
                "{spin} vs {expected}"
            );
            let distance = set_distance(&spectrum, &follower);
            assert!(distance < 20.0 * nu, "p={load} nu={nu}: {distance:e}");
            assert!(distance < previous, "not converging: p={load} nu={nu}");
            previous = distance;
        }
    }
}
