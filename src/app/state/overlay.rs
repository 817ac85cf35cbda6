//! A second preset's root locus and critical loads drawn behind the current
//! model's (the paper's Fig. 8 sets the ideal column beside the roller).

use super::AppState;
use crate::analysis::{
    AffinePencil, AnalysisError, Locus, Transition, critical_loads_along, locus,
};
use crate::app::analysis_cache::LOCUS_SAMPLES;
use crate::app::notice::Notice;
use crate::model::{Assignment, Key, ModelError, PresetId, apply_assignments};

/// Another preset's root locus, at the current model's `a`.
pub struct Overlay {
    pub preset: PresetId,
    /// The group `a` the locus was computed with.
    pub(super) a: f64,
    pub locus: Locus,
    /// Its critical loads along the slider's range.
    pub transitions: Vec<Transition>,
}

/// Why the overlay could not be drawn.
#[derive(Debug, thiserror::Error)]
enum OverlayError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Analysis(#[from] AnalysisError),
}

impl AppState {
    /// Shows `name`'s locus behind the current one, at the current `a`
    /// (`None`: no overlay).
    pub(super) fn set_overlay(&mut self, id: Option<PresetId>) {
        let Some(id) = id else {
            self.overlay = None;
            return;
        };
        let a = self.group_a();
        let build = || -> Result<(Locus, Vec<Transition>), OverlayError> {
            let mut model = id.model();
            apply_assignments(
                &mut model,
                &[Assignment {
                    key: Key::A,
                    value: a,
                }],
            )?;
            let pencil = AffinePencil::new(&model)?;
            let locus = locus(&pencil, 0.0, model.load_bar_max_p(), LOCUS_SAMPLES)?;
            let transitions = critical_loads_along(&pencil, &locus)?;
            Ok((locus, transitions))
        };
        match build() {
            Ok((locus, transitions)) => {
                self.overlay = Some(Overlay {
                    preset: id,
                    a,
                    locus,
                    transitions,
                });
            }
            Err(error) => {
                self.overlay = None;
                self.say(Notice::error(format!("overlay unavailable: {error}")));
            }
        }
    }
}
