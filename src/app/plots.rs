//! The live plots: the root locus in the complex plane, and Re, Im of the
//! eigenvalues against the load with the current load and the stability
//! ranges marked (the paper's Figs 3 and 8).

use eframe::egui::{self, vec2};
use egui_plot::{Line, MarkerShape, Plot, PlotPoint, PlotPoints, Points, Span, Text, VLine};

use super::history::History;
use super::locus_view::{
    EdgeMark, Side, ViewRect, deciding_extent, default_view, edge_marks, versus_load_extent,
};
use super::plot_frame::{Swatch, axes, curve, legend_row, refit_if, view_settled};
use super::state::Overlay;
use super::theme::{Theme, load_color};
use crate::analysis::{C64, Locus, State};

/// Branch segments are drawn in this many colour bands along the load.
const COLOR_BANDS: usize = 24;

/// Evenly spaced samples the plots draw at most (a plot is a few hundred
/// pixels wide); the refinement's samples are all drawn.
const DRAWN_GRID_SAMPLES: usize = 300;

/// Evenly spaced samples of all branches together a plot draws at most: a
/// long chain's many branches get fewer samples each (64 rods: 78), so a
/// frame stays within its time.
const DRAWN_GRID_POINTS: usize = 10_000;

/// The indices of the locus samples a plot draws: every k-th evenly spaced
/// one, so that at most [`DRAWN_GRID_SAMPLES`] are (and at most
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

/// The root locus: every branch as a curve coloured by load, the current
/// eigenvalues as large markers, the imaginary axis emphasised.
pub fn root_locus_ui(
    ui: &mut egui::Ui,
    locus: &Locus,
    overlay: Option<&Overlay>,
    current: &[C64],
    measured: Option<&[C64]>,
    refit: bool,
    theme: &Theme,
) {
    let (min, max) = (
        locus.loads.first().copied().unwrap_or(0.0),
        locus.loads.last().copied().unwrap_or(1.0),
    );
    // The eigenvalues that decide stability, the overlay's too, in equal
    // scales: egui_plot keeps the x range and sets the y range from the
    // plot's shape, so the shape is estimated here (the axes and their
    // labels take about 60 x 40 points).
    let size = ui.available_size();
    let shape = (f64::from(size.x) - 60.0).max(1.0) / (f64::from(size.y) - 40.0).max(1.0);
    let mut extents = vec![deciding_extent(locus)];
    extents.extend(overlay.map(|other| deciding_extent(&other.locus)));
    let (half_width, half_height) = default_view(&extents, shape);
    let plot = Plot::new("root locus")
        .data_aspect(1.0)
        .default_x_bounds(-half_width, half_width)
        .default_y_bounds(-half_height, half_height);
    refit_if(axes(plot, "Re λ (1/s)", "Im λ (rad/s)"), refit).show(ui, |plot_ui| {
        let settled = view_settled(plot_ui, refit);
        plot_ui.vline(
            VLine::new("", 0.0)
                .color(theme.axis)
                .width(2.0 * theme.stroke_scale),
        );
        if let Some(other) = overlay {
            for branch in &other.locus.branches {
                let points = branch.iter().map(|z| [z.re, z.im]);
                plot_ui.line(
                    curve(plot_ui, settled, points)
                        .color(theme.overlay)
                        .width(1.5 * theme.stroke_scale),
                );
            }
        }
        let shown = drawn_samples(locus);
        let n = shown.len();
        for branch in &locus.branches {
            for band in 0..COLOR_BANDS {
                let (k0, k1) = (
                    band * (n - 1) / COLOR_BANDS,
                    ((band + 1) * (n - 1) / COLOR_BANDS).min(n - 1),
                );
                if k1 <= k0 {
                    continue;
                }
                let (i0, i1) = (shown[k0], shown[k1]);
                let points = shown[k0..=k1].iter().map(|&i| [branch[i].re, branch[i].im]);
                let mid = 0.5 * (locus.loads[i0] + locus.loads[i1]);
                plot_ui.line(
                    curve(plot_ui, settled, points)
                        .color(load_color(mid, min, max))
                        .width(2.0 * theme.stroke_scale),
                );
            }
        }
        let now: PlotPoints<'_> = current.iter().map(|z| [z.re, z.im]).collect();
        plot_ui.points(
            Points::new("", now)
                .radius(6.0 * theme.stroke_scale)
                .color(theme.now)
                .filled(true),
        );
        if let Some(measured) = measured {
            let points: PlotPoints<'_> = measured.iter().map(|z| [z.re, z.im]).collect();
            plot_ui.points(
                Points::new("", points)
                    .radius(9.0 * theme.stroke_scale)
                    .color(theme.measured)
                    .filled(false),
            );
        }
        let bounds = plot_ui.plot_bounds();
        let view = ViewRect {
            re: (bounds.min()[0], bounds.max()[0]),
            im: (bounds.min()[1], bounds.max()[1]),
        };
        let marks = edge_marks(current, view, EDGE_INSET);
        edge_marks_ui(plot_ui, &marks, theme);
        plot_ui.ctx().data_mut(|data| {
            data.insert_temp(egui::Id::unique(LOCUS_SHOWN_ID), LocusShown { view, marks })
        });
    });
}

