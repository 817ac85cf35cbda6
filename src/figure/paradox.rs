//! The paradox curves as a figure: the first critical load against the
//! swept ratio on a log axis, one curve per damping level (or band speed),
//! the undamped (or massless) reference as a dashed line, the model's own
//! point.

use std::sync::atomic::AtomicBool;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::layout::{Swatch, XTicks, chart, dashed, legend_above, line, marker_style, panel};
use super::style::{INK, Ink, series_color};
use super::{Drawn, FigureError, drawing};
use crate::analysis::{Curves, DampingKind, own_point, paradox_curves};
use crate::format::load_text;
use crate::model::Model;

/// The explorer's curves and the model's own point `(log10 ratio, load)`.
#[derive(Clone, Debug)]
pub struct ParadoxData {
    pub curves: Curves,
    pub here: Option<(f64, f64)>,
}

impl ParadoxData {
    /// The curves of `model` for damping of `kind` (the roller's: its mass
    /// ratio and band speed), and the model's own first critical load.
    #[must_use]
    pub fn new(model: &Model, kind: DampingKind) -> Self {
        let curves = paradox_curves(model, kind, &AtomicBool::new(false));
        let here = own_point(model, kind, None).map(|[x, p]| (x, p));
        Self { curves, here }
    }
}

pub(super) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    data: &ParadoxData,
    ink: &Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    let curves = &data.curves;
    if let Some(note) = &curves.note {
        return Err(FigureError::Empty(note.clone()));
    }
    let mut entries: Vec<(Swatch, String)> = curves
        .lines
        .iter()
        .enumerate()
        .map(|(k, (name, _))| (Swatch::Line(series_color(k)), name.clone()))
        .collect();
    let (highest, reference_within) = curves.fitted_top(data.here.map(|h| h.1));
    if let Some(name) = curves.reference_label(reference_within) {
        entries.push((Swatch::Dashed(INK), name));
    }
    if let Some((_, p)) = data.here {
        entries.push((
            Swatch::Marker(INK, true),
            format!("this model: p = {}", load_text(p)),
        ));
    }
    let area = legend_above(root, &entries, 1, ink)?;
    let points = curves.lines.iter().flat_map(|(_, points)| points.iter());
    let (x0, x1) = points
        .clone()
        .map(|p| p[0])
        .chain(data.here.map(|h| h.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
            (lo.min(x), hi.max(x))
        });
    if !(x0.is_finite() && x1 > x0) {
        return Err(FigureError::Empty("the curves have no extent".to_owned()));
    }
    let mut plot = chart(
        &area,
        x0..x1,
        0.0..1.1 * highest.max(1e-9),
        (
            &format!("{} (log scale)", curves.x_label),
            "first critical load p",
        ),
        XTicks::Decades,
        ink,
    )?;
    if let Some((_, p)) = curves.reference.as_ref().filter(|_| reference_within) {
        dashed(&mut plot, &[(x0, *p), (x1, *p)], INK, ink)?;
    }
    for (k, (_, points)) in curves.lines.iter().enumerate() {
        let points: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[1])).collect();
        line(&mut plot, &points, ink.stroke(series_color(k), 1.0))?;
    }
    if let Some(here) = data.here {
        drawing(plot.draw_series(std::iter::once(Circle::new(
            here,
            ink.units(2.2),
            marker_style(INK, true, ink),
        ))))?;
    }
    Ok(Drawn {
        panels: vec![panel(&plot)],
        notes: Vec::new(),
    })
}
