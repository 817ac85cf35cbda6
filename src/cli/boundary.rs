//! `zieglerlab boundary`: the stability boundaries followed in the load and
//! a second parameter, with the first Lyapunov coefficient along each
//! flutter boundary and the special points, as CSV, JSON or a figure.

use std::io::Write;
use std::str::FromStr;

use anyhow::Result;
use clap::ValueEnum;
use serde_json::json;

use zieglerlab::analysis::{
    Boundaries, BoundaryKind, BoundarySpec, SpecialKind, boundaries, check_largest_load,
};
use zieglerlab::figure::{self, Page, render};
use zieglerlab::format::Exact;
use zieglerlab::model::Axis;
use zieglerlab::plot::boundary::BoundaryPlane;

use super::map::finite_number;
use super::output::{check_output, write_atomically};
use super::{ModelArgs, spinner};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Csv,
    Json,
    /// The plane as a figure (the page of `figure`'s defaults).
    Png,
    /// The same as SVG.
    Svg,
}

/// The second parameter as `KEY:MIN:MAX`.
#[derive(Clone, Debug)]
pub struct RangeArg {
    pub text: String,
    pub name: String,
    pub min: f64,
    pub max: f64,
}

impl FromStr for RangeArg {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let mut parts = text.rsplitn(3, ':');
        let (Some(max), Some(min), Some(name)) = (parts.next(), parts.next(), parts.next()) else {
            return Err("must be KEY:MIN:MAX (e.g. c2:0:0.01)".to_owned());
        };
        let (min, max) = (finite_number(min)?, finite_number(max)?);
        if max <= min {
            return Err("MAX must be above MIN".to_owned());
        }
        Ok(Self {
            text: text.to_owned(),
            name: name.trim().to_owned(),
            min,
            max,
        })
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    #[command(flatten)]
    lang: super::headless::FigureLanguage,
    /// The second parameter and its range, KEY:MIN:MAX (any key `map` takes).
    #[arg(long, allow_hyphen_values = true)]
    y: RangeArg,
    /// Lower end of the loads.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    load_min: f64,
    /// Upper end of the loads [default: the end of the window's load bar].
    #[arg(long, allow_hyphen_values = true)]
    load_max: Option<f64>,
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    format: Format,
    /// Where to write [default: standard output].
    #[arg(long)]
    out: Option<std::path::PathBuf>,
}

impl Args {
    /// Whether the boundaries go to standard output, a pipe or a device.
    pub fn streams(&self) -> bool {
        super::output::streams(self.out.as_deref())
    }
}

pub fn run(args: &Args) -> Result<()> {
    let figure = match args.format {
        Format::Png => Some(figure::Format::Png),
        Format::Svg => Some(figure::Format::Svg),
        Format::Csv | Format::Json => None,
    };
    match (&args.out, figure) {
        (None, Some(_)) => anyhow::bail!(
            "--format {}: give the picture's file with --out",
            if figure == Some(figure::Format::Png) {
                "png"
            } else {
                "svg"
            }
        ),
        (Some(out), _) => {
            if figure == Some(figure::Format::Svg) && figure::Format::of(out) != figure {
                anyhow::bail!(
                    "out = {}: --format svg writes SVG; name the file *.svg",
                    out.display()
                );
            }
            check_output(out, figure == Some(figure::Format::Png))?;
        }
        (None, None) => {}
    }
    let (_, model) = args.model.build()?;
    let axis = Axis::parse(&args.y.name, &model)
        .map_err(|e| anyhow::anyhow!("--y {}: {e}", args.y.text))?;
    let load_max = args.load_max.unwrap_or_else(|| model.load_bar_max_p());
    check_largest_load(load_max)?;
    let spec = BoundarySpec {
        model,
        axis,
        axis_range: (args.y.min, args.y.max),
        load_range: (args.load_min, load_max),
    };
    let working = spinner("following the stability boundaries");
    let found = boundaries(&spec)?;
    working.finish_and_clear();
    for point in &found.special_points {
        let second = point.second_lyapunov.map_or_else(String::new, |l2| {
            format!(" (second Lyapunov coefficient {l2:.4e})")
        });
        eprintln!(
            "{}: {} = {}, p = {}{second}",
            special_name(point.kind),
            args.y.name,
            Exact(point.value),
            Exact(point.load)
        );
    }
    if let (Some(format), Some(out)) = (figure, &args.out) {
        let sheet =
            BoundaryPlane::of(&found, &spec, zieglerlab::i18n::words(args.lang.language)).sheet();
        let rendered = render(&sheet, &Page::default(), format)?;
        return write_atomically(out, |file| file.write_all(&rendered.bytes));
    }
    let write = |out: &mut dyn Write| -> std::io::Result<()> {
        match args.format {
            Format::Json => write_json(out, &found, &args.y.name),
            Format::Csv | Format::Png | Format::Svg => write_csv(out, &found, &args.y.name),
        }
    };
    if let Some(path) = &args.out {
        write_atomically(path, |file| write(file))?;
    } else {
        let mut out = zieglerlab::files::standard_output();
        write(&mut out)?;
        out.flush()?;
    }
    Ok(())
}

