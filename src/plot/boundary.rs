//! The stability boundaries described once: the plane of the second
//! parameter and the load, each flutter boundary in the flutter colour,
//! solid where its onset is soft and dashed where it is hard, each
//! divergence boundary in the divergence colour, each fold of cycles in
//! the main ink with the band of hysteresis between it and the hard
//! flutter boundary above it tinted, and the special points ringed and
//! named.

use super::axis_words;
use super::spec::{Entry, Ink, Mark, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight};
use crate::analysis::{Boundaries, BoundaryKind, BoundarySpec, SpecialKind, State, load_on_chord};
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
    /// Drawn over a stability map's cells, which are in the states'
    /// colours: the boundaries then in the main ink (soft solid, hard
    /// dashed), so that they read on the cells of their own colour.
    pub over_cells: bool,
}

/// A band's lower and upper edges, point by point.
type Band = (Vec<[f64; 2]>, Vec<[f64; 2]>);

/// How a stretch of a flutter boundary sets in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Onset {
    Soft,
    Hard,
    /// No coefficient there (it failed).
    Unknown,
}

impl<'a> BoundaryPlane<'a> {
    /// The plane `found` was followed over, `spec`'s, on paper.
    #[must_use]
    pub fn of(found: &'a Boundaries, spec: &'a BoundarySpec, words: &'static Words) -> Self {
        Self {
            found,
            axis: &spec.axis,
            axis_range: spec.axis_range,
            load_range: spec.load_range,
            words,
            over_cells: false,
        }
    }

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

    /// The loads the view spans: the boundaries' and folds' loads and a
    /// quarter of their spread each side (from the range's start where
    /// that comes near it; within the range; all of it without
    /// boundaries), so that curves close together in a wide range are not
    /// a sliver and a thin band of hysteresis shows.
    fn fitted_loads(&self) -> (f64, f64) {
        let (p0, p1) = self.load_range;
        let loads = self
            .found
            .curves
            .iter()
            .flat_map(|c| c.points.iter().map(|p| p.load))
            .chain(
                self.found
                    .folds
                    .iter()
                    .flat_map(|f| f.points.iter().map(|p| p.load)),
            );
        let (low, high) = loads.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
        if !(low.is_finite() && high.is_finite()) {
            return (p0, p1);
        }
        let pad = 0.25 * (high - low).max(1e-3 * (p1 - p0));
        let bottom = if low - 2.0 * pad <= p0 { p0 } else { low - pad };
        (bottom.max(p0), (high + pad).min(p1))
    }

    /// The ink of a boundary of `state`.
    fn ink(&self, state: State) -> Ink {
        if self.over_cells {
            Ink::Main
        } else {
            Ink::State(state)
        }
    }

    /// The folds of cycles as polylines `[value, load]`.
    fn folds(&self) -> Vec<Vec<[f64; 2]>> {
        self.found
            .folds
            .iter()
            .map(|fold| fold.points.iter().map(|p| [p.value, p.load]).collect())
            .collect()
    }

    /// The bands of hysteresis: below, each fold of cycles over a stretch
    /// where it runs one way in the parameter; above, the nearest flutter
    /// boundary at each of its points (where there is one).
    fn bands(&self) -> Vec<Band> {
        let mut out = Vec::new();
        for fold in self.folds() {
            for run in fold.chunk_by(|a, b| a[0] != b[0]).flat_map(monotone_runs) {
                let mut run = run.to_vec();
                run.sort_by(|a, b| a[0].total_cmp(&b[0]));
                let (lower, upper): (Vec<_>, Vec<_>) = run
                    .iter()
                    .filter_map(|&low| Some((low, [low[0], self.onset_above(low)?])))
                    .unzip();
                if lower.len() >= 2 {
                    out.push((lower, upper));
                }
            }
        }
        out
    }

    /// The least flutter onset at `point`'s parameter at or above its load
    /// (less the fold's accuracy), interpolated along the flutter
    /// boundaries' chords.
    fn onset_above(&self, point: [f64; 2]) -> Option<f64> {
        let [x, load] = point;
        self.found
            .curves
            .iter()
            .filter(|c| c.kind == BoundaryKind::Flutter)
            .flat_map(|c| c.points.windows(2))
            .filter_map(|w| load_on_chord((w[0].value, w[0].load), (w[1].value, w[1].load), x))
            .filter(|&onset| onset >= load - 1e-6 * load.abs().max(1.0))
            .reduce(f64::min)
    }

