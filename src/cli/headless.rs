//! Pictures of the app without a window: the arguments they share (the
//! panel, size, scale, projector mode and language of a snapshot or a
//! recording; the language of a figure), and the headless renderer (wgpu on
//! Mesa's CPU GL will do) with one clear error when there is none.

use std::str::FromStr;

use clap::builder::TypedValueParser as _;

use anyhow::Result;

use zieglerlab::app::{Panel, ZieglerApp};
use zieglerlab::i18n::{Language, words};

use super::tiles::TiledRenderer;

/// The `--panel` values: the window, the scene and every tab of the app's
/// registry, listed in `--help`.
fn panel_parser() -> impl clap::builder::TypedValueParser<Value = Panel> {
    clap::builder::PossibleValuesParser::new(Panel::names()).try_map(|name| Panel::from_str(&name))
}

/// A picture's size in pixels, `WIDTHxHEIGHT`, each 64 to 8192.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Size {
    pub width: u16,
    pub height: u16,
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

/// How a picture shows the app: which panel, projector mode, and pixels
/// per point.
#[derive(clap::Args, Debug)]
pub struct Look {
    /// Pixels per point, 0.5 to 8: 2 draws the same layout as 1 with
    /// twice as many pixels each way (text for a 4K slide: `--size
    /// 3840x2160 --scale 3` lays out a 1280x720 window).
    #[arg(long, default_value_t = 1.0, allow_hyphen_values = true)]
    pub scale: f32,
    #[arg(long)]
    pub projector: bool,
    #[arg(long, default_value = "window", value_parser = panel_parser())]
    pub panel: Panel,
    /// The window's language: en, de, it, pl, es or fr [default: the
    /// system's language, as the window follows it]
    #[arg(long, value_name = "CODE", value_parser = language_parser())]
    pub lang: Option<Language>,
}

/// A figure's `--lang`: the language of its axes and legend, English
/// unless asked (a paper's figure), whatever the system's.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct FigureLanguage {
    /// The language of the figure's axes and legend: en, de, it, pl, es or
    /// fr.
    #[arg(long = "lang", value_name = "CODE", default_value = "en", value_parser = language_parser())]
    pub language: Language,
}

/// The `--lang` values: the window's languages (and, unlisted, the
/// pseudo-language of the layout tests).
pub fn language_parser() -> impl clap::builder::TypedValueParser<Value = Language> {
    let codes = Language::CHOSEN_FROM
        .iter()
        .map(|l| clap::builder::PossibleValue::new(l.code()))
        .chain([clap::builder::PossibleValue::new(Language::Pseudo.code()).hide(true)]);
    clap::builder::PossibleValuesParser::new(codes).try_map(|code| Language::from_code(&code))
}

impl Look {
    /// The panel these arguments picture.
    pub fn panel(&self) -> Panel {
        self.panel
    }

    /// The language asked for, or the system's.
    pub fn language(&self) -> Language {
        self.lang.unwrap_or_else(Language::system)
    }

    /// Pixels per point must be 0.5 to 8, and `size` at that scale must lay
    /// the panel out in at least [`Panel::smallest_points`]: a smaller
    /// layout is a clipped fragment of the app (or nothing at all), never
    /// what a window shows.
    ///
    /// # Errors
    /// A scale out of range or not a number, or too few points for the panel.
    pub fn check(&self, size: Size) -> Result<()> {
        let scale = self.scale;
        if !(scale.is_finite() && (0.5..=8.0).contains(&scale)) {
            // The number as typed (f32), in exponent form when huge or tiny.
            let magnitude = scale.abs();
            let shown =
                if magnitude == 0.0 || !magnitude.is_finite() || (1e-4..1e7).contains(&magnitude) {
                    format!("{scale}")
                } else {
                    format!("{scale:e}")
                };
            anyhow::bail!("scale = {shown}: must be 0.5 to 8 pixels per point");
        }
        let panel = self.panel();
        let [least_w, least_h] = panel.smallest_points();
        let (points_w, points_h) = (
            f32::from(size.width) / scale,
            f32::from(size.height) / scale,
        );
        if points_w < least_w || points_h < least_h {
            let what = match panel {
                Panel::Window => "the window (the smallest it opens at)",
                Panel::Scene | Panel::Tab(_) => "one panel",
            };
            let most_scale =
                (f32::from(size.width) / least_w).min(f32::from(size.height) / least_h);
            let hint = if most_scale >= 0.5 {
                format!(
                    "a scale of at most {:.2} or a larger --size",
                    (most_scale * 100.0).floor() / 100.0
                )
            } else {
                "a larger --size".to_owned()
            };
            anyhow::bail!(
                "size = {}x{} at scale = {scale} lays out {points_w:.0}x{points_h:.0} points; {what} needs at least {least_w:.0}x{least_h:.0}: use {hint}",
                size.width,
                size.height,
            );
        }
        Ok(())
    }
}

