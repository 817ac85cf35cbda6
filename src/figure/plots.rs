//! Draws plots' descriptions ([`crate::plot::spec`]) on a page with
//! plotters, in ink on white: the figures' one renderer of plots.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{
    Chart, Swatch as PageSwatch, XTicks, chart, dashed, legend_above, line, marker_style, panel,
    plot_size,
};
use super::style::{INK, Ink as PageInk, rgb, state_color, tint};
use super::{Drawn, FigureError, drawing};
use crate::analysis::State;
use crate::plot::spec::CellGrid;
use crate::plot::spec::{Entry, Ink, Mark, Plot, Size, Swatch, Ticks, View, Weight, graded_lines};
use crate::plot::view::default_view;
use crate::plot::{Palette, pattern};

/// `ink` on white paper (a map cell's at one of [`CELL_LEVELS`]).
fn ink_color(ink: &Ink) -> RGBColor {
    match *ink {
        Ink::Cell(state, strength) => cell_color(state, strength),
        _ => rgb(Palette::PAPER.ink(ink)),
    }
}

/// A line's width in points.
fn width_pt(weight: Weight) -> f64 {
    match weight {
        Weight::Fine => 0.8,
        Weight::Regular => 1.0,
        Weight::Layered(k) => [1.6, 1.0, 0.6][k.min(2)],
    }
}

/// A marker's radius in points.
fn radius_pt(size: Size) -> f64 {
    match size {
        Size::Small => 1.4,
        Size::Regular => 2.2,
        Size::Large => 2.4,
    }
}

/// Levels of strength a map cell's colour takes on paper (a run of equal
/// cells is one rectangle, so an SVG of a fine map stays small).
const CELL_LEVELS: f64 = 8.0;

/// A map cell's colour: its state's, paler the slower it grows or decays.
fn cell_color(state: State, strength: f64) -> RGBColor {
    let level = (strength * CELL_LEVELS).round() / CELL_LEVELS;
    rgb(Palette::PAPER.ink(&Ink::Cell(state, level)))
}

/// The pale tint of a stability range.
fn range_tint(state: State) -> RGBColor {
    tint(state_color(state), Palette::RANGE_TINT)
}

/// A legend entry's swatch on paper.
fn swatch(swatch: &Swatch) -> PageSwatch {
    match swatch {
        Swatch::Line(ink) => PageSwatch::Line(ink_color(ink)),
        Swatch::Dashed(ink) => PageSwatch::Dashed(ink_color(ink)),
        Swatch::Marker(ink, filled) => PageSwatch::Marker(ink_color(ink), *filled),
        Swatch::Fill(state) => PageSwatch::Fill(range_tint(*state)),
        Swatch::Scale(inks) => PageSwatch::Scale(inks.iter().map(ink_color).collect()),
    }
}

/// `legend` at the top of `root` and `plots` stacked below it, each as
/// tall as the others.
///
/// # Errors
/// A page too small for the legend and the plots, or the drawing failing.
pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    legend: &[Entry],
    plots: &[Plot],
    ink: &PageInk,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let entries: Vec<(PageSwatch, String)> = legend
        .iter()
        .map(|entry| (swatch(&entry.swatch), entry.text.clone()))
        .collect();
    let count = i32::try_from(plots.len()).unwrap_or(i32::MAX);
    let area = legend_above(root, &entries, count, ink)?;
    let mut drawn = Drawn {
        panels: Vec::new(),
        notes: Vec::new(),
    };
    let each = area.dim_in_pixel().1 / u32::try_from(plots.len().max(1)).unwrap_or(1);
    let mut rest = area;
    for (k, plot) in plots.iter().enumerate() {
        let here = if k + 1 < plots.len() {
            let (top, below) = rest.split_vertically(each);
            rest = below;
            top
        } else {
            rest.clone()
        };
        draw_plot(&here, plot, ink, &mut drawn)?;
    }
    Ok(drawn)
}

