//! The full nonlinear equations of motion (physics.md section 3) as a pure
//! function state -> state derivative, with the roller's Coulomb friction.

use nalgebra::{DVector, Matrix2, Vector2};

use super::chain::{ChainState, chain_accelerations, chain_energy_j};
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

/// The rods' angles and rates of a chain's state.
fn chain_state(column: &Column, x: &StateVec) -> ChainState {
    let n = column.rods;
    ChainState {
        angles_rad: x.rows(0, n).iter().copied().collect(),
        rates_rad_per_s: x.rows(n + 1, n).iter().copied().collect(),
    }
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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Friction {
    /// Slip velocity of the contact point K relative to the band, eq. (21).
    pub slip_m_per_s: Vector2<f64>,
    /// Force of the band on the roller, eq. (15).
    pub force_n: Vector2<f64>,
    /// Angle of the force from the ideal follower direction (-rod 2), eq. (23).
    pub delta_rad: f64,
    /// Generalized forces on `(phi1, phi2, psi)` by virtual power, eq. (28)
    /// with the erratum `Q3 = -(r/l2) Q2`.
    pub generalized_n_m: [f64; 3],
    /// True when |w| fell below [`SLIP_REGULARIZATION_M_PER_S`]: stick-slip,
    /// outside the model's validity.
    pub regularized: bool,
}

fn unit(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(angle_rad.cos(), angle_rad.sin())
}

fn normal(angle_rad: f64) -> Vector2<f64> {
    Vector2::new(-angle_rad.sin(), angle_rad.cos())
}

/// The slip speed `l2 phi2' - r psi'` that makes the transverse friction
/// vanish: what a massless roller spins up to instantly (`Q3 = 0` forces `Q2 = 0`).
fn massless_roller_spin_rate(column: &Column, roller: &Roller, x: &StateVec) -> f64 {
    let (l1, l2) = (column.rod1.length_m, column.rod2.length_m);
    let slip_along_normal =
        roller.band_speed_m_per_s * x[1].sin() - l1 * x[3] * (x[1] - x[0]).cos();
    (l2 * x[4] - slip_along_normal) / roller.radius_m
}

/// Friction of the band on the roller, eqs (15)-(28). For a massless roller the
/// spin rate in `x` is ignored and replaced by the slaved one, so the force is
/// exactly the ideal follower force `P = mu R` while the contact slips forward.
#[must_use]
pub fn friction(column: &Column, roller: &Roller, x: &StateVec) -> Friction {
    let (l1, l2, r) = (column.rod1.length_m, column.rod2.length_m, roller.radius_m);
    let (phi1, phi2) = (x[0], x[1]);
    let psi_dot = if roller.mass_kg > 0.0 {
        x[5]
    } else {
        massless_roller_spin_rate(column, roller, x)
    };
    let (t1, t2) = (normal(phi1), normal(phi2));
    let band = Vector2::new(roller.band_speed_m_per_s, 0.0);
    let slip = l1 * x[3] * t1 + (l2 * x[4] - r * psi_dot) * t2 + band;
    let speed = slip.norm();
    let regularized = speed < SLIP_REGULARIZATION_M_PER_S;
    let force_n = -roller.friction_force_n() * slip / speed.max(SLIP_REGULARIZATION_M_PER_S);
    let e2 = unit(phi2);
    let delta_rad = slip.dot(&t2).atan2(slip.dot(&e2));
    let q1 = force_n.dot(&(l1 * t1));
    let q2 = force_n.dot(&(l2 * t2));
    Friction {
        slip_m_per_s: slip,
        force_n,
        delta_rad,
        generalized_n_m: [q1, q2, -r / l2 * q2],
        regularized,
    }
}

/// The load at the tip in one state, whatever its kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TipLoad {
    /// Force on the tip (for the roller: of the band on the roller), in N.
    pub force_n: Vector2<f64>,
    /// Generalized forces on `(phi1, phi2, psi)`.
    pub generalized_n_m: [f64; 3],
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

/// Velocity of the tip B in state `x` (the rods' swing, not the roller's
/// spin), in m/s.
#[must_use]
pub fn tip_velocity_m_per_s(column: &Column, x: &StateVec) -> Vector2<f64> {
    let n = column.rods;
    (0..n).fold(Vector2::zeros(), |v, i| {
        v + column.rod(i).length_m * x[n + 1 + i] * normal(x[i])
    })
}

/// The tip load of `model` in state `x` (section 2).
#[must_use]
pub fn tip_load(model: &Model, x: &StateVec) -> TipLoad {
    let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
    let ideal = |force_n: Vector2<f64>| TipLoad {
        force_n,
        generalized_n_m: [
            force_n.dot(&(l1 * normal(x[0]))),
            force_n.dot(&(l2 * normal(x[1]))),
            0.0,
        ],
        delta_rad: 0.0,
        regularized: false,
    };
    match model.load {
        Load::Follower { force_n, eta } => ideal(-force_n * unit(eta * x[model.column.rods - 1])),
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

/// [`rods_drag`] on the two rods of state `x`.
#[must_use]
pub fn rod_drag(column: &Column, x: &StateVec) -> [RodDrag; 2] {
    let drag = rods_drag(column, &[x[0], x[1]], &[x[3], x[4]]);
    [drag[0], drag[1]]
}

/// The generalized forces of the drag on `(phi1, phi2)`: each rod's moment
/// about its joint, and rod 2's force working through rod 1's swing.
#[must_use]
pub fn drag_generalized_n_m(column: &Column, x: &StateVec) -> [f64; 2] {
    let [rod1, rod2] = rod_drag(column, x);
    let swing = column.rod1.length_m * normal(x[0]);
    [rod1.moment_nm + rod2.force_n.dot(&swing), rod2.moment_nm]
}

/// Torques of the joints' springs and dampers `(at O on phi1, at A on
/// phi2 - phi1)`, in N m.
#[must_use]
pub fn joint_torques_nm(column: &Column, x: &StateVec) -> [f64; 2] {
    let Column {
        k1_nm_per_rad: k1,
        k2_nm_per_rad: k2,
        c1_nms_per_rad: c1,
        c2_nms_per_rad: c2,
        ..
    } = *column;
    [
        -k1 * x[0] - c1 * x[3],
        -k2 * (x[1] - x[0]) - c2 * (x[4] - x[3]),
    ]
}

/// The state derivative of the nonlinear equations of motion (section 3,
/// eqs 29-30 corrected), with the joint dampers. For a massless roller the
/// spin follows its slaved rate: `psi''` is that rate's time derivative, so a
/// state that starts consistent stays so.
///
/// A chain of more than two rods (no roller) moves by
/// [`chain_accelerations`]; a state it cannot move (a roller on a chain)
/// gets NaN, which the engines stop on.
#[must_use]
pub fn state_derivative(model: &Model, x: &StateVec) -> StateVec {
    let n = model.column.rods;
    if n != 2 {
        let Some(accelerations) = chain_accelerations(model, &chain_state(&model.column, x)) else {
            return StateVec::from_element(x.len(), f64::NAN);
        };
        let mut derivative = StateVec::zeros(x.len());
        for i in 0..n {
            derivative[i] = x[n + 1 + i];
            derivative[n + 1 + i] = accelerations[i];
        }
        return derivative;
    }
    let (phi1, phi2, phi1_dot, phi2_dot) = (x[0], x[1], x[3], x[4]);
    let [q1, q2, q3] = tip_load(model, x).generalized_n_m;
    let [phi1_ddot, phi2_ddot] = column_accelerations(model, x, [q1, q2]);
    let inertia = model.inertia();
    let d = phi2 - phi1;
    let (sin_d, cos_d) = d.sin_cos();
    let (psi_dot, psi_ddot) = match model.roller() {
        None => (0.0, 0.0),
        Some(roller) if roller.mass_kg > 0.0 => (x[5], q3 / inertia.spin_kg_m2),
        Some(roller) => {
            let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
            let rate = massless_roller_spin_rate(&model.column, roller, x);
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
    let [torque_o, torque_a] = joint_torques_nm(&model.column, x);
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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TipResponse {
    /// `J M^-1 J^T`: the change of the tip's velocity per unit impulse
    /// there, in (m/s) / (N s), with `J` the tip's Jacobian `[l1 t1, l2 t2]`.
    pub mobility: Matrix2<f64>,
    /// The rates `(phi1', phi2')` after `dt` with no tip load (explicit).
    pub free_rates: [f64; 2],
}

/// The tip's response in state `x` over a step `dt` (for a friction force
/// that is solved implicitly with the rods' motion).
#[must_use]
pub fn tip_response(model: &Model, x: &StateVec, dt: f64) -> TipResponse {
    let inertia = model.inertia();
    let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
    let b_cos = inertia.b_kg_m2 * (x[1] - x[0]).cos();
    let mass = Matrix2::new(inertia.a_kg_m2, b_cos, b_cos, inertia.c_kg_m2);
    let jacobian = Matrix2::from_columns(&[l1 * normal(x[0]), l2 * normal(x[1])]);
    // `Model::validate` keeps the mass matrix positive definite.
    let inverse = mass.try_inverse().unwrap_or_else(Matrix2::zeros);
    let [a1, a2] = column_accelerations(model, x, [0.0, 0.0]);
    TipResponse {
        mobility: jacobian * inverse * jacobian.transpose(),
        free_rates: [x[3] + dt * a1, x[4] + dt * a2],
    }
}

/// Kinetic energy (13) and spring energy (14), in joules.
#[must_use]
pub fn energy_j(model: &Model, x: &StateVec) -> (f64, f64) {
    if model.column.rods != 2 {
        return chain_energy_j(model, &chain_state(&model.column, x));
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
