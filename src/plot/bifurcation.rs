//! The bifurcation diagram described once: the straight column along the
//! load axis (solid where stable, dashed where not), the largest angle over
//! each limit cycle against the load (stable solid, unstable dashed, in the
//! flutter colour), the flutter onsets as rings; on paper a sweep's runs
//! (dots up, rings down), in the window the current load, the onset a ramp
//! saw and the running column's swing.

use super::spec::{Entry, Ink, Mark, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight};
use crate::analysis::{
    AffinePencil, AnalysisError, Branch, CycleBifurcation, CycleBifurcationKind, Offshoot, Onset,
    State, classify, critical_loads, stability_ranges,
};
use crate::i18n::Words;
use crate::tr;

/// What a printed diagram shows, gathered as `bifurcation` and
/// `figure --kind bifurcation` gather it.
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

impl BifurcationData {
    /// The diagram over `load_range` of the column of `pencil`: the
    /// straight column's stability there (its critical loads as `critical`
    /// finds them), the branches followed from `onsets`, and `sweep`.
    ///
    /// # Errors
    /// An eigenvalue computation that fails.
    pub fn new(
        pencil: &AffinePencil,
        (lo, hi): (f64, f64),
        onsets: &[Onset],
        sweep: Vec<(f64, f64, bool)>,
    ) -> Result<Self, AnalysisError> {
        let first = pencil.spectrum(lo)?;
        let first = classify(&first.eigenvalues, first.scale_per_s).state;
        let transitions = critical_loads(pencil, lo, hi)?;
        let equilibrium = stability_ranges(&transitions, first, lo, hi)
            .into_iter()
            .map(|(from, to, state)| (from, to, state == State::Stable))
            .collect();
        Ok(Self {
            load_range: (lo, hi),
            equilibrium,
            branches: onsets
                .iter()
                .filter_map(|o| o.branch.clone().ok())
                .collect(),
            sweep,
        })
    }

    /// The diagram's sheet on paper, in `words`.
    #[must_use]
    pub fn sheet(&self, words: &'static Words) -> Sheet {
        Diagram {
            load_range: self.load_range,
            equilibrium: &self.equilibrium,
            branches: self.branches.iter().collect(),
            sweep: &self.sweep,
            present: None,
            words,
        }
        .sheet()
    }
}

/// The window's present on the diagram.
#[derive(Clone, Copy, Debug)]
pub struct Present {
    pub load: f64,
    /// The load at which a ramp saw the column start to swing.
    pub seen_at: Option<f64>,
    /// The running column's largest angle over its last period.
    pub swing_rad: Option<f64>,
}

/// What the diagram shows.
#[derive(Clone, Debug)]
pub struct Diagram<'a> {
    /// The loads the view spans.
    pub load_range: (f64, f64),
    /// The straight column's stretches `(from, to, stable)`.
    pub equilibrium: &'a [(f64, f64, bool)],
    pub branches: Vec<&'a Branch>,
    /// A sweep's steps `(load, largest angle, upward)` (paper).
    pub sweep: &'a [(f64, f64, bool)],
    /// `Some` in the window.
    pub present: Option<Present>,
    /// The language of the axes and the legend.
    pub words: &'static Words,
}

