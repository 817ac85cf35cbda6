//! Stability maps: the state and growth rate over the load and a second
//! parameter, one row per value of that parameter, each row with its exact
//! critical loads; rows computed coarse first, then where the boundaries run,
//! on every core.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use crate::analysis::AnalysisError;
use crate::analysis::critical::{bracketing_locus, bracketing_locus_through, critical_loads_along};
use crate::analysis::crossing::Transition;
use crate::analysis::locus::{load_grid, locus};
use crate::analysis::pencil::AffinePencil;
use crate::analysis::stability::{State, classify};
use crate::model::{Axis, Model};

/// What to map: the model, the second axis and both grids (evenly spaced,
/// ends included).
#[derive(Clone, Debug, PartialEq)]
pub struct MapSpec {
    pub model: Model,
    pub axis: Axis,
    pub load_range: (f64, f64),
    pub loads: usize,
    pub axis_range: (f64, f64),
    pub values: usize,
}

/// One cell: the state and the largest real part of the moving eigenvalues.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cell {
    pub state: State,
    pub growth_per_s: f64,
}

/// One row of the map: the cells at the grid loads, and the row's critical
/// loads over the load range (as `critical` finds them).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub value: f64,
    pub cells: Vec<Cell>,
    pub transitions: Vec<Transition>,
}

/// A row's answer: the row, or why this value makes no analysis.
pub type RowResult = Result<Row, AnalysisError>;

impl MapSpec {
    /// The grid loads.
    ///
    /// # Errors
    /// A bad range or count.
    pub fn load_grid(&self) -> Result<Vec<f64>, AnalysisError> {
        load_grid(self.load_range.0, self.load_range.1, self.loads)
    }

    /// The values of the second axis, one per row: evenly spaced, ends
    /// included; on an axis that counts (`rods`), each the nearest whole
    /// number (so rows may repeat one when there are more rows than whole
    /// numbers in the range).
    ///
    /// # Errors
    /// A bad range or count.
    pub fn value_grid(&self) -> Result<Vec<f64>, AnalysisError> {
        // The ends as the axis takes them ("eta = -1: must be in [0, 1]"),
        // before the grid's own checks.
        for end in [self.axis_range.0, self.axis_range.1] {
            self.axis.apply(&self.model, end)?;
        }
        let grid =
            load_grid(self.axis_range.0, self.axis_range.1, self.values).map_err(|e| match e {
                AnalysisError::BadRange { value, allowed, .. } => AnalysisError::BadRange {
                    what: "axis range",
                    value,
                    allowed,
                },
                other => other,
            })?;
        Ok(if self.axis.counts() {
            grid.into_iter().map(f64::round).collect()
        } else {
            grid
        })
    }

    /// The row at `value` of the second axis: the model with the axis there,
    /// its locus over the grid loads (the growth rates) and its critical
    /// loads (the states).
    ///
    /// # Errors
    /// A value the model or the analysis refuses.
    pub fn row(&self, value: f64) -> RowResult {
        let model = self.axis.apply(&self.model, value)?;
        let pencil = AffinePencil::new(&model)?;
        let (min, max) = self.load_range;
        // One locus for both where its evenly spaced loads can hold the cells.
        let (transitions, grid, stride) =
            match bracketing_locus_through(&pencil, (min, max), self.loads)? {
                Some((bracket, stride)) => {
                    (critical_loads_along(&pencil, &bracket)?, bracket, stride)
                }
                None => (
                    critical_loads_along(&pencil, &bracketing_locus(&pencil, min, max)?)?,
                    locus(&pencil, min, max, self.loads)?,
                    1,
                ),
            };
        let first = pencil.spectrum(min)?;
        let mut state = classify(&first.eigenvalues, first.scale_per_s).state;
        let mut next = transitions.iter().peekable();
        let cells = (0..grid.loads.len())
            .filter(|&i| grid.on_grid[i])
            .step_by(stride)
            .map(|i| {
                let p = grid.loads[i];
                // The state between critical loads is the one `critical` says.
                while let Some(t) = next.next_if(|t| t.load <= p) {
                    state = t.to;
                }
                let growth_per_s = grid
                    .moving_branches()
                    .iter()
                    .map(|branch| branch[i].re)
                    .fold(f64::NEG_INFINITY, f64::max);
                Cell {
                    state,
                    growth_per_s,
                }
            })
            .collect();
        Ok(Row {
            value,
            cells,
            transitions,
        })
    }
}

/// The order rows are computed in: every `stride`-th row first (coarse), then
/// level by level the rows halfway between computed ones, those where the
/// neighbours' critical loads differ (a boundary runs between them) before
/// the others.
struct Schedule {
    rows: usize,
    done: Vec<Option<Vec<Transition>>>,
}

