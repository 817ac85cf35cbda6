//! The command line: parses the arguments, runs one subcommand (each in a
//! file of its own with its arguments), and turns every error into one line
//! on stderr with exit status 2.

mod bench;
mod bifurcation;
mod boundary;
mod critical;
mod desktop;
mod figure;
mod headless;
mod lesson;
mod locus;
mod map;
mod output;
mod presets;
mod record;
mod signals;
mod simulate;
mod snapshot;
mod tiles;

use std::process::ExitCode;

use anyhow::Result;
use clap::{CommandFactory, Parser, Subcommand, ValueEnum};

use zieglerlab::model::{Key, Model, ModelError, PresetId, apply_assignments, parse_assignment};
use zieglerlab::sim::EngineKind;
use zieglerlab::sim::Ramp;

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
    /// What draws the window: glow (OpenGL, the default: five times the
    /// frames of wgpu on a machine without a GPU) or wgpu. Also read from
    /// the environment variable `ZIEGLERLAB_RENDERER`; the flag wins.
    #[arg(long, value_enum)]
    renderer: Option<RendererArg>,
    /// Seconds a command may run before it stops with a message (status
    /// 124), 1 to 604800; the slowest allowed inputs take minutes (see the
    /// README's "Bad input and extremes").
    #[arg(long, global = true, value_name = "SECS", default_value_t = DEFAULT_TIME_LIMIT_SECS, allow_hyphen_values = true)]
    time_limit: f64,
}

/// The time a command may run by default, in seconds (15 minutes: the
/// slowest answer the README lists, a 32-rod chain's limit cycles, takes 6).
const DEFAULT_TIME_LIMIT_SECS: f64 = 900.0;

/// The longest time limit that may be asked for: a week.
const MOST_TIME_LIMIT_SECS: f64 = 604_800.0;

/// Status of a command stopped by its time limit (as `timeout` reports it).
const TIMED_OUT: i32 = 124;

/// How long a stopping command waits for a write to a stream to finish,
/// so that the stream ends on a whole line.
const STREAM_WAIT: std::time::Duration = std::time::Duration::from_secs(2);

/// Stops the process after `limit_secs`, watched on a thread of its own:
/// the file being written is removed and one line says why, so no input
/// keeps a command (or a script waiting on it) running without end.
fn stop_after(limit_secs: f64) {
    let watch = move || {
        std::thread::sleep(std::time::Duration::from_secs_f64(limit_secs));
        zieglerlab::files::remove_unfinished();
        let streams = zieglerlab::files::stop_streams(STREAM_WAIT);
        // A progress bar may hold the terminal's line: start a new one.
        if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
            eprintln!();
        }
        eprintln!(
            "error: stopped after {} s, the time limit of a command (--time-limit SECS allows more); no file was left half-written{}",
            zieglerlab::format::number_text(limit_secs),
            zieglerlab::files::stopped_words(streams.as_ref())
        );
        std::process::exit(TIMED_OUT);
    };
    drop(
        std::thread::Builder::new()
            .name("time-limit".to_owned())
            .spawn(watch),
    );
}

/// The environment variable that chooses the window's renderer.
const RENDERER_VAR: &str = "ZIEGLERLAB_RENDERER";

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum RendererArg {
    Glow,
    Wgpu,
}

impl From<RendererArg> for zieglerlab::app::Renderer {
    fn from(renderer: RendererArg) -> Self {
        match renderer {
            RendererArg::Glow => Self::Glow,
            RendererArg::Wgpu => Self::Wgpu,
        }
    }
}

/// The window's renderer: the flag, else `from_env` (the value of
/// [`RENDERER_VAR`], if set), else glow.
///
/// # Errors
/// An environment value that names no renderer.
fn renderer(flag: Option<RendererArg>, from_env: Option<&str>) -> Result<RendererArg> {
    if let Some(flag) = flag {
        return Ok(flag);
    }
    match from_env.map(str::trim) {
        Some(text) if !text.is_empty() => RendererArg::from_str(text, true).map_err(|_| {
            anyhow::anyhow!(
                "{RENDERER_VAR}={}: must be glow or wgpu",
                printable(&zieglerlab::format::clipped(text, 40))
            )
        }),
        _ => Ok(RendererArg::Glow),
    }
}

