//! The named models of the paper, each one `Model` value with its source.

use strum::VariantArray;

use super::ModelError;
use super::params::{Column, Load, Model, Rod, Roller, SpinInertia};

/// A preset, by the name the command line and the settings use.
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    Hash,
    serde::Serialize,
    serde::Deserialize,
    strum::VariantArray,
    strum::IntoStaticStr,
    strum::Display,
)]
#[serde(try_from = "String", into = "String")]
#[strum(serialize_all = "kebab-case")]
pub enum PresetId {
    #[strum(serialize = "ziegler-1952")]
    Ziegler1952,
    UniformRods,
    MidpointMasses,
    Roller,
    RollerAsPrinted,
    Tabletop,
    TabletopRoller,
    Beck,
    Pflueger,
    BeckRoller,
    PfluegerRoller,
}

impl PresetId {
    /// Every preset, in the order of [`PRESETS`].
    #[must_use]
    pub fn all() -> &'static [Self] {
        Self::VARIANTS
    }

    /// The preset's name, as typed.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.into()
    }

    /// The preset itself.
    #[must_use]
    pub fn preset(self) -> &'static Preset {
        &PRESETS[self as usize]
    }

    /// The preset's model at its default load.
    #[must_use]
    pub fn model(self) -> Model {
        self.preset().model()
    }

    /// This preset's column, switched to from `previous`: the load stays
    /// where it was unless it is beyond this column's load bar (a chain's is
    /// shorter), where the preset's own load is taken.
    #[must_use]
    pub fn switched_from(self, previous: &Model) -> Model {
        let model = self.model();
        let p = previous.load_p();
        if p <= model.load_bar_max_p() {
            model.at_load(p)
        } else {
            model
        }
    }
}

impl std::str::FromStr for PresetId {
    type Err = ModelError;

    fn from_str(name: &str) -> Result<Self, ModelError> {
        crate::names::variant_named(name).ok_or_else(|| ModelError::UnknownPreset {
            name: name.to_owned(),
            known: crate::names::variant_names::<Self>(),
        })
    }
}

impl TryFrom<String> for PresetId {
    type Error = ModelError;

    fn try_from(name: String) -> Result<Self, ModelError> {
        name.parse()
    }
}

impl From<PresetId> for String {
    fn from(id: PresetId) -> Self {
        id.name().to_owned()
    }
}

/// A named model with the line that says where it comes from.
#[derive(Clone, Copy, Debug)]
pub struct Preset {
    pub id: PresetId,
    /// Where in the paper the model is: a figure or equations.
    pub source: &'static str,
    pub description: &'static str,
    build: fn() -> Model,
}

// `PresetId::preset` indexes the table by the variant: the two orders are
// tied when the crate compiles.
const _: () = {
    let mut i = 0;
    while i < PRESETS.len() {
        assert!(
            PRESETS[i].id as usize == i,
            "PRESETS is not in the order of PresetId"
        );
        i += 1;
    }
    assert!(
        PRESETS.len() == PresetId::VARIANTS.len(),
        "a preset without its row"
    );
};

impl Preset {
    /// The preset's model at its default load.
    #[must_use]
    pub fn model(&self) -> Model {
        (self.build)()
    }
}

/// Every preset, in the order the UI and `zieglerlab presets` show them.
pub const PRESETS: [Preset; 11] = [
    Preset {
        id: PresetId::Ziegler1952,
        source: "Ziegler 1952",
        description: "Ziegler's column: massless rods, point mass 2m at the joint A and m at the tip, ideal follower force",
        build: ziegler_1952,
    },
    Preset {
        id: PresetId::UniformRods,
        source: "Fig. 1a",
        description: "Uniform rigid rods of mass m (Fig. 1a), ideal follower force",
        build: uniform_rods,
    },
    Preset {
        id: PresetId::MidpointMasses,
        source: "Fig. 1b, eqs 1-7",
        description: "Massless rods with a point mass m at each midpoint (Fig. 1b, eqs 1-7), ideal follower force",
        build: midpoint_masses,
    },
    Preset {
        id: PresetId::Roller,
        source: "Fig. 7, eqs 8-38",
        description: "Uniform rods with a roller dragged by a moving band (Fig. 7, eqs 8-38), consistent spin inertia; Fig. 8 parameters",
        build: roller,
    },
    Preset {
        id: PresetId::RollerAsPrinted,
        source: "eq. 39, Fig. 8",
        description: "The roller model as printed in eq. (39): spin inertia multiplied by r/l2 (physics.md erratum); Fig. 8 parameters",
        build: roller_as_printed,
    },
    Preset {
        id: PresetId::Tabletop,
        source: "lecture pace",
        description: "A desk-sized column for a lecture: uniform rods of 25 cm and 100 g, springs of 0.0625 N m/rad (a = 10 1/s^2), ideal follower force; past p = 2.54 it flutters with a period of about 1.5 s",
        build: tabletop,
    },
    Preset {
        id: PresetId::TabletopRoller,
        source: "lecture pace",
        description: "The tabletop column pushed by a 10 g roller of radius 2.5 cm on a band at 0.1 m/s (nu = rho = mu = 0.1): a weak flutter from p = 0.024 that takes minutes to grow, a strong one near the ideal column's load",
        build: tabletop_roller,
    },
    Preset {
        id: PresetId::Beck,
        source: "Beck 1952, a chain of 16 rods",
        description: "Beck's column as a chain of 16 uniform rods with springs k at every joint (a beam of EI = k l, L = 16 l), follower force: flutter at P L^2/EI = 18.78 (Beck's continuous column: 20.05)",
        build: beck,
    },
    Preset {
        id: PresetId::Pflueger,
        source: "Pflueger's column, a chain of 16 rods",
        description: "Pflueger's column: Beck's chain of 16 rods with a tip mass of half the column's mass, follower force: the tip mass lowers the flutter load to P L^2/EI = 15.06",
        build: pflueger,
    },
    Preset {
        id: PresetId::BeckRoller,
        source: "Beck's chain loaded as in Bigoni et al. 2018",
        description: "Beck's chain of 16 rods loaded by the roller on the moving band (the paper's groups on each rod: roller mass 0.1 m, radius 0.1 l, mu = 0.1, V = 0.1 m/s): the slip's damping makes it flutter weakly from P L^2/EI = 0.025 (growth below 3e-4 1/s), and strongly from about 18.8, where the follower chain flutters",
        build: beck_roller,
    },
    Preset {
        id: PresetId::PfluegerRoller,
        source: "Pflueger's chain loaded as in Bigoni et al. 2018",
        description: "Pflueger's chain of 16 rods (tip mass half the rods' mass) loaded by the same roller on the moving band: weak flutter from P L^2/EI = 0.008 (growth below 4e-5 1/s), strong flutter from 15.06, where the follower chain flutters",
        build: pflueger_roller,
    },
];

