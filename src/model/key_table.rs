//! The table of settable keys: for each, its unit, range, scope and how it
//! reads and writes a model (a group such as `a` or `nu` writes the SI
//! values it stands for).

use strum::VariantArray;

use super::keys::{Key, KeySpec, Scope, Sign};
use super::params::{Load, MAX_RODS, Model, Rod, Roller};

/// Rod 1 or rod 2 of the model.
fn rod_mut(model: &mut Model, rod: usize) -> &mut Rod {
    if rod == 1 {
        &mut model.column.rod1
    } else {
        &mut model.column.rod2
    }
}

fn set_length(model: &mut Model, rod: usize, length_m: f64) {
    // The rod keeps its shape: centre of mass and radius of gyration scale with it.
    let rod = rod_mut(model, rod);
    let ratio = length_m / rod.length_m;
    rod.com_m *= ratio;
    rod.inertia_kg_m2 *= ratio * ratio;
    rod.length_m = length_m;
}

fn set_mass(model: &mut Model, rod: usize, mass_kg: f64) {
    // The rod keeps its mass distribution (its radius of gyration).
    let rod = rod_mut(model, rod);
    rod.inertia_kg_m2 = if rod.mass_kg > 0.0 {
        rod.inertia_kg_m2 * mass_kg / rod.mass_kg
    } else {
        rod.inertia_kg_m2
    };
    rod.mass_kg = mass_kg;
}

fn roller_mut(model: &mut Model) -> Option<&mut Roller> {
    match &mut model.load {
        Load::Roller(roller) => Some(roller),
        Load::Follower { .. } => None,
    }
}

fn roller_value(model: &Model, get: fn(&Roller) -> f64) -> f64 {
    model.roller().map_or(f64::NAN, get)
}

