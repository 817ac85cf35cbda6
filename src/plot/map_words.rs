//! Where each state's name is written on the stability map: at the centre
//! of the largest label-shaped box that the state's cells fill, or nowhere
//! if no box of a readable size fits (the colour and the stripes still say).

use super::spec::CellGrid;
use crate::analysis::State;

/// A name's box at scale 1, as fractions of the map's width and height
/// (about a word of the plots' text on the window's map and on a figure).
const BOX_FRACTION: (f64, f64) = (0.2, 0.08);

/// The scales tried, largest first; below the last one no name is written.
const SCALES: [f64; 9] = [2.0, 1.75, 1.5, 1.3, 1.15, 1.0, 0.85, 0.7, 0.6];

/// Counts of each state's cells in every rectangle of the grid in O(1): a
/// summed-area table per state.
struct Counts {
    columns: usize,
    /// `(columns + 1) * (rows + 1)` prefix sums per state.
    sums: [Vec<u32>; 3],
}

fn slot(state: State) -> usize {
    match state {
        State::Stable => 0,
        State::Flutter => 1,
        State::Divergence => 2,
    }
}

impl Counts {
    fn new(grid: &CellGrid) -> Self {
        let (columns, rows) = (grid.columns, grid.rows);
        let width = columns + 1;
        let mut sums = [
            vec![0; width * (rows + 1)],
            vec![0; width * (rows + 1)],
            vec![0; width * (rows + 1)],
        ];
        for j in 0..rows {
            for i in 0..columns {
                let cell = grid.cells.get(j * columns + i).copied().flatten();
                for (k, table) in sums.iter_mut().enumerate() {
                    let here = u32::from(cell.is_some_and(|(state, _)| slot(state) == k));
                    table[(j + 1) * width + i + 1] =
                        here + table[j * width + i + 1] + table[(j + 1) * width + i]
                            - table[j * width + i];
                }
            }
        }
        Self { columns, sums }
    }

    /// How many of columns `i0..i1` by rows `j0..j1` are `state`'s.
    fn count(&self, state: State, (i0, i1): (usize, usize), (j0, j1): (usize, usize)) -> u32 {
        let table = &self.sums[slot(state)];
        let width = self.columns + 1;
        table[j1 * width + i1] + table[j0 * width + i0]
            - table[j0 * width + i1]
            - table[j1 * width + i0]
    }

    /// Whether columns `is` by rows `js` are `state`'s cells alone.
    fn filled(&self, state: State, is: (usize, usize), js: (usize, usize)) -> bool {
        let area = (is.1 - is.0) * (js.1 - js.0);
        usize::try_from(self.count(state, is, js)).is_ok_and(|n| n == area)
    }
}

/// Where a box centred on each cell along one axis begins and ends.
type Spans = Vec<Option<(usize, usize)>>;

/// Along one axis of `n` cells, the cells that a box of half size `half`
/// (in cells) centred on each cell covers, where it lies inside the grid.
fn spans(n: usize, half: f64) -> Spans {
    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
    let span = |at: usize| {
        let centre = at as f64 + 0.5;
        let (lo, hi) = (centre - half, centre + half);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "inside [0, n] by the check before"
        )]
        (lo >= 0.0 && hi <= n as f64).then(|| (lo.floor() as usize, hi.ceil() as usize))
    };
    (0..n).map(span).collect()
}

