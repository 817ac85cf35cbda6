//! Parses the command line, runs one subcommand, and turns every error into
//! one line on stderr with exit status 2.

use std::io::Write;
use std::process::ExitCode;

use anyhow::Result;
use clap::{Parser, Subcommand, ValueEnum};
use serde_json::json;

use std::sync::atomic::{AtomicBool, AtomicUsize};

use zieglerlab::analysis::{
    AffinePencil, DEFAULT_LOAD_MAX, MapSpec, Row, RowResult, bracketing_locus, compute_map,
    critical_loads_along, locus, resolution_warning,
};
use zieglerlab::app::{Panel, Settings, Tab, ZieglerApp};
use zieglerlab::model::{Axis, KEYS, Model, PRESETS, apply_assignments, parse_assignment, preset};
use zieglerlab::sim::{
    DEFAULT_STEP_SECS, EngineKind, Observables, Simulation, Status, initial_state,
};

/// The load axis, as printed in every output.
const LOAD_AXIS: &str = "p = P l/k";

#[derive(Parser, Debug)]
#[command(
    name = "zieglerlab",
    version,
    about = "Flutter and divergence of the Ziegler column: ideal follower force versus a roller on a moving band"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

/// The model options shared by the analysis subcommands.
#[derive(clap::Args, Debug)]
struct ModelArgs {
    /// Preset name (see `zieglerlab presets`).
    #[arg(long)]
    preset: String,
    /// Parameter override, `key=value` (repeatable): `load`, the paper's groups
    /// `a`, `nu`, `rho`, `mu`, `V`, or any SI key that `presets` lists.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<String>,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum LocusFormat {
    Csv,
    Json,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum EngineArg {
    Rapier,
    Reference,
}

impl From<EngineArg> for EngineKind {
    fn from(engine: EngineArg) -> Self {
        match engine {
            EngineArg::Rapier => Self::Rapier,
            EngineArg::Reference => Self::Reference,
        }
    }
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum TableFormat {
    Csv,
}

/// Most rows a simulation prints (duration / dt).
const MAX_ROWS: f64 = 1.0e7;

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum MapFormat {
    Csv,
    Png,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum PanelArg {
    Window,
    Locus,
    Scene,
    Histories,
    Map,
    Paradox,
}

impl From<PanelArg> for Panel {
    fn from(panel: PanelArg) -> Self {
        match panel {
            PanelArg::Window => Self::Window,
            PanelArg::Locus => Self::Tab(Tab::Locus),
            PanelArg::Scene => Self::Scene,
            PanelArg::Histories => Self::Tab(Tab::Histories),
            PanelArg::Map => Self::Tab(Tab::Map),
            PanelArg::Paradox => Self::Tab(Tab::Paradox),
        }
    }
}

#[derive(Subcommand, Debug)]
enum Command {
    /// List the presets with every parameter, its unit and its range.
    Presets {
        #[arg(long)]
        json: bool,
    },
    /// Critical loads: every change of stability along the load axis.
    Critical {
        #[command(flatten)]
        model: ModelArgs,
        /// Lower end of the load range searched.
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        load_min: f64,
        /// Upper end of the load range searched.
        #[arg(long, default_value_t = DEFAULT_LOAD_MAX, allow_negative_numbers = true)]
        load_max: f64,
        #[arg(long)]
        json: bool,
    },
    /// Root locus: every eigenvalue at evenly spaced loads, branches tracked.
    Locus {
        #[command(flatten)]
        model: ModelArgs,
        #[arg(long, allow_negative_numbers = true)]
        load_min: f64,
        #[arg(long, allow_negative_numbers = true)]
        load_max: f64,
        #[arg(long)]
        samples: usize,
        #[arg(long, value_enum, default_value_t = LocusFormat::Csv)]
        format: LocusFormat,
    },
    /// Time simulation from phi1 = phi2 = perturb, at rest; one CSV row per step.
    Simulate {
        #[command(flatten)]
        model: ModelArgs,
        /// Simulated time in seconds.
        #[arg(long, allow_negative_numbers = true)]
        duration: f64,
        #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
        engine: EngineArg,
        /// Initial angle of both rods, in rad.
        #[arg(long, default_value_t = 0.001, allow_negative_numbers = true)]
        perturb: f64,
        /// Time step (and output interval), in s.
        #[arg(long, default_value_t = DEFAULT_STEP_SECS, allow_negative_numbers = true)]
        dt: f64,
        #[arg(long, value_enum, default_value_t = TableFormat::Csv)]
        format: TableFormat,
    },
    /// Stability map: the state and growth rate of every cell of a grid over
    /// the load and a second parameter (a key, c1/c2 or damping).
    Map {
        #[command(flatten)]
        model: ModelArgs,
        /// The load axis, load:MIN:MAX:N (N evenly spaced loads, ends included).
        #[arg(long)]
        x: String,
        /// The second axis, KEY:MIN:MAX:N.
        #[arg(long)]
        y: String,
        #[arg(long, value_enum, default_value_t = MapFormat::Csv)]
        format: MapFormat,
        #[arg(long)]
        out: std::path::PathBuf,
    },
    /// Speed: the root locus, the eigenvalues, the critical loads, both
    /// engines and the app's frame time, measured in this process.
    Bench {
        #[arg(long)]
        json: bool,
        /// Frames timed for the frame-time quantiles.
        #[arg(long, default_value_t = zieglerlab::bench::FRAMES)]
        frames: usize,
    },
    /// Render the app (or one panel) headlessly to a PNG after simulating
    /// `--time` seconds from the standard perturbation.
    Snapshot {
        #[command(flatten)]
        model: ModelArgs,
        /// Simulated time before the picture, in s.
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        time: f64,
        #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
        engine: EngineArg,
        /// Image size in pixels, `WIDTHxHEIGHT`.
        #[arg(long, default_value = "1280x800", allow_hyphen_values = true)]
        size: String,
        #[arg(long)]
        projector: bool,
        #[arg(long, value_enum, default_value_t = PanelArg::Window)]
        panel: PanelArg,
        #[arg(long)]
        out: std::path::PathBuf,
    },
}

/// Runs the command line; status 0 on success, 2 with one line on any error.
pub fn run() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => {
            use clap::error::ErrorKind;
            if matches!(
                error.kind(),
                ErrorKind::DisplayHelp | ErrorKind::DisplayVersion
            ) {
                let _ = error.print();
                return ExitCode::SUCCESS;
            }
            // clap's message runs over several lines (the missing arguments
            // are listed under the first): its first paragraph, on one line.
            let text = error.to_string();
            let first: Vec<&str> = text
                .lines()
                .take_while(|line| !line.trim().is_empty())
                .map(str::trim)
                .collect();
            let first = if first.is_empty() {
                "error: bad arguments".to_owned()
            } else {
                first.join(" ")
            };
            eprintln!("{} (see zieglerlab --help)", printable(&first));
            return ExitCode::from(2);
        }
    };
    let Some(command) = cli.command else {
        // No subcommand: the app.
        return match zieglerlab::app::run() {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: the app could not start: {error}");
                ExitCode::from(2)
            }
        };
    };
    match execute(command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // A reader that stopped reading (`| head`) is not an error: end
            // quietly, as Unix tools do.
            let broken_pipe = error.chain().any(|cause| {
                cause
                    .downcast_ref::<std::io::Error>()
                    .is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe)
            });
            if broken_pipe {
                return ExitCode::SUCCESS;
            }
            let chain: Vec<String> = error.chain().map(ToString::to_string).collect();
            eprintln!("error: {}", printable(&chain.join(": ")));
            ExitCode::from(2)
        }
    }
}

