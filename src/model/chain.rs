//! The nonlinear equations of motion of a chain of N rods (physics.md
//! section 3) under any tip load (follower, partial, dead or the roller),
//! with the joints' springs and dampers and the drag along the rods: state
//! in, state derivative out. The entry point for every column; two rods go
//! the closed-form fast path of `two_rods`.

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};

use super::chain_factor::MassFactor;
use super::kinematics::normal;
use super::loads::{angles_trig, joint_torques_nm, rods_drag, slaved_spin_rate, tip_load_trig};
use super::mass::{ChainInertia, chain_inertia, chain_mass_matrix};
use super::params::{Column, Model};
use super::state::{StateVec, StateView, StateViewMut};
use super::two_rods;

/// The state derivative of the nonlinear equations of motion (section 3,
/// eqs 29-30 corrected), with the joint dampers. For a massless roller the
/// spin follows its slaved rate: `psi''` is that rate's time derivative, so a
/// state that starts consistent stays so.
///
/// Two rods take the closed-form 2x2 solve of `two_rods` (a test holds it
/// to [`chain_derivative`]); any other chain moves by [`chain_derivative`].
/// A state whose mass matrix cannot be factored gets NaN, which the engines
/// stop on.
#[must_use]
pub fn state_derivative(model: &Model, x: &StateVec) -> StateVec {
    if model.column.rods == 2 {
        return two_rods::state_derivative(model, x);
    }
    chain_derivative(model, x).unwrap_or_else(|| StateVec::from_element(x.len(), f64::NAN))
}

/// Kinetic energy (rods and the roller's spin, eq. 13) and spring energy
/// (eq. 14), in joules.
#[must_use]
pub fn energy_j(model: &Model, x: &StateVec) -> (f64, f64) {
    if model.column.rods == 2 {
        return two_rods::energy_j(model, x);
    }
    chain_energy_j(model, x)
}

/// The rods' angles and rates of a chain's state.
fn angles_and_rates(x: &StateVec) -> (&[f64], &[f64]) {
    let state = StateView::new(x);
    (state.angles_rad(), state.rates_rad_per_s())
}

/// The generalized forces on the rods' angles of everything but the tip
/// load: the joints' springs and dampers (joint i's torque acts on rod i,
/// and back on rod i - 1), and the drag (each rod's moment about its inner
/// joint, and the resultants of the rods beyond it working through its
/// swing; physics.md sections 2, 3).
fn joint_and_drag_forces(column: &Column, x: &StateVec, phi: &[f64], rate: &[f64]) -> Vec<f64> {
    let n = phi.len();
    let torques = joint_torques_nm(column, x);
    let mut q = torques.clone();
    for i in 1..n {
        q[i - 1] -= torques[i];
    }
    if column.drag_ns_per_m2 != 0.0 {
        let drag = rods_drag(column, phi, rate);
        let mut resultant_beyond = Vector2::zeros();
        for i in (0..n).rev() {
            q[i] += drag[i].moment_nm
                + resultant_beyond.dot(&(column.rod(i).length_m * normal(phi[i])));
            resultant_beyond += drag[i].force_n;
        }
    }
    q
}

/// The right side of Lagrange's equations of the chain in state `x`
///
/// ```text
/// sum_k mu_jk [cos(phi_j - phi_k) phi_k'' + sin(phi_j - phi_k) phi_k'^2] = Q_j
/// ```
///
/// (`mu` the mass matrix at rest, by its generators `inertia`: every
/// point's velocity is `sum_j c_j phi_j' t_j`, and `t_j . t_k = cos(phi_j -
/// phi_k)`), that is `Q` (the springs, dampers and drag plus `tip_q`, the
/// tip load's generalized forces on the rods) less the centripetal terms;
/// `trig` holds each angle's `(sin, cos)`. The left side's matrix
/// `M(phi)_jk = mu_jk cos(phi_j - phi_k)` is factored by [`MassFactor`].
///
/// The centripetal sums take O(N): for `k > j`, `mu_jk sin(phi_j - phi_k)
/// = l_j g_k (e_k x e_j)`, so the terms beyond j are `l_j e_j x` (a running
/// sum of `g_k phi_k'^2 e_k` from the tip), and those before it `g_j e_j x`
/// (a running sum of `l_k phi_k'^2 e_k` from the foot), with `a x b` the
/// 2-D cross product `a_y b_x - a_x b_y`.
pub(super) fn lagrange_rhs(
    model: &Model,
    inertia: &ChainInertia,
    x: &StateVec,
    tip_q: &[f64],
    trig: &[(f64, f64)],
) -> Vec<f64> {
    let (phi, rate) = angles_and_rates(x);
    let n = phi.len();
    let mut rhs = joint_and_drag_forces(&model.column, x, phi, rate);
    let cross = |(sin, cos): (f64, f64), sum: [f64; 2]| sin * sum[0] - cos * sum[1];
    // Sum over k > j of g_k phi_k'^2 e_k, from the tip.
    let mut beyond = [0.0; 2];
    for j in (0..n).rev() {
        rhs[j] += tip_q[j] - inertia.lever_m[j] * cross(trig[j], beyond);
        let weight = inertia.moment_kg_m[j] * rate[j] * rate[j];
        beyond[0] += weight * trig[j].1;
        beyond[1] += weight * trig[j].0;
    }
    // Sum over k < j of l_k phi_k'^2 e_k, from the foot.
    let mut before = [0.0; 2];
    for j in 0..n {
        rhs[j] -= inertia.moment_kg_m[j] * cross(trig[j], before);
        let weight = inertia.lever_m[j] * rate[j] * rate[j];
        before[0] += weight * trig[j].1;
        before[1] += weight * trig[j].0;
    }
    rhs
}

