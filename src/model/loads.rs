//! The forces on the chain in a state: the tip load (follower, partial,
//! dead, or the band's friction on the roller), the joints' springs and
//! dampers, and the drag along the rods, as forces and as generalized forces.

use nalgebra::Vector2;

use super::kinematics::{normal, unit};
use super::params::{Column, Load, Model, Roller};
use super::state::{StateVec, StateView};

/// Below this slip speed |w| the Coulomb law `F = -mu R w/|w|` is replaced by
/// the viscous law `F = -mu R w/eps` (continuous at |w| = eps). Above it the
/// friction is exactly Coulomb's. The model is singular at w = 0 (physics.md
/// section 2): this is the stated regularization, 1e-3 of the paper's band
/// speed. Smaller makes the friction in a stick episode stiffer (the
/// reference integrator crawls, rapier's explicit force chatters) for no
/// visible change: the roller's swing at p = 5 moves by 1e-3 rad from 1e-5
/// to 1e-4 m/s.
pub const SLIP_REGULARIZATION_M_PER_S: f64 = 1e-4;

/// The friction of the band on the roller in one state.
#[derive(Clone, Debug, PartialEq)]
pub struct Friction {
    /// Slip velocity of the contact point K relative to the band, eq. (21).
    pub slip_m_per_s: Vector2<f64>,
    /// Force of the band on the roller, eq. (15).
    pub force_n: Vector2<f64>,
    /// Angle of the force from the ideal follower direction (-rod 2), eq. (23).
    pub delta_rad: f64,
    /// Generalized forces on `(phi_1 .. phi_N, psi)` by virtual power, eq.
    /// (28) with the erratum `Q_psi = -(r/l_N) Q_N`.
    pub generalized_n_m: Vec<f64>,
    /// True when |w| fell below [`SLIP_REGULARIZATION_M_PER_S`]: stick-slip,
    /// outside the model's validity.
    pub regularized: bool,
}

/// The spin rate that makes the friction across the last rod vanish: what a
/// massless roller spins up to instantly (`Q_psi = 0` forces `Q_N = 0`),
/// `r psi' = l_N phi_N' + sum_{i<N} l_i phi_i' cos(phi_N - phi_i) - V sin(phi_N)`.
pub(super) fn slaved_spin_rate(column: &Column, roller: &Roller, x: &StateVec) -> f64 {
    let n = column.rods;
    let state = StateView::new(x);
    let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
    let last = state.last_angle_rad();
    let slip_along_normal = (0..n - 1).fold(roller.band_speed_m_per_s * last.sin(), |slip, i| {
        slip - column.rod(i).length_m * rates[i] * (last - angles[i]).cos()
    });
    (column.rod(n - 1).length_m * state.last_rate_rad_per_s() - slip_along_normal) / roller.radius_m
}

/// Friction of the band on the roller at the end of the last rod, eqs
/// (15)-(28) for a chain of any length. For a massless roller the spin rate
/// in `x` is ignored and replaced by the slaved one, so the force is exactly
/// the ideal follower force `P = mu R` while the contact slips forward.
#[must_use]
pub fn friction(column: &Column, roller: &Roller, x: &StateVec) -> Friction {
    friction_trig(column, roller, x, &angles_trig(x))
}

/// [`friction`] with each angle's `(sin, cos)` in `x` given
/// ([`angles_trig`]), for a caller that has them already.
fn friction_trig(column: &Column, roller: &Roller, x: &StateVec, trig: &[(f64, f64)]) -> Friction {
    let state = StateView::new(x);
    let (last, r) = (column.rods - 1, roller.radius_m);
    let l_last = column.rod(last).length_m;
    let psi_dot = if roller.mass_kg > 0.0 {
        state.spin_rate_rad_per_s()
    } else {
        slaved_spin_rate(column, roller, x)
    };
    let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
    let t_last = normal(angles[last]);
    let band = Vector2::new(roller.band_speed_m_per_s, 0.0);
    let inner = (0..last).fold(Vector2::zeros(), |v, i| {
        v + column.rod(i).length_m * rates[i] * normal(angles[i])
    });
    let slip = inner + (l_last * rates[last] - r * psi_dot) * t_last + band;
    let speed = slip.norm();
    let regularized = speed < SLIP_REGULARIZATION_M_PER_S;
    let force_n = -roller.friction_force_n() * slip / speed.max(SLIP_REGULARIZATION_M_PER_S);
    let delta_rad = slip.dot(&t_last).atan2(slip.dot(&unit(angles[last])));
    let mut generalized_n_m = rods_generalized(column, trig, force_n);
    generalized_n_m.push(-r / l_last * generalized_n_m[last]);
    Friction {
        slip_m_per_s: slip,
        force_n,
        delta_rad,
        generalized_n_m,
        regularized,
    }
}