/// How far inside the view an edge mark is drawn, as a fraction of its size.
const EDGE_INSET: f64 = 0.03;

/// The egui memory key of what the root locus showed last ([`LocusShown`]).
pub const LOCUS_SHOWN_ID: &str = "root locus shown";

/// What the root locus drew in its last frame: the view and the marks of the
/// eigenvalues outside it (kept in egui's memory for tests to read).
#[derive(Clone, Debug, PartialEq)]
pub struct LocusShown {
    pub view: ViewRect,
    pub marks: Vec<EdgeMark>,
}

/// Each eigenvalue outside the view as an arrow on the edge towards it,
/// with its value beside it.
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

/// Re(lambda) or Im(lambda) >= 0 of every branch against the load, with
/// the stability ranges shaded and a cursor at the current load. Of Im,
/// the upper half only, as the figures draw it: the lower is its mirror
/// image (conjugate pairs), and a chain's 32 branches in both halves were
/// a blur with one tick.
#[expect(clippy::too_many_arguments, reason = "one plot's inputs")]
pub fn versus_load_ui(
    ui: &mut egui::Ui,
    locus: &Locus,
    overlay: Option<&Overlay>,
    ranges: &[(f64, f64, State)],
    load: f64,
    imaginary: bool,
    refit: bool,
    theme: &Theme,
) {
    let label = if imaginary {
        "Im λ (rad/s)"
    } else {
        "Re λ (1/s)"
    };
    let extent = versus_load_extent(
        overlay.map(|o| &o.locus).into_iter().chain([locus]),
        imaginary,
    );
    let (min, max) = (
        locus.loads.first().copied().unwrap_or(0.0),
        locus.loads.last().copied().unwrap_or(1.0),
    );
    // The locus's range, also when the load is beyond it.
    let lowest = if imaginary {
        -0.05 * extent
    } else {
        -1.1 * extent
    };
    let plot = Plot::new(label)
        .default_x_bounds(min, max)
        .default_y_bounds(lowest, 1.1 * extent);
    refit_if(axes(plot, "p = P l/k", label), refit).show(ui, |plot_ui| {
        let settled = view_settled(plot_ui, refit);
        for &(start, end, state) in ranges {
            let color = theme.state_color(state).gamma_multiply(0.18);
            plot_ui.span(Span::new(state.name(), start..=end).fill(color));
        }
        // The overlay behind, the current model in front.
        let layers = overlay
            .map(|o| (&o.locus, theme.overlay))
            .into_iter()
            .chain([(locus, theme.text)]);
        for (shown, color) in layers {
            let samples = drawn_samples(shown);
            for branch in &shown.branches {
                if imaginary && branch.iter().all(|z| z.im < 0.0) {
                    continue;
                }
                let points = samples.iter().map(|&i| {
                    let z = branch[i];
                    [shown.loads[i], if imaginary { z.im } else { z.re }]
                });
                plot_ui.line(
                    curve(plot_ui, settled, points)
                        .color(color)
                        .width(1.5 * theme.stroke_scale),
                );
            }
        }
        plot_ui.vline(
            VLine::new("load", load)
                .color(theme.load_line)
                .width(2.0 * theme.stroke_scale),
        );
    });
}

