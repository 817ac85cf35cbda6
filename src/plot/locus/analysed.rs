//! A model's root locus as a figure gathers it: the one pipeline over a
//! range of loads, and the eigenvalues at each critical load.

use super::Layer;
use crate::analysis::{
    AlongLoad, AnalysisError, C64, Locus, NotResolved, Sampling, State, Transition, Unresolved,
};
use crate::model::Model;

/// A model's locus over a load range, its critical loads and stability
/// ranges, and its eigenvalues at each critical load: a figure's layer.
#[derive(Clone, Debug)]
pub struct Analysed {
    pub name: String,
    pub locus: Locus,
    pub transitions: Vec<Transition>,
    pub ranges: Vec<(f64, f64, State)>,
    /// The moving eigenvalues at each transition's load.
    pub at_transitions: Vec<Vec<C64>>,
    /// Why the states are not resolved over the range, if they are not.
    pub warning: Option<NotResolved>,
}

impl Analysed {
    /// `model`'s locus from `load_min` to `load_max` on the loads
    /// `critical` brackets with ([`Sampling::Plotted`]), solved on
    /// `threads`, its critical loads found on it as `critical` finds them,
    /// and the warning `critical` gives where rounding decides the states.
    /// Where it does, the changes it makes are noise (thousands of them,
    /// for a roller of mass nu = 1e-50): none is drawn as if it were
    /// found, and no range is tinted.
    ///
    /// # Errors
    /// A bad range, or an eigenvalue computation that fails.
    pub fn new(
        name: &str,
        model: &Model,
        (load_min, load_max): (f64, f64),
        threads: usize,
    ) -> Result<Self, AnalysisError> {
        let (
            pencil,
            AlongLoad {
                locus,
                transitions,
                ranges,
                warning,
            },
        ) = AlongLoad::of_model(
            model,
            (load_min, load_max),
            Sampling::Plotted,
            Unresolved::Dropped,
            threads,
        )?;
        let at_transitions = transitions
            .iter()
            .map(|t| Ok(pencil.spectrum(t.load)?.eigenvalues))
            .collect::<Result<_, AnalysisError>>()?;
        Ok(Self {
            name: name.to_owned(),
            locus,
            transitions,
            ranges,
            at_transitions,
            warning,
        })
    }

    /// This model as a layer of the locus plots.
    #[must_use]
    pub fn layer(&self) -> Layer<'_> {
        Layer {
            name: &self.name,
            locus: &self.locus,
            transitions: &self.transitions,
            ranges: &self.ranges,
            at_transitions: &self.at_transitions,
        }
    }
}
