//! The full nonlinear equations of motion (physics.md section 3) as a pure
//! function state -> state derivative, with the roller's Coulomb friction.

use nalgebra::{DVector, Matrix2, Vector2};

use super::chain::{chain_derivative, chain_energy_j, tip_mobility};
use super::params::{Column, Load, Model, Roller};

/// `(phi_1 .. phi_N, psi, phi_1' .. phi_N', psi')` in rad and rad/s: for
/// two rods `(phi1, phi2, psi, phi1', phi2', psi')`. The spin entries stay
/// zero without a roller.
pub type StateVec = DVector<f64>;

/// The state of rest of `column`'s chain (all angles and rates zero).
#[must_use]
pub fn rest_state(column: &Column) -> StateVec {
    StateVec::zeros(2 * (column.rods + 1))
}

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

/// The unit vector `e` along a rod at `angle_rad`.
#[must_use]
pub fn unit(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(angle_rad.cos(), angle_rad.sin())
}

/// The unit normal `t` of a rod at `angle_rad` (`e` turned a quarter left).
#[must_use]
pub fn normal(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(-angle_rad.sin(), angle_rad.cos())
}

/// The spin rate that makes the friction across the last rod vanish: what a
/// massless roller spins up to instantly (`Q_psi = 0` forces `Q_N = 0`),
/// `r psi' = l_N phi_N' + sum_{i<N} l_i phi_i' cos(phi_N - phi_i) - V sin(phi_N)`.
pub(super) fn slaved_spin_rate(column: &Column, roller: &Roller, x: &StateVec) -> f64 {
    let n = column.rods;
    let last = x[n - 1];
    let slip_along_normal = (0..n - 1).fold(roller.band_speed_m_per_s * last.sin(), |slip, i| {
        slip - column.rod(i).length_m * x[n + 1 + i] * (last - x[i]).cos()
    });
    (column.rod(n - 1).length_m * x[2 * n] - slip_along_normal) / roller.radius_m
}

