//! The rapier2d engine: the rods of the chain as rigid bodies on multibody
//! revolute joints, with the springs, dampers, drag and tip force applied as
//! explicit forces every step, and the roller's spin advanced implicitly
//! beside them. The only module that knows rapier2d: glam f32 here,
//! nalgebra f64 everywhere else.

use nalgebra::Vector2;
use rapier2d::prelude::*;

use crate::model::{
    Column, Load, Model, Roller, SLIP_REGULARIZATION_M_PER_S, StateVec, StateView, StateViewMut,
    TipResponse, friction, joint_torques_nm, joints_m, normal, rods_drag, state_len, tip_load,
    tip_response, unit,
};

/// The rapier world of one column, and the roller's spin (f64, ours).
pub struct RapierEngine {
    world: PhysicsWorld,
    /// The rods from the clamp out, and the joints at their inner ends.
    rods: Vec<RigidBodyHandle>,
    joints: Vec<MultibodyJointHandle>,
    psi_rad: f64,
    psi_dot_rad_per_s: f64,
    /// The rods' rates one step ago, to evaluate the velocity-dependent
    /// forces at mid-step (second order instead of first).
    previous_rates: Option<Vec<f64>>,
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

/// Mass properties of the last rod with the tip mass and the roller at its
/// end: mass, centre of mass along the rod, inertia about that centre (the
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

/// Mass, centre of mass along the rod and inertia about it of rod `i`.
fn body(model: &Model, i: usize) -> (f64, f64, f64) {
    if i + 1 == model.column.rods {
        outer_body(model)
    } else {
        let rod = model.column.rod(i);
        (rod.mass_kg, rod.com_m, rod.inertia_kg_m2)
    }
}

/// Whether two models give the same rapier world (geometry and masses).
fn same_bodies(a: &Model, b: &Model) -> bool {
    a.column.rods == b.column.rods
        && a.column.rod1 == b.column.rod1
        && a.column.rod2 == b.column.rod2
        && outer_body(a) == outer_body(b)
}

impl RapierEngine {
    /// A world for `model` in state `x`, stepping `step_secs`.
    #[must_use]
    pub fn new(model: &Model, x: &StateVec, step_secs: f64) -> Option<Self> {
        let n = model.column.rods;
        let mut world = PhysicsWorld::new();
        world.gravity = Vector::ZERO;
        world.integration_parameters.dt = f32_of(step_secs);
        // One solver iteration: the explicit spring torques are then
        // integrated by plain symplectic Euler (with substeps they are held
        // fixed while positions move, and pump energy in).
        world.integration_parameters.num_solver_iterations = 1;
        let ground = world.insert_body(RigidBodyBuilder::fixed());
        let mut rods = Vec::with_capacity(n);
        let mut joints = Vec::with_capacity(n);
        let mut inner_joint_m = 0.0;
        for i in 0..n {
            let (mass, com, inertia) = body(model, i);
            let rod = world.insert_body(
                RigidBodyBuilder::dynamic()
                    .can_sleep(false)
                    .translation(vec2(inner_joint_m, 0.0))
                    .additional_mass_properties(MassProperties::new(
                        vec2(com, 0.0),
                        f32_of(mass),
                        f32_of(inertia),
                    )),
            );
            let (parent, anchor) = match rods.last() {
                Some(&parent) => (parent, vec2(model.column.rod(i - 1).length_m, 0.0)),
                None => (ground, Vector::ZERO),
            };
            let joint = RevoluteJointBuilder::new()
                .local_anchor1(anchor)
                .local_anchor2(Vector::ZERO);
            joints.push(world.insert_multibody_joint(parent, rod, joint)?);
            rods.push(rod);
            inner_joint_m += model.column.rod(i).length_m;
        }
        let mut engine = Self {
            world,
            rods,
            joints,
            psi_rad: StateView::new(x).spin_rad(),
            psi_dot_rad_per_s: StateView::new(x).spin_rate_rad_per_s(),
            previous_rates: None,
            built_for: *model,
        };
        engine.set_joints(x)?;
        Some(engine)
    }

