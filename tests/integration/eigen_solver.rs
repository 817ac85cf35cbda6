//! The eigenvalue solver against the closed-form roots of the ideal column's
//! characteristic polynomial, which is a quadratic in `s = lambda^2`:
//! `det M s^2 + (a K22 + c K11 - b (K12 + K21)) s + det K = 0`. Loads are
//! swept through flutter and divergence, and through a load next to the
//! uniform-rods collision where nalgebra's balanced Schur iteration stalls
//! (regression: the solver must fall back, not fail).

use crate::common;

use common::{model, pencil, set_distance};
use zieglerlab::analysis::C64;
use zieglerlab::model::linearize;

fn closed_form(name: &str, p: f64) -> Vec<C64> {
    let lin = linearize(&model(name, &[]).at_load(p)).unwrap();
    let (m, k) = (&lin.mass, &lin.stiffness);
    let (a, b, c) = (m[(0, 0)], m[(0, 1)], m[(1, 1)]);
    let qa = a * c - b * b;
    let qb = a * k[(1, 1)] + c * k[(0, 0)] - b * (k[(0, 1)] + k[(1, 0)]);
    let qc = k[(0, 0)] * k[(1, 1)] - k[(0, 1)] * k[(1, 0)];
    let root = C64::new(qb * qb - 4.0 * qa * qc, 0.0).sqrt();
    let s = [(-qb + root) / (2.0 * qa), (-qb - root) / (2.0 * qa)];
    s.iter().flat_map(|s| [s.sqrt(), -s.sqrt()]).collect()
}

#[test]
fn spectra_match_the_closed_form_roots() {
    for name in ["ziegler-1952", "uniform-rods", "midpoint-masses"] {
        for i in 0..=80 {
            let p = 0.1 * f64::from(i);
            let exact = closed_form(name, p);
            let ours = pencil(name, &[]).spectrum(p).unwrap().eigenvalues;
            let scale = exact.iter().map(|z| z.norm()).fold(0.0, f64::max);
            // Next to a double root both sides are exact only to sqrt(eps).
            assert!(set_distance(&ours, &exact) < 1e-7 * scale, "{name} p={p}");
        }
    }
}

#[test]
fn stalled_schur_falls_back() {
    let p = 2.541_796_874_999_999_3;
    let ours = pencil("uniform-rods", &[]).spectrum(p).unwrap().eigenvalues;
    assert!(set_distance(&ours, &closed_form("uniform-rods", p)) < 1e-9);
}
