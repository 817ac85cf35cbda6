//! `zieglerlab map`: the state and growth rate of every cell of a grid over
//! the load and a second parameter, as CSV or a PNG picture.

use std::str::FromStr;
use std::sync::atomic::{AtomicBool, AtomicUsize};

use anyhow::Result;
use clap::ValueEnum;

use zieglerlab::analysis::{
    AffinePencil, AnalysisError, MapSpec, Row, RowResult, bracketing_locus, check_largest_load,
    compute_map, load_grid, resolution_warning,
};
use zieglerlab::model::{Axis, Key, Model, Shown};

use zieglerlab::figure::{self, Page, render};
use zieglerlab::format::Exact;
use zieglerlab::plot::map::MapData;

use super::output::{check_output, write_atomically};
use super::{ModelArgs, printable, progress_bar};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Csv,
    Png,
}

/// The most cells along one axis of a map.
const MAX_CELLS: usize = 2048;

/// `text` as a finite number, or why it is not one.
pub fn finite_number(text: &str) -> Result<f64, String> {
    text.trim()
        .parse::<f64>()
        .ok()
        .filter(|v| v.is_finite())
        .ok_or_else(|| format!("'{text}' is not a finite number"))
}

/// One axis of the map as `NAME:MIN:MAX:N`: N evenly spaced values from MIN
/// to MAX, ends included (the name may hold ':'-free '/', as c1/c2).
#[derive(Clone, Debug)]
pub struct AxisArg {
    pub text: String,
    pub name: String,
    pub min: f64,
    pub max: f64,
    pub count: usize,
}

impl FromStr for AxisArg {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        let shape = || "must be NAME:MIN:MAX:N (e.g. nu:0.01:1:256)".to_owned();
        let mut parts = text.rsplitn(4, ':');
        let (Some(n), Some(max), Some(min), Some(name)) =
            (parts.next(), parts.next(), parts.next(), parts.next())
        else {
            return Err(shape());
        };
        let (min, max) = (finite_number(min)?, finite_number(max)?);
        let count: usize = n
            .trim()
            .parse()
            .map_err(|_| format!("N = '{n}' is not a count"))?;
        if !(1..=MAX_CELLS).contains(&count) {
            return Err(format!("N = {count}: must be 1 to {MAX_CELLS}"));
        }
        if !(max > min || (count == 1 && max == min)) {
            return Err("MAX must be above MIN (or equal with N = 1)".to_owned());
        }
        Ok(Self {
            text: text.to_owned(),
            name: name.trim().to_owned(),
            min,
            max,
            count,
        })
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    #[command(flatten)]
    lang: super::headless::FigureLanguage,
    /// The load axis, load:MIN:MAX:N (N evenly spaced loads, ends included).
    #[arg(long, allow_hyphen_values = true)]
    x: AxisArg,
    /// The second axis, KEY:MIN:MAX:N.
    #[arg(long, allow_hyphen_values = true)]
    y: AxisArg,
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    format: Format,
    #[arg(long)]
    out: std::path::PathBuf,
}

impl Args {
    /// Whether the map goes to a pipe or a device (`--out /dev/stdout`)
    /// rather than a file.
    pub fn streams(&self) -> bool {
        super::output::streams(Some(&self.out))
    }
}

pub fn run(args: &Args) -> Result<()> {
    let Args { x, y, out, .. } = args;
    check_output(out, args.format == Format::Png)?;
    let (_, model) = args.model.build()?;
    let spec = map_spec(model, x, y)?;
    let rows = compute_rows(&spec)?;
    let complete = complete_rows(&rows, &y.text)?;
    warn_if_unresolved(&spec, &complete, &y.name)?;
    match args.format {
        Format::Csv => {
            let grid = spec.load_grid()?;
            write_atomically(out, |file| {
                writeln!(file, "load,{},state,growth_rate", y.name)?;
                for row in &complete {
                    for (p, cell) in grid.iter().zip(&row.cells) {
                        writeln!(
                            file,
                            "{},{},{},{}",
                            Exact(*p),
                            Exact(row.value),
                            cell.state.name(),
                            Exact(cell.growth_per_s)
                        )?;
                    }
                }
                Ok(())
            })?;
        }
        Format::Png => {
            // The same figure as `figure --kind map`, at its default page.
            let sheet = MapData { spec, rows }.sheet(zieglerlab::i18n::words(args.lang.language));
            let rendered = render(&sheet, &Page::default(), figure::Format::Png)?;
            write_atomically(out, |file| file.write_all(&rendered.bytes))?;
        }
    }
    Ok(())
}

