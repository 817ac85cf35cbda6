//! The Jacobian of a chain's equations of motion in closed form, for a
//! tip force that turns with the last rod (follower, partial or dead load)
//! and the joints' springs and dampers: one factorization of the mass
//! matrix and 2N solves, where differences take 2N or more evaluations of
//! the equations (each its own factorization). Drag along the rods and the
//! roller are not written here.
//!
//! With `M(phi) phi'' = r(phi, phi')` (Lagrange's equations, see `chain`),
//! `M_jl = mu_jl cos(phi_j - phi_l)`, and `r_j = Q_j + T_j - sum_k mu_jk
//! sin(phi_j - phi_k) phi_k'^2` (joints, tip load, the centripetal terms),
//! the accelerations `a` have
//!
//! ```text
//! da/dphi_m  = M^-1 (dr/dphi_m - (dM/dphi_m) a),   da/dphi'_m = M^-1 dr/dphi'_m,
//! ```
//!
//! where `dM/dphi_m` has only row and column m. The follower force
//! `-P (cos theta, sin theta)`, `theta = eta phi_N`, works on rod j through
//! `l_j (-sin phi_j, cos phi_j)`: `T_j = -P l_j sin(theta - phi_j)`.

use nalgebra::{DMatrix, DVector};

use super::chain::{angles_trig, lagrange_rhs};
use super::loads::tip_load;
use super::mass::chain_inertia;
use super::params::{Load, Model};
use super::state::{StateVec, StateViewMut, state_len};

