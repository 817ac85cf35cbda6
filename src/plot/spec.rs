//! A plot as data: its axes and default view, what is drawn on it in which
//! order and by what meaning, its legend and its notes. The window draws a
//! [`Plot`] with `egui_plot` and the figures with plotters; neither decides
//! what is shown.

use std::sync::Arc;

use crate::analysis::State;

/// The map's cells, one per load and row, the first row at the bottom:
/// each its state and its colour's strength in [0, 1], `None` where the
/// row has no analysis.
#[derive(Clone, Debug, PartialEq)]
pub struct CellGrid {
    pub columns: usize,
    pub rows: usize,
    pub cells: Vec<Option<(State, f64)>>,
    /// The growth or decay rate that takes the strongest colour, in 1/s.
    pub largest_per_s: f64,
}

/// Who looks at the plot: someone at the window, with the column moving
/// and a load to point at, or a reader of a printed figure.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Medium {
    Window,
    Paper,
}

/// What a colour stands for; each renderer gives it its theme's colour.
#[derive(Clone, Debug, PartialEq)]
pub enum Ink {
    /// The main model's curves and the text (light on the window's dark
    /// background, black on paper).
    Main,
    /// The k-th series: other models, further curves.
    Series(usize),
    /// The overlaid model, behind the current one.
    Overlay,
    State(State),
    /// The present: the current eigenvalues.
    Now,
    /// Eigenvalues measured from the run.
    Measured,
    /// The current load.
    LoadLine,
    /// An axis drawn across the plot (Re λ = 0).
    Axis,
    /// A value drawn for comparison (the undamped load).
    Reference,
    /// A stability map's cell of a state, its colour's strength in [0, 1]
    /// (the faster it grows or decays, the stronger).
    Cell(State, f64),
    /// Where there is no analysis.
    NoData,
    /// A fraction in [0, 1] of the way along a range (a branch's load
    /// from the smallest drawn to the largest), on the palette's ramp.
    Along(f64),
}

/// How heavy a line is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Weight {
    Fine,
    Regular,
    /// The k-th of curves drawn over each other, each narrower than the
    /// one before, so that curves that coincide all show.
    Layered(usize),
}

/// How large a marker is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    Small,
    Regular,
    Large,
}

/// What becomes of a marker outside the plot's view.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OffView {
    /// Left out.
    Hidden,
    /// Marked on the view's edge with its value, pointing towards it.
    EdgeMarked,
}

/// One thing drawn on a plot.
#[derive(Clone, Debug, PartialEq)]
pub enum Mark {
    /// A polyline.
    Line {
        points: Vec<[f64; 2]>,
        ink: Ink,
        weight: Weight,
        dashed: bool,
    },
    /// A polyline coloured along its samples: `along[i]` in [0, 1] is
    /// where `points[i]` lies on the palette's ramp (a root-locus branch
    /// coloured by the load). Drawn in [`graded_lines`] of one colour
    /// each, [`Ink::Along`] of the fraction at the piece's middle.
    Graded {
        points: Vec<[f64; 2]>,
        along: Vec<f64>,
        weight: Weight,
    },
    /// Markers at points.
    Markers {
        points: Vec<[f64; 2]>,
        ink: Ink,
        size: Size,
        filled: bool,
        off_view: OffView,
    },
    /// A vertical line across the plot at `x`, named (a hover shows it).
    Vertical {
        x: f64,
        name: String,
        ink: Ink,
        weight: Weight,
        dashed: bool,
    },
    /// A horizontal line across the plot at `y`.
    Horizontal {
        y: f64,
        ink: Ink,
        weight: Weight,
        dashed: bool,
    },
    /// A grid of cells covering `x` by `y`, the first row at the bottom.
    Cells {
        x: (f64, f64),
        y: (f64, f64),
        grid: Arc<CellGrid>,
    },
    /// A range of x tinted across the plot in the colour of a state.
    Range { from: f64, to: f64, state: State },
    /// The region between two curves over the same x (`lower[i][0] ==
    /// upper[i][0]`, x increasing), tinted in the colour of a state.
    Band {
        lower: Vec<[f64; 2]>,
        upper: Vec<[f64; 2]>,
        state: State,
    },
    /// A word written on the plot, centred at `at`, on a plate of the
    /// background so that it reads over cells and lines; `of`, the point
    /// it names (a ringed bifurcation beside it), which is what a screen
    /// reader is told.
    Label {
        at: [f64; 2],
        text: String,
        of: Option<[f64; 2]>,
    },
}

