//! The post-critical tab: the bifurcation diagram of the current column
//! (the straight column, stable or not, and the limit cycles born at its
//! flutter onsets, the largest angle over each cycle against the load,
//! stable solid and unstable dashed), the current load, the ramp's seen
//! onset and the running column's own swing as a live dot, so a class sees
//! it settle onto the curve. The cycles are computed off the UI thread.

#[cfg(test)]
use std::sync::atomic::AtomicBool;

use eframe::egui;

use super::{TabSpec, TabView, save_buttons};
use crate::analysis::{
    AnalysisError, Branch, BranchEnd, MAX_AMPLITUDE_RAD, MAX_PERIOD_GROWTH, MAX_POINTS, NoBranch,
    Onset, State, TRIVIAL_TOLERANCE, cycle_branches,
};
use crate::app::View;
use crate::app::action::Actions;
use crate::app::history::{HISTORY_SECS, History};
use crate::app::jobs::Jobs;
use crate::app::plot_draw::{legend_ui, plot_ui};
use crate::app::plot_frame::Fit;
use crate::app::speak::Speak as _;
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::load_text;
use crate::i18n::Words;
use crate::model::Model;
use crate::plot::bifurcation::{self, Present};
use crate::tr;

pub const TAB: TabSpec = TabSpec {
    tab: super::Tab::PostCritical,
    id: "post-critical",
    background: true,
    make: || Box::new(PostCriticalPanel::default()),
};

/// The longest chain whose cycles the window follows (over the load bar, a
/// chain of 8 rods with joint dampers takes about 5 s in a release build on
/// two cores, 16 rods about 20 s: the README's figures).
const WINDOW_MAX_RODS: usize = 16;

/// What the diagram depends on: the column (at load 0) and the load range.
type DiagramKey = (Model, f64);

/// The branches found, or why there are none.
type Diagram = Result<Vec<Onset>, NoDiagram>;

/// Why the window has no branches of cycles to draw.
#[derive(Debug)]
enum NoDiagram {
    /// A chain longer than [`WINDOW_MAX_RODS`].
    TooLong {
        rods: usize,
    },
    Analysis(AnalysisError),
    NoThread(String),
}

impl NoDiagram {
    fn words(&self, words: &'static Words) -> String {
        match self {
            Self::TooLong { rods } => tr!(words, "cycles-chain-too-long", rods = *rods),
            Self::Analysis(error) => crate::i18n::analysis_error(words, error),
            Self::NoThread(why) => tr!(words, "cycles-no-thread", why = why.as_str()),
        }
    }
}

/// The panel and its diagram.
pub struct PostCriticalPanel {
    jobs: Jobs<DiagramKey, Diagram>,
    diagram: Option<(DiagramKey, Diagram)>,
    /// Refits when a new diagram arrives, and on "reset all".
    fit: Fit<(u64, DiagramKey)>,
}

impl Default for PostCriticalPanel {
    fn default() -> Self {
        Self {
            jobs: Jobs::new("limit cycles"),
            diagram: None,
            fit: Fit::default(),
        }
    }
}

impl PostCriticalPanel {
    /// Starts the diagram for `key` unless it is the newest asked for (a
    /// chain too long for the window is told so instead).
    fn follow(&mut self, key: DiagramKey) {
        if self.jobs.key() == Some(&key) {
            return;
        }
        let started = self.jobs.request(key, |(model, load_max), cancel, send| {
            let rods = model.column.rods;
            if rods > WINDOW_MAX_RODS {
                send(Err(NoDiagram::TooLong { rods }));
                return;
            }
            let found = cycle_branches(model, 0.0, *load_max, cancel.flag());
            if !cancel.requested() {
                send(found.map_err(NoDiagram::Analysis));
            }
        });
        if let Err(error) = started {
            self.diagram = Some((key, Err(NoDiagram::NoThread(error.to_string()))));
        }
    }

    /// Takes the diagram that came in; the newest is kept.
    fn receive(&mut self) {
        if let Some(newest) = self.jobs.drain().last() {
            self.diagram = Some(newest);
        }
    }

    fn key(state: &AppState) -> DiagramKey {
        (state.model().at_load(0.0), state.load_max())
    }
}

impl TabView for PostCriticalPanel {
    fn complete_background_work(&mut self, state: &AppState) {
        self.follow(Self::key(state));
        self.jobs.wait();
        self.receive();
    }
}