/// Every settable key, in the order `zieglerlab presets` lists them.
pub const KEYS: [KeySpec; 26] = [
    KeySpec {
        key: Key::Load,
        unit: "",
        description: "load p = P l/k on the common axis (P = mu R for the roller; l = l1, k = k1)",
        range: ">= 0",
        scope: Scope::All,
        is_group: true,
        derived: true,
        sign: Sign::NonNegative,
        stage: 5,
        get: Model::load_p,
        set: Model::set_load_p,
    },
    KeySpec {
        key: Key::A,
        unit: "1/s^2",
        description: "a = k/(m l^2): sets k1 (and k2 in the same ratio), keeps p",
        range: "> 0",
        scope: Scope::All,
        is_group: true,
        derived: true,
        sign: Sign::Positive,
        stage: 3,
        get: |m| {
            m.reference_stiffness_nm_per_rad()
                / (m.reference_mass_kg() * m.reference_length_m().powi(2))
        },
        set: |m, a| {
            let p = m.load_p();
            let k1 = a * m.reference_mass_kg() * m.reference_length_m().powi(2);
            m.column.k2_nm_per_rad *= k1 / m.column.k1_nm_per_rad;
            m.column.k1_nm_per_rad = k1;
            m.set_load_p(p);
        },
    },
    KeySpec {
        key: Key::Nu,
        unit: "",
        description: "nu = m3/m, roller mass over the rod's mass",
        range: ">= 0",
        scope: Scope::Roller,
        is_group: true,
        derived: true,
        sign: Sign::NonNegative,
        stage: 3,
        get: |m| roller_value(m, |r| r.mass_kg) / m.reference_mass_kg(),
        set: |m, nu| {
            let mass_kg = nu * m.reference_mass_kg();
            if let Some(roller) = roller_mut(m) {
                roller.mass_kg = mass_kg;
            }
        },
    },
    KeySpec {
        key: Key::Rho,
        unit: "",
        description: "rho = r/l, roller radius over the rod's length",
        range: "in (0, l2/l]",
        scope: Scope::Roller,
        is_group: true,
        derived: true,
        sign: Sign::Positive,
        stage: 3,
        get: |m| roller_value(m, |r| r.radius_m) / m.reference_length_m(),
        set: |m, rho| {
            let radius_m = rho * m.reference_length_m();
            if let Some(roller) = roller_mut(m) {
                roller.radius_m = radius_m;
            }
        },
    },
    KeySpec {
        key: Key::Mu,
        unit: "",
        description: "friction coefficient; only mu R enters the equations, so R is held and the load p = mu R l/k moves",
        range: "> 0",
        scope: Scope::Roller,
        is_group: true,
        derived: false,
        sign: Sign::Positive,
        stage: 4,
        get: |m| roller_value(m, |r| r.mu),
        set: |m, mu| {
            if let Some(roller) = roller_mut(m) {
                roller.mu = mu;
            }
        },
    },
    KeySpec {
        key: Key::V,
        unit: "m/s",
        description: "band speed (the band moves toward -x); the linear analysis needs V > 0",
        range: ">= 0",
        scope: Scope::Roller,
        is_group: true,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| roller_value(m, |r| r.band_speed_m_per_s),
        set: |m, v| {
            if let Some(roller) = roller_mut(m) {
                roller.band_speed_m_per_s = v;
            }
        },
    },
    KeySpec {
        key: Key::L1,
        unit: "m",
        description: "length of rod 1 (its mass distribution scales with it)",
        range: "> 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::Positive,
        stage: 0,
        get: |m| m.column.rod1.length_m,
        set: |m, v| set_length(m, 1, v),
    },
    KeySpec {
        key: Key::L2,
        unit: "m",
        description: "length of rod 2 (its mass distribution scales with it)",
        range: "> 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::Positive,
        stage: 0,
        get: |m| m.column.rod2.length_m,
        set: |m, v| set_length(m, 2, v),
    },
    KeySpec {
        key: Key::M1,
        unit: "kg",
        description: "mass of rod 1, point masses on it included (distribution kept)",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 1,
        get: |m| m.column.rod1.mass_kg,
        set: |m, v| set_mass(m, 1, v),
    },
    KeySpec {
        key: Key::M2,
        unit: "kg",
        description: "mass of rod 2 (distribution kept)",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 1,
        get: |m| m.column.rod2.mass_kg,
        set: |m, v| set_mass(m, 2, v),
    },
    KeySpec {
        key: Key::S1,
        unit: "m",
        description: "centre of mass of rod 1, from the clamp O",
        range: "in [0, l1]",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.rod1.com_m,
        set: |m, v| m.column.rod1.com_m = v,
    },
    KeySpec {
        key: Key::S2,
        unit: "m",
        description: "centre of mass of rod 2, from the joint A",
        range: "in [0, l2]",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.rod2.com_m,
        set: |m, v| m.column.rod2.com_m = v,
    },
    KeySpec {
        key: Key::I1,
        unit: "kg m^2",
        description: "moment of inertia of rod 1 about its centre of mass",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.rod1.inertia_kg_m2,
        set: |m, v| m.column.rod1.inertia_kg_m2 = v,
    },
    KeySpec {
        key: Key::I2,
        unit: "kg m^2",
        description: "moment of inertia of rod 2 about its centre of mass",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.rod2.inertia_kg_m2,
        set: |m, v| m.column.rod2.inertia_kg_m2 = v,
    },
    KeySpec {
        key: Key::MTip,
        unit: "kg",
        description: "point mass at the tip B (the roller's mass is m3)",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.tip_mass_kg,
        set: |m, v| m.column.tip_mass_kg = v,
    },
    KeySpec {
        key: Key::K1,
        unit: "N m/rad",
        description: "rotary spring at the clamp O",
        range: "> 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::Positive,
        stage: 2,
        get: |m| m.column.k1_nm_per_rad,
        set: |m, v| m.column.k1_nm_per_rad = v,
    },
    KeySpec {
        key: Key::K2,
        unit: "N m/rad",
        description: "rotary spring at the joint A",
        range: "> 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::Positive,
        stage: 2,
        get: |m| m.column.k2_nm_per_rad,
        set: |m, v| m.column.k2_nm_per_rad = v,
    },
    KeySpec {
        key: Key::C1,
        unit: "N m s/rad",
        description: "viscous damper at the clamp O",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.c1_nms_per_rad,
        set: |m, v| m.column.c1_nms_per_rad = v,
    },
    KeySpec {
        key: Key::C2,
        unit: "N m s/rad",
        description: "viscous damper at the joint A",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.c2_nms_per_rad,
        set: |m, v| m.column.c2_nms_per_rad = v,
    },
    KeySpec {
        key: Key::CExt,
        unit: "N s/m^2",
        description: "external viscous drag along both rods (air drag, linearized): a force per unit length of c_ext times the local velocity across the rod",
        range: ">= 0",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.column.drag_ns_per_m2,
        set: |m, v| m.column.drag_ns_per_m2 = v,
    },
    KeySpec {
        key: Key::Rods,
        unit: "",
        description: "rods in the chain: rod 1, then copies of rod 2 with joint A's spring and damper at every joint; the tip mass and load at the last rod's end",
        range: "from 2 to 64",
        scope: Scope::All,
        is_group: false,
        derived: false,
        sign: Sign::Count(2, MAX_RODS),
        stage: 1,
        #[expect(clippy::cast_precision_loss, reason = "at most 64 rods")]
        get: |m| m.column.rods as f64,
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a whole number from 2 to 64, checked before it is set"
        )]
        set: |m, v| m.column.rods = v as usize,
    },
    KeySpec {
        key: Key::P,
        unit: "N",
        description: "magnitude of the tip force",
        range: ">= 0",
        scope: Scope::Force,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 5,
        get: Model::follower_force_n,
        set: |m, v| {
            if let Load::Follower { force_n, .. } = &mut m.load {
                *force_n = v;
            }
        },
    },
    KeySpec {
        key: Key::Eta,
        unit: "",
        description: "tangency of the tip force: its direction turns by eta times the last rod's angle (1: follower force, 0: dead load)",
        range: "in [0, 1]",
        scope: Scope::Force,
        is_group: true,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| m.load.eta().unwrap_or(f64::NAN),
        set: |m, v| {
            if let Load::Follower { eta, .. } = &mut m.load {
                *eta = v;
            }
        },
    },
    KeySpec {
        key: Key::M3,
        unit: "kg",
        description: "mass of the roller (0: massless, the ideal follower force)",
        range: ">= 0",
        scope: Scope::Roller,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 2,
        get: |m| roller_value(m, |r| r.mass_kg),
        set: |m, v| {
            if let Some(roller) = roller_mut(m) {
                roller.mass_kg = v;
            }
        },
    },
    KeySpec {
        key: Key::RollerRadius,
        unit: "m",
        description: "radius of the roller",
        range: "in (0, l2]",
        scope: Scope::Roller,
        is_group: false,
        derived: false,
        sign: Sign::Positive,
        stage: 2,
        get: |m| roller_value(m, |r| r.radius_m),
        set: |m, v| {
            if let Some(roller) = roller_mut(m) {
                roller.radius_m = v;
            }
        },
    },
    KeySpec {
        key: Key::NormalForce,
        unit: "N",
        description: "normal force of the roller on the band",
        range: ">= 0",
        scope: Scope::Roller,
        is_group: false,
        derived: false,
        sign: Sign::NonNegative,
        stage: 5,
        get: |m| roller_value(m, |r| r.normal_force_n),
        set: |m, v| {
            if let Some(roller) = roller_mut(m) {
                roller.normal_force_n = v;
            }
        },
    },
];

