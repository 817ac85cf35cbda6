//! `zieglerlab locus`: every eigenvalue at evenly spaced loads, branches
//! tracked, as CSV or JSON (streamed row by row either way).

use std::io::Write;

use anyhow::Result;
use clap::ValueEnum;
use serde_json::json;

use zieglerlab::analysis::{AffinePencil, locus_reporting, resolution_warning};
use zieglerlab::format::Exact;

use super::{LOAD_AXIS, ModelArgs, printable, progress_bar};

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Format {
    Csv,
    Json,
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    #[arg(long, allow_hyphen_values = true)]
    load_min: f64,
    #[arg(long, allow_hyphen_values = true)]
    load_max: f64,
    #[arg(long, allow_hyphen_values = true)]
    samples: usize,
    #[arg(long, value_enum, default_value_t = Format::Csv)]
    format: Format,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    let (name, model) = args.model.build()?;
    let pencil = AffinePencil::new(&model)?;
    // A long chain's fine locus takes minutes: progress on a terminal.
    let progress = progress_bar(args.samples.saturating_sub(1) as u64, "loads");
    let locus = locus_reporting(
        &pencil,
        args.load_min,
        args.load_max,
        args.samples,
        &mut |done, _| {
            if done % 50 == 0 {
                progress.set_position(done as u64);
            }
        },
    )?;
    progress.finish_and_clear();
    if let Some(warning) = resolution_warning(&pencil, &locus)? {
        eprintln!("warning: {}", printable(&warning));
    }
    let locus = &locus;
    let rows = (0..locus.loads.len())
        .filter(|&i| locus.on_grid[i])
        .flat_map(|i| {
            locus
                .at(i)
                .enumerate()
                .map(move |(b, z)| (locus.loads[i], b, z))
        });
    match args.format {
        Format::Csv => {
            writeln!(out, "load,branch,re,im")?;
            for (load, branch, z) in rows {
                writeln!(
                    out,
                    "{},{branch},{},{}",
                    Exact(load),
                    Exact(z.re),
                    Exact(z.im)
                )?;
            }
        }
        Format::Json => {
            // Streamed row by row, as the CSV is (a million samples would
            // otherwise be one document in memory); the keys in serde_json's
            // order, so the text is what one `to_string` of it would be.
            write!(
                out,
                "{{\"load_axis\":{},\"preset\":{},\"rows\":[",
                serde_json::to_string(LOAD_AXIS)?,
                serde_json::to_string(&name)?
            )?;
            for (k, (load, branch, z)) in rows.enumerate() {
                let row = json!({"load": load, "branch": branch, "re": z.re, "im": z.im});
                let separator = if k == 0 { "" } else { "," };
                write!(out, "{separator}{}", serde_json::to_string(&row)?)?;
            }
            writeln!(
                out,
                "],\"structural_zero_branches\":{}}}",
                locus.structural_zeros
            )?;
        }
    }
    Ok(())
}
