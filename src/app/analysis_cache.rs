//! The linear analysis of the current parameters as the app keeps it: the
//! locus over the slider's range, the critical loads, the stability ranges
//! and the resolution warning, computed once per change of parameters.

use crate::analysis::{
    AffinePencil, AlongLoad, AnalysisError, BRACKET_SAMPLES, Hopf, HopfSteps, Locus, NoHopf,
    Sampling, State, Transition, Unresolved, first_loss_of_stability, hopf_at, is_hopf,
};
use crate::model::ValidModel;

/// Evenly spaced loads of the plotted locus (plus the refinement). The same
/// locus brackets the critical loads, with the sample count `critical` uses.
pub const LOCUS_SAMPLES: usize = BRACKET_SAMPLES;

/// The linear analysis of the current parameters, over the slider's range.
pub struct Analysis {
    /// The model at p = 0: the locus depends on everything but the load.
    pub(super) key: ValidModel,
    pub(super) pencil: AffinePencil,
    pub locus: Locus,
    pub transitions: Vec<Transition>,
    /// The stability ranges `(from, to, state)` that cover the slider's range.
    pub ranges: Vec<(f64, f64, State)>,
    /// Why the transitions cannot be trusted, when they cannot.
    pub warning: Option<crate::analysis::NotResolved>,
    /// Each flutter onset (stable to flutter) with its Hopf criticality, or
    /// why there is none (see [`hopf_at`]); `None` where it failed.
    pub onsets: Vec<(f64, Option<Result<Hopf, NoHopf>>)>,
}

/// The window's root locus of `model` (its load ignored) over the load
/// bar's range, the critical loads kept where rounding decides them (the
/// load bar says so beside them): the analysis's and the overlay's.
///
/// # Errors
/// As [`AlongLoad::of_model`].
pub fn window_locus(model: &ValidModel) -> Result<(AffinePencil, AlongLoad), AnalysisError> {
    AlongLoad::of_model(
        model,
        (0.0, model.load_bar_max_p()),
        Sampling::Even(LOCUS_SAMPLES),
        Unresolved::Kept,
        crate::machine_threads(),
    )
}

impl Analysis {
    pub(super) fn new(model: &ValidModel) -> Result<Self, AnalysisError> {
        let key = model.at_load(0.0)?;
        let (
            pencil,
            AlongLoad {
                locus,
                transitions,
                ranges,
                warning,
            },
        ) = window_locus(&key)?;
        let onsets = transitions
            .iter()
            .filter(|t| is_hopf(t.from, t.to) && t.to == State::Flutter)
            .map(|t| (t.load, hopf_at(&key, t.load, HopfSteps::DEFAULT).ok()))
            .collect();
        Ok(Self {
            key,
            pencil,
            locus,
            transitions,
            ranges,
            warning,
            onsets,
        })
    }

    /// The first load at which the column loses stability, if it does below
    /// the slider's end.
    #[must_use]
    pub fn first_instability(&self) -> Option<f64> {
        first_loss_of_stability(&self.transitions)
    }

    /// The flutter onset at or below `load` nearest it, with its Hopf
    /// criticality (the onset a column fluttering at `load` came through).
    #[must_use]
    pub fn onset_below(&self, load: f64) -> Option<&(f64, Option<Result<Hopf, NoHopf>>)> {
        self.onsets.iter().rev().find(|(onset, _)| *onset <= load)
    }
}
