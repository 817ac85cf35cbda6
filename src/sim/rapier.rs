//! The rapier2d engine: the two rods as rigid bodies on multibody revolute
//! joints, with the springs, dampers and tip force applied as explicit forces
//! every step, and the roller's spin advanced implicitly beside them. The only
//! module that knows rapier2d: glam f32 here, nalgebra f64 everywhere else.

use rapier2d::prelude::*;

use crate::model::{
    Column, Load, Model, Roller, SLIP_REGULARIZATION_M_PER_S, StateVec, TipResponse, friction,
    joint_torques_nm, rod_drag, tip_load, tip_m, tip_response,
};

/// The rapier world of one column, and the roller's spin (f64, ours).
pub struct RapierEngine {
    world: PhysicsWorld,
    rods: [RigidBodyHandle; 2],
    joints: [MultibodyJointHandle; 2],
    psi_rad: f64,
    psi_dot_rad_per_s: f64,
    /// The column's rates one step ago, to evaluate the velocity-dependent
    /// forces at mid-step (second order instead of first).
    previous_rates: Option<[f64; 2]>,
    /// The model whose geometry and masses the world was built with.
    built_for: Model,
}

impl std::fmt::Debug for RapierEngine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RapierEngine")
            .field("state", &self.state())
            .finish_non_exhaustive()
    }
}

#[expect(clippy::cast_possible_truncation, reason = "rapier2d computes in f32")]
fn f32_of(v: f64) -> f32 {
    v as f32
}

fn vec2(x: f64, y: f64) -> Vector {
    Vector::new(f32_of(x), f32_of(y))
}

/// Mass properties of rod 2 with the tip mass and the roller at its end:
/// mass, centre of mass along the rod, inertia about that centre (the
/// roller's yaw inertia included; its spin inertia is the engine's own).
fn outer_body(model: &Model) -> (f64, f64, f64) {
    let Column {
        rod2, tip_mass_kg, ..
    } = model.column;
    let (roller_kg, yaw_kg_m2) = model
        .roller()
        .map_or((0.0, 0.0), |r| (r.mass_kg, r.yaw_inertia_kg_m2()));
    let end_kg = tip_mass_kg + roller_kg;
    let mass = rod2.mass_kg + end_kg;
    let com = if mass > 0.0 {
        (rod2.mass_kg * rod2.com_m + end_kg * rod2.length_m) / mass
    } else {
        0.0
    };
    let inertia = rod2.inertia_kg_m2
        + rod2.mass_kg * (rod2.com_m - com).powi(2)
        + end_kg * (rod2.length_m - com).powi(2)
        + yaw_kg_m2;
    (mass, com, inertia)
}

/// Whether two models give the same rapier world (geometry and masses).
fn same_bodies(a: &Model, b: &Model) -> bool {
    a.column.rod1 == b.column.rod1
        && a.column.rod2 == b.column.rod2
        && outer_body(a) == outer_body(b)
}

impl RapierEngine {
    /// A world for `model` in state `x`, stepping `step_secs`.
    #[must_use]
    pub fn new(model: &Model, x: &StateVec, step_secs: f64) -> Option<Self> {
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        world.integration_parameters.dt = f32_of(step_secs);
        // One solver iteration: the explicit spring torques are then
        // integrated by plain symplectic Euler (with substeps they are held
        // fixed while positions move, and pump energy in).
        world.integration_parameters.num_solver_iterations = 1;
        let ground = world.insert_body(RigidBodyBuilder::fixed());
        let rod1 = model.column.rod1;
        let body1 = RigidBodyBuilder::dynamic()
            .can_sleep(false)
            .additional_mass_properties(MassProperties::new(
                vec2(rod1.com_m, 0.0),
                f32_of(rod1.mass_kg),
                f32_of(rod1.inertia_kg_m2),
            ));
        let (mass2, com2, inertia2) = outer_body(model);
        let body2 = RigidBodyBuilder::dynamic()
            .can_sleep(false)
            .translation(vec2(rod1.length_m, 0.0))
            .additional_mass_properties(MassProperties::new(
                vec2(com2, 0.0),
                f32_of(mass2),
                f32_of(inertia2),
            ));
        let rods = [world.insert_body(body1), world.insert_body(body2)];
        let joint1 = RevoluteJointBuilder::new()
            .local_anchor1(Vector::ZERO)
            .local_anchor2(Vector::ZERO);
        let joint2 = RevoluteJointBuilder::new()
            .local_anchor1(vec2(rod1.length_m, 0.0))
            .local_anchor2(Vector::ZERO);
        let joints = [
            world.insert_multibody_joint(ground, rods[0], joint1)?,
            world.insert_multibody_joint(rods[0], rods[1], joint2)?,
        ];
        let mut engine = Self {
            world,
            rods,
            joints,
            psi_rad: x[2],
            psi_dot_rad_per_s: x[5],
            previous_rates: None,
            built_for: *model,
        };
        engine.set_joints(x)?;
        Some(engine)
    }

