//! `zieglerlab bifurcation`: the straight column's stability and the limit
//! cycles born at its flutter onsets, at evenly spaced loads, as CSV or
//! JSON, or as a figure (PNG); with `--sweep`, also what a run shows with
//! the load stepped up and back down.

use std::io::Write;
use std::sync::atomic::AtomicBool;

use anyhow::Result;
use clap::ValueEnum;
use serde_json::json;

use zieglerlab::analysis::{
    AffinePencil, Branch, Cycle, CycleBifurcation, CycleBifurcationKind, NoBranch, Onset, State,
    classify, cycle_branches, cycles_at,
};
use zieglerlab::figure::{self, Page, render};
use zieglerlab::format::{Exact, Shown};
use zieglerlab::model::Model;
use zieglerlab::plot::bifurcation::BifurcationData;
use zieglerlab::sim::{Status, SweepStep, SweepTimes, sweep};

use super::map::{AxisArg, check_load_axis, load_axis_grid};
use super::output::{check_output, write_atomically};
use super::{LOAD_AXIS, ModelArgs, printable, progress_bar, spinner};

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Csv,
    Json,
    /// The diagram as a figure (the page of `figure`'s defaults).
    Png,
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    #[command(flatten)]
    lang: super::headless::FigureLanguage,
    /// The loads, load:MIN:MAX:N (N evenly spaced, ends included). Cycles
    /// are followed from every flutter onset in this range. One load,
    /// load:L:L:1, gives the cycles at L followed from every onset below.
    #[arg(long, allow_hyphen_values = true)]
    x: AxisArg,
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    format: Format,
    /// Where to write [default: standard output].
    #[arg(long)]
    out: Option<std::path::PathBuf>,
    /// Also sweep as an experiment does: the reference engine with the load
    /// stepped up the loads then back down, each step going on from where
    /// the last ended, its largest angles measured after settling (rows
    /// `sweep-up` and `sweep-down`, `stable` left empty: a run, not an
    /// analysis).
    #[arg(long)]
    sweep: bool,
    /// Each sweep step runs this many periods of the column's slowest
    /// oscillation at the first load before it is measured.
    #[arg(
        long,
        default_value_t = 50.0,
        requires = "sweep",
        allow_hyphen_values = true
    )]
    settle_periods: f64,
    /// ... and is measured over this many.
    #[arg(
        long,
        default_value_t = 4.0,
        requires = "sweep",
        allow_hyphen_values = true
    )]
    measure_periods: f64,
}

impl Args {
    /// Whether the diagram goes to standard output, a pipe or a device.
    pub fn streams(&self) -> bool {
        super::output::streams(self.out.as_deref())
    }
}

/// Most sweep periods per step (settling and measuring).
const MAX_SWEEP_PERIODS: f64 = 10_000.0;

/// One row of the diagram.
struct Row {
    load: f64,
    branch: String,
    /// Empty for a sweep step.
    stable: Option<bool>,
    period_secs: Option<f64>,
    amplitude_rad: Vec<f64>,
    multipliers: Vec<[f64; 2]>,
}

