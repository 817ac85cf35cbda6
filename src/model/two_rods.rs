//! The two-rod equations of motion in closed form (physics.md section 3,
//! eqs 29-30 corrected): the fast path the chain's equations hand two rods
//! to, held to them by a test. Each angle's sine and cosine is taken once,
//! and nothing is allocated but for the roller's friction.

use super::loads::{friction, joint_torque_nm, slaved_spin_rate};
use super::params::{Column, Load, Model};
use super::state::StateVec;

/// Two rods' state by name: `[phi1, phi2, psi, phi1', phi2', psi']`.
pub type TwoRodState = [f64; 6];

/// Two rods' state by name from the full state.
fn named(x: &StateVec) -> TwoRodState {
    [x[0], x[1], x[2], x[3], x[4], x[5]]
}

/// The sines and cosines of `phi1`, `phi2` and `d = phi2 - phi1`.
struct Trig {
    sin1: f64,
    cos1: f64,
    sin2: f64,
    cos2: f64,
    sin_d: f64,
    cos_d: f64,
}

impl Trig {
    fn of(phi1: f64, phi2: f64) -> Self {
        let ((sin1, cos1), (sin2, cos2)) = (phi1.sin_cos(), phi2.sin_cos());
        let (sin_d, cos_d) = (phi2 - phi1).sin_cos();
        Self {
            sin1,
            cos1,
            sin2,
            cos2,
            sin_d,
            cos_d,
        }
    }
}

/// The state derivative of two rods in closed form: eqs 29-30 (corrected)
/// with the 2x2 mass matrix solved by hand.
pub(super) fn state_derivative(model: &Model, x: &StateVec) -> StateVec {
    StateVec::from_column_slice(&two_rod_derivative(model, named(x)))
}

/// [`state_derivative`] of a two-rod `model` on the state by name, without
/// allocating (but for the roller's friction).
#[must_use]
pub fn two_rod_derivative(model: &Model, s: TwoRodState) -> TwoRodState {
    let [phi1, phi2, _, phi1_dot, phi2_dot, spin_rate] = s;
    let trig = Trig::of(phi1, phi2);
    let q = tip_generalized_n_m(model, &s, &trig);
    let [phi1_ddot, phi2_ddot] = column_accelerations(model, &s, &trig, [q[0], q[1]]);
    let (psi_dot, psi_ddot) = match model.roller() {
        None => (0.0, 0.0),
        Some(roller) if roller.mass_kg > 0.0 => (spin_rate, q[2] / model.inertia().spin_kg_m2),
        Some(roller) => {
            let (l1, l2) = (model.column.rod1.length_m, model.column.rod2.length_m);
            let rate = slaved_spin_rate(&model.column, roller, &StateVec::from_column_slice(&s));
            let slip_along_normal_dot = roller.band_speed_m_per_s * trig.cos2 * phi2_dot
                - l1 * phi1_ddot * trig.cos_d
                + l1 * phi1_dot * trig.sin_d * (phi2_dot - phi1_dot);
            (
                rate,
                (l2 * phi2_ddot - slip_along_normal_dot) / roller.radius_m,
            )
        }
    };
    [phi1_dot, phi2_dot, psi_dot, phi1_ddot, phi2_ddot, psi_ddot]
}

/// The tip load's generalized forces on `(phi1, phi2, psi)`: the follower
/// force `-P (cos eta phi2, sin eta phi2)` working through each rod's swing
/// `l_i (-sin phi_i, cos phi_i)`, or the band's friction on the roller.
fn tip_generalized_n_m(model: &Model, s: &TwoRodState, trig: &Trig) -> [f64; 3] {
    match model.load {
        Load::Follower { force_n, eta } => {
            #[expect(clippy::float_cmp, reason = "the ideal follower's own angle")]
            let (sin, cos) = if eta == 1.0 {
                (trig.sin2, trig.cos2)
            } else {
                (eta * s[1]).sin_cos()
            };
            let (fx, fy) = (-force_n * cos, -force_n * sin);
            let column = &model.column;
            let across = |l: f64, sin_i: f64, cos_i: f64| l * (-fx * sin_i + fy * cos_i);
            [
                across(column.rod1.length_m, trig.sin1, trig.cos1),
                across(column.rod2.length_m, trig.sin2, trig.cos2),
                0.0,
            ]
        }
        Load::Roller(roller) => {
            let q =
                friction(&model.column, &roller, &StateVec::from_column_slice(s)).generalized_n_m;
            [q[0], q[1], q[2]]
        }
    }
}

/// The rods' angular accelerations `(phi1'', phi2'')` under the joints'
/// springs and dampers, the drag and the generalized tip forces `q`
/// (eqs 29-30).
fn column_accelerations(
    model: &Model,
    s: &TwoRodState,
    trig: &Trig,
    [q1, q2]: [f64; 2],
) -> [f64; 2] {
    let inertia = model.inertia();
    let column = &model.column;
    let [phi1, phi2, _, phi1_dot, phi2_dot, _] = *s;
    // The torque at A acts on rod 2, and back on rod 1.
    let (angles, rates) = ([phi1, phi2], [phi1_dot, phi2_dot]);
    let torque_o = joint_torque_nm(column, &angles, &rates, 0);
    let torque_a = joint_torque_nm(column, &angles, &rates, 1);
    let [drag1, drag2] = drag_generalized_n_m(column, s, trig);
    let (b, sin_d) = (inertia.b_kg_m2, trig.sin_d);
    let rhs1 = q1 + drag1 + b * sin_d * phi2_dot * phi2_dot + torque_o - torque_a;
    let rhs2 = q2 + drag2 - b * sin_d * phi1_dot * phi1_dot + torque_a;
    // 2x2 mass matrix [[A, B cos d], [B cos d, C]]; its determinant is at
    // least A C - B^2 > 0, which `Model::validate` guarantees.
    let (a, c, b_cos) = (inertia.a_kg_m2, inertia.c_kg_m2, b * trig.cos_d);
    let det = a * c - b_cos * b_cos;
    [
        (c * rhs1 - b_cos * rhs2) / det,
        (a * rhs2 - b_cos * rhs1) / det,
    ]
}

/// The generalized forces of the drag `-c v_perp` on `(phi1, phi2)`: each
/// rod's moment about its inner joint, and rod 2's force working through
/// rod 1's swing (`t_2 . t_1 = cos d`). Across rod 1 at `s` the velocity is
/// `s phi1'`; across rod 2, `l1 cos d phi1' + s phi2'`.
fn drag_generalized_n_m(column: &Column, s: &TwoRodState, trig: &Trig) -> [f64; 2] {
    let c = column.drag_ns_per_m2;
    if c == 0.0 {
        return [0.0, 0.0];
    }
    let [_, _, _, phi1_dot, phi2_dot, _] = *s;
    let (l1, l2) = (column.rod1.length_m, column.rod2.length_m);
    let across = l1 * trig.cos_d * phi1_dot;
    // The integrals over rod 2 of v_perp and of s v_perp.
    let total2 = l2 * across + l2 * l2 / 2.0 * phi2_dot;
    let moment2 = l2 * l2 / 2.0 * across + l2.powi(3) / 3.0 * phi2_dot;
    let moment1 = l1.powi(3) / 3.0 * phi1_dot;
    [-c * (moment1 + total2 * l1 * trig.cos_d), -c * moment2]
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
