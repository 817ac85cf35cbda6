//! A model's stability along the load, the one pipeline every root locus
//! goes through (the window's, its overlay's, a figure's): the locus, the
//! critical loads found on it, the ranges of each state, and why they
//! cannot be trusted where they cannot.

use super::critical::{critical_loads_along, plotted_locus};
use super::crossing::{Transition, stability_ranges};
use super::locus::{Locus, locus};
use super::pencil::AffinePencil;
use super::resolution::{NotResolved, resolution_warning};
use super::stability::{State, classify};
use crate::analysis::AnalysisError;
use crate::model::AsValid;

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

/// Where the loads of a locus lie.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    /// This many evenly spaced loads and the refinement's (the window's
    /// load bar).
    Even(usize),
    /// [`plotted_locus`]'s: the loads `critical` brackets with (evenly
    /// over the column's natural range, by decades beyond), every axis
    /// crossing refined (a figure's).
    Plotted,
}

impl AlongLoad {
    /// The pipeline every root locus goes through: `model`'s pencil,
    /// solving on `threads`, and the stability along its locus over
    /// `loads`, sampled as `sampling` says.
    ///
    /// # Errors
    /// A model the pencil refuses, a bad range, or an eigenvalue
    /// computation that fails.
    pub fn of_model(
        model: &impl AsValid,
        loads: (f64, f64),
        sampling: Sampling,
        unresolved: Unresolved,
        threads: usize,
    ) -> Result<(AffinePencil, Self), AnalysisError> {
        let pencil = AffinePencil::new(model)?.with_threads(threads);
        let (min, max) = loads;
        let locus = match sampling {
            Sampling::Even(samples) => locus(&pencil, min, max, samples)?,
            Sampling::Plotted => plotted_locus(&pencil, min, max)?,
        };
        let along = Self::new(&pencil, locus, unresolved)?;
        Ok((pencil, along))
    }

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