/// Lagrange's equations in state `x` (see [`lagrange_rhs`]): the factored
/// mass matrix and the right side. `None` for a mass matrix that cannot
/// be factored.
fn lagrange(
    model: &Model,
    inertia: &ChainInertia,
    x: &StateVec,
    tip_q: &[f64],
) -> Option<(MassFactor, Vec<f64>)> {
    let trig = angles_trig(x);
    let rhs = lagrange_rhs(model, inertia, x, tip_q, &trig);
    Some((MassFactor::new(inertia, &trig)?, rhs))
}

/// How the tip answers a force there, from one factorization of the mass
/// matrix: the mobility `J M(phi)^-1 J^T` (the change of the tip's velocity
/// per unit impulse, `J = [l_i t_i]` the tip's Jacobian) and the rods'
/// accelerations without the tip load. `None` for a mass matrix that cannot
/// be factored.
#[must_use]
pub fn tip_mobility(model: &Model, x: &StateVec) -> Option<(Matrix2<f64>, DVector<f64>)> {
    let column = &model.column;
    let n = column.rods;
    let (factor, mut free) = lagrange(model, &chain_inertia(model), x, &vec![0.0; n])?;
    factor.solve_in_place(&mut free);
    let angles = StateView::new(x).angles_rad();
    let jacobian = DMatrix::from_fn(2, n, |row, i| {
        column.rod(i).length_m * normal(angles[i])[row]
    });
    let mut solved = jacobian.transpose();
    for column in solved.as_mut_slice().chunks_exact_mut(n) {
        factor.solve_in_place(column);
    }
    let product = &jacobian * solved;
    let mobility = Matrix2::new(
        product[(0, 0)],
        product[(0, 1)],
        product[(1, 0)],
        product[(1, 1)],
    );
    Some((mobility, DVector::from_vec(free)))
}

/// The state derivative of a chain of any length under any tip load. The
/// roller's spin obeys `J psi'' = Q_psi`; a massless roller's spin follows
/// its slaved rate, and `psi''` is that rate's time derivative. `None` for
/// a mass matrix that cannot be factored.
#[must_use]
pub fn chain_derivative(model: &Model, x: &StateVec) -> Option<StateVec> {
    chain_derivative_with(model, &chain_inertia(model), x)
}

/// [`chain_derivative`] with the mass matrix at rest (its generators,
/// [`chain_inertia`] of `model`) given, for a caller that evaluates the
/// same chain many times.
#[must_use]
pub fn chain_derivative_with(
    model: &Model,
    inertia: &ChainInertia,
    x: &StateVec,
) -> Option<StateVec> {
    let [derivative] = chain_derivatives_with(model, inertia, [x]);
    derivative
}

/// [`chain_derivative_with`] in `L` states at once (a step's stages):
/// the mass matrices factored and solved side by side
/// ([`MassFactor::new_lanes`]), each state's derivative the same to the
/// bit as alone.
#[must_use]
pub fn chain_derivatives_with<const L: usize>(
    model: &Model,
    inertia: &ChainInertia,
    xs: [&StateVec; L],
) -> [Option<StateVec>; L] {
    let n = model.column.rods;
    let trigs = xs.map(angles_trig);
    let tips = std::array::from_fn::<_, L, _>(|lane| tip_load_trig(model, xs[lane], &trigs[lane]));
    let mut accelerations: [Vec<f64>; L] = std::array::from_fn(|lane| {
        lagrange_rhs(
            model,
            inertia,
            xs[lane],
            &tips[lane].generalized_n_m[..n],
            &trigs[lane],
        )
    });
    let factors = MassFactor::new_lanes(inertia, trigs.each_ref().map(Vec::as_slice));
    MassFactor::solve_lanes(
        factors.each_ref().map(Option::as_ref),
        &mut accelerations.each_mut().map(Vec::as_mut_slice),
    );
    std::array::from_fn(|lane| {
        factors[lane].as_ref()?;
        Some(assemble(
            model,
            xs[lane],
            &tips[lane].generalized_n_m,
            &accelerations[lane],
        ))
    })
}