    /// Puts the joints at the angles and rates of `x` (relative angle at A).
    fn set_joints(&mut self, x: &StateVec) -> Option<()> {
        let (multibody, _) = self.world.multibody_joints.get_mut(self.joints[0])?;
        // Settles the fixed root (no degrees of freedom) before anything else.
        multibody.forward_kinematics(&self.world.bodies, false);
        if multibody.ndofs() != 2 {
            return None;
        }
        // rapier's multibody joints carry a default damping of 0.1: none here.
        multibody.damping_mut().fill(0.0);
        let current = [x[0], x[1] - x[0]];
        multibody.apply_displacements(&current.map(f32_of));
        let mut velocity = multibody.generalized_velocity_mut();
        velocity[0] = f32_of(x[3]);
        velocity[1] = f32_of(x[4] - x[3]);
        multibody.forward_kinematics(&self.world.bodies, false);
        multibody.update_rigid_bodies(&mut self.world.bodies, true);
        Some(())
    }

    /// `(phi1, phi2, psi, phi1', phi2', psi')` in f64.
    #[must_use]
    pub fn state(&self) -> StateVec {
        let joint = |i: usize| -> (f64, f64) {
            self.world
                .multibody_joints
                .get(self.joints[i])
                .and_then(|(multibody, id)| {
                    let link = multibody.link(id)?;
                    let rate = multibody.joint_velocity(link)[0];
                    Some((f64::from(link.joint.coords()[2]), f64::from(rate)))
                })
                .unwrap_or((f64::NAN, f64::NAN))
        };
        let ((a1, w1), (a2, w2)) = (joint(0), joint(1));
        StateVec::from_vec(vec![
            a1,
            a1 + a2,
            self.psi_rad,
            w1,
            w1 + w2,
            self.psi_dot_rad_per_s,
        ])
    }

