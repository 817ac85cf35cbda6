//! Draws a plot's description ([`crate::plot::spec`]) in the window with
//! `egui_plot`, in the theme's colours: the window's one renderer of plots.

use super::speak::Speak as _;
use crate::i18n::state_name;
use crate::tr;
use std::sync::Arc;

use eframe::egui::{self, Color32};
use egui_plot::{
    HLine, LineStyle, MarkerShape, Plot as EguiPlot, PlotImage, PlotPoint, PlotPoints,
    PlotResponse, Points, Polygon, Span, Text, VLine, log_grid_spacer,
};

use super::legend::{Swatch as RowSwatch, legend_row};
use super::plot_frame::{axes, curve, refit_if, show_framed, view_settled};
use super::plot_keys;
use super::theme::{Theme, color};
use crate::analysis::{C64, State};
use crate::format::number_text;
use crate::plot::describe::describe;
use crate::plot::pattern;
use crate::plot::spec::CellGrid;
use crate::plot::spec::{
    Entry, Ink, Mark, OffView, Plot, Size, Swatch, Ticks, View, Weight, graded_lines,
};
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
    color(theme.palette.ink(ink))
}

/// A line's width in points.
fn width(weight: Weight, theme: &Theme) -> f32 {
    theme.stroke_scale
        * match weight {
            Weight::Fine => 1.5,
            Weight::Regular => 2.0,
            Weight::Layered(k) => [3.5, 2.2, 1.2][k.min(2)],
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
    #[expect(clippy::cast_possible_truncation, reason = "a share in [0, 1]")]
    theme
        .state_color(state)
        .gamma_multiply(crate::plot::palette::Palette::RANGE_TINT as f32)
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

/// `plot` in the space `ui` offers, its view refitted with `refit`. The
/// plot's response comes back with where the pointer is on it.
pub fn plot_ui(
    ui: &mut egui::Ui,
    plot: &Plot,
    refit: bool,
    theme: &Theme,
) -> PlotResponse<Option<PlotPoint>> {
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
    let mut egui_plot = axes(egui_plot, plot.x_label.as_str(), plot.y_label.as_str());
    if plot.x_ticks == Ticks::Decades {
        // Decades on the log axis, not 1-2-5 steps of the exponent.
        egui_plot = egui_plot
            .x_grid_spacer(log_grid_spacer(10))
            .x_axis_formatter(|mark, _| number_text(10f64.powf(mark.value)));
    }
    let egui_plot = refit_if(egui_plot, refit);
    let shown = show_framed(egui_plot, ui, |plot_ui| {
        let keyed = plot_keys::keys_ui(plot_ui, theme);
        let settled = view_settled(plot_ui, refit);
        let zoom = view_zoom(plot.view, &plot_ui.plot_bounds());
        let mut edge_marked = Vec::new();
        for mark in &plot.marks {
            if let Some(points) = mark_ui(plot_ui, (plot.id, zoom), mark, settled, theme) {
                edge_marked.extend(points.iter().map(|p| C64::new(p[0], p[1])));
            }
        }
        // Enter on a focused plot picks its centre, where the pointer is not.
        let pointer = keyed.or_else(|| plot_ui.pointer_coordinate());
        if edge_marked.is_empty() {
            return pointer;
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
        pointer
    });
    if shown.response.has_focus() {
        ui.painter().rect_stroke(
            shown.response.rect,
            2.0,
            theme.focus_stroke(),
            egui::StrokeKind::Outside,
        );
    }
    // A screen reader's name and description of the plot.
    // (The words first: the node's builder holds the context.)
    let words = ui.words();
    let name = tr!(
        words,
        "plot-name",
        y = plot.y_label.clone(),
        x = plot.x_label.clone()
    );
    let description = describe(plot, words);
    shown
        .response
        .widget_info(|| egui::WidgetInfo::labeled(egui::Role::Image, true, &name));
    ui.ctx().accesskit_node_builder(shown.response.id, |node| {
        node.set_description(description);
    });
    shown
}

/// How many times the default view's extent the view shows, along x and
/// y (1 at the default view, 2 zoomed out twofold); 1 for a view of equal
/// scales, whose default extent follows the plot's shape.
fn view_zoom(view: View, bounds: &egui_plot::PlotBounds) -> [f64; 2] {
    match view {
        View::Ranges { x, y } => {
            let ratio = |shown: f64, default: f64| {
                let zoom = shown / default;
                if zoom.is_finite() && zoom > 0.0 {
                    zoom
                } else {
                    1.0
                }
            };
            [
                ratio(bounds.width(), x.1 - x.0),
                ratio(bounds.height(), y.1 - y.0),
            ]
        }
        View::Equal { .. } => [1.0, 1.0],
    }
}

/// Where a name set at `at` beside the point `of` it names is drawn in a
/// view zoomed by `zoom` (see [`view_zoom`]): its offset from the point
/// scaled with the view, so that on the screen the name keeps its place
/// beside its ring however far the view is zoomed; at `at` itself in the
/// default view.
fn label_at(at: [f64; 2], of: Option<[f64; 2]>, zoom: [f64; 2]) -> [f64; 2] {
    match of {
        Some(of) if zoom != [1.0, 1.0] => [
            of[0] + (at[0] - of[0]) * zoom[0],
            of[1] + (at[1] - of[1]) * zoom[1],
        ],
        _ => at,
    }
}

/// Draws one mark (in the plot `plot_id`, its view zoomed by `zoom`, see
/// [`view_zoom`]); the points of markers to mark on the view's edge when
/// off it come back.
fn mark_ui<'a>(
    plot_ui: &mut egui_plot::PlotUi<'_>,
    (plot_id, zoom): (&str, [f64; 2]),
    mark: &'a Mark,
    settled: bool,
    theme: &Theme,
) -> Option<&'a [[f64; 2]]> {
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
        Mark::Graded {
            points,
            along,
            weight,
        } => graded_ui(
            plot_ui,
            settled,
            points,
            along,
            width(*weight, theme),
            theme,
        ),
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
                return Some(points);
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
        Mark::Horizontal {
            y,
            ink,
            weight,
            dashed,
        } => {
            let line = HLine::new("", *y)
                .color(ink_color(ink, theme))
                .width(width(*weight, theme));
            plot_ui.hline(if *dashed {
                line.style(LineStyle::dashed_loose())
            } else {
                line
            });
        }
        Mark::Cells { x, y, grid } => cells_ui(plot_ui, plot_id, (*x, *y), grid, theme),
        Mark::Range { from, to, state } => {
            let name = state_name(plot_ui.ctx().words(), *state);
            plot_ui.span(Span::new(name, *from..=*to).fill(range_tint(*state, theme)));
        }
        Mark::Band {
            lower,
            upper,
            state,
        } => band_ui(plot_ui, lower, upper, *state, theme),
        Mark::Label { at, text, of } => {
            let at = label_at(*at, *of, zoom);
            // Spaces pad the plate on both sides of the word.
            let word = egui::RichText::new(format!(" {text} "))
                .size(theme.text_size)
                .color(color(theme.palette.text))
                .background_color(color(theme.palette.background).gamma_multiply(0.85));
            plot_ui.text(
                Text::new("", PlotPoint::new(at[0], at[1]), word)
                    .id(("label", text))
                    .allow_hover(false),
            );
        }
    }
    None
}

