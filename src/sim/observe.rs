//! What a run shows at one instant, computed from the model and the state
//! alone (the same for every engine).

use serde::Serialize;

use crate::model::{Model, StateVec, StateView, energy_j, tip_load, tip_m};

/// The observables of one state.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Observables {
    pub t_secs: f64,
    /// Every rod's angle and rate, from the clamp out (rods 1 and 2 of a
    /// two-rod column are also `phi1_rad`, `phi2_rad` below).
    pub angles_rad: Vec<f64>,
    pub rates_rad_per_s: Vec<f64>,
    pub phi1_rad: f64,
    pub phi2_rad: f64,
    /// The roller's spin angle (0 without a roller).
    pub psi_rad: f64,
    pub phi1_dot_rad_per_s: f64,
    pub phi2_dot_rad_per_s: f64,
    pub psi_dot_rad_per_s: f64,
    /// Angle of the friction force from the ideal follower direction, eq. (23)
    /// (0 for the ideal loads).
    pub delta_rad: f64,
    /// Force of the band on the roller, or the tip force, in N.
    pub tip_force_n: [f64; 2],
    pub kinetic_j: f64,
    pub spring_j: f64,
    /// Power the tip force delivers into the column and roller,
    /// `F . v_K = sum Q_j q_j'` (for the roller: what the band feeds in).
    pub band_power_w: f64,
    /// Position of the tip B.
    pub tip_m: [f64; 2],
    /// True when the slip speed fell below the regularization scale
    /// (stick-slip: outside the model's validity).
    pub stick_slip: bool,
}

impl Observables {
    /// Kinetic plus spring energy.
    #[must_use]
    pub fn energy_j(&self) -> f64 {
        self.kinetic_j + self.spring_j
    }
}

/// The observables of `model` in state `x` at time `t_secs`.
#[must_use]
pub fn observe(model: &Model, t_secs: f64, x: &StateVec) -> Observables {
    let state = StateView::new(x);
    let tip = tip_m(&model.column, x);
    let (kinetic_j, spring_j) = energy_j(model, x);
    let load = tip_load(model, x);
    // F . v_K = sum Q_j q_j' over the rods' angles and the spin.
    let band_power_w = load
        .generalized_n_m
        .iter()
        .zip(state.all_rates())
        .map(|(q, v)| q * v)
        .sum();
    Observables {
        t_secs,
        angles_rad: state.angles_rad().to_vec(),
        rates_rad_per_s: state.rates_rad_per_s().to_vec(),
        phi1_rad: state.angles_rad()[0],
        phi2_rad: state.angles_rad()[1],
        psi_rad: state.spin_rad(),
        phi1_dot_rad_per_s: state.rates_rad_per_s()[0],
        phi2_dot_rad_per_s: state.rates_rad_per_s()[1],
        psi_dot_rad_per_s: state.spin_rate_rad_per_s(),
        delta_rad: load.delta_rad,
        tip_force_n: [load.force_n.x, load.force_n.y],
        kinetic_j,
        spring_j,
        band_power_w,
        tip_m: [tip.x, tip.y],
        stick_slip: load.regularized,
    }
}
