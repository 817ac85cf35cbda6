//! The Ziegler paradox explorer: the load at which the column first loses
//! stability as the damping vanishes (joint dampers of a given ratio, or
//! external drag and equal joint dampers in a given ratio; the roller's mass
//! at several band speeds), next to the undamped value, computed off the UI
//! thread.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, mpsc};

use eframe::egui;
use egui_plot::{Corner, HLine, Legend, Line, Plot, PlotPoints, Points, log_grid_spacer};

use super::{TabSpec, TabView};
use crate::analysis::{
    first_instability, flutter_load_damped, flutter_load_external, natural_load_max,
};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::plot_frame::{Fit, axes, refit_if};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{Axis, Key, Load, Model};

/// Points per curve.
const POINTS: usize = 41;
/// Joint damping levels g2 of the column curves, down to "vanishing".
const LEVELS: [f64; 3] = [0.1, 0.01, 1e-4];
/// log10 of the damper ratio c1/c2, and of the external to internal
/// damping ratio `c_ext l^3 / c`, shown.
const RATIO_DECADES: (f64, f64) = (-2.0, 2.0);
/// log10 of the roller's mass ratio nu shown.
const NU_DECADES: (f64, f64) = (-6.0, 1.0);
/// Curves closer than this, relative to their loads, are one curve.
const SAME_CURVE: f64 = 1e-6;
/// The plot's height over its highest point: room for the legend above the data.
const HEADROOM: f64 = 1.5;

/// Which damping of a column with a tip force vanishes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DampingKind {
    /// The joint dampers, in the ratio c1/c2.
    #[default]
    Joints,
    /// External drag along the rods and equal joint dampers (internal
    /// damping), in the ratio `c_ext l^3 / c`.
    External,
}

impl DampingKind {
    /// The x axis's quantity, for the axis and the menu.
    fn ratio_name(self) -> &'static str {
        match self {
            Self::Joints => "c1/c2",
            Self::External => "c_ext l^3 / c (external / internal)",
        }
    }

    /// The current model's ratio, when it has this kind of damping.
    fn ratio(self, model: &Model) -> f64 {
        let c = &model.column;
        match self {
            Self::Joints if c.c2_nms_per_rad > 0.0 => c.c1_nms_per_rad / c.c2_nms_per_rad,
            Self::External if c.c2_nms_per_rad > 0.0 && c.c1_nms_per_rad == c.c2_nms_per_rad => {
                c.drag_ns_per_m2 * model.reference_length_m().powi(3) / c.c2_nms_per_rad
            }
            Self::Joints | Self::External => f64::NAN,
        }
    }
}

/// What the explorer draws: curves of the first critical load against
/// log10 of the swept ratio, and the undamped (or massless) reference.
#[derive(Clone, Debug, Default)]
pub struct Curves {
    pub x_label: &'static str,
    pub lines: Vec<(String, Vec<[f64; 2]>)>,
    pub reference: Option<(String, f64)>,
    /// Why there is nothing to draw, if so.
    pub note: Option<String>,
}

impl Curves {
    /// Curves with `reference`; with a note instead when no line has a point.
    fn new(
        x_label: &'static str,
        lines: Vec<(String, Vec<[f64; 2]>)>,
        failures: Vec<Option<String>>,
        reference: Option<(String, f64)>,
        load_max: f64,
    ) -> Self {
        let note = lines
            .iter()
            .all(|(_, points)| points.is_empty())
            .then(|| empty_reason(failures, load_max));
        Self {
            x_label,
            lines,
            reference,
            note,
        }
    }
}

