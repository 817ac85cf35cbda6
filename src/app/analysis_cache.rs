//! The linear analysis of the current parameters as the app keeps it: the
//! locus over the slider's range, the critical loads, the stability ranges
//! and the resolution warning, computed once per change of parameters.

use crate::analysis::{
    AffinePencil, AnalysisError, BRACKET_SAMPLES, Locus, State, Transition, classify,
    critical_loads_along, first_loss_of_stability, locus, resolution_warning,
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
    pub warning: Option<String>,
}

impl Analysis {
    pub(super) fn new(model: &ValidModel) -> Result<Self, AnalysisError> {
        let key = model.at_load(0.0)?;
        let pencil = AffinePencil::new(&key)?;
        let load_max = model.load_bar_max_p();
        let locus = locus(&pencil, 0.0, load_max, LOCUS_SAMPLES)?;
        let transitions = critical_loads_along(&pencil, &locus)?;
        let warning = resolution_warning(&pencil, &locus)?;
        let at_zero = pencil.spectrum(0.0)?;
        let first = classify(&at_zero.eigenvalues, at_zero.scale_per_s).state;
        let ranges = ranges(&transitions, first, load_max);
        Ok(Self {
            key,
            pencil,
            locus,
            transitions,
            ranges,
            warning,
        })
    }

    /// The first load at which the column loses stability, if it does below
    /// the slider's end.
    #[must_use]
    pub fn first_instability(&self) -> Option<f64> {
        first_loss_of_stability(&self.transitions)
    }
}

/// The stability ranges `(from, to, state)` covering `[0, max]`, from the
/// transitions and the state at p = 0.
#[must_use]
pub fn ranges(transitions: &[Transition], first: State, max: f64) -> Vec<(f64, f64, State)> {
    let mut out = Vec::new();
    let (mut start, mut state) = (0.0, first);
    for t in transitions {
        if t.load > max {
            break;
        }
        out.push((start, t.load, state));
        (start, state) = (t.load, t.to);
    }
    out.push((start, max, state));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn t(load: f64, from: State, to: State) -> Transition {
        Transition { load, from, to }
    }

    #[test]
    fn ranges_cover_the_slider_from_zero_to_its_end() {
        let transitions = [
            t(2.0, State::Stable, State::Flutter),
            t(4.0, State::Flutter, State::Divergence),
            t(9.0, State::Divergence, State::Flutter),
        ];
        let ranges = ranges(&transitions, State::Stable, 8.0);
        assert_eq!(
            ranges,
            vec![
                (0.0, 2.0, State::Stable),
                (2.0, 4.0, State::Flutter),
                (4.0, 8.0, State::Divergence)
            ]
        );
    }
}
