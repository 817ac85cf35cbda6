//! A parameter to sweep (a stability map's second axis, the paradox
//! explorer's): any key, or the joints' damper ratio c1/c2 or damping level
//! with the other held.

use super::allowed::Allowed;
use super::assign::{Assignment, apply_assignments};
use super::key_table::KEYS;
use super::keys::Key;
use super::quantity::{DAMPER_RATIO, DAMPING_LEVEL, MASS_RATIO, Quantity};
use super::{Model, ModelError};

/// A swept parameter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Axis {
    /// A key as `--set` takes it.
    Key(Key),
    DamperRatio,
    DampingLevel,
    MassRatio,
}

impl Axis {
    /// The axis named `name` for `model`: a key that applies to it, `c1/c2`
    /// or `damping`.
    ///
    /// # Errors
    /// An unknown name, naming the ones there are.
    pub fn parse(name: &str, model: &Model) -> Result<Self, ModelError> {
        match name {
            DAMPER_RATIO => return Ok(Self::DamperRatio),
            DAMPING_LEVEL => return Ok(Self::DampingLevel),
            MASS_RATIO => return Ok(Self::MassRatio),
            _ => {}
        }
        name.parse::<Key>()
            .ok()
            .filter(|key| key.applies_to(model))
            .map(Self::Key)
            .ok_or_else(|| ModelError::UnknownKey {
                key: name.to_owned(),
                known: Self::names(model).join(", "),
            })
    }

    /// Every axis name for `model`.
    #[must_use]
    pub fn names(model: &Model) -> Vec<&'static str> {
        KEYS.iter()
            .filter(|spec| spec.applies_to(model))
            .map(|spec| spec.key.name())
            .chain([DAMPER_RATIO, DAMPING_LEVEL, MASS_RATIO])
            .collect()
    }

    #[must_use]
    pub fn name(&self) -> &'static str {
        match self {
            Self::Key(key) => key.name(),
            Self::DamperRatio => DAMPER_RATIO,
            Self::DampingLevel => DAMPING_LEVEL,
            Self::MassRatio => MASS_RATIO,
        }
    }

    /// The axis's value for `model` (a ratio c1/c2 of an undamped column is
    /// reported as 1, the value a damping level would be given with).
    #[must_use]
    pub fn get(&self, model: &Model) -> f64 {
        let c = &model.column;
        match self {
            Self::Key(key) => key.get(model),
            Self::DamperRatio => ratio(model).unwrap_or(1.0),
            Self::DampingLevel => c.c2_nms_per_rad / damping_scale(model),
            Self::MassRatio => c.rod1.mass_kg / mass_beyond_joint(model),
        }
    }

    /// Whether the axis counts (`rods`): a map samples it at whole numbers.
    #[must_use]
    pub fn counts(&self) -> bool {
        matches!(self, Self::Key(Key::Rods))
    }

    /// `model` with this axis at `value`, validated like `--set`.
    ///
    /// # Errors
    /// A value or a resulting model that is refused, naming the axis.
    pub fn apply(&self, model: &Model, value: f64) -> Result<Model, ModelError> {
        let mut out = *model;
        match self {
            Self::MassRatio => {
                non_negative(Quantity::MassRatio, value)?;
                let m1 = value * mass_beyond_joint(model);
                return Self::Key(Key::M1).apply(model, m1);
            }
            Self::Key(key) => {
                apply_assignments(&mut out, &[Assignment { key: *key, value }])?;
            }
            Self::DamperRatio => {
                non_negative(Quantity::DamperRatio, value)?;
                let c2 = out.column.c2_nms_per_rad;
                if c2 <= 0.0 {
                    return Err(ModelError::invalid(
                        Quantity::DamperRatio,
                        value,
                        Allowed::NeedsDampedJoint2,
                    ));
                }
                out.column.c1_nms_per_rad = value * c2;
            }
            Self::DampingLevel => {
                non_negative(Quantity::DampingLevel, value)?;
                let Some(beta) =
                    ratio(model).or((model.column.c1_nms_per_rad == 0.0).then_some(1.0))
                else {
                    return Err(ModelError::invalid(
                        Quantity::DampingLevel,
                        value,
                        Allowed::InfiniteDamperRatio,
                    ));
                };
                let c2 = value * damping_scale(model);
                out.column.c2_nms_per_rad = c2;
                out.column.c1_nms_per_rad = beta * c2;
            }
        }
        out.validate()?;
        Ok(out)
    }
}

/// Refuses a value of a derived axis that is negative or not finite.
fn non_negative(axis: Quantity, value: f64) -> Result<(), ModelError> {
    if value.is_finite() && value >= 0.0 {
        Ok(())
    } else {
        Err(ModelError::invalid(axis, value, Allowed::NonNegative))
    }
}

/// c1/c2 when c2 > 0.
fn ratio(model: &Model) -> Option<f64> {
    let c = &model.column;
    (c.c2_nms_per_rad > 0.0).then(|| c.c1_nms_per_rad / c.c2_nms_per_rad)
}

/// `sqrt(k m l^2)`, the damping that makes `g = 1` (physics.md section 7).
fn damping_scale(model: &Model) -> f64 {
    (model.reference_stiffness_nm_per_rad()
        * model.reference_mass_kg()
        * model.reference_length_m().powi(2))
    .sqrt()
}

/// The mass beyond the joint A: every rod after the first (rod 2, repeated
/// on a chain), the tip mass and the roller.
fn mass_beyond_joint(model: &Model) -> f64 {
    let c = &model.column;
    #[expect(clippy::cast_precision_loss, reason = "at most 64 rods")]
    let rods_beyond = (c.rods - 1) as f64;
    rods_beyond * c.rod2.mass_kg + c.tip_mass_kg + model.roller().map_or(0.0, |r| r.mass_kg)
}