/// The region between `lower` and `upper` tinted in `state`'s colour:
/// one trapezoid per step in x (egui fills convex shapes only).
fn band_ui(
    plot_ui: &mut egui_plot::PlotUi<'_>,
    lower: &[[f64; 2]],
    upper: &[[f64; 2]],
    state: State,
    theme: &Theme,
) {
    let name = state_name(plot_ui.ctx().words(), state);
    let fill = range_tint(state, theme);
    for (i, (l, u)) in lower.windows(2).zip(upper.windows(2)).enumerate() {
        let corners = vec![l[0], l[1], u[1], u[0]];
        plot_ui.polygon(
            Polygon::new(name.clone(), PlotPoints::from(corners))
                .id(("band", i))
                .fill_color(fill)
                .stroke(egui::Stroke::NONE)
                .allow_hover(false),
        );
    }
}

/// A line coloured along its samples, `width_pt` wide: in
/// [`graded_lines`] at least twice its width long on the screen (shorter
/// ones show no colour of their own; a 16-rod chain's 32 short branches
/// were 768 pieces, a third of the frame's triangles). While the view is
/// changing the plot's transform may be another view's: every piece is
/// drawn then.
fn graded_ui(
    plot_ui: &mut egui_plot::PlotUi<'_>,
    settled: bool,
    points: &[[f64; 2]],
    along: &[f64],
    width_pt: f32,
    theme: &Theme,
) {
    let shortest = if settled {
        2.0 * f64::from(width_pt)
    } else {
        0.0
    };
    let transform = *plot_ui.transform();
    let drawn: Vec<[f64; 2]> = points
        .iter()
        .map(|&[x, y]| {
            let at = transform.position_from_point(&PlotPoint::new(x, y));
            [f64::from(at.x), f64::from(at.y)]
        })
        .collect();
    for (piece, ink) in graded_lines(points, along, &drawn, shortest) {
        let line = curve(plot_ui, settled, piece.iter().copied())
            .color(ink_color(&ink, theme))
            .width(width_pt);
        plot_ui.line(line);
    }
}

