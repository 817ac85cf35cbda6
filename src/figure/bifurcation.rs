//! The bifurcation diagram as a figure: the straight column along the load
//! axis (solid where stable, dashed where not), the largest angle over each
//! limit cycle against the load (stable solid, unstable dashed, in the
//! flutter colour), the flutter onsets as open rings, and a sweep's runs
//! as dots (up) and rings (down).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::style::Ink;
use super::{Drawn, FigureError, plots};
use crate::analysis::Branch;
use crate::plot::bifurcation::Diagram;

/// What the diagram shows.
#[derive(Clone, Debug)]
pub struct BifurcationData {
    /// The load range drawn.
    pub load_range: (f64, f64),
    /// The straight column's stretches `(from, to, stable)`.
    pub equilibrium: Vec<(f64, f64, bool)>,
    /// The branches of cycles.
    pub branches: Vec<Branch>,
    /// A sweep's steps `(load, largest angle, upward)`, if one was run.
    pub sweep: Vec<(f64, f64, bool)>,
}

/// The diagram ([`Diagram`]) with its legend above.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &BifurcationData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let diagram = Diagram {
        load_range: data.load_range,
        equilibrium: &data.equilibrium,
        branches: data.branches.iter().collect(),
        sweep: &data.sweep,
        present: None,
        words: ink.words,
    };
    plots::draw(root, &diagram.legend(), &[diagram.plot()], ink)
}
