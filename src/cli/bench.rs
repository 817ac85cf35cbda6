//! `zieglerlab bench`: the speed figures of this machine, as a table with the
//! targets or as JSON.

use std::io::Write;

use anyhow::Result;

use zieglerlab::bench::{FRAMES, Report};

/// The most frames `bench` times (about a minute of frames).
const MAX_FRAMES: usize = 10_000;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(long)]
    json: bool,
    /// Frames timed for the frame-time quantiles.
    #[arg(long, default_value_t = FRAMES, allow_hyphen_values = true)]
    frames: usize,
    /// Skip the real window's frames (timed by default when there is a
    /// display: two windows open for a few seconds each).
    #[arg(long)]
    no_window: bool,
    /// Skip the limit cycles of a 16-rod chain (about 16 s on two cores).
    #[arg(long)]
    no_cycles: bool,
}

/// A target on a 2-core machine.
#[derive(Clone, Copy)]
enum Target {
    AtMost(f64),
    AtLeast(f64),
}

/// A figure of the report.
type Figure = fn(&Report) -> f64;

/// The table: each line's JSON key, figure, unit, what was measured and the
/// target, if there is one.
const LINES: [(&str, Figure, &str, &str, Option<Target>); 26] = [
    (
        "locus_us_per_load",
        |r| r.locus_us_per_load,
        "us per load",
        "tracked locus, roller, 1000 loads",
        Some(Target::AtMost(0.8)),
    ),
    (
        "locus2_us_per_load",
        |r| r.locus2_us_per_load,
        "us per load",
        "tracked locus, midpoint-masses, 1000 loads",
        None,
    ),
    (
        "eig_us_per_pencil",
        |r| r.eig_us_per_pencil,
        "us per pencil",
        "eigenvalues alone, 100000 roller pencils",
        None,
    ),
    (
        "critical_ms",
        |r| r.critical_ms,
        "ms",
        "critical loads, roller, p in [0, 10]",
        None,
    ),
    (
        "critical_chain32_ms",
        |r| r.critical_chain32_ms,
        "ms",
        "critical loads, 32 uniform rods, P L^2/EI in [0, 40]",
        Some(Target::AtMost(1000.0)),
    ),
    (
        "sim_reference_x_realtime",
        |r| r.sim_reference_x_realtime,
        "x real time",
        "reference engine, roller p = 1, dt = 1/240 s",
        Some(Target::AtLeast(1000.0)),
    ),
    (
        "sim_rapier_x_realtime",
        |r| r.sim_rapier_x_realtime,
        "x real time",
        "rapier engine, roller p = 1, dt = 1/240 s",
        Some(Target::AtLeast(200.0)),
    ),
    (
        "frame_ms_p50",
        |r| r.frame_ms_p50,
        "ms",
        "app frame at 1280x800, nu moving every frame: median",
        None,
    ),
    (
        "frame_ms_p99",
        |r| r.frame_ms_p99,
        "ms",
        "the same, 99th percentile",
        Some(Target::AtMost(8.0)),
    ),
    (
        "frame_ms_p99_map",
        |r| r.frame_ms_p99_map,
        "ms",
        "the stability-map tab open, rho dragged (restarts the map): p99",
        Some(Target::AtMost(8.0)),
    ),
    (
        "frame_ms_p99_paradox",
        |r| r.frame_ms_p99_paradox,
        "ms",
        "the same drag with the paradox tab open: p99",
        Some(Target::AtMost(8.0)),
    ),
    (
        "frame_ms_p99_chain16",
        |r| r.frame_ms_p99_chain16,
        "ms",
        "beck preset (16 rods, reference engine), load dragged: p99 (interactive: a 60 Hz frame)",
        Some(Target::AtMost(16.0)),
    ),
    (
        "locus_sheet_ms_chain16",
        |r| r.locus_sheet_ms_chain16,
        "ms",
        "beck's locus tab sheet built whole, as each frame built it before",
        None,
    ),
    (
        "locus_sheet_kept_ms_chain16",
        |r| r.locus_sheet_kept_ms_chain16,
        "ms",
        "the same as a frame makes it now: kept part copied, present added",
        None,
    ),
    (
        "map_ms",
        |r| r.map_ms,
        "ms",
        "roller map 256x256 (load, nu) on every core (interactive: follows a drag)",
        Some(Target::AtMost(100.0)),
    ),
    (
        "numpy_eig_us_per_pencil",
        |r| r.numpy_eig_us_per_pencil.unwrap_or(f64::NAN),
        "us per pencil",
        "numpy's batched eigvals, the same 6x6 pencils (NaN: no numpy)",
        None,
    ),
    (
        "locus_speedup_vs_numpy",
        |r| r.locus_speedup_vs_numpy.unwrap_or(f64::NAN),
        "x",
        "numpy per pencil over the locus per load",
        Some(Target::AtLeast(12.0)),
    ),
    (
        "numpy_chain32_scan_ms",
        |r| r.numpy_chain32_scan_ms.unwrap_or(f64::NAN),
        "ms",
        "numpy's scan for the first flutter of the 32-rod chain (NaN: no numpy)",
        None,
    ),
    (
        "critical_chain32_over_numpy",
        |r| r.critical_chain32_over_numpy.unwrap_or(f64::NAN),
        "x",
        "every change of stability of the chain over numpy's first one",
        Some(Target::AtMost(0.7)),
    ),
    (
        "window_fps",
        |r| r.window_fps.unwrap_or(f64::NAN),
        "frames per s",
        "the real window at 1280x800, drawing included (NaN: no display)",
        Some(Target::AtLeast(45.0)),
    ),
    (
        "window_frame_ms_p99",
        |r| r.window_frame_ms_p99.unwrap_or(f64::NAN),
        "ms",
        "the same, frame interval: 99th percentile",
        None,
    ),
    (
        "window_fps_1920x1080",
        |r| r.window_fps_1920x1080.unwrap_or(f64::NAN),
        "frames per s",
        "the real window at 1920x1080 (NaN: no display)",
        Some(Target::AtLeast(30.0)),
    ),
    (
        "window_frame_ms_p99_1920x1080",
        |r| r.window_frame_ms_p99_1920x1080.unwrap_or(f64::NAN),
        "ms",
        "the same, frame interval: 99th percentile",
        None,
    ),
    (
        "window_fps_chain16_projector_1920x1080",
        |r| r.window_fps_chain16_projector_1920x1080.unwrap_or(f64::NAN),
        "frames per s",
        "the window at 1920x1080, beck (16 rods) in projector mode (NaN: no display)",
        Some(Target::AtLeast(40.0)),
    ),
    (
        "window_frame_ms_p99_chain16_projector_1920x1080",
        |r| {
            r.window_frame_ms_p99_chain16_projector_1920x1080
                .unwrap_or(f64::NAN)
        },
        "ms",
        "the same, frame interval: 99th percentile",
        None,
    ),
    (
        "bifurcation_chain16_s",
        |r| r.bifurcation_chain16_s.unwrap_or(f64::NAN),
        "s",
        "limit cycles of 16 uniform rods, dampers 0.05, over the load bar (NaN: skipped)",
        Some(Target::AtMost(20.0)),
    ),
];

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    if !(1..=MAX_FRAMES).contains(&args.frames) {
        anyhow::bail!("frames = {}: must be 1 to {MAX_FRAMES}", args.frames);
    }
    if cfg!(debug_assertions) {
        eprintln!(
            "note: this is a debug build; for representative numbers run `cargo run --release -- bench`"
        );
    }
    let report = zieglerlab::bench::run(args.frames, !args.no_window, !args.no_cycles)?;
    if args.json {
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
        return Ok(());
    }
    let width = LINES.iter().map(|line| line.0.len()).max().unwrap_or(0);
    for (key, figure, unit, what, target) in LINES {
        let figure = figure(&report);
        let target = target
            .map(|target| {
                let (sign, bound, met) = match target {
                    Target::AtMost(bound) => ("<=", bound, figure <= bound),
                    Target::AtLeast(bound) => (">=", bound, figure >= bound),
                };
                let verdict = if met { "met" } else { "MISSED" };
                format!("  (target {sign} {bound}: {verdict})")
            })
            .unwrap_or_default();
        writeln!(
            out,
            "{key:<width$} {figure:>10.3} {unit:<14} {what}{target}"
        )?;
    }
    Ok(())
}
