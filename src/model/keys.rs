//! The parameters a user can set by name (`--set key=value`, the UI's fields):
//! every SI parameter and the paper's dimensionless groups, with units and ranges.

use super::ModelError;
pub use super::key_table::KEYS;
use super::params::{Model, analysis_range_text};

/// A settable parameter, by the name `--set` and the app's fields use (and
/// read by that name from a file).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, serde::Deserialize)]
#[serde(try_from = "String")]
pub enum Key {
    Load,
    A,
    Nu,
    Rho,
    Mu,
    V,
    L1,
    L2,
    M1,
    M2,
    S1,
    S2,
    I1,
    I2,
    MTip,
    K1,
    K2,
    C1,
    C2,
    CExt,
    Rods,
    P,
    Eta,
    M3,
    RollerRadius,
    NormalForce,
}

impl Key {
    /// Every key, in the order of [`KEYS`].
    pub const ALL: [Self; 26] = [
        Self::Load,
        Self::A,
        Self::Nu,
        Self::Rho,
        Self::Mu,
        Self::V,
        Self::L1,
        Self::L2,
        Self::M1,
        Self::M2,
        Self::S1,
        Self::S2,
        Self::I1,
        Self::I2,
        Self::MTip,
        Self::K1,
        Self::K2,
        Self::C1,
        Self::C2,
        Self::CExt,
        Self::Rods,
        Self::P,
        Self::Eta,
        Self::M3,
        Self::RollerRadius,
        Self::NormalForce,
    ];

    /// The key's name, as typed.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Load => "load",
            Self::A => "a",
            Self::Nu => "nu",
            Self::Rho => "rho",
            Self::Mu => "mu",
            Self::V => "V",
            Self::L1 => "l1",
            Self::L2 => "l2",
            Self::M1 => "m1",
            Self::M2 => "m2",
            Self::S1 => "s1",
            Self::S2 => "s2",
            Self::I1 => "I1",
            Self::I2 => "I2",
            Self::MTip => "m_tip",
            Self::K1 => "k1",
            Self::K2 => "k2",
            Self::C1 => "c1",
            Self::C2 => "c2",
            Self::CExt => "c_ext",
            Self::Rods => "rods",
            Self::P => "P",
            Self::Eta => "eta",
            Self::M3 => "m3",
            Self::RollerRadius => "r",
            Self::NormalForce => "R",
        }
    }

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
    pub fn why_absent(self, model: &Model) -> Option<&'static str> {
        match self {
            Self::Eta if model.roller().is_some() => Some(
                "the roller has no eta: the band's friction sets the force's direction, against the contact's slip, and its angle delta from rod 2 is an outcome of the motion, not a parameter",
            ),
            _ => None,
        }
    }

    /// The names of the keys that apply to `model`, for messages.
    #[must_use]
    pub fn names_for(model: &Model) -> String {
        Self::ALL
            .iter()
            .filter(|key| key.applies_to(model))
            .map(|key| key.name())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

impl std::fmt::Display for Key {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl TryFrom<String> for Key {
    type Error = ModelError;

    fn try_from(name: String) -> Result<Self, ModelError> {
        name.parse()
    }
}

/// The most characters of an unknown key a message repeats.
const MOST_KEY_CHARS: usize = 40;

impl std::str::FromStr for Key {
    type Err = ModelError;

    /// The key named `name` (case-sensitive: `r` is the roller's radius, `R`
    /// the band's normal force).
    fn from_str(name: &str) -> Result<Self, ModelError> {
        Self::ALL
            .into_iter()
            .find(|key| key.name() == name)
            .ok_or_else(|| ModelError::UnknownKey {
                key: crate::format::clipped(name, MOST_KEY_CHARS),
                known: Self::ALL.map(Self::name).join(", "),
            })
    }
}

/// Which loads a key exists for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    All,
    /// Ideal follower or dead force.
    Force,
    Roller,
}

/// The immediate check on a value, before the whole model is validated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Sign {
    Positive,
    NonNegative,
    /// A whole number from the first to the second, inclusive.
    Count(usize, usize),
}

/// One settable parameter.
#[derive(Clone, Copy, Debug)]
pub struct KeySpec {
    pub key: Key,
    pub unit: &'static str,
    pub description: &'static str,
    /// The allowed range, as text (bounds may name other parameters).
    pub range: &'static str,
    pub scope: Scope,
    /// True for the paper's dimensionless groups (and the load p).
    pub is_group: bool,
    pub(super) sign: Sign,
    /// Keys are applied in increasing stage, so that the load is set last and
    /// a group is computed from the final lengths and masses.
    pub(super) stage: u8,
    pub(super) get: fn(&Model) -> f64,
    pub(super) set: fn(&mut Model, f64),
}

impl KeySpec {
    /// Whether the key exists for this model's load.
    #[must_use]
    pub fn applies_to(&self, model: &Model) -> bool {
        match self.scope {
            Scope::All => true,
            Scope::Force => model.roller().is_none(),
            Scope::Roller => model.roller().is_some(),
        }
    }

    /// The parameter's current value in `model`.
    #[must_use]
    pub fn get(&self, model: &Model) -> f64 {
        (self.get)(model)
    }
}

