//! The two-rod equations of motion in closed form (physics.md section 3,
//! eqs 29-30 corrected): the fast path the chain's equations hand two rods
//! to, held to them by a test.

use super::kinematics::normal;
use super::loads::{joint_torque_nm, rods_drag, slaved_spin_rate, tip_load};
use super::params::{Column, Model};
use super::state::StateVec;

/// Two rods' state by name: `[phi1, phi2, psi, phi1', phi2', psi']`.
fn named(x: &StateVec) -> [f64; 6] {
    [x[0], x[1], x[2], x[3], x[4], x[5]]
}

/// The state derivative of two rods in closed form: eqs 29-30 (corrected)
/// with the 2x2 mass matrix solved by hand.
pub(super) fn state_derivative(model: &Model, x: &StateVec) -> StateVec {
    let [phi1, phi2, _, phi1_dot, phi2_dot, spin_rate] = named(x);
    let q = tip_load(model, x).generalized_n_m;
    let [phi1_ddot, phi2_ddot] = column_accelerations(model, x, [q[0], q[1]]);
    let inertia = model.inertia();
    let d = phi2 - phi1;
    let (sin_d, cos_d) = d.sin_cos();
    let (psi_dot, psi_ddot) = match model.roller() {
        None => (0.0, 0.0),
        Some(roller) if roller.mass_kg > 0.0 => (spin_rate, q[2] / inertia.spin_kg_m2),
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
    let [phi1, phi2, _, phi1_dot, phi2_dot, _] = named(x);
    let (sin_d, cos_d) = (phi2 - phi1).sin_cos();
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

/// The generalized forces of the drag on `(phi1, phi2)`: each rod's moment
/// about its joint, and rod 2's force working through rod 1's swing.
fn drag_generalized_n_m(column: &Column, x: &StateVec) -> [f64; 2] {
    if column.drag_ns_per_m2 == 0.0 {
        return [0.0, 0.0];
    }
    let [phi1, phi2, _, phi1_dot, phi2_dot, _] = named(x);
    let drag = rods_drag(column, &[phi1, phi2], &[phi1_dot, phi2_dot]);
    let (rod1, rod2) = (drag[0], drag[1]);
    let swing = column.rod1.length_m * normal(phi1);
    [rod1.moment_nm + rod2.force_n.dot(&swing), rod2.moment_nm]
}

/// Kinetic energy (13) and spring energy (14) of two rods, in joules.
pub(super) fn energy_j(model: &Model, x: &StateVec) -> (f64, f64) {
    let inertia = model.inertia();
    let [phi1, phi2, _, phi1_dot, phi2_dot, psi_dot] = named(x);
    let kinetic = 0.5 * inertia.a_kg_m2 * phi1_dot * phi1_dot
        + inertia.b_kg_m2 * (phi2 - phi1).cos() * phi1_dot * phi2_dot
        + 0.5 * inertia.c_kg_m2 * phi2_dot * phi2_dot
        + 0.5 * inertia.spin_kg_m2 * psi_dot * psi_dot;
    let spring = 0.5 * model.column.k1_nm_per_rad * phi1 * phi1
        + 0.5 * model.column.k2_nm_per_rad * (phi2 - phi1).powi(2);
    (kinetic, spring)
}
