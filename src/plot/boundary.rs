//! The stability boundaries described once: the plane of the second
//! parameter and the load, each flutter boundary in the flutter colour,
//! solid where its onset is soft and dashed where it is hard, each
//! divergence boundary in the divergence colour, and the special points
//! ringed and named.

use super::map::axis_words;
use super::spec::{Entry, Ink, Mark, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight};
use crate::analysis::{Boundaries, BoundaryKind, SpecialKind, State};
use crate::i18n::Words;
use crate::model::Axis;
use crate::tr;

/// What the plane shows.
#[derive(Clone, Copy, Debug)]
pub struct BoundaryPlane<'a> {
    pub found: &'a Boundaries,
    /// The second parameter, along x.
    pub axis: &'a Axis,
    pub axis_range: (f64, f64),
    pub load_range: (f64, f64),
    /// The language of the axes and the legend.
    pub words: &'static Words,
}

/// How a stretch of a flutter boundary sets in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Onset {
    Soft,
    Hard,
    /// No coefficient there (it failed).
    Unknown,
}

impl BoundaryPlane<'_> {
    /// The plane and its legend.
    #[must_use]
    pub fn sheet(&self) -> Sheet {
        Sheet {
            legend: self.legend(),
            plots: vec![self.plot()],
        }
    }

    /// The boundaries' stretches: their points, ink and whether dashed.
    fn stretches(&self) -> Vec<(Vec<[f64; 2]>, State, Onset)> {
        let mut out = Vec::new();
        for curve in &self.found.curves {
            let state = match curve.kind {
                BoundaryKind::Flutter => State::Flutter,
                BoundaryKind::Divergence => State::Divergence,
            };
            let mut run: Vec<[f64; 2]> = Vec::new();
            let mut onset = None;
            for point in &curve.points {
                let here = match (curve.kind, point.first_lyapunov) {
                    (BoundaryKind::Flutter, Some(l1)) if l1 < 0.0 => Onset::Soft,
                    (BoundaryKind::Flutter, Some(_)) => Onset::Hard,
                    (BoundaryKind::Divergence, _) | (BoundaryKind::Flutter, None) => Onset::Unknown,
                };
                let xy = [point.value, point.load];
                match onset {
                    Some(before) if before != here => {
                        // The stretches meet: the next starts where this ends.
                        run.push(xy);
                        out.push((std::mem::take(&mut run), state, before));
                        run.push(xy);
                    }
                    _ => run.push(xy),
                }
                onset = Some(here);
            }
            if let Some(onset) = onset {
                out.push((run, state, onset));
            }
        }
        out
    }

    /// The loads the view spans: from the range's start to a quarter
    /// above the highest boundary (within the range; all of it without
    /// boundaries), so that curves low in a wide range are not a sliver.
    fn fitted_loads(&self) -> (f64, f64) {
        let (p0, p1) = self.load_range;
        let highest = self
            .found
            .curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.load))
            .reduce(f64::max);
        match highest {
            Some(top) if top > p0 => (p0, (p0 + 1.25 * (top - p0)).min(p1)),
            _ => (p0, p1),
        }
    }

    /// The plane over the second parameter's range and the fitted loads.
    fn plot(&self) -> Plot {
        let mut marks: Vec<Mark> = self
            .stretches()
            .into_iter()
            .map(|(points, state, onset)| Mark::Line {
                points,
                ink: Ink::State(state),
                weight: if onset == Onset::Unknown && state == State::Flutter {
                    Weight::Fine
                } else {
                    Weight::Regular
                },
                dashed: onset == Onset::Hard,
            })
            .collect();
        let special = &self.found.special_points;
        if !special.is_empty() {
            marks.push(Mark::Markers {
                points: special.iter().map(|s| [s.value, s.load]).collect(),
                ink: Ink::Main,
                size: Size::Large,
                filled: false,
                off_view: OffView::Hidden,
            });
        }
        let (p0, p1) = self.fitted_loads();
        let above = 0.06 * (p1 - p0);
        marks.extend(special.iter().map(|s| Mark::Label {
            at: [s.value, s.load + above],
            text: short_name(s.kind).to_owned(),
        }));
        Plot {
            id: "stability boundaries",
            x_label: axis_words(self.axis, self.words),
            y_label: tr!(self.words, "axis-load-named"),
            x_ticks: Ticks::Plain,
            view: View::Ranges {
                x: self.axis_range,
                y: (p0, p1),
            },
            marks,
            far_left: Vec::new(),
        }
    }

    /// The legend: the kinds of boundary drawn and the special points' names.
    fn legend(&self) -> Vec<Entry> {
        let words = self.words;
        let stretches = self.stretches();
        let any = |state: State, onset: Onset| {
            stretches
                .iter()
                .any(|(_, s, o)| *s == state && (*o == onset || state == State::Divergence))
        };
        let flutter = Ink::State(State::Flutter);
        let mut entries = Vec::new();
        if any(State::Flutter, Onset::Soft) {
            entries.push(Entry::new(
                Swatch::Line(flutter.clone()),
                tr!(words, "legend-flutter-soft"),
            ));
        }
        if any(State::Flutter, Onset::Unknown) {
            entries.push(Entry::new(
                Swatch::Line(flutter.clone()),
                tr!(words, "legend-hopf-point"),
            ));
        }
        if any(State::Flutter, Onset::Hard) {
            entries.push(Entry::new(
                Swatch::Dashed(flutter),
                tr!(words, "legend-flutter-hard"),
            ));
        }
        if any(State::Divergence, Onset::Unknown) {
            entries.push(Entry::new(
                Swatch::Line(Ink::State(State::Divergence)),
                tr!(words, "legend-divergence-onset"),
            ));
        }
        if !self.found.special_points.is_empty() {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Main, false),
                tr!(words, "legend-special-points"),
            ));
        }
        entries
    }
}

/// A special point's label on the plot (its legend entry spells it out).
fn short_name(kind: SpecialKind) -> &'static str {
    match kind {
        SpecialKind::Bautin => "B",
        SpecialKind::BogdanovTakens => "BT",
        SpecialKind::DoubleHopf => "DH",
        SpecialKind::ZeroHopf => "ZH",
    }
}
