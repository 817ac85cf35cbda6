//! A plot in words, for a screen reader (and whoever cannot see its
//! colours): what it plots against what, the ranges of each state, the
//! lines marked, the present's eigenvalues on the right of the axis, the
//! map's share of each state. Medium-independent: built from the plot's
//! description, as both renderers are.

use super::spec::{Ink, Mark, Plot};
use crate::analysis::{RELATIVE_TOLERANCE, State};
use crate::format::number_text;

/// `plot` in a few sentences.
#[must_use]
pub fn describe(plot: &Plot) -> String {
    let mut sentences = vec![format!("{} against {}", plot.y_label, plot.x_label)];
    let ranges: Vec<String> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Range { from, to, state } => Some(format!(
                "{} from {} to {}",
                state.name(),
                number_text(*from),
                number_text(*to)
            )),
            _ => None,
        })
        .collect();
    if !ranges.is_empty() {
        sentences.push(format!("ranges: {}", ranges.join("; ")));
    }
    let marked: Vec<String> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Vertical { x, name, .. } if !name.is_empty() => {
                Some(format!("{name} at {}", number_text(*x)))
            }
            _ => None,
        })
        .collect();
    if !marked.is_empty() {
        sentences.push(format!("marked: {}", marked.join("; ")));
    }
    let curves = plot
        .marks
        .iter()
        .filter(|mark| matches!(mark, Mark::Line { .. }))
        .count();
    if curves > 0 {
        sentences.push(format!(
            "{curves} {}",
            if curves == 1 { "curve" } else { "curves" }
        ));
    }
    if let Some(now) = present(plot) {
        sentences.push(now);
    }
    if let Some(cells) = cell_shares(plot) {
        sentences.push(cells);
    }
    sentences.join(". ")
}

/// The present's eigenvalues on a plane of Re λ (x) and Im λ (y): how many
/// lie right of the imaginary axis, growing.
fn present(plot: &Plot) -> Option<String> {
    let points: Vec<[f64; 2]> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Markers {
                points,
                ink: Ink::Now,
                ..
            } => Some(points.iter().copied()),
            _ => None,
        })
        .flatten()
        .collect();
    if points.is_empty() || !plot.x_label.starts_with("Re") {
        return None;
    }
    // Rounding leaves an undamped column's pairs a hair off the axis: the
    // classification's tolerance, relative to the largest eigenvalue.
    let tolerance =
        RELATIVE_TOLERANCE * points.iter().map(|p| p[0].hypot(p[1])).fold(0.0, f64::max);
    let right = points.iter().filter(|p| p[0] > tolerance).count();
    let oscillating = points
        .iter()
        .filter(|p| p[0] > tolerance && p[1].abs() > tolerance)
        .count();
    Some(match right {
        0 => format!(
            "at the present load all {} eigenvalues lie left of the imaginary axis: a kick dies away",
            points.len()
        ),
        _ => format!(
            "at the present load {right} of {} eigenvalues lie right of the imaginary axis, {oscillating} of them off the real axis: {}",
            points.len(),
            if oscillating > 0 {
                "a swing grows (flutter)"
            } else {
                "the column bends away (divergence)"
            }
        ),
    })
}

/// A map's share of each state, in per cent of its cells.
fn cell_shares(plot: &Plot) -> Option<String> {
    let grid = plot.marks.iter().find_map(|mark| match mark {
        Mark::Cells { grid, .. } => Some(grid),
        _ => None,
    })?;
    let total = grid.cells.len().max(1);
    let share = |state: State| {
        let count = grid
            .cells
            .iter()
            .filter(|cell| cell.is_some_and(|(s, _)| s == state))
            .count();
        100 * count / total
    };
    Some(format!(
        "a map of {} by {} cells: stable {}%, flutter {}%, divergence {}%",
        grid.columns,
        grid.rows,
        share(State::Stable),
        share(State::Flutter),
        share(State::Divergence)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::spec::{OffView, Size, Ticks, View, Weight};

    fn plane(now: Vec<[f64; 2]>) -> Plot {
        Plot {
            id: "test",
            x_label: "Re λ (1/s)".to_owned(),
            y_label: "Im λ (rad/s)".to_owned(),
            x_ticks: Ticks::Plain,
            view: View::Equal { extent: (1.0, 1.0) },
            marks: vec![
                Mark::Line {
                    points: vec![[0.0, 0.0], [1.0, 1.0]],
                    ink: Ink::Main,
                    weight: Weight::Regular,
                    dashed: false,
                },
                Mark::Markers {
                    points: now,
                    ink: Ink::Now,
                    size: Size::Large,
                    filled: true,
                    off_view: OffView::EdgeMarked,
                },
            ],
            far_left: Vec::new(),
        }
    }

    #[test]
    fn the_present_is_counted_on_its_side_of_the_axis() {
        let stable = describe(&plane(vec![[-0.1, 1.0], [-0.1, -1.0]]));
        assert!(stable.contains("all 2 eigenvalues lie left"), "{stable}");
        let flutter = describe(&plane(vec![[0.1, 1.0], [0.1, -1.0], [-2.0, 0.0]]));
        assert!(
            flutter.contains("2 of 3 eigenvalues lie right") && flutter.contains("flutter"),
            "{flutter}"
        );
        let divergence = describe(&plane(vec![[0.3, 0.0], [-0.3, 0.0]]));
        assert!(divergence.contains("divergence"), "{divergence}");
        assert!(divergence.starts_with("Im λ (rad/s) against Re λ (1/s)"));
    }
}