/// A progress bar of `len` steps on stderr, drawn only when stderr is a
/// terminal (indicatif's default target hides itself otherwise), so piped
/// and scripted runs see nothing.
fn progress_bar(len: u64, what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    if let Ok(style) = indicatif::ProgressStyle::with_template(
        "{bar:40} {pos}/{len} {msg} ({elapsed}, about {eta} left)",
    ) {
        bar.set_style(style);
    }
    bar.set_message(what.to_owned());
    bar
}

/// `text` with control characters (a key typed with a tab or an escape
/// sequence) shown escaped, so an error message stays one readable line.
fn printable(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_default().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

fn execute(command: Command) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match command {
        Command::Presets { json } => presets(&mut out, json),
        Command::Critical {
            model,
            load_min,
            load_max,
            json,
        } => critical(&mut out, &model, (load_min, load_max), json),
        Command::Simulate {
            model,
            duration,
            engine,
            perturb,
            dt,
            format: TableFormat::Csv,
        } => simulate(&mut out, &model, duration, engine.into(), perturb, dt),
        Command::Bench { json, frames } => bench(&mut out, json, frames),
        Command::Map {
            model,
            x,
            y,
            format,
            out,
        } => map(&model, &x, &y, format, &out),
        Command::Snapshot {
            model,
            time,
            engine,
            size,
            projector,
            panel,
            out,
        } => snapshot(
            &model,
            time,
            engine.into(),
            &size,
            projector,
            panel.into(),
            &out,
        ),
        Command::Locus {
            model,
            load_min,
            load_max,
            samples,
            format,
        } => locus_table(&mut out, &model, (load_min, load_max), samples, format),
    }
}

