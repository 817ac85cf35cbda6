//! `zieglerlab locus`: every eigenvalue at evenly spaced loads, branches
//! tracked, as CSV or JSON (streamed row by row either way).

use std::io::Write;

use anyhow::Result;
use clap::ValueEnum;
use serde_json::json;

use zieglerlab::analysis::{AffinePencil, locus_streamed, resolution_warning};
use zieglerlab::export::{LOCUS_HEADER, locus_rows};

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
    let pencil = AffinePencil::new(&model)?.with_threads(zieglerlab::machine_threads());
    // The rows go out as each load is final, so a long chain's locus shows
    // at once and a reader that has gone (`| head`) stops the work; the
    // header with the first load, so that a refused range writes nothing.
    let header = |out: &mut dyn Write| -> Result<()> {
        match args.format {
            Format::Csv => writeln!(out, "{LOCUS_HEADER}")?,
            Format::Json => write!(
                out,
                "{{\"load_axis\":{},\"preset\":{},\"rows\":[",
                serde_json::to_string(LOAD_AXIS)?,
                serde_json::to_string(&name)?
            )?,
        }
        Ok(())
    };
    let progress = progress_bar(args.samples.saturating_sub(1) as u64, "loads");
    let mut written: Result<()> = Ok(());
    let locus = locus_streamed(
        &pencil,
        args.load_min,
        args.load_max,
        args.samples,
        |index, load, row: &[zieglerlab::analysis::C64]| {
            if index % 50 == 0 {
                progress.set_position(index as u64);
            }
            written = if index == 0 { header(out) } else { Ok(()) }
                .and_then(|()| write_rows(out, args.format, index, load, row));
            written.is_ok()
        },
    )?;
    progress.finish_and_clear();
    written?;
    if let Format::Json = args.format {
        writeln!(
            out,
            "],\"structural_zero_branches\":{}}}",
            locus.structural_zeros
        )?;
    }
    if let Some(warning) = resolution_warning(&pencil, &locus)? {
        eprintln!("warning: {}", printable(&warning.to_string()));
    }
    Ok(())
}

/// One load's rows, every branch: CSV lines, or JSON objects each after a
/// comma but the very first (the keys in `serde_json`'s order, so the text is
/// what one `to_string` of the whole would be).
fn write_rows(
    out: &mut impl Write,
    format: Format,
    index: usize,
    load: f64,
    row: &[zieglerlab::analysis::C64],
) -> Result<()> {
    if matches!(format, Format::Csv) {
        write!(out, "{}", locus_rows(load, row))?;
        return Ok(());
    }
    for (branch, z) in row.iter().enumerate() {
        let row = json!({"load": load, "branch": branch, "re": z.re, "im": z.im});
        let separator = if index == 0 && branch == 0 { "" } else { "," };
        write!(out, "{separator}{}", serde_json::to_string(&row)?)?;
    }
    Ok(())
}