/// The map of `model` over the axes `x` (the load) and `y`.
///
/// # Errors
/// An axis that is not the load first, negative loads, an unknown second
/// axis or the load again.
pub fn map_spec(model: Model, x: &AxisArg, y: &AxisArg) -> Result<MapSpec> {
    check_load_axis(x, "the map's first axis")?;
    load_axis_grid(x)?;
    let axis = Axis::parse(&y.name, &model)?;
    if axis == Axis::Key(Key::Load) {
        anyhow::bail!("--y {}: the second axis cannot be the load again", y.text);
    }
    let spec = MapSpec {
        model,
        axis,
        load_range: (x.min, x.max),
        loads: x.count,
        axis_range: (y.min, y.max),
        values: y.count,
    };
    // The second axis's ends and grid, named as typed, before any work.
    spec.value_grid()
        .map_err(|error| in_axis_words("--y", y, &error))?;
    Ok(spec)
}

/// That `--x` is the load from 0 up (`what`: the axis, for the message).
///
/// # Errors
/// Another axis, or negative loads.
pub fn check_load_axis(x: &AxisArg, what: &str) -> Result<()> {
    if x.name != "load" {
        anyhow::bail!("--x {}: {what} is the load: load:MIN:MAX:N", x.text);
    }
    if x.min < 0.0 {
        anyhow::bail!("--x {}: loads must be >= 0", x.text);
    }
    Ok(())
}

/// The loads of `--x` (checked by [`check_load_axis`] first): at most the
/// largest load the analysis resolves, and a grid of distinct loads, by
/// the analysis's own checks, refused in the axis's own words.
///
/// # Errors
/// A range past the largest load or a grid the loads cannot hold.
pub fn load_axis_grid(x: &AxisArg) -> Result<Vec<f64>> {
    check_largest_load(x.max)
        .and_then(|()| load_grid(x.min, x.max, x.count))
        .map_err(|error| in_axis_words("--x", x, &error))
}

/// `error` about the grid of the axis `flag` said in the axis's words
/// (`MIN`, `MAX`, `N`), not in those of `critical`'s options.
fn in_axis_words(flag: &str, x: &AxisArg, error: &AnalysisError) -> anyhow::Error {
    match error {
        AnalysisError::BadRange {
            what,
            value,
            allowed,
        } => {
            let part = match *what {
                "load-min" => "MIN",
                "load-max" => "MAX",
                "samples" => "N",
                "axis range" => "MIN:MAX",
                other => other,
            };
            let allowed = allowed
                .replace("load-min", "MIN")
                .replace("load-max", "MAX")
                .replace("samples", "N");
            anyhow::anyhow!("{flag} {}: {part} = {}: {allowed}", x.text, Shown(*value))
        }
        other => anyhow::anyhow!("{flag} {}: {other}", x.text),
    }
}

/// Every row of a computed map, or why one has no analysis (`y_text`: the
/// second axis as given, for the message).
///
/// # Errors
/// A row without analysis, or one not computed.
pub fn complete_rows<'a>(rows: &'a [Option<RowResult>], y_text: &str) -> Result<Vec<&'a Row>> {
    rows.iter()
        .map(|row| match row {
            Some(Ok(row)) => Ok(row),
            Some(Err(reason)) => Err(anyhow::anyhow!("--y {y_text}: no analysis there: {reason}")),
            None => Err(anyhow::anyhow!("a map row was not computed")),
        })
        .collect()
}

/// Every row of `spec` on every core, with a progress bar.
pub fn compute_rows(spec: &MapSpec) -> Result<Vec<Option<RowResult>>> {
    let rows: std::sync::Mutex<Vec<Option<RowResult>>> =
        std::sync::Mutex::new(vec![None; spec.values]);
    let threads = zieglerlab::machine_threads();
    let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
    let progress = progress_bar(spec.values as u64, "map rows");
    compute_map(spec, threads, &cancel, &done, &|j, row| {
        if let Ok(mut rows) = rows.lock() {
            rows[j] = Some(row);
        }
        progress.inc(1);
    })?;
    progress.finish_and_clear();
    rows.into_inner()
        .map_err(|_| anyhow::anyhow!("a map thread failed"))
}

/// Checks the resolution of the map's rows at both ends of the second axis
/// and in its middle: where a singular limit (a tiny roller mass, a slow
/// band) leaves the states to rounding, the map says so as `critical` does.
pub fn warn_if_unresolved(spec: &MapSpec, rows: &[&Row], y_name: &str) -> Result<()> {
    let (load_min, load_max) = spec.load_range;
    for row in [rows.first(), rows.get(rows.len() / 2), rows.last()]
        .into_iter()
        .flatten()
    {
        let model = spec.axis.apply(&spec.model, row.value)?;
        let pencil = AffinePencil::new(&model)?;
        let bracket = bracketing_locus(&pencil, load_min, load_max)?;
        if let Some(warning) = resolution_warning(&pencil, &bracket)? {
            eprintln!(
                "warning: at {y_name} = {}: {}",
                Shown(row.value),
                printable(&warning.to_string())
            );
            break;
        }
    }
    Ok(())
}