/// How a plot's default view is set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum View {
    /// These ranges of x and y.
    Ranges { x: (f64, f64), y: (f64, f64) },
    /// Equal scales on both axes, centred on the origin, holding `extent`
    /// = (half width, half height) whatever the plot's shape
    /// ([`super::view::default_view`]).
    Equal { extent: (f64, f64) },
}

/// How the x axis's ticks read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ticks {
    /// The values themselves.
    Plain,
    /// The axis holds log10 of the quantity: ticks at decades, written as
    /// the quantity (0.01, 1, 100).
    Decades,
}

/// How a legend entry is drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum Swatch {
    Line(Ink),
    Dashed(Ink),
    /// A marker, filled or a ring.
    Marker(Ink, bool),
    /// A tinted range.
    Fill(State),
    /// A colour scale, from one end to the other.
    Scale(Vec<Ink>),
}

/// One entry of a legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    pub swatch: Swatch,
    pub text: String,
}

impl Entry {
    #[must_use]
    pub fn new(swatch: Swatch, text: impl Into<String>) -> Self {
        Self {
            swatch,
            text: text.into(),
        }
    }
}

/// One plot: its axes' words, its default view and what is drawn on it,
/// in drawing order.
#[derive(Clone, Debug, PartialEq)]
pub struct Plot {
    /// egui's id of the plot (the window keeps its view under it).
    pub id: &'static str,
    pub x_label: String,
    pub y_label: String,
    pub x_ticks: Ticks,
    pub view: View,
    pub marks: Vec<Mark>,
    /// What lies left of the view when it does: a figure says so beside
    /// it (the window marks the present on the edge instead).
    pub far_left: Vec<FarLeft>,
}

/// Data reaching left to `x`, and what to say when that is left of the view.
#[derive(Clone, Debug, PartialEq)]
pub struct FarLeft {
    pub x: f64,
    pub note: String,
}

/// What one view of a plot kind shows, in either medium: its legend and
/// its plots. Every builder of [`super`] returns one; the window and the
/// figures draw it as it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    pub legend: Vec<Entry>,
    pub plots: Vec<Plot>,
}

/// How many pieces of one colour a [`Mark::Graded`] line has at most.
pub const GRADED_PIECES: usize = 24;

/// The pieces of a [`Mark::Graded`] line through `drawn` (its samples
/// where they are drawn, in pixels or any unit of length), as ranges
/// `(first, last)` of sample indices, each piece's last the next one's
/// first. [`GRADED_PIECES`] pieces of equal counts of samples, and then
/// neighbours joined until each is at least `shortest` long: a piece
/// shorter than its line is wide shows no colour of its own, and each
/// piece costs a CPU renderer a dozen triangles. A line shorter than
/// `shortest` is one piece.
#[must_use]
pub fn graded_pieces(drawn: &[[f64; 2]], shortest: f64) -> Vec<(usize, usize)> {
    let last = drawn.len().saturating_sub(1);
    let length = |first: usize, end: usize| -> f64 {
        drawn[first..=end]
            .windows(2)
            .map(|pair| (pair[1][0] - pair[0][0]).hypot(pair[1][1] - pair[0][1]))
            .sum()
    };
    let mut pieces: Vec<(usize, usize)> = Vec::new();
    let mut first = 0;
    for piece in 0..GRADED_PIECES {
        let end = ((piece + 1) * last / GRADED_PIECES).min(last);
        if end > first && length(first, end) >= shortest {
            pieces.push((first, end));
            first = end;
        }
    }
    // What is left is too short for a piece of its own: the last piece
    // takes it (or it is the whole line).
    match pieces.last_mut() {
        Some(piece) if first < last => piece.1 = last,
        None if last > 0 => pieces.push((0, last)),
        _ => {}
    }
    pieces
}