/// `grid` as an image, each cell a square of pixels (so a map of 128 cells
/// a side is 1024 pixels), striped where the pattern says: the image's
/// first row is the top, the grid's last.
fn cell_image(grid: &CellGrid, theme: &Theme) -> egui::ColorImage {
    let columns = grid.columns.max(1);
    let scale = (1024 / columns.max(grid.rows).max(1)).clamp(1, 8);
    let (width, height) = (columns * scale, grid.rows * scale);
    let mut image = egui::ColorImage::filled([width, height], color(theme.palette.no_data));
    // The pattern in fractions of the map's extent, as on paper.
    let spacing = 1.0 / pattern::MAP_STRIPES_PER_VIEW;
    #[expect(clippy::cast_precision_loss, reason = "pixel counts")]
    let fraction = |pixel: usize, of: usize| (pixel as f64 + 0.5) / of as f64;
    let across: Vec<f64> = (0..width).map(|column| fraction(column, width)).collect();
    let stripe = color(theme.palette.background);
    for (k, cell) in grid.cells.iter().enumerate() {
        let (j, i) = (k / columns, k % columns);
        let Some((state, strength)) = *cell else {
            continue;
        };
        let fill = ink_color(&Ink::Cell(state, strength), theme);
        let columns_of_cell = i * scale..(i + 1) * scale;
        for row in (grid.rows - 1 - j) * scale..(grid.rows - j) * scale {
            let start = row * width;
            let pixels =
                &mut image.pixels[start + columns_of_cell.start..start + columns_of_cell.end];
            if pattern::striped(state) {
                let up = fraction(height - 1 - row, height);
                for (pixel, &x) in pixels.iter_mut().zip(&across[columns_of_cell.clone()]) {
                    *pixel = if pattern::on_stripe(x, up, spacing) {
                        stripe
                    } else {
                        fill
                    };
                }
            } else {
                // A cell's row of pixels in one fill: a 256-cell map is a
                // million pixels, remade as each row of cells comes in.
                pixels.fill(fill);
            }
        }
    }
    image
}

/// A grid's texture as last made, for the theme it was made in.
#[derive(Clone)]
struct CellTexture {
    grid: Arc<CellGrid>,
    theme: Theme,
    texture: egui::TextureHandle,
}

