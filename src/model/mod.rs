//! The Ziegler column and its loads: parameters, presets, nonlinear equations
//! of motion and their linearization. Pure f64 physics (no UI, no clock, no rapier).
//!
//! The physics notes below (`src/model/physics.md`) derive the models and say
//! how every number is checked; code comments cite them by section.
#![doc = include_str!("physics.md")]

mod assign;
mod axis;
mod chain;
mod key_table;
mod keys;
mod kinematics;
mod linear;
mod loads;
mod mass;
mod params;
mod presets;
mod state;
mod two_rods;
mod validate;

pub use crate::format::Shown;
pub use assign::{Assignment, apply_assignments, parse_assignment};
pub use axis::{Axis, DAMPER_RATIO, DAMPING_LEVEL, MASS_RATIO};
pub use chain::{
    TipResponse, chain_derivative, chain_energy_j, energy_j, state_derivative, tip_mobility,
    tip_response,
};
pub use key_table::KEYS;
pub use keys::{Key, KeySpec};
pub use kinematics::{joints_m, normal, tip_m, unit};
pub use linear::{LinearModel, joint_matrices, linearize};
pub use loads::{
    Friction, RodDrag, SLIP_REGULARIZATION_M_PER_S, TipLoad, friction, joint_torques_nm, rods_drag,
    tip_load,
};
pub use mass::{Inertia, chain_mass_matrix};
pub(crate) use params::analysis_range_text;
pub use params::{
    Column, LARGEST_DERIVED, LOAD_BAR_MAX_P, Load, MAX_RODS, Model, Rod, Roller, SpinInertia,
};
pub use presets::{PRESETS, Preset, PresetId, preset};
pub use state::{StateVec, StateView, StateViewMut, rest_state, state_len};

/// A parameter value that makes no model, named so the user can fix it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    #[error("{key} = {}: {allowed}", Shown(*.value))]
    Invalid {
        key: String,
        value: f64,
        allowed: String,
    },
    #[error("unknown preset '{name}'; the presets are: {known}")]
    UnknownPreset { name: String, known: String },
    #[error("unknown key '{key}'; the keys are: {known}")]
    UnknownKey { key: String, known: String },
    #[error("'{text}' is not key=value with a number (e.g. load=2.5): {reason}")]
    Malformed { text: String, reason: String },
    #[error("{first} and {second} both set the same quantity; give only one")]
    Conflict { first: String, second: String },
}

impl ModelError {
    /// The parameter (key) the error is about, when it is about one.
    #[must_use]
    pub fn parameter(&self) -> Option<&str> {
        match self {
            Self::Invalid { key, .. } | Self::UnknownKey { key, .. } => Some(key),
            Self::Conflict { first, .. } => Some(first),
            Self::UnknownPreset { .. } | Self::Malformed { .. } => None,
        }
    }

    pub(crate) fn invalid(key: &str, value: f64, allowed: &str) -> Self {
        Self::Invalid {
            key: key.to_owned(),
            value,
            allowed: allowed.to_owned(),
        }
    }
}
