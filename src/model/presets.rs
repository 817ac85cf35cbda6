//! The named models of the paper, each one `Model` value with its source.

use super::ModelError;
use super::params::{Column, Load, Model, Rod, Roller, SpinInertia};

/// A named model with the line that says where it comes from.
#[derive(Clone, Copy, Debug)]
pub struct Preset {
    pub name: &'static str,
    /// Where in the paper the model is: a figure or equations.
    pub source: &'static str,
    pub description: &'static str,
    build: fn() -> Model,
}

impl Preset {
    /// The preset's model at its default load.
    #[must_use]
    pub fn model(&self) -> Model {
        (self.build)()
    }
}

/// Every preset, in the order the UI and `zieglerlab presets` show them.
pub const PRESETS: [Preset; 5] = [
    Preset {
        name: "ziegler-1952",
        source: "Ziegler 1952",
        description: "Ziegler's column: massless rods, point mass 2m at the joint A and m at the tip, ideal follower force",
        build: ziegler_1952,
    },
    Preset {
        name: "uniform-rods",
        source: "Fig. 1a",
        description: "Uniform rigid rods of mass m (Fig. 1a), ideal follower force",
        build: uniform_rods,
    },
    Preset {
        name: "midpoint-masses",
        source: "Fig. 1b, eqs 1-7",
        description: "Massless rods with a point mass m at each midpoint (Fig. 1b, eqs 1-7), ideal follower force",
        build: midpoint_masses,
    },
    Preset {
        name: "roller",
        source: "Fig. 7, eqs 8-38",
        description: "Uniform rods with a roller dragged by a moving band (Fig. 7, eqs 8-38), consistent spin inertia; Fig. 8 parameters",
        build: roller,
    },
    Preset {
        name: "roller-as-printed",
        source: "eq. 39, Fig. 8",
        description: "The roller model as printed in eq. (39): spin inertia multiplied by r/l2 (physics.md erratum); Fig. 8 parameters",
        build: roller_as_printed,
    },
];

/// The preset called `name`.
///
/// # Errors
/// [`ModelError::UnknownPreset`] listing the known names.
pub fn preset(name: &str) -> Result<&'static Preset, ModelError> {
    PRESETS
        .iter()
        .find(|p| p.name == name)
        .ok_or_else(|| ModelError::UnknownPreset {
            name: name.to_owned(),
            known: PRESETS.map(|p| p.name).join(", "),
        })
}

const LENGTH_M: f64 = 1.0;
const MASS_KG: f64 = 1.0;
/// `a = k / (m l^2) = 0.1 1/s^2` with m = 1 kg, l = 1 m (Fig. 8).
const STIFFNESS_NM_PER_RAD: f64 = 0.1;
/// Every preset starts at `p = 1`: below flutter for the ideal columns,
/// in the roller's weak flutter range.
const DEFAULT_LOAD_P: f64 = 1.0;

fn column(rod1: Rod, rod2: Rod, tip_mass_kg: f64) -> Column {
    Column {
        rod1,
        rod2,
        tip_mass_kg,
        k1_nm_per_rad: STIFFNESS_NM_PER_RAD,
        k2_nm_per_rad: STIFFNESS_NM_PER_RAD,
        c1_nms_per_rad: 0.0,
        c2_nms_per_rad: 0.0,
    }
}

fn follower(column: Column) -> Model {
    let mut model = Model {
        column,
        load: Load::Follower { force_n: 0.0 },
    };
    model.set_load_p(DEFAULT_LOAD_P);
    model
}

fn ziegler_1952() -> Model {
    follower(column(
        Rod::point_mass(LENGTH_M, 2.0 * MASS_KG, LENGTH_M),
        Rod::point_mass(LENGTH_M, 0.0, 0.0),
        MASS_KG,
    ))
}

fn uniform_rods() -> Model {
    follower(column(
        Rod::uniform(LENGTH_M, MASS_KG),
        Rod::uniform(LENGTH_M, MASS_KG),
        0.0,
    ))
}

fn midpoint_masses() -> Model {
    follower(column(
        Rod::point_mass(LENGTH_M, MASS_KG, LENGTH_M / 2.0),
        Rod::point_mass(LENGTH_M, MASS_KG, LENGTH_M / 2.0),
        0.0,
    ))
}

fn roller_with_spin(spin: SpinInertia) -> Model {
    // Fig. 8: nu = rho = mu = 0.1, V = 0.1 m/s.
    let mut model = Model {
        column: column(
            Rod::uniform(LENGTH_M, MASS_KG),
            Rod::uniform(LENGTH_M, MASS_KG),
            0.0,
        ),
        load: Load::Roller(Roller {
            mass_kg: 0.1 * MASS_KG,
            radius_m: 0.1 * LENGTH_M,
            mu: 0.1,
            normal_force_n: 0.0,
            band_speed_m_per_s: 0.1,
            spin,
        }),
    };
    model.set_load_p(DEFAULT_LOAD_P);
    model
}

fn roller() -> Model {
    roller_with_spin(SpinInertia::Consistent)
}

fn roller_as_printed() -> Model {
    roller_with_spin(SpinInertia::AsPrinted)
}