/// One plot on `area`, its panel and notes added to `drawn`.
fn draw_plot<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    plot: &Plot,
    ink: &PageInk,
    drawn: &mut Drawn,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let (x, y) = match plot.view {
        View::Ranges { x, y } => (x, y),
        View::Equal { extent } => {
            // Equal scales: the view has the plot's shape.
            let (width, height) = plot_size(area, ink);
            let (half_width, half_height) = default_view(&[extent], width / height.max(1.0));
            ((-half_width, half_width), (-half_height, half_height))
        }
    };
    let ticks = match plot.x_ticks {
        Ticks::Plain => XTicks::Plain,
        Ticks::Decades => XTicks::Decades,
    };
    let mut chart = chart(
        area,
        x.0..x.1,
        y.0..y.1,
        (&plot.x_label, &plot.y_label),
        ticks,
        ink,
    )?;
    let inside = |p: &[f64; 2]| (x.0..=x.1).contains(&p[0]) && (y.0..=y.1).contains(&p[1]);
    for mark in &plot.marks {
        match mark {
            Mark::Line {
                points,
                ink: color,
                weight,
                dashed: is_dashed,
            } => {
                let points: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[1])).collect();
                stroked(&mut chart, &points, (color, *weight, *is_dashed), ink)?;
            }
            Mark::Graded {
                points,
                along,
                weight,
            } => graded(&mut chart, points, along, *weight, ink)?,
            Mark::Markers {
                points,
                ink: color,
                size,
                filled,
                ..
            } => {
                let (radius, style) = (
                    ink.units(radius_pt(*size)),
                    marker_style(ink_color(color), *filled, ink),
                );
                drawing(
                    chart.draw_series(
                        points
                            .iter()
                            .filter(|p| inside(p))
                            .map(|p| Circle::new((p[0], p[1]), radius, style)),
                    ),
                )?;
            }
            Mark::Vertical {
                x: at,
                ink: color,
                weight,
                dashed: is_dashed,
                ..
            } => {
                let points = [(*at, y.0), (*at, y.1)];
                stroked(&mut chart, &points, (color, *weight, *is_dashed), ink)?;
            }
            Mark::Horizontal {
                y: at,
                ink: color,
                weight,
                dashed: is_dashed,
            } => {
                let points = [(x.0, *at), (x.1, *at)];
                stroked(&mut chart, &points, (color, *weight, *is_dashed), ink)?;
            }
            Mark::Cells { x, y, grid } => cells(&mut chart, (*x, *y), grid)?,
            Mark::Range { from, to, state } => {
                drawing(chart.draw_series(std::iter::once(Rectangle::new(
                    [(*from, y.0), (*to, y.1)],
                    range_tint(*state).filled(),
                ))))?;
            }
            Mark::Band {
                lower,
                upper,
                state,
            } => band(&mut chart, (lower, upper), *state)?,
            Mark::Label { at, text, .. } => label(&mut chart, *at, text, ink)?,
        }
    }
    drawn.notes.extend(
        plot.far_left
            .iter()
            .filter(|far| far.x < x.0)
            .map(|far| far.note.clone()),
    );
    drawn.panels.push(panel(&chart));
    Ok(())
}

/// The region between `lower` and `upper` (matched points), tinted as a
/// range of `state` is: one polygon round both.
fn band<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    (lower, upper): (&[[f64; 2]], &[[f64; 2]]),
    state: State,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let outline: Vec<(f64, f64)> = lower
        .iter()
        .chain(upper.iter().rev())
        .map(|p| (p[0], p[1]))
        .collect();
    drawing(chart.draw_series(std::iter::once(Polygon::new(
        outline,
        range_tint(state).filled(),
    ))))?;
    Ok(())
}

/// `text` centred at `at` on a plate of the paper, half an em wider than
/// the word each side.
fn label<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    at: [f64; 2],
    text: &str,
    ink: &PageInk,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let style = ink.text(1.0);
    let em_px = style.font.get_size() / super::glyphs::SIZE_PER_EM;
    let (width, height) = super::glyphs::text_size(&super::glyphs::font()?, em_px, text);
    #[expect(clippy::cast_possible_truncation, reason = "lengths on a page")]
    let (half_width, half_height) = (
        (0.5 * width + 0.5 * em_px).round() as i32,
        (0.5 * height + 0.15 * em_px).round() as i32,
    );
    let centred = style
        .color(&INK)
        .pos(plotters::style::text_anchor::Pos::new(
            plotters::style::text_anchor::HPos::Center,
            plotters::style::text_anchor::VPos::Center,
        ));
    let word = EmptyElement::at((at[0], at[1]))
        + Rectangle::new(
            [(-half_width, -half_height), (half_width, half_height)],
            rgb(Palette::PAPER.background).mix(0.85).filled(),
        )
        + Text::new(text.to_owned(), (0, 0), centred);
    drawing(chart.draw_series(std::iter::once(word)))?;
    Ok(())
}

