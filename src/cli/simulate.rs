//! `zieglerlab simulate`: a time simulation from every angle = perturb at
//! rest, one CSV row per step.

use std::io::Write;
use std::ops::ControlFlow;

use anyhow::Result;
use clap::ValueEnum;
use zieglerlab::format::Shown;

use zieglerlab::export::{history_header, history_row};
use zieglerlab::sim::{DEFAULT_STEP_SECS, Observables, Ramp, Simulation, Status, initial_state};

use super::{EngineArg, ModelArgs};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Format {
    Csv,
}

/// Most rows a simulation prints (duration / dt).
const MAX_ROWS: f64 = 1.0e7;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// Simulated time in seconds.
    #[arg(long, allow_hyphen_values = true)]
    duration: f64,
    #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
    engine: EngineArg,
    /// Initial angle of both rods, in rad.
    #[arg(long, default_value_t = 0.001, allow_hyphen_values = true)]
    perturb: f64,
    /// Time step (and output interval), in s.
    #[arg(long, default_value_t = DEFAULT_STEP_SECS, allow_hyphen_values = true)]
    dt: f64,
    /// A quasi-static load ramp, `FROM:TO:RATE` (loads p, RATE in p per
    /// simulated second): the load starts at FROM, moves at RATE, stays at
    /// TO; the CSV gains a `load` column.
    #[arg(long, value_name = "FROM:TO:RATE")]
    ramp: Option<Ramp>,
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    format: Format,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    let Format::Csv = args.format;
    let (_, model) = args.model.build_ramped(args.ramp.as_ref())?;
    let (duration, perturb, dt) = (args.duration, args.perturb, args.dt);
    if !(duration.is_finite() && duration > 0.0) {
        anyhow::bail!(
            "duration = {}: must be a positive number of seconds",
            Shown(duration)
        );
    }
    if !(perturb.is_finite() && perturb.abs() <= 1.0) {
        anyhow::bail!(
            "perturb = {}: must be an angle in [-1, 1] rad",
            Shown(perturb)
        );
    }
    if dt.is_finite() && dt > 0.0 && duration / dt > MAX_ROWS {
        anyhow::bail!(
            "duration / dt = {}: at most {MAX_ROWS} rows; raise dt",
            duration / dt
        );
    }
    let mut simulation = Simulation::new(
        model,
        args.engine.into(),
        initial_state(&model, perturb),
        dt,
    )?;
    let mut out = std::io::BufWriter::new(out);
    writeln!(
        out,
        "{}",
        history_header(model.column.rods, args.ramp.is_some())
    )?;
    let mut row = |o: &Observables, load: Option<f64>| writeln!(out, "{}", history_row(o, load));
    let first_load = args.ramp.map(|ramp| ramp.from_p);
    row(&simulation.observe(), first_load)?;
    // A row that cannot be written (the reader went away: `| head`) ends
    // the run there, not at the end of the duration.
    let mut written = Ok(());
    let mut keep = |result: std::io::Result<()>| {
        written = result;
        if written.is_ok() {
            ControlFlow::Continue(())
        } else {
            ControlFlow::Break(())
        }
    };
    let status = match &args.ramp {
        Some(ramp) => {
            simulation.run_ramp_while(ramp, duration, |o, load| keep(row(o, Some(load))))?
        }
        None => simulation.run_while(duration, |o| keep(row(o, None))),
    };
    written?;
    out.flush()?;
    if status != Status::Running {
        eprintln!("run stopped: {status}");
    }
    Ok(())
}
