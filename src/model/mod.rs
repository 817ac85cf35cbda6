//! The Ziegler column and its loads: parameters, presets, nonlinear equations
//! of motion and their linearization. Pure f64 physics (no UI, no clock, no rapier).
//!
//! The physics notes below (`src/model/physics.md`) derive the models and say
//! how every number is checked; code comments cite them by section.
#![doc = include_str!("physics.md")]

mod allowed;
mod assign;
mod axis;
mod chain;
mod chain_factor;
mod chain_jacobian;
mod key_table;
mod keys;
mod kinematics;
mod linear;
mod load_axis;
mod loads;
mod mass;
mod params;
mod presets;
mod quantity;
mod state;
mod two_rods;
mod valid;
mod validate;

pub use crate::format::Shown;
pub use allowed::Allowed;
pub use assign::{Assignment, apply_assignments, parse_assignment};
pub use axis::Axis;
pub use chain::{
    TipResponse, chain_derivative, chain_derivative_with, chain_derivatives_with, chain_energy_j,
    energy_j, state_derivative, tip_mobility, tip_response,
};
pub use chain_jacobian::chain_jacobian;
pub use key_table::KEYS;
pub use keys::{Key, KeySpec};
pub use kinematics::{joints_m, normal, tip_m, unit};
pub use linear::{LinearModel, joint_matrices, linearize};
pub use load_axis::{ANALYSIS_MAX_P, LOAD_BAR_MAX_P};
pub use loads::{
    Friction, RodDrag, SLIP_REGULARIZATION_M_PER_S, TipLoad, friction, joint_torques_nm, rods_drag,
    tip_load,
};
pub use mass::{ChainInertia, Inertia, chain_inertia, chain_mass_matrix};
pub use params::{Column, LARGEST_DERIVED, Load, MAX_RODS, Model, Rod, Roller, SpinInertia};
pub use presets::{PRESETS, Preset, PresetId, preset};
pub use quantity::Quantity;
pub use quantity::{DAMPER_RATIO, DAMPING_LEVEL, MASS_RATIO};
pub use state::{StateVec, StateView, StateViewMut, rest_state, state_len};
pub use two_rods::{TwoRodState, two_rod_derivative};
pub use valid::{AsValid, ValidModel};

/// What a refused value is: a parameter the user sets by its key, or a
/// quantity made of several (the mass matrix, a map's derived axis, the
/// load P behind the load p).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject {
    Key(Key),
    Derived(Quantity),
}

impl std::fmt::Display for Subject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Key(key) => f.write_str(key.name()),
            Self::Derived(what) => f.write_str(what.name()),
        }
    }
}

impl From<Key> for Subject {
    fn from(key: Key) -> Self {
        Self::Key(key)
    }
}

impl From<Quantity> for Subject {
    fn from(what: Quantity) -> Self {
        Self::Derived(what)
    }
}

/// A parameter value that makes no model, named so the user can fix it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    #[error("{subject} = {}: {allowed}", Shown(*.value))]
    Invalid {
        subject: Subject,
        value: f64,
        allowed: Allowed,
    },
    #[error("unknown preset '{name}'; the presets are: {known}")]
    UnknownPreset { name: String, known: String },
    #[error("unknown key '{key}'; the keys are: {known}")]
    UnknownKey { key: String, known: String },
    #[error("'{text}' is not key=value with a number (e.g. load=2.5): {reason}")]
    Malformed { text: String, reason: String },
    #[error("{first} and {second} both set the same quantity; give only one")]
    Conflict { first: Key, second: Key },
}

impl ModelError {
    /// The name of what the error is about (a key, also one that is not
    /// known, or a derived quantity), when it is about one.
    #[must_use]
    pub fn parameter(&self) -> Option<&str> {
        match self {
            Self::Invalid {
                subject: Subject::Key(key),
                ..
            }
            | Self::Conflict { first: key, .. } => Some(key.name()),
            Self::Invalid {
                subject: Subject::Derived(what),
                ..
            } => Some(what.name()),
            Self::UnknownKey { key, .. } => Some(key),
            Self::UnknownPreset { .. } | Self::Malformed { .. } => None,
        }
    }

    /// The settable parameter the error is about, when it is one.
    #[must_use]
    pub fn key(&self) -> Option<Key> {
        match self {
            Self::Invalid {
                subject: Subject::Key(key),
                ..
            }
            | Self::Conflict { first: key, .. } => Some(*key),
            _ => None,
        }
    }

    pub(crate) fn invalid(subject: impl Into<Subject>, value: f64, allowed: Allowed) -> Self {
        Self::Invalid {
            subject: subject.into(),
            value,
            allowed,
        }
    }
}
