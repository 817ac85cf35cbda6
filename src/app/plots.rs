//! The time histories: the angles and delta against time, the energies,
//! and a phase portrait of rod 2.

use super::speak::Speak as _;
use crate::tr;
use eframe::egui::{self, vec2};
use egui_plot::{Line, Plot, PlotPoints};

use super::history::History;
use super::legend::{Swatch, legend_row};
use super::plot_frame::{axes, refit_if, show_framed};
use super::theme::{Theme, color};

/// The run's recent past: the angles and delta against time, the energies,
/// and a phase portrait of rod 2.
/// The band's angle and power only where there is a band (`band`).
pub fn histories_ui(ui: &mut egui::Ui, history: &History, band: bool, refit: bool, theme: &Theme) {
    let samples: Vec<_> = history.thinned(1500).collect();
    let series = |f: &dyn Fn(&crate::sim::Observables) -> f64| -> PlotPoints<'_> {
        samples.iter().map(|o| [o.t_secs, f(o)]).collect()
    };
    let (width, height) = (ui.available_width(), ui.available_height());
    let words = ui.words();
    let energy = tr!(words, "histories-energy");
    let power = tr!(words, "histories-band-power");
    ui.horizontal(|ui| {
        ui.vertical(|ui| {
            ui.allocate_ui(vec2(0.62 * width, 0.5 * height - 4.0), |ui| {
                let mut legend = vec![
                    (
                        Swatch::Line(color(theme.palette.series[0])),
                        "φ1".to_owned(),
                    ),
                    (
                        Swatch::Line(color(theme.palette.series[1])),
                        "φ2".to_owned(),
                    ),
                ];
                if band {
                    legend.push((
                        Swatch::Line(color(theme.palette.series[2])),
                        tr!(words, "histories-delta"),
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
                show_framed(refit_if(axes(plot, "t (s)", "rad"), refit), ui, |plot_ui| {
                    plot_ui.line(
                        Line::new("φ1", series(&|o| o.phi1_rad))
                            .color(color(theme.palette.series[0])),
                    );
                    plot_ui.line(
                        Line::new("φ2", series(&|o| o.phi2_rad))
                            .color(color(theme.palette.series[1])),
                    );
                    if band {
                        plot_ui.line(
                            Line::new("δ", series(&|o| o.delta_rad))
                                .color(color(theme.palette.series[2])),
                        );
                    }
                });
            });
            ui.allocate_ui(vec2(0.62 * width, 0.5 * height - 4.0), |ui| {
                let mut legend =
                    vec![(Swatch::Line(color(theme.palette.series[3])), energy.clone())];
                if band {
                    legend.push((Swatch::Line(color(theme.palette.series[4])), power.clone()));
                }
                legend_row(ui, &legend);
                let plot = Plot::new("energy");
                let units = if band { "J, W" } else { "J" };
                show_framed(refit_if(axes(plot, "t (s)", units), refit), ui, |plot_ui| {
                    plot_ui.line(
                        Line::new(energy.as_str(), series(&|o| o.energy_j()))
                            .color(color(theme.palette.series[3])),
                    );
                    if band {
                        plot_ui.line(
                            Line::new(power.as_str(), series(&|o| o.band_power_w))
                                .color(color(theme.palette.series[4])),
                        );
                    }
                });
            });
        });
        ui.allocate_ui(vec2(ui.available_width(), height), |ui| {
            let plot = Plot::new("phase portrait");
            show_framed(
                refit_if(axes(plot, "φ2 (rad)", "φ2' (rad/s)"), refit),
                ui,
                |plot_ui| {
                    let points: PlotPoints<'_> = samples
                        .iter()
                        .map(|o| [o.phi2_rad, o.phi2_dot_rad_per_s])
                        .collect();
                    plot_ui.line(
                        Line::new(tr!(words, "histories-rod-2"), points)
                            .color(color(theme.palette.series[5])),
                    );
                },
            );
        });
    });
}
