//! The root locus plots described once: the branches in the complex plane,
//! and Re and Im of every eigenvalue against the load (the paper's Figs 3
//! and 8), for the window (the present marked, the branches coloured by
//! load) and for a printed figure (the critical loads marked, other models
//! overlaid in series colours); and a model's locus as a figure gathers it.

use super::spec::{
    Entry, FarLeft, Ink, Mark, Medium, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight,
};
use super::view::{deciding_extent, versus_load_extent};
use crate::analysis::{C64, Locus, State, Transition};
use crate::format::number_text;
use crate::i18n::{Words, state_name, transition_in, transition_text};
use crate::tr;

mod analysed;
pub use analysed::Analysed;

/// One model's locus and what was found on it.
#[derive(Clone, Copy, Debug)]
pub struct Layer<'a> {
    pub name: &'a str,
    pub locus: &'a Locus,
    pub transitions: &'a [Transition],
    /// The stability ranges `(from, to, state)` over the locus's loads.
    pub ranges: &'a [(f64, f64, State)],
    /// The moving eigenvalues at each transition's load (paper only).
    pub at_transitions: &'a [Vec<C64>],
}

/// The window's present: the load and the eigenvalues there.
#[derive(Clone, Copy, Debug)]
pub struct Present<'a> {
    pub load: f64,
    pub eigenvalues: &'a [C64],
    /// The eigenvalues measured from the run, once measured.
    pub measured: Option<&'a [C64]>,
}

/// What the locus plots show: the main model and the models behind it (the
/// window's one overlay, a figure's several).
#[derive(Clone, Debug)]
pub struct Loci<'a> {
    pub main: Layer<'a>,
    pub others: Vec<Layer<'a>>,
    /// The window (the present added by [`Present::mark`]) or paper.
    pub medium: Medium,
    /// The language of the axes and the legends.
    pub words: &'static Words,
}

/// Which of the locus plots a sheet holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The complex plane.
    Plane,
    /// Re λ (top) and Im λ ≥ 0 (bottom) against the load.
    VersusLoad,
    /// All three, as the window's tab shows them.
    All,
}

/// The plots' ids (their names for the views that keep state per plot,
/// in no language).
const PLANE: &str = "root locus";
const RE: &str = "Re λ (1/s)";
const IM: &str = "Im λ (rad/s)";

/// Evenly spaced samples the window draws at most (a plot is a few hundred
/// pixels wide); the refinement's samples are all drawn.
const DRAWN_GRID_SAMPLES: usize = 300;

/// Evenly spaced samples of all branches together the window draws at
/// most: a long chain's many branches get fewer samples each (64 rods: 78),
/// so a frame stays within its time.
const DRAWN_GRID_POINTS: usize = 10_000;

/// The most critical loads a figure's legend names; the rest are counted
/// in one entry (`critical` lists them all).
const MOST_LEGEND_LOADS: usize = 8;

