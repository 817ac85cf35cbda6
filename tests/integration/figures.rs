//! The figures for a paper draw the physics where it is: the critical loads
//! where `critical` finds them (and Ziegler's closed form), the flutter
//! onset's eigenvalues on the imaginary axis at the closed-form frequency,
//! every map cell in its state's colour and the boundaries on the rows'
//! critical loads; the SVG has the page's size in millimetres and the words.

use crate::cli::{run, stdout};
use crate::common::{analysed_to, model, paper_loci, transitions};
use zieglerlab::analysis::{DampingKind, MapSpec, State, compute_map};
use zieglerlab::figure::{Format, Page, Rendered, render};
use zieglerlab::i18n::{Language, words};
use zieglerlab::model::Axis;
use zieglerlab::plot::locus::{Analysed, Part};
use zieglerlab::plot::map::MapData;
use zieglerlab::plot::map_words::state_words;
use zieglerlab::plot::paradox::ParadoxData;
use zieglerlab::plot::spec::CellGrid;
use zieglerlab::plot::{Palette, Rgb};

/// The pixels of a PNG figure.
fn pixels(rendered: &Rendered) -> image::RgbImage {
    image::load_from_memory(&rendered.bytes)
        .expect("a PNG")
        .to_rgb8()
}

/// The pixel nearest to `(x, y)` on the page.
fn pixel_at(image: &image::RgbImage, (x, y): (f64, f64)) -> [u8; 3] {
    #[expect(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
    let (x, y) = (x.round() as u32, y.round() as u32);
    image.get_pixel(x, y).0
}

/// The state whose paper colour, laid over white at some strength (a
/// range's pale tint up to a deep cell or line), is nearest to `color`, and
/// that strength; none when no state's colour is near.
fn state_of(color: [u8; 3]) -> Option<(State, f64)> {
    let paper = Palette::PAPER;
    let mut best: Option<(f64, State, f64)> = None;
    for state in [State::Stable, State::Flutter, State::Divergence] {
        let Rgb(r, g, b) = paper.state(state);
        for k in 5..=100 {
            let strength = f64::from(k) / 100.0;
            let mix = |c: u8| 255.0 + (f64::from(c) - 255.0) * strength;
            let distance = [mix(r), mix(g), mix(b)]
                .iter()
                .zip(color)
                .map(|(m, c)| (m - f64::from(c)).powi(2))
                .sum::<f64>()
                .sqrt();
            if best.is_none_or(|(d, _, _)| distance < d) {
                best = Some((distance, state, strength));
            }
        }
    }
    best.filter(|(d, _, _)| *d < 30.0)
        .map(|(_, state, strength)| (state, strength))
}

/// Whether `color` is `state`'s paper colour, pale or deep.
fn has_hue_of(color: [u8; 3], state: State) -> bool {
    state_of(color).is_some_and(|(s, _)| s == state)
}

/// Whether `color` is `state`'s paper colour at more than half strength (a
/// line, not a range's tint).
fn is_deep(color: [u8; 3], state: State) -> bool {
    state_of(color).is_some_and(|(s, strength)| s == state && strength > 0.5)
}

/// The analysis of a preset over the load bar's range.
fn analysed(name: &str, sets: &[&str]) -> Analysed {
    let m = model(name, sets);
    analysed_to(name, &m, m.load_bar_max_p()).expect("an analysis")
}

