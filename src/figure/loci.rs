//! The root locus figures: the branches in the complex plane, and Re and Im
//! of every eigenvalue against the load (the paper's Figs 3 and 8), with the
//! critical loads marked and other models overlaid.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::style::Ink;
use super::{Drawn, FigureError, plots};
use crate::analysis::{
    AffinePencil, AlongLoad, AnalysisError, C64, Locus, State, Transition, Unresolved,
    plotted_locus,
};
use crate::model::Model;
use crate::plot::locus::{Layer, Loci};

/// A model's locus over a load range, its critical loads and stability
/// ranges, and its eigenvalues at each critical load.
#[derive(Clone, Debug)]
pub struct Analysed {
    pub name: String,
    pub locus: Locus,
    pub transitions: Vec<Transition>,
    pub ranges: Vec<(f64, f64, State)>,
    /// The moving eigenvalues at each transition's load.
    pub at_transitions: Vec<Vec<C64>>,
    /// Why the states are not resolved over the range, if they are not.
    pub warning: Option<crate::analysis::NotResolved>,
}

/// `model`'s locus from `load_min` to `load_max` on the loads `critical`
/// brackets with (evenly spaced over the column's natural range, by decades
/// beyond it; [`plotted_locus`]) and the range rules it has, its critical
/// loads found on it as `critical` finds them, and the warning `critical`
/// gives where rounding decides the states.
///
/// # Errors
/// A bad range, or an eigenvalue computation that fails.
pub fn analyse(
    name: &str,
    model: &Model,
    load_min: f64,
    load_max: f64,
) -> Result<Analysed, AnalysisError> {
    let pencil = AffinePencil::new(model)?.with_threads(crate::machine_threads());
    // Where rounding decides the states, the changes it makes are noise
    // (thousands of them, for a roller of mass nu = 1e-50): none is drawn
    // as if it were found, and no range is tinted.
    let AlongLoad {
        locus,
        transitions,
        ranges,
        warning,
    } = AlongLoad::new(
        &pencil,
        plotted_locus(&pencil, load_min, load_max)?,
        Unresolved::Dropped,
    )?;
    let at_transitions = transitions
        .iter()
        .map(|t| Ok(pencil.spectrum(t.load)?.eigenvalues))
        .collect::<Result<_, AnalysisError>>()?;
    Ok(Analysed {
        name: name.to_owned(),
        locus,
        transitions,
        ranges,
        at_transitions,
        warning,
    })
}

impl Analysed {
    /// This model as a layer of the locus plots.
    fn layer(&self) -> Layer<'_> {
        Layer {
            name: &self.name,
            locus: &self.locus,
            transitions: &self.transitions,
            ranges: &self.ranges,
            at_transitions: &self.at_transitions,
        }
    }
}

/// The locus plots of `main` with `overlays` behind it, on paper.
fn loci<'a>(main: &'a Analysed, overlays: &'a [Analysed], ink: &Ink) -> Loci<'a> {
    Loci {
        main: main.layer(),
        others: overlays.iter().map(Analysed::layer).collect(),
        present: None,
        words: ink.words,
    }
}

/// The root locus in the complex plane ([`Loci::plane`]).
pub(super) fn draw_plane<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    main: &Analysed,
    overlays: &[Analysed],
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let loci = loci(main, overlays, ink);
    plots::draw(root, &loci.paper_legend(true), &[loci.plane()], ink)
}

/// Re λ (top) and Im λ ≥ 0 (bottom) against the load ([`Loci::versus_load`]).
pub(super) fn draw_versus_load<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    main: &Analysed,
    overlays: &[Analysed],
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let loci = loci(main, overlays, ink);
    let plots = [loci.versus_load(false), loci.versus_load(true)];
    self::plots::draw(root, &loci.paper_legend(false), &plots, ink)
}