impl Loci<'_> {
    /// The plots `part` names with their legend: in the window the one
    /// legend of the tab, on paper the figure's of the plane or of the
    /// loads. The window's present is added by [`Present::mark`].
    #[must_use]
    pub fn sheet(&self, part: Part) -> Sheet {
        let plots = match part {
            Part::Plane => vec![self.plane()],
            Part::VersusLoad => vec![self.versus_load(false), self.versus_load(true)],
            Part::All => vec![
                self.plane(),
                self.versus_load(false),
                self.versus_load(true),
            ],
        };
        let legend = match self.medium {
            Medium::Window => self.window_legend(),
            Medium::Paper => self.paper_legend(part == Part::Plane),
        };
        Sheet { legend, plots }
    }

    /// The models in drawing order, each with its ink: the others behind,
    /// the main model in front.
    fn layers(&self) -> impl Iterator<Item = (&Layer<'_>, Ink)> {
        let window = self.medium == Medium::Window;
        self.others
            .iter()
            .enumerate()
            .map(move |(k, other)| (other, if window { Ink::Overlay } else { Ink::Series(k) }))
            .chain(std::iter::once((&self.main, Ink::Main)))
    }

    /// The load range of the main model's locus.
    fn load_range(&self) -> (f64, f64) {
        let loads = &self.main.locus.loads;
        (
            loads.first().copied().unwrap_or(0.0),
            loads.last().copied().unwrap_or(1.0),
        )
    }

    /// The root locus in the complex plane, at equal scales, holding the
    /// eigenvalues that decide stability of every model drawn. In the
    /// window: the main model's branches coloured by load, the current
    /// eigenvalues (marked on the edge when off the view) and the measured
    /// ones. On paper: open rings at the range's first load, the main
    /// model's eigenvalues at each critical load filled in the colour of
    /// the state entered.
    fn plane(&self) -> Plot {
        let extent = self
            .layers()
            .map(|(layer, _)| deciding_extent(layer.locus))
            .fold((0.0, 0.0), |(re, im): (f64, f64), (r, i)| {
                (re.max(r), im.max(i))
            });
        let marks = match self.medium {
            Medium::Window => self.window_plane_marks(),
            Medium::Paper => self.paper_plane_marks(),
        };
        let far_left = self
            .layers()
            .map(|(layer, _)| {
                let furthest = layer
                    .locus
                    .moving_branches()
                    .iter()
                    .flatten()
                    .map(|z| z.re)
                    .fold(0.0, f64::min);
                FarLeft {
                    x: furthest,
                    note: tr!(
                        self.words,
                        "locus-far-left",
                        name = layer.name,
                        re = number_text(furthest)
                    ),
                }
            })
            .collect();
        Plot {
            id: PLANE,
            x_label: tr!(self.words, "axis-re"),
            y_label: tr!(self.words, "axis-im"),
            x_ticks: Ticks::Plain,
            view: View::Equal { extent },
            marks,
            far_left,
        }
    }

    /// The plane's marks in the window: the axis, the overlay's branches,
    /// the main model's coloured by load.
    fn window_plane_marks(&self) -> Vec<Mark> {
        let mut marks = Vec::new();
        marks.push(Mark::Vertical {
            x: 0.0,
            name: String::new(),
            ink: Ink::Axis,
            weight: Weight::Regular,
            dashed: false,
        });
        for other in &self.others {
            for branch in &other.locus.branches {
                marks.push(Mark::Line {
                    points: points(branch),
                    ink: Ink::Overlay,
                    weight: Weight::Fine,
                    dashed: false,
                });
            }
        }
        marks.extend(self.graded_branches());
        marks
    }

    /// The plane's marks on paper: the axis dashed, every model's moving
    /// branches, the first load's rings and the critical loads' eigenvalues.
    fn paper_plane_marks(&self) -> Vec<Mark> {
        let mut marks = Vec::new();
        marks.push(Mark::Vertical {
            x: 0.0,
            name: String::new(),
            ink: Ink::Axis,
            weight: Weight::Fine,
            dashed: true,
        });
        for (layer, ink) in self.layers() {
            for branch in layer.locus.moving_branches() {
                marks.push(Mark::Line {
                    points: points(branch),
                    ink: ink.clone(),
                    weight: Weight::Fine,
                    dashed: false,
                });
            }
        }
        marks.push(Mark::Markers {
            points: points(&self.main.locus.moving_at(0)),
            ink: Ink::Main,
            size: Size::Regular,
            filled: false,
            off_view: OffView::Hidden,
        });
        for (t, eigenvalues) in self.main.transitions.iter().zip(self.main.at_transitions) {
            marks.push(Mark::Markers {
                points: points(eigenvalues),
                ink: Ink::State(t.to),
                size: Size::Regular,
                filled: true,
                off_view: OffView::Hidden,
            });
        }
        marks
    }

    /// The main model's branches as the window draws them: at most
    /// [`DRAWN_GRID_SAMPLES`] samples each ([`drawn_samples`]), coloured by
    /// the load along them.
    fn graded_branches(&self) -> Vec<Mark> {
        let locus = self.main.locus;
        let (min, max) = self.load_range();
        let shown = drawn_samples(locus);
        let along: Vec<f64> = shown
            .iter()
            .map(|&i| fraction(locus.loads[i], min, max))
            .collect();
        locus
            .branches
            .iter()
            .map(|branch| Mark::Graded {
                points: shown
                    .iter()
                    .map(|&i| [branch[i].re, branch[i].im])
                    .collect(),
                along: along.clone(),
                weight: Weight::Regular,
            })
            .collect()
    }

    /// Re λ or (`imaginary`) Im λ ≥ 0 of every branch against the load: the
    /// main model's stability ranges tinted in their states' colours, the
    /// others behind it; in the window the current load as a line, on paper
    /// the main model's critical loads dashed. The Re plot holds the real
    /// part of the eigenvalue furthest right at every load, of every model
    /// drawn. Of Im the upper half only: the lower is its mirror image
    /// (conjugate pairs), and a chain's 32 branches in both halves were a
    /// blur.
    fn versus_load(&self, imaginary: bool) -> Plot {
        let extent = versus_load_extent(self.layers().map(|(layer, _)| layer.locus), imaginary);
        let (p0, p1) = self.load_range();
        let window = self.medium == Medium::Window;
        let lowest = match (imaginary, window) {
            (false, _) => -1.1 * extent,
            (true, true) => -0.05 * extent,
            (true, false) => 0.0,
        };
        let mut marks: Vec<Mark> = self
            .main
            .ranges
            .iter()
            .map(|&(from, to, state)| Mark::Range { from, to, state })
            .collect();
        if !window {
            marks.extend(self.main.transitions.iter().map(|t| Mark::Vertical {
                x: t.load,
                name: String::new(),
                ink: Ink::State(t.to),
                weight: Weight::Fine,
                dashed: true,
            }));
        }
        for (layer, ink) in self.layers() {
            let locus = layer.locus;
            let part = |z: C64| if imaginary { z.im } else { z.re };
            if window {
                let samples = drawn_samples(locus);
                let layer_start = marks.len();
                for branch in &locus.branches {
                    if imaginary && branch.iter().all(|z| z.im < 0.0) {
                        continue;
                    }
                    let points: Vec<[f64; 2]> = samples
                        .iter()
                        .map(|&i| [locus.loads[i], part(branch[i])])
                        .collect();
                    // A conjugate pair's real parts (and real roots' zero
                    // imaginary parts) are one curve: drawn once, not
                    // shaded twice on a CPU renderer and counted twice to
                    // a listener.
                    let drawn = marks[layer_start..].iter().any(
                        |mark| matches!(mark, Mark::Line { points: line, .. } if *line == points),
                    );
                    if drawn {
                        continue;
                    }
                    marks.push(Mark::Line {
                        points,
                        ink: ink.clone(),
                        weight: Weight::Fine,
                        dashed: false,
                    });
                }
            } else {
                for branch in locus.moving_branches() {
                    marks.push(Mark::Line {
                        points: locus
                            .loads
                            .iter()
                            .zip(branch)
                            .map(|(&p, &z)| [p, part(z)])
                            .collect(),
                        ink: ink.clone(),
                        weight: Weight::Fine,
                        dashed: false,
                    });
                }
            }
        }
        let (id, label) = if imaginary {
            (IM, "axis-im")
        } else {
            (RE, "axis-re")
        };
        Plot {
            id,
            x_label: tr!(self.words, "axis-load"),
            y_label: self.words.get(label).into_owned(),
            x_ticks: Ticks::Plain,
            view: View::Ranges {
                x: (p0, p1),
                y: (lowest, 1.1 * extent),
            },
            marks,
            far_left: Vec::new(),
        }
    }

    /// The legend of the window's locus tab: what the colours, markers and
    /// lines are, and the overlay's own critical loads (the measured
    /// eigenvalues' entry is the present's, [`Present::mark`]).
    fn window_legend(&self) -> Vec<Entry> {
        let words = self.words;
        let (min, max) = self.load_range();
        let scale = (0..8).map(|i| Ink::Along(f64::from(i) / 7.0)).collect();
        let mut entries = vec![
            Entry::new(
                Swatch::Scale(scale),
                tr!(
                    words,
                    "legend-branch-colour",
                    from = number_text(min),
                    to = number_text(max)
                ),
            ),
            Entry::new(
                Swatch::Marker(Ink::Now, true),
                tr!(words, "legend-eigenvalues-now"),
            ),
        ];
        entries.push(Entry::new(
            Swatch::Line(Ink::LoadLine),
            tr!(words, "legend-current-load"),
        ));
        for other in &self.others {
            let loads = if other.transitions.is_empty() {
                tr!(words, "legend-overlay-no-change")
            } else {
                other
                    .transitions
                    .iter()
                    .map(|t| transition_text(words, t))
                    .collect::<Vec<_>>()
                    .join(";  ")
            };
            entries.push(Entry::new(
                Swatch::Line(Ink::Overlay),
                tr!(words, "legend-overlay", name = other.name, loads = loads),
            ));
        }
        entries
    }

    /// The legend of a figure of the plane (`plane`) or of Re and Im
    /// against the load: each model's curve, the plane's open rings, the
    /// main model's critical loads (at most [`MOST_LEGEND_LOADS`], the rest
    /// counted) and, against the load, the states its ranges are tinted in.
    fn paper_legend(&self, plane: bool) -> Vec<Entry> {
        let mark = |ink: Ink| {
            if plane {
                Swatch::Marker(ink, true)
            } else {
                Swatch::Dashed(ink)
            }
        };
        let mut entries = vec![Entry::new(Swatch::Line(Ink::Main), self.main.name)];
        entries.extend(
            self.others
                .iter()
                .enumerate()
                .map(|(k, other)| Entry::new(Swatch::Line(Ink::Series(k)), other.name)),
        );
        if plane {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Main, false),
                format!("p = {}", number_text(self.load_range().0)),
            ));
        }
        let transitions = self.main.transitions;
        let words = self.words;
        entries.extend(transitions.iter().take(MOST_LEGEND_LOADS).map(|t| {
            Entry::new(
                mark(Ink::State(t.to)),
                transition_in(words, "legend-transition", t),
            )
        }));
        let more = transitions.len().saturating_sub(MOST_LEGEND_LOADS);
        if more > 0 {
            entries.push(Entry::new(
                mark(Ink::Main),
                tr!(words, "legend-more-loads", count = more),
            ));
        }
        if !plane {
            for state in [State::Stable, State::Flutter, State::Divergence] {
                if self.main.ranges.iter().any(|r| r.2 == state) {
                    entries.push(Entry::new(Swatch::Fill(state), state_name(words, state)));
                }
            }
        }
        entries
    }
}

