//! The bifurcation diagram as a figure: the straight column along the load
//! axis (solid where stable, dashed where not), the largest angle over each
//! limit cycle against the load (stable solid, unstable dashed, in the
//! flutter colour), the flutter onsets as open rings, and a sweep's runs
//! as dots (up) and rings (down).

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{Swatch, XTicks, chart, dashed, legend_above, line, marker_style, panel};
use super::style::{INK, Ink, state_color};
use super::{Drawn, FigureError, drawing};
use crate::analysis::{Branch, State};

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

pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &BifurcationData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let flutter = state_color(State::Flutter);
    let runs: Vec<(Vec<[f64; 2]>, bool)> = data.branches.iter().flat_map(Branch::runs).collect();
    let any = |stable: bool| runs.iter().any(|(_, s)| *s == stable);
    let mut entries = vec![(Swatch::Line(INK), "straight column, stable".to_owned())];
    if data.equilibrium.iter().any(|(_, _, stable)| !stable) {
        entries.push((Swatch::Dashed(INK), "straight column, unstable".to_owned()));
    }
    if any(true) {
        entries.push((Swatch::Line(flutter), "stable limit cycle".to_owned()));
    }
    if any(false) {
        entries.push((Swatch::Dashed(flutter), "unstable limit cycle".to_owned()));
    }
    if !data.branches.is_empty() {
        entries.push((
            Swatch::Marker(flutter, false),
            "flutter onset (Hopf point)".to_owned(),
        ));
    }
    for (upward, words) in [(true, "sweep up (a run)"), (false, "sweep down (a run)")] {
        if data.sweep.iter().any(|s| s.2 == upward) {
            entries.push((Swatch::Marker(INK, upward), words.to_owned()));
        }
    }
    let area = legend_above(root, &entries, 1, ink)?;
    let (x0, x1) = data.load_range;
    let highest = runs
        .iter()
        .flat_map(|(points, _)| points.iter().map(|p| p[1]))
        .chain(data.sweep.iter().map(|s| s.1))
        .fold(0.1, f64::max);
    let mut plot = chart(
        &area,
        x0..x1,
        0.0..1.1 * highest,
        ("load p = P l/k", "largest |φ_i| over a cycle (rad)"),
        XTicks::Plain,
        ink,
    )?;
    for &(from, to, stable) in &data.equilibrium {
        if stable {
            line(&mut plot, &[(from, 0.0), (to, 0.0)], ink.stroke(INK, 1.0))?;
        } else {
            dashed(&mut plot, &[(from, 0.0), (to, 0.0)], INK, ink)?;
        }
    }
    for (points, stable) in &runs {
        let points: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[1])).collect();
        if *stable {
            line(&mut plot, &points, ink.stroke(flutter, 1.0))?;
        } else {
            dashed(&mut plot, &points, flutter, ink)?;
        }
    }
    for branch in &data.branches {
        drawing(plot.draw_series(std::iter::once(Circle::new(
            (branch.hopf().load, 0.0),
            ink.units(2.2),
            marker_style(flutter, false, ink),
        ))))?;
    }
    for &(load, amplitude, upward) in &data.sweep {
        drawing(plot.draw_series(std::iter::once(Circle::new(
            (load, amplitude),
            ink.units(if upward { 1.4 } else { 2.4 }),
            marker_style(INK, upward, ink),
        ))))?;
    }
    Ok(Drawn {
        panels: vec![panel(&plot)],
        notes: Vec::new(),
    })
}
