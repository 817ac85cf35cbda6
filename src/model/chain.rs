//! The nonlinear equations of motion of a chain of N rods under a tip force
//! (follower, partial or dead), with the joints' springs and dampers and the
//! drag along the rods: angles and rates in, angular accelerations out.

use nalgebra::{DMatrix, DVector, Vector2};

use super::dynamics::rods_drag;
use super::linear::chain_mass_matrix;
use super::params::{Load, Model};

/// The state of a chain: each rod's absolute angle and its rate.
#[derive(Clone, Debug, PartialEq)]
pub struct ChainState {
    pub angles_rad: Vec<f64>,
    pub rates_rad_per_s: Vec<f64>,
}

fn normal(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(-angle_rad.sin(), angle_rad.cos())
}

/// The generalized forces on the rods' angles: the joints' springs and
/// dampers, the tip force `Q_i = P l_i sin(phi_i - eta phi_N)` and the drag
/// (each rod's moment about its inner joint, and the resultants of the rods
/// beyond it working through its swing; physics.md sections 2, 3).
fn generalized_forces(model: &Model, x: &ChainState) -> Vec<f64> {
    let column = &model.column;
    let (phi, rate) = (&x.angles_rad, &x.rates_rad_per_s);
    let n = phi.len();
    let length = |i: usize| column.rod(i).length_m;
    let mut q = vec![0.0; n];
    for i in 0..n {
        let (bend, bend_rate) = if i == 0 {
            (phi[0], rate[0])
        } else {
            (phi[i] - phi[i - 1], rate[i] - rate[i - 1])
        };
        let torque = -column.spring_nm_per_rad(i) * bend - column.damper_nms_per_rad(i) * bend_rate;
        q[i] += torque;
        if i > 0 {
            q[i - 1] -= torque;
        }
    }
    if let Load::Follower { force_n, eta } = model.load {
        let direction = eta * phi[n - 1];
        for (i, qi) in q.iter_mut().enumerate() {
            *qi += force_n * length(i) * (phi[i] - direction).sin();
        }
    }
    if column.drag_ns_per_m2 != 0.0 {
        // Each rod's drag moment about its joint, and the resultants of the
        // rods beyond it working through its swing.
        let drag = rods_drag(column, phi, rate);
        let mut resultant_beyond = Vector2::zeros();
        for i in (0..n).rev() {
            q[i] += drag[i].moment_nm + resultant_beyond.dot(&(length(i) * normal(phi[i])));
            resultant_beyond += drag[i].force_n;
        }
    }
    q
}

/// The rods' angular accelerations from Lagrange's equations
///
/// ```text
/// sum_k mu_jk [cos(phi_j - phi_k) phi_k'' + sin(phi_j - phi_k) phi_k'^2] = Q_j
/// ```
///
/// with `mu` the chain's mass matrix at rest (every point's velocity is
/// `sum_j c_j phi_j' t_j`, and `t_j . t_k = cos(phi_j - phi_k)`). `None`
/// for a roller (its chain is not built yet) or a mass matrix that cannot
/// be factored.
#[must_use]
pub fn chain_accelerations(model: &Model, x: &ChainState) -> Option<Vec<f64>> {
    if model.roller().is_some() {
        return None;
    }
    let (phi, rate) = (&x.angles_rad, &x.rates_rad_per_s);
    let n = phi.len();
    let mu = chain_mass_matrix(model);
    let mass = DMatrix::from_fn(n, n, |j, k| mu[(j, k)] * (phi[j] - phi[k]).cos());
    let q = generalized_forces(model, x);
    let rhs = DVector::from_fn(n, |j, _| {
        q[j] - (0..n)
            .map(|k| mu[(j, k)] * (phi[j] - phi[k]).sin() * rate[k] * rate[k])
            .sum::<f64>()
    });
    let accelerations = mass.cholesky()?.solve(&rhs);
    Some(accelerations.iter().copied().collect())
}

/// Kinetic and spring energy of the chain, in joules.
#[must_use]
pub fn chain_energy_j(model: &Model, x: &ChainState) -> (f64, f64) {
    let (phi, rate) = (&x.angles_rad, &x.rates_rad_per_s);
    let n = phi.len();
    let mu = chain_mass_matrix(model);
    let mut kinetic = 0.0;
    for j in 0..n {
        for k in 0..n {
            kinetic += 0.5 * mu[(j, k)] * (phi[j] - phi[k]).cos() * rate[j] * rate[k];
        }
    }
    let spring = (0..n)
        .map(|i| {
            let bend = if i == 0 { phi[0] } else { phi[i] - phi[i - 1] };
            0.5 * model.column.spring_nm_per_rad(i) * bend * bend
        })
        .sum();
    (kinetic, spring)
}