impl Present<'_> {
    /// Adds the present to a window's `sheet` of the locus: the current
    /// eigenvalues (marked on the edge when off the view) and the measured
    /// ones on the plane, the current load on the plots against the load,
    /// and the measured eigenvalues' legend entry after the current ones'.
    /// The rest of the sheet depends on the analysis only, so the window
    /// keeps it from frame to frame.
    pub fn mark(&self, sheet: &mut Sheet, words: &'static Words) {
        for plot in &mut sheet.plots {
            if plot.id == PLANE {
                plot.marks.push(Mark::Markers {
                    points: points(self.eigenvalues),
                    ink: Ink::Now,
                    size: Size::Regular,
                    filled: true,
                    off_view: OffView::EdgeMarked,
                });
                if let Some(measured) = self.measured {
                    plot.marks.push(Mark::Markers {
                        points: points(measured),
                        ink: Ink::Measured,
                        size: Size::Large,
                        filled: false,
                        off_view: OffView::Hidden,
                    });
                }
            } else {
                plot.marks.push(Mark::Vertical {
                    x: self.load,
                    name: tr!(words, "mark-load"),
                    ink: Ink::LoadLine,
                    weight: Weight::Regular,
                    dashed: false,
                });
            }
        }
        if self.measured.is_some() {
            let now = Swatch::Marker(Ink::Now, true);
            let after = sheet
                .legend
                .iter()
                .position(|entry| entry.swatch == now)
                .map_or(0, |i| i + 1);
            sheet.legend.insert(
                after,
                Entry::new(
                    Swatch::Marker(Ink::Measured, false),
                    tr!(words, "legend-measured"),
                ),
            );
        }
    }
}