/// A [`Mark::Graded`] line's pieces (see [`graded_pieces`], `drawn` its
/// samples where they are drawn) as their points and their ink: the ramp
/// at the fraction halfway between the piece's ends.
pub fn graded_lines<'a>(
    points: &'a [[f64; 2]],
    along: &'a [f64],
    drawn: &[[f64; 2]],
    shortest: f64,
) -> impl Iterator<Item = (&'a [[f64; 2]], Ink)> {
    graded_pieces(drawn, shortest)
        .into_iter()
        .filter_map(move |(first, last)| {
            let (from, to) = (along.get(first)?, along.get(last)?);
            Some((points.get(first..=last)?, Ink::Along(0.5 * (from + to))))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `n` samples evenly along x from 0 to `length`.
    fn straight(n: u32, length: f64) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| [length * f64::from(i) / f64::from(n - 1), 0.0])
            .collect()
    }

    #[test]
    fn a_long_line_has_every_piece_in_equal_counts_of_samples() {
        let pieces = graded_pieces(&straight(241, 2400.0), 4.0);
        assert_eq!(pieces.len(), GRADED_PIECES);
        assert!(pieces.iter().all(|&(a, b)| b - a == 10), "{pieces:?}");
        assert!(pieces.windows(2).all(|w| w[0].1 == w[1].0));
        assert_eq!((pieces[0].0, pieces[GRADED_PIECES - 1].1), (0, 240));
    }

    #[test]
    fn short_pieces_join_their_neighbours_until_long_enough() {
        // 24 pieces of 1.5 each: joined in threes (4.5 >= 4), 8 pieces.
        let pieces = graded_pieces(&straight(241, 36.0), 4.0);
        assert_eq!(pieces.len(), 8, "{pieces:?}");
        assert!(pieces.iter().all(|&(a, b)| b - a == 30), "{pieces:?}");
        // Still covering the whole line, end to end.
        assert!(pieces.windows(2).all(|w| w[0].1 == w[1].0));
        assert_eq!((pieces[0].0, pieces[7].1), (0, 240));
        // 24 pieces of 25/24 each: joined in fours, nothing left over.
        assert_eq!(graded_pieces(&straight(241, 25.0), 4.0).len(), 6);
        // 24 of 0.9: five make 4.5, four pieces of five, the last four
        // (3.6) join the fourth.
        let odd = graded_pieces(&straight(241, 21.6), 4.0);
        assert_eq!(odd.len(), 4, "{odd:?}");
        assert_eq!(odd[3], (150, 240));
    }

    #[test]
    fn a_line_shorter_than_a_piece_is_one_piece_and_a_point_none() {
        assert_eq!(graded_pieces(&straight(50, 1.0), 4.0), vec![(0, 49)]);
        // A root that does not move with the load: one piece, its colour
        // the middle load's.
        assert_eq!(graded_pieces(&[[1.0, 2.0]; 30], 4.0), vec![(0, 29)]);
        assert_eq!(graded_pieces(&[[1.0, 2.0]], 4.0), Vec::new());
        assert_eq!(graded_pieces(&[], 4.0), Vec::new());
    }

    #[test]
    fn with_no_shortest_the_pieces_are_the_equal_ones_even_when_still() {
        let still = graded_pieces(&[[0.0, 0.0]; 49], 0.0);
        assert_eq!(still.len(), GRADED_PIECES);
        assert!(still.iter().all(|&(a, b)| b - a == 2));
        // Fewer samples than pieces: one piece a segment.
        assert_eq!(graded_pieces(&straight(5, 1.0), 0.0).len(), 4);
    }
}