/// The points `(log10 x, first critical load)` of `load_at(x)` over
/// `decades`, leaving out values where the column never loses stability or
/// cannot be analysed (the first such reason is returned with them). Stops
/// computing (the rest left out) once `cancel` is set.
fn curve<E: std::fmt::Display>(
    decades: (f64, f64),
    cancel: &AtomicBool,
    load_at: impl Fn(f64) -> Result<Option<f64>, E>,
) -> (Vec<[f64; 2]>, Option<String>) {
    #[expect(clippy::cast_precision_loss, reason = "point counts")]
    let step = (decades.1 - decades.0) / (POINTS - 1) as f64;
    let mut failure = None;
    let points = (0..POINTS)
        .take_while(|_| !cancel.load(Ordering::Relaxed))
        .filter_map(|i| {
            #[expect(clippy::cast_precision_loss, reason = "point counts")]
            let e = decades.0 + step * i as f64;
            match load_at(10f64.powf(e)) {
                Ok(load) => load.map(|p| [e, p]),
                Err(error) => {
                    failure.get_or_insert_with(|| error.to_string());
                    None
                }
            }
        })
        .collect();
    (points, failure)
}

/// Why a plot with no point at all is empty: the first failure, or that
/// no point loses stability below `load_max`.
fn empty_reason(failures: impl IntoIterator<Item = Option<String>>, load_max: f64) -> String {
    failures.into_iter().flatten().next().map_or_else(
        || {
            format!(
                "No curve to draw: at every ratio shown the column keeps its stability up to p = {}.",
                number_text(load_max)
            )
        },
        |error| format!("No curve to draw: {error}."),
    )
}

/// The explorer's curves for `model` (its load and the swept parameters are
/// set by the curves themselves). Once `cancel` is set the curves end early:
/// a cancelled result is for no one.
#[must_use]
pub fn curves(model: &Model, kind: DampingKind, cancel: &AtomicBool) -> Curves {
    // The first loss of stability is sought over the column's own range, as
    // `critical` does by default (a chain of 16 rods searched to p = 10, 64
    // times its range, took ten minutes per picture).
    let load_max = natural_load_max(model);
    let first = |m: &Model| first_instability(m, load_max).ok().flatten();
    match model.load {
        Load::Follower { eta: 0.0, .. } => Curves {
            note: Some(
                "A dead load (eta = 0) is conservative: it never flutters, so there is no paradox to show."
                    .to_owned(),
            ),
            ..Curves::default()
        },
        Load::Follower { .. } => {
            let undamped = Axis::DampingLevel
                .apply(model, 0.0)
                .ok()
                .and_then(|m| first(&m));
            let (lines, failures): (Vec<_>, Vec<_>) = LEVELS
                .iter()
                .map(|&level| {
                    let (points, failure) = curve(RATIO_DECADES, cancel, |ratio| match kind {
                        DampingKind::Joints => flutter_load_damped(model, ratio, level, load_max),
                        DampingKind::External => {
                            flutter_load_external(model, ratio, level, load_max)
                        }
                    });
                    (
                        (format!("damping g2 = {}", number_text(level)), points),
                        failure,
                    )
                })
                .unzip();
            Curves::new(
                kind.ratio_name(),
                lines,
                failures,
                undamped.map(|p| ("undamped".to_owned(), p)),
                load_max,
            )
        }
        Load::Roller(roller) => {
            let v = roller.band_speed_m_per_s;
            let massless = Axis::Key(Key::Nu)
                .apply(model, 0.0)
                .ok()
                .and_then(|m| first(&m));
            let (lines, failures): (Vec<_>, Vec<_>) = [0.1 * v, v, 10.0 * v]
                .iter()
                .map(|&speed| {
                    let (points, failure) = curve(NU_DECADES, cancel, |nu| {
                        let m = Axis::Key(Key::V)
                            .apply(model, speed)
                            .map_err(|e| e.to_string())?;
                        let m = Axis::Key(Key::Nu)
                            .apply(&m, nu)
                            .map_err(|e| e.to_string())?;
                        first_instability(&m, load_max).map_err(|e| e.to_string())
                    });
                    ((format!("V = {} m/s", number_text(speed)), points), failure)
                })
                .unzip();
            let lines = merge_if_one_curve(lines, "the first critical load does not depend on V");
            Curves::new(
                "nu = m3/m",
                lines,
                failures,
                massless.map(|p| ("nu = 0: the ideal follower".to_owned(), p)),
                load_max,
            )
        }
    }
}

