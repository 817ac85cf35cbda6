//! What every figure shares: the legend above the plots (it never covers a
//! curve), the axes with their units and ticks, and the plot's place on the
//! page for the caller.

use std::ops::Range;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use super::clip::{Bounds, clip_polyline};
use super::style::{INK, Ink};
use super::{FigureError, Panel, drawing};
use crate::format::number_text;

/// A plot with two numeric axes.
pub type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// What a legend entry shows beside its words.
#[derive(Clone, Debug)]
pub enum Swatch {
    Line(RGBColor),
    Dashed(RGBColor),
    /// A circle, filled or open.
    Marker(RGBColor, bool),
    Fill(RGBColor),
    /// A colour scale, from one end to the other.
    Scale(Vec<RGBColor>),
}

/// Ticks on each axis (plotters rounds them to a readable step).
const TICKS: usize = 6;

/// Text widths are taken this much wider than the figures' font sets them:
/// an SVG viewer's sans-serif (`DejaVu Sans`, Arial) is wider than Ubuntu Light.
const WIDER_FONTS: f64 = 1.2;

/// `text` broken at spaces into lines no wider than `most` by `width`.
fn wrapped(text: &str, most: f64, width: impl Fn(&str) -> f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if width(&format!("{line} {word}")) <= most => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    lines
}

/// The smallest plot a figure draws, in font sizes each way: smaller, the
/// curves are a smudge between the axes' words.
const MIN_PLOT_EMS: i32 = 4;

/// The legend's entries laid out in rows across `root`'s width (an entry
/// wider than the page is wrapped onto lines of its own); draws them at the
/// top and returns the area below for `plots` plots stacked one above the
/// other.
///
/// # Errors
/// A page on which the legend and the axes' words leave less than
/// [`MIN_PLOT_EMS`] font sizes each way for each plot, with the page size
/// or font size that would fit; or the drawing failing.
pub fn legend_above<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    entries: &[(Swatch, String)],
    plots: i32,
    ink: &Ink,
) -> Result<DrawingArea<DB, Shift>, FigureError>
where
    DB::ErrorType: 'static,
{
    let em = ink.font_units();
    let width = i32::try_from(root.dim_in_pixel().0).unwrap_or(i32::MAX);
    let style = ink.text(1.0);
    let (swatch, gap, spacing, line_height) = (2 * em, em / 2, em + em / 2, em + em / 2);
    let margin = em / 2;
    let font = super::glyphs::font()?;
    let em_px = style.font.get_size() / super::glyphs::SIZE_PER_EM;
    let text_width = |text: &str| super::glyphs::text_size(&font, em_px, text).0 * WIDER_FONTS;
    let most = f64::from(width - 2 * margin - swatch - gap);
    // Each entry at (x, first line) with its lines.
    let mut placed: Vec<(i32, i32, Swatch, Vec<String>)> = Vec::new();
    let (mut x, mut line, mut row_lines) = (margin, 0, 1);
    for (kind, text) in entries {
        let lines = wrapped(text, most, text_width);
        let widest = lines.iter().map(|l| text_width(l)).fold(0.0, f64::max);
        #[expect(clippy::cast_possible_truncation, reason = "a length on a page")]
        let entry_width = swatch + gap + widest.ceil() as i32;
        let count = i32::try_from(lines.len()).unwrap_or(1);
        if x > margin && (x + entry_width > width - margin || count > 1) {
            (x, line, row_lines) = (margin, line + row_lines, 1);
        }
        row_lines = row_lines.max(count);
        placed.push((x, line, kind.clone(), lines));
        x += entry_width + spacing;
    }
    let height = if placed.is_empty() {
        0
    } else {
        (line + row_lines) * line_height + margin
    };
    check_room(root, height, plots, ink)?;
    let anchor = plotters::style::text_anchor::Pos::new(
        plotters::style::text_anchor::HPos::Left,
        plotters::style::text_anchor::VPos::Center,
    );
    for (x, first, kind, lines) in placed {
        let middle = |k: i32| margin + (first + k) * line_height + line_height / 2;
        draw_swatch(root, &kind, (x, middle(0)), swatch, ink)?;
        for (k, text) in (0..).zip(lines) {
            drawing(root.draw(&Text::new(
                text,
                (x + swatch + gap, middle(k)),
                style.pos(anchor),
            )))?;
        }
    }
    let (_, below) = root.split_vertically(height);
    Ok(below)
}