pub fn run(args: &Args) -> Result<()> {
    match (&args.out, args.format) {
        (None, Format::Png) => {
            anyhow::bail!("--format png: give the picture's file with --out FILE.png")
        }
        (Some(out), format) => check_output(out, format == Format::Png)?,
        (None, _) => {}
    }
    let (name, model) = args.model.build()?;
    let loads = loads(&args.x)?;
    if !(args.settle_periods.is_finite()
        && args.settle_periods > 0.0
        && args.settle_periods <= MAX_SWEEP_PERIODS)
    {
        anyhow::bail!(
            "--settle-periods {}: must be a number of periods in (0, {MAX_SWEEP_PERIODS}]",
            Shown(args.settle_periods)
        );
    }
    // The largest angle of a swing is only seen over a whole period.
    if !(args.measure_periods.is_finite()
        && (1.0..=MAX_SWEEP_PERIODS).contains(&args.measure_periods))
    {
        anyhow::bail!(
            "--measure-periods {}: must be a number of periods from 1 to {MAX_SWEEP_PERIODS} (the largest angle of a swing is seen over a whole period)",
            Shown(args.measure_periods)
        );
    }
    // One load: the cycles there, followed from every onset below it.
    let single = loads.len() == 1;
    if single && (args.sweep || args.format == Format::Png) {
        anyhow::bail!(
            "--x {}: one load has no diagram and no sweep; give a range of loads for --format png or --sweep",
            args.x.text
        );
    }
    let (lo, hi) = if single {
        (0.0, args.x.max)
    } else {
        (args.x.min, args.x.max)
    };
    let pencil = AffinePencil::new(&model)?.with_threads(zieglerlab::machine_threads());
    let mut rows = equilibrium_rows(&pencil, &loads, model.column.rods)?;
    let working = spinner("limit cycles: shooting and continuation");
    let branches = cycle_branches(&model, lo, hi, &AtomicBool::new(false))?;
    working.finish_and_clear();
    for onset in &branches {
        report(onset.load, &onset.branch);
        if let Ok(branch) = &onset.branch {
            rows.extend(cycle_rows(branch.name(), &loads, |p| {
                cycles_at(&model, branch, p)
            }));
            for offshoot in &branch.offshoots {
                rows.extend(cycle_rows(offshoot.name(), &loads, |p| {
                    offshoot.cycles_at(&model, p)
                }));
            }
        }
    }
    if args.sweep {
        rows.extend(sweep_rows(&model, &pencil, &loads, args)?);
    }
    if args.format == Format::Png {
        let data = BifurcationData::new(&pencil, (lo, hi), &branches, sweep_steps(&rows))?;
        let sheet = data.sheet(zieglerlab::i18n::words(args.lang.language));
        let rendered = render(&sheet, &Page::default(), figure::Format::Png)?;
        let out = args
            .out
            .as_ref()
            .ok_or_else(|| anyhow::anyhow!("no --out"))?;
        return write_atomically(out, |file| file.write_all(&rendered.bytes));
    }
    let write = |out: &mut dyn Write| -> std::io::Result<()> {
        match args.format {
            Format::Json => write_json(out, &name.to_string(), &branches, &rows),
            Format::Csv | Format::Png => {
                write_csv(out, &rows, &branches, (lo, hi), model.column.rods)
            }
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

/// The grid of `--x`, checked: the load, from 0 up; one load as
/// `load:L:L:1`.
fn loads(x: &AxisArg) -> Result<Vec<f64>> {
    check_load_axis(x, "the diagram's axis")?;
    if x.count == 1 && x.max == x.min {
        return Ok(vec![x.min]);
    }
    if x.count < 2 || x.max <= x.min {
        anyhow::bail!(
            "--x {}: a diagram needs a range of loads (MAX above MIN, N at least 2), or one load as load:L:L:1",
            x.text
        );
    }
    // The grid of the other commands (`locus`, `map`): the same loads.
    load_axis_grid(x)
}

/// The straight column at each load: stable or not, at rest.
fn equilibrium_rows(pencil: &AffinePencil, loads: &[f64], rods: usize) -> Result<Vec<Row>> {
    loads
        .iter()
        .map(|&p| {
            let spectrum = pencil.spectrum(p)?;
            let state = classify(&spectrum.eigenvalues, spectrum.scale_per_s).state;
            Ok(Row {
                load: p,
                branch: "equilibrium".to_owned(),
                stable: Some(state == State::Stable),
                period_secs: None,
                amplitude_rad: vec![0.0; rods],
                multipliers: Vec::new(),
            })
        })
        .collect()
}

/// A sweep's steps among `rows`: `(load, largest angle, upward)`.
fn sweep_steps(rows: &[Row]) -> Vec<(f64, f64, bool)> {
    let largest = |row: &Row| row.amplitude_rad.iter().copied().fold(0.0, f64::max);
    rows.iter()
        .filter(|row| row.branch.starts_with("sweep-"))
        .map(|row| (row.load, largest(row), row.branch == "sweep-up"))
        .collect()
}

/// What was found at one flutter onset, on stderr.
pub fn report(onset: f64, found: &Result<Branch, NoBranch>) {
    let at = Shown(onset);
    let line = match found {
        Ok(branch) => {
            let hopf = branch.hopf();
            format!(
                "{}: {} onset at p = {at} (first Lyapunov coefficient {:.4e}), {} cycles followed; the branch ended: {}",
                branch.name(),
                branch.onset_word(),
                hopf.first_lyapunov,
                branch.cycles.len(),
                branch.end
            )
        }
        Err(why) => format!("flutter onset at p = {at}: {why}"),
    };
    eprintln!("{}", printable(&line));
    if let Ok(branch) = found {
        report_bifurcations(branch.name(), &branch.bifurcations);
        for offshoot in &branch.offshoots {
            eprintln!(
                "{}: asymmetric cycles born at the break of {}'s mirror symmetry at p = {}, {} cycles followed (and their mirror images); the branch ended: {}",
                offshoot.name(),
                branch.name(),
                Shown(offshoot.born.load),
                offshoot.cycles.len(),
                offshoot.end
            );
            report_bifurcations(offshoot.name(), &offshoot.bifurcations);
        }
    }
}

/// A line on stderr for each of the bifurcations `found` on the branch
/// `name`.
fn report_bifurcations(name: &str, found: &[CycleBifurcation]) {
    for found in found {
        let kind = match found.kind {
            CycleBifurcationKind::Fold => "fold of cycles",
            CycleBifurcationKind::PeriodDoubling => "period doubling",
            CycleBifurcationKind::NeimarkSacker => "Neimark-Sacker (torus)",
            CycleBifurcationKind::SymmetryBreaking => {
                "break of the mirror symmetry (branch point of cycles)"
            }
        };
        let placed = if found.refined {
            ""
        } else {
            ", interpolated between two cycles: not solved for"
        };
        eprintln!(
            "{name}: {kind} at p = {} (largest angle {:.4} rad{placed})",
            Shown(found.load),
            found.amplitude_rad
        );
    }
}

fn cycle_row(cycle: &Cycle, branch: &str) -> Row {
    Row {
        load: cycle.load,
        branch: branch.to_owned(),
        stable: Some(cycle.stable),
        period_secs: Some(cycle.period_secs),
        amplitude_rad: cycle.amplitude_rad.clone(),
        multipliers: cycle.multipliers.iter().map(|m| [m.re, m.im]).collect(),
    }
}

/// The cycles of the branch `name` at each grid load (two where it folds
/// back), as `at` solves for them at a load.
fn cycle_rows(name: &str, loads: &[f64], at: impl Fn(f64) -> Vec<Cycle>) -> Vec<Row> {
    let progress = progress_bar(loads.len() as u64, &format!("{name} at the loads"));
    let rows = loads
        .iter()
        .flat_map(|&p| {
            progress.inc(1);
            at(p)
        })
        .map(|cycle| cycle_row(&cycle, name))
        .collect();
    progress.finish_and_clear();
    rows
}

/// The sweep's steps as rows.
fn sweep_rows(
    model: &Model,
    pencil: &AffinePencil,
    loads: &[f64],
    args: &Args,
) -> Result<Vec<Row>> {
    let slowest = pencil
        .spectrum(loads[0])?
        .eigenvalues
        .iter()
        .map(|z| z.im.abs())
        .filter(|w| *w > 0.0)
        .fold(f64::INFINITY, f64::min);
    if !slowest.is_finite() {
        anyhow::bail!(
            "--sweep: the column does not oscillate at p = {}: no period to settle over",
            Shown(loads[0])
        );
    }
    let period = std::f64::consts::TAU / slowest;
    let times = SweepTimes {
        settle_secs: args.settle_periods * period,
        measure_secs: args.measure_periods * period,
        step_secs: (period / 256.0).min(1.0),
    };
    let progress = progress_bar(2 * loads.len() as u64 - 1, "sweep steps");
    let (steps, status) = sweep(model, loads, times, |_| progress.inc(1))?;
    progress.finish_and_clear();
    if status != Status::Running {
        let at = steps.last().map_or(loads[0], |s: &SweepStep| s.load);
        eprintln!(
            "warning: the sweep stopped after p = {}: the run stopped ({status:?}); {} of {} steps",
            Shown(at),
            steps.len(),
            2 * loads.len() - 1
        );
    }
    Ok(steps
        .into_iter()
        .map(|step| Row {
            load: step.load,
            branch: if step.upward {
                "sweep-up"
            } else {
                "sweep-down"
            }
            .to_owned(),
            stable: None,
            period_secs: step.period_secs,
            amplitude_rad: step.amplitude_rad,
            multipliers: Vec::new(),
        })
        .collect())
}

/// The rows, then a row for each bifurcation of the cycles in `[lo, hi]`
/// (its load, its branch, its kind in the last column, the rest empty).
fn write_csv(
    out: &mut dyn Write,
    rows: &[Row],
    branches: &[Onset],
    (lo, hi): (f64, f64),
    rods: usize,
) -> std::io::Result<()> {
    let amplitudes: Vec<String> = (1..=rods).map(|i| format!("amp_phi{i}_rad")).collect();
    writeln!(
        out,
        "load,branch,stable,period_s,{},bifurcation",
        amplitudes.join(",")
    )?;
    for row in rows {
        let stable = row.stable.map_or(String::new(), |s| s.to_string());
        let period = row
            .period_secs
            .map_or(String::new(), |t| Exact(t).to_string());
        let amplitudes: Vec<String> = row
            .amplitude_rad
            .iter()
            .map(|a| Exact(*a).to_string())
            .collect();
        writeln!(
            out,
            "{},{},{stable},{period},{},",
            Exact(row.load),
            row.branch,
            amplitudes.join(",")
        )?;
    }
    let empty = ",".repeat(rods);
    let paths = branches
        .iter()
        .filter_map(|onset| onset.branch.as_ref().ok())
        .flat_map(|branch| {
            let offshoots = branch.offshoots.iter();
            std::iter::once((branch.name(), &branch.bifurcations))
                .chain(offshoots.map(|o| (o.name(), &o.bifurcations)))
        });
    for (name, events) in paths {
        for event in events {
            if (lo..=hi).contains(&event.load) {
                writeln!(
                    out,
                    "{},{name},,,{empty}{}",
                    Exact(event.load),
                    bifurcation_word(event.kind)
                )?;
            }
        }
    }
    Ok(())
}

/// A bifurcation of the cycles as the CSV names it.
fn bifurcation_word(kind: CycleBifurcationKind) -> &'static str {
    match kind {
        CycleBifurcationKind::Fold => "fold",
        CycleBifurcationKind::PeriodDoubling => "period-doubling",
        CycleBifurcationKind::NeimarkSacker => "neimark-sacker",
        CycleBifurcationKind::SymmetryBreaking => "symmetry-breaking",
    }
}

fn write_json(
    out: &mut dyn Write,
    preset: &str,
    branches: &[Onset],
    rows: &[Row],
) -> std::io::Result<()> {
    let onsets: Vec<_> = branches
        .iter()
        .map(|Onset { load, branch }| match branch {
            Ok(branch) => json!({
                "load": load,
                "hopf": branch.hopf(),
                "branch": branch.name(),
                "cycles_followed": branch.cycles.len(),
                "cycle_bifurcations": branch.bifurcations,
                "end": branch.end.to_string(),
                "offshoots": branch.offshoots.iter().map(|o| json!({
                    "branch": o.name(),
                    "born_at_load": o.born.load,
                    "cycles_followed": o.cycles.len(),
                    "cycle_bifurcations": o.bifurcations,
                    "end": o.end.to_string(),
                })).collect::<Vec<_>>(),
            }),
            Err(why) => {
                json!({"load": load, "branch": null, "why": format!("{why:?}").to_lowercase()})
            }
        })
        .collect();
    let rows: Vec<_> = rows
        .iter()
        .map(|row| {
            json!({
                "load": row.load,
                "branch": row.branch,
                "stable": row.stable,
                "period_s": row.period_secs,
                "amplitude_rad": row.amplitude_rad,
                "floquet_multipliers": row.multipliers,
            })
        })
        .collect();
    let value = json!({"axis": LOAD_AXIS, "preset": preset, "onsets": onsets, "rows": rows});
    serde_json::to_writer_pretty(&mut *out, &value)?;
    writeln!(out)
}
