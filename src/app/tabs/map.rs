//! The stability-map panel: the load against a second parameter, computed
//! off the UI thread on every core (coarse first), drawn as coloured cells
//! with the boundaries as curves; a click sets both parameters.

use crate::app::speak::Speak as _;
use crate::tr;
use std::sync::Arc;
use std::sync::atomic::AtomicUsize;

use eframe::egui;
use egui_plot::{PlotPoint, PlotResponse};

use super::map_readout::{Readout, cell_at, readout_ui};
use super::{TabSpec, TabView, save_buttons};
use crate::analysis::{
    AnalysisError, Boundaries, BoundarySpec, MapSpec, RowResult, boundaries_until, compute_map,
    default_map_axis,
};
use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::jobs::{Cancel, Jobs};
use crate::app::plot_draw::{legend_ui, plot_ui};
use crate::app::plot_frame::{Fit, SingleClick};
use crate::app::state::AppState;
use crate::app::theme::{Theme, color};
use crate::format::number_text;
use crate::model::{Axis, Model};
use crate::plot::map::StabilityMap;
use crate::plot::spec::CellGrid;

/// Cells along the load and along the second parameter.
pub const MAP_LOADS: usize = 256;
pub const MAP_VALUES: usize = 256;

/// The map shown: its spec, its rows as they arrive, its picture.
struct Shown {
    spec: MapSpec,
    rows: Vec<Option<RowResult>>,
    /// The cells as last made (kept from the map before while its axes
    /// are the same, until this one's rows arrive).
    grid: Option<Arc<CellGrid>>,
    /// Rows arrived since the grid was made.
    stale: bool,
    /// Why the map could not start, if it could not.
    error: Option<MapError>,
}

impl Shown {
    fn new(spec: MapSpec, error: Option<MapError>) -> Self {
        Self {
            rows: vec![None; spec.values],
            spec,
            grid: None,
            stale: true,
            error,
        }
    }

    /// Rows computed so far.
    fn done(&self) -> usize {
        self.rows.iter().flatten().count()
    }
}

/// Why the map shows no map, or stopped.
#[derive(Debug, thiserror::Error)]
pub enum MapError {
    #[error(transparent)]
    Axis(#[from] crate::model::ModelError),
    #[error("map range {lo} to {hi} is empty")]
    EmptyRange { lo: f64, hi: f64 },
    #[error(transparent)]
    Grid(AnalysisError),
    #[error("no thread for the map: {0}")]
    NoThread(std::io::Error),
    #[error("the map stopped: {0}")]
    Stopped(AnalysisError),
}

impl MapError {
    /// The error in `words`' language.
    #[must_use]
    pub fn words(&self, words: &'static crate::i18n::Words) -> String {
        use crate::i18n::{analysis_error, model_error};
        match self {
            Self::Axis(error) => model_error(words, error),
            Self::EmptyRange { lo, hi } => tr!(
                words,
                "map-empty-range",
                lo = crate::format::Shown(*lo).to_string(),
                hi = crate::format::Shown(*hi).to_string()
            ),
            Self::Grid(error) => analysis_error(words, error),
            Self::NoThread(error) => tr!(words, "map-no-thread", why = error.to_string()),
            Self::Stopped(error) => {
                tr!(words, "map-stopped", why = analysis_error(words, error))
            }
        }
    }
}

/// What the map's job sends: a row as it is done, or why the map stopped.
type RowMessage = Result<(usize, RowResult), AnalysisError>;

/// Computes the rows of `spec`, each sent as it is done. One core is left
/// to the window, so the frame rate holds while the map is computed.
fn compute_rows(spec: &MapSpec, cancel: &Cancel, send: &(dyn Fn(RowMessage) + Sync)) {
    let threads = crate::machine_threads().saturating_sub(1).max(1);
    let done = AtomicUsize::new(0);
    // A cancelled map stops between rows: what it did not compute is for no one.
    let on_row = |j, row| send(Ok((j, row)));
    if let Err(error) = compute_map(spec, threads, cancel.flag(), &done, &on_row) {
        send(Err(error));
    }
}

/// What the map's view shows: the "reset all" count, the second axis, its
/// range, the load range.
type MapAxes = (u64, String, (f64, f64), (f64, f64));

pub const TAB: TabSpec = TabSpec {
    tab: super::Tab::Map,
    id: "map",
    background: true,
    make: || Box::new(MapPanel::default()),
};

/// The panel's choices and its current job.
pub struct MapPanel {
    axis: Option<Axis>,
    range: (f64, f64),
    /// The rows being computed, newest spec first.
    jobs: Jobs<MapSpec, RowMessage>,
    shown: Option<Shown>,
    /// The view refits when the axes change: (second axis, its range, loads).
    fit: Fit<MapAxes>,
    /// A click sets the load and the parameter unless it was a double-click.
    click: SingleClick<Pick>,
    /// The state's "reset all" count this frame.
    generation: u64,
    /// The cell under the pointer in the last frame (shown above the map).
    hovered: Option<Readout>,
    /// The boundaries followed over the map's axes, newest first.
    following: Jobs<BoundarySpec, Result<Boundaries, AnalysisError>>,
    /// The last that came in, for the plane it was asked for.
    followed: Option<(BoundarySpec, Result<Boundaries, AnalysisError>)>,
}

impl Default for MapPanel {
    fn default() -> Self {
        Self {
            axis: None,
            range: (0.0, 1.0),
            jobs: Jobs::new("stability map"),
            shown: None,
            fit: Fit::default(),
            click: SingleClick::default(),
            generation: 0,
            hovered: None,
            following: Jobs::new("stability boundaries"),
            followed: None,
        }
    }
}

/// What a click on the map asks for: the load and the second parameter.
pub struct Pick {
    pub load: f64,
    pub axis: Axis,
    pub value: f64,
}

impl MapPanel {
    /// The map's spec for `model`: the second parameter is set to the start
    /// of its range, so moving along it (a click) does not restart the map.
    fn spec(&self, model: &Model, load_max: f64) -> Option<MapSpec> {
        let axis = self.axis.clone()?;
        let base = axis
            .apply(&model.at_load(0.0), self.range.0)
            .unwrap_or_else(|_| model.at_load(0.0));
        Some(MapSpec {
            model: base,
            axis,
            load_range: (0.0, load_max),
            loads: MAP_LOADS,
            axis_range: self.range,
            values: MAP_VALUES,
        })
    }