/// `grid` as an image over `x` by `y`, one pixel per cell; the texture is
/// made again only when the grid or the theme changed.
fn cells_ui(
    plot_ui: &mut egui_plot::PlotUi<'_>,
    plot_id: &str,
    (x, y): ((f64, f64), (f64, f64)),
    grid: &Arc<CellGrid>,
    theme: &Theme,
) {
    let ctx = plot_ui.ctx().clone();
    let key = egui::Id::unique((plot_id, "cells"));
    let cached = ctx
        .data(|data| data.get_temp::<CellTexture>(key))
        .filter(|c| (Arc::ptr_eq(&c.grid, grid) || c.grid == *grid) && c.theme == *theme);
    let texture = if let Some(cached) = cached {
        cached.texture
    } else {
        let image = cell_image(grid, theme);
        let texture = ctx.load_texture(plot_id, image, egui::TextureOptions::LINEAR);
        ctx.data_mut(|data| {
            data.insert_temp(
                key,
                CellTexture {
                    grid: Arc::clone(grid),
                    theme: *theme,
                    texture: texture.clone(),
                },
            );
        });
        texture
    };
    #[expect(clippy::cast_possible_truncation, reason = "plot sizes")]
    let size = [(x.1 - x.0) as f32, (y.1 - y.0) as f32];
    plot_ui.image(PlotImage::new(
        "map",
        texture.id(),
        PlotPoint::new(0.5 * (x.0 + x.1), 0.5 * (y.0 + y.1)),
        size,
    ));
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
                .color(color(theme.palette.now))
                .filled(true),
        );
        plot_ui.text(
            Text::new(
                "",
                PlotPoint::new(mark.at.re, mark.at.im),
                egui::RichText::new(format!("    {}    ", mark.label)).strong(),
            )
            .color(color(theme.palette.now))
            .anchor(anchor),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A name beside its ring keeps its place on the screen as the view
    /// zooms: its offset from the ring, in the plot's units, grows with the
    /// view's extent (twice the extent, twice the offset: the same pixels),
    /// and in the default view it is where the plot put it, to the bit. A
    /// name of no point (a map's state) and a view of equal scales are left
    /// as they are.
    #[test]
    fn a_name_keeps_its_pixels_from_its_ring_as_the_view_zooms() {
        let view = View::Ranges {
            x: (0.0, 3.3),
            y: (0.0, 2.1),
        };
        let default = egui_plot::PlotBounds::from_min_max([0.0, 0.0], [3.3, 2.1]);
        assert_eq!(view_zoom(view, &default), [1.0, 1.0]);
        let (ring, name) = ([2.130_384_928, 0.351_7], [2.130_384_928 - 0.264, 0.351_7]);
        assert_eq!(label_at(name, Some(ring), [1.0, 1.0]), name);
        let out = egui_plot::PlotBounds::from_min_max([-1.0, -0.7], [5.6, 3.5]);
        let zoom = view_zoom(view, &out);
        assert!(
            (zoom[0] - 2.0).abs() < 1e-12 && (zoom[1] - 2.0).abs() < 1e-12,
            "{zoom:?}"
        );
        let drawn = label_at(name, Some(ring), zoom);
        assert!(
            (drawn[0] - (ring[0] - 2.0 * 0.264)).abs() < 1e-12,
            "{drawn:?}"
        );
        assert!((drawn[1] - ring[1]).abs() < 1e-12, "{drawn:?}");
        assert_eq!(label_at(name, None, zoom), name);
        let equal = View::Equal { extent: (1.0, 1.0) };
        assert_eq!(view_zoom(equal, &out), [1.0, 1.0]);
        let flat = egui_plot::PlotBounds::from_min_max([0.0, 1.0], [0.0, 1.0]);
        assert_eq!(view_zoom(view, &flat), [1.0, 1.0]);
    }
}
