//! The paradox curves described once: the first critical load against the
//! swept ratio on a log axis, one curve per damping level (or band speed),
//! the undamped (or massless) reference dashed, and the model's own point.

use super::spec::{Entry, Ink, Mark, OffView, Plot, Size, Swatch, Ticks, View, Weight};
use crate::analysis::Curves;
use crate::format::load_text;
use crate::i18n::Words;
use crate::tr;

/// The plot's height over its highest point.
const HEADROOM: f64 = 1.1;

/// Room left and right of the curves, as a fraction of their extent (the
/// first decade's label clear of the load axis's zero).
const SIDE_ROOM: f64 = 0.02;

/// The curves and the model's own point `[log10 ratio, load]`, if it has one.
#[derive(Clone, Copy, Debug)]
pub struct Paradox<'a> {
    pub curves: &'a Curves,
    pub here: Option<[f64; 2]>,
    /// The language of the axes and the legend.
    pub words: &'static Words,
}

impl Paradox<'_> {
    /// The plot, fitted to the curves and the model's point (the reference
    /// line only when it lies near them: [`Curves::fitted_top`]); `None`
    /// when the curves have no extent along the ratio.
    #[must_use]
    pub fn plot(&self) -> Option<Plot> {
        let curves = self.curves;
        let (x0, x1) = curves
            .lines
            .iter()
            .flat_map(|(_, points)| points.iter().map(|p| p[0]))
            .chain(self.here.map(|h| h[0]))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
                (lo.min(x), hi.max(x))
            });
        if !(x0.is_finite() && x1 > x0) {
            return None;
        }
        let (highest, reference_within) = curves.fitted_top(self.here.map(|h| h[1]));
        let mut marks = Vec::new();
        if let Some((_, p)) = curves.reference.as_ref().filter(|_| reference_within) {
            marks.push(Mark::Horizontal {
                y: *p,
                ink: Ink::Reference,
                weight: Weight::Fine,
                dashed: true,
            });
        }
        marks.extend(
            curves
                .lines
                .iter()
                .enumerate()
                .map(|(k, (_, points))| Mark::Line {
                    points: points.clone(),
                    ink: Ink::Series(k),
                    weight: Weight::Layered(k),
                    dashed: false,
                }),
        );
        if let Some(here) = self.here {
            marks.push(Mark::Markers {
                points: vec![here],
                ink: Ink::Now,
                size: Size::Regular,
                filled: true,
                off_view: OffView::Hidden,
            });
        }
        Some(Plot {
            id: "paradox",
            x_label: tr!(self.words, "axis-log-scale", axis = curves.x_label),
            y_label: tr!(self.words, "axis-first-critical-load"),
            x_ticks: Ticks::Decades,
            view: View::Ranges {
                x: (x0 - SIDE_ROOM * (x1 - x0), x1 + SIDE_ROOM * (x1 - x0)),
                y: (0.0, HEADROOM * highest.max(1e-9)),
            },
            marks,
            far_left: Vec::new(),
        })
    }

    /// The legend: each curve, the reference (said to lie above the axis
    /// when it is not drawn) and the model's own load.
    #[must_use]
    pub fn legend(&self) -> Vec<Entry> {
        let curves = self.curves;
        let mut entries: Vec<Entry> = curves
            .lines
            .iter()
            .enumerate()
            .map(|(k, (name, _))| Entry::new(Swatch::Line(Ink::Series(k)), name.clone()))
            .collect();
        let (_, reference_within) = curves.fitted_top(self.here.map(|h| h[1]));
        if let Some(name) = curves.reference_label(reference_within) {
            entries.push(Entry::new(Swatch::Dashed(Ink::Reference), name));
        }
        if let Some([_, p]) = self.here {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Now, true),
                tr!(self.words, "legend-this-model", load = load_text(p)),
            ));
        }
        entries
    }
}
