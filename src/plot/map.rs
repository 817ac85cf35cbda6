//! The stability map described once: each cell in its state's colour,
//! stronger the faster it grows or decays, the boundaries between states
//! as lines, on axes of the load and the second parameter; in the window
//! the current model's point.

use crate::i18n::{Words, state_name};
use crate::tr;
use std::sync::Arc;

use super::axis_words;
use super::boundary::BoundaryPlane;
use super::map_words;
use super::spec::{
    CellGrid, Entry, Ink, Mark, OffView, Plot, Sheet, Size, Swatch, Ticks, View, Weight,
};
use crate::analysis::{Boundaries, MapSpec, Row, RowResult, State, map_boundaries};
use crate::format::number_text;

impl CellGrid {
    /// The cells of `rows` on `spec`'s grid: a row not computed yet takes
    /// the nearest computed row's cells (a map coming in fills at once).
    #[must_use]
    pub fn new(spec: &MapSpec, rows: &[Option<RowResult>]) -> Self {
        let largest_per_s = largest_rate(rows.iter().flatten().flatten());
        let (columns, height) = (spec.loads, rows.len());
        let nearest = |j: usize| {
            (0..height)
                .flat_map(|d| [j.checked_sub(d), Some(j + d)])
                .flatten()
                .find_map(|k| rows.get(k).and_then(Option::as_ref))
        };
        let mut cells = vec![None; columns * height];
        for j in 0..height {
            let Some(Ok(row)) = nearest(j) else {
                continue;
            };
            for (i, cell) in row.cells.iter().enumerate().take(columns) {
                cells[j * columns + i] =
                    Some((cell.state, rate_strength(cell.growth_per_s, largest_per_s)));
            }
        }
        Self {
            columns,
            rows: height,
            cells,
            largest_per_s,
        }
    }
}

/// The largest size of a growth rate over the map's rows: the rate that
/// takes the deepest colour.
#[must_use]
pub fn largest_rate<'a>(rows: impl IntoIterator<Item = &'a Row>) -> f64 {
    rows.into_iter()
        .flat_map(|row| row.cells.iter().map(|c| c.growth_per_s.abs()))
        .filter(|g| g.is_finite())
        .fold(0.0, f64::max)
}

/// How deep a cell's colour is, in [0, 1]: the square root of its rate over
/// the map's largest ([`largest_rate`]), so slow rates still show.
#[must_use]
pub fn rate_strength(growth_per_s: f64, largest_per_s: f64) -> f64 {
    if largest_per_s > 0.0 {
        (growth_per_s.abs() / largest_per_s).sqrt().clamp(0.0, 1.0)
    } else {
        0.0
    }
}

/// A computed map as a figure draws it: what was asked and every row's
/// answer.
#[derive(Clone, Debug)]
pub struct MapData {
    pub spec: MapSpec,
    pub rows: Vec<Option<RowResult>>,
}

impl MapData {
    /// The map's sheet on paper, in `words`.
    #[must_use]
    pub fn sheet(&self, words: &'static Words) -> Sheet {
        StabilityMap {
            spec: &self.spec,
            rows: &self.rows,
            grid: Arc::new(CellGrid::new(&self.spec, &self.rows)),
            now: None,
            followed: None,
            words,
        }
        .sheet()
    }
}

/// What the map shows.
#[derive(Clone, Debug)]
pub struct StabilityMap<'a> {
    pub spec: &'a MapSpec,
    pub rows: &'a [Option<RowResult>],
    /// [`CellGrid::new`] of the rows (made once per change of them).
    pub grid: Arc<CellGrid>,
    /// The current model's point `[load, value]` (the window's).
    pub now: Option<[f64; 2]>,
    /// The boundaries followed over the map's axes (the window's, once
    /// computed): soft and hard onsets, folds of cycles, bands of
    /// hysteresis and special points drawn over the cells.
    pub followed: Option<&'a Boundaries>,
    /// The language of the axes and the key.
    pub words: &'static Words,
}

/// `value` to three significant digits (a key's scale needs no more).
fn significant(value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    let unit = 10f64.powf(value.abs().log10().floor() - 2.0);
    (value / unit).round() * unit
}