    /// Puts the joints at the angles and rates of `x` (each joint's angle
    /// relative to the rod before it).
    fn set_joints(&mut self, x: &StateVec) -> Option<()> {
        let n = self.rods.len();
        let (multibody, _) = self.world.multibody_joints.get_mut(self.joints[0])?;
        // Settles the fixed root (no degrees of freedom) before anything else.
        multibody.forward_kinematics(&self.world.bodies, false);
        if multibody.ndofs() != n {
            return None;
        }
        // rapier's multibody joints carry a default damping of 0.1: none here.
        multibody.damping_mut().fill(0.0);
        // Each joint turns its rod relative to the rod before it.
        let relative = |values: &[f64], i: usize| {
            if i == 0 {
                values[0]
            } else {
                values[i] - values[i - 1]
            }
        };
        let state = StateView::new(x);
        let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
        let displacements: Vec<f32> = (0..n).map(|i| f32_of(relative(angles, i))).collect();
        multibody.apply_displacements(&displacements);
        let mut velocity = multibody.generalized_velocity_mut();
        for i in 0..n {
            velocity[i] = f32_of(relative(rates, i));
        }
        multibody.forward_kinematics(&self.world.bodies, false);
        multibody.update_rigid_bodies(&mut self.world.bodies, true);
        Some(())
    }

    /// `(phi_1 .. phi_N, psi, phi_1' .. phi_N', psi')` in f64.
    #[must_use]
    pub fn state(&self) -> StateVec {
        let mut x = StateVec::zeros(state_len(self.rods.len()));
        let mut write = StateViewMut::new(&mut x);
        let (mut angle, mut rate) = (0.0, 0.0);
        for (i, &handle) in self.joints.iter().enumerate() {
            let (relative_angle, relative_rate) = self
                .world
                .multibody_joints
                .get(handle)
                .and_then(|(multibody, id)| {
                    let link = multibody.link(id)?;
                    let rate = multibody.joint_velocity(link)[0];
                    Some((f64::from(link.joint.coords()[2]), f64::from(rate)))
                })
                .unwrap_or((f64::NAN, f64::NAN));
            angle += relative_angle;
            rate += relative_rate;
            write.angles_rad()[i] = angle;
            write.rates_rad_per_s()[i] = rate;
        }
        *write.spin_rad() = self.psi_rad;
        *write.spin_rate_rad_per_s() = self.psi_dot_rad_per_s;
        x
    }