    /// Advances one step of the world's dt with `model`'s forces; rebuilds
    /// the world first if the geometry or the masses changed.
    pub fn step(&mut self, model: &Model) -> Option<()> {
        let now = self.state();
        if !same_bodies(model, &self.built_for) {
            *self = Self::new(model, &now, f64::from(self.world.integration_parameters.dt))?;
        }
        // Symplectic Euler takes the forces at the start of the step. For the
        // velocity-dependent ones (dampers, friction) that is first order and
        // shifts growth rates by O(dt); the rates extrapolated to mid-step
        // make them second order.
        let mut x = now.clone();
        if let Some([w1, w2]) = self.previous_rates {
            x[3] = 1.5 * now[3] - 0.5 * w1;
            x[4] = 1.5 * now[4] - 0.5 * w2;
        }
        self.previous_rates = Some([now[3], now[4]]);
        let dt = f64::from(self.world.integration_parameters.dt);
        let [torque_o, torque_a] = joint_torques_nm(&model.column, &x);
        let tip = tip_m(&model.column, &x);
        let tip = vec2(tip.x, tip.y);
        let force_n = match model.load {
            Load::Follower { .. } => {
                let f = tip_load(model, &x).force_n;
                vec2(f.x, f.y)
            }
            Load::Roller(roller) => {
                // How the tip answers a force this step: for the stiffness
                // test and, near stick, the implicit step.
                let response = tip_response(model, &now, dt);
                let (force, psi_dot) = if friction_is_stiff(model, &roller, &now, &response, dt) {
                    implicit_roller_step(model, &roller, &now, &response, dt)
                } else {
                    roller_step(&model.column, &roller, &x, dt)
                };
                self.psi_dot_rad_per_s = psi_dot;
                vec2(force[0], force[1])
            }
        };
        // The drag on each rod: its resultant at the rod's inner joint and
        // its moment about that joint.
        let [drag1, drag2] = rod_drag(&model.column, &x);
        let joint_a = model.column.rod1.length_m * nalgebra::Vector2::new(x[0].cos(), x[0].sin());
        let [rod1, rod2] = self.rods;
        let body1 = self.world.bodies.get_mut(rod1)?;
        body1.reset_forces(false);
        body1.reset_torques(false);
        body1.add_torque(f32_of(torque_o - torque_a + drag1.moment_nm), false);
        body1.add_force_at_point(
            vec2(drag1.force_n.x, drag1.force_n.y),
            vec2(0.0, 0.0),
            false,
        );
        let body2 = self.world.bodies.get_mut(rod2)?;
        body2.reset_forces(false);
        body2.reset_torques(false);
        body2.add_torque(f32_of(torque_a + drag2.moment_nm), false);
        body2.add_force_at_point(force_n, tip, false);
        body2.add_force_at_point(
            vec2(drag2.force_n.x, drag2.force_n.y),
            vec2(joint_a.x, joint_a.y),
            false,
        );
        self.world.step();
        self.psi_rad += dt * self.psi_dot_rad_per_s;
        Some(())
    }
}

/// Whether the friction's answer to the slip it causes within one step is
/// too strong for an explicit force: `dt mu R |W| / |w| > 1/2`, with `W`
/// the contact's mobility (the rods' and the spin's) and `w` the slip. Near
/// stick (|w| small) an explicit friction reverses the slip every step and
/// the force chatters; there the step is taken implicitly.
fn friction_is_stiff(
    model: &Model,
    roller: &Roller,
    x: &StateVec,
    response: &TipResponse,
    dt: f64,
) -> bool {
    let spin_inertia = roller.spin_inertia_kg_m2(model.column.rod2.length_m);
    let spin_mobility = if spin_inertia > 0.0 {
        roller.radius_m * roller.radius_m / spin_inertia
    } else {
        0.0
    };
    // The largest eigenvalue of the symmetric mobility is at most its trace.
    let mobility = response.mobility.trace() + spin_mobility;
    let slip = friction(&model.column, roller, x).slip_m_per_s.norm();
    dt * roller.friction_force_n() * mobility > 0.5 * slip
}