/// `lines`, or the one curve they all draw (the same points, loads within
/// [`SAME_CURVE`]) under a name that lists them and says `why`.
fn merge_if_one_curve(
    lines: Vec<(String, Vec<[f64; 2]>)>,
    why: &str,
) -> Vec<(String, Vec<[f64; 2]>)> {
    let Some((_, first)) = lines.first() else {
        return lines;
    };
    let same = |points: &Vec<[f64; 2]>| {
        points.len() == first.len()
            && points.iter().zip(first).all(|(a, b)| {
                a[0] == b[0] && (a[1] - b[1]).abs() <= SAME_CURVE * a[1].abs().max(b[1].abs())
            })
    };
    if lines.len() < 2 || first.is_empty() || !lines.iter().all(|(_, points)| same(points)) {
        return lines;
    }
    let names: Vec<&str> = lines.iter().map(|(name, _)| name.as_str()).collect();
    let name = format!("{}: one curve, {why}", names.join(", "));
    let points = first.clone();
    vec![(name, points)]
}

/// The curves of one model, computed or being computed. Dropping the job
/// (the parameters moved on) cancels its computation within one point.
struct Job {
    key: CurveKey,
    receiver: mpsc::Receiver<Curves>,
    curves: Option<Curves>,
    cancel: Arc<AtomicBool>,
    thread: Option<std::thread::JoinHandle<()>>,
}

impl Drop for Job {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
    }
}

pub const TAB: TabSpec = TabSpec {
    id: "paradox",
    title: "paradox",
    tooltip: "the first critical load as the damping (or the roller's mass) vanishes",
    make: || Box::new(ParadoxPanel::default()),
};

/// The panel and its job.
#[derive(Default)]
pub struct ParadoxPanel {
    job: Option<Job>,
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
    /// Starts the curves for `model` when they are not those of its key.
    fn follow(&mut self, model: &Model) {
        let kind = self.kind;
        let key = curve_key(model, kind);
        if self.job.as_ref().is_some_and(|job| job.key == key) {
            return;
        }
        // The previous job is cancelled (it ends within one point) and the
        // new one starts when it has ended: while a slider is dragged the
        // restarts queue up instead of running side by side.
        let previous = self.job.take().and_then(|mut job| job.thread.take());
        let (sender, receiver) = mpsc::channel();
        let cancel = Arc::new(AtomicBool::new(false));
        let (model_copy, flag) = (*model, Arc::clone(&cancel));
        let spawned = std::thread::Builder::new()
            .name("paradox curves".to_owned())
            .spawn(move || {
                if let Some(previous) = previous {
                    drop(previous.join());
                }
                drop(sender.send(curves(&model_copy, kind, &flag)));
            });
        let (thread, curves) = match spawned {
            Ok(handle) => (Some(handle), None),
            Err(error) => (
                None,
                Some(Curves {
                    note: Some(format!("no thread for the curves: {error}")),
                    ..Curves::default()
                }),
            ),
        };
        self.job = Some(Job {
            key,
            receiver,
            curves,
            cancel,
            thread,
        });
    }

    /// Blocks until the curves are computed (for pictures and tests).
    pub fn wait(&mut self, model: &Model) {
        self.follow(model);
        if let Some(job) = &mut self.job
            && job.curves.is_none()
        {
            job.curves = job.receiver.recv().ok();
        }
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
        let x = match model.load {
            Load::Roller(_) => Axis::Key(Key::Nu).get(model),
            Load::Follower { .. } => self.kind.ratio(model),
        };
        let point = (x > 0.0 && x.is_finite())
            .then(|| {
                known.or_else(|| {
                    first_instability(&key, natural_load_max(&key))
                        .ok()
                        .flatten()
                })
            })
            .flatten()
            .map(|p| [x.log10(), p]);
        self.current = Some(((key, self.kind), point));
        point
    }

