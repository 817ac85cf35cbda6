//! The Ziegler paradox explorer: the load at which the column first loses
//! stability as the damping vanishes (joint dampers of a given ratio, or
//! external drag and equal joint dampers in a given ratio; the roller's mass
//! at several band speeds), next to the undamped value, computed off the UI
//! thread.

use eframe::egui;
use egui_plot::{Corner, HLine, Legend, Line, Plot, PlotPoints, Points, log_grid_spacer};

use super::{TabSpec, TabView, save_buttons};
use crate::analysis::{Curves, DampingKind, own_point, paradox_curves};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::jobs::Jobs;
use crate::app::plot_frame::{Fit, axes, refit_if};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{Axis, Key, Load, Model};

/// The plot's height over its highest point: room for the legend above the data.
const HEADROOM: f64 = 1.5;

impl Default for ParadoxPanel {
    fn default() -> Self {
        Self {
            jobs: Jobs::new("paradox curves"),
            curves: None,
            kind: DampingKind::default(),
            current: None,
            fit: Fit::default(),
            generation: 0,
        }
    }
}

pub const TAB: TabSpec = TabSpec {
    id: "paradox",
    title: "paradox",
    tooltip: "the first critical load as the damping (or the roller's mass) vanishes",
    make: || Box::new(ParadoxPanel::default()),
};

/// The panel and its curves.
pub struct ParadoxPanel {
    /// The curves being computed, newest parameters first.
    jobs: Jobs<CurveKey, Curves>,
    /// The newest curves received, and what they are for.
    curves: Option<(CurveKey, Curves)>,
    /// Which damping of a column with a tip force vanishes.
    kind: DampingKind,
    /// The current model's own point, and the model and kind it is for.
    current: Option<(CurveKey, Option<[f64; 2]>)>,
    /// Refits when the curves of other parameters arrive, and on "reset all".
    fit: Fit<(u64, CurveKey)>,
    /// The state's "reset all" count this frame.
    generation: u64,
}

/// What the curves depend on: the model with the swept parameters at a
/// fixed value, and the kind of damping swept.
type CurveKey = (Model, DampingKind);

/// The curves' key of `model`.
fn curve_key(model: &Model, kind: DampingKind) -> CurveKey {
    let zero = match model.load {
        Load::Roller(_) => Axis::Key(Key::Nu).apply(model, 0.0),
        Load::Follower { .. } => Axis::DampingLevel.apply(model, 0.0),
    };
    let mut key = zero.unwrap_or(*model).at_load(0.0);
    if kind == DampingKind::External {
        key.column.c1_nms_per_rad = 0.0;
        key.column.drag_ns_per_m2 = 0.0;
    }
    (key, kind)
}

impl ParadoxPanel {
    /// Starts the curves for `model` when they are not those of its key
    /// (the newest wins: the job before ends within one point).
    fn follow(&mut self, model: &Model) {
        let key = curve_key(model, self.kind);
        if self.jobs.key() == Some(&key) {
            return;
        }
        let kind = self.kind;
        let started = self.jobs.request(key, move |(model, _), cancel, send| {
            send(paradox_curves(model, kind, cancel.flag()));
        });
        if let Err(error) = started {
            self.curves = Some((
                key,
                Curves {
                    note: Some(format!("no thread for the curves: {error}")),
                    ..Curves::default()
                },
            ));
        }
    }

    /// Takes the curves that came in; the newest are kept.
    fn receive(&mut self) {
        if let Some(newest) = self.jobs.drain().last() {
            self.curves = Some(newest);
        }
    }

    /// Blocks until the curves are computed (for pictures and tests).
    pub fn wait(&mut self, model: &Model) {
        self.follow(model);
        self.jobs.wait();
        self.receive();
    }

    /// The current model's point: its ratio (log10) and first critical
    /// load. `known`: that load when the app's analysis has found it (it
    /// covers a shorter range), so it is not searched for again.
    fn current_point(&mut self, model: &Model, known: Option<f64>) -> Option<[f64; 2]> {
        let key = model.at_load(0.0);
        if let Some((cached, point)) = &self.current
            && *cached == (key, self.kind)
        {
            return *point;
        }
        let point = own_point(&key, self.kind, known);
        self.current = Some(((key, self.kind), point));
        point
    }

