//! The Ziegler paradox: the load at which a column first loses stability,
//! with joint dampers of a given ratio, or with external drag and equal
//! joint dampers in a given ratio, as their level goes to zero (or a roller
//! as its mass goes to zero), next to the undamped value.

use super::AnalysisError;
use super::critical::first_loss_within;
use super::crossing::Transition;
use super::pencil::AffinePencil;
use super::stability::State;
use crate::model::{Axis, Model};

/// The lowest load in `[0, load_max]` at which `model` goes from stable to
/// unstable, if it does.
///
/// # Errors
/// A model the linear analysis refuses.
pub fn first_instability(model: &Model, load_max: f64) -> Result<Option<f64>, AnalysisError> {
    let pencil = AffinePencil::new(model)?;
    Ok(first_loss_within(&pencil, load_max)?.map(|t| t.load))
}

/// The load of the first change from stable to unstable among
/// `transitions` (in increasing load), if there is one.
#[must_use]
pub fn first_loss_of_stability(transitions: &[Transition]) -> Option<f64> {
    transitions
        .iter()
        .find(|t| t.from == State::Stable)
        .map(|t| t.load)
}

/// [`first_instability`] with joint dampers `g1 = ratio level`,
/// `g2 = level` (`g_i = c_i / sqrt(k m l^2)`, physics.md section 7).
///
/// # Errors
/// A ratio or level the model refuses, or a failed analysis.
pub fn flutter_load_damped(
    model: &Model,
    ratio: f64,
    level: f64,
    load_max: f64,
) -> Result<Option<f64>, AnalysisError> {
    let damped = Axis::DampingLevel.apply(model, level)?;
    let damped = Axis::DamperRatio.apply(&damped, ratio)?;
    first_instability(&damped, load_max)
}

/// [`first_instability`] with equal joint dampers `g1 = g2 = level`
/// (the internal damping) and the external drag in the ratio `ratio` to
/// them: `c_ext l^3 = ratio c2`, with `l` the reference length. For
/// Ziegler's column its limit as `level` vanishes is in physics.md
/// section 7.
///
/// # Errors
/// A ratio or level the model refuses, or a failed analysis.
pub fn flutter_load_external(
    model: &Model,
    ratio: f64,
    level: f64,
    load_max: f64,
) -> Result<Option<f64>, AnalysisError> {
    if !(ratio.is_finite() && ratio >= 0.0) {
        return Err(crate::model::ModelError::invalid(
            "c_ext l^3/c",
            ratio,
            "must be a finite number >= 0",
        )
        .into());
    }
    let mut undamped = *model;
    undamped.column.c1_nms_per_rad = 0.0;
    undamped.column.c2_nms_per_rad = 0.0;
    let mut damped = Axis::DampingLevel.apply(&undamped, level)?;
    damped.column.drag_ns_per_m2 =
        ratio * damped.column.c2_nms_per_rad / damped.reference_length_m().powi(3);
    damped.validate()?;
    first_instability(&damped, load_max)
}