#[test]
fn re_im_figure_marks_the_critical_loads_where_critical_finds_them() {
    let main = analysed("ziegler-1952", &[]);
    // Ziegler's closed form: flutter from p = 7/2 - sqrt 2.
    let onset = 3.5 - 2f64.sqrt();
    let searched = transitions(&model("ziegler-1952", &[]), 8.0);
    assert_eq!(main.transitions.len(), searched.len());
    for (drawn, found) in main.transitions.iter().zip(&searched) {
        assert!((drawn.load - found.load).abs() <= 1e-10 * found.load);
        assert_eq!((drawn.from, drawn.to), (found.from, found.to));
    }
    assert!((main.transitions[0].load - onset).abs() < 1e-10);
    let overlays = [analysed("uniform-rods", &[])];
    let content = paper_loci(&main, &overlays, Part::VersusLoad);
    let page = Page::default();
    let png = render(&content, &page, Format::Png).unwrap();
    let image = pixels(&png);
    assert_eq!(png.panels.len(), 2, "Re and Im");
    for panel in &png.panels {
        let (y0, y1) = panel.y_range;
        // Each critical load is a dashed line of its new state's colour:
        // some pixels of its column are that colour's, none of the next
        // column but one are.
        for t in &main.transitions {
            let column: Vec<[u8; 3]> = (1..40)
                .map(|k| {
                    let y = y0 + (y1 - y0) * f64::from(k) / 40.0;
                    pixel_at(&image, panel.page_point(t.load, y))
                })
                .collect();
            let dashes = column.iter().filter(|c| is_deep(**c, t.to)).count();
            assert!(dashes > 5, "{t:?}: {dashes} of 39 in its colour");
        }
        // The ranges are tinted: stable before the onset, flutter after.
        let high = y0 + 0.95 * (y1 - y0);
        let before = pixel_at(&image, panel.page_point(0.5 * onset, high));
        let after = pixel_at(&image, panel.page_point(onset + 0.5, high));
        assert!(has_hue_of(before, State::Stable), "{before:?}");
        assert!(has_hue_of(after, State::Flutter), "{after:?}");
    }
    let svg = render(&content, &page, Format::Svg).unwrap();
    let text = String::from_utf8(svg.bytes).unwrap();
    assert!(text.starts_with("<svg width=\"85mm\" height=\"68mm\" viewBox="));
    assert!(text.trim_end().ends_with("</svg>"));
    for words in [
        "ziegler-1952",
        "uniform-rods",
        "p = 2.0858: stable to flutter",
        "Re λ (1/s)",
        "Im λ (rad/s)",
        "p = P l/k",
    ] {
        assert!(text.contains(words), "{words} not in the SVG");
    }
}

#[test]
fn locus_figure_puts_the_flutter_onset_on_the_imaginary_axis_at_its_frequency() {
    let main = analysed("ziegler-1952", &[]);
    let m = model("ziegler-1952", &[]);
    // det(M s + K) = 2 s^2 + (7 - 2p) s + 1 in units k / (m l^2): at the
    // onset the double root is s = -sqrt(2)/2.
    let c = &m.column;
    let unit = c.k1_nm_per_rad / (c.tip_mass_kg * c.rod1.length_m.powi(2));
    let omega = (0.5 * 2f64.sqrt() * unit).sqrt();
    let at_onset = &main.at_transitions[0];
    assert!(
        at_onset
            .iter()
            .all(|z| z.re.abs() < 1e-6 && (z.im.abs() - omega).abs() < 1e-6 * omega),
        "{at_onset:?} vs ±{omega}i"
    );
    let rendered = render(
        &paper_loci(&main, &[], Part::Plane),
        &Page::default(),
        Format::Png,
    )
    .unwrap();
    let image = pixels(&rendered);
    let panel = &rendered.panels[0];
    for im in [omega, -omega] {
        let marker = pixel_at(&image, panel.page_point(0.0, im));
        assert!(is_deep(marker, State::Flutter), "{marker:?} at {im}i");
    }
    // Equal scales: a unit of Re and of Im are as long on the page.
    let (x_per, y_per) = (
        f64::from(panel.x_px.1 - panel.x_px.0) / (panel.x_range.1 - panel.x_range.0),
        f64::from(panel.y_px.1 - panel.y_px.0) / (panel.y_range.1 - panel.y_range.0),
    );
    assert!(
        (x_per / y_per - 1.0).abs() < 0.02,
        "{x_per} vs {y_per}: {panel:?}"
    );
}

