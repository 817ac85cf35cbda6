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
    #[arg(long)]
    projector: bool,
    #[arg(long, value_enum, default_value_t = PanelArg::Window)]
    panel: PanelArg,
    #[arg(long)]
    out: std::path::PathBuf,
}

pub fn run(args: &Args) -> Result<()> {
    check_output(&args.out, true)?;
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
    let image = render(&mut app, panel, (f32::from(width), f32::from(height)))?;
    write_png(&args.out, &image)
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