/// Each curve's name: `flutter-1`, ..., `divergence-1`, ... in the order
/// found.
fn curve_names(found: &Boundaries) -> Vec<String> {
    let mut counts = [0usize; 2];
    found
        .curves
        .iter()
        .map(|curve| {
            let (k, word) = match curve.kind {
                BoundaryKind::Flutter => (0, "flutter"),
                BoundaryKind::Divergence => (1, "divergence"),
            };
            counts[k] += 1;
            format!("{word}-{}", counts[k])
        })
        .collect()
}

/// The `k`-th fold of cycles' name (from 0): `fold-1`, `fold-2`, ...
fn fold_name(k: usize) -> String {
    format!("fold-{}", k + 1)
}

/// Soft or hard, from the first Lyapunov coefficient's sign.
fn onset(first_lyapunov: Option<f64>) -> &'static str {
    match first_lyapunov {
        Some(l1) if l1 < 0.0 => "soft",
        Some(l1) if l1 > 0.0 => "hard",
        _ => "",
    }
}

fn special_name(kind: SpecialKind) -> &'static str {
    match kind {
        SpecialKind::Bautin => "bautin",
        SpecialKind::BogdanovTakens => "bogdanov-takens",
        SpecialKind::DoubleHopf => "double-hopf",
        SpecialKind::ZeroHopf => "zero-hopf",
    }
}

/// `curve,KEY,load,first_lyapunov,onset`, one row per point.
fn write_csv(out: &mut dyn Write, found: &Boundaries, key: &str) -> std::io::Result<()> {
    writeln!(out, "curve,{key},load,first_lyapunov,onset")?;
    for (curve, name) in found.curves.iter().zip(curve_names(found)) {
        for point in &curve.points {
            let l1 = point
                .first_lyapunov
                .map_or_else(String::new, |l1| Exact(l1).to_string());
            writeln!(
                out,
                "{name},{},{},{l1},{}",
                Exact(point.value),
                Exact(point.load),
                onset(point.first_lyapunov)
            )?;
        }
    }
    for (k, fold) in found.folds.iter().enumerate() {
        for point in &fold.points {
            writeln!(
                out,
                "{},{},{},,",
                fold_name(k),
                Exact(point.value),
                Exact(point.load)
            )?;
        }
    }
    Ok(())
}

/// The curves with their points and ends, and the special points.
fn write_json(out: &mut dyn Write, found: &Boundaries, key: &str) -> std::io::Result<()> {
    let names = curve_names(found);
    let curves: Vec<_> = found
        .curves
        .iter()
        .zip(&names)
        .map(|(curve, name)| {
            let points: Vec<_> = curve
                .points
                .iter()
                .map(|point| {
                    json!({
                        key: point.value,
                        "load": point.load,
                        "frequency_rad_per_s": point.eigenvalue.im,
                        "first_lyapunov": point.first_lyapunov,
                        "onset": match curve.kind {
                            BoundaryKind::Flutter => Some(onset(point.first_lyapunov)),
                            BoundaryKind::Divergence => None,
                        },
                    })
                })
                .collect();
            json!({"curve": name, "kind": curve.kind, "ends": curve.ends, "points": points})
        })
        .collect();
    let special: Vec<_> = found
        .special_points
        .iter()
        .map(|point| {
            json!({
                "kind": special_name(point.kind),
                key: point.value,
                "load": point.load,
                "curves": [&names[point.curves[0]], &names[point.curves[1]]],
                "second_lyapunov": point.second_lyapunov,
            })
        })
        .collect();
    let folds: Vec<_> = found
        .folds
        .iter()
        .enumerate()
        .map(|(k, fold)| {
            let points: Vec<_> = fold
                .points
                .iter()
                .map(|point| {
                    json!({
                        key: point.value,
                        "load": point.load,
                        "amplitude_rad": point.amplitude_rad,
                        "period_s": point.period_secs,
                        "second_multiplier": [point.second_multiplier.re, point.second_multiplier.im],
                    })
                })
                .collect();
            json!({"curve": fold_name(k), "kind": "cycle-fold", "ends": fold.ends, "points": points})
        })
        .collect();
    let document = json!({
        "key": key,
        "curves": curves,
        "special_points": special,
        "folds": folds,
    });
    serde_json::to_writer_pretty(&mut *out, &document)?;
    writeln!(out)
}