/// Eigenvalues as points of the plane.
fn points(eigenvalues: &[C64]) -> Vec<[f64; 2]> {
    eigenvalues.iter().map(|z| [z.re, z.im]).collect()
}

/// The indices of the locus samples the window draws: every k-th evenly
/// spaced one, so that at most [`DRAWN_GRID_SAMPLES`] are (and at most
/// [`DRAWN_GRID_POINTS`] over all branches), every sample the refinement
/// added (branch points, axis crossings) and the last.
fn drawn_samples(locus: &Locus) -> Vec<usize> {
    let grid = locus.on_grid.iter().filter(|&&g| g).count();
    let most = DRAWN_GRID_SAMPLES.min(DRAWN_GRID_POINTS / locus.branches.len().max(1));
    let stride = grid.div_ceil(most.max(2)).max(1);
    let last = locus.loads.len().saturating_sub(1);
    let mut grid_index = 0;
    (0..locus.loads.len())
        .filter(|&i| {
            if !locus.on_grid[i] {
                return true;
            }
            grid_index += 1;
            (grid_index - 1) % stride == 0 || i == last
        })
        .collect()
}

/// How far `load` lies from `min` to `max`, in [0, 1].
fn fraction(load: f64, min: f64, max: f64) -> f64 {
    if max > min {
        ((load - min) / (max - min)).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests;
