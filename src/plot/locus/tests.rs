//! The locus builder's tests: the window and a figure describe one locus.

use super::*;
use crate::analysis::{AffinePencil, AlongLoad, Unresolved, plotted_locus};
use crate::model::PresetId;

/// The tinted ranges of a plot, in order.
fn ranges(plot: &Plot) -> Vec<(f64, f64, State)> {
    plot.marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Range { from, to, state } => Some((*from, *to, *state)),
            _ => None,
        })
        .collect()
}

/// The pencil of `preset` and its locus over its load bar, analysed.
fn analysed(preset: PresetId) -> (AffinePencil, AlongLoad) {
    let model = preset.model();
    let pencil = AffinePencil::new(&model).unwrap();
    let locus = plotted_locus(&pencil, 0.0, model.load_bar_max_p()).unwrap();
    let along = AlongLoad::new(&pencil, locus, Unresolved::Dropped).unwrap();
    (pencil, along)
}

/// `along`'s locus as the plots' one model, drawn for `medium`.
fn loci<'a>(name: &'a str, along: &'a AlongLoad, medium: Medium) -> Loci<'a> {
    Loci {
        main: Layer {
            name,
            locus: &along.locus,
            transitions: &along.transitions,
            ranges: &along.ranges,
            at_transitions: &[],
        },
        others: Vec::new(),
        medium,
        words: crate::i18n::words(crate::i18n::Language::English),
    }
}

/// Ziegler's column (equal masses and springs, undamped) flutters at
/// p = 7/2 - sqrt 2 and diverges at 7/2 + sqrt 2. The window and a figure
/// of its locus hold the same eigenvalues in view, tint the same ranges,
/// bounded by those loads; the figure dashes a line at each, the window
/// draws the current load instead.
#[test]
fn the_window_and_a_figure_describe_the_same_locus() {
    let (pencil, along) = analysed(PresetId::Ziegler1952);
    let now = pencil.spectrum(1.0).unwrap().eigenvalues;
    let paper = loci("ziegler-1952", &along, Medium::Paper);
    let words = paper.words;
    let plane = paper.sheet(Part::Plane).plots;
    let paper_loads = paper.sheet(Part::VersusLoad).plots;
    let mut window = Loci {
        medium: Medium::Window,
        ..paper.clone()
    }
    .sheet(Part::All);
    Present {
        load: 1.0,
        eigenvalues: &now,
        measured: None,
    }
    .mark(&mut window, words);
    assert_eq!(window.plots.len(), 3);
    assert_eq!(plane[0].view, window.plots[0].view);
    // The present: the eigenvalues at p = 1 on the plane.
    assert!(window.plots[0].marks.iter().any(|mark| matches!(
        mark,
        Mark::Markers { ink: Ink::Now, points, .. } if points.len() == now.len()
    )));
    let onsets = [
        (3.5 - 2f64.sqrt(), State::Flutter),
        (3.5 + 2f64.sqrt(), State::Divergence),
    ];
    for (on_paper, on_screen) in paper_loads.iter().zip(&window.plots[1..]) {
        let tinted = ranges(on_paper);
        assert_eq!(tinted, ranges(on_screen));
        assert_eq!(tinted.len(), 3);
        for ((load, state), pair) in onsets.iter().zip(tinted.windows(2)) {
            assert!((pair[0].1 - load).abs() < 1e-9 && pair[1].0 == pair[0].1);
            assert_eq!(pair[1].2, *state);
            assert!(on_paper.marks.iter().any(|mark| matches!(
                mark,
                Mark::Vertical { x, ink: Ink::State(s), dashed: true, .. }
                    if (x - load).abs() < 1e-9 && s == state
            )));
        }
        let current = |plot: &Plot| {
            plot.marks.iter().any(
                |mark| matches!(mark, Mark::Vertical { ink: Ink::LoadLine, x, .. } if *x == 1.0),
            )
        };
        assert!(current(on_screen) && !current(on_paper));
        let (View::Ranges { x: px, y: py }, View::Ranges { x: wx, y: wy }) =
            (on_paper.view, on_screen.view)
        else {
            panic!("plots against the load have ranges");
        };
        assert_eq!((px, py.1), (wx, wy.1));
    }
    // The plane's view holds the eigenvalues at the flutter onset.
    let View::Equal { extent } = window.plots[0].view else {
        panic!("the plane has equal scales");
    };
    let at_onset = pencil.spectrum(onsets[0].0).unwrap().eigenvalues;
    assert!(at_onset.iter().all(|z| z.im.abs() <= extent.1 + 1e-12));
}

/// Beck's column (16 rods, undamped) over its load bar, stable and then
/// fluttering, has every eigenvalue in a conjugate pair, whose two
/// branches have the same real part at every load; 14 of the pairs stay on
/// the imaginary axis (real part exactly 0, no damping) and one quadruple
/// +-a +-ib leaves it at the flutter load. The window's Re plot draws each
/// distinct curve once: 0, +a and -a, 3 lines for 32 branches, and misses
/// no branch.
#[test]
fn the_re_plot_draws_each_curve_once() {
    let (_, along) = analysed(PresetId::Beck);
    let window = loci("beck", &along, Medium::Window);
    let re_plot = &window.sheet(Part::VersusLoad).plots[0];
    let lines: Vec<&Vec<[f64; 2]>> = re_plot
        .marks
        .iter()
        .filter_map(|mark| match mark {
            Mark::Line { points, .. } => Some(points),
            _ => None,
        })
        .collect();
    let branches = &along.locus.branches;
    assert_eq!(branches.len(), 32);
    assert_eq!(lines.len(), 3);
    for branch in branches {
        // Its real part against the load at the drawn samples.
        let line = lines
            .iter()
            .find(|line| {
                line.iter().all(|&[load, re]| {
                    let i = along.locus.loads.iter().position(|&p| p == load).unwrap();
                    branch[i].re == re
                })
            })
            .is_some();
        assert!(line, "a branch's real part is not drawn");
    }
}
