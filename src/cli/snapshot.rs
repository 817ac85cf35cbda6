//! `zieglerlab snapshot`: the app (or one panel) rendered headlessly to a PNG
//! after a given simulated time.

use anyhow::Result;
use zieglerlab::format::Shown;

use zieglerlab::app::{Settings, ZieglerApp};

use super::headless::{Look, Size, render_frames};
use super::output::{check_output, write_png};
use super::{EngineArg, ModelArgs, progress_bar};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// Simulated time before the picture, in s.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    time: f64,
    #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
    engine: EngineArg,
    /// Image size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "1280x800", allow_hyphen_values = true)]
    size: Size,
    #[command(flatten)]
    look: Look,
    #[arg(long)]
    out: std::path::PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    check_output(&args.out, true)?;
    args.look.check(args.size)?;
    let (name, model) = args.model.build()?;
    let time = args.time;
    if !(time.is_finite() && (0.0..=1.0e5).contains(&time)) {
        anyhow::bail!(
            "time = {}: must be a number of seconds in [0, 100000]",
            Shown(time)
        );
    }
    let settings = Settings {
        preset: name,
        model,
        engine: args.engine.into(),
        speed: 1.0,
        projector: args.look.projector,
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
    let panel = args.look.panel();
    let mut image = None;
    render_frames(
        app,
        panel,
        args.size,
        args.look.scale,
        1,
        |_, _| {},
        |_, frame| {
            image = Some(frame);
            Ok(())
        },
    )?;
    match image {
        Some(image) => write_png(&args.out, &image),
        None => anyhow::bail!("rendering gave no picture"),
    }
}