// `Key::spec` indexes the table by the variant: the two orders are tied
// when the crate compiles.
const _: () = {
    let mut i = 0;
    while i < KEYS.len() {
        assert!(KEYS[i].key as usize == i, "KEYS is not in the order of Key");
        i += 1;
    }
    assert!(
        KEYS.len() == Key::VARIANTS.len(),
        "a key without its row in KEYS"
    );
};

impl Key {
    /// What the key is: unit, range, scope, how it reads and writes a model.
    #[must_use]
    pub fn spec(self) -> &'static KeySpec {
        &KEYS[self as usize]
    }

    /// The parameter's current value in `model` (NaN where the key does not
    /// apply, e.g. the roller's keys on a column).
    #[must_use]
    pub fn get(self, model: &Model) -> f64 {
        self.spec().get(model)
    }

    /// Whether the key exists for this model's load.
    #[must_use]
    pub fn applies_to(self, model: &Model) -> bool {
        self.spec().applies_to(model)
    }

    /// Why the key is not a parameter of `model`, where that needs saying
    /// (beyond listing the keys that are).
    #[must_use]
    pub fn why_absent(self, model: &Model) -> Option<super::Allowed> {
        match self {
            Self::Eta if model.roller().is_some() => Some(super::Allowed::RollerHasNoEta),
            _ => None,
        }
    }

    /// The names of the keys that apply to `model`, for messages.
    #[must_use]
    pub fn names_for(model: &Model) -> String {
        Self::VARIANTS
            .iter()
            .filter(|key| key.applies_to(model))
            .map(|key| key.name())
            .collect::<Vec<_>>()
            .join(", ")
    }
}