    fn draw(
        &mut self,
        ui: &mut egui::Ui,
        model: &Model,
        known: Option<f64>,
        for_picture: bool,
        actions: &mut Actions,
        theme: &Theme,
    ) {
        self.follow(model);
        let here = self.current_point(model, known);
        self.receive();
        let key = curve_key(model, self.kind);
        let Some((curves_key, curves)) = self.curves.as_ref().filter(|(k, _)| *k == key) else {
            ui.ctx().request_repaint();
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label("computing the flutter loads as the damping vanishes ...");
            });
            return;
        };
        if let Some(note) = &curves.note {
            ui.colored_label(theme.warning, note);
            return;
        }
        ui.label(match (model.load, self.kind) {
            (Load::Roller(_), _) => "The load at which the roller column first loses stability, against the roller's mass, for three band speeds (the slip damping is mu R / V). As nu -> 0 it goes to zero, not to the massless roller's (ideal follower's) value.",
            (Load::Follower { .. }, DampingKind::Joints) => "The flutter load with joint dampers c1 = (c1/c2) c2 as the damping level g2 = c2 / sqrt(k m l^2) goes to zero: the limit depends on the ratio and lies below the undamped load (Ziegler's paradox).",
            (Load::Follower { .. }, DampingKind::External) => "The flutter load with equal joint dampers c1 = c2 = c (internal damping) and drag c_ext = (c_ext l^3 / c) c / l^3 along the rods (external damping) as the level g2 = c / sqrt(k m l^2) goes to zero: external damping destabilizes too, and the limit depends on the ratio.",
        });
        self.fit
            .bar_ui(ui, for_picture, |ui| save_buttons(ui, None, actions));
        let refit = self.fit.refit((self.generation, *curves_key));
        let palette = [theme.series[0], theme.series[3], theme.series[4]];
        let highest = curves
            .lines
            .iter()
            .flat_map(|(_, points)| points.iter().map(|p| p[1]))
            .chain(curves.reference.as_ref().map(|(_, p)| *p))
            .fold(0.0, f64::max);
        let plot = Plot::new("paradox")
            .legend(Legend::default().position(Corner::LeftTop))
            .include_y(0.0)
            .include_y(HEADROOM * highest);
        let plot = axes(
            plot,
            format!("{} (log scale)", curves.x_label),
            "first critical load p",
        )
        // Decades on the log axis, not 1-2-5 steps of the exponent.
        .x_grid_spacer(log_grid_spacer(10))
        .x_axis_formatter(|mark, _| number_text(10f64.powf(mark.value)));
        refit_if(plot, refit).show(ui, |plot_ui| {
            if let Some((label, p)) = &curves.reference {
                plot_ui.hline(
                    HLine::new(label.clone(), *p)
                        .color(theme.text)
                        .width(1.5 * theme.stroke_scale),
                );
            }
            for ((label, points), color) in curves.lines.iter().zip(palette.iter().cycle()) {
                plot_ui.line(
                    Line::new(label.clone(), PlotPoints::from(points.clone()))
                        .color(*color)
                        .width(2.0 * theme.stroke_scale),
                );
            }
            if let Some(point) = here {
                plot_ui.points(
                    Points::new("this model", vec![point])
                        .radius(5.0 * theme.stroke_scale)
                        .color(theme.now)
                        .filled(true),
                );
            }
        });
    }
}

impl TabView for ParadoxPanel {
    fn complete_background_work(&mut self, state: &AppState) {
        self.wait(state.model());
    }
}

impl View for ParadoxPanel {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        let model = *state.model();
        // The analysis shown during a drag may be of the parameters before:
        // its load is not this model's point.
        let known = state
            .analysis()
            .filter(|analysis| *analysis.key == model.at_load(0.0))
            .and_then(crate::app::analysis_cache::Analysis::first_instability);
        self.generation = state.view_generation();
        if matches!(model.load, Load::Follower { eta, .. } if eta > 0.0) {
            self.kind_ui(ui);
        }
        self.draw(ui, &model, known, state.for_picture(), actions, theme);
    }
}

impl ParadoxPanel {
    /// The choice of the damping that vanishes.
    fn kind_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            ui.label("damping that vanishes:");
            ui.selectable_value(&mut self.kind, DampingKind::Joints, "joint dampers")
                .on_hover_text("the joint dampers c1 and c2 in the ratio c1/c2");
            ui.selectable_value(
                &mut self.kind,
                DampingKind::External,
                "external drag and internal",
            )
            .on_hover_text(
                "drag c_ext along the rods (external) and equal joint dampers c1 = c2 = c (internal) in the ratio c_ext l^3 / c",
            );
        });
    }
}
