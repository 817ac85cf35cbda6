//! The root locus figures: the branches in the complex plane, and Re and Im
//! of every eigenvalue against the load (the paper's Figs 3 and 8), with the
//! critical loads marked and other models overlaid.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{
    Swatch, XTicks, chart, dashed, legend_above, line, marker_style, panel, plot_size,
};
use super::style::{INK, Ink, series_color, state_color, tint};
use super::{Drawn, FigureError, drawing};
use crate::analysis::{
    AffinePencil, AnalysisError, C64, Locus, State, Transition, classify, critical_loads_along,
    plotted_locus, resolution_warning, stability_ranges,
};
use crate::app::{deciding_extent, default_view, versus_load_extent};
use crate::format::{load_text, number_text};
use crate::model::Model;

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
    pub warning: Option<String>,
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
    let pencil = AffinePencil::new(model)?;
    let locus = plotted_locus(&pencil, load_min, load_max)?;
    let warning = resolution_warning(&pencil, &locus)?;
    // Where rounding decides the states, the changes it makes are noise
    // (thousands of them, for a roller of mass nu = 1e-50): none is drawn
    // as if it were found, and no range is tinted.
    let (transitions, ranges) = if warning.is_some() {
        (Vec::new(), Vec::new())
    } else {
        let transitions = critical_loads_along(&pencil, &locus)?;
        let start = pencil.spectrum(load_min)?;
        let first = classify(&start.eigenvalues, start.scale_per_s).state;
        let ranges = stability_ranges(&transitions, first, load_min, load_max);
        (transitions, ranges)
    };
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

/// A critical load as the legend says it.
fn transition_text(t: &Transition) -> String {
    format!(
        "p = {}: {} to {}",
        load_text(t.load),
        t.from.name(),
        t.to.name()
    )
}

/// The most critical loads the legend names; the rest are counted in one
/// entry (`critical` lists them all).
const MOST_LEGEND_LOADS: usize = 8;

/// The legend: each model's curve, then the main model's critical loads
/// (at most [`MOST_LEGEND_LOADS`], the rest counted).
fn legend(main: &Analysed, overlays: &[Analysed], critical: Swatch) -> Vec<(Swatch, String)> {
    let mut entries = vec![(Swatch::Line(INK), main.name.clone())];
    entries.extend(
        overlays
            .iter()
            .enumerate()
            .map(|(k, other)| (Swatch::Line(series_color(k)), other.name.clone())),
    );
    entries.extend(main.transitions.iter().take(MOST_LEGEND_LOADS).map(|t| {
        let swatch = match critical {
            Swatch::Marker(_, filled) => Swatch::Marker(state_color(t.to), filled),
            _ => Swatch::Dashed(state_color(t.to)),
        };
        (swatch, transition_text(t))
    }));
    let more = main.transitions.len().saturating_sub(MOST_LEGEND_LOADS);
    if more > 0 {
        entries.push((
            match critical {
                Swatch::Marker(_, filled) => Swatch::Marker(INK, filled),
                _ => Swatch::Dashed(INK),
            },
            format!("{more} more critical loads (zieglerlab critical lists them)"),
        ));
    }
    entries
}

/// The models in drawing order: overlays behind, the main model in front,
/// each with its colour.
fn layers<'a>(
    main: &'a Analysed,
    overlays: &'a [Analysed],
) -> impl Iterator<Item = (&'a Analysed, RGBColor)> {
    overlays
        .iter()
        .enumerate()
        .map(|(k, other)| (other, series_color(k)))
        .chain(std::iter::once((main, INK)))
}