/// The preset called `name`.
///
/// # Errors
/// [`ModelError::UnknownPreset`] listing the known names.
pub fn preset(name: &str) -> Result<&'static Preset, ModelError> {
    name.parse::<PresetId>().map(PresetId::preset)
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
        drag_ns_per_m2: 0.0,
        rods: 2,
    }
}

fn follower(column: Column) -> Model {
    let mut model = Model {
        column,
        load: Load::follower(0.0),
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

/// Rods of the Beck and Pflueger chains: the flutter load is within 7% of
/// the continuous column's, and the analysis takes 0.07 s.
const CHAIN_RODS: usize = 16;

/// Beck's chain at half its flutter load.
fn beck() -> Model {
    let mut model = uniform_rods();
    model.column.rods = CHAIN_RODS;
    #[expect(clippy::cast_precision_loss, reason = "16 rods")]
    let n2 = (CHAIN_RODS * CHAIN_RODS) as f64;
    // P L^2/EI = 10: stable, half Beck's load.
    model.set_load_p(10.0 / n2);
    model
}

/// Pflueger's chain: Beck's with a tip mass of half the rods' mass.
fn pflueger() -> Model {
    let mut model = beck();
    #[expect(clippy::cast_precision_loss, reason = "16 rods")]
    let rods_kg = CHAIN_RODS as f64 * MASS_KG;
    model.column.tip_mass_kg = 0.5 * rods_kg;
    model
}

/// A chain loaded by the roller preset's roller at the chain's load.
fn with_roller(chain: Model) -> Model {
    let mut model = Model {
        load: roller().load,
        ..chain
    };
    model.set_load_p(chain.load_p());
    model
}

fn beck_roller() -> Model {
    with_roller(beck())
}

fn pflueger_roller() -> Model {
    with_roller(pflueger())
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

/// The tabletop column: the uniform rods at a desk's scale, `a = k / (m l^2)
/// = 10 1/s^2`, so its motion is `sqrt(10 / 0.1) = 10` times faster than
/// the paper's (the eigenvalues scale with `sqrt(a)` at a fixed `p`).
const TABLETOP_LENGTH_M: f64 = 0.25;
const TABLETOP_MASS_KG: f64 = 0.1;
const TABLETOP_STIFFNESS_NM_PER_RAD: f64 = 0.0625;

fn tabletop_column() -> Column {
    Column {
        k1_nm_per_rad: TABLETOP_STIFFNESS_NM_PER_RAD,
        k2_nm_per_rad: TABLETOP_STIFFNESS_NM_PER_RAD,
        ..column(
            Rod::uniform(TABLETOP_LENGTH_M, TABLETOP_MASS_KG),
            Rod::uniform(TABLETOP_LENGTH_M, TABLETOP_MASS_KG),
            0.0,
        )
    }
}

fn tabletop() -> Model {
    follower(tabletop_column())
}

fn tabletop_roller() -> Model {
    // The paper's groups nu = rho = mu = 0.1 at the desk's scale.
    let mut model = Model {
        column: tabletop_column(),
        load: Load::Roller(Roller {
            mass_kg: 0.1 * TABLETOP_MASS_KG,
            radius_m: 0.1 * TABLETOP_LENGTH_M,
            mu: 0.1,
            normal_force_n: 0.0,
            band_speed_m_per_s: 0.1,
            spin: SpinInertia::Consistent,
        }),
    };
    model.set_load_p(DEFAULT_LOAD_P);
    model
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `PresetId::preset` indexes `PRESETS` by the variant; names read back,
    /// and the stored form is the name (settings files stay readable).
    #[test]
    fn every_preset_reads_back_from_its_name() {
        for &id in PresetId::VARIANTS {
            assert_eq!(id.preset().id, id);
            assert_eq!(id.name().parse::<PresetId>().unwrap(), id);
            assert_eq!(ron::to_string(&id).unwrap(), format!("\"{}\"", id.name()));
        }
        let error = "nope".parse::<PresetId>().unwrap_err().to_string();
        assert!(error.contains("unknown preset 'nope'"), "{error}");
        assert!(ron::from_str::<PresetId>("\"nope\"").is_err());
    }
}