fn critical(
    out: &mut impl Write,
    args: &ModelArgs,
    (load_min, load_max): (f64, f64),
    json: bool,
) -> Result<()> {
    let (name, model) = build_model(args)?;
    let pencil = AffinePencil::new(&model)?;
    let bracket = bracketing_locus(&pencil, load_min, load_max)?;
    let transitions = critical_loads_along(&pencil, &bracket)?;
    let warning = resolution_warning(&pencil, &bracket)?;
    if let Some(warning) = &warning {
        eprintln!("warning: {warning}");
    }
    if json {
        let value = json!({
            "preset": name,
            "load_axis": LOAD_AXIS,
            "load_min": load_min,
            "load_max": load_max,
            "transitions": transitions,
            "resolved": warning.is_none(),
            "warning": warning,
        });
        writeln!(out, "{}", serde_json::to_string_pretty(&value)?)?;
    } else {
        writeln!(
            out,
            "{name}: stability changes for {LOAD_AXIS} in [{load_min}, {load_max}]"
        )?;
        if transitions.is_empty() {
            writeln!(out, "  none")?;
        }
        // The roller's own load q = R l/k = p / mu, beside p.
        let mu = model.roller().map(|roller| roller.mu);
        for t in &transitions {
            let (from, to) = (t.from.name(), t.to.name());
            let q = mu
                .map(|mu| format!("  (q = R l/k = {:.9})", t.load / mu))
                .unwrap_or_default();
            writeln!(out, "  p = {:<22} {from} -> {to}{q}", t.load)?;
        }
    }
    Ok(())
}