impl StabilityMap<'_> {
    /// The cells' rectangle: each cell centred on its load and value (a
    /// count such as `rods` a row per whole number, one unit high).
    fn extent(&self) -> ((f64, f64), (f64, f64)) {
        let spec = self.spec;
        let half_step = |(lo, hi): (f64, f64), n: usize| {
            #[expect(clippy::cast_precision_loss, reason = "cell counts")]
            let step = if n > 1 {
                (hi - lo) / (n - 1) as f64
            } else {
                1.0
            };
            0.5 * step
        };
        let hx = half_step(spec.load_range, spec.loads);
        let hy = if spec.axis.counts() {
            0.5
        } else {
            half_step(spec.axis_range, spec.values)
        };
        let ((p0, p1), (y0, y1)) = (spec.load_range, spec.axis_range);
        ((p0 - hx, p1 + hx), (y0 - hy, y1 + hy))
    }

    /// The followed boundaries as the boundaries' plane draws them.
    fn plane(&self) -> Option<BoundaryPlane<'_>> {
        Some(BoundaryPlane {
            found: self.followed?,
            axis: &self.spec.axis,
            axis_range: self.spec.axis_range,
            load_range: self.spec.load_range,
            words: self.words,
            over_cells: true,
        })
    }

    /// The map and its key.
    #[must_use]
    pub fn sheet(&self) -> Sheet {
        Sheet {
            legend: self.legend(),
            plots: vec![self.plot()],
        }
    }

    /// The map: the cells, the boundaries, the current point.
    fn plot(&self) -> Plot {
        let (x, y) = self.extent();
        let mut marks = vec![Mark::Cells {
            x,
            y,
            grid: Arc::clone(&self.grid),
        }];
        marks.extend(
            map_boundaries(self.rows)
                .into_iter()
                .filter(|curve| curve.len() > 1)
                .map(|points| Mark::Line {
                    points,
                    ink: Ink::Main,
                    weight: Weight::Fine,
                    dashed: false,
                }),
        );
        if let Some(plane) = self.plane() {
            marks.extend(plane.marks(true, 0.03 * (x.1 - x.0)));
        }
        marks.extend(
            map_words::state_words(&self.grid, x, y)
                .into_iter()
                .map(|(at, state)| Mark::Label {
                    at,
                    text: state_name(self.words, state),
                    of: None,
                }),
        );
        if let Some(now) = self.now {
            marks.push(Mark::Markers {
                points: vec![now],
                ink: Ink::Now,
                size: Size::Regular,
                filled: true,
                off_view: OffView::Hidden,
            });
        }
        Plot {
            id: "stability map",
            x_label: tr!(self.words, "axis-load"),
            y_label: axis_words(&self.spec.axis, self.words),
            x_ticks: Ticks::Plain,
            view: View::Ranges { x, y },
            marks,
            far_left: Vec::new(),
        }
    }

    /// The key: the states met, rows without analysis, the colours'
    /// strength, the critical loads and the current point.
    fn legend(&self) -> Vec<Entry> {
        let cells = &self.grid.cells;
        let mut entries: Vec<Entry> = [State::Stable, State::Flutter, State::Divergence]
            .into_iter()
            .filter(|&state| cells.iter().flatten().any(|c| c.0 == state))
            .map(|state| {
                Entry::new(
                    Swatch::Scale(vec![Ink::Cell(state, 1.0)]),
                    state_name(self.words, state),
                )
            })
            .collect();
        if self.rows.iter().flatten().any(Result::is_err) {
            entries.push(Entry::new(
                Swatch::Scale(vec![Ink::NoData]),
                tr!(self.words, "legend-no-analysis"),
            ));
        }
        entries.push(Entry::new(
            Swatch::Scale(vec![
                Ink::Cell(State::Flutter, 0.0),
                Ink::Cell(State::Flutter, 1.0),
            ]),
            tr!(
                self.words,
                "legend-stronger",
                largest = number_text(significant(self.grid.largest_per_s))
            ),
        ));
        entries.push(Entry::new(
            Swatch::Line(Ink::Main),
            tr!(self.words, "legend-critical-loads"),
        ));
        if let Some(plane) = self.plane() {
            entries.extend(plane.legend());
        }
        if let Some(now) = self.now {
            entries.push(Entry::new(
                Swatch::Marker(Ink::Now, true),
                self.now_words(now),
            ));
        }
        entries
    }

    /// The present's entry in the key: "now", or why its dot is not on the
    /// map (the column lies off the map's axes).
    fn now_words(&self, [load, value]: [f64; 2]) -> String {
        let words = self.words;
        let ((p0, p1), (y0, y1)) = (self.spec.load_range, self.spec.axis_range);
        let beyond = |name: &str, x: f64, (lo, hi): (f64, f64)| {
            let (id, bound) = if x < lo {
                ("legend-now-below", lo)
            } else if x > hi {
                ("legend-now-above", hi)
            } else {
                return None;
            };
            Some(words.with(
                id,
                &[
                    ("name", name.to_owned().into()),
                    ("value", number_text(x).into()),
                    ("bound", number_text(bound).into()),
                ],
            ))
        };
        let axis = self.spec.axis.name();
        if !value.is_finite() {
            return tr!(words, "legend-now-no-value", axis = axis);
        }
        let off: Vec<String> = [beyond("p", load, (p0, p1)), beyond(axis, value, (y0, y1))]
            .into_iter()
            .flatten()
            .collect();
        if off.is_empty() {
            tr!(words, "legend-now")
        } else {
            tr!(words, "legend-now-off", why = off.join(", "))
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicBool, AtomicUsize};

    use super::*;
    use crate::analysis::compute_map;
    use crate::model::Axis;
    use crate::model::PresetId;

    /// Ziegler's column against its damping level: on the undamped row the
    /// cells are stable below p = 7/2 - sqrt 2, flutter to 7/2 + sqrt 2,
    /// divergence beyond; the strongest cell has strength 1; a row not
    /// computed yet shows its nearest row's cells; the map's rectangle
    /// holds every cell whole.
    #[test]
    fn the_cells_follow_the_critical_loads() {
        let model = PresetId::Ziegler1952.model();
        let spec = MapSpec {
            axis: Axis::parse("damping", &model).unwrap(),
            model,
            load_range: (0.0, 8.0),
            loads: 33,
            axis_range: (0.0, 0.2),
            values: 3,
        };
        let rows = Mutex::new(vec![None; spec.values]);
        compute_map(
            &spec,
            1,
            &AtomicBool::new(false),
            &AtomicUsize::new(0),
            &|j, row| {
                rows.lock().unwrap()[j] = Some(row);
            },
        )
        .unwrap();
        let mut rows = rows.into_inner().unwrap();
        let grid = CellGrid::new(&spec, &rows);
        let (flutter, divergence) = (3.5 - 2f64.sqrt(), 3.5 + 2f64.sqrt());
        for (i, cell) in grid.cells[..spec.loads].iter().enumerate() {
            let load = 0.25 * f64::from(u32::try_from(i).unwrap());
            let expected = if load < flutter {
                State::Stable
            } else if load < divergence {
                State::Flutter
            } else {
                State::Divergence
            };
            assert_eq!(cell.unwrap().0, expected, "p = {load}");
        }
        let strongest = grid.cells.iter().flatten().map(|c| c.1).fold(0.0, f64::max);
        assert!((strongest - 1.0).abs() < 1e-12);
        rows[2] = None;
        let filled = CellGrid::new(&spec, &rows);
        assert_eq!(filled.cells[2 * 33..], grid.cells[33..2 * 33]);
        let map = StabilityMap {
            spec: &spec,
            rows: &rows,
            grid: Arc::new(grid),
            now: None,
            followed: None,
            words: crate::i18n::words(crate::i18n::Language::English),
        };
        let plot = map.plot();
        let View::Ranges { x, y } = plot.view else {
            panic!("a map has ranges");
        };
        assert_eq!((x, y), ((-0.125, 8.125), (-0.05, 0.25)));
        // The present off the map's axis is said, not silently missing.
        let off = StabilityMap {
            now: Some([1.0, 0.3]),
            ..map.clone()
        };
        let said = off.legend().last().unwrap().text.clone();
        assert_eq!(said, "now: off the map (damping = 0.3 is above 0.2)");
        let on = StabilityMap {
            now: Some([1.0, 0.1]),
            ..map.clone()
        };
        assert_eq!(on.legend().last().unwrap().text, "now");
        // Each state named once, inside its own range of loads.
        let words: Vec<(f64, &str)> = plot
            .marks
            .iter()
            .filter_map(|mark| match mark {
                Mark::Label { at, text, .. } => Some((at[0], text.as_str())),
                _ => None,
            })
            .collect();
        assert_eq!(
            words.iter().map(|w| w.1).collect::<Vec<_>>(),
            ["stable", "flutter", "divergence"]
        );
        assert!(words[0].0 < flutter, "{words:?}");
        assert!((flutter..divergence).contains(&words[1].0), "{words:?}");
        assert!(words[2].0 > divergence, "{words:?}");
    }
}
