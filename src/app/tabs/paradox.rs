//! The Ziegler paradox explorer: the load at which the column first loses
//! stability as the damping vanishes (joint dampers of a given ratio, or
//! external drag and equal joint dampers in a given ratio; the roller's mass
//! at several band speeds), next to the undamped value, computed off the UI
//! thread.

use crate::app::speak::Speak as _;
use crate::i18n::Words;
use crate::tr;
use eframe::egui;

use super::{TabSpec, TabView, save_buttons};
use crate::analysis::{Curves, DampingKind, NoCurve, own_point, paradox_curves};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::jobs::Jobs;
use crate::app::plot_draw::{legend_ui, plot_ui};
use crate::app::plot_frame::Fit;
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::number_text;
use crate::model::{Axis, Key, Load, Model};
use crate::plot::paradox::Paradox;

impl Default for ParadoxPanel {
    fn default() -> Self {
        Self {
            jobs: Jobs::new("paradox curves"),
            points: Jobs::new("paradox point"),
            curves: None,
            kind: DampingKind::default(),
            current: None,
            fit: Fit::default(),
            generation: 0,
        }
    }
}

pub const TAB: TabSpec = TabSpec {
    tab: super::Tab::Paradox,
    id: "paradox",
    background: true,
    make: || Box::new(ParadoxPanel::default()),
};

/// The panel and its curves.
pub struct ParadoxPanel {
    /// The curves being computed, newest parameters first.
    jobs: Jobs<CurveKey, Curves>,
    /// The newest curves received (or why no thread could compute them),
    /// and what they are for.
    curves: Option<(CurveKey, Result<Curves, String>)>,
    /// Which damping of a column with a tip force vanishes.
    kind: DampingKind,
    /// The current model's own point being found, off the window's thread
    /// (a long chain's first critical load is a search of its own).
    points: Jobs<CurveKey, Option<[f64; 2]>>,
    /// The newest point found, and the model (at load 0) and kind it is for.
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

/// The current model's first critical load as the app's analysis has it,
/// if it is this model's: the analysis shown during a drag may be of the
/// parameters before, and its load is not this model's point.
fn known_load(state: &AppState) -> Option<f64> {
    state
        .analysis()
        .filter(|analysis| *analysis.key == state.model().at_load(0.0))
        .and_then(crate::app::analysis_cache::Analysis::first_instability)
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
            send(paradox_curves(
                model,
                kind,
                crate::machine_threads(),
                cancel.flag(),
            ));
        });
        if let Err(error) = started {
            self.curves = Some((key, Err(error.to_string())));
        }
    }

    /// Takes the curves that came in; the newest are kept.
    fn receive(&mut self) {
        if let Some(newest) = self.jobs.drain().last() {
            self.curves = Some((newest.0, Ok(newest.1)));
        }
    }

    /// Blocks until the curves and the model's own point are computed
    /// (for pictures and tests).
    pub fn wait(&mut self, model: &Model, known: Option<f64>) {
        self.follow(model);
        self.follow_point(model, known);
        self.jobs.wait();
        self.points.wait();
        self.receive();
    }

    /// Starts finding the current model's point unless it is the newest
    /// asked for. `known`: its first critical load when the app's analysis
    /// has found it (it covers a shorter range), so it is not searched for
    /// again.
    fn follow_point(&mut self, model: &Model, known: Option<f64>) {
        let key = (model.at_load(0.0), self.kind);
        if self.points.key() == Some(&key) {
            return;
        }
        let started = self.points.request(key, move |(model, kind), _, send| {
            send(own_point(model, *kind, known, crate::machine_threads()));
        });
        if started.is_err() {
            // No thread: no point drawn, rather than a stale one.
            self.current = Some((key, None));
        }
    }

    /// The current model's point (its ratio, log10, and first critical
    /// load) once found; `None` while it is sought, and where it has none.
    fn current_point(&mut self, model: &Model, known: Option<f64>) -> Option<[f64; 2]> {
        self.follow_point(model, known);
        if let Some(newest) = self.points.drain().last() {
            self.current = Some(newest);
        }
        let key = (model.at_load(0.0), self.kind);
        self.current
            .as_ref()
            .filter(|(k, _)| *k == key)
            .and_then(|(_, point)| *point)
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
        if self.points.busy() {
            ui.ctx().request_repaint();
        }
        self.receive();
        let key = curve_key(model, self.kind);
        let words = ui.words();
        let Some((curves_key, curves)) = self.curves.as_ref().filter(|(k, _)| *k == key) else {
            ui.ctx().request_repaint();
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label(tr!(words, "paradox-computing"));
            });
            return;
        };
        let curves = match curves {
            Ok(curves) => curves,
            Err(why) => {
                ui.colored_label(
                    color(theme.palette.warning),
                    tr!(words, "paradox-no-thread", why = why.as_str()),
                );
                return;
            }
        };
        if let Some(note) = &curves.note {
            ui.colored_label(color(theme.palette.warning), no_curve_words(words, note));
            return;
        }
        ui.label(match (model.load, self.kind) {
            (Load::Roller(_), _) => roller_caption(curves, words),
            (Load::Follower { .. }, DampingKind::Joints) => tr!(words, "paradox-joints"),
            (Load::Follower { .. }, DampingKind::External) => tr!(words, "paradox-external"),
        });
        self.fit
            .bar_ui(ui, for_picture, |ui| save_buttons(ui, None, actions));
        let refit = self.fit.refit((self.generation, *curves_key));
        let sheet = Paradox {
            curves,
            here,
            words,
        }
        .sheet();
        legend_ui(ui, &sheet.legend, theme);
        match sheet.plots.first() {
            Some(plot) => {
                plot_ui(ui, plot, refit, theme);
            }
            None => {
                ui.colored_label(
                    color(theme.palette.warning),
                    tr!(words, "paradox-no-extent"),
                );
            }
        }
    }
}