    /// Starts (or restarts) the map for the current model when what it shows changed.
    pub fn follow(&mut self, model: &Model, load_max: f64) {
        let fits = self
            .axis
            .as_ref()
            .is_some_and(|axis| Axis::parse(axis.name(), model).is_ok());
        if !fits {
            let (axis, range) = default_map_axis(model);
            self.axis = Some(axis);
            self.range = range;
        }
        let Some(spec) = self.spec(model, load_max) else {
            return;
        };
        self.follow_boundaries(&spec);
        if self.jobs.key() == Some(&spec) {
            return;
        }
        // While a slider is dragged the map restarts every frame: the last
        // picture stays up (same axes) until the new rows arrive.
        let same_axes = |old: &MapSpec| {
            (&old.axis, old.axis_range, old.load_range)
                == (&spec.axis, spec.axis_range, spec.load_range)
        };
        let kept = self
            .shown
            .take()
            .filter(|old| same_axes(&old.spec))
            .and_then(|old| old.grid);
        let grids = spec.load_grid().and_then(|_| spec.value_grid());
        let started = grids.map_err(MapError::Grid).and_then(|_| {
            self.jobs
                .request(spec.clone(), compute_rows)
                .map_err(MapError::NoThread)
        });
        let mut shown = Shown::new(spec, started.err());
        if kept.is_some() {
            shown.grid = kept;
            shown.stale = false;
        }
        self.shown = Some(shown);
    }

    /// Starts following the boundaries over `spec`'s plane when they are
    /// not already (a parameter that varies continuously only: the rods
    /// are counted).
    fn follow_boundaries(&mut self, spec: &MapSpec) {
        if spec.axis.counts() {
            return;
        }
        let wanted = plane_of(spec);
        if self.following.key() != Some(&wanted) {
            // No thread: the map is drawn without them.
            let _ = self.following.request(wanted, |spec, cancel, send| {
                let found = boundaries_until(spec, cancel.flag());
                if !cancel.requested() {
                    send(found);
                }
            });
        }
    }

    /// Takes the rows that came in for the map shown.
    fn receive(&mut self) {
        if let Some(last) = self.following.drain().last() {
            self.followed = Some(last);
        }
        let Some(shown) = &mut self.shown else {
            return;
        };
        for (spec, message) in self.jobs.drain() {
            if spec != shown.spec {
                continue;
            }
            match message {
                Ok((j, row)) => {
                    if let Some(slot) = shown.rows.get_mut(j) {
                        *slot = Some(row);
                        shown.stale = true;
                    }
                }
                Err(why) => shown.error = Some(MapError::Stopped(why)),
            }
        }
    }