/// The run's recent past: the angles and delta against time, the energies,
/// and a phase portrait of rod 2.
/// The band's angle and power only where there is a band (`band`).
pub fn histories_ui(ui: &mut egui::Ui, history: &History, band: bool, refit: bool, theme: &Theme) {
    let samples: Vec<_> = history.thinned(1500).collect();
    let series = |f: &dyn Fn(&crate::sim::Observables) -> f64| -> PlotPoints<'_> {
        samples.iter().map(|o| [o.t_secs, f(o)]).collect()
    };
    let (width, height) = (ui.available_width(), ui.available_height());
    ui.horizontal(|ui| {
        ui.vertical(|ui| {
            ui.allocate_ui(vec2(0.62 * width, 0.5 * height - 4.0), |ui| {
                let mut legend = vec![
                    (Swatch::Line(theme.series[0]), "φ1".to_owned()),
                    (Swatch::Line(theme.series[1]), "φ2".to_owned()),
                ];
                if band {
                    legend.push((
                        Swatch::Line(theme.series[2]),
                        "δ: the band force's angle from rod 2".to_owned(),
                    ));
                }
                legend_row(ui, &legend);
                // Symmetric about 0 and as high as a labelled grid step.
                let widest = samples
                    .iter()
                    .flat_map(|o| [o.phi1_rad, o.phi2_rad, if band { o.delta_rad } else { 0.0 }])
                    .map(f64::abs)
                    .filter(|a| a.is_finite())
                    .fold(0.0, f64::max);
                let half = crate::app::plot_frame::grid_ceil(widest);
                let plot = Plot::new("angles").include_y(-half).include_y(half);
                refit_if(axes(plot, "t (s)", "rad"), refit).show(ui, |plot_ui| {
                    plot_ui.line(Line::new("φ1", series(&|o| o.phi1_rad)).color(theme.series[0]));
                    plot_ui.line(Line::new("φ2", series(&|o| o.phi2_rad)).color(theme.series[1]));
                    if band {
                        plot_ui
                            .line(Line::new("δ", series(&|o| o.delta_rad)).color(theme.series[2]));
                    }
                });
            });
            ui.allocate_ui(vec2(0.62 * width, 0.5 * height - 4.0), |ui| {
                let mut legend = vec![(
                    Swatch::Line(theme.series[3]),
                    "kinetic + spring energy".to_owned(),
                )];
                if band {
                    legend.push((
                        Swatch::Line(theme.series[4]),
                        "power from the band".to_owned(),
                    ));
                }
                legend_row(ui, &legend);
                let plot = Plot::new("energy");
                let units = if band { "J, W" } else { "J" };
                refit_if(axes(plot, "t (s)", units), refit).show(ui, |plot_ui| {
                    plot_ui.line(
                        Line::new("kinetic + spring energy", series(&|o| o.energy_j()))
                            .color(theme.series[3]),
                    );
                    if band {
                        plot_ui.line(
                            Line::new("power from the band", series(&|o| o.band_power_w))
                                .color(theme.series[4]),
                        );
                    }
                });
            });
        });
        ui.allocate_ui(vec2(ui.available_width(), height), |ui| {
            let plot = Plot::new("phase portrait");
            refit_if(axes(plot, "φ2 (rad)", "φ2' (rad/s)"), refit).show(ui, |plot_ui| {
                let points: PlotPoints<'_> = samples
                    .iter()
                    .map(|o| [o.phi2_rad, o.phi2_dot_rad_per_s])
                    .collect();
                plot_ui.line(Line::new("rod 2", points).color(theme.series[5]));
            });
        });
    });
}
