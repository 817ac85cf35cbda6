//! Why a value was refused, as data: what a refused value must be. English
//! words here (the command line's); the window words the same data in its
//! language.

use super::keys::Key;
use super::params::LARGEST_DERIVED;
use super::quantity::Quantity;
use crate::format::Shown;
use std::fmt;

/// What a refused value must be (or why no value of it can be taken).
#[derive(Debug, Clone, Copy, PartialEq, strum::IntoStaticStr)]
#[strum(serialize_all = "kebab-case")]
pub enum Allowed {
    Finite,
    Positive,
    NonNegative,
    /// Within the key's own range (its table row's range and unit).
    KeyRange(Key),
    /// Between `min` and the parameter `max_key`, whose value is `max`.
    Between {
        min: f64,
        max: f64,
        max_key: Key,
    },
    /// A whole number of rods from 2 to `most`.
    Rods {
        most: usize,
    },
    /// eta in [0, 1].
    EtaRange,
    /// mu = 0: no load at all.
    FrictionlessBand,
    /// mu so small that the load `load_p` needs an infinite normal force.
    FrictionTooSmall {
        load_p: f64,
    },
    /// The value itself is beyond the analysis's range.
    BeyondAnalysis,
    /// The value makes a derived quantity beyond the analysis's range.
    MakesBeyondAnalysis(Quantity),
    /// The mass matrix's determinant is below rounding: unequal masses.
    MassesTooUnequal,
    /// The mass matrix is singular: no mass where one is needed.
    MassMissing,
    /// A chain whose copies of rod 2 carry no mass.
    ChainMassless,
    /// The damper ratio needs a damped joint 2.
    NeedsDampedJoint2,
    /// The damping level would hold an infinite ratio c1/c2.
    InfiniteDamperRatio,
    /// A band at rest: friction not differentiable about rest.
    BandAtRest,
    /// eta asked of a roller, where it is an outcome, not a parameter.
    RollerHasNoEta,
    /// A state of `2 (rods + 1)` numbers.
    StateLength,
    /// A time step in (0, 1] s.
    TimeStep,
}

impl Allowed {
    /// A short stable id (for message catalogues): the variant's name.
    #[must_use]
    pub fn id(&self) -> &'static str {
        self.into()
    }
}

impl fmt::Display for Allowed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Finite => f.write_str("must be a finite number"),
            Self::Positive => f.write_str("must be > 0"),
            Self::NonNegative => f.write_str("must be >= 0"),
            Self::KeyRange(key) => {
                let spec = key.spec();
                let text = if spec.counts() {
                    format!("must be a whole number {}", spec.range)
                } else {
                    format!("must be a finite number {} {}", spec.range, spec.unit)
                };
                f.write_str(text.trim_end())
            }
            Self::Between { min, max, max_key } => write!(
                f,
                "must lie between {} and {max_key} = {}",
                Shown(min),
                Shown(max)
            ),
            Self::Rods { most } => write!(f, "must be a whole number from 2 to {most}"),
            Self::EtaRange => f.write_str("must lie between 0 (dead load) and 1 (follower force)"),
            Self::FrictionlessBand => f.write_str(
                "must be > 0: without friction the band exerts no load at all (use load=0 for an unloaded column)",
            ),
            Self::FrictionTooSmall { load_p } => write!(
                f,
                "too small: the load p = {} would need the normal force R = P / mu beyond every number",
                Shown(load_p)
            ),
            Self::BeyondAnalysis => f.write_str(&analysis_range_text()),
            Self::MakesBeyondAnalysis(what) => {
                write!(f, "makes {what} {}", analysis_range_text())
            }
            Self::MassesTooUnequal => f.write_str(
                "the masses are too unequal: the determinant of the mass matrix is below 1e-12 of its scale, so rounding decides the motion (e.g. a tip mass or roller over about 1e12 times the rods')",
            ),
            Self::MassMissing => f.write_str(
                "the column needs mass beyond the joint A (rod 2, tip or roller) and mass or inertia that moves with rod 1 on its own; the mass matrix is singular",
            ),
            Self::ChainMassless => f.write_str(
                "a chain needs mass or inertia on every copy of rod 2 (m2 or I2 > 0): with rod 2 massless the chain's mass matrix is singular",
            ),
            Self::NeedsDampedJoint2 => f.write_str(
                "needs a damped joint 2: set c2 > 0 (or the damping level) first",
            ),
            Self::InfiniteDamperRatio => f.write_str(
                "c2 = 0 with c1 > 0: the ratio c1/c2 to hold is infinite; set c2 > 0 first",
            ),
            Self::BandAtRest => f.write_str(
                "must be > 0 for the linear analysis: at V = 0 Coulomb friction is not differentiable about rest (stick-slip)",
            ),
            Self::RollerHasNoEta => f.write_str(
                "the roller has no eta: the band's friction sets the force's direction, against the contact's slip, and its angle delta from rod 2 is an outcome of the motion, not a parameter",
            ),
            Self::StateLength => {
                f.write_str("must be 2 (rods + 1): the angles, the spin and their rates")
            }
            Self::TimeStep => f.write_str("must be a time step in (0, 1] s"),
        }
    }
}

/// What [`super::Model::beyond_analysis`] allows, in words for a refusal.
fn analysis_range_text() -> String {
    format!(
        "beyond what the analysis can square (sizes {:e} to {LARGEST_DERIVED:e})",
        1.0 / LARGEST_DERIVED
    )
}