/// A line coloured along its samples (`along`, on the ramp), in all its
/// [`graded_lines`]: paper has no pixels to spare.
fn graded<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    points: &[[f64; 2]],
    along: &[f64],
    weight: Weight,
    ink: &PageInk,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    for (piece, color) in graded_lines(points, along, points, 0.0) {
        let piece: Vec<(f64, f64)> = piece.iter().map(|p| (p[0], p[1])).collect();
        stroked(chart, &piece, (&color, weight, false), ink)?;
    }
    Ok(())
}

/// The polyline `points` in `color` at `weight`, solid or `dashed`.
fn stroked<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    points: &[(f64, f64)],
    (color, weight, is_dashed): (&Ink, Weight, bool),
    ink: &PageInk,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    if is_dashed {
        dashed(chart, points, ink_color(color), ink)
    } else {
        line(
            chart,
            points,
            ink.stroke(ink_color(color), width_pt(weight)),
        )
    }
}

/// `grid`'s cells over `x` by `y`, each row's runs of one colour as one
/// rectangle; cells without analysis left white.
fn cells<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    (x, y): ((f64, f64), (f64, f64)),
    grid: &CellGrid,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let columns = grid.columns.max(1);
    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
    let (width, height) = (
        (x.1 - x.0) / columns as f64,
        (y.1 - y.0) / grid.rows.max(1) as f64,
    );
    for (j, row) in (0u32..).zip(grid.cells.chunks(columns)) {
        let colors: Vec<Option<RGBColor>> = row
            .iter()
            .map(|cell| cell.map(|(state, strength)| cell_color(state, strength)))
            .collect();
        let bottom = y.0 + f64::from(j) * height;
        let mut start = 0;
        for i in 1..=colors.len() {
            if i == colors.len() || colors[i] != colors[start] {
                if let Some(color) = colors[start] {
                    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
                    let (a, b) = (x.0 + start as f64 * width, x.0 + i as f64 * width);
                    drawing(chart.draw_series(std::iter::once(Rectangle::new(
                        [(a, bottom), (b, bottom + height)],
                        color.filled(),
                    ))))?;
                }
                start = i;
            }
        }
        stripes(chart, (x, y), grid, j)?;
    }
    Ok(())
}

/// The stripes of row `j`'s striped runs of cells, in white (the paper),
/// on the same pattern as the window's map: periods of a 48th of the map's
/// extent.
fn stripes<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    (x, y): ((f64, f64), (f64, f64)),
    grid: &CellGrid,
    j: u32,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let columns = grid.columns.max(1);
    let row_start = usize::try_from(j)
        .unwrap_or(usize::MAX)
        .saturating_mul(columns);
    let Some(row) = grid.cells.get(row_start..row_start + columns) else {
        return Ok(());
    };
    let striped = |i: usize| row[i].is_some_and(|(state, _)| pattern::striped(state));
    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
    let (columns_f, rows_f) = (columns as f64, grid.rows.max(1) as f64);
    let v = (f64::from(j) / rows_f, f64::from(j + 1) / rows_f);
    let mut i = 0;
    while i < columns {
        if !striped(i) {
            i += 1;
            continue;
        }
        let start = i;
        while i < columns && striped(i) {
            i += 1;
        }
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let u = (start as f64 / columns_f, i as f64 / columns_f);
        let polygons = pattern::stripes(u, v, 1.0 / pattern::MAP_STRIPES_PER_VIEW);
        drawing(chart.draw_series(polygons.into_iter().map(|polygon| {
            Polygon::new(
                polygon
                    .into_iter()
                    .map(|[pu, pv]| (x.0 + pu * (x.1 - x.0), y.0 + pv * (y.1 - y.0)))
                    .collect::<Vec<_>>(),
                rgb(Palette::PAPER.background).filled(),
            )
        })))?;
    }
    Ok(())
}