    /// The second axis chosen, by name, and its range.
    #[must_use]
    pub fn axis_choice(&self) -> Option<(String, f64, f64)> {
        let axis = self.axis.as_ref()?;
        Some((axis.name().to_owned(), self.range.0, self.range.1))
    }

    /// Chooses the second axis `name` over `[lo, hi]` when it applies to
    /// `model` and the range is one; says why not otherwise.
    ///
    /// # Errors
    /// An axis the model does not have, or an empty or non-finite range.
    pub fn choose_axis(
        &mut self,
        model: &Model,
        (name, lo, hi): (&str, f64, f64),
    ) -> Result<(), MapError> {
        let axis = Axis::parse(name, model)?;
        if !(lo.is_finite() && hi.is_finite() && hi > lo) {
            return Err(MapError::EmptyRange { lo, hi });
        }
        self.axis = Some(axis);
        self.range = (lo, hi);
        Ok(())
    }

    /// Blocks until the current map and its boundaries are complete (for
    /// pictures and tests).
    pub fn wait(&mut self) {
        self.jobs.wait();
        self.following.wait();
        self.receive();
    }

    /// The panel: axis choice and range, progress, the map. Returns a click.
    fn draw(
        &mut self,
        ui: &mut egui::Ui,
        model: &Model,
        for_picture: bool,
        actions: &mut Actions,
        theme: &Theme,
    ) -> Option<Pick> {
        self.controls_ui(ui, model);
        self.receive();
        let busy = self.jobs.busy();
        let job = self.shown.as_mut()?;
        let done = job.done();
        let total = job.spec.values;
        if busy || (done < total && job.error.is_none()) {
            ui.ctx().request_repaint();
        }
        if let Some(error) = &job.error {
            ui.colored_label(color(theme.palette.error), error.words(ui.words()));
        }
        if done < total {
            #[expect(clippy::cast_precision_loss, reason = "row counts")]
            let fraction = done as f32 / total as f32;
            ui.add(egui::ProgressBar::new(fraction).text(tr!(
                ui.words(),
                "map-rows",
                done = done,
                total = total
            )));
        }
        if let Some(reason) = job.rows.iter().flatten().find_map(|r| r.as_ref().err()) {
            warn(ui, theme, "map-grey-rows", reason);
        }
        if job.stale || job.grid.is_none() {
            job.grid = Some(Arc::new(CellGrid::new(&job.spec, &job.rows)));
            job.stale = false;
        }
        let grid = Arc::clone(job.grid.as_ref()?);
        self.fit
            .bar_ui(ui, for_picture, |ui| save_buttons(ui, None, actions));
        let spec = &job.spec;
        let followed = followed_for(self.followed.as_ref(), spec);
        match followed {
            None if self.following.busy() => {
                ui.weak(tr!(ui.words(), "map-following"));
                ui.ctx()
                    .request_repaint_after(std::time::Duration::from_millis(100));
            }
            Some(Err(why)) => warn(ui, theme, "map-not-followed", why),
            _ => {}
        }
        let found = followed.and_then(|f| f.as_ref().ok());
        let sheet = StabilityMap {
            spec,
            rows: &job.rows,
            grid,
            now: Some([model.load_p(), spec.axis.get(model)]),
            followed: found,
            words: ui.words(),
        }
        .sheet();
        legend_ui(ui, &sheet.legend, theme);
        if !for_picture {
            readout_ui(ui, self.hovered.as_ref(), spec.axis.name(), theme);
        }
        let refit = self.fit.refit((
            self.generation,
            spec.axis.name().to_owned(),
            spec.axis_range,
            spec.load_range,
        ));
        let response = plot_ui(ui, sheet.plots.first()?, refit, theme);
        let (click, double, pointer) = clicked(&response, spec);
        // What a kick does is read at the pointer itself: a band of
        // hysteresis may be narrower than a cell.
        let hovered = pointer.and_then(|point| {
            let cell = cell_at(spec, &job.rows, point.x, point.y)?;
            let kick = found.and_then(|b| b.kick_at(point.y, point.x, cell.state));
            Some(Readout { kick, ..cell })
        });
        if hovered != self.hovered {
            // Shown above the map from the next frame: ask for it now.
            self.hovered = hovered;
            ui.ctx().request_repaint();
        }
        let now_secs = ui.input(|i| i.time);
        let window_secs = ui.ctx().options(|o| o.input_options.max_double_click_delay);
        let pick = self.click.update(click, double, now_secs, window_secs);
        if self.click.waiting() {
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_secs_f64(window_secs));
        }
        pick
    }