impl Diagram<'_> {
    /// The cycles' own bifurcations along every branch and the asymmetric
    /// branches born on it, each with the way its branch opens there (see
    /// [`Branch::opening`]).
    fn cycle_bifurcations(&self) -> Vec<(CycleBifurcation, f64)> {
        self.branches
            .iter()
            .flat_map(|b| {
                let own = b.bifurcations.iter().map(|t| (*t, b.opening(t)));
                let offshoots = b
                    .offshoots
                    .iter()
                    .flat_map(|o| o.bifurcations.iter().map(move |t| (*t, o.opening(t))));
                own.chain(offshoots).collect::<Vec<_>>()
            })
            .collect()
    }

    /// The cycles' bifurcations ringed, each named `above` its ring, or at a
    /// fold `aside` it where the branch is not (the name would hide the
    /// branch's turn).
    fn turn_marks(&self, above: f64, aside: f64) -> Vec<Mark> {
        let turns = self.cycle_bifurcations();
        if turns.is_empty() {
            return Vec::new();
        }
        let mut marks = vec![Mark::Markers {
            points: turns
                .iter()
                .map(|(t, _)| [t.load, t.amplitude_rad])
                .collect(),
            ink: Ink::Main,
            size: Size::Large,
            filled: false,
            off_view: OffView::Hidden,
        }];
        marks.extend(turns.iter().map(|(t, opening)| Mark::Label {
            at: if *opening == 0.0 {
                [t.load, t.amplitude_rad + above]
            } else {
                [t.load - opening * aside, t.amplitude_rad]
            },
            text: short_name(t.kind).to_owned(),
            of: Some([t.load, t.amplitude_rad]),
        }));
        marks
    }

    /// The cycles as runs of equal stability, the asymmetric branches' too.
    fn runs(&self) -> Vec<(Vec<[f64; 2]>, bool)> {
        self.branches
            .iter()
            .flat_map(|b| {
                let offshoots = b.offshoots.iter().flat_map(Offshoot::runs);
                b.runs().into_iter().chain(offshoots).collect::<Vec<_>>()
            })
            .collect()
    }

    /// The diagram and its legend.
    #[must_use]
    pub fn sheet(&self) -> Sheet {
        Sheet {
            legend: self.legend(),
            plots: vec![self.plot()],
        }
    }

    /// The diagram: amplitudes up to a tenth above the largest
    /// (cycle, sweep or swing; a tenth of a radian where there is none).
    fn plot(&self) -> Plot {
        let runs = self.runs();
        let highest = runs
            .iter()
            .flat_map(|(points, _)| points.iter().map(|p| p[1]))
            .chain(self.sweep.iter().map(|s| s.1))
            .chain(self.present.and_then(|p| p.swing_rad))
            .fold(0.1, f64::max);
        let mut marks: Vec<Mark> = self
            .equilibrium
            .iter()
            .map(|&(from, to, stable)| Mark::Line {
                points: vec![[from, 0.0], [to, 0.0]],
                ink: Ink::Main,
                weight: Weight::Regular,
                dashed: !stable,
            })
            .collect();
        marks.extend(runs.into_iter().map(|(points, stable)| Mark::Line {
            points,
            ink: Ink::State(State::Flutter),
            weight: Weight::Regular,
            dashed: !stable,
        }));
        if !self.branches.is_empty() {
            marks.push(Mark::Markers {
                points: self.branches.iter().map(|b| [b.hopf().load, 0.0]).collect(),
                ink: Ink::State(State::Flutter),
                size: Size::Regular,
                filled: false,
                off_view: OffView::Hidden,
            });
        }
        let (lo, hi) = self.load_range;
        marks.extend(self.turn_marks(0.06 * highest, 0.08 * (hi - lo)));
        for upward in [true, false] {
            let points: Vec<[f64; 2]> = self
                .sweep
                .iter()
                .filter(|s| s.2 == upward)
                .map(|s| [s.0, s.1])
                .collect();
            if !points.is_empty() {
                marks.push(Mark::Markers {
                    points,
                    ink: Ink::Main,
                    size: if upward { Size::Small } else { Size::Large },
                    filled: upward,
                    off_view: OffView::Hidden,
                });
            }
        }
        if let Some(present) = self.present {
            marks.push(Mark::Vertical {
                x: present.load,
                name: tr!(self.words, "mark-load"),
                ink: Ink::LoadLine,
                weight: Weight::Fine,
                dashed: false,
            });
            if let Some(seen) = present.seen_at {
                marks.push(Mark::Vertical {
                    x: seen,
                    name: tr!(self.words, "legend-seen-in-ramp"),
                    ink: Ink::Measured,
                    weight: Weight::Fine,
                    dashed: true,
                });
            }
            if let Some(swing) = present.swing_rad {
                marks.push(Mark::Markers {
                    points: vec![[present.load, swing]],
                    ink: Ink::Now,
                    size: Size::Regular,
                    filled: true,
                    off_view: OffView::Hidden,
                });
            }
        }
        Plot {
            id: "post-critical",
            x_label: tr!(self.words, "axis-load-named"),
            y_label: tr!(self.words, "axis-largest-angle"),
            x_ticks: Ticks::Plain,
            // A little below zero: the straight column's line along the
            // load axis clear of the plot's edge.
            view: View::Ranges {
                x: self.load_range,
                y: (-0.03 * 1.1 * highest, 1.1 * highest),
            },
            marks,
            far_left: Vec::new(),
        }
    }

    /// The legend: what each line and marker drawn is.
    fn legend(&self) -> Vec<Entry> {
        let words = self.words;
        let flutter = Ink::State(State::Flutter);
        let runs = self.runs();
        let any = |stable: bool| runs.iter().any(|(_, s)| *s == stable);
        let mut entries = vec![Entry::new(
            Swatch::Line(Ink::Main),
            tr!(words, "legend-straight-stable"),
        )];
        if self.equilibrium.iter().any(|(_, _, stable)| !stable) {
            entries.push(Entry::new(
                Swatch::Dashed(Ink::Main),
                tr!(words, "legend-straight-unstable"),
            ));
        }
        if any(true) {
            entries.push(Entry::new(
                Swatch::Line(flutter.clone()),
                tr!(words, "legend-stable-cycle"),
            ));
        }
        if any(false) {
            entries.push(Entry::new(
                Swatch::Dashed(flutter.clone()),
                tr!(words, "legend-unstable-cycle"),
            ));
        }
        if !self.branches.is_empty() {
            entries.push(Entry::new(
                Swatch::Marker(flutter, false),
                tr!(words, "legend-hopf-point"),
            ));
        }
        let turns = self.cycle_bifurcations();
        let kinds: Vec<String> = [
            (CycleBifurcationKind::Fold, "legend-cycle-fold"),
            (
                CycleBifurcationKind::PeriodDoubling,
                "legend-cycle-period-doubling",
            ),
            (CycleBifurcationKind::NeimarkSacker, "legend-cycle-torus"),
            (
                CycleBifurcationKind::SymmetryBreaking,
                "legend-cycle-symmetry-breaking",
            ),
        ]
        .into_iter()
        .filter(|(kind, _)| turns.iter().any(|(t, _)| t.kind == *kind))
        .map(|(_, id)| words.get(id).into_owned())
        .collect();
        if !kinds.is_empty() {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Main, false),
                kinds.join(", "),
            ));
        }
        for (upward, id) in [(true, "legend-sweep-up"), (false, "legend-sweep-down")] {
            if self.sweep.iter().any(|s| s.2 == upward) {
                entries.push(Entry::new(Swatch::Marker(Ink::Main, upward), words.get(id)));
            }
        }
        if let Some(present) = self.present {
            entries.push(Entry::new(
                Swatch::Line(Ink::LoadLine),
                tr!(words, "legend-current-load"),
            ));
            if present.seen_at.is_some() {
                entries.push(Entry::new(
                    Swatch::Dashed(Ink::Measured),
                    tr!(words, "legend-seen-in-ramp"),
                ));
            }
            if present.swing_rad.is_some() {
                entries.push(Entry::new(
                    Swatch::Marker(Ink::Now, true),
                    tr!(words, "legend-largest-angle"),
                ));
            }
        }
        entries
    }
}

/// A bifurcation of the cycles as labelled on the diagram (the legend
/// spells it out).
fn short_name(kind: CycleBifurcationKind) -> &'static str {
    match kind {
        CycleBifurcationKind::Fold => "LPC",
        CycleBifurcationKind::PeriodDoubling => "PD",
        CycleBifurcationKind::NeimarkSacker => "NS",
        CycleBifurcationKind::SymmetryBreaking => "BPC",
    }
}
