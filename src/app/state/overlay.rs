//! A second preset's root locus and critical loads drawn behind the current
//! model's (the paper's Fig. 8 sets the ideal column beside the roller).

use super::AppState;
use crate::analysis::{AlongLoad, AnalysisError, Locus, Transition};
use crate::app::analysis_cache::window_locus;
use crate::app::jobs::Jobs;
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
pub(super) enum OverlayError {
    #[error(transparent)]
    Model(#[from] ModelError),
    #[error(transparent)]
    Analysis(#[from] AnalysisError),
}

/// What an overlay is computed for: the preset and the group `a`.
pub(super) type OverlayKey = (PresetId, f64);

/// Overlays computed off the UI thread.
pub(super) type OverlayJobs = Jobs<OverlayKey, Result<Overlay, OverlayError>>;

/// `id`'s locus and critical loads at the group `a`.
fn build(id: PresetId, a: f64) -> Result<Overlay, OverlayError> {
    let mut model = id.model();
    let valid = apply_assignments(
        &mut model,
        &[Assignment {
            key: Key::A,
            value: a,
        }],
    )?;
    let (
        _,
        AlongLoad {
            locus, transitions, ..
        },
    ) = window_locus(&valid)?;
    Ok(Overlay {
        preset: id,
        a,
        locus,
        transitions,
    })
}

impl Overlay {
    /// The group `a` the locus was computed with.
    #[must_use]
    pub fn a(&self) -> f64 {
        self.a
    }
}

impl AppState {
    /// Shows `id`'s locus behind the current one, at the current `a`
    /// (`None`: no overlay): on the analysis thread's side when the state
    /// analyses in the background (the overlay drawn until then stays),
    /// here otherwise.
    pub(super) fn set_overlay(&mut self, id: Option<PresetId>) {
        let Some(id) = id else {
            self.overlay = None;
            self.overlay_wanted = None;
            return;
        };
        let key = (id, self.group_a());
        self.overlay_wanted = Some(key);
        if self.worker.is_some() {
            let jobs = self
                .overlay_jobs
                .get_or_insert_with(|| Jobs::new("overlay"));
            if jobs.key() == Some(&key) {
                return;
            }
            let started = jobs.request(key, |&(id, a), _, send| {
                send(build(id, a));
            });
            if started.is_ok() {
                return;
            }
        }
        self.install_overlay(key, build(key.0, key.1));
    }

    /// The preset chosen for the overlay (shown once computed).
    #[must_use]
    pub fn overlay_choice(&self) -> Option<PresetId> {
        self.overlay_wanted.map(|(id, _)| id)
    }

    /// Whether the overlay chosen is still being computed.
    pub(super) fn overlay_pending(&self) -> bool {
        self.overlay_wanted.is_some()
            && self.overlay.as_ref().map(|o| (o.preset, o.a)) != self.overlay_wanted
    }

    /// Takes the overlays computed off the UI thread (once a frame), and
    /// with `wait` first waits for the one chosen.
    pub(super) fn receive_overlay(&mut self, wait: bool) {
        let Some(jobs) = &mut self.overlay_jobs else {
            return;
        };
        if wait {
            jobs.wait();
        }
        let finished: Vec<_> = jobs.drain().collect();
        for (key, result) in finished {
            self.install_overlay(key, result);
        }
    }

    /// Shows an overlay computed for `key` if it is still the one chosen.
    fn install_overlay(&mut self, key: OverlayKey, result: Result<Overlay, OverlayError>) {
        if self.overlay_wanted != Some(key) {
            return;
        }
        match result {
            Ok(overlay) => self.overlay = Some(overlay),
            Err(error) => {
                self.overlay = None;
                self.overlay_wanted = None;
                let words = self.words();
                let why = match &error {
                    OverlayError::Model(error) => crate::i18n::model_error(words, error),
                    OverlayError::Analysis(error) => crate::i18n::analysis_error(words, error),
                };
                self.say(Notice::error(crate::tr!(
                    words,
                    "notice-overlay-unavailable",
                    why = why
                )));
            }
        }
    }
}
