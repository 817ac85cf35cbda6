//! What persists between runs of the app and can be shared as text: the
//! preset, its model, the engine, the speed and projector mode.

use crate::model::{Model, PresetId};
use crate::sim::EngineKind;

/// What persists between runs of the app.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct Settings {
    pub preset: PresetId,
    pub model: Model,
    pub engine: EngineKind,
    /// Simulated seconds per wall second.
    pub speed: f64,
    pub projector: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            preset: PresetId::Roller,
            model: PresetId::Roller.model(),
            engine: EngineKind::Rapier,
            speed: 1.0,
            projector: false,
        }
    }
}