impl TabView for ParadoxPanel {
    fn complete_background_work(&mut self, state: &AppState) {
        self.wait(state.model(), known_load(state));
    }
}

impl View for ParadoxPanel {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        let model = *state.model();
        let known = known_load(state);
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
        let words = ui.words();
        ui.horizontal(|ui| {
            ui.label(tr!(words, "paradox-kind"));
            ui.selectable_value(
                &mut self.kind,
                DampingKind::Joints,
                tr!(words, "paradox-kind-joints"),
            )
            .on_hover_text(tr!(words, "paradox-kind-joints.tooltip"));
            ui.selectable_value(
                &mut self.kind,
                DampingKind::External,
                tr!(words, "paradox-kind-external"),
            )
            .on_hover_text(tr!(words, "paradox-kind-external.tooltip"));
        });
    }
}

/// A curve falling to below this share of its value at the largest mass
/// shown is said to go toward zero.
const FALLING_SHARE: f64 = 0.5;

/// The roller's caption, said from what its curves show: where they stand
/// at the smallest mass shown beside the massless roller's load, and
/// whether they fall toward zero as nu -> 0 (with drag along the rods they
/// stay flat, and a caption that always said "goes to zero" contradicted
/// them).
/// Why there is no curve, in `words`' language.
fn no_curve_words(words: &'static Words, note: &NoCurve) -> String {
    match note {
        NoCurve::DeadLoad => tr!(words, "paradox-dead-load"),
        NoCurve::StableThroughout { load_max } => tr!(
            words,
            "paradox-stable-throughout",
            end = number_text(*load_max)
        ),
        NoCurve::Failed(error) => tr!(
            words,
            "paradox-failed",
            why = crate::i18n::analysis_error(words, error)
        ),
    }
}

fn roller_caption(curves: &Curves, words: &'static Words) -> String {
    let intro = tr!(words, "paradox-roller");
    // Each line's load at its smallest and at its largest mass (x is log10 nu).
    let ends: Vec<(f64, f64, f64)> = curves
        .lines
        .iter()
        .filter_map(|(_, points)| {
            let first = points.iter().min_by(|a, b| a[0].total_cmp(&b[0]))?;
            let last = points.iter().max_by(|a, b| a[0].total_cmp(&b[0]))?;
            Some((first[0], first[1], last[1]))
        })
        .collect();
    let Some(smallest_x) = ends.iter().map(|e| e.0).reduce(f64::min) else {
        return intro;
    };
    let (low, high) = ends
        .iter()
        .map(|e| e.1)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
            (lo.min(p), hi.max(p))
        });
    let at_smallest = if high - low <= 1e-3 * high.abs() {
        format!("p = {}", number_text(low))
    } else {
        format!("p = {} to {}", number_text(low), number_text(high))
    };
    let falling = ends
        .iter()
        .all(|&(_, small, large)| small < FALLING_SHARE * large);
    let trend = if falling {
        tr!(words, "paradox-roller-falling")
    } else {
        tr!(words, "paradox-roller-flat")
    };
    let massless = curves
        .reference
        .as_ref()
        .map(|(_, p)| tr!(words, "paradox-roller-massless", load = number_text(*p)))
        .unwrap_or_default();
    tr!(
        words,
        "paradox-roller-caption",
        intro = intro,
        nu = number_text(10f64.powf(smallest_x)),
        at = at_smallest,
        trend = trend,
        massless = massless
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Assignment, PresetId, apply_assignments};

    fn caption(sets: &[(Key, f64)]) -> String {
        let mut model = PresetId::Roller.model();
        let assignments: Vec<Assignment> = sets
            .iter()
            .map(|&(key, value)| Assignment { key, value })
            .collect();
        apply_assignments(&mut model, &assignments).unwrap();
        let curves = paradox_curves(
            &model,
            DampingKind::Joints,
            1,
            &std::sync::atomic::AtomicBool::new(false),
        );
        roller_caption(&curves, crate::i18n::words(crate::i18n::Language::English))
    }

    /// The caption says what the curves show: the plain roller's first
    /// critical load falls toward zero with its mass; with drag along the
    /// rods (`c_ext` = 0.01) it stays near 0.085 (two rods: 2.54), and the
    /// caption no longer says "goes to zero" over flat curves.
    #[test]
    fn the_roller_s_caption_follows_its_curves() {
        let plain = caption(&[]);
        assert!(plain.contains("falling toward zero as nu -> 0"), "{plain}");
        let dragged = caption(&[
            (Key::Mu, 0.2),
            (Key::V, 0.01),
            (Key::Nu, 0.05),
            (Key::Rho, 0.2),
            (Key::CExt, 0.01),
        ]);
        assert!(
            dragged.contains("not falling toward zero over this range"),
            "{dragged}"
        );
        assert!(!dragged.contains("goes to zero"), "{dragged}");
    }
}