/// One backward Euler step of the friction together with the rods' and the
/// spin's velocities: with `w_free` the slip at the step's end without
/// friction and `W` the contact's mobility, the slip `w` at the end solves
/// `w + dt mu R W w / s = w_free` with `s = max(|w|, eps)`. For a given `s`
/// that is a 2x2 linear system, and `|w(s)|` grows with `s`, so the root in
/// `s` is found by bisection: the friction stops the slip (the viscous
/// regime below `eps`) or slides with it, and never reverses it. A massless
/// roller slips only along rod 2. Returns the force `(Fx, Fy)` and the new
/// spin rate.
fn implicit_roller_step(
    model: &Model,
    roller: &Roller,
    x: &StateVec,
    response: &TipResponse,
    dt: f64,
) -> ([f64; 2], f64) {
    let column = &model.column;
    let (l1, l2, r) = (column.rod1.length_m, column.rod2.length_m, roller.radius_m);
    let [v1, v2] = response.free_rates;
    let (phi1, phi2) = (x[0], x[1]);
    let t1 = nalgebra::Vector2::new(-phi1.sin(), phi1.cos());
    let (e2, t2) = (
        nalgebra::Vector2::new(phi2.cos(), phi2.sin()),
        nalgebra::Vector2::new(-phi2.sin(), phi2.cos()),
    );
    let band = nalgebra::Vector2::new(roller.band_speed_m_per_s, 0.0);
    let spin_inertia = roller.spin_inertia_kg_m2(l2);
    let without_spin = l1 * v1 * t1 + l2 * v2 * t2 + band;
    let (w_free, mobility) = if spin_inertia > 0.0 {
        (
            without_spin - r * x[5] * t2,
            response.mobility + (r * r / spin_inertia) * t2 * t2.transpose(),
        )
    } else {
        // The massless roller's spin cancels the slip across rod 2.
        let along = e2.dot(&(response.mobility * e2));
        (without_spin.dot(&e2) * e2, along * e2 * e2.transpose())
    };
    let mu_r = roller.friction_force_n();
    let impulse = dt * mu_r;
    let eps = SLIP_REGULARIZATION_M_PER_S;
    let slip_at = |s: f64| {
        (nalgebra::Matrix2::identity() + (impulse / s) * mobility)
            .try_inverse()
            .map_or(w_free, |inverse| inverse * w_free)
    };
    let s = if slip_at(eps).norm() <= eps {
        eps
    } else {
        let (mut lo, mut hi) = (eps, w_free.norm().max(eps));
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if mid < slip_at(mid).norm() {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let force = -mu_r / s * slip_at(s);
    let psi_dot = if spin_inertia > 0.0 {
        x[5] - dt * r * t2.dot(&force) / spin_inertia
    } else {
        // The slaved spin of the rods' velocities at the step's end.
        let mobility_force = response.mobility * force * dt;
        (without_spin + mobility_force).dot(&t2) / r
    };
    ([force.x, force.y], psi_dot)
}

/// One implicit (backward Euler) step of the roller's spin, and the friction
/// force that goes with it. With `u` the slip of the contact across rod 2
/// (along its normal t2) and `b` the slip along it, the spin equation
/// `J psi'' = -r F . t2` becomes `u (1 + kappa / |w|) = u_n` with
/// `kappa = mu R r^2 dt / J`: monotone in `u`, so one root between 0 and
/// `u_n`, stable for any roller mass. A massless roller (J = 0) gives u = 0
/// exactly: the friction is then along rod 2, the ideal follower force.
/// Returns the force `(Fx, Fy)` and the new spin rate.
fn roller_step(column: &Column, roller: &Roller, x: &StateVec, dt: f64) -> ([f64; 2], f64) {
    let (l1, l2, r) = (column.rod1.length_m, column.rod2.length_m, roller.radius_m);
    let (phi2, d) = (x[1], x[1] - x[0]);
    let v = roller.band_speed_m_per_s;
    let mu_r = roller.friction_force_n();
    // Slip across rod 2 without the spin's part, and along rod 2.
    let across_without_spin = l1 * x[3] * d.cos() + l2 * x[4] - v * phi2.sin();
    let along = l1 * x[3] * d.sin() + v * phi2.cos();
    let spin_inertia = roller.spin_inertia_kg_m2(l2);
    let u_n = across_without_spin - r * x[5];
    let u = if spin_inertia > 0.0 {
        let kappa = mu_r * r * r * dt / spin_inertia;
        let residual = |u: f64| {
            let slip = (u * u + along * along)
                .sqrt()
                .max(SLIP_REGULARIZATION_M_PER_S);
            u * (1.0 + kappa / slip) - u_n
        };
        // Bisection on the bracket [0, u_n]: about 60 halvings to f64 resolution.
        let (mut lo, mut hi) = if u_n >= 0.0 { (0.0, u_n) } else { (u_n, 0.0) };
        for _ in 0..64 {
            let mid = 0.5 * (lo + hi);
            if residual(mid) > 0.0 {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        0.5 * (lo + hi)
    } else {
        0.0
    };
    let psi_dot = (across_without_spin - u) / r;
    let (e2, t2) = ([phi2.cos(), phi2.sin()], [-phi2.sin(), phi2.cos()]);
    let slip = (u * u + along * along)
        .sqrt()
        .max(SLIP_REGULARIZATION_M_PER_S);
    let scale = -mu_r / slip;
    (
        [
            scale * (u * t2[0] + along * e2[0]),
            scale * (u * t2[1] + along * e2[1]),
        ],
        psi_dot,
    )
}
