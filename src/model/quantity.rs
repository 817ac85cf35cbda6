//! What a refusal names when it is not a parameter set by its key: a
//! quantity made of several (an inertia, the load P), a map's derived axis
//! or an argument of a run. A leaf of the model: the parameters, the axes
//! and the refusals all name these.

use std::fmt;

/// The name of the damper-ratio axis, `c1/c2` (the damping level held).
pub const DAMPER_RATIO: &str = "c1/c2";
/// The name of the mass-ratio axis: rod 1's mass (with what sits at A) over
/// the mass beyond A (rod 2, tip, roller), which is held.
pub const MASS_RATIO: &str = "mass_ratio";
/// The name of the damping-level axis, `g2 = c2 / sqrt(k m l^2)` (physics.md
/// section 7; the ratio c1/c2 held, 1 for an undamped column).
pub const DAMPING_LEVEL: &str = "damping";

/// A quantity made of several parameters (or an argument of a run) that a
/// refusal names when it is not a parameter the user sets by its key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, strum::VariantArray)]
pub enum Quantity {
    /// The load P, a force.
    LoadForce,
    /// The load p = P l/k.
    LoadP,
    InertiaO,
    InertiaCoupling,
    InertiaA,
    StiffnessK1,
    StiffnessK2,
    DamperC1,
    DamperC2,
    /// The drag `c_ext l^3`.
    Drag,
    /// The roller's slip damping `mu R l^2 / V`.
    SlipDamping,
    /// The roller's spin inertia `m3 r^2 / 2`.
    SpinInertia,
    MassMatrix,
    /// The map's axis c1/c2.
    DamperRatio,
    /// The map's axis "damping" (both dampers scaled).
    DampingLevel,
    /// The map's axis `mass_ratio`.
    MassRatio,
    /// The paradox explorer's external drag ratio `c_ext l^3 / c`.
    DragRatio,
    /// A simulation's initial state's length.
    StateLength,
    /// A simulation's time step.
    TimeStep,
}

impl Quantity {
    /// Its name in English (a symbol where it has one).
    #[must_use]
    pub const fn name(self) -> &'static str {
        match self {
            Self::LoadForce => "the load P",
            Self::LoadP => "the load p = P l/k",
            Self::InertiaO => "the inertia about O",
            Self::InertiaCoupling => "the coupling inertia",
            Self::InertiaA => "the inertia about A",
            Self::StiffnessK1 => "the stiffness k1",
            Self::StiffnessK2 => "the stiffness k2",
            Self::DamperC1 => "the damper c1",
            Self::DamperC2 => "the damper c2",
            Self::Drag => "the drag c_ext l^3",
            Self::SlipDamping => "the slip damping mu R l^2 / V",
            Self::SpinInertia => "the roller's spin inertia m3 r^2 / 2",
            Self::MassMatrix => "mass matrix",
            Self::DamperRatio => DAMPER_RATIO,
            Self::DampingLevel => DAMPING_LEVEL,
            Self::MassRatio => MASS_RATIO,
            Self::DragRatio => "c_ext l^3/c",
            Self::StateLength => "the state's length",
            Self::TimeStep => "dt",
        }
    }

    /// A short stable id (for message catalogues).
    #[must_use]
    pub const fn id(self) -> &'static str {
        match self {
            Self::LoadForce => "load-force",
            Self::LoadP => "load-p",
            Self::InertiaO => "inertia-o",
            Self::InertiaCoupling => "inertia-coupling",
            Self::InertiaA => "inertia-a",
            Self::StiffnessK1 => "stiffness-k1",
            Self::StiffnessK2 => "stiffness-k2",
            Self::DamperC1 => "damper-c1",
            Self::DamperC2 => "damper-c2",
            Self::Drag => "drag",
            Self::SlipDamping => "slip-damping",
            Self::SpinInertia => "spin-inertia",
            Self::MassMatrix => "mass-matrix",
            Self::DamperRatio => "damper-ratio",
            Self::DampingLevel => "damping-level",
            Self::MassRatio => "mass-ratio",
            Self::DragRatio => "drag-ratio",
            Self::StateLength => "state-length",
            Self::TimeStep => "time-step",
        }
    }
}

impl fmt::Display for Quantity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