    fn draw(
        &mut self,
        ui: &mut egui::Ui,
        model: &Model,
        known: Option<f64>,
        for_picture: bool,
        theme: &Theme,
    ) {
        self.follow(model);
        let here = self.current_point(model, known);
        let Some(job) = &mut self.job else {
            return;
        };
        if job.curves.is_none() {
            job.curves = job.receiver.try_recv().ok();
        }
        let Some(curves) = &job.curves else {
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
        self.fit.bar_ui(ui, for_picture);
        let refit = self.fit.refit((self.generation, job.key));
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
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, _actions: &mut Actions, theme: &Theme) {
        let known = state
            .analysis()
            .and_then(crate::app::analysis_cache::Analysis::first_instability);
        let model = *state.model();
        self.generation = state.view_generation();
        if matches!(model.load, Load::Follower { eta, .. } if eta > 0.0) {
            self.kind_ui(ui);
        }
        self.draw(ui, &model, known, state.for_picture(), theme);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    fn roller_with(key: Key, value: f64) -> Model {
        Axis::Key(key)
            .apply(&PresetId::Roller.model(), value)
            .unwrap()
    }

    /// The roller's first critical load is the same at every band speed
    /// (computed, not assumed): the three curves are drawn as one, and the
    /// legend says so; curves that differ stay apart.
    #[test]
    fn the_roller_s_band_speeds_draw_one_curve_and_say_why() {
        let curves = curves(
            &PresetId::Roller.model(),
            DampingKind::Joints,
            &AtomicBool::new(false),
        );
        assert_eq!(curves.lines.len(), 1, "{:?}", curves.lines);
        let (name, points) = &curves.lines[0];
        assert!(name.contains("does not depend on V"), "{name}");
        assert_eq!(points.len(), POINTS);
        let apart = vec![
            ("a".to_owned(), vec![[0.0, 1.0], [1.0, 2.0]]),
            ("b".to_owned(), vec![[0.0, 1.0], [1.0, 2.001]]),
        ];
        assert_eq!(merge_if_one_curve(apart, "same").len(), 2);
    }

    /// A stopped band has no linear analysis: the panel says so instead of
    /// claiming that the column never loses stability.
    #[test]
    fn a_stopped_band_leaves_the_plot_empty_with_the_reason() {
        let curves = curves(
            &roller_with(Key::V, 0.0),
            DampingKind::Joints,
            &AtomicBool::new(false),
        );
        let note = curves.note.unwrap();
        assert!(note.contains("V = 0"), "{note}");
    }

    /// External and internal damping vanishing together: the curve of the
    /// smallest level follows the Routh-Hurwitz limit (physics.md section
    /// 7), from near internal damping's 41/28 at small ratios toward
    /// external damping's 2 at large ones, below the undamped 7/2 - sqrt 2
    /// that the reference line shows.
    #[test]
    fn external_damping_curves_follow_the_vanishing_damping_limit() {
        let limit = |r: f64| {
            let a = 15.0 * r * r + 210.0 * r;
            let b = -(104.0 * r * r + 1467.0 * r + 504.0);
            let c = 148.0 * r * r + 2214.0 * r + 738.0;
            (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a)
        };
        let curves = curves(
            &PresetId::Ziegler1952.model(),
            DampingKind::External,
            &AtomicBool::new(false),
        );
        let (_, vanishing) = curves.lines.last().unwrap();
        assert_eq!(vanishing.len(), POINTS);
        for point in vanishing {
            let expected = limit(10f64.powf(point[0]));
            assert!(
                (point[1] - expected).abs() < 1e-3,
                "{point:?} vs {expected}"
            );
        }
        assert!((vanishing[0][1] - 41.0 / 28.0).abs() < 0.02);
        assert!((vanishing[POINTS - 1][1] - 2.0).abs() < 0.03);
        let undamped = curves.reference.unwrap().1;
        assert!((undamped - (3.5 - 2f64.sqrt())).abs() < 1e-9);
    }
}
