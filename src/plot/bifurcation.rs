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

/// Where each of `names` (its text, its ring, the way its branch opens
/// there) goes: the first of [`name_places`] whose plate covers no name
/// placed before it and no other ring (the first place where none is
/// free). The plate's size is estimated from `above` and `aside`.
fn place_names(names: &[(&str, [f64; 2], f64)], above: f64, aside: f64) -> Vec<[f64; 2]> {
    // A ring reaches about a fifth of `aside` and half of `above` from its
    // centre.
    let ring_reach = [aside / 5.0, above / 2.0];
    let mut taken: Vec<([f64; 2], [f64; 2])> = Vec::new();
    for (text, ring, opening) in names {
        // Half a name's plate: a sixth of `aside` a letter and one for the
        // padding, and 0.6 of `above` (a printed figure's names, the
        // largest against its data; the window's are smaller).
        #[expect(clippy::cast_precision_loss, reason = "a few letters")]
        let half = [(text.len() + 1) as f64 * aside / 6.0, 0.6 * above];
        let free = |at: [f64; 2]| {
            let apart = |c: [f64; 2], reach: [f64; 2]| {
                (at[0] - c[0]).abs() >= half[0] + reach[0]
                    || (at[1] - c[1]).abs() >= half[1] + reach[1]
            };
            taken.iter().all(|&(c, h)| apart(c, h))
                && names
                    .iter()
                    .filter(|(_, other, _)| other != ring)
                    .all(|(_, other, _)| apart(*other, ring_reach))
        };
        let places = name_places(*ring, *opening, above, aside);
        let at = places
            .iter()
            .copied()
            .find(|&at| free(at))
            .unwrap_or(places[0]);
        taken.push((at, half));
    }
    taken.into_iter().map(|(at, _)| at).collect()
}

/// Where the name of the ring at `ring` may go, in order: `above` it, or
/// at a fold (`opening` not 0) `aside` it where the branch is not; then
/// below it, on either side, and twice and three times as high.
fn name_places(ring: [f64; 2], opening: f64, above: f64, aside: f64) -> [[f64; 2]; 6] {
    let [x, y] = ring;
    let first = if opening == 0.0 {
        [x, y + above]
    } else {
        [x - opening * aside, y]
    };
    [
        first,
        [x, y - above],
        [x + aside, y],
        [x - aside, y],
        [x, y + 2.0 * above],
        [x, y + 3.0 * above],
    ]
}

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
                own.chain(offshoots)
            })
            .collect()
    }

    /// The cycles' bifurcations ringed, each named `above` its ring, or at a
    /// fold `aside` it where the branch is not (the name would hide the
    /// branch's turn), or where that name would cover another's or another
    /// ring, at the first free place of [`name_places`].
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
        let names: Vec<(&str, [f64; 2], f64)> = turns
            .iter()
            .map(|(t, opening)| (short_name(t.kind), [t.load, t.amplitude_rad], *opening))
            .collect();
        let places = place_names(&names, above, aside);
        marks.extend(
            names
                .iter()
                .zip(places)
                .map(|((text, ring, _), at)| Mark::Label {
                    at,
                    text: (*text).to_owned(),
                    of: Some(*ring),
                }),
        );
        marks
    }

    /// The cycles as runs of equal stability, the asymmetric branches' too.
    fn runs(&self) -> Vec<(Vec<[f64; 2]>, bool)> {
        self.branches
            .iter()
            .flat_map(|b| {
                let offshoots = b.offshoots.iter().flat_map(Offshoot::runs);
                b.runs().into_iter().chain(offshoots)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Whether the estimated plates of the names at `a` and `b` (texts
    /// `ta`, `tb`) overlap.
    fn overlap(a: [f64; 2], ta: &str, b: [f64; 2], tb: &str, above: f64, aside: f64) -> bool {
        #[expect(clippy::cast_precision_loss, reason = "a few letters")]
        let half = |t: &str| [(t.len() + 1) as f64 * aside / 6.0, 0.6 * above];
        let (ha, hb) = (half(ta), half(tb));
        (a[0] - b[0]).abs() < ha[0] + hb[0] && (a[1] - b[1]).abs() < ha[1] + hb[1]
    }

    /// A lone ring's name stays above it (a fold's beside it, away from
    /// the branch). Three rings as close as the hard onset's break of
    /// symmetry and the two tori past it on a printed page (0.1 of the
    /// load apart) get names on three different sides, none over another
    /// name or another ring; placed above each, as before, they covered
    /// each other.
    #[test]
    fn crowded_rings_get_names_that_do_not_cover_each_other() {
        let (above, aside) = (0.18, 0.32);
        assert_eq!(
            place_names(&[("NS", [2.0, 1.0], 0.0)], above, aside),
            [[2.0, 1.18]]
        );
        assert_eq!(
            place_names(&[("LPC", [2.0, 1.0], 1.0)], above, aside),
            [[1.68, 1.0]]
        );
        let names = [
            ("BPC", [2.297, 2.278], 0.0),
            ("NS", [2.360, 2.375], 0.0),
            ("NS", [2.445, 2.451], 0.0),
        ];
        let placed = place_names(&names, above, aside);
        for (i, (a, (ta, ring_a, _))) in placed.iter().zip(&names).enumerate() {
            for (b, (tb, ring_b, _)) in placed.iter().zip(&names).skip(i + 1) {
                assert!(!overlap(*a, ta, *b, tb, above, aside), "{placed:?}");
                assert!(!overlap(*a, ta, *ring_b, "", above, aside), "{placed:?}");
                assert!(!overlap(*b, tb, *ring_a, "", above, aside), "{placed:?}");
            }
        }
        let above_each: Vec<[f64; 2]> =
            names.iter().map(|(_, r, _)| [r[0], r[1] + above]).collect();
        assert!(overlap(
            above_each[0],
            "BPC",
            above_each[1],
            "NS",
            above,
            aside
        ));
    }
}
