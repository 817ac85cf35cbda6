//! `zieglerlab record`: an animated GIF of a run for slides and handouts,
//! drawn by the same headless renderer as `snapshot`, one frame per 1/fps s
//! of simulated time: the same arguments give the same bytes.

use anyhow::Result;
use zieglerlab::format::Shown;

use zieglerlab::app::{Action, Settings, ZieglerApp};
use zieglerlab::recording::GifRecording;
use zieglerlab::sim::Ramp;

use super::headless::{Look, Size, render_frames};
use super::output::{check_output, write_atomically};
use super::{EngineArg, ModelArgs, progress_bar};

/// Most frames a recording holds (5 minutes at 10 frames per second).
const MAX_FRAMES: f64 = 3000.0;
/// The app's frame: the run advances in these steps between pictures, as
/// `snapshot` and the app do.
const APP_FRAME_SECS: f64 = 1.0 / 60.0;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// A quasi-static load ramp during the recording, `FROM:TO:RATE`.
    #[arg(long, value_name = "FROM:TO:RATE")]
    ramp: Option<Ramp>,
    /// Simulated seconds recorded.
    #[arg(long, default_value_t = 10.0, allow_hyphen_values = true)]
    duration: f64,
    /// Frames per simulated second (1 to 50).
    #[arg(long, default_value_t = 10, allow_hyphen_values = true)]
    fps: u16,
    #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
    engine: EngineArg,
    /// Picture size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "1024x700", allow_hyphen_values = true)]
    size: Size,
    #[command(flatten)]
    look: Look,
    /// The GIF file to write (written whole at the end, or not at all).
    #[arg(long)]
    out: std::path::PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    check_output(&args.out, false)?;
    if !args
        .out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("gif"))
    {
        anyhow::bail!(
            "out = {}: recordings are written as GIF; name the file *.gif",
            args.out.display()
        );
    }
    args.look.check(args.size)?;
    if !(1..=50).contains(&args.fps) {
        anyhow::bail!("fps = {}: must be 1 to 50 frames per second", args.fps);
    }
    let duration = args.duration;
    let frames = duration * f64::from(args.fps);
    if !(duration.is_finite() && duration > 0.0 && frames <= MAX_FRAMES) {
        anyhow::bail!(
            "duration = {}: must be a positive number of seconds, at most {MAX_FRAMES} frames at {} fps",
            Shown(duration),
            args.fps
        );
    }
    let (name, model) = match &args.ramp {
        Some(ramp) => args.model.build_ramped(Some(ramp))?,
        None => args.model.build_for_the_window()?,
    };
    let mut app = ZieglerApp::new(Settings {
        preset: name,
        model,
        engine: args.engine.into(),
        speed: 1.0,
        projector: args.look.projector,
    })?;
    app.apply(Action::Language(args.look.language()));
    if let Some(ramp) = args.ramp {
        app.apply(Action::RampStart(ramp));
    }
    let panel = args.look.panel();
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "frames is checked to lie in (0, MAX_FRAMES]"
    )]
    let frames = frames.round().max(1.0) as usize;
    let Size { width, height } = args.size;
    let progress = progress_bar(frames as u64, "frames");
    let mut gif = GifRecording::new(width, height, args.fps)?;
    let mut app_time_secs = 0.0;
    render_frames(
        app,
        panel,
        args.size,
        args.look.scale,
        frames,
        |app, i| {
            // Whole app frames up to this picture's simulated time.
            #[expect(clippy::cast_precision_loss, reason = "at most MAX_FRAMES")]
            let due_secs = i as f64 / f64::from(args.fps);
            while app_time_secs + 0.5 * APP_FRAME_SECS < due_secs {
                app.advance(APP_FRAME_SECS);
                app_time_secs += APP_FRAME_SECS;
            }
        },
        |i, image| {
            gif.push(&mut image.into_raw())?;
            progress.set_position(i as u64 + 1);
            Ok(())
        },
    )?;
    let encoded = gif.finish()?;
    progress.finish_and_clear();
    write_atomically(&args.out, |w| w.write_all(&encoded))
}