/// Friction of the band on the roller at the end of the last rod, eqs
/// (15)-(28) for a chain of any length. For a massless roller the spin rate
/// in `x` is ignored and replaced by the slaved one, so the force is exactly
/// the ideal follower force `P = mu R` while the contact slips forward.
#[must_use]
pub fn friction(column: &Column, roller: &Roller, x: &StateVec) -> Friction {
    let n = column.rods;
    let (last, r) = (n - 1, roller.radius_m);
    let l_last = column.rod(last).length_m;
    let psi_dot = if roller.mass_kg > 0.0 {
        x[2 * n + 1]
    } else {
        slaved_spin_rate(column, roller, x)
    };
    let t_last = normal(x[last]);
    let band = Vector2::new(roller.band_speed_m_per_s, 0.0);
    let inner = (0..last).fold(Vector2::zeros(), |v, i| {
        v + column.rod(i).length_m * x[n + 1 + i] * normal(x[i])
    });
    let slip = inner + (l_last * x[2 * n] - r * psi_dot) * t_last + band;
    let speed = slip.norm();
    let regularized = speed < SLIP_REGULARIZATION_M_PER_S;
    let force_n = -roller.friction_force_n() * slip / speed.max(SLIP_REGULARIZATION_M_PER_S);
    let delta_rad = slip.dot(&t_last).atan2(slip.dot(&unit(x[last])));
    let mut generalized_n_m = rods_generalized(column, x, force_n);
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
/// `Q_i = F . l_i t_i`.
fn rods_generalized(column: &Column, x: &StateVec, force_n: Vector2<f64>) -> Vec<f64> {
    // Room for the spin's entry, which the callers push.
    let mut q = Vec::with_capacity(column.rods + 1);
    q.extend((0..column.rods).map(|i| force_n.dot(&(column.rod(i).length_m * normal(x[i])))));
    q
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

/// Positions of the joints from the clamp O to the tip B in state `x`, in m
/// (`rods + 1` points).
#[must_use]
pub fn joints_m(column: &Column, x: &StateVec) -> Vec<Vector2<f64>> {
    let mut at = Vector2::zeros();
    let mut joints = vec![at];
    for i in 0..column.rods {
        at += column.rod(i).length_m * unit(x[i]);
        joints.push(at);
    }
    joints
}

/// Position of the tip B in state `x`, in m.
#[must_use]
pub fn tip_m(column: &Column, x: &StateVec) -> Vector2<f64> {
    (0..column.rods).fold(Vector2::zeros(), |tip, i| {
        tip + column.rod(i).length_m * unit(x[i])
    })
}

/// The tip load of `model` in state `x` (section 2).
#[must_use]
pub fn tip_load(model: &Model, x: &StateVec) -> TipLoad {
    match model.load {
        Load::Follower { force_n, eta } => {
            let force_n = -force_n * unit(eta * x[model.column.rods - 1]);
            let mut generalized_n_m = rods_generalized(&model.column, x, force_n);
            generalized_n_m.push(0.0);
            TipLoad {
                force_n,
                generalized_n_m,
                delta_rad: 0.0,
                regularized: false,
            }
        }
        Load::Roller(roller) => {
            let f = friction(&model.column, &roller, x);
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

/// The generalized forces of the drag on `(phi1, phi2)`: each rod's moment
/// about its joint, and rod 2's force working through rod 1's swing.
fn drag_generalized_n_m(column: &Column, x: &StateVec) -> [f64; 2] {
    if column.drag_ns_per_m2 == 0.0 {
        return [0.0, 0.0];
    }
    let drag = rods_drag(column, &[x[0], x[1]], &[x[3], x[4]]);
    let (rod1, rod2) = (drag[0], drag[1]);
    let swing = column.rod1.length_m * normal(x[0]);
    [rod1.moment_nm + rod2.force_n.dot(&swing), rod2.moment_nm]
}

/// The torque of joint i's spring and damper on `phi_i - phi_{i-1}`
/// (`phi_0 = 0`: joint 0 is the clamp O, then A, ...), in N m.
fn joint_torque_nm(column: &Column, x: &StateVec, i: usize) -> f64 {
    let n = column.rods;
    let (bend, bend_rate) = if i == 0 {
        (x[0], x[n + 1])
    } else {
        (x[i] - x[i - 1], x[n + 1 + i] - x[n + i])
    };
    -column.spring_nm_per_rad(i) * bend - column.damper_nms_per_rad(i) * bend_rate
}

/// Every joint's torque ([`joint_torque_nm`]), from the clamp out.
#[must_use]
pub fn joint_torques_nm(column: &Column, x: &StateVec) -> Vec<f64> {
    (0..column.rods)
        .map(|i| joint_torque_nm(column, x, i))
        .collect()
}

/// The state derivative of the nonlinear equations of motion (section 3,
/// eqs 29-30 corrected), with the joint dampers. For a massless roller the
/// spin follows its slaved rate: `psi''` is that rate's time derivative, so a
/// state that starts consistent stays so.
///
/// Two rods take the closed-form 2x2 solve below; a chain of any other
/// length moves by [`chain_derivative`], the same equations for N rods
/// (a test holds the two to each other for two rods). A state whose mass
/// matrix cannot be factored gets NaN, which the engines stop on.
#[must_use]
pub fn state_derivative(model: &Model, x: &StateVec) -> StateVec {
    if model.column.rods != 2 {
        return chain_derivative(model, x)
            .unwrap_or_else(|| StateVec::from_element(x.len(), f64::NAN));
    }
    let (phi1, phi2, phi1_dot, phi2_dot) = (x[0], x[1], x[3], x[4]);
    let q = tip_load(model, x).generalized_n_m;
    let [phi1_ddot, phi2_ddot] = column_accelerations(model, x, [q[0], q[1]]);
    let inertia = model.inertia();
    let d = phi2 - phi1;
    let (sin_d, cos_d) = d.sin_cos();
    let (psi_dot, psi_ddot) = match model.roller() {
        None => (0.0, 0.0),
        Some(roller) if roller.mass_kg > 0.0 => (x[5], q[2] / inertia.spin_kg_m2),
        Some(roller) => {
            let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
            let rate = slaved_spin_rate(&model.column, roller, x);
            let slip_along_normal_dot = roller.band_speed_m_per_s * phi2.cos() * phi2_dot
                - l1 * phi1_ddot * cos_d
                + l1 * phi1_dot * sin_d * (phi2_dot - phi1_dot);
            (
                rate,
                (l2 * phi2_ddot - slip_along_normal_dot) / roller.radius_m,
            )
        }
    };
    StateVec::from_vec(vec![
        phi1_dot, phi2_dot, psi_dot, phi1_ddot, phi2_ddot, psi_ddot,
    ])
}

/// The rods' angular accelerations `(phi1'', phi2'')` under the joints'
/// springs and dampers and the generalized tip forces `q` (eqs 29-30).
fn column_accelerations(model: &Model, x: &StateVec, [q1, q2]: [f64; 2]) -> [f64; 2] {
    let inertia = model.inertia();
    let (phi1_dot, phi2_dot) = (x[3], x[4]);
    let (sin_d, cos_d) = (x[1] - x[0]).sin_cos();
    // The torque at A acts on rod 2, and back on rod 1.
    let (torque_o, torque_a) = (
        joint_torque_nm(&model.column, x, 0),
        joint_torque_nm(&model.column, x, 1),
    );
    let [drag1, drag2] = drag_generalized_n_m(&model.column, x);
    let b = inertia.b_kg_m2;
    let rhs1 = q1 + drag1 + b * sin_d * phi2_dot * phi2_dot + torque_o - torque_a;
    let rhs2 = q2 + drag2 - b * sin_d * phi1_dot * phi1_dot + torque_a;
    // 2x2 mass matrix [[A, B cos d], [B cos d, C]]; its determinant is at
    // least A C - B^2 > 0, which `Model::validate` guarantees.
    let (a, c, b_cos) = (inertia.a_kg_m2, inertia.c_kg_m2, b * cos_d);
    let det = a * c - b_cos * b_cos;
    [
        (c * rhs1 - b_cos * rhs2) / det,
        (a * rhs2 - b_cos * rhs1) / det,
    ]
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
        free_rates: (0..n).map(|i| x[n + 1 + i] + dt * free[i]).collect(),
    }
}

/// Kinetic energy (13) and spring energy (14), in joules.
#[must_use]
pub fn energy_j(model: &Model, x: &StateVec) -> (f64, f64) {
    if model.column.rods != 2 {
        return chain_energy_j(model, x);
    }
    let inertia = model.inertia();
    let (phi1, phi2, phi1_dot, phi2_dot, psi_dot) = (x[0], x[1], x[3], x[4], x[5]);
    let kinetic = 0.5 * inertia.a_kg_m2 * phi1_dot * phi1_dot
        + inertia.b_kg_m2 * (phi2 - phi1).cos() * phi1_dot * phi2_dot
        + 0.5 * inertia.c_kg_m2 * phi2_dot * phi2_dot
        + 0.5 * inertia.spin_kg_m2 * psi_dot * psi_dot;
    let spring = 0.5 * model.column.k1_nm_per_rad * phi1 * phi1
        + 0.5 * model.column.k2_nm_per_rad * (phi2 - phi1).powi(2);
    (kinetic, spring)
}
