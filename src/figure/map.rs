//! The stability map as a figure: each cell in its state's colour, deeper
//! the faster it grows or decays, the boundaries between states as lines,
//! on axes of the load and the second parameter.

use plotters::coord::Shift;
use plotters::prelude::*;

use std::sync::Arc;

use super::style::Ink;
use super::{Drawn, FigureError, plots};
use crate::analysis::{MapSpec, RowResult};
use crate::plot::map::StabilityMap;
use crate::plot::spec::CellGrid;

/// A computed map: what was asked and every row's answer.
#[derive(Clone, Debug)]
pub struct MapData {
    pub spec: MapSpec,
    pub rows: Vec<Option<RowResult>>,
}

/// The map ([`StabilityMap`]) with its key above.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &MapData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    if !data.rows.iter().flatten().any(Result::is_ok) {
        return Err(FigureError::Empty(
            "no row of the map has an analysis".to_owned(),
        ));
    }
    let map = StabilityMap {
        spec: &data.spec,
        rows: &data.rows,
        grid: Arc::new(CellGrid::new(&data.spec, &data.rows)),
        now: None,
        words: ink.words,
    };
    plots::draw(root, &map.legend(), &[map.plot()], ink)
}