/// The model options shared by the analysis subcommands.
#[derive(clap::Args, Debug)]
struct ModelArgs {
    /// Preset name (see `zieglerlab presets`).
    #[arg(long)]
    preset: PresetId,
    /// Parameter override, `key=value` (repeatable): `load`, the paper's groups
    /// `a`, `nu`, `rho`, `mu`, `V`, or any SI key that `presets` lists.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<String>,
}

impl ModelArgs {
    /// The first key among `keys` that a `--set` assigns.
    fn sets_any(&self, keys: &[Key]) -> Option<Key> {
        self.set
            .iter()
            .filter_map(|text| parse_assignment(text).ok())
            .map(|a| a.key)
            .find(|key| keys.contains(key))
    }

    /// The preset and its model with the `--set` overrides applied and
    /// validated. A key the preset does not have is named with the preset
    /// and the keys it has.
    fn build(&self) -> Result<(PresetId, Model)> {
        let in_preset = |error: ModelError| match error {
            ModelError::UnknownKey { key, .. } => anyhow::anyhow!(
                "unknown key '{key}' for preset {}; its keys are: {}",
                self.preset,
                Key::names_for(&self.preset.model())
            ),
            other => other.into(),
        };
        let assignments = self
            .set
            .iter()
            .map(|text| parse_assignment(text))
            .collect::<Result<Vec<_>, _>>()
            .map_err(in_preset)?;
        let mut model = self.preset.model();
        apply_assignments(&mut model, &assignments).map_err(in_preset)?;
        Ok((self.preset, model))
    }

    /// [`Self::build`] for a picture of the window: rods set with no load
    /// start the load where the preset's stands on its bar, as rods typed
    /// in the window do ([`Model::load_in_place_of`]).
    fn build_for_the_window(&self) -> Result<(PresetId, Model)> {
        let (preset, model) = self.build()?;
        let loaded = self.sets_any(&[Key::Load, Key::P, Key::NormalForce]);
        if self.sets_any(&[Key::Rods]).is_none() || loaded.is_some() {
            return Ok((preset, model));
        }
        let load = model.load_in_place_of(&preset.model());
        Ok((preset, model.at_load(load)))
    }

