//! The stability map as a figure: each cell in its state's colour, deeper
//! the faster it grows or decays, the boundaries between states as lines,
//! on axes of the load and the second parameter.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{Swatch, XTicks, chart, legend_above, line, panel};
use super::style::{INK, Ink, state_color, tint};
use super::{Drawn, FigureError, drawing};
use crate::analysis::{MapSpec, RowResult, State, map_boundaries};
use crate::format::number_text;
use crate::model::Axis;
use crate::plot::map_scale::{largest_rate, rate_strength};

/// A computed map: what was asked and every row's answer.
#[derive(Clone, Debug)]
pub struct MapData {
    pub spec: MapSpec,
    pub rows: Vec<Option<RowResult>>,
}

/// Levels of depth a cell's colour takes (a run of equal cells is one
/// rectangle, so an SVG of a fine map stays small).
const LEVELS: f64 = 8.0;

/// A cell's colour: its state's, deeper the faster it grows or decays (the
/// square root of the rate over the map's largest, as in the window).
fn cell_color(state: State, growth_per_s: f64, scale_per_s: f64) -> RGBColor {
    let level = (rate_strength(growth_per_s, scale_per_s) * LEVELS).round() / LEVELS;
    tint(state_color(state), 0.3 + 0.7 * level)
}

/// `value` to three significant digits (a key's scale needs no more).
fn significant(value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    let unit = 10f64.powf(value.abs().log10().floor() - 2.0);
    (value / unit).round() * unit
}

/// The second axis's words: its name and unit.
fn axis_words(axis: &Axis) -> String {
    match axis {
        Axis::Key(key) if !key.spec().unit.is_empty() => {
            format!("{} ({})", key.name(), key.spec().unit)
        }
        Axis::DampingLevel => "damping g2 = c2 / √(k m l²)".to_owned(),
        Axis::MassRatio => "mass ratio m1 / (mass beyond joint A)".to_owned(),
        _ => axis.name().to_owned(),
    }
}

pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &MapData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let spec = &data.spec;
    let rows: Vec<_> = data.rows.iter().flatten().flatten().collect();
    if rows.is_empty() {
        return Err(FigureError::Empty(
            "no row of the map has an analysis".to_owned(),
        ));
    }
    let scale = largest_rate(rows.iter().copied());
    let mut entries: Vec<(Swatch, String)> = [State::Stable, State::Flutter, State::Divergence]
        .into_iter()
        .filter(|&state| {
            rows.iter()
                .any(|r| r.cells.iter().any(|c| c.state == state))
        })
        .map(|state| (Swatch::Fill(state_color(state)), state.name().to_owned()))
        .collect();
    entries.push((
        Swatch::Fill(tint(state_color(State::Flutter), 0.3)),
        format!(
            "paler: slower growth or decay (deepest: {} 1/s)",
            number_text(significant(scale))
        ),
    ));
    entries.push((Swatch::Line(INK), "critical loads".to_owned()));
    let area = legend_above(root, &entries, 1, ink)?;
    let loads = spec
        .load_grid()
        .map_err(|e| FigureError::Empty(e.to_string()))?;
    let half_step = |lo: f64, hi: f64, n: usize| {
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let step = if n > 1 {
            (hi - lo) / (n - 1) as f64
        } else {
            1.0
        };
        0.5 * step
    };
    let (p0, p1) = spec.load_range;
    let (y0, y1) = spec.axis_range;
    // A count (`rods`) has a row per whole number, one unit high.
    let (hx, hy) = (
        half_step(p0, p1, spec.loads),
        if spec.axis.counts() {
            0.5
        } else {
            half_step(y0, y1, spec.values)
        },
    );
    let mut plot = chart(
        &area,
        p0 - hx..p1 + hx,
        y0 - hy..y1 + hy,
        ("p = P l/k", &axis_words(&spec.axis)),
        XTicks::Plain,
        ink,
    )?;
    for row in &rows {
        let centre = row.value;
        let colors: Vec<RGBColor> = row
            .cells
            .iter()
            .map(|c| cell_color(c.state, c.growth_per_s, scale))
            .collect();
        // Runs of one colour as one rectangle.
        let mut start = 0;
        for i in 1..=colors.len() {
            if i == colors.len() || colors[i] != colors[start] {
                let (a, b) = (loads[start] - hx, loads[i - 1] + hx);
                drawing(plot.draw_series(std::iter::once(Rectangle::new(
                    [(a, centre - hy), (b, centre + hy)],
                    colors[start].filled(),
                ))))?;
                start = i;
            }
        }
    }
    for curve in map_boundaries(&data.rows) {
        let points: Vec<(f64, f64)> = curve.iter().map(|&[p, v]| (p, v)).collect();
        if points.len() > 1 {
            line(&mut plot, &points, ink.stroke(INK, 0.8))?;
        }
    }
    Ok(Drawn {
        panels: vec![panel(&plot)],
        notes: Vec::new(),
    })
}