#[test]
fn map_figure_draws_each_cell_in_its_state_and_the_boundaries_on_the_critical_loads() {
    let m = model("ziegler-1952", &[]);
    let spec = MapSpec {
        model: m,
        axis: Axis::DampingLevel,
        load_range: (0.0, 8.0),
        loads: 24,
        axis_range: (0.05, 0.3),
        values: 6,
    };
    let rows = std::sync::Mutex::new(vec![None; spec.values]);
    let (cancel, done) = (
        std::sync::atomic::AtomicBool::new(false),
        std::sync::atomic::AtomicUsize::new(0),
    );
    compute_map(&spec, 2, &cancel, &done, &|j, row| {
        rows.lock().unwrap()[j] = Some(row);
    })
    .unwrap();
    let data = MapData {
        spec: spec.clone(),
        rows: rows.into_inner().unwrap(),
    };
    let sheet = data.sheet(words(Language::English));
    let rendered = render(&sheet, &Page::default(), Format::Png).unwrap();
    let image = pixels(&rendered);
    let panel = &rendered.panels[0];
    let loads = spec.load_grid().unwrap();
    // The states' names are written over the cells: cells within the
    // largest box a name may take (two fifths of the map's width by a
    // sixth of its height) are not read.
    let grid = CellGrid::new(&spec, &data.rows);
    let (x, y) = (panel.x_range, panel.y_range);
    let words = state_words(&grid, x, y);
    let under_a_word = |p: f64, value: f64| {
        words.iter().any(|(at, _)| {
            (p - at[0]).abs() < 0.2 * (x.1 - x.0) && (value - at[1]).abs() < 0.08 * (y.1 - y.0)
        })
    };
    assert_eq!(words.len(), 3, "each state named: {words:?}");
    let mut seen = Vec::new();
    for row in data.rows.iter().flatten().flatten() {
        for (cell, &p) in row.cells.iter().zip(&loads) {
            // Away from a boundary (it is drawn over the cells) and a name.
            if row.transitions.iter().any(|t| (t.load - p).abs() < 0.2)
                || under_a_word(p, row.value)
            {
                continue;
            }
            // The deepest pixel about the cell's centre: a striped cell's
            // stripes are white.
            let (x, y) = panel.page_point(p, row.value);
            let color = (-2..=2)
                .flat_map(|dx| (-2..=2).map(move |dy| (x + f64::from(dx), y + f64::from(dy))))
                .map(|at| pixel_at(&image, at))
                .min_by_key(|c| c.iter().map(|&v| u32::from(v)).sum::<u32>())
                .unwrap();
            assert!(
                has_hue_of(color, cell.state),
                "{:?} at p = {p}, g2 = {}: {color:?}",
                cell.state,
                row.value
            );
            seen.push(cell.state);
        }
        // The boundary passes through each critical load of the row.
        for t in &row.transitions {
            let (x, y) = panel.page_point(t.load, row.value);
            let darkest = (-3..=3)
                .flat_map(|dx| (-3..=3).map(move |dy| (x + f64::from(dx), y + f64::from(dy))))
                .map(|at| pixel_at(&image, at))
                .map(|[r, g, b]| u32::from(r) + u32::from(g) + u32::from(b))
                .min()
                .unwrap();
            assert!(darkest < 150, "no boundary at {t:?}, g2 = {}", row.value);
        }
    }
    for state in [State::Stable, State::Flutter, State::Divergence] {
        assert!(seen.contains(&state), "{state:?} never checked");
    }
}

#[test]
fn paradox_figure_names_the_undamped_load_and_draws_it_at_its_height() {
    let m = model("ziegler-1952", &["c1=0.001", "c2=0.001"]);
    let data = ParadoxData::new(&m, DampingKind::Joints, 2);
    let (_, undamped) = data.curves.reference.expect("the undamped load");
    assert!((undamped - (3.5 - 2f64.sqrt())).abs() < 1e-9);
    let here = data.here.expect("the model's own point");
    assert!(here[0].abs() < 1e-12, "c1/c2 = 1 is log10 0");
    let sheet = data.sheet(words(Language::English));
    let rendered = render(&sheet, &Page::default(), Format::Png).unwrap();
    let image = pixels(&rendered);
    let panel = &rendered.panels[0];
    // The reference is a black dashed line across the plot.
    let (x0, x1) = panel.x_range;
    let black = (1..40)
        .map(|k| x0 + (x1 - x0) * f64::from(k) / 40.0)
        .filter(|&x| {
            pixel_at(&image, panel.page_point(x, undamped))
                .iter()
                .all(|&v| v < 80)
        })
        .count();
    assert!(black > 10, "{black} of 39 points on the undamped line");
    let svg = render(&sheet, &Page::default(), Format::Svg).unwrap();
    let text = String::from_utf8(svg.bytes).unwrap();
    assert!(text.contains("undamped: p = 2.0858"));
    assert!(text.contains(&format!("this model: p = {:.4}", here[1])));
}

