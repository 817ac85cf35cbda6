//! The stability-map panel: the load against a second parameter, computed
//! off the UI thread on every core (coarse first), drawn as coloured cells
//! with the boundaries as curves; a click sets both parameters.

use std::sync::atomic::AtomicUsize;

use eframe::egui::{self, Color32, ColorImage, TextureHandle, TextureOptions};
use egui_plot::{Line, Plot, PlotImage, PlotPoint, PlotPoints, Points};

use super::map_key::{Readout, cell_at, key_ui, readout_ui};
use super::{TabSpec, TabView, save_buttons};
use crate::analysis::{
    AnalysisError, MapSpec, RowResult, State, compute_map, default_map_axis,
    map_boundaries as boundaries,
};
use crate::app::View;
use crate::app::action::{Action, Actions};
use crate::app::jobs::{Cancel, Jobs};
use crate::app::plot_frame::{Fit, SingleClick, axes, refit_if};
use crate::app::state::AppState;
use crate::app::theme::Theme;
use crate::format::number_text;
use crate::model::{Axis, Model};
use crate::plot::map_scale::{largest_rate, rate_strength};

/// Cells along the load and along the second parameter.
pub const MAP_LOADS: usize = 256;
pub const MAP_VALUES: usize = 256;

/// The map shown: its spec, its rows as they arrive, its picture.
struct Shown {
    spec: MapSpec,
    rows: Vec<Option<RowResult>>,
    texture: Option<TextureHandle>,
    /// Rows arrived since the texture was made.
    stale: bool,
    /// Why the map could not start, if it could not.
    error: Option<MapError>,
}