impl View for PostCriticalPanel {
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        let key = Self::key(state);
        self.follow(key);
        self.receive();
        let Some((_, diagram)) = self.diagram.as_ref().filter(|(k, _)| *k == key) else {
            ui.ctx().request_repaint();
            ui.horizontal(|ui| {
                ui.spinner();
                ui.label(tr!(ui.words(), "cycles-computing"));
            });
            return;
        };
        let onsets = match diagram {
            Ok(onsets) => onsets,
            Err(why) => {
                let why = why.words(state.words());
                ui.colored_label(
                    color(theme.palette.warning),
                    tr!(state.words(), "cycles-none", why = why),
                );
                return;
            }
        };
        for line in notes(onsets, state.words()) {
            ui.label(egui::RichText::new(line).small());
        }
        self.fit.bar_ui(ui, state.for_picture(), |ui| {
            save_buttons(ui, None, actions);
        });
        let refit = self.fit.refit((state.view_generation(), key));
        let load = state.model().load_p();
        let branches: Vec<&Branch> = onsets
            .iter()
            .filter_map(|o| o.branch.as_ref().ok())
            .collect();
        let swing = live_swing(state.history(), &branches, load);
        let equilibrium = equilibrium(state, key.1);
        // Fitted to the cycles, not to the straight column's whole range:
        // the roller's branch (p = 0.0238 to 0.0441) was a sliver at the
        // left of a 0 to 8 axis.
        let reach = cycles_reach(&branches, key.1).unwrap_or(key.1.max(load));
        let sheet = bifurcation::Diagram {
            load_range: (0.0, reach),
            equilibrium: &equilibrium,
            branches,
            sweep: &[],
            present: Some(Present {
                load,
                seen_at: state.ramp().and_then(|ramp| ramp.seen_at_p),
                swing_rad: swing,
            }),
            words: state.words(),
        }
        .sheet();
        legend_ui(ui, &sheet.legend, theme);
        for plot in &sheet.plots {
            plot_ui(ui, plot, refit, theme);
        }
    }
}

/// The load the diagram's view reaches by default: a quarter past the
/// furthest cycle, within the straight column's range `load_max` (the
/// load shown may lie beyond: panning or "fit" after a zoom reaches it);
/// `None` without cycles (the whole range then).
fn cycles_reach(branches: &[&Branch], load_max: f64) -> Option<f64> {
    let furthest = branches
        .iter()
        .flat_map(|b| b.every_cycle().map(|c| c.load))
        .reduce(f64::max)?;
    let end = (1.25 * furthest).min(load_max);
    (end > 0.0).then_some(end)
}

/// The straight column's stretches over `[0, load_max]`, stable or not,
/// from the app's analysis when it is of this column.
fn equilibrium(state: &AppState, load_max: f64) -> Vec<(f64, f64, bool)> {
    let model = state.model().at_load(0.0);
    state
        .analysis()
        .filter(|analysis| *analysis.key == model)
        .map(|analysis| {
            analysis
                .ranges
                .iter()
                .filter(|(from, _, _)| *from < load_max)
                .map(|&(from, to, s)| (from, to.min(load_max), s == State::Stable))
                .collect()
        })
        .unwrap_or_default()
}

/// The running column's largest `|phi_i|` over its last period (that of
/// the cycle nearest the current load, else of the onset), once the
/// history holds a whole period.
fn live_swing(history: &History, branches: &[&Branch], load: f64) -> Option<f64> {
    let period = branches
        .iter()
        .flat_map(|b| b.every_cycle())
        .min_by(|a, b| (a.load - load).abs().total_cmp(&(b.load - load).abs()))
        .map(|cycle| cycle.period_secs)
        .or_else(|| {
            branches
                .first()
                .map(|b| std::f64::consts::TAU / b.hopf().frequency_rad_per_s)
        })?
        .min(HISTORY_SECS);
    let now = history.samples().last()?.t_secs;
    let oldest = history.samples().next()?.t_secs;
    if now - oldest < period {
        return None;
    }
    history
        .samples()
        .filter(|o| o.t_secs >= now - period)
        .flat_map(|o| o.angles_rad.iter().map(|a| a.abs()))
        .reduce(f64::max)
}

/// One line per flutter onset: soft or hard, and where its branch ended,
/// in `words`' language.
fn notes(onsets: &[Onset], words: &'static Words) -> Vec<String> {
    if onsets.is_empty() {
        return vec![tr!(words, "cycles-no-onset")];
    }
    onsets
        .iter()
        .flat_map(|onset| {
            let at = load_text(onset.load);
            match &onset.branch {
                Ok(branch) => {
                    let own = tr!(
                        words,
                        "cycles-branch",
                        name = branch.name(),
                        onset = if branch.soft() {
                            tr!(words, "cycles-onset-soft")
                        } else {
                            tr!(words, "cycles-onset-hard")
                        },
                        at = at,
                        end = end_words(words, branch.end)
                    );
                    let offshoots = branch.offshoots.iter().map(|o| {
                        tr!(
                            words,
                            "cycles-offshoot",
                            name = o.name(),
                            at = load_text(o.born.load),
                            end = end_words(words, o.end)
                        )
                    });
                    std::iter::once(own).chain(offshoots).collect()
                }
                Err(why) => vec![tr!(
                    words,
                    "cycles-no-branch",
                    at = at,
                    why = no_branch_words(words, why)
                )],
            }
        })
        .collect()
}

