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
    /// background so that it reads over cells and lines.
    Label { at: [f64; 2], text: String },
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