impl Shown {
    fn new(spec: MapSpec, error: Option<MapError>) -> Self {
        Self {
            rows: vec![None; spec.values],
            spec,
            texture: None,
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

/// What the map's job sends: a row as it is done, or why the map stopped.
type RowMessage = Result<(usize, RowResult), AnalysisError>;

/// Computes the rows of `spec`, each sent as it is done. One core is left
/// to the window, so the frame rate holds while the map is computed.
fn compute_rows(spec: &MapSpec, cancel: &Cancel, send: &(dyn Fn(RowMessage) + Sync)) {
    let threads = std::thread::available_parallelism()
        .map_or(1, |n| n.get().saturating_sub(1))
        .max(1);
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
    title: "stability map",
    tooltip: "the stability of every load against a second parameter",
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
            .and_then(|old| old.texture);
        let grids = spec.load_grid().and_then(|_| spec.value_grid());
        let started = grids.map_err(MapError::Grid).and_then(|_| {
            self.jobs
                .request(spec.clone(), compute_rows)
                .map_err(MapError::NoThread)
        });
        let mut shown = Shown::new(spec, started.err());
        if kept.is_some() {
            shown.texture = kept;
            shown.stale = false;
        }
        self.shown = Some(shown);
    }

    /// Takes the rows that came in for the map shown.
    fn receive(&mut self) {
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

    /// Blocks until the current map is complete (for pictures and tests).
    pub fn wait(&mut self) {
        self.jobs.wait();
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
            ui.colored_label(theme.error, error.to_string());
        }
        if done < total {
            #[expect(clippy::cast_precision_loss, reason = "row counts")]
            let fraction = done as f32 / total as f32;
            ui.add(egui::ProgressBar::new(fraction).text(format!("rows {done} of {total}")));
        }
        if let Some(reason) = job.rows.iter().flatten().find_map(|r| r.as_ref().err()) {
            ui.colored_label(
                theme.warning,
                format!("grey rows have no analysis: {reason}"),
            );
        }
        if job.stale || job.texture.is_none() {
            let image = map_image(&job.rows, job.spec.loads, theme);
            match &mut job.texture {
                Some(texture) => texture.set(image, TextureOptions::NEAREST),
                None => {
                    job.texture = Some(ui.ctx().load_texture(
                        "stability map",
                        image,
                        TextureOptions::NEAREST,
                    ));
                }
            }
            job.stale = false;
        }
        let texture = job.texture.as_ref()?;
        self.fit
            .bar_ui(ui, for_picture, |ui| save_buttons(ui, None, actions));
        key_ui(ui, theme);
        if !for_picture {
            readout_ui(ui, self.hovered.as_ref(), job.spec.axis.name(), theme);
        }
        let spec = &job.spec;
        let refit = self.fit.refit((
            self.generation,
            spec.axis.name().to_owned(),
            spec.axis_range,
            spec.load_range,
        ));
        let (click, double, pointer) = map_plot_ui(ui, job, texture, model, refit, theme);
        let hovered = pointer.and_then(|point| cell_at(spec, &job.rows, point.x, point.y));
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
        ui.horizontal(|ui| {
            let label = ui.label("load p against");
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
                .on_hover_text("the map's second parameter (its range below restarts the map)");
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
            ui.label("from");
            let (mut lo, mut hi) = self.range;
            let speed = 0.01 * (hi - lo).abs().max(1e-6);
            ui.add(range_field(&mut lo, speed))
                .accessible_name("map range from")
                .on_hover_text("where the second parameter starts");
            ui.label("to");
            ui.add(range_field(&mut hi, speed))
                .accessible_name("map range to")
                .on_hover_text("where the second parameter ends");
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

/// A number field for the map's range.
fn range_field(value: &mut f64, speed: f64) -> egui::DragValue<'_> {
    egui::DragValue::new(value)
        .speed(speed)
        .custom_formatter(|v, _| number_text(v))
}

/// The colour of a cell: its state, brighter the faster it grows or decays
/// (square root of the rate over the map's largest).
fn cell_color(state: State, growth_per_s: f64, scale_per_s: f64, theme: &Theme) -> Color32 {
    let base = theme.state_color(state);
    let strength = rate_strength(growth_per_s, scale_per_s);
    #[expect(clippy::cast_possible_truncation, reason = "a fraction in [0, 1]")]
    base.gamma_multiply(0.3 + 0.7 * strength as f32)
}

/// The map as an image, one pixel per cell, the first row at the bottom;
/// rows not computed yet take the nearest computed row's colours, rows
/// without analysis are grey.
#[must_use]
pub fn map_image(rows: &[Option<RowResult>], loads: usize, theme: &Theme) -> ColorImage {
    let scale = largest_rate(rows.iter().flatten().flatten());
    let height = rows.len();
    let mut image = ColorImage::filled([loads, height], theme.no_data);
    let nearest = |j: usize| {
        (0..height)
            .flat_map(|d| [j.checked_sub(d), Some(j + d)])
            .flatten()
            .find_map(|k| rows.get(k).and_then(Option::as_ref))
    };
    for j in 0..height {
        let Some(Ok(row)) = nearest(j) else {
            continue;
        };
        let y = height - 1 - j;
        for (i, cell) in row.cells.iter().enumerate().take(loads) {
            image.pixels[y * loads + i] = cell_color(cell.state, cell.growth_per_s, scale, theme);
        }
    }
    image
}

/// The map with its boundaries and the current point. Returns a click's
/// pick this frame, whether the frame completed a double-click, and where
/// the pointer is on the map.
fn map_plot_ui(
    ui: &mut egui::Ui,
    job: &Shown,
    texture: &TextureHandle,
    model: &Model,
    refit: bool,
    theme: &Theme,
) -> (Option<Pick>, bool, Option<PlotPoint>) {
    let spec = &job.spec;
    let (p0, p1) = spec.load_range;
    let (y0, y1) = spec.axis_range;
    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
    let (cell_x, cell_y) = (
        (p1 - p0) / (spec.loads.max(2) - 1) as f64,
        (y1 - y0) / (spec.values.max(2) - 1) as f64,
    );
    let axis_name = spec.axis.name();
    let plot = Plot::new("stability map")
        .default_x_bounds(p0 - 0.5 * cell_x, p1 + 0.5 * cell_x)
        .default_y_bounds(y0 - 0.5 * cell_y, y1 + 0.5 * cell_y);
    let response = refit_if(axes(plot, "p = P l/k", axis_name), refit).show(ui, |plot_ui| {
        #[expect(clippy::cast_possible_truncation, reason = "plot sizes")]
        let size = [(p1 - p0 + cell_x) as f32, (y1 - y0 + cell_y) as f32];
        plot_ui.image(PlotImage::new(
            "map",
            texture.id(),
            PlotPoint::new(0.5 * (p0 + p1), 0.5 * (y0 + y1)),
            size,
        ));
        for curve in boundaries(&job.rows) {
            if curve.len() > 1 {
                plot_ui.line(
                    Line::new("boundary", PlotPoints::from(curve))
                        .color(theme.text)
                        .width(1.5 * theme.stroke_scale),
                );
            }
        }
        let here = [model.load_p(), spec.axis.get(model)];
        plot_ui.points(
            Points::new("now", vec![here])
                .radius(5.0 * theme.stroke_scale)
                .color(theme.now)
                .filled(true),
        );
        plot_ui.pointer_coordinate()
    });
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
