//! `zieglerlab critical`: every change of stability along the load axis.

use std::io::Write;

use anyhow::Result;
use serde_json::json;

use zieglerlab::analysis::{
    AffinePencil, HopfSteps, NoHopf, Transition, bracketing_locus_reporting, critical_loads_along,
    hopf_at, is_hopf, resolution_warning,
};
use zieglerlab::format::Shown;
use zieglerlab::model::Model;

use super::{LOAD_AXIS, ModelArgs, printable, progress_bar};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// Lower end of the load range searched.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    load_min: f64,
    /// Upper end of the load range searched [default: 10 for two rods; for
    /// a chain of N rods 10 (2/N)^2, the same range in the continuous
    /// column's units P L^2/EI (0 to 40)].
    #[arg(long, allow_hyphen_values = true)]
    load_max: Option<f64>,
    #[arg(long)]
    json: bool,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    let (name, model) = args.model.build()?;
    let load_min = args.load_min;
    let load_max = args.load_max.unwrap_or_else(|| model.analysis_max_p());
    if load_max == load_min {
        anyhow::bail!(
            "load-max = {}: must exceed load-min: the changes of stability are sought over a range of loads",
            Shown(load_max)
        );
    }
    let pencil = AffinePencil::new(&model)?.with_threads(zieglerlab::machine_threads());
    // A wide range on a long chain takes minutes: progress on a terminal.
    let progress = progress_bar(0, "loads bracketed");
    let bracket = bracketing_locus_reporting(&pencil, load_min, load_max, &mut |done, total| {
        if done % 50 == 0 {
            progress.set_length(total as u64);
            progress.set_position(done as u64);
        }
    })?;
    progress.finish_and_clear();
    let transitions = critical_loads_along(&pencil, &bracket)?;
    let warning = resolution_warning(&pencil, &bracket)?;
    if let Some(warning) = &warning {
        eprintln!("warning: {}", printable(&warning.to_string()));
    }
    // Where rounding decides the states, the changes it makes are noise
    // (thousands, for a roller of mass nu = 1e-50): none is listed as if it
    // were found; they are counted.
    let unlisted = if warning.is_some() {
        transitions.len()
    } else {
        0
    };
    let transitions = &transitions[..transitions.len() - unlisted];
    if args.json {
        let listed = transitions
            .iter()
            .map(|t| with_hopf(&model, t))
            .collect::<Result<Vec<_>>>()?;
        let value = json!({
            "preset": name,
            "load_axis": LOAD_AXIS,
            "load_min": load_min,
            "load_max": load_max,
            "transitions": listed,
            "rods": model.column.rods,
            "beck_loads": transitions.iter().map(|t| model.beck_load(t.load)).collect::<Vec<_>>(),
            "resolved": warning.is_none(),
            "transitions_not_listed": unlisted,
            "warning": warning.map(|w| w.to_string()),
        });
        writeln!(out, "{}", serde_json::to_string_pretty(&value)?)?;
        return Ok(());
    }
    writeln!(
        out,
        "{name}: stability changes for {LOAD_AXIS} in [{}, {}]",
        Shown(load_min),
        Shown(load_max)
    )?;
    if transitions.is_empty() && unlisted == 0 {
        writeln!(out, "  none")?;
    }
    // The roller's own load q = R l/k = p / mu, beside p.
    let mu = model.roller().map(|roller| roller.mu);
    for t in transitions {
        let (from, to) = (t.from.name(), t.to.name());
        let q = mu
            .map(|mu| format!("  (q = R l/k = {})", fixed_or_exponent(t.load / mu, 9)))
            .unwrap_or_default();
        // A chain of equal rods discretizes a beam: its load in the beam's units.
        let beck = model
            .beck_load(t.load)
            .map(|beck| format!("  (P L^2/EI = {})", fixed_or_exponent(beck, 6)))
            .unwrap_or_default();
        let load = Shown(t.load).to_string();
        writeln!(out, "  p = {load:<22} {from} -> {to}{q}{beck}")?;
    }
    if unlisted > 0 {
        writeln!(
            out,
            "  not resolved: the {unlisted} changes that rounding makes over this range are not listed (see the warning)"
        )?;
    }
    Ok(())
}

/// A transition as JSON; a flutter onset or end (a Hopf point) with its
/// criticality under `"hopf"`: the first Lyapunov coefficient, soft
/// (supercritical) or hard (subcritical) flutter and the normal form's
/// amplitudes, or why there is none.
fn with_hopf(model: &Model, t: &Transition) -> Result<serde_json::Value> {
    let mut value = serde_json::to_value(t)?;
    if is_hopf(t.from, t.to) {
        let hopf = match hopf_at(model, t.load, HopfSteps::DEFAULT) {
            Ok(Ok(hopf)) => serde_json::to_value(hopf)?,
            Ok(Err(NoHopf::Reversible)) => json!({
                "kind": "reversible",
                "why": "no damping: the column is reversible, two pairs meet on the imaginary axis and there is no attractor for a limit cycle to be",
            }),
            Err(error) => json!({"kind": "not computed", "why": error.to_string()}),
        };
        value["hopf"] = hopf;
    }
    Ok(value)
}

/// `value` with `decimals` decimals, or in exponent form beyond 1e7 (no
/// line of 150 digits for a load of 1e150).
fn fixed_or_exponent(value: f64, decimals: usize) -> String {
    if value.abs() < 1e7 {
        format!("{value:.decimals$}")
    } else {
        format!("{value:.decimals$e}")
    }
}