/// Renders `panel` of `app` headlessly with wgpu, `size` pixels at `scale`
/// pixels per point: `frames` pictures, `before(app, i)` run before picture
/// `i` and each picture handed to `each`. One renderer serves all the
/// frames. Every tab's background work (the map, the paradox curves, the
/// limit cycles) is completed before each picture of it, so a picture
/// depends on the arguments alone. A missing renderer (no Mesa, no GPU)
/// panics inside its setup: that becomes one clear error.
///
/// # Errors
/// No renderer, a drawing that failed, or an error of `each`.
pub fn render_frames(
    mut app: ZieglerApp,
    panel: Panel,
    size: Size,
    scale: f32,
    frames: usize,
    mut before: impl FnMut(&mut ZieglerApp, usize),
    mut each: impl FnMut(usize, image::RgbaImage) -> Result<()>,
) -> Result<()> {
    let (width, height) = (f32::from(size.width), f32::from(size.height));
    app.draw_for_pictures();
    // The tab drawn: the panel's, or the one open in the window (a lesson
    // step may have opened the paradox curves).
    let drawn = match panel {
        Panel::Tab(tab) => Some(tab),
        Panel::Window => Some(app.layout().tab),
        Panel::Scene => None,
    };
    let background = drawn.filter(|&tab| tab.spec().background);
    if let Some(tab) = background {
        // A long chain's map takes minutes: say what is being waited for.
        let working = super::spinner(&format!(
            "computing the {} tab",
            tab.title(words(Language::English))
        ));
        app.complete_background_work(tab);
        working.finish_and_clear();
    }
    let previous_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let rendered = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut harness = egui_kittest::Harness::builder()
            .renderer(TiledRenderer::new())
            .with_size([width / scale, height / scale])
            .with_pixels_per_point(scale)
            .build_ui_state(|ui, app: &mut ZieglerApp| app.panel_ui(ui, panel), app);
        for i in 0..frames {
            before(harness.state_mut(), i);
            if let Some(tab) = background
                && i > 0
            {
                harness.state_mut().complete_background_work(tab);
            }
            harness.run_steps(if i == 0 { 4 } else { 2 });
            let image = harness.render().map_err(Stop::Drawing)?;
            each(i, image).map_err(Stop::Taking)?;
        }
        Ok(())
    }));
    std::panic::set_hook(previous_hook);
    match rendered {
        Ok(Ok(())) => Ok(()),
        Ok(Err(Stop::Taking(error))) => Err(error),
        // The renderer exists (its creation panics otherwise): this is the
        // drawing itself failing.
        Ok(Err(Stop::Drawing(error))) => {
            anyhow::bail!(failure_message(&Failure::Drawing(error), width, height))
        }
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

/// Why the frames stopped before the end.
enum Stop {
    /// The renderer could not draw a frame.
    Drawing(String),
    /// The one taking the frames failed (a write, an encoder).
    Taking(anyhow::Error),
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
        Failure::Drawing(error) if timed_out(error) => format!(
            "rendering timed out ({error}): Mesa's CPU renderer needs more time for a {width}x{height} picture on this machine; try a smaller --size or run it again when the machine is less busy"
        ),
        Failure::Drawing(error) => format!("rendering failed: {error}"),
        Failure::NoRenderer(what) => format!(
            "rendering failed ({what}); if no renderer could be created (a GPU, or Mesa's CPU GL: Debian packages libegl1 libegl-mesa0 libgl1-mesa-dri)"
        ),
    }
}

/// Whether a renderer's error says that it waited too long (wgpu says
/// "timed out", other layers "timeout").
fn timed_out(error: &str) -> bool {
    let error = error.to_lowercase();
    error.contains("timeout") || error.contains("timed out")
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
        // wgpu's own words for it.
        let wgpu = failure_message(
            &Failure::Drawing(
                "PollError: The requested Wait timed out before the submission was completed."
                    .to_owned(),
            ),
            8192.0,
            8192.0,
        );
        assert!(wgpu.starts_with("rendering timed out"), "{wgpu}");
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