fn locus_table(
    out: &mut impl Write,
    args: &ModelArgs,
    (load_min, load_max): (f64, f64),
    samples: usize,
    format: LocusFormat,
) -> Result<()> {
    let (name, model) = build_model(args)?;
    let pencil = AffinePencil::new(&model)?;
    let locus = locus(&pencil, load_min, load_max, samples)?;
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
    match format {
        LocusFormat::Csv => {
            writeln!(out, "load,branch,re,im")?;
            for (load, branch, z) in rows {
                writeln!(out, "{load},{branch},{},{}", z.re, z.im)?;
            }
        }
        LocusFormat::Json => {
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

fn simulate(
    out: &mut impl Write,
    args: &ModelArgs,
    duration: f64,
    engine: EngineKind,
    perturb: f64,
    dt: f64,
) -> Result<()> {
    let (_, model) = build_model(args)?;
    if !(duration.is_finite() && duration > 0.0) {
        anyhow::bail!("duration = {duration}: must be a positive number of seconds");
    }
    if !(perturb.is_finite() && perturb.abs() <= 1.0) {
        anyhow::bail!("perturb = {perturb}: must be an angle in [-1, 1] rad");
    }
    if dt.is_finite() && dt > 0.0 && duration / dt > MAX_ROWS {
        anyhow::bail!(
            "duration / dt = {}: at most {MAX_ROWS} rows; raise dt",
            duration / dt
        );
    }
    let mut simulation = Simulation::new(model, engine, initial_state(&model, perturb), dt)?;
    let mut out = std::io::BufWriter::new(out);
    writeln!(
        out,
        "t,phi1,phi2,psi,phi1_dot,phi2_dot,psi_dot,delta,energy"
    )?;
    let mut row = |o: &Observables| {
        writeln!(
            out,
            "{},{},{},{},{},{},{},{},{}",
            o.t_secs,
            o.phi1_rad,
            o.phi2_rad,
            o.psi_rad,
            o.phi1_dot_rad_per_s,
            o.phi2_dot_rad_per_s,
            o.psi_dot_rad_per_s,
            o.delta_rad,
            o.energy_j()
        )
    };
    row(&simulation.observe())?;
    let mut written = Ok(());
    let status = simulation.run(duration, |o| {
        if written.is_ok() {
            written = row(o);
        }
    });
    written?;
    out.flush()?;
    if status != Status::Running {
        eprintln!("run stopped: {status}");
    }
    Ok(())
}

/// Renders the app headlessly and writes a PNG.
fn snapshot(
    args: &ModelArgs,
    time: f64,
    engine: EngineKind,
    size: &str,
    projector: bool,
    panel: Panel,
    out: &std::path::Path,
) -> Result<()> {
    check_output(out, true)?;
    let (name, model) = build_model(args)?;
    if !(time.is_finite() && (0.0..=1.0e5).contains(&time)) {
        anyhow::bail!("time = {time}: must be a number of seconds in [0, 100000]");
    }
    let (width, height) = size
        .split_once('x')
        .and_then(|(w, h)| Some((w.trim().parse::<u16>().ok()?, h.trim().parse::<u16>().ok()?)))
        .filter(|&(w, h)| (64..=8192).contains(&w) && (64..=8192).contains(&h))
        .ok_or_else(|| {
            anyhow::anyhow!(
                "size = {size}: must be WIDTHxHEIGHT in pixels, each 64 to 8192 (e.g. 1280x800)"
            )
        })?;
    let settings = Settings {
        preset: name,
        model,
        engine,
        speed: 1.0,
        projector,
    };
    let mut app = ZieglerApp::new(settings)?;
    // Whole 1/60 s frames, as the app advances: the same picture every time.
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "time is checked to lie in [0, 100000] s: at most 6e6 frames"
    )]
    let frames = (time * 60.0).round() as u64;
    let progress = progress_bar(frames, "simulated frames");
    for frame in 0..frames {
        app.advance(1.0 / 60.0);
        if frame % 600 == 0 {
            progress.set_position(frame);
        }
    }
    progress.finish_and_clear();
    if matches!(panel, Panel::Tab(Tab::Map | Tab::Paradox)) {
        app.complete_background_work();
    }
    let image = render(&mut app, panel, (f32::from(width), f32::from(height)))?;
    write_png(out, &image)
}

/// Refuses an output path before any work is done: its folder must exist,
/// and a picture must be named `*.png` (the only format written).
fn check_output(out: &std::path::Path, png: bool) -> Result<()> {
    let shown = out.display();
    if png
        && !out
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("png"))
    {
        anyhow::bail!("out = {shown}: pictures are written as PNG; name the file *.png");
    }
    let folder = folder_of(out);
    if !folder.is_dir() {
        anyhow::bail!(
            "out = {shown}: the folder {} does not exist",
            folder.display()
        );
    }
    if out.is_dir() {
        anyhow::bail!("out = {shown}: is a folder, not a file");
    }
    Ok(())
}

/// The folder `out` is written in (`.` for a bare file name).
fn folder_of(out: &std::path::Path) -> &std::path::Path {
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => std::path::Path::new("."),
    }
}

/// Writes `out` whole or not at all: into a temporary file in the same
/// folder, flushed and synced, then renamed over `out`. A failure (a full
/// disk, a killed process) leaves any existing `out` as it was.
fn write_atomically(
    out: &std::path::Path,
    write: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> std::io::Result<()>,
) -> Result<()> {
    let error = |e: &dyn std::fmt::Display| anyhow::anyhow!("cannot write {}: {e}", out.display());
    if std::fs::metadata(out).is_ok_and(|m| !m.is_file()) {
        // A device or a pipe (/dev/stdout, /dev/null): nothing to replace.
        let mut file = std::fs::File::options()
            .write(true)
            .open(out)
            .map_err(|e| error(&e))?;
        let mut buffered = std::io::BufWriter::new(&mut file);
        return write(&mut buffered)
            .and_then(|()| buffered.flush())
            .map_err(|e| error(&e));
    }
    let folder = folder_of(out);
    let mut file = tempfile::NamedTempFile::new_in(folder).map_err(|e| error(&e))?;
    {
        let mut buffered = std::io::BufWriter::new(file.as_file_mut());
        write(&mut buffered)
            .and_then(|()| buffered.flush())
            .map_err(|e| error(&e))?;
    }
    file.as_file().sync_all().map_err(|e| error(&e))?;
    file.persist(out).map_err(|e| error(&e.error))?;
    Ok(())
}

