//! The state following the analysis of its parameters: the locus and the
//! critical loads computed inline or on the analysis thread (the newest
//! parameters win, a late answer for parameters left behind is dropped),
//! and the spectrum at the current load, always exact at once.

use super::AppState;
use crate::analysis::AnalysisError;
use crate::analysis::{AffinePencil, C64, Spectrum};
use crate::app::analysis_cache::Analysis;
use crate::app::jobs::Jobs;
use crate::app::notice::Notice;
use crate::model::ValidModel;

/// The analyses computed off the UI thread, each tagged with the
/// parameters (at p = 0) it is for.
pub type AnalysisJobs = Jobs<ValidModel, Result<Analysis, AnalysisError>>;

/// A finished analysis and the parameters it is for.
type Finished = (ValidModel, Result<Analysis, AnalysisError>);

impl AppState {
    /// Analyses new parameters on a thread of their own from now on: the
    /// locus and the critical loads follow a frame or so behind a dragged
    /// slider, and the frame never waits for them. Stays inline when the
    /// system gives no thread.
    pub fn analyse_in_background(&mut self) {
        if self.worker.is_none() {
            self.worker = Some(Jobs::new("analysis"));
        }
    }

    /// Whether an analysis of the current parameters is still being computed.
    #[must_use]
    pub fn analysis_pending(&self) -> bool {
        self.pending.is_some()
    }

    /// Whether anything is still computed off the UI thread (the analysis or
    /// the overlay): the window keeps drawing until it is in.
    #[must_use]
    pub fn background_pending(&self) -> bool {
        self.pending.is_some() || self.overlay_pending()
    }

    /// Takes what the analysis thread finished (call once a frame).
    pub fn receive_analysis(&mut self) {
        let finished: Vec<Finished> = self
            .worker
            .as_ref()
            .map(|jobs| jobs.drain().collect())
            .unwrap_or_default();
        for result in finished {
            self.install(result);
        }
        self.receive_overlay(false);
    }

    /// Waits until the analysis of the current parameters is in (for
    /// pictures and tests; the window never waits).
    pub fn settle_analysis(&mut self) {
        self.receive_overlay(true);
        if self.pending.is_none() {
            return;
        }
        if let Some(jobs) = &mut self.worker {
            jobs.wait();
        }
        self.receive_analysis();
        if self.pending.is_some() {
            // The job ended without an answer (its thread panicked): from now
            // on, analyse here.
            self.worker = None;
            self.pending = None;
            self.refresh_analysis();
        }
    }

    /// Recomputes the locus and the critical loads when the parameters
    /// (anything but the load) changed, inline or on the analysis thread;
    /// the spectrum at the current load always here and now.
    pub(super) fn refresh_analysis(&mut self) {
        self.receive_analysis();
        // The model as the simulation checked it: nothing here checks it again.
        let Ok(key) = self.sim.valid_model().at_load(0.0) else {
            return;
        };
        if !self.shows_analysis_of(&key) && self.pending != Some(key) {
            let sent = self.worker.as_mut().is_some_and(|jobs| {
                jobs.request(key, |key, _, send| send(Analysis::new(key)))
                    .is_ok()
            });
            if sent {
                self.pending = Some(key);
            } else {
                self.worker = None;
                self.install((key, Analysis::new(&key)));
            }
        }
        let model = self.settings.model;
        let spectrum = match &self.analysis {
            Some(analysis) if analysis.key == key => analysis.pencil.spectrum(model.load_p()),
            // The locus is on its way; the spectrum here cannot wait for it.
            _ => AffinePencil::new(&key).and_then(|pencil| pencil.spectrum(model.load_p())),
        };
        self.current = spectrum.ok().map(|spectrum| (model, spectrum));
    }

    /// Whether the analysis (or its failure) shown is that of `key`.
    fn shows_analysis_of(&self, key: &ValidModel) -> bool {
        self.analysis.as_ref().is_some_and(|a| a.key == *key)
            || self
                .analysis_failure
                .as_ref()
                .is_some_and(|(k, _)| k == key)
    }

    /// Shows a finished analysis: the current parameters' or, while a
    /// slider is dragged on, the newest there is (it is dropped once the
    /// current parameters' own analysis is shown).
    fn install(&mut self, (key, result): Finished) {
        if self.pending == Some(key) {
            self.pending = None;
        }
        if let Ok(current) = self.sim.valid_model().at_load(0.0)
            && key != current
            && self.shows_analysis_of(&current)
        {
            return;
        }
        self.analysis_failure = None;
        match result {
            Ok(analysis) => self.analysis = Some(analysis),
            Err(error) => {
                // No stale plots: the old locus belongs to other parameters.
                self.analysis = None;
                let why = crate::i18n::analysis_error(self.words(), &error);
                self.say(Notice::error(crate::tr!(
                    self.words(),
                    "notice-analysis-unavailable",
                    why = why
                )));
                self.analysis_failure = Some((key, error));
            }
        }
    }

    /// The spectrum at the current load, if the current model has one.
    #[must_use]
    pub fn current_spectrum(&self) -> Option<&Spectrum> {
        self.current
            .as_ref()
            .filter(|(m, _)| *m == self.settings.model && self.analysis.is_some())
            .map(|(_, spectrum)| spectrum)
    }

    /// Every eigenvalue at the current load (none without an analysis).
    #[must_use]
    pub fn current_eigenvalues(&self) -> Vec<C64> {
        self.current_spectrum()
            .map(|s| s.all().collect())
            .unwrap_or_default()
    }
}