/// Refuses a page on which a legend `legend_height` tall leaves less than
/// [`MIN_PLOT_EMS`] font sizes each way for each of `plots` plots stacked
/// below it, saying what would fit.
fn check_room<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    legend_height: i32,
    plots: i32,
    ink: &Ink,
) -> Result<(), FigureError> {
    let (width, height) = root.dim_in_pixel();
    let (width, height) = (f64::from(width), f64::from(height));
    let [margin, right, below, left] = frame(ink);
    let least = f64::from(MIN_PLOT_EMS * ink.font_units());
    let beside = f64::from(margin + right + left);
    let under = f64::from(legend_height) + f64::from(plots) * f64::from(2 * margin + below);
    let (need_width, need_height) = (beside + least, under + f64::from(plots) * least);
    if width >= need_width && height >= need_height {
        return Ok(());
    }
    // Everything above scales with the font: the largest font that fits
    // this page (the legend wraps differently at another size, so this is
    // an estimate, said as one).
    let ratio = (width / need_width).min(height / need_height);
    let page = |w: f64, h: f64| {
        format!(
            "{} x {} mm",
            number_text(ink.mm(w).ceil()),
            number_text(ink.mm(h).ceil())
        )
    };
    let font_pt = (ink.font_pt() * ratio * 10.0).floor() / 10.0;
    let smaller_font = if font_pt >= super::Page::FONT_PT.0 {
        format!(
            " or a font of about {} pt or less (--font-pt)",
            number_text(font_pt)
        )
    } else {
        String::new()
    };
    Err(FigureError::Page(format!(
        "a {} page at {} pt leaves no room for the plot{}: its legend and the axes' words need about {}; use a page of at least that (--width-mm, --height-mm){smaller_font}",
        page(width, height),
        number_text(ink.font_pt()),
        if plots > 1 { "s" } else { "" },
        page(width.max(need_width), height.max(need_height)),
    )))
}

/// One swatch, `length` wide, its middle left end at `at`.
fn draw_swatch<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    kind: &Swatch,
    at: (i32, i32),
    length: i32,
    ink: &Ink,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    let (x, y) = at;
    let half = ink.units(3.0);
    match kind {
        Swatch::Line(color) => drawing(root.draw(&PathElement::new(
            vec![(x, y), (x + length, y)],
            ink.stroke(*color, 1.0),
        ))),
        Swatch::Dashed(color) => {
            let dash = length / 5;
            for k in [0, 2, 4] {
                drawing(root.draw(&PathElement::new(
                    vec![(x + k * dash, y), (x + (k + 1) * dash, y)],
                    ink.stroke(*color, 0.75),
                )))?;
            }
            Ok(())
        }
        Swatch::Marker(color, filled) => drawing(root.draw(&Circle::new(
            (x + length / 2, y),
            ink.units(2.2),
            marker_style(*color, *filled, ink),
        ))),
        Swatch::Fill(color) => drawing(root.draw(&Rectangle::new(
            [(x, y - half), (x + length, y + half)],
            color.filled(),
        ))),
        Swatch::Scale(colors) => {
            let count = i32::try_from(colors.len().max(1)).unwrap_or(1);
            for (k, color) in (0..).zip(colors) {
                drawing(root.draw(&Rectangle::new(
                    [
                        (x + k * length / count, y - half),
                        (x + (k + 1) * length / count, y + half),
                    ],
                    color.filled(),
                )))?;
            }
            Ok(())
        }
    }
}

/// A marker's look: filled, or an open ring.
pub fn marker_style(color: RGBColor, filled: bool, ink: &Ink) -> ShapeStyle {
    if filled {
        color.filled()
    } else {
        ink.stroke(color, 0.6)
    }
}

/// How the x axis's ticks read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XTicks {
    /// The values themselves.
    Plain,
    /// The axis holds log10 of the quantity: ticks at whole decades, each
    /// written as the quantity (0.01, 1, 100).
    Decades,
}

/// The room around a plot: its margin, the margin on its right, and the
/// areas of the axes' ticks and words below and on the left.
fn frame(ink: &Ink) -> [i32; 4] {
    let em = ink.font_units();
    [em / 2, em, em * 3, em * 5]
}

