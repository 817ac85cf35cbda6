//! A model's stability along the load, the one pipeline every root locus
//! goes through (the window's, its overlay's, a figure's): the locus, the
//! critical loads found on it, the ranges of each state, and why they
//! cannot be trusted where they cannot.

use super::critical::critical_loads_along;
use super::crossing::{Transition, stability_ranges};
use super::locus::Locus;
use super::pencil::AffinePencil;
use super::resolution::{NotResolved, resolution_warning};
use super::stability::{State, classify};
use crate::analysis::AnalysisError;

/// What a locus says about stability along its loads.
#[derive(Clone, Debug)]
pub struct AlongLoad {
    pub locus: Locus,
    pub transitions: Vec<Transition>,
    /// The stability ranges `(from, to, state)` that cover the locus's loads.
    pub ranges: Vec<(f64, f64, State)>,
    /// Why the transitions cannot be trusted, when they cannot
    /// ([`resolution_warning`]).
    pub warning: Option<NotResolved>,
}

/// What becomes of the states where rounding decides them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unresolved {
    /// Found as everywhere else, beside the warning (the window's load bar
    /// and status card say the warning with them).
    Kept,
    /// Left out: no transition and no range (thousands of them for a
    /// roller of mass nu = 1e-50, each noise), as a figure draws it.
    Dropped,
}

impl AlongLoad {
    /// The stability of `pencil`'s model along `locus`.
    ///
    /// # Errors
    /// An eigenvalue computation that fails.
    pub fn new(
        pencil: &AffinePencil,
        locus: Locus,
        unresolved: Unresolved,
    ) -> Result<Self, AnalysisError> {
        let warning = resolution_warning(pencil, &locus)?;
        let (load_min, load_max) = match (locus.loads.first(), locus.loads.last()) {
            (Some(&first), Some(&last)) => (first, last),
            _ => (0.0, 0.0),
        };
        let (transitions, ranges) = if warning.is_some() && unresolved == Unresolved::Dropped {
            (Vec::new(), Vec::new())
        } else {
            let transitions = critical_loads_along(pencil, &locus)?;
            let start = pencil.spectrum(load_min)?;
            let first = classify(&start.eigenvalues, start.scale_per_s).state;
            let ranges = stability_ranges(&transitions, first, load_min, load_max);
            (transitions, ranges)
        };
        Ok(Self {
            locus,
            transitions,
            ranges,
            warning,
        })
    }
}