/// `image` as a PNG file at `out`, atomically.
fn write_png(out: &std::path::Path, image: &image::RgbaImage) -> Result<()> {
    write_atomically(out, |w| {
        let mut encoded = Vec::new();
        image
            .write_to(
                &mut std::io::Cursor::new(&mut encoded),
                image::ImageFormat::Png,
            )
            .map_err(std::io::Error::other)?;
        w.write_all(&encoded)
    })
}

/// The picture of `panel` by wgpu, headless. A missing renderer (no Mesa, no
/// GPU) panics inside the renderer's setup: that becomes one clear error.
fn render(
    app: &mut ZieglerApp,
    panel: Panel,
    (width, height): (f32, f32),
) -> Result<image::RgbaImage> {
    let previous_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let rendered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut harness = egui_kittest::Harness::builder()
            .wgpu()
            .with_size([width, height])
            .build_ui(|ui| app.panel_ui(ui, panel));
        harness.run_steps(4);
        harness.render()
    }));
    std::panic::set_hook(previous_hook);
    let help = "no renderer could be created (a GPU, or Mesa's CPU GL: Debian packages libegl1 libegl-mesa0 libgl1-mesa-dri)";
    match rendered {
        Ok(Ok(image)) => Ok(image),
        // The renderer exists (its creation panics otherwise): this is the
        // drawing itself failing, e.g. a large picture timing out on a busy
        // machine's CPU renderer.
        Ok(Err(error)) if error.to_lowercase().contains("timeout") => anyhow::bail!(
            "rendering timed out ({error}): Mesa's CPU renderer needs more time for a {width}x{height} picture on this machine; try a smaller --size or run it again when the machine is less busy"
        ),
        Ok(Err(error)) => anyhow::bail!("rendering failed: {error}"),
        Err(payload) => {
            let what = payload
                .downcast_ref::<String>()
                .map(String::as_str)
                .or_else(|| payload.downcast_ref::<&str>().copied())
                .unwrap_or("")
                .lines()
                .next()
                .unwrap_or("")
                .to_owned();
            anyhow::bail!("rendering failed ({what}); if {help}")
        }
    }
}

/// The preset with the `--set` overrides applied and validated.
fn build_model(args: &ModelArgs) -> Result<(String, Model)> {
    let preset = preset(&args.preset)?;
    let assignments = args
        .set
        .iter()
        .map(|text| parse_assignment(text))
        .collect::<Result<Vec<_>, _>>()?;
    let mut model = preset.model();
    apply_assignments(&mut model, preset.name, &assignments)?;
    Ok((preset.name.to_owned(), model))
}

fn presets(out: &mut impl Write, json: bool) -> Result<()> {
    if json {
        let presets: Vec<_> = PRESETS
            .iter()
            .map(|preset| {
                let model = preset.model();
                let parameters: Vec<_> = KEYS
                    .iter()
                    .filter(|key| key.applies_to(&model))
                    .map(|key| {
                        json!({
                            "key": key.key,
                            "value": key.get(&model),
                            "unit": key.unit,
                            "range": key.range,
                            "group": key.is_group,
                            "description": key.description,
                        })
                    })
                    .collect();
                json!({"name": preset.name, "source": preset.source, "description": preset.description, "parameters": parameters})
            })
            .collect();
        writeln!(out, "{}", serde_json::to_string_pretty(&presets)?)?;
        return Ok(());
    }
    for preset in &PRESETS {
        let model = preset.model();
        writeln!(
            out,
            "{} ({})\n  {}",
            preset.name, preset.source, preset.description
        )?;
        for key in KEYS.iter().filter(|key| key.applies_to(&model)) {
            let unit = if key.unit.is_empty() { "-" } else { key.unit };
            writeln!(
                out,
                "  {:<6} {:>12} {:<10} {:<12} {}",
                key.key,
                format!("{:.6}", key.get(&model))
                    .trim_end_matches('0')
                    .trim_end_matches('.'),
                unit,
                key.range,
                key.description
            )?;
        }
        writeln!(out)?;
    }
    Ok(())
}

/// The targets `bench` compares with on a 2-core machine: each key, the
/// bound and whether it is an upper bound.
const BENCH_TARGETS: [(&str, f64, bool); 8] = [
    ("locus_us_per_load", 0.8, true),
    ("locus_speedup_vs_numpy", 8.0, false),
    ("frame_ms_p99", 8.0, true),
    ("frame_ms_p99_map", 8.0, true),
    ("frame_ms_p99_paradox", 8.0, true),
    ("map_ms", 300.0, true),
    ("sim_reference_x_realtime", 1000.0, false),
    ("sim_rapier_x_realtime", 200.0, false),
];