/// Why a branch's continuation stopped, in `words`' language.
fn end_words(words: &'static Words, end: BranchEnd) -> String {
    match end {
        BranchEnd::LeftRange => tr!(words, "cycles-end-left-range"),
        BranchEnd::LargeAmplitude => tr!(
            words,
            "cycles-end-large-amplitude",
            most = MAX_AMPLITUDE_RAD.to_string()
        ),
        BranchEnd::LongPeriod => tr!(
            words,
            "cycles-end-long-period",
            most = MAX_PERIOD_GROWTH.to_string()
        ),
        BranchEnd::Lost { load } => tr!(words, "cycles-end-lost", load = load_text(load)),
        BranchEnd::StickSlip { load } => {
            tr!(words, "cycles-end-stick-slip", load = load_text(load))
        }
        BranchEnd::Unresolved { load } => tr!(
            words,
            "cycles-end-unresolved",
            load = load_text(load),
            tolerance = format!("{TRIVIAL_TOLERANCE:e}")
        ),
        BranchEnd::PointLimit => tr!(
            words,
            "cycles-end-point-limit",
            most = MAX_POINTS.to_string()
        ),
        BranchEnd::Cancelled => tr!(words, "cycles-end-cancelled"),
    }
}

/// Why no branch was followed from an onset, in `words`' language.
fn no_branch_words(words: &'static Words, why: &NoBranch) -> String {
    match why {
        NoBranch::Reversible => tr!(words, "cycles-no-branch-reversible"),
        NoBranch::Degenerate => tr!(words, "cycles-no-branch-degenerate"),
        NoBranch::NotConverged => tr!(words, "cycles-no-branch-not-converged"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;
    use crate::sim::{EngineKind, Simulation};

    fn damped_ziegler() -> Model {
        let mut model = PresetId::Ziegler1952.model();
        model.column.c1_nms_per_rad = 0.3;
        model.column.c2_nms_per_rad = 0.3;
        model
    }

    /// The diagram's curve starts at the Hopf point and runs on unbroken;
    /// the live dot of a run on the cycle is the cycle's amplitude, and
    /// there is no dot before the history holds a period.
    #[test]
    fn the_curve_starts_at_the_onset_and_a_run_on_the_cycle_sits_on_it() {
        let model = damped_ziegler();
        let never = AtomicBool::new(false);
        let onsets = cycle_branches(&model, 0.0, 2.4, &never).unwrap();
        let branch = onsets[0].branch.as_ref().unwrap();
        let runs = branch.runs();
        assert_eq!(runs.len(), 1, "a stable branch is one run");
        let (points, stable) = &runs[0];
        assert!(*stable);
        assert_eq!(points[0], [branch.hopf().load, 0.0]);
        assert_eq!(points.len(), branch.cycles.len() + 1);
        let cycle = crate::analysis::cycles_at(&model, branch, 2.2).remove(0);
        let at = model.at_load(2.2);
        let mut sim = Simulation::new(
            at,
            EngineKind::Reference,
            cycle.start_state(&at),
            1.0 / 60.0,
        )
        .unwrap();
        let mut history = History::default();
        history.push(sim.observe());
        let branches = [branch];
        sim.run(0.5 * cycle.period_secs, |o| history.push(o.clone()));
        assert_eq!(live_swing(&history, &branches, 2.2), None);
        sim.run(cycle.period_secs, |o| history.push(o.clone()));
        let swing = live_swing(&history, &branches, 2.2).unwrap();
        assert!(
            (swing / cycle.largest_amplitude_rad() - 1.0).abs() < 1e-4,
            "{swing} vs {cycle:?}"
        );
        let notes = notes(&onsets, crate::i18n::words(crate::i18n::Language::English));
        assert!(
            notes[0].starts_with("cycle-1: soft onset at p = 1.9143"),
            "{notes:?}"
        );
    }

    /// A chain too long to follow in the window is told so, not left
    /// spinning, and a column after it is computed again.
    #[test]
    fn a_long_chain_is_told_to_use_the_command_line() {
        let mut panel = PostCriticalPanel::default();
        let mut chain = damped_ziegler();
        chain.column.rods = 20;
        for (model, too_long) in [(chain, true), (damped_ziegler(), false)] {
            let key = (model, 2.0);
            panel.follow(key);
            panel.jobs.wait();
            panel.receive();
            let (got, diagram) = panel.diagram.as_ref().unwrap();
            assert_eq!(*got, key);
            match diagram {
                Err(why) => assert!(
                    too_long && matches!(why, NoDiagram::TooLong { rods: 20 }),
                    "{why:?}"
                ),
                Ok(onsets) => assert!(!too_long && onsets[0].branch.is_ok()),
            }
        }
    }
}