/// The width and height of the plot that [`chart`] makes on `area`.
pub fn plot_size<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, ink: &Ink) -> (f64, f64) {
    let [margin, right, below, left] = frame(ink);
    let (width, height) = area.dim_in_pixel();
    (
        f64::from(width) - f64::from(margin + right + left),
        f64::from(height) - f64::from(2 * margin + below),
    )
}

/// A plot over `x` by `y` on `area` with its axes, ticks and their words.
pub fn chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    x: Range<f64>,
    y: Range<f64>,
    (x_desc, y_desc): (&str, &str),
    x_ticks: XTicks,
    ink: &Ink,
) -> Result<Chart<'a, DB>, FigureError>
where
    DB::ErrorType: 'static,
{
    let (x_span, y_span) = (x.end - x.start, y.end - y.start);
    let [margin, right, below, left] = frame(ink);
    let mut chart = drawing(
        ChartBuilder::on(area)
            .margin(margin)
            .margin_right(right)
            .x_label_area_size(below)
            .y_label_area_size(left)
            .build_cartesian_2d(x, y),
    )?;
    let x_tick = |v: &f64| match x_ticks {
        XTicks::Plain => tick(*v, x_span),
        XTicks::Decades => crate::format::number_text(10f64.powf(v.round())),
    };
    let y_tick = |v: &f64| tick(*v, y_span);
    // Whole decades only: as many labels as there are decades.
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a few decades"
    )]
    let x_labels = match x_ticks {
        XTicks::Plain => TICKS,
        XTicks::Decades => (x_span.floor() as usize + 1).clamp(2, 12),
    };
    drawing(
        chart
            .configure_mesh()
            .disable_mesh()
            .x_labels(x_labels)
            .y_labels(TICKS)
            .x_label_formatter(&x_tick)
            .y_label_formatter(&y_tick)
            .label_style(ink.text(0.9))
            .axis_desc_style(ink.text(1.0))
            .axis_style(ink.stroke(INK, 0.6))
            .set_all_tick_mark_size(ink.units(2.5))
            .x_desc(x_desc)
            .y_desc(y_desc)
            .draw(),
    )?;
    Ok(chart)
}

/// A tick's words: six significant digits at most, zero as "0" (plotters'
/// steps are sums of floats: 0.30000000000000004).
fn tick(value: f64, span: f64) -> String {
    if value.abs() < 1e-9 * span.abs() {
        "0".to_owned()
    } else {
        crate::format::number_text(value)
    }
}

/// Where `chart` drew its plot on the page.
pub fn panel<DB: DrawingBackend>(chart: &Chart<'_, DB>) -> Panel {
    let (x, y) = chart.plotting_area().get_pixel_range();
    let (xr, yr) = (chart.x_range(), chart.y_range());
    Panel {
        x_range: (xr.start, xr.end),
        y_range: (yr.start, yr.end),
        x_px: (x.start, x.end),
        y_px: (y.start, y.end),
    }
}

/// The data box of `chart`.
pub fn bounds<DB: DrawingBackend>(chart: &Chart<'_, DB>) -> Bounds {
    let (xr, yr) = (chart.x_range(), chart.y_range());
    Bounds {
        x: (xr.start, xr.end),
        y: (yr.start, yr.end),
    }
}

/// The polyline `points` on `chart`, cut to its box.
pub fn line<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    points: &[(f64, f64)],
    style: ShapeStyle,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    for piece in clip_polyline(points, bounds(chart)) {
        drawing(chart.draw_series(std::iter::once(PathElement::new(piece, style))))?;
    }
    Ok(())
}

/// The polyline `points` dashed on `chart`, cut to its box.
pub fn dashed<DB: DrawingBackend>(
    chart: &mut Chart<'_, DB>,
    points: &[(f64, f64)],
    color: RGBColor,
    ink: &Ink,
) -> Result<(), FigureError>
where
    DB::ErrorType: 'static,
{
    for piece in clip_polyline(points, bounds(chart)) {
        drawing(chart.draw_series(DashedLineSeries::new(
            piece,
            ink.units(3.0),
            ink.units(2.0),
            ink.stroke(color, 0.75),
        )))?;
    }
    Ok(())
}
