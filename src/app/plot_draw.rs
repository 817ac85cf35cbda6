//! Draws a plot's description ([`crate::plot::spec`]) in the window with
//! `egui_plot`, in the theme's colours: the window's one renderer of plots.

use eframe::egui::{self, Color32};
use egui_plot::{LineStyle, MarkerShape, Plot as EguiPlot, PlotPoint, Points, Span, Text, VLine};

use super::plot_frame::{Swatch as RowSwatch, axes, curve, legend_row, refit_if, view_settled};
use super::theme::{Theme, color};
use crate::analysis::{C64, State};
use crate::plot::spec::{Entry, Ink, Mark, OffView, Plot, Size, Swatch, View, Weight};
use crate::plot::view::{EdgeMark, Side, ViewRect, default_view, edge_marks};

/// How far inside the view an edge mark is drawn, as a fraction of its size.
const EDGE_INSET: f64 = 0.03;

/// The egui memory key of what the root locus showed last ([`LocusShown`]).
pub const LOCUS_SHOWN_ID: &str = "root locus shown";

/// What a plot with edge-marked markers (the root locus) drew in its last
/// frame: the view and the marks of the markers outside it (kept in egui's
/// memory for tests to read).
#[derive(Clone, Debug, PartialEq)]
pub struct LocusShown {
    pub view: ViewRect,
    pub marks: Vec<EdgeMark>,
}

/// `ink` in `theme`'s colours.
fn ink_color(ink: &Ink, theme: &Theme) -> Color32 {
    match ink {
        Ink::Main => theme.text,
        Ink::Series(k) => theme.series[k % theme.series.len()],
        Ink::Overlay => theme.overlay,
        Ink::State(state) => theme.state_color(*state),
        Ink::Now => theme.now,
        Ink::Measured => theme.measured,
        Ink::LoadLine => theme.load_line,
        Ink::Axis => theme.axis,
        Ink::Rgb(rgb) => color(*rgb),
    }
}

/// A line's width in points.
fn width(weight: Weight, theme: &Theme) -> f32 {
    theme.stroke_scale
        * match weight {
            Weight::Fine => 1.5,
            Weight::Regular => 2.0,
        }
}

/// A marker's radius in points.
fn radius(size: Size, theme: &Theme) -> f32 {
    theme.stroke_scale
        * match size {
            Size::Small => 4.0,
            Size::Regular => 6.0,
            Size::Large => 9.0,
        }
}

/// The tint of a state's range.
fn range_tint(state: State, theme: &Theme) -> Color32 {
    theme.state_color(state).gamma_multiply(0.18)
}

/// A legend as a row of text above the plots.
pub fn legend_ui(ui: &mut egui::Ui, entries: &[Entry], theme: &Theme) {
    let rows: Vec<(RowSwatch, String)> = entries
        .iter()
        .map(|entry| {
            let swatch = match &entry.swatch {
                Swatch::Line(ink) => RowSwatch::Line(ink_color(ink, theme)),
                Swatch::Dashed(ink) => RowSwatch::Dashed(ink_color(ink, theme)),
                Swatch::Marker(ink, true) => RowSwatch::Dot(ink_color(ink, theme)),
                Swatch::Marker(ink, false) => RowSwatch::Ring(ink_color(ink, theme)),
                Swatch::Fill(state) => RowSwatch::Fill(range_tint(*state, theme)),
                Swatch::Scale(inks) => {
                    RowSwatch::Scale(inks.iter().map(|ink| ink_color(ink, theme)).collect())
                }
            };
            (swatch, entry.text.clone())
        })
        .collect();
    legend_row(ui, &rows);
}