/// Each state's name's place on the map `(x, y)` drawn from `grid`, as
/// `[load, value]`: for each state, the cells where the largest box of
/// [`SCALES`] fits, and of those the one nearest their mean.
#[must_use]
pub fn state_words(grid: &CellGrid, x: (f64, f64), y: (f64, f64)) -> Vec<([f64; 2], State)> {
    if grid.columns == 0 || grid.rows == 0 {
        return Vec::new();
    }
    let counts = Counts::new(grid);
    #[expect(clippy::cast_precision_loss, reason = "cell counts")]
    let (columns, rows) = (grid.columns as f64, grid.rows as f64);
    // Each scale's box's cells about every column and every row: the same
    // for every cell of a column (row), so found once, not once a cell.
    let boxes: Vec<_> = SCALES
        .iter()
        .map(|&scale| {
            (
                spans(grid.columns, 0.5 * BOX_FRACTION.0 * scale * columns),
                spans(grid.rows, 0.5 * BOX_FRACTION.1 * scale * rows),
            )
        })
        .collect();
    let mut words = Vec::new();
    for state in [State::Stable, State::Flutter, State::Divergence] {
        // A box covers the cell it is centred on, so only the state's own
        // cells can centre one.
        let own: Vec<(usize, usize)> = (0..grid.rows)
            .flat_map(|j| (0..grid.columns).map(move |i| (i, j)))
            .filter(|&(i, j)| {
                let cell = grid.cells.get(j * grid.columns + i).copied().flatten();
                cell.is_some_and(|(s, _)| s == state)
            })
            .collect();
        let at_scale = |(is, js): &(Spans, Spans)| {
            own.iter()
                .copied()
                .filter(|&(i, j)| match (is[i], js[j]) {
                    (Some(across), Some(up)) => counts.filled(state, across, up),
                    _ => false,
                })
                .collect::<Vec<_>>()
        };
        let Some(fitting) = boxes.iter().map(at_scale).find(|cells| !cells.is_empty()) else {
            continue;
        };
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let (mean_i, mean_j) = {
            let n = fitting.len() as f64;
            (
                fitting.iter().map(|c| c.0 as f64).sum::<f64>() / n,
                fitting.iter().map(|c| c.1 as f64).sum::<f64>() / n,
            )
        };
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let distance = |c: &(usize, usize)| {
            ((c.0 as f64 - mean_i) / columns).powi(2) + ((c.1 as f64 - mean_j) / rows).powi(2)
        };
        let Some(&(i, j)) = fitting
            .iter()
            .min_by(|a, b| distance(a).total_cmp(&distance(b)))
        else {
            continue;
        };
        #[expect(clippy::cast_precision_loss, reason = "cell counts")]
        let at = [
            x.0 + (i as f64 + 0.5) / columns * (x.1 - x.0),
            y.0 + (j as f64 + 0.5) / rows * (y.1 - y.0),
        ];
        words.push((at, state));
    }
    words
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A grid of `columns` by `rows` whose cell `(i, j)` takes `state(i, j)`.
    fn grid(
        columns: usize,
        rows: usize,
        state: impl Fn(usize, usize) -> Option<State>,
    ) -> CellGrid {
        CellGrid {
            columns,
            rows,
            cells: (0..rows)
                .flat_map(|j| (0..columns).map(move |i| (i, j)))
                .map(|(i, j)| state(i, j).map(|s| (s, 1.0)))
                .collect(),
            largest_per_s: 1.0,
        }
    }

    /// Three vertical bands of a 60 x 30 map: each name at its band's
    /// middle, on the map's middle row; every cell the box covers is the
    /// band's.
    #[test]
    fn each_band_gets_its_name_at_its_middle() {
        let bands = grid(60, 30, |i, _| {
            Some(match i {
                0..20 => State::Stable,
                20..40 => State::Flutter,
                _ => State::Divergence,
            })
        });
        let words = state_words(&bands, (0.0, 6.0), (0.0, 3.0));
        assert_eq!(words.len(), 3);
        for ((at, state), centre) in words.iter().zip([1.0, 3.0, 5.0]) {
            assert!((at[0] - centre).abs() <= 0.1, "{state:?} at {at:?}");
            assert!((at[1] - 1.5).abs() <= 0.1, "{state:?} at {at:?}");
        }
    }

    /// A region too thin for any box gets no name; rows without analysis
    /// are no state's; a wedge's name sits where the wedge is widest.
    #[test]
    fn thin_regions_get_no_name_and_wedges_their_wide_end() {
        let thin = grid(60, 30, |i, _| {
            Some(if i == 30 {
                State::Flutter
            } else {
                State::Stable
            })
        });
        let words = state_words(&thin, (0.0, 1.0), (0.0, 1.0));
        assert_eq!(
            words.iter().map(|w| w.1).collect::<Vec<_>>(),
            [State::Stable]
        );
        let empty = grid(60, 30, |_, _| None);
        assert!(state_words(&empty, (0.0, 1.0), (0.0, 1.0)).is_empty());
        // Flutter right of the line i = 2 j: wide at the bottom.
        let wedge = grid(60, 30, |i, j| {
            Some(if i >= 2 * j {
                State::Flutter
            } else {
                State::Stable
            })
        });
        let words = state_words(&wedge, (0.0, 1.0), (0.0, 1.0));
        let flutter = words.iter().find(|w| w.1 == State::Flutter).unwrap().0;
        let stable = words.iter().find(|w| w.1 == State::Stable).unwrap().0;
        assert!(flutter[1] < 0.5 && flutter[0] > 0.5, "{flutter:?}");
        assert!(stable[1] > 0.5 && stable[0] < 0.5, "{stable:?}");
    }
}
