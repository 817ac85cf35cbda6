//! A plot in words, for a screen reader (and whoever cannot see its
//! colours): what it plots against what, the ranges of each state, the
//! lines marked, the points named (a diagram's bifurcations), the
//! present's eigenvalues on the right of the axis, the map's share of
//! each state. Medium-independent: built from the plot's
//! description, as both renderers are.

use super::spec::{Ink, Mark, Plot};
use crate::analysis::{RELATIVE_TOLERANCE, State};
use crate::format::number_text;
use crate::i18n::{Words, state_name};
use crate::tr;

/// `plot` in a few sentences.
#[must_use]
pub fn describe(plot: &Plot, words: &'static Words) -> String {
    let mut sentences = vec![tr!(
        words,
        "describe-against",
        y = plot.y_label.clone(),
        x = plot.x_label.clone()
    )];
    let ranges: Vec<String> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Range { from, to, state } => Some(tr!(
                words,
                "describe-range",
                state = state_name(words, *state),
                from = number_text(*from),
                to = number_text(*to)
            )),
            _ => None,
        })
        .collect();
    if !ranges.is_empty() {
        sentences.push(tr!(words, "describe-ranges", ranges = ranges.join("; ")));
    }
    let marked: Vec<String> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Vertical { x, name, .. } if !name.is_empty() => Some(tr!(
                words,
                "describe-mark",
                name = name.clone(),
                x = number_text(*x)
            )),
            _ => None,
        })
        .collect();
    if !marked.is_empty() {
        sentences.push(tr!(words, "describe-marked", marks = marked.join("; ")));
    }
    let named: Vec<String> = plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Label {
                text, of: Some(at), ..
            } => Some(tr!(
                words,
                "describe-point",
                name = text.clone(),
                x = number_text(at[0]),
                y = number_text(at[1])
            )),
            _ => None,
        })
        .collect();
    if !named.is_empty() {
        sentences.push(tr!(words, "describe-points", points = named.join("; ")));
    }
    let curves = plot
        .marks
        .iter()
        .filter(|mark| matches!(mark, Mark::Line { .. } | Mark::Graded { .. }))
        .count();
    if curves > 0 {
        sentences.push(tr!(words, "describe-curves", count = curves));
    }
    if plot
        .marks
        .iter()
        .any(|mark| matches!(mark, Mark::Band { .. }))
    {
        sentences.push(tr!(words, "describe-bands"));
    }
    if let Some(now) = present(plot, words) {
        sentences.push(now);
    }
    if let Some(cells) = cell_shares(plot, words) {
        sentences.push(cells);
    }
    sentences.join(". ")
}

/// The present's eigenvalues on a plane of Re λ (x) and Im λ (y): how many
/// lie right of the imaginary axis, growing.
fn present(plot: &Plot, words: &'static Words) -> Option<String> {
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
    if points.is_empty() || plot.id != "root locus" {
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
        0 => tr!(words, "describe-now-stable", count = points.len()),
        _ if oscillating > 0 => tr!(
            words,
            "describe-now-flutter",
            right = right,
            count = points.len(),
            oscillating = oscillating
        ),
        _ => tr!(
            words,
            "describe-now-divergence",
            right = right,
            count = points.len()
        ),
    })
}

/// A map's share of each state, in per cent of its cells.
fn cell_shares(plot: &Plot, words: &'static Words) -> Option<String> {
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
    Some(tr!(
        words,
        "describe-map",
        columns = grid.columns,
        rows = grid.rows,
        stable = share(State::Stable),
        flutter = share(State::Flutter),
        divergence = share(State::Divergence)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Language, words};
    use crate::plot::spec::{OffView, Size, Ticks, View, Weight};

    fn english() -> &'static Words {
        words(Language::English)
    }

    fn plane(now: Vec<[f64; 2]>) -> Plot {
        Plot {
            id: "root locus",
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
        let stable = describe(&plane(vec![[-0.1, 1.0], [-0.1, -1.0]]), english());
        assert!(stable.contains("all 2 eigenvalues lie left"), "{stable}");
        let flutter = describe(
            &plane(vec![[0.1, 1.0], [0.1, -1.0], [-2.0, 0.0]]),
            english(),
        );
        assert!(
            flutter.contains("2 of 3 eigenvalues lie right") && flutter.contains("flutter"),
            "{flutter}"
        );
        let divergence = describe(&plane(vec![[0.3, 0.0], [-0.3, 0.0]]), english());
        assert!(divergence.contains("divergence"), "{divergence}");
        assert!(divergence.starts_with("Im λ (rad/s) against Re λ (1/s)"));
    }

    /// A name beside a ringed point is read with the point it names (a
    /// bifurcation's load and amplitude), not where the word stands; a
    /// word that names no point (a map's state) is not read as one.
    #[test]
    fn a_named_point_is_read_where_it_is() {
        let mut plot = plane(vec![[-0.1, 1.0]]);
        plot.marks.push(Mark::Label {
            at: [2.05, 0.3517],
            text: "LPC".to_owned(),
            of: Some([2.1304, 0.3517]),
        });
        plot.marks.push(Mark::Label {
            at: [1.0, 1.0],
            text: "stable".to_owned(),
            of: None,
        });
        let said = describe(&plot, english());
        assert!(said.contains(". named: LPC at (2.1304, 0.3517)."), "{said}");
        assert!(!said.contains("stable at"), "{said}");
    }

    /// A branch coloured along the load is drawn in pieces but is one
    /// curve to a listener (a 16-rod chain's plane said 768 curves).
    #[test]
    fn a_graded_branch_is_one_curve() {
        let mut plot = plane(vec![[-0.1, 1.0]]);
        for _ in 0..3 {
            plot.marks.push(Mark::Graded {
                points: (0..100).map(|i| [0.0, f64::from(i)]).collect(),
                along: (0..100).map(|i| f64::from(i) / 99.0).collect(),
                weight: Weight::Regular,
            });
        }
        let said = describe(&plot, english());
        assert!(said.contains(". 4 curves."), "{said}");
    }
}
