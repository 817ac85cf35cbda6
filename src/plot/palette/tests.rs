//! The palettes measured for every colour vision: the states, the marks of
//! the present and the curves stay apart, the ramp's lightness rises.

use super::Palette;
use crate::analysis::State;
use crate::plot::Rgb;
use crate::plot::vision::{Vision, difference, ucs};

/// The three palettes, named.
const PALETTES: [(&str, Palette); 3] = [
    ("normal", Palette::NORMAL),
    ("projector", Palette::PROJECTOR),
    ("paper", Palette::PAPER),
];

/// The smallest difference between any two of `colours` (and, given, each
/// of `beside`) under every vision, with the pair and vision it is found at.
fn smallest(colours: &[(&str, Rgb)], beside: &[(&str, Rgb)]) -> (f64, String) {
    let mut worst = (f64::INFINITY, String::new());
    for vision in Vision::ALL {
        for (i, &(a_name, a)) in colours.iter().enumerate() {
            let others = colours[i + 1..].iter().chain(beside);
            for &(b_name, b) in others {
                let d = difference(a, b, vision);
                if d < worst.0 {
                    worst = (d, format!("{a_name} vs {b_name}, {vision:?}"));
                }
            }
        }
    }
    worst
}

/// The bar: stable, flutter and divergence at least 20 apart for
/// every colour vision, in both themes and on paper, and each clear of the
/// background.
#[test]
fn the_states_stay_apart_for_every_colour_vision() {
    for (name, p) in PALETTES {
        let states = [
            ("stable", p.stable),
            ("flutter", p.flutter),
            ("divergence", p.divergence),
        ];
        let (d, at) = smallest(&states, &[]);
        assert!(d >= 20.0, "{name}: states {d:.1} apart ({at})");
        let (d, at) = smallest(&[("background", p.background)], &states);
        assert!(d >= 20.0, "{name}: a state on the background {d:.1} ({at})");
    }
}

/// The map's cells, from the faintest (the slowest growth or decay) to
/// the strongest: the three states at each strength 20 apart for every
/// colour vision, in both themes and on paper.
#[test]
fn the_map_s_faintest_cells_stay_apart() {
    for (name, p) in PALETTES {
        for strength in [0.0, 0.25, 0.5, 1.0] {
            let cells = [
                ("stable", p.cell(State::Stable, strength)),
                ("flutter", p.cell(State::Flutter, strength)),
                ("divergence", p.cell(State::Divergence, strength)),
            ];
            let (d, at) = smallest(&cells, &[]);
            assert!(d >= 20.0, "{name}, strength {strength}: {d:.1} ({at})");
        }
    }
}

/// The marks of the present (the eigenvalues now, the load line, the
/// measured eigenvalues) differ from each other, from the lines they are
/// drawn over (the text colour's branches, the flutter branch of cycles)
/// and from the background.
#[test]
fn the_present_the_load_line_and_the_measured_stay_apart() {
    for (name, p) in PALETTES.into_iter().filter(|(name, _)| *name != "paper") {
        let marks = [
            ("now", p.now),
            ("load line", p.load_line),
            ("measured", p.measured),
        ];
        let (d, at) = smallest(&marks, &[("background", p.background)]);
        assert!(d >= 20.0, "{name}: {d:.1} ({at})");
        // The lines: over the branches drawn in the text colour and the
        // flutter branch of cycles (the present's marker is a filled disc
        // larger than the line, told by its shape).
        let lines = [("load line", p.load_line), ("measured", p.measured)];
        let (d, at) = smallest(&lines, &[("text", p.text), ("flutter", p.flutter)]);
        assert!(d >= 20.0, "{name}: {d:.1} ({at})");
    }
}

/// A plot's curves (damping levels, overlaid models) and a history's
/// series are told apart for every vision, and from the background, the
/// grey reference (and the curves from the present's marker).
#[test]
fn curves_and_series_stay_apart_for_every_colour_vision() {
    for (name, p) in PALETTES {
        let named = |colours: &[Rgb]| -> Vec<(String, Rgb)> {
            colours
                .iter()
                .enumerate()
                .map(|(k, &c)| (format!("#{k}"), c))
                .collect()
        };
        let beside = [
            ("background", p.background),
            ("reference", p.reference),
            ("now", p.now),
        ];
        let kinds = [
            ("curve", named(&p.curves), &beside[..]),
            ("series", named(&p.series), &beside[..2]),
        ];
        for (what, colours, beside) in kinds {
            if name == "paper" && what == "series" {
                continue;
            }
            let colours: Vec<(&str, Rgb)> = colours.iter().map(|(n, c)| (n.as_str(), *c)).collect();
            let (d, at) = smallest(&colours, beside);
            assert!(d >= 15.0, "{name}: {what} {d:.1} ({at})");
        }
    }
}

/// The scene's two arrows at the tip, the band's force and the rod's
/// direction, differ for every vision.
#[test]
fn the_scene_s_arrows_stay_apart() {
    for (name, p) in PALETTES.into_iter().filter(|(name, _)| *name != "paper") {
        let (d, at) = smallest(
            &[("friction", p.friction), ("follower", p.follower)],
            &[("background", p.background)],
        );
        assert!(d >= 20.0, "{name}: {d:.1} ({at})");
    }
}

/// Along a branch the ramp's lightness J' rises for every vision, so the
/// order of the loads reads even in grey, and every colour of it stands
/// out from the background.
#[test]
fn the_ramp_s_lightness_rises_for_every_colour_vision() {
    for (name, p) in PALETTES {
        for vision in Vision::ALL {
            let lightness: Vec<f64> = (0..=40)
                .map(|i| ucs(p.along(f64::from(i) / 40.0), vision)[0])
                .collect();
            for pair in lightness.windows(2) {
                assert!(pair[1] > pair[0], "{name}, {vision:?}: {lightness:?}");
            }
            let span = lightness[40] - lightness[0];
            assert!(span > 40.0, "{name}, {vision:?}: J' spans {span:.1}");
        }
        let ends: Vec<(&str, Rgb)> = vec![("start", p.along(0.0)), ("end", p.along(1.0))];
        let (d, at) = smallest(&[("background", p.background)], &ends);
        assert!(
            d >= 20.0,
            "{name}: the ramp on the background {d:.1} ({at})"
        );
    }
}

#[test]
fn the_ramp_runs_from_its_first_colour_to_its_last() {
    for (_, p) in PALETTES {
        assert_eq!(p.along(0.0), p.along[0]);
        assert_eq!(p.along(1.0), p.along[p.along.len() - 1]);
        assert_eq!(p.along(-3.0), p.along(0.0));
        assert_eq!(p.along(f64::NAN), p.along(0.0));
        assert_eq!(p.along(7.0), p.along(1.0));
    }
}