/// The state derivative from the rods' `accelerations` and the tip load's
/// generalized forces `tip_q` (on the rods, then the spin): the roller's
/// spin obeys `J psi'' = Q_psi`; a massless roller's spin follows its
/// slaved rate, and `psi''` is that rate's time derivative.
fn assemble(model: &Model, x: &StateVec, tip_q: &[f64], accelerations: &[f64]) -> StateVec {
    let column = &model.column;
    let n = column.rods;
    let state = StateView::new(x);
    let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
    let (psi_dot, psi_ddot) = match model.roller() {
        None => (0.0, 0.0),
        Some(roller) if roller.mass_kg > 0.0 => (
            state.spin_rate_rad_per_s(),
            tip_q[n] / roller.spin_inertia_kg_m2(column.rod2.length_m),
        ),
        Some(roller) => {
            // r psi' = l_N phi_N' + sum_{i<N} l_i phi_i' cos(phi_N - phi_i)
            // - V sin(phi_N), differentiated along the motion.
            let last = n - 1;
            let (phi_n, rate_n) = (angles[last], rates[last]);
            let mut slip_rate = column.rod(last).length_m * accelerations[last]
                - roller.band_speed_m_per_s * phi_n.cos() * rate_n;
            for i in 0..last {
                let (angle, rate) = (phi_n - angles[i], rates[i]);
                slip_rate += column.rod(i).length_m
                    * (accelerations[i] * angle.cos() - rate * angle.sin() * (rate_n - rate));
            }
            (
                slaved_spin_rate(column, roller, x),
                slip_rate / roller.radius_m,
            )
        }
    };
    let mut derivative = StateVec::zeros(x.len());
    let mut write = StateViewMut::new(&mut derivative);
    write.angles_rad().copy_from_slice(rates);
    write.rates_rad_per_s().copy_from_slice(accelerations);
    *write.spin_rad() = psi_dot;
    *write.spin_rate_rad_per_s() = psi_ddot;
    derivative
}

/// Kinetic (rods and roller's spin) and spring energy of the chain, in joules.
#[must_use]
pub fn chain_energy_j(model: &Model, x: &StateVec) -> (f64, f64) {
    let (phi, rate) = angles_and_rates(x);
    let n = phi.len();
    let mu = chain_mass_matrix(model);
    let mut kinetic = 0.0;
    for j in 0..n {
        for k in 0..n {
            kinetic += 0.5 * mu[(j, k)] * (phi[j] - phi[k]).cos() * rate[j] * rate[k];
        }
    }
    if let Some(roller) = model.roller() {
        let spin_rate = StateView::new(x).spin_rate_rad_per_s();
        kinetic +=
            0.5 * roller.spin_inertia_kg_m2(model.column.rod2.length_m) * spin_rate * spin_rate;
    }
    let spring = (0..n)
        .map(|i| {
            let bend = if i == 0 { phi[0] } else { phi[i] - phi[i - 1] };
            0.5 * model.column.spring_nm_per_rad(i) * bend * bend
        })
        .sum();
    (kinetic, spring)
}

/// How the tip's velocity answers a force at the tip, for a step of `dt`.
#[derive(Clone, Debug, PartialEq)]
pub struct TipResponse {
    /// `J M^-1 J^T`: the change of the tip's velocity per unit impulse
    /// there, in (m/s) / (N s), with `J` the tip's Jacobian `[l_i t_i]`.
    pub mobility: Matrix2<f64>,
    /// The rods' rates after `dt` with no tip load (explicit).
    pub free_rates: Vec<f64>,
}

/// The tip's response in state `x` over a step `dt` (for a friction force
/// that is solved implicitly with the rods' motion).
#[must_use]
pub fn tip_response(model: &Model, x: &StateVec, dt: f64) -> TipResponse {
    let n = model.column.rods;
    let (mobility, free) = tip_mobility(model, x)
        .unwrap_or_else(|| (Matrix2::zeros(), DVector::from_element(n, f64::NAN)));
    TipResponse {
        mobility,
        free_rates: StateView::new(x)
            .rates_rad_per_s()
            .iter()
            .zip(free.iter())
            .map(|(rate, acceleration)| rate + dt * acceleration)
            .collect(),
    }
}