/// The generalized forces on the rods' angles of a force at the tip:
/// `Q_i = F . l_i t_i`, from each angle's `(sin, cos)`.
fn rods_generalized(column: &Column, trig: &[(f64, f64)], force_n: Vector2<f64>) -> Vec<f64> {
    // Room for the spin's entry, which the callers push.
    let mut q = Vec::with_capacity(column.rods + 1);
    q.extend(
        trig.iter().enumerate().map(|(i, &(sin, cos))| {
            force_n.dot(&(column.rod(i).length_m * Vector2::new(-sin, cos)))
        }),
    );
    q
}

/// Each angle's `(sin, cos)` in state `x`, by `libm` (musl's routines,
/// within an ulp as the system's): glibc's save and restore the rounding
/// mode on every call, which took a tenth of a long chain's flow.
#[must_use]
pub(super) fn angles_trig(x: &StateVec) -> Vec<(f64, f64)> {
    StateView::new(x)
        .angles_rad()
        .iter()
        .map(|&a| libm::sincos(a))
        .collect()
}

/// The load at the tip in one state, whatever its kind.
#[derive(Clone, Debug, PartialEq)]
pub struct TipLoad {
    /// Force on the tip (for the roller: of the band on the roller), in N.
    pub force_n: Vector2<f64>,
    /// Generalized forces on `(phi_1 .. phi_N, psi)`.
    pub generalized_n_m: Vec<f64>,
    /// Angle from the ideal follower direction, eq. (23) (0 for ideal loads).
    pub delta_rad: f64,
    /// The roller's slip was regularized (stick-slip).
    pub regularized: bool,
}

/// The tip load of `model` in state `x` (section 2).
#[must_use]
pub fn tip_load(model: &Model, x: &StateVec) -> TipLoad {
    tip_load_trig(model, x, &angles_trig(x))
}

/// [`tip_load`] with each angle's `(sin, cos)` in `x` given
/// ([`angles_trig`]), for a caller that has them already.
#[must_use]
pub(super) fn tip_load_trig(model: &Model, x: &StateVec, trig: &[(f64, f64)]) -> TipLoad {
    match model.load {
        Load::Follower { force_n, eta } => {
            let force_n = -force_n * unit(eta * StateView::new(x).last_angle_rad());
            let mut generalized_n_m = rods_generalized(&model.column, trig, force_n);
            generalized_n_m.push(0.0);
            TipLoad {
                force_n,
                generalized_n_m,
                delta_rad: 0.0,
                regularized: false,
            }
        }
        Load::Roller(roller) => {
            let f = friction_trig(&model.column, &roller, x, trig);
            TipLoad {
                force_n: f.force_n,
                generalized_n_m: f.generalized_n_m,
                delta_rad: f.delta_rad,
                regularized: f.regularized,
            }
        }
    }
}

/// The external drag on one rod, reduced to its inner joint.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RodDrag {
    /// The resultant of the drag along the rod, in N.
    pub force_n: Vector2<f64>,
    /// Its moment about the rod's inner joint, in N m.
    pub moment_nm: f64,
}

/// The external viscous drag `-c_ext v_perp(s) t_i` per unit length on each
/// rod of a chain with these angles and rates, where
/// `v_perp(s) = u_i + s phi_i'` is the velocity across rod i at distance s
/// from its inner joint (`u_i = sum_{j<i} l_j cos(phi_i - phi_j) phi_j'`).
#[must_use]
pub fn rods_drag(column: &Column, angles_rad: &[f64], rates_rad_per_s: &[f64]) -> Vec<RodDrag> {
    let c = column.drag_ns_per_m2;
    let (phi, rate) = (angles_rad, rates_rad_per_s);
    let length = |i: usize| column.rod(i).length_m;
    (0..phi.len())
        .map(|i| {
            let l = length(i);
            let across: f64 = (0..i)
                .map(|j| length(j) * (phi[i] - phi[j]).cos() * rate[j])
                .sum();
            // The integrals over the rod of v_perp and of s v_perp.
            let total = l * across + l * l / 2.0 * rate[i];
            let moment = l * l / 2.0 * across + l.powi(3) / 3.0 * rate[i];
            RodDrag {
                force_n: -c * total * normal(phi[i]),
                moment_nm: -c * moment,
            }
        })
        .collect()
}

/// The torque of joint i's spring and damper on `phi_i - phi_{i-1}`
/// (`phi_0 = 0`: joint 0 is the clamp O, then A, ...) at these angles and
/// rates, in N m.
pub(super) fn joint_torque_nm(column: &Column, angles: &[f64], rates: &[f64], i: usize) -> f64 {
    let (bend, bend_rate) = if i == 0 {
        (angles[0], rates[0])
    } else {
        (angles[i] - angles[i - 1], rates[i] - rates[i - 1])
    };
    -column.spring_nm_per_rad(i) * bend - column.damper_nms_per_rad(i) * bend_rate
}

/// Every joint's torque ([`joint_torque_nm`]), from the clamp out.
#[must_use]
pub fn joint_torques_nm(column: &Column, x: &StateVec) -> Vec<f64> {
    let state = StateView::new(x);
    let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
    (0..column.rods)
        .map(|i| joint_torque_nm(column, angles, rates, i))
        .collect()
}
