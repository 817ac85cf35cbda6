//! The names of the parameters a user can set (`--set key=value`, the
//! lessons, the UI's fields, the stored settings) and what describes each
//! one; the descriptions themselves are the table in `key_table`.

use super::ModelError;
use strum::VariantArray;

use super::params::Model;

/// A settable parameter, by the name `--set` and the app's fields use (and
/// read by that name from a file).
#[derive(
    Clone,
    Copy,
    Debug,
    PartialEq,
    Eq,
    Hash,
    PartialOrd,
    Ord,
    serde::Deserialize,
    strum::VariantArray,
    strum::IntoStaticStr,
    strum::Display,
)]
#[serde(try_from = "String")]
pub enum Key {
    #[strum(serialize = "load")]
    Load,
    #[strum(serialize = "a")]
    A,
    #[strum(serialize = "nu")]
    Nu,
    #[strum(serialize = "rho")]
    Rho,
    #[strum(serialize = "mu")]
    Mu,
    #[strum(serialize = "V")]
    V,
    #[strum(serialize = "l1")]
    L1,
    #[strum(serialize = "l2")]
    L2,
    #[strum(serialize = "m1")]
    M1,
    #[strum(serialize = "m2")]
    M2,
    #[strum(serialize = "s1")]
    S1,
    #[strum(serialize = "s2")]
    S2,
    #[strum(serialize = "I1")]
    I1,
    #[strum(serialize = "I2")]
    I2,
    #[strum(serialize = "m_tip")]
    MTip,
    #[strum(serialize = "k1")]
    K1,
    #[strum(serialize = "k2")]
    K2,
    #[strum(serialize = "c1")]
    C1,
    #[strum(serialize = "c2")]
    C2,
    #[strum(serialize = "c_ext")]
    CExt,
    #[strum(serialize = "rods")]
    Rods,
    #[strum(serialize = "P")]
    P,
    #[strum(serialize = "eta")]
    Eta,
    #[strum(serialize = "m3")]
    M3,
    #[strum(serialize = "r")]
    RollerRadius,
    #[strum(serialize = "R")]
    NormalForce,
}

impl Key {
    /// Every key, in the order of its declaration (and of `KEYS`).
    #[must_use]
    pub fn all() -> &'static [Self] {
        Self::VARIANTS
    }

    /// The key's name, as typed.
    #[must_use]
    pub fn name(self) -> &'static str {
        self.into()
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
        crate::names::variant_named(name).ok_or_else(|| ModelError::UnknownKey {
            key: crate::format::clipped(name, MOST_KEY_CHARS),
            known: crate::names::variant_names::<Self>(),
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
    /// True for a key that stands for other parameters (the load p for P or
    /// R, `a` for k1 and k2, `nu` for m3, `rho` for r): settings are stored
    /// without them, by the parameters they stand for.
    pub derived: bool,
    pub(super) sign: Sign,
    /// Keys are applied in increasing stage, so that the load is set last and
    /// a group is computed from the final lengths and masses.
    pub stage: u8,
    pub(super) get: fn(&Model) -> f64,
    pub(super) set: fn(&mut Model, f64),
}

impl KeySpec {
    /// Whether the key counts (a whole number), rather than measures.
    #[must_use]
    pub const fn counts(&self) -> bool {
        matches!(self.sign, Sign::Count(..))
    }

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