    /// [`Self::build`] at the start of `ramp`, if there is one: the ramp
    /// sets the load, so a `--set` of the load beside it (as `load`, the
    /// force `P` or the roller's normal force `R`) is refused: it would be
    /// silently overridden.
    fn build_ramped(&self, ramp: Option<&Ramp>) -> Result<(PresetId, Model)> {
        let (preset, model) = self.build()?;
        let Some(ramp) = ramp else {
            return Ok((preset, model));
        };
        if let Some(key) = self.sets_any(&[Key::Load, Key::P, Key::NormalForce]) {
            anyhow::bail!(
                "--ramp sets the load (from its FROM on): leave out --set {}",
                key.name()
            );
        }
        ramp.check_for(&model)
            .map_err(|why| anyhow::anyhow!("--ramp: {why}"))?;
        Ok((preset, model.at_load(ramp.from_p)))
    }
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

#[derive(Subcommand, Debug)]
enum Command {
    /// List the presets with every parameter, its unit and its range.
    Presets(presets::Args),
    /// Check a lesson file (its first problem, with the line), or list the built-in lessons
    Lesson(lesson::Args),
    /// Critical loads: every change of stability along the load axis.
    Critical(critical::Args),
    /// Root locus: every eigenvalue at evenly spaced loads, branches tracked.
    Locus(locus::Args),
    /// Time simulation from phi1 = phi2 = perturb, at rest; one CSV row per step.
    Simulate(simulate::Args),
    /// Stability map: the state and growth rate of every cell of a grid over
    /// the load and a second parameter (a key, c1/c2 or damping).
    Map(map::Args),
    /// Limit cycles past the flutter onsets: the straight column's stability
    /// and every cycle (period, amplitude of each angle, stability by its
    /// Floquet multipliers) at evenly spaced loads; optionally a sweep of
    /// the load up and down as an experiment does.
    Bifurcation(bifurcation::Args),
    /// Stability boundaries followed in the load and a second parameter
    /// (pseudo-arclength continuation): every flutter and divergence onset,
    /// soft or hard along each flutter boundary by its first Lyapunov
    /// coefficient, and the Bautin, Bogdanov-Takens, double-Hopf and
    /// zero-Hopf points.
    Boundary(boundary::Args),
    /// A figure for a paper, SVG or PNG at a journal's size: the root locus,
    /// Re and Im against the load (other presets overlaid), the stability
    /// map, the paradox curves or the bifurcation diagram.
    Figure(figure::Args),
    /// Speed: the root locus, the eigenvalues, the critical loads, both
    /// engines and the app's frame time, measured in this process.
    Bench(bench::Args),
    /// Render the app (or one panel) headlessly to a PNG after simulating
    /// `--time` seconds from the standard perturbation.
    Snapshot(snapshot::Args),
    /// An animated GIF of a run (the app or one panel, drawn headlessly), one frame per 1/fps s of simulated time
    Record(record::Args),
    /// The shell's completions of every command and option: bash, zsh or fish.
    Completions(desktop::CompletionsArgs),
    /// The man page (roff): zieglerlab.1 to standard output, or every page into a folder.
    Manual(desktop::ManualArgs),
}

/// An option that takes negative numbers (`--time-limit -1` is refused by
/// name) followed by another option instead of its value: clap takes the
/// option as the value and complains of the word after it (`--time-limit
/// --set load=1` said "unexpected argument 'load=1'"). The message names
/// the option that lacks its value.
fn value_taken_by_an_option(args: &[String]) -> Option<String> {
    let command = Cli::command();
    let takes_hyphens = |name: &str| {
        std::iter::once(&command)
            .chain(command.get_subcommands())
            .flat_map(clap::Command::get_arguments)
            .any(|arg| arg.is_allow_hyphen_values_set() && arg.get_long() == Some(name))
    };
    args.windows(2).find_map(|pair| {
        let name = pair[0].strip_prefix("--")?;
        let next = pair[1].strip_prefix("--")?;
        (takes_hyphens(name) && next.chars().next().is_some_and(char::is_alphabetic)).then(|| {
            format!("error: --{name} needs a value, but the next word is the option --{next}")
        })
    })
}

/// Status of a run stopped by Ctrl-C, SIGTERM, SIGHUP or SIGQUIT (128 +
/// SIGINT, as shells report Ctrl-C).
const STOPPED: i32 = 130;

/// Runs the command line; status 0 on success, 2 with one line on any error.
pub fn run() -> ExitCode {
    // Ctrl-C, SIGTERM, SIGQUIT or a closed terminal stops at once, and a
    // file being written is not left half-made beside its output; a signal
    // ignored at start (`nohup`, a background job) stays ignored.
    signals::stop_on_signals(STOPPED);
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
            let args: Vec<String> = std::env::args().skip(1).collect();
            let first = if let Some(missing) = value_taken_by_an_option(&args) {
                missing
            } else if first.is_empty() {
                "error: bad arguments".to_owned()
            } else {
                first.join(" ")
            };
            eprintln!(
                "{} (see zieglerlab --help)",
                printable(&clipped_words(&first))
            );
            return ExitCode::from(2);
        }
    };
    let Some(command) = cli.command else {
        // No subcommand: the app.
        let from_env = std::env::var(RENDERER_VAR).ok();
        let renderer = match renderer(cli.renderer, from_env.as_deref()) {
            Ok(renderer) => renderer,
            Err(error) => {
                eprintln!("error: {error}");
                return ExitCode::from(2);
            }
        };
        return match zieglerlab::app::run(renderer.into()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                let other = match renderer {
                    RendererArg::Glow => "wgpu",
                    RendererArg::Wgpu => "glow",
                };
                eprintln!(
                    "error: the app could not start: {error} (the other renderer may work: --renderer {other})"
                );
                ExitCode::from(2)
            }
        };
    };
    if !(1.0..=MOST_TIME_LIMIT_SECS).contains(&cli.time_limit) {
        eprintln!(
            "error: --time-limit {}: must be 1 to {} seconds",
            zieglerlab::format::Shown(cli.time_limit),
            zieglerlab::format::number_text(MOST_TIME_LIMIT_SECS)
        );
        return ExitCode::from(2);
    }
    stop_after(cli.time_limit);
    if cli.renderer.is_some() {
        eprintln!(
            "error: --renderer chooses what draws the window; give it without a subcommand (snapshot and record draw headlessly with wgpu)"
        );
        return ExitCode::from(2);
    }
    match execute(&command) {
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

fn execute(command: &Command) -> Result<()> {
    // What writes its answer to standard output stops when nobody reads it
    // (a map written to a file goes on).
    let to_stdout = match command {
        Command::Critical(_)
        | Command::Locus(_)
        | Command::Simulate(_)
        | Command::Bench(_)
        | Command::Completions(_)
        | Command::Manual(_) => true,
        Command::Map(args) => args.streams(),
        Command::Bifurcation(args) => args.streams(),
        Command::Boundary(args) => args.streams(),
        _ => false,
    };
    if to_stdout {
        output::stop_when_the_reader_goes();
    }
    let mut out = zieglerlab::files::standard_output();
    let done = match command {
        Command::Presets(args) => presets::run(args, &mut out),
        Command::Lesson(args) => lesson::run(args, &mut out),
        Command::Critical(args) => critical::run(args, &mut out),
        Command::Locus(args) => locus::run(args, &mut out),
        Command::Simulate(args) => simulate::run(args, &mut out),
        Command::Map(args) => map::run(args),
        Command::Figure(args) => figure::run(args),
        Command::Bifurcation(args) => bifurcation::run(args),
        Command::Boundary(args) => boundary::run(args),
        Command::Bench(args) => bench::run(args, &mut out),
        Command::Snapshot(args) => snapshot::run(args),
        Command::Record(args) => record::run(args),
        Command::Completions(args) => desktop::completions(args, &mut Cli::command(), &mut out),
        Command::Manual(args) => desktop::manual(args, Cli::command(), &mut out),
    };
    // The end of the output, a part of a line included, once it is whole.
    done.and_then(|()| Ok(std::io::Write::flush(&mut out)?))
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

/// A spinner with `what` and the time taken, for work whose length is not
/// known ahead (drawn only when stderr is a terminal, as the bars).
fn spinner(what: &str) -> indicatif::ProgressBar {
    let spinner = indicatif::ProgressBar::new_spinner();
    if let Ok(style) = indicatif::ProgressStyle::with_template("{spinner} {msg} ({elapsed})") {
        spinner.set_style(style);
    }
    spinner.set_message(what.to_owned());
    spinner.enable_steady_tick(std::time::Duration::from_millis(120));
    spinner
}

/// `text` with every word longer than 60 characters clipped (clap repeats
/// a value as typed, and a 4096-character one buried the message).
fn clipped_words(text: &str) -> String {
    text.split(' ')
        .map(|word| zieglerlab::format::clipped(word, 60))
        .collect::<Vec<_>>()
        .join(" ")
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The flag wins over the environment, which wins over the default; an
    /// unknown name is refused with the variable named.
    #[test]
    fn the_renderer_comes_from_the_flag_then_the_environment() {
        let glow = Some(RendererArg::Glow);
        assert_eq!(renderer(None, None).unwrap(), RendererArg::Glow);
        assert_eq!(renderer(None, Some("")).unwrap(), RendererArg::Glow);
        assert_eq!(renderer(None, Some(" WGPU ")).unwrap(), RendererArg::Wgpu);
        assert_eq!(renderer(glow, Some("wgpu")).unwrap(), RendererArg::Glow);
        assert_eq!(renderer(glow, Some("vulkan")).unwrap(), RendererArg::Glow);
        let unknown = renderer(None, Some("vulkan")).unwrap_err().to_string();
        assert!(
            unknown.contains("ZIEGLERLAB_RENDERER=vulkan") && unknown.contains("glow or wgpu"),
            "{unknown}"
        );
    }

    /// A snapshot's or a recording's chain (`--set rods=16`) starts inside
    /// its own bar at the place of the preset's load; a load given with it
    /// (as `load` or the force `P`) is kept; commands other than the
    /// window's pictures keep the preset's load.
    #[test]
    fn a_chain_in_a_picture_starts_inside_its_bar() {
        let args = |set: &[&str]| ModelArgs {
            preset: PresetId::Tabletop,
            set: set.iter().map(|s| (*s).to_owned()).collect(),
        };
        let preset = PresetId::Tabletop.model();
        let (_, chain) = args(&["rods=16"]).build_for_the_window().unwrap();
        assert!((chain.load_p() - preset.load_p() / 64.0).abs() < 1e-15);
        let (_, given) = args(&["rods=16", "load=0.1"])
            .build_for_the_window()
            .unwrap();
        assert!((given.load_p() - 0.1).abs() < 1e-15);
        let (_, two) = args(&["c2=0.1"]).build_for_the_window().unwrap();
        assert_eq!(two.load_p(), preset.load_p());
        let (_, simulated) = args(&["rods=16"]).build().unwrap();
        assert_eq!(simulated.load_p(), preset.load_p());
    }
}