/// The most frames `bench` times (about a minute of frames).
const MAX_BENCH_FRAMES: usize = 10_000;

fn bench(out: &mut impl Write, json: bool, frames: usize) -> Result<()> {
    if !(1..=MAX_BENCH_FRAMES).contains(&frames) {
        anyhow::bail!("frames = {frames}: must be 1 to {MAX_BENCH_FRAMES}");
    }
    if cfg!(debug_assertions) {
        eprintln!(
            "note: this is a debug build; for representative numbers run `cargo run --release -- bench`"
        );
    }
    let report = zieglerlab::bench::run(frames)?;
    if json {
        writeln!(out, "{}", serde_json::to_string_pretty(&report)?)?;
        return Ok(());
    }
    let value = serde_json::to_value(report)?;
    let rows = [
        (
            "locus_us_per_load",
            "us per load",
            "tracked locus, roller, 1000 loads",
        ),
        (
            "locus2_us_per_load",
            "us per load",
            "tracked locus, midpoint-masses, 1000 loads",
        ),
        (
            "eig_us_per_pencil",
            "us per pencil",
            "eigenvalues alone, 100000 roller pencils",
        ),
        ("critical_ms", "ms", "critical loads, roller, p in [0, 10]"),
        (
            "sim_reference_x_realtime",
            "x real time",
            "reference engine, roller p = 1, dt = 1/240 s",
        ),
        (
            "sim_rapier_x_realtime",
            "x real time",
            "rapier engine, roller p = 1, dt = 1/240 s",
        ),
        (
            "frame_ms_p50",
            "ms",
            "app frame at 1280x800, nu moving every frame: median",
        ),
        ("frame_ms_p99", "ms", "the same, 99th percentile"),
        (
            "frame_ms_p99_map",
            "ms",
            "the same drag with the stability-map tab open: p99",
        ),
        (
            "frame_ms_p99_paradox",
            "ms",
            "the same drag with the paradox tab open: p99",
        ),
        (
            "map_ms",
            "ms",
            "roller map 256x256 (load, nu) on every core",
        ),
        (
            "numpy_eig_us_per_pencil",
            "us per pencil",
            "numpy's batched eigvals, the same 6x6 pencils (NaN: no numpy)",
        ),
        (
            "locus_speedup_vs_numpy",
            "x",
            "numpy per pencil over the locus per load",
        ),
    ];
    for (key, unit, what) in rows {
        let figure = value[key].as_f64().unwrap_or(f64::NAN);
        let target = BENCH_TARGETS
            .iter()
            .find(|(k, _, _)| *k == key)
            .map(|&(_, bound, upper)| {
                let met = if upper {
                    figure <= bound
                } else {
                    figure >= bound
                };
                let sign = if upper { "<=" } else { ">=" };
                format!(
                    "  (target {sign} {bound}: {})",
                    if met { "met" } else { "MISSED" }
                )
            })
            .unwrap_or_default();
        writeln!(out, "{key:<26} {figure:>10.3} {unit:<14} {what}{target}")?;
    }
    Ok(())
}

/// The most cells along one axis of `map`.
const MAP_MAX_CELLS: usize = 2048;

/// `NAME:MIN:MAX:N` of `map --x/--y` (the name may hold '/', as c1/c2).
fn map_axis(flag: &str, text: &str) -> Result<(String, f64, f64, usize)> {
    let shape = || anyhow::anyhow!("{flag} {text}: must be NAME:MIN:MAX:N (e.g. nu:0.01:1:256)");
    let mut parts = text.rsplitn(4, ':');
    let (Some(n), Some(max), Some(min), Some(name)) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(shape());
    };
    let number = |s: &str| -> Result<f64> {
        s.trim()
            .parse::<f64>()
            .ok()
            .filter(|v| v.is_finite())
            .ok_or_else(|| anyhow::anyhow!("{flag} {text}: '{s}' is not a finite number"))
    };
    let (min, max) = (number(min)?, number(max)?);
    let n: usize = n
        .trim()
        .parse()
        .map_err(|_| anyhow::anyhow!("{flag} {text}: N = '{n}' is not a count"))?;
    if !(1..=MAP_MAX_CELLS).contains(&n) {
        anyhow::bail!("{flag} {text}: N = {n}: must be 1 to {MAP_MAX_CELLS}");
    }
    if !(max > min || (n == 1 && max == min)) {
        anyhow::bail!("{flag} {text}: MAX must be above MIN (or equal with N = 1)");
    }
    Ok((name.trim().to_owned(), min, max, n))
}

