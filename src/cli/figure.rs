//! `zieglerlab figure`: a figure for a paper (the root locus, Re and Im
//! against the load, the stability map, the paradox curves or the
//! bifurcation diagram) as SVG or PNG at a journal's size.

use anyhow::Result;
use clap::ValueEnum;

use std::sync::atomic::AtomicBool;

use zieglerlab::analysis::{
    AffinePencil, BRACKET_SAMPLES, DampingKind, RowResult, cycle_branches, default_map_axis,
    load_grid,
};
use zieglerlab::figure::{FigureError, Format, Page, render};
use zieglerlab::format::{Shown, number_text};
use zieglerlab::i18n::Words;
use zieglerlab::model::{Model, PresetId};
use zieglerlab::plot::bifurcation::BifurcationData;
use zieglerlab::plot::locus::{Analysed, Loci, Part};
use zieglerlab::plot::map::MapData;
use zieglerlab::plot::paradox::ParadoxData;
use zieglerlab::plot::spec::{Medium, Sheet};

use super::map::{AxisArg, complete_rows, compute_rows, map_spec, warn_if_unresolved};
use super::output::{check_output, write_atomically};
use super::{ModelArgs, printable, progress_bar, spinner};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Kind {
    /// The root locus in the complex plane.
    Locus,
    /// Re and Im of the eigenvalues against the load (the paper's Figs 3 and 8).
    ReIm,
    /// The stability map over the load and a second parameter.
    Map,
    /// The first critical load as the damping (or the roller's mass) vanishes.
    Paradox,
    /// The limit cycles' largest angle against the load, with the straight
    /// column's stability (as `bifurcation --format png` draws it).
    Bifurcation,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum DampingArg {
    /// Joint dampers, swept in the ratio c1/c2.
    Joints,
    /// External drag against equal joint dampers.
    External,
}

/// The default height over the width, by kind: Re and Im are two plots.
fn default_aspect(kind: Kind) -> f64 {
    match kind {
        Kind::ReIm => 1.1,
        Kind::Locus | Kind::Map | Kind::Bifurcation => 0.8,
        Kind::Paradox => 0.75,
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    #[arg(long, value_enum)]
    kind: Kind,
    /// Another preset drawn beside the model (locus and re-im; repeatable),
    /// with its own parameters over the same loads.
    #[arg(long, value_name = "PRESET")]
    overlay: Vec<PresetId>,
    /// The figure, `*.svg` (vector) or `*.png`.
    #[arg(long)]
    out: std::path::PathBuf,
    /// Width in mm (a journal's column: 85 or so; a page: 170 to 180).
    #[arg(long, default_value_t = 85.0, allow_hyphen_values = true)]
    width_mm: f64,
    /// Height in mm [default: 0.8 of the width; 1.1 for re-im, which has
    /// two plots; 0.75 for paradox].
    #[arg(long, allow_hyphen_values = true)]
    height_mm: Option<f64>,
    /// Font size of the text in points.
    #[arg(long, default_value_t = 8.0, allow_hyphen_values = true)]
    font_pt: f64,
    /// Dots per inch of a PNG.
    #[arg(long, default_value_t = 300.0, allow_hyphen_values = true)]
    dpi: f64,
    #[command(flatten)]
    lang: super::headless::FigureLanguage,
    /// Lower end of the loads (locus, re-im and bifurcation).
    #[arg(long, allow_hyphen_values = true)]
    load_min: Option<f64>,
    /// Upper end of the loads (locus, re-im and bifurcation) [default: the
    /// end of the window's load bar: 8 for two rods, 8 (2/N)^2 for a chain
    /// of N].
    #[arg(long, allow_hyphen_values = true)]
    load_max: Option<f64>,
    /// The map's load axis, load:MIN:MAX:N [default: the load bar's range, 128 loads].
    #[arg(long, allow_hyphen_values = true)]
    x: Option<AxisArg>,
    /// The map's second axis, KEY:MIN:MAX:N [default: as the window's map, 128 values].
    #[arg(long, allow_hyphen_values = true)]
    y: Option<AxisArg>,
    /// The damping the paradox curves sweep, for a column with a tip force.
    #[arg(long, value_enum)]
    damping: Option<DampingArg>,
}

/// Cells along each axis of a map figure by default.
const MAP_CELLS: usize = 128;

impl Args {
    /// Refuses options the kind does not use: they would be ignored silently.
    fn check_options(&self) -> Result<()> {
        let mut unused: Vec<&str> = Vec::new();
        let loads = self.load_min.is_some() || self.load_max.is_some();
        match self.kind {
            Kind::Locus | Kind::ReIm | Kind::Bifurcation => {
                if self.x.is_some() || self.y.is_some() {
                    unused.push("--x/--y (the map's axes)");
                }
                if self.damping.is_some() {
                    unused.push("--damping (the paradox curves')");
                }
                if self.kind == Kind::Bifurcation && !self.overlay.is_empty() {
                    unused.push("--overlay (locus and re-im only)");
                }
            }
            Kind::Map | Kind::Paradox => {
                if !self.overlay.is_empty() {
                    unused.push("--overlay (locus and re-im only)");
                }
                if loads {
                    unused.push(if self.kind == Kind::Map {
                        "--load-min/--load-max (the map's loads are --x)"
                    } else {
                        "--load-min/--load-max (the paradox curves search their own range)"
                    });
                }
                if self.kind == Kind::Map && self.damping.is_some() {
                    unused.push("--damping (the paradox curves')");
                }
                if self.kind == Kind::Paradox && (self.x.is_some() || self.y.is_some()) {
                    unused.push("--x/--y (the map's axes)");
                }
            }
        }
        if unused.is_empty() {
            Ok(())
        } else {
            anyhow::bail!(
                "--kind {}: does not use {}",
                self.kind_name(),
                unused.join(", ")
            )
        }
    }

    fn kind_name(&self) -> String {
        self.kind
            .to_possible_value()
            .map_or_else(String::new, |v| v.get_name().to_owned())
    }

    fn page(&self) -> Page {
        Page {
            width_mm: self.width_mm,
            height_mm: self
                .height_mm
                .unwrap_or(self.width_mm * default_aspect(self.kind)),
            font_pt: self.font_pt,
            dpi: self.dpi,
        }
    }
}

pub fn run(args: &Args) -> Result<()> {
    let format = Format::of(&args.out).ok_or_else(|| {
        anyhow::anyhow!(
            "out = {}: figures are written as SVG or PNG; name the file *.svg or *.png",
            args.out.display()
        )
    })?;
    check_output(&args.out, false)?;
    args.check_options()?;
    // The page is checked before the work (a map takes seconds); a height
    // not typed is the width's, said so.
    let page = args.page();
    let (lowest, highest) = Page::WIDTH_MM;
    if args.height_mm.is_none()
        && (lowest..=highest).contains(&args.width_mm)
        && !(lowest..=highest).contains(&page.height_mm)
    {
        let aspect = default_aspect(args.kind);
        anyhow::bail!(
            "--width-mm {}: a {} figure is {} times as tall as it is wide unless --height-mm is given, here {} mm, beyond the page's {lowest} to {highest} mm; give --height-mm, or a width of {} to {} mm",
            Shown(args.width_mm),
            args.kind_name(),
            number_text(aspect),
            number_text(page.height_mm),
            number_text((lowest / aspect).max(lowest).ceil()),
            number_text((highest / aspect).min(highest).floor())
        );
    }
    page.check(format)?;
    let (preset, model) = args.model.build()?;
    let words = zieglerlab::i18n::words(args.lang.language);
    let sheet = match args.kind {
        Kind::Locus | Kind::ReIm => loci_sheet(args, &preset.to_string(), &model, words)?,
        Kind::Map => map_data(args, &model)?.sheet(words),
        Kind::Paradox => paradox_sheet(args, &model, words)?,
        Kind::Bifurcation => bifurcation_sheet(args, &model, words)?,
    };
    let rendered = render(&sheet, &page, format)?;
    for note in &rendered.notes {
        eprintln!("note: {}", printable(note));
    }
    write_atomically(&args.out, |file| {
        std::io::Write::write_all(file, &rendered.bytes)
    })
}

/// The loads the options ask for, checked with the rules of `critical`
/// (at most 1e150).
fn load_range(args: &Args, model: &Model) -> Result<(f64, f64)> {
    let load_min = args.load_min.unwrap_or(0.0);
    let load_max = args.load_max.unwrap_or_else(|| model.load_bar_max_p());
    load_grid(load_min, load_max, BRACKET_SAMPLES)?;
    Ok((load_min, load_max))
}

/// The root locus (`locus`) or Re and Im against the load (`re-im`) of
/// `model`, named `name`, with the overlays behind it.
fn loci_sheet(args: &Args, name: &str, model: &Model, words: &'static Words) -> Result<Sheet> {
    let loads = load_range(args, model)?;
    let progress = progress_bar(1 + args.overlay.len() as u64, "loci");
    let each = |name: &str, model: &Model| -> Result<Analysed> {
        let analysed = Analysed::new(name, model, loads, zieglerlab::machine_threads())?;
        if let Some(warning) = &analysed.warning {
            progress.suspend(|| {
                eprintln!(
                    "warning: {name}: {}; no critical load is drawn and no range tinted",
                    printable(&warning.to_string())
                );
            });
        }
        progress.inc(1);
        Ok(analysed)
    };
    let main = each(name, model)?;
    let overlays = args
        .overlay
        .iter()
        .map(|other| each(&other.to_string(), &other.model()))
        .collect::<Result<Vec<_>>>()?;
    progress.finish_and_clear();
    let loci = Loci {
        main: main.layer(),
        others: overlays.iter().map(Analysed::layer).collect(),
        medium: Medium::Paper,
        words,
    };
    Ok(loci.sheet(if args.kind == Kind::Locus {
        Part::Plane
    } else {
        Part::VersusLoad
    }))
}

/// The paradox curves of `model` for the damping asked for.
fn paradox_sheet(args: &Args, model: &Model, words: &'static Words) -> Result<Sheet> {
    let kind = match args.damping {
        Some(DampingArg::External) => DampingKind::External,
        Some(DampingArg::Joints) | None => DampingKind::Joints,
    };
    if args.damping.is_some() && model.roller().is_some() {
        anyhow::bail!(
            "--damping: the roller's curves sweep its mass ratio nu at three band speeds; leave --damping out"
        );
    }
    // A long chain's curves take seconds (16 rods: 8 s).
    let working = spinner("computing the first critical load at each ratio");
    let data = ParadoxData::new(model, kind, zieglerlab::machine_threads());
    working.finish_and_clear();
    if let Some(note) = &data.curves.note {
        return Err(FigureError::Empty(note.to_string()).into());
    }
    let sheet = data.sheet(words);
    if sheet.plots.is_empty() {
        return Err(FigureError::Empty("the curves have no extent".to_owned()).into());
    }
    Ok(sheet)
}

/// The bifurcation diagram of `model` over the loads asked for: the
/// branches of cycles from every flutter onset there, each said on
/// standard error as `bifurcation` says it.
fn bifurcation_sheet(args: &Args, model: &Model, words: &'static Words) -> Result<Sheet> {
    let loads = load_range(args, model)?;
    let pencil = AffinePencil::new(model)?.with_threads(zieglerlab::machine_threads());
    let working = spinner("limit cycles: shooting and continuation");
    let branches = cycle_branches(model, loads.0, loads.1, &AtomicBool::new(false))?;
    working.finish_and_clear();
    for onset in &branches {
        super::bifurcation::report(onset.load, &onset.branch);
    }
    Ok(BifurcationData::new(&pencil, loads, &branches, Vec::new())?.sheet(words))
}

/// The map the options ask for, computed on every core.
fn map_data(args: &Args, model: &Model) -> Result<MapData> {
    // The defaults as the axes would be typed (an f64 reads back exactly).
    let x = match &args.x {
        Some(x) => x.clone(),
        None => format!("load:0:{}:{MAP_CELLS}", model.load_bar_max_p())
            .parse()
            .map_err(anyhow::Error::msg)?,
    };
    let y = if let Some(y) = &args.y {
        y.clone()
    } else {
        let (axis, (min, max)) = default_map_axis(model);
        format!("{}:{min}:{max}:{MAP_CELLS}", axis.name())
            .parse()
            .map_err(anyhow::Error::msg)?
    };
    let spec = map_spec(*model, &x, &y)?;
    let rows: Vec<Option<RowResult>> = compute_rows(&spec)?;
    let complete = complete_rows(&rows, spec.axis.name())?;
    warn_if_unresolved(&spec, &complete, spec.axis.name())?;
    Ok(MapData { spec, rows })
}