impl Schedule {
    fn coarse(rows: usize) -> (Self, Vec<usize>, usize) {
        let stride = (rows / 16).next_power_of_two().max(1);
        let mut first: Vec<usize> = (0..rows).step_by(stride).collect();
        if first.last() != Some(&(rows - 1)) {
            first.push(rows - 1);
        }
        let schedule = Self {
            rows,
            done: vec![None; rows],
        };
        (schedule, first, stride)
    }

    /// The rows of the next level (stride halved), boundary rows first.
    fn level(&self, stride: usize) -> Vec<usize> {
        let computed: Vec<usize> = (0..self.rows).filter(|&j| self.done[j].is_some()).collect();
        let mut boundary = Vec::new();
        let mut interior = Vec::new();
        for pair in computed.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let differs = match (&self.done[a], &self.done[b]) {
                (Some(ta), Some(tb)) => !same_structure(ta, tb),
                _ => true,
            };
            let mut j = a + stride;
            while j < b {
                if differs {
                    boundary.push(j);
                } else {
                    interior.push(j);
                }
                j += stride;
            }
        }
        boundary.extend(interior);
        boundary
    }
}

/// Whether two rows have the same changes of stability at nearby loads.
fn same_structure(a: &[Transition], b: &[Transition]) -> bool {
    a.len() == b.len()
        && a.iter().zip(b).all(|(x, y)| {
            (x.from, x.to) == (y.from, y.to)
                && (x.load - y.load).abs() <= 0.02 * x.load.abs().max(y.load.abs()).max(1e-3)
        })
}

/// Computes every row of `spec` on `threads` threads, coarse first, calling
/// `on_row(j, row)` as each is done (from any of the threads). Stops early
/// when `cancel` is set; `done` counts finished rows.
///
/// # Errors
/// A bad grid (no row is computed then).
pub fn compute(
    spec: &MapSpec,
    threads: usize,
    cancel: &AtomicBool,
    done: &AtomicUsize,
    on_row: &(dyn Fn(usize, RowResult) + Sync),
) -> Result<(), AnalysisError> {
    spec.load_grid()?;
    let values = spec.value_grid()?;
    let (schedule, first, mut stride) = Schedule::coarse(values.len());
    let schedule = Mutex::new(schedule);
    let mut batch = first;
    loop {
        let next = AtomicUsize::new(0);
        std::thread::scope(|scope| {
            for _ in 0..threads.max(1) {
                scope.spawn(|| {
                    loop {
                        if cancel.load(Ordering::Relaxed) {
                            return;
                        }
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        let Some(&j) = batch.get(k) else {
                            return;
                        };
                        let row = spec.row(values[j]);
                        let transitions = row
                            .as_ref()
                            .map_or_else(|_| Vec::new(), |r| r.transitions.clone());
                        if let Ok(mut s) = schedule.lock() {
                            s.done[j] = Some(transitions);
                        }
                        on_row(j, row);
                        done.fetch_add(1, Ordering::Relaxed);
                    }
                });
            }
        });
        if cancel.load(Ordering::Relaxed) || stride <= 1 {
            return Ok(());
        }
        stride /= 2;
        batch = match schedule.lock() {
            Ok(s) => s.level(stride),
            Err(_) => return Ok(()),
        };
    }
}
#[must_use]
/// The map's default second axis and its range for a model: the roller's mass
/// ratio; for the columns the damping level (the paradox in a picture).
pub fn default_map_axis(model: &Model) -> (Axis, (f64, f64)) {
    if model.roller().is_some() {
        (Axis::Key(crate::model::Key::Nu), (0.005, 1.0))
    } else {
        (Axis::DampingLevel, (0.0, 0.5))
    }
}

/// The boundaries between states: each row's critical loads joined to the next row's of
/// the same kind and order.
#[must_use]
pub fn boundaries(rows: &[Option<RowResult>]) -> Vec<Vec<[f64; 2]>> {
    // A boundary's kind: the change of state and its order among the row's
    // changes of that kind.
    type Kind = (State, State, usize);
    let mut curves: Vec<(Kind, Vec<[f64; 2]>)> = Vec::new();
    let mut open: Vec<Kind> = Vec::new();
    for row in rows {
        let Some(Ok(Row {
            value, transitions, ..
        })) = row
        else {
            // A missing row breaks every curve.
            open.clear();
            continue;
        };
        let mut seen: Vec<Kind> = Vec::new();
        for Transition { load, from, to } in transitions {
            let k = seen.iter().filter(|s| (s.0, s.1) == (*from, *to)).count();
            let kind = (*from, *to, k);
            seen.push(kind);
            match curves.iter_mut().rev().find(|(c, _)| *c == kind) {
                Some((_, points)) if open.contains(&kind) => points.push([*load, *value]),
                _ => curves.push((kind, vec![[*load, *value]])),
            }
        }
        open = seen;
    }
    curves.into_iter().map(|(_, points)| points).collect()
}