    /// Advances one step of the world's dt with `model`'s forces; rebuilds
    /// the world first if the geometry or the masses changed.
    pub fn step(&mut self, model: &Model) -> Option<()> {
        let now = self.state();
        if !same_bodies(model, &self.built_for) {
            *self = Self::new(model, &now, f64::from(self.world.integration_parameters.dt))?;
        }
        let n = self.rods.len();
        // Symplectic Euler takes the forces at the start of the step. For the
        // velocity-dependent ones (dampers, friction) that is first order and
        // shifts growth rates by O(dt); the rates extrapolated to mid-step
        // make them second order.
        let mut x = now.clone();
        let rates = StateView::new(&now).rates_rad_per_s().to_vec();
        if let Some(previous) = &self.previous_rates {
            let mut write = StateViewMut::new(&mut x);
            for ((mid, rate), before) in
                write.rates_rad_per_s().iter_mut().zip(&rates).zip(previous)
            {
                *mid = 1.5 * rate - 0.5 * before;
            }
        }
        self.previous_rates = Some(rates);
        let dt = f64::from(self.world.integration_parameters.dt);
        let torques = joint_torques_nm(&model.column, &x);
        let joints = joints_m(&model.column, &x);
        let tip = joints[n];
        let force_n = match model.load {
            Load::Follower { .. } => tip_load(model, &x).force_n,
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
                force
            }
        };
        // The drag on each rod: its resultant at the rod's inner joint and
        // its moment about that joint.
        let drag = (model.column.drag_ns_per_m2 != 0.0).then(|| {
            let angles: Vec<f64> = x.rows(0, n).iter().copied().collect();
            let drag_rates: Vec<f64> = x.rows(n + 1, n).iter().copied().collect();
            rods_drag(&model.column, &angles, &drag_rates)
        });
        for i in 0..n {
            // Joint i's torque turns rod i, and rod i - 1 back.
            let outer_torque = torques.get(i + 1).copied().unwrap_or(0.0);
            let rod = self.world.bodies.get_mut(self.rods[i])?;
            rod.reset_forces(false);
            rod.reset_torques(false);
            let drag_moment_nm = drag.as_ref().map_or(0.0, |drag| drag[i].moment_nm);
            rod.add_torque(f32_of(torques[i] - outer_torque + drag_moment_nm), false);
            if i + 1 == n {
                rod.add_force_at_point(vec2(force_n.x, force_n.y), vec2(tip.x, tip.y), false);
            }
            if let Some(drag) = &drag {
                rod.add_force_at_point(
                    vec2(drag[i].force_n.x, drag[i].force_n.y),
                    vec2(joints[i].x, joints[i].y),
                    false,
                );
            }
        }
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
/// roller slips only along the last rod. Returns the force and the new spin
/// rate.
fn implicit_roller_step(
    model: &Model,
    roller: &Roller,
    x: &StateVec,
    response: &TipResponse,
    dt: f64,
) -> (Vector2<f64>, f64) {
    let column = &model.column;
    let n = column.rods;
    let (l_last, r) = (column.rod2.length_m, roller.radius_m);
    let state = StateView::new(x);
    let (e_last, t_last) = (unit(state.last_angle_rad()), normal(state.last_angle_rad()));
    let band = Vector2::new(roller.band_speed_m_per_s, 0.0);
    let spin_inertia = roller.spin_inertia_kg_m2(l_last);
    let swing = (0..n).fold(Vector2::zeros(), |v, i| {
        v + column.rod(i).length_m * response.free_rates[i] * normal(state.angles_rad()[i])
    });
    let without_spin = swing + band;
    let (w_free, mobility) = if spin_inertia > 0.0 {
        (
            without_spin - r * state.spin_rate_rad_per_s() * t_last,
            response.mobility + (r * r / spin_inertia) * t_last * t_last.transpose(),
        )
    } else {
        // The massless roller's spin cancels the slip across the last rod.
        let along = e_last.dot(&(response.mobility * e_last));
        (
            without_spin.dot(&e_last) * e_last,
            along * e_last * e_last.transpose(),
        )
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
        state.spin_rate_rad_per_s() - dt * r * t_last.dot(&force) / spin_inertia
    } else {
        // The slaved spin of the rods' velocities at the step's end.
        let mobility_force = response.mobility * force * dt;
        (without_spin + mobility_force).dot(&t_last) / r
    };
    (force, psi_dot)
}

/// One implicit (backward Euler) step of the roller's spin, and the friction
/// force that goes with it. With `u` the slip of the contact across the last
/// rod (along its normal) and `b` the slip along it, the spin equation
/// `J psi'' = -r F . t_N` becomes `u (1 + kappa / |w|) = u_n` with
/// `kappa = mu R r^2 dt / J`: monotone in `u`, so one root between 0 and
/// `u_n`, stable for any roller mass. A massless roller (J = 0) gives u = 0
/// exactly: the friction is then along the last rod, the ideal follower
/// force. Returns the force and the new spin rate.
fn roller_step(column: &Column, roller: &Roller, x: &StateVec, dt: f64) -> (Vector2<f64>, f64) {
    let n = column.rods;
    let last = n - 1;
    let (l_last, r) = (column.rod2.length_m, roller.radius_m);
    let state = StateView::new(x);
    let (angles, rates) = (state.angles_rad(), state.rates_rad_per_s());
    let phi_last = angles[last];
    let v = roller.band_speed_m_per_s;
    let mu_r = roller.friction_force_n();
    // Slip across the last rod without the spin's part, and along it: the
    // inner rods' swing seen from the last rod, its own swing, the band.
    let (across_inner, along_inner) = (0..last).fold((0.0, 0.0), |(across, along), i| {
        let (bend, swing) = (phi_last - angles[i], column.rod(i).length_m * rates[i]);
        (across + swing * bend.cos(), along + swing * bend.sin())
    });
    let across_without_spin = across_inner + l_last * rates[last] - v * phi_last.sin();
    let along = along_inner + v * phi_last.cos();
    let spin_inertia = roller.spin_inertia_kg_m2(l_last);
    let u_n = across_without_spin - r * state.spin_rate_rad_per_s();
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
    let slip = (u * u + along * along)
        .sqrt()
        .max(SLIP_REGULARIZATION_M_PER_S);
    let scale = -mu_r / slip;
    (
        scale * (u * normal(phi_last) + along * unit(phi_last)),
        psi_dot,
    )
}
