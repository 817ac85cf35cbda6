//! Draws plots' descriptions ([`crate::plot::spec`]) on a page with
//! plotters, in ink on white: the figures' one renderer of plots.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{
    Swatch as PageSwatch, XTicks, chart, dashed, legend_above, line, marker_style, panel, plot_size,
};
use super::style::{INK, Ink as PageInk, rgb, series_color, state_color, tint};
use super::{Drawn, FigureError, drawing};
use crate::analysis::State;
use crate::plot::Palette;
use crate::plot::spec::{Entry, Ink, Mark, Plot, Size, Swatch, Ticks, View, Weight};
use crate::plot::view::default_view;

/// `ink` on white paper.
fn ink_color(ink: &Ink) -> RGBColor {
    match ink {
        Ink::Main | Ink::Now => INK,
        Ink::Series(k) => series_color(*k),
        Ink::Overlay => series_color(0),
        Ink::State(state) => state_color(*state),
        Ink::Measured => rgb(Palette::NORMAL.measured),
        Ink::LoadLine => rgb(Palette::NORMAL.load_line),
        Ink::Axis => tint(INK, 0.5),
        Ink::Rgb(color) => rgb(*color),
    }
}

/// A line's width in points.
fn width_pt(weight: Weight) -> f64 {
    match weight {
        Weight::Fine => 0.8,
        Weight::Regular => 1.0,
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

/// The pale tint of a stability range.
fn range_tint(state: State) -> RGBColor {
    tint(state_color(state), 0.18)
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
                if *is_dashed {
                    dashed(&mut chart, &points, ink_color(color), ink)?;
                } else {
                    line(
                        &mut chart,
                        &points,
                        ink.stroke(ink_color(color), width_pt(*weight)),
                    )?;
                }
            }
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
                if *is_dashed {
                    dashed(&mut chart, &points, ink_color(color), ink)?;
                } else {
                    line(
                        &mut chart,
                        &points,
                        ink.stroke(ink_color(color), width_pt(*weight)),
                    )?;
                }
            }
            Mark::Range { from, to, state } => {
                drawing(chart.draw_series(std::iter::once(Rectangle::new(
                    [(*from, y.0), (*to, y.1)],
                    range_tint(*state).filled(),
                ))))?;
            }
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