fn map(args: &ModelArgs, x: &str, y: &str, format: MapFormat, out: &std::path::Path) -> Result<()> {
    check_output(out, matches!(format, MapFormat::Png))?;
    let (name, model) = build_model(args)?;
    let (x_name, load_min, load_max, loads) = map_axis("--x", x)?;
    if x_name != "load" {
        anyhow::bail!("--x {x}: the map's first axis is the load: load:MIN:MAX:N");
    }
    if load_min < 0.0 {
        anyhow::bail!("--x {x}: loads must be >= 0");
    }
    let (y_name, value_min, value_max, values) = map_axis("--y", y)?;
    let axis = Axis::parse(&y_name, &model, &name)?;
    if axis == Axis::Key("load") {
        anyhow::bail!("--y {y}: the second axis cannot be the load again");
    }
    let spec = MapSpec {
        model,
        preset: name,
        axis,
        load_range: (load_min, load_max),
        loads,
        axis_range: (value_min, value_max),
        values,
    };
    let rows: std::sync::Mutex<Vec<Option<RowResult>>> = std::sync::Mutex::new(vec![None; values]);
    let threads = std::thread::available_parallelism().map_or(2, std::num::NonZero::get);
    let (cancel, done) = (AtomicBool::new(false), AtomicUsize::new(0));
    let progress = progress_bar(values as u64, "map rows");
    compute_map(&spec, threads, &cancel, &done, &|j, row| {
        if let Ok(mut rows) = rows.lock() {
            rows[j] = Some(row);
        }
        progress.inc(1);
    })?;
    progress.finish_and_clear();
    let rows = rows
        .into_inner()
        .map_err(|_| anyhow::anyhow!("a map thread failed"))?;
    let mut complete = Vec::with_capacity(values);
    for row in &rows {
        match row {
            Some(Ok(row)) => complete.push(row),
            Some(Err(reason)) => anyhow::bail!("--y {y}: no analysis there: {reason}"),
            None => anyhow::bail!("a map row was not computed"),
        }
    }
    warn_if_unresolved(&spec, &complete, &y_name)?;
    match format {
        MapFormat::Csv => {
            let grid = spec.load_grid()?;
            write_atomically(out, |file| {
                writeln!(file, "load,{y_name},state,growth_rate")?;
                for row in &complete {
                    for (p, cell) in grid.iter().zip(&row.cells) {
                        writeln!(
                            file,
                            "{p},{},{},{}",
                            row.value,
                            cell.state.name(),
                            cell.growth_per_s
                        )?;
                    }
                }
                Ok(())
            })?;
        }
        MapFormat::Png => {
            let scale = (512 / loads.max(values)).max(1);
            let picture = zieglerlab::app::map_picture(&rows, loads, scale);
            let [width, height] = picture.size;
            let bytes: Vec<u8> = picture
                .pixels
                .iter()
                .flat_map(eframe::egui::Color32::to_array)
                .collect();
            let width = u32::try_from(width)?;
            let height = u32::try_from(height)?;
            let image = image::RgbaImage::from_raw(width, height, bytes)
                .ok_or_else(|| anyhow::anyhow!("the map picture has the wrong size"))?;
            write_png(out, &image)?;
        }
    }
    Ok(())
}

/// Checks the resolution of the map's rows at both ends of the second axis
/// and in its middle: where a singular limit (a tiny roller mass, a slow
/// band) leaves the states to rounding, the map says so as `critical` does.
fn warn_if_unresolved(spec: &MapSpec, rows: &[&Row], y_name: &str) -> Result<()> {
    let (load_min, load_max) = spec.load_range;
    for row in [rows.first(), rows.get(rows.len() / 2), rows.last()]
        .into_iter()
        .flatten()
    {
        let model = spec.axis.apply(&spec.model, &spec.preset, row.value)?;
        let pencil = AffinePencil::new(&model)?;
        let bracket = bracketing_locus(&pencil, load_min, load_max)?;
        if let Some(warning) = resolution_warning(&pencil, &bracket)? {
            eprintln!(
                "warning: at {y_name} = {}: {}",
                zieglerlab::model::Shown(row.value),
                printable(&warning)
            );
            break;
        }
    }
    Ok(())
}