/// The Jacobian of the reduced field `(phi, phi') -> (phi', phi'')` of
/// `model`'s chain at these angles and rates, `2N x 2N`; `None` where the
/// equations are not covered (drag along the rods, the roller) or the mass
/// matrix cannot be factored.
#[must_use]
pub fn chain_jacobian(model: &Model, phi: &[f64], rate: &[f64]) -> Option<DMatrix<f64>> {
    let column = &model.column;
    let Load::Follower { force_n, eta } = model.load else {
        return None;
    };
    if column.drag_ns_per_m2 != 0.0 {
        return None;
    }
    let n = phi.len();
    let mut state = StateVec::zeros(state_len(n));
    let mut view = StateViewMut::new(&mut state);
    view.angles_rad().copy_from_slice(phi);
    view.rates_rad_per_s().copy_from_slice(rate);
    // The equations themselves (`chain::lagrange_rhs`): the mass matrix,
    // factored, and the accelerations. Factored dense here, not by its
    // structure as in the equations of motion (`chain_factor`): the two
    // Jacobians agree to 5e-14 of their largest entry, yet with the
    // structured one the shooting's Newton iterations on a 32-rod chain's
    // cycle next to its onset (whose monodromy this Jacobian builds) no
    // longer converged. They are that sensitive there; until that is
    // mended, this keeps the arithmetic they were tested with.
    let inertia = chain_inertia(model);
    let mu = inertia.matrix();
    let tip = tip_load(model, &state).generalized_n_m;
    let trig = angles_trig(&state);
    let r = lagrange_rhs(model, &inertia, &state, &tip[..n], &trig);
    let cos_diff = |j: usize, k: usize| trig[j].1 * trig[k].1 + trig[j].0 * trig[k].0;
    let factor = DMatrix::from_fn(n, n, |j, k| mu[(j, k)] * cos_diff(j, k)).cholesky()?;
    let a = factor.solve(&DVector::from_vec(r));

    let sin_diff = |j: usize, k: usize| trig[j].0 * trig[k].1 - trig[j].1 * trig[k].0;
    let theta = eta * phi[n - 1];
    let length = |j: usize| column.rod(j).length_m;

    // dr/dphi - (dM/dphi) a (left n columns) and dr/dphi' (right n).
    let mut rhs = DMatrix::<f64>::zeros(n, 2 * n);
    for i in 0..n {
        // Joint i's torque `-k_i b_i - c_i b_i'` on its bend `b_i = phi_i -
        // phi_{i-1}` acts on rod i (+) and back on rod i - 1 (-), through
        // the bend's dependence on phi_i (+1) and phi_{i-1} (-1).
        let (k, c) = (column.spring_nm_per_rad(i), column.damper_nms_per_rad(i));
        let bent: &[(usize, f64)] = if i == 0 {
            &[(0, 1.0)]
        } else {
            &[(i, 1.0), (i - 1, -1.0)]
        };
        for &(m, sign) in bent {
            rhs[(i, m)] -= k * sign;
            rhs[(i, n + m)] -= c * sign;
            if i > 0 {
                rhs[(i - 1, m)] += k * sign;
                rhs[(i - 1, n + m)] += c * sign;
            }
        }
    }
    for j in 0..n {
        let tip_slope = force_n * length(j) * (theta - phi[j]).cos();
        rhs[(j, j)] += tip_slope;
        rhs[(j, n - 1)] -= eta * tip_slope;
        for m in (0..n).filter(|&m| m != j) {
            let (s, c) = (sin_diff(j, m), cos_diff(j, m));
            // The centripetal term's and dM/dphi_m a's parts.
            rhs[(j, m)] += mu[(j, m)] * c * rate[m] * rate[m] - mu[(j, m)] * s * a[m];
            rhs[(j, j)] -= mu[(j, m)] * c * rate[m] * rate[m] - mu[(j, m)] * s * a[m];
            rhs[(j, n + m)] -= 2.0 * mu[(j, m)] * s * rate[m];
        }
    }
    let lower = factor.solve(&rhs);
    let mut jacobian = DMatrix::<f64>::zeros(2 * n, 2 * n);
    for i in 0..n {
        jacobian[(i, n + i)] = 1.0;
    }
    jacobian.view_mut((n, 0), (n, 2 * n)).copy_from(&lower);
    Some(jacobian)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{PresetId, StateVec, state_derivative, state_len};

    /// The reduced field `(phi, phi') -> (phi', phi'')` by the equations
    /// of motion themselves.
    fn field(model: &Model, x: &[f64]) -> Vec<f64> {
        let n = model.column.rods;
        let mut full = StateVec::zeros(state_len(n));
        full.as_mut_slice()[..n].copy_from_slice(&x[..n]);
        full.as_mut_slice()[n + 1..=2 * n].copy_from_slice(&x[n..]);
        let d = state_derivative(model, &full);
        [&d.as_slice()[..n], &d.as_slice()[n + 1..=2 * n]].concat()
    }

    /// The Jacobian by central differences at `h` and `h/2`, extrapolated
    /// (error of order `h^4`).
    fn differences(model: &Model, x: &[f64], h: f64) -> DMatrix<f64> {
        let d = x.len();
        let central = |h: f64| {
            DMatrix::from_fn(d, d, |i, j| {
                let (mut plus, mut minus) = (x.to_vec(), x.to_vec());
                plus[j] += h;
                minus[j] -= h;
                (field(model, &plus)[i] - field(model, &minus)[i]) / (2.0 * h)
            })
        };
        (central(h / 2.0) * 4.0 - central(h)) / 3.0
    }

    /// Far from rest (angles up to 1.2 rad, fast rates), with every joint's
    /// spring and damper, a tip mass and a partial follower, the closed
    /// form agrees with differences of the equations of motion (the
    /// chain's general ones for five rods, the closed form of `two_rods`
    /// for two) to their accuracy; likewise for a follower and a dead load.
    #[test]
    fn the_closed_form_is_the_derivative_of_the_equations() {
        for (rods, eta) in [(5, 0.6), (2, 1.0), (3, 0.0), (2, 0.3)] {
            let mut model = PresetId::UniformRods.model().at_load(1.7);
            model.column.rods = rods;
            model.column.c1_nms_per_rad = 0.3;
            model.column.c2_nms_per_rad = 0.2;
            model.column.k2_nm_per_rad = 0.13;
            model.column.tip_mass_kg = 0.4;
            if let Load::Follower { eta: e, .. } = &mut model.load {
                *e = eta;
            }
            #[expect(clippy::cast_precision_loss, reason = "a few rods")]
            let x: Vec<f64> = (0..2 * rods)
                .map(|i| 1.2 * (0.7 * i as f64 + 0.3).sin() + 0.1 * i as f64)
                .collect();
            let closed = chain_jacobian(&model, &x[..rods], &x[rods..]).expect("covered");
            let reference = differences(&model, &x, 1e-3);
            let off = (&closed - &reference).amax();
            assert!(
                off < 1e-8 * reference.amax(),
                "{rods} rods, eta {eta}: {off}\n{closed}\n{reference}"
            );
        }
    }

    /// The drag along the rods and the roller are left to differences.
    #[test]
    fn drag_and_the_roller_are_not_covered() {
        let mut model = PresetId::Ziegler1952.model();
        model.column.drag_ns_per_m2 = 0.05;
        assert!(chain_jacobian(&model, &[0.1, 0.2], &[0.0, 0.0]).is_none());
        let roller = PresetId::Roller.model();
        assert!(chain_jacobian(&roller, &[0.1, 0.2], &[0.0, 0.0]).is_none());
    }
}