/// The root locus in the complex plane, at equal scales, holding the
/// eigenvalues that decide stability (a fast mode far left is cut, and the
/// notes say so); open rings at the range's first load, the main model's
/// eigenvalues at each critical load filled in the colour of the state
/// entered.
pub(super) fn draw_plane<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    main: &Analysed,
    overlays: &[Analysed],
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let mut entries = legend(main, overlays, Swatch::Marker(INK, true));
    let first_load = main.locus.loads.first().copied().unwrap_or(0.0);
    entries.insert(
        1 + overlays.len(),
        (
            Swatch::Marker(INK, false),
            format!("p = {}", number_text(first_load)),
        ),
    );
    let area = legend_above(root, &entries, 1, ink)?;
    // Equal scales: the view has the plot's shape.
    let (width, height) = plot_size(&area, ink);
    let shape = width / height.max(1.0);
    let extents: Vec<(f64, f64)> = layers(main, overlays)
        .map(|(a, _)| deciding_extent(&a.locus))
        .collect();
    let (half_width, half_height) = default_view(&extents, shape);
    let mut plane = chart(
        &area,
        -half_width..half_width,
        -half_height..half_height,
        ("Re λ (1/s)", "Im λ (rad/s)"),
        XTicks::Plain,
        ink,
    )?;
    dashed(
        &mut plane,
        &[(0.0, -half_height), (0.0, half_height)],
        tint(INK, 0.5),
        ink,
    )?;
    for (analysed, color) in layers(main, overlays) {
        for branch in analysed.locus.moving_branches() {
            let points: Vec<(f64, f64)> = branch.iter().map(|z| (z.re, z.im)).collect();
            line(&mut plane, &points, ink.stroke(color, 0.8))?;
        }
    }
    let inside = |z: &C64| z.re.abs() <= half_width && z.im.abs() <= half_height;
    let radius = ink.units(2.2);
    let starts = main.locus.moving_at(0);
    drawing(
        plane.draw_series(
            starts
                .iter()
                .filter(|z| inside(z))
                .map(|z| Circle::new((z.re, z.im), radius, marker_style(INK, false, ink))),
        ),
    )?;
    for (t, eigenvalues) in main.transitions.iter().zip(&main.at_transitions) {
        let style = marker_style(state_color(t.to), true, ink);
        drawing(
            plane.draw_series(
                eigenvalues
                    .iter()
                    .filter(|z| inside(z))
                    .map(|z| Circle::new((z.re, z.im), radius, style)),
            ),
        )?;
    }
    let mut notes = Vec::new();
    for (analysed, _) in layers(main, overlays) {
        let furthest = analysed
            .locus
            .moving_branches()
            .iter()
            .flatten()
            .map(|z| z.re)
            .fold(0.0, f64::min);
        if furthest < -half_width {
            notes.push(format!(
                "{}: eigenvalues down to Re λ = {} 1/s (fast decaying modes) lie left of the view, which holds those that decide stability",
                analysed.name,
                number_text(furthest)
            ));
        }
    }
    Ok(Drawn {
        panels: vec![panel(&plane)],
        notes,
    })
}

/// Re λ (top) and Im λ ≥ 0 (bottom) of every branch against the load: the
/// main model's stability ranges tinted in their states' colours, its
/// critical loads as dashed lines. The Re plot holds the real part of the
/// eigenvalue furthest right at every load, of every model drawn.
pub(super) fn draw_versus_load<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    main: &Analysed,
    overlays: &[Analysed],
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let mut entries = legend(main, overlays, Swatch::Dashed(INK));
    for state in [State::Stable, State::Flutter, State::Divergence] {
        if main.ranges.iter().any(|r| r.2 == state) {
            entries.push((Swatch::Fill(range_tint(state)), state.name().to_owned()));
        }
    }
    let area = legend_above(root, &entries, 2, ink)?;
    let (top, bottom) = area.split_vertically(area.dim_in_pixel().1 / 2);
    let (p0, p1) = (
        main.locus.loads.first().copied().unwrap_or(0.0),
        main.locus.loads.last().copied().unwrap_or(1.0),
    );
    let mut panels = Vec::new();
    for (half, imaginary) in [(&top, false), (&bottom, true)] {
        let extent = versus_load_extent(layers(main, overlays).map(|(a, _)| &a.locus), imaginary);
        let (y_range, y_desc) = if imaginary {
            (0.0..1.1 * extent, "Im λ (rad/s)")
        } else {
            (-1.1 * extent..1.1 * extent, "Re λ (1/s)")
        };
        let (y0, y1) = (y_range.start, y_range.end);
        let mut plot = chart(
            half,
            p0..p1,
            y_range,
            ("p = P l/k", y_desc),
            XTicks::Plain,
            ink,
        )?;
        drawing(plot.draw_series(main.ranges.iter().map(|&(a, b, state)| {
            Rectangle::new([(a, y0), (b, y1)], range_tint(state).filled())
        })))?;
        for t in &main.transitions {
            dashed(
                &mut plot,
                &[(t.load, y0), (t.load, y1)],
                state_color(t.to),
                ink,
            )?;
        }
        for (analysed, color) in layers(main, overlays) {
            let locus = &analysed.locus;
            for branch in locus.moving_branches() {
                let points: Vec<(f64, f64)> = locus
                    .loads
                    .iter()
                    .zip(branch)
                    .map(|(&p, z)| (p, if imaginary { z.im } else { z.re }))
                    .collect();
                line(&mut plot, &points, ink.stroke(color, 0.8))?;
            }
        }
        panels.push(panel(&plot));
    }
    Ok(Drawn {
        panels,
        notes: Vec::new(),
    })
}

/// The pale tint of a stability range (as the window's shading).
fn range_tint(state: State) -> RGBColor {
    tint(state_color(state), 0.18)
}