/// `plot` in the space `ui` offers, its view refitted with `refit`.
pub fn plot_ui(ui: &mut egui::Ui, plot: &Plot, refit: bool, theme: &Theme) {
    let mut egui_plot = EguiPlot::new(plot.id);
    match plot.view {
        View::Ranges { x, y } => {
            egui_plot = egui_plot
                .default_x_bounds(x.0, x.1)
                .default_y_bounds(y.0, y.1);
        }
        View::Equal { extent } => {
            // egui_plot keeps the x range and sets the y range from the
            // plot's shape, so the shape is estimated here (the axes and
            // their labels take about 60 x 40 points).
            let size = ui.available_size();
            let shape = (f64::from(size.x) - 60.0).max(1.0) / (f64::from(size.y) - 40.0).max(1.0);
            let (half_width, half_height) = default_view(&[extent], shape);
            egui_plot = egui_plot
                .data_aspect(1.0)
                .default_x_bounds(-half_width, half_width)
                .default_y_bounds(-half_height, half_height);
        }
    }
    let egui_plot = refit_if(
        axes(egui_plot, plot.x_label.as_str(), plot.y_label.as_str()),
        refit,
    );
    egui_plot.show(ui, |plot_ui| {
        let settled = view_settled(plot_ui, refit);
        let mut edge_marked = Vec::new();
        for mark in &plot.marks {
            match mark {
                Mark::Line {
                    points,
                    ink,
                    weight,
                    dashed,
                } => {
                    let line = curve(plot_ui, settled, points.iter().copied())
                        .color(ink_color(ink, theme))
                        .width(width(*weight, theme));
                    plot_ui.line(if *dashed {
                        line.style(LineStyle::dashed_loose())
                    } else {
                        line
                    });
                }
                Mark::Markers {
                    points,
                    ink,
                    size,
                    filled,
                    off_view,
                } => {
                    plot_ui.points(
                        Points::new("", points.clone())
                            .radius(radius(*size, theme))
                            .color(ink_color(ink, theme))
                            .filled(*filled),
                    );
                    if *off_view == OffView::EdgeMarked {
                        edge_marked.extend(points.iter().map(|p| C64::new(p[0], p[1])));
                    }
                }
                Mark::Vertical {
                    x,
                    name,
                    ink,
                    weight,
                    dashed,
                } => {
                    let line = VLine::new(name.as_str(), *x)
                        .color(ink_color(ink, theme))
                        .width(width(*weight, theme));
                    plot_ui.vline(if *dashed {
                        line.style(LineStyle::dashed_loose())
                    } else {
                        line
                    });
                }
                Mark::Range { from, to, state } => {
                    plot_ui
                        .span(Span::new(state.name(), *from..=*to).fill(range_tint(*state, theme)));
                }
            }
        }
        if edge_marked.is_empty() {
            return;
        }
        let bounds = plot_ui.plot_bounds();
        let view = ViewRect {
            re: (bounds.min()[0], bounds.max()[0]),
            im: (bounds.min()[1], bounds.max()[1]),
        };
        let marks = edge_marks(&edge_marked, view, EDGE_INSET);
        edge_marks_ui(plot_ui, &marks, theme);
        plot_ui.ctx().data_mut(|data| {
            data.insert_temp(egui::Id::unique(LOCUS_SHOWN_ID), LocusShown { view, marks });
        });
    });
}

/// Each marker outside the view as an arrow on the edge towards it, with
/// its value beside it.
fn edge_marks_ui(plot_ui: &mut egui_plot::PlotUi<'_>, marks: &[EdgeMark], theme: &Theme) {
    for mark in marks {
        let (shape, anchor) = match mark.side {
            Side::Left => (MarkerShape::Left, egui::Align2::LEFT_BOTTOM),
            Side::Right => (MarkerShape::Right, egui::Align2::RIGHT_BOTTOM),
            Side::Up => (MarkerShape::Up, egui::Align2::LEFT_TOP),
            Side::Down => (MarkerShape::Down, egui::Align2::LEFT_BOTTOM),
        };
        plot_ui.points(
            Points::new("", vec![[mark.at.re, mark.at.im]])
                .shape(shape)
                .radius(7.0 * theme.stroke_scale)
                .color(theme.now)
                .filled(true),
        );
        plot_ui.text(
            Text::new(
                "",
                PlotPoint::new(mark.at.re, mark.at.im),
                egui::RichText::new(format!("    {}    ", mark.label)).strong(),
            )
            .color(theme.now)
            .anchor(anchor),
        );
    }
}