    fn controls_ui(&mut self, ui: &mut egui::Ui, model: &Model) {
        let words = ui.words();
        ui.horizontal(|ui| {
            let label = ui.label(tr!(words, "map-axis"));
            let current = self.axis.as_ref().map_or("", Axis::name);
            let mut chosen = current;
            egui::ComboBox::from_id_salt("map axis")
                .selected_text(current)
                .show_ui(ui, |ui| {
                    for name in Axis::names(model) {
                        if name != "load" {
                            ui.selectable_value(&mut chosen, name, name);
                        }
                    }
                })
                .response
                .labelled_by(label.id)
                .on_hover_text(tr!(words, "map-axis.tooltip"));
            if chosen != current
                && let Ok(axis) = Axis::parse(chosen, model)
            {
                let now = axis.get(model);
                self.range = if now.is_finite() && now > 0.0 {
                    (0.1 * now, 2.0 * now)
                } else {
                    (0.0, 1.0)
                };
                self.axis = Some(axis);
            }
            ui.label(tr!(words, "map-from"));
            let (mut lo, mut hi) = self.range;
            let speed = 0.01 * (hi - lo).abs().max(1e-6);
            ui.add(range_field(&mut lo, speed))
                .accessible_name(tr!(words, "map-from.name"))
                .on_hover_text(tr!(words, "map-from.tooltip"));
            ui.label(tr!(words, "map-to"));
            ui.add(range_field(&mut hi, speed))
                .accessible_name(tr!(words, "map-to.name"))
                .on_hover_text(tr!(words, "map-to.tooltip"));
            // An empty or reversed range is not taken; the old one stays.
            if lo.is_finite() && hi.is_finite() && hi > lo {
                self.range = (lo, hi);
            }
        });
    }
}

impl TabView for MapPanel {
    fn complete_background_work(&mut self, state: &AppState) {
        let model = state.model();
        self.follow(model, model.load_bar_max_p());
        self.wait();
    }
}

impl View for MapPanel {
    /// The stability map of the current parameters; a click on it sets the
    /// load and the map's second parameter.
    fn ui(&mut self, ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
        let model = *state.model();
        self.follow(&model, model.load_bar_max_p());
        self.generation = state.view_generation();
        if let Some(pick) = self.draw(ui, &model, state.for_picture(), actions, theme) {
            actions.push(Action::MapPick {
                axis: pick.axis,
                load: pick.load,
                value: pick.value,
            });
        }
    }
}

/// The message `id` with the analysis error `why` in its place, as a
/// warning.
fn warn(ui: &mut egui::Ui, theme: &Theme, id: &str, why: &AnalysisError) {
    let words = ui.words();
    ui.colored_label(
        color(theme.palette.warning),
        tr!(words, id, why = crate::i18n::analysis_error(words, why)),
    );
}

/// The boundaries `followed` for `spec`'s plane, if that is what they
/// were followed over.
fn followed_for<'a>(
    followed: Option<&'a (BoundarySpec, Result<Boundaries, AnalysisError>)>,
    spec: &MapSpec,
) -> Option<&'a Result<Boundaries, AnalysisError>> {
    let (key, found) = followed?;
    (*key == plane_of(spec)).then_some(found)
}

/// The plane of the map `spec`, as the boundaries are followed over it.
fn plane_of(spec: &MapSpec) -> BoundarySpec {
    BoundarySpec {
        model: spec.model,
        axis: spec.axis.clone(),
        axis_range: spec.axis_range,
        load_range: spec.load_range,
    }
}

/// A number field for the map's range.
fn range_field(value: &mut f64, speed: f64) -> egui::DragValue<'_> {
    egui::DragValue::new(value)
        .speed(speed)
        .custom_formatter(|v, _| number_text(v))
}

/// What the person did on the map's plot (its `response`): a click's pick
/// this frame, whether the frame completed a double-click, and where the
/// pointer is on the map.
fn clicked(
    response: &PlotResponse<Option<PlotPoint>>,
    spec: &MapSpec,
) -> (Option<Pick>, bool, Option<PlotPoint>) {
    let (p0, p1) = spec.load_range;
    let (y0, y1) = spec.axis_range;
    let (clicked, double) = (
        response.response.clicked(),
        response.response.double_clicked(),
    );
    let pointer = response.inner.filter(|_| response.response.hovered());
    let pick = response
        .inner
        .filter(|point| clicked && (y0..=y1).contains(&point.y) && (p0..=p1).contains(&point.x));
    let pick = pick.map(|point| Pick {
        load: point.x,
        axis: spec.axis.clone(),
        // A count (`rods`) is picked at the whole number its row shows.
        value: if spec.axis.counts() {
            point.y.round()
        } else {
            point.y
        },
    });
    (pick, double, pointer)
}