#[test]
fn a_figure_from_the_command_line_is_an_svg_of_the_page_or_a_png_at_its_dpi() {
    let dir = std::env::temp_dir().join(format!("zl-figures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("re-im.svg");
    stdout(&[
        "figure",
        "--preset",
        "roller",
        "--kind",
        "re-im",
        "--overlay",
        "uniform-rods",
        "--width-mm",
        "170",
        "--font-pt",
        "9",
        "--out",
        svg.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg width=\"170mm\" height=\"187mm\""));
    assert!(text.contains("uniform-rods") && text.contains("roller"));
    // 9 pt at four units a point.
    assert!(text.contains("font-size=\"36\""));
    let png = dir.join("locus.png");
    let out = run(&[
        "figure",
        "--preset",
        "roller",
        "--kind",
        "locus",
        "--dpi",
        "150",
        "--out",
        png.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    // The roller's spin settling far left is named, not squeezed in.
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("lie left of the view"), "{said}");
    let size = image::image_dimensions(&png).unwrap();
    // 85 x 68 mm at 150 dpi.
    assert_eq!(size, (502, 402));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The README's figure and the note beside its locus example are what the
/// commands make now, byte for byte and line for line.
#[test]
fn the_readme_figure_and_note_are_what_the_commands_make() {
    let readme = std::fs::read_to_string("README.md").expect("the README");
    let made = "*Made with `zieglerlab figure ";
    let start = readme.find(made).expect("the figure's command") + made.len() - "figure ".len();
    let command: Vec<&str> = readme[start..]
        .split('`')
        .next()
        .unwrap()
        .split_whitespace()
        .collect();
    assert_eq!(command.last(), Some(&"assets/re-im.png"));
    let dir = std::env::temp_dir().join(format!("zl-readme-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("re-im.png");
    let mut args = command.clone();
    *args.last_mut().unwrap() = out.to_str().unwrap();
    stdout(&args);
    assert!(
        std::fs::read(&out).unwrap() == std::fs::read("assets/re-im.png").unwrap(),
        "assets/re-im.png is stale: make it again with `zieglerlab {}`",
        command.join(" ")
    );
    let example = "    $ zieglerlab figure --preset roller --kind locus --out locus.svg\n";
    let at = readme.find(example).expect("the locus example") + example.len();
    let shown = readme[at..].lines().next().unwrap().trim_start();
    let svg = dir.join("locus.svg");
    let said = run(&[
        "figure",
        "--preset",
        "roller",
        "--kind",
        "locus",
        "--out",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(String::from_utf8_lossy(&said.stderr).trim_end(), shown);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `figure --kind bifurcation` is the diagram `bifurcation --format png`
/// draws, through the same sheet and page: byte for byte the same PNG,
/// and the same onset said on stderr.
#[test]
fn the_bifurcation_figure_is_the_diagram_bifurcation_draws() {
    let folder = tempfile::tempdir().unwrap();
    let (figure, diagram) = (folder.path().join("f.png"), folder.path().join("d.png"));
    let damped = [
        "--preset",
        "ziegler-1952",
        "--set",
        "c1=0.3",
        "--set",
        "c2=0.3",
    ];
    let mut args = vec!["figure"];
    args.extend(damped);
    args.extend([
        "--kind",
        "bifurcation",
        "--load-min",
        "1.6",
        "--load-max",
        "3",
    ]);
    args.extend(["--out", figure.to_str().unwrap()]);
    let drawn = run(&args);
    assert!(drawn.status.success(), "{drawn:?}");
    let mut args = vec!["bifurcation"];
    args.extend(damped);
    args.extend(["--x", "load:1.6:3:8", "--format", "png"]);
    args.extend(["--out", diagram.to_str().unwrap()]);
    let computed = run(&args);
    assert!(computed.status.success(), "{computed:?}");
    assert_eq!(
        std::fs::read(&figure).unwrap(),
        std::fs::read(&diagram).unwrap()
    );
    let said = String::from_utf8_lossy(&drawn.stderr);
    assert!(said.contains("cycle-1: soft onset at p = "), "{said}");
    assert_eq!(said, String::from_utf8_lossy(&computed.stderr));
}

/// The boundaries' figure draws each boundary in its state's colour where
/// the continuation put it: the middle point of the divergence curve and
/// of the flutter curve of the partial follower with dampers.
#[test]
fn the_boundary_figure_draws_each_boundary_where_it_was_found() {
    use zieglerlab::analysis::{BoundaryKind, BoundarySpec, boundaries};
    use zieglerlab::model::Axis;
    use zieglerlab::plot::boundary::BoundaryPlane;
    let m = model("ziegler-1952", &["c1=0.1", "c2=0.1"]);
    let axis = Axis::parse("eta", &m).unwrap();
    let spec = BoundarySpec {
        model: m,
        axis,
        axis_range: (0.0, 1.0),
        load_range: (0.0, 8.0),
    };
    let found = boundaries(&spec).unwrap();
    let sheet = BoundaryPlane::of(&found, &spec, words(Language::English)).sheet();
    let rendered = render(&sheet, &Page::default(), Format::Png).unwrap();
    let image = pixels(&rendered);
    let panel = &rendered.panels[0];
    for curve in &found.curves {
        let state = match curve.kind {
            BoundaryKind::Flutter => State::Flutter,
            BoundaryKind::Divergence => State::Divergence,
        };
        let middle = curve.points[curve.points.len() / 2];
        let (x, y) = panel.page_point(middle.value, middle.load);
        let drawn = (-3..=3).any(|dx| {
            (-3..=3).any(|dy| {
                let color = pixel_at(&image, (x + f64::from(dx), y + f64::from(dy)));
                state_of(color).is_some_and(|(s, strength)| s == state && strength > 0.5)
            })
        });
        assert!(
            drawn,
            "{state:?} at eta = {}, p = {}",
            middle.value, middle.load
        );
    }
}

/// The boundaries' figure tints the band of hysteresis between the fold of
/// cycles and the hard flutter onset above it (drag, a light first rod):
/// between them at m1 = 0.25 the page is tinted in the flutter colour
/// (a range's tint, 0.18 of it); 0.03 below the fold (a tenth of the view) it is not.
#[test]
fn the_boundary_figure_tints_the_band_of_hysteresis() {
    use zieglerlab::plot::boundary::BoundaryPlane;
    let (spec, found) = crate::common::drag_column_boundaries();
    let fold = &found.folds[0].points;
    let sheet = BoundaryPlane::of(found, spec, words(Language::English)).sheet();
    let rendered = render(&sheet, &Page::default(), Format::Png).unwrap();
    let image = pixels(&rendered);
    let panel = &rendered.panels[0];
    // The fold's chord about m1 = 0.3, and the onset there from the Hopf
    // curve's chord.
    let on_chord = |points: &[(f64, f64)], x: f64| {
        points
            .windows(2)
            .find_map(|w| {
                let ((x0, y0), (x1, y1)) = (w[0], w[1]);
                ((x0.min(x1)..=x0.max(x1)).contains(&x))
                    .then(|| y0 + (x - x0) / (x1 - x0) * (y1 - y0))
            })
            .unwrap()
    };
    let fold_chord: Vec<_> = fold.iter().map(|p| (p.value, p.load)).collect();
    let hopf_chord: Vec<_> = found.curves[0]
        .points
        .iter()
        .map(|p| (p.value, p.load))
        .collect();
    let (low, high) = (on_chord(&fold_chord, 0.25), on_chord(&hopf_chord, 0.25));
    assert!(high - low > 3e-3, "{low} {high}");
    let tint = |load: f64| state_of(pixel_at(&image, panel.page_point(0.25, load)));
    // The band is a few pixels tall between the two lines: some pixel in
    // it is the tint, not a line.
    let (_, y_low) = panel.page_point(0.25, low);
    let (_, y_high) = panel.page_point(0.25, high);
    #[expect(clippy::cast_possible_truncation, reason = "pixel rows")]
    let rows = y_high.ceil() as i32..=y_low.floor() as i32;
    let tinted = rows.into_iter().any(|y| {
        let (x, _) = panel.page_point(0.25, low);
        state_of(pixel_at(&image, (x, f64::from(y))))
            .is_some_and(|(s, strength)| s == State::Flutter && (0.1..0.3).contains(&strength))
    });
    assert!(tinted, "{y_high} {y_low}");
    let below = tint(low - 0.03);
    assert!(
        below.is_none_or(|(_, strength)| strength <= 0.05),
        "{below:?}"
    );
}