    /// The boundaries' marks: the bands of hysteresis, the folds of cycles,
    /// the boundaries, the special points ringed and named (the names set
    /// off by `name_offset` in the load). Each point is `[value, load]`,
    /// or `[load, value]` where `transposed` (the stability map's axes).
    #[must_use]
    pub fn marks(&self, transposed: bool, name_offset: f64) -> Vec<Mark> {
        let at = |[value, load]: [f64; 2]| {
            if transposed {
                [load, value]
            } else {
                [value, load]
            }
        };
        let flip = |points: Vec<[f64; 2]>| points.into_iter().map(at).collect();
        let mut marks: Vec<Mark> = self
            .bands()
            .into_iter()
            .map(|(lower, upper)| Mark::Band {
                lower: flip(lower),
                upper: flip(upper),
                state: State::Flutter,
            })
            .collect();
        marks.extend(self.folds().into_iter().map(|points| Mark::Line {
            points: flip(points),
            ink: Ink::Main,
            weight: Weight::Fine,
            dashed: false,
        }));
        marks.extend(
            self.stretches()
                .into_iter()
                .map(|(points, state, onset)| Mark::Line {
                    points: flip(points),
                    ink: self.ink(state),
                    weight: if onset == Onset::Unknown && state == State::Flutter {
                        Weight::Fine
                    } else {
                        Weight::Regular
                    },
                    dashed: onset == Onset::Hard,
                }),
        );
        let special = &self.found.special_points;
        if !special.is_empty() {
            marks.push(Mark::Markers {
                points: special.iter().map(|s| at([s.value, s.load])).collect(),
                ink: Ink::Main,
                size: Size::Large,
                filled: false,
                off_view: OffView::Hidden,
            });
        }
        marks.extend(special.iter().map(|s| Mark::Label {
            at: at([s.value, s.load + name_offset]),
            text: short_name(s.kind).to_owned(),
            of: Some(at([s.value, s.load])),
        }));
        marks
    }

    /// The plane over the second parameter's range and the fitted loads.
    fn plot(&self) -> Plot {
        let (p0, p1) = self.fitted_loads();
        Plot {
            id: "stability boundaries",
            x_label: axis_words(self.axis, self.words),
            y_label: tr!(self.words, "axis-load-named"),
            x_ticks: Ticks::Plain,
            view: View::Ranges {
                x: self.axis_range,
                y: (p0, p1),
            },
            marks: self.marks(false, 0.06 * (p1 - p0)),
            far_left: Vec::new(),
        }
    }

    /// The legend: the kinds of boundary drawn and the special points' names.
    #[must_use]
    pub fn legend(&self) -> Vec<Entry> {
        let words = self.words;
        let stretches = self.stretches();
        let any = |state: State, onset: Onset| {
            stretches
                .iter()
                .any(|(_, s, o)| *s == state && (*o == onset || state == State::Divergence))
        };
        let flutter = self.ink(State::Flutter);
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
                Swatch::Line(self.ink(State::Divergence)),
                tr!(words, "legend-divergence-onset"),
            ));
        }
        if !self.found.folds.is_empty() {
            entries.push(Entry::new(
                Swatch::Line(Ink::Main),
                tr!(words, "legend-fold-of-cycles"),
            ));
        }
        if !self.bands().is_empty() {
            entries.push(Entry::new(
                Swatch::Fill(State::Flutter),
                tr!(words, "legend-hysteresis"),
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

/// `points` cut where they turn back in x, each piece running one way (the
/// pieces share their ends).
fn monotone_runs(points: &[[f64; 2]]) -> Vec<&[[f64; 2]]> {
    let mut out = Vec::new();
    let mut start = 0;
    for i in 1..points.len().saturating_sub(1) {
        let before = points[i][0] - points[i - 1][0];
        let after = points[i + 1][0] - points[i][0];
        if before * after < 0.0 {
            out.push(&points[start..=i]);
            start = i;
        }
    }
    if points.len() > start + 1 {
        out.push(&points[start..]);
    }
    out
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