/// A parsed `key=value`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Assignment {
    pub key: Key,
    pub value: f64,
}

/// Parses `key=value` with a decimal number (`nan` and `inf` parse and are
/// rejected later, with the key named).
///
/// # Errors
/// [`ModelError::Malformed`] when there is no `=` or the value is not a
/// number, [`ModelError::UnknownKey`] for a name that is no key.
pub fn parse_assignment(text: &str) -> Result<Assignment, ModelError> {
    let malformed = |reason: &str| ModelError::Malformed {
        text: text.to_owned(),
        reason: reason.to_owned(),
    };
    let (key, value) = text.split_once('=').ok_or_else(|| malformed("no '='"))?;
    let key = key.trim();
    if key.is_empty() {
        return Err(malformed("empty key"));
    }
    let value = value
        .trim()
        .parse::<f64>()
        .map_err(|_| malformed(&format!("'{}' is not a number", value.trim())))?;
    Ok(Assignment {
        key: key.parse()?,
        value,
    })
}

/// Keys that write the same quantity; setting both is ambiguous.
const CONFLICTS: [(Key, Key); 6] = [
    (Key::M3, Key::Nu),
    (Key::RollerRadius, Key::Rho),
    (Key::K1, Key::A),
    (Key::K2, Key::A),
    (Key::Load, Key::P),
    (Key::Load, Key::NormalForce),
];

/// Applies the assignments to `model` in the canonical order and validates the result.
///
/// # Errors
/// Unknown or inapplicable key, a key given twice or with a conflicting
/// partner, a value out of range (named by the key the user typed), or a
/// resulting model that [`Model::validate`] rejects.
pub fn apply_assignments(model: &mut Model, assignments: &[Assignment]) -> Result<(), ModelError> {
    let mut specs: Vec<&KeySpec> = Vec::with_capacity(assignments.len());
    for assignment in assignments {
        let key = assignment.key;
        if !key.applies_to(model) {
            if let Some(why) = key.why_absent(model) {
                return Err(ModelError::invalid(key.name(), assignment.value, why));
            }
            return Err(ModelError::UnknownKey {
                key: key.name().to_owned(),
                known: Key::names_for(model),
            });
        }
        let spec = key.spec();
        for earlier in &specs {
            let clash = earlier.key == spec.key
                || CONFLICTS.iter().any(|&(a, b)| {
                    (a, b) == (earlier.key, spec.key) || (b, a) == (earlier.key, spec.key)
                });
            if clash {
                return Err(ModelError::Conflict {
                    first: earlier.key.name().to_owned(),
                    second: spec.key.name().to_owned(),
                });
            }
        }
        specs.push(spec);
    }
    let mut order: Vec<(&KeySpec, f64)> = specs
        .into_iter()
        .zip(assignments.iter().map(|assignment| assignment.value))
        .collect();
    order.sort_by_key(|(spec, _)| spec.stage);
    for (spec, value) in order {
        check_sign(spec, value)?;
        (spec.set)(model, value);
        if let Some((what, _)) = model.beyond_analysis() {
            return Err(ModelError::invalid(
                spec.key.name(),
                value,
                &format!("makes {what} {}", analysis_range_text()),
            ));
        }
    }
    model.validate()
}

fn check_sign(spec: &KeySpec, value: f64) -> Result<(), ModelError> {
    let allowed = match spec.sign {
        Sign::Count(..) => format!("must be a whole number {}", spec.range),
        Sign::Positive | Sign::NonNegative => {
            format!("must be a finite number {} {}", spec.range, spec.unit)
        }
    };
    #[expect(clippy::cast_precision_loss, reason = "small counts")]
    let ok = value.is_finite()
        && match spec.sign {
            Sign::Positive => value > 0.0,
            Sign::NonNegative => value >= 0.0,
            Sign::Count(min, max) => {
                value.fract() == 0.0 && (min as f64..=max as f64).contains(&value)
            }
        };
    if ok {
        Ok(())
    } else {
        Err(ModelError::invalid(
            spec.key.name(),
            value,
            allowed.trim_end(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Key::spec` indexes `KEYS` by the variant: the two orders must agree,
    /// and every name reads back as its key.
    #[test]
    fn every_key_reads_back_from_its_name_and_finds_its_spec() {
        for key in Key::ALL {
            assert_eq!(key.spec().key, key);
            assert_eq!(key.name().parse::<Key>().unwrap(), key);
            assert_eq!(key.to_string(), key.name());
        }
        let unknown = "colour".parse::<Key>().unwrap_err();
        assert!(unknown.to_string().contains("unknown key 'colour'"));
        // r and R are different keys.
        assert_ne!("r".parse::<Key>().unwrap(), "R".parse::<Key>().unwrap());
    }

    #[test]
    fn a_key_of_another_load_is_refused_naming_the_model_s_keys() {
        let mut column = super::super::PresetId::UniformRods.model();
        let set_r = Assignment {
            key: Key::NormalForce,
            value: 3.0,
        };
        let error = apply_assignments(&mut column, &[set_r]).unwrap_err();
        let text = error.to_string();
        assert!(text.starts_with("unknown key 'R'"), "{text}");
        assert!(text.contains("load, a, l1"), "{text}");
        assert!(!text.contains("nu"), "{text}");
    }
}
