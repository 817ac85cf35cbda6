//! `zieglerlab snapshot`: the app (or one panel) rendered headlessly to a PNG
//! after a given simulated time.

use std::str::FromStr;

use anyhow::Result;
use clap::ValueEnum;

use zieglerlab::app::{Panel, Settings, Tab, ZieglerApp};

use super::output::{check_output, write_png};
use super::{EngineArg, ModelArgs, progress_bar};

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

/// A picture's size in pixels, `WIDTHxHEIGHT`, each 64 to 8192.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    width: u16,
    height: u16,
}

impl FromStr for Size {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, String> {
        text.split_once('x')
            .and_then(|(w, h)| Some((w.trim().parse().ok()?, h.trim().parse().ok()?)))
            .filter(|&(w, h)| (64..=8192).contains(&w) && (64..=8192).contains(&h))
            .map(|(width, height)| Self { width, height })
            .ok_or_else(|| {
                "must be WIDTHxHEIGHT in pixels, each 64 to 8192 (e.g. 1280x800)".to_owned()
            })
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// Simulated time before the picture, in s.
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    time: f64,
    #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
    engine: EngineArg,
    /// Image size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "1280x800", allow_hyphen_values = true)]
    size: Size,
    /// Pixels per point, 0.5 to 8: 2 draws the same layout as 1 with
    /// twice as many pixels each way (text for a 4K slide: `--size
    /// 3840x2160 --scale 3` lays out a 1280x720 window).
    #[arg(long, default_value_t = 1.0)]
    scale: f32,
    #[arg(long)]
    projector: bool,
    #[arg(long, value_enum, default_value_t = PanelArg::Window)]
    panel: PanelArg,
    #[arg(long)]
    out: std::path::PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    check_output(&args.out, true)?;
    if !(args.scale.is_finite() && (0.5..=8.0).contains(&args.scale)) {
        anyhow::bail!("scale = {}: must be 0.5 to 8 pixels per point", args.scale);
    }
    let (name, model) = args.model.build()?;
    let time = args.time;
    if !(time.is_finite() && (0.0..=1.0e5).contains(&time)) {
        anyhow::bail!("time = {time}: must be a number of seconds in [0, 100000]");
    }
    let settings = Settings {
        preset: name,
        model,
        engine: args.engine.into(),
        speed: 1.0,
        projector: args.projector,
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
    let panel = Panel::from(args.panel);
    if matches!(panel, Panel::Tab(Tab::Map | Tab::Paradox)) {
        app.complete_background_work();
    }
    let Size { width, height } = args.size;
    let image = render(
        &mut app,
        panel,
        (f32::from(width), f32::from(height)),
        args.scale,
    )?;
    write_png(&args.out, &image)
}

/// The picture of `panel` by wgpu, headless, `width` x `height` pixels at
/// `scale` pixels per point. A missing renderer (no Mesa, no GPU) panics
/// inside the renderer's setup: that becomes one clear error.
fn render(
    app: &mut ZieglerApp,
    panel: Panel,
    (width, height): (f32, f32),
    scale: f32,
) -> Result<image::RgbaImage> {
    let previous_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let rendered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut harness = egui_kittest::Harness::builder()
            .wgpu()
            .with_size([width / scale, height / scale])
            .with_pixels_per_point(scale)
            .build_ui(|ui| app.panel_ui(ui, panel));
        harness.run_steps(4);
        harness.render()
    }));
    std::panic::set_hook(previous_hook);
    match rendered {
        Ok(Ok(image)) => Ok(image),
        // The renderer exists (its creation panics otherwise): this is the
        // drawing itself failing.
        Ok(Err(error)) => anyhow::bail!(failure_message(&Failure::Drawing(error), width, height)),
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
            anyhow::bail!(failure_message(&Failure::NoRenderer(what), width, height))
        }
    }
}

/// How a headless picture failed.
#[derive(Debug)]
enum Failure {
    /// The renderer exists; drawing failed with this message.
    Drawing(String),
    /// The renderer could not be created (its setup panicked with this).
    NoRenderer(String),
}

/// What the user is told: a drawing that timed out (a large picture on a
/// busy machine's CPU renderer) says so and what to try; a missing renderer
/// names the packages that provide one.
fn failure_message(failure: &Failure, width: f32, height: f32) -> String {
    match failure {
        Failure::Drawing(error) if error.to_lowercase().contains("timeout") => format!(
            "rendering timed out ({error}): Mesa's CPU renderer needs more time for a {width}x{height} picture on this machine; try a smaller --size or run it again when the machine is less busy"
        ),
        Failure::Drawing(error) => format!("rendering failed: {error}"),
        Failure::NoRenderer(what) => format!(
            "rendering failed ({what}); if no renderer could be created (a GPU, or Mesa's CPU GL: Debian packages libegl1 libegl-mesa0 libgl1-mesa-dri)"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A timed-out drawing is not reported as a missing renderer (it once
    /// said "install Mesa" for a 4096x4096 picture on a busy machine).
    #[test]
    fn a_timeout_says_so_and_a_missing_renderer_names_the_packages() {
        let timeout = failure_message(
            &Failure::Drawing("Timeout waiting for the GPU".to_owned()),
            4096.0,
            4096.0,
        );
        assert!(timeout.starts_with("rendering timed out"), "{timeout}");
        assert!(timeout.contains("4096x4096"), "{timeout}");
        assert!(timeout.contains("smaller --size"), "{timeout}");
        assert!(!timeout.contains("Mesa's CPU GL: Debian"), "{timeout}");
        let other = failure_message(&Failure::Drawing("lost device".to_owned()), 64.0, 64.0);
        assert_eq!(other, "rendering failed: lost device");
        let missing = failure_message(&Failure::NoRenderer("no adapter".to_owned()), 1280.0, 800.0);
        assert!(missing.contains("(no adapter)"), "{missing}");
        assert!(
            missing.contains("libegl1 libegl-mesa0 libgl1-mesa-dri"),
            "{missing}"
        );
    }
}
