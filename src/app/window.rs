//! The real window: eframe's options, the renderer that draws it, and timed
//! runs of the window for the bench (the whole frame, drawing included).

use std::sync::{Arc, Mutex};
use std::time::Instant;

use eframe::egui;

use super::notice::Notice;
use super::state::Settings;
use super::{APP_ID, ZieglerApp, store_check};

/// Which of eframe's renderers draws the window.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Renderer {
    /// OpenGL through glow: the default. Without a GPU (Mesa's llvmpipe) it
    /// draws about five times the frames of wgpu's GL backend.
    #[default]
    Glow,
    /// wgpu (Vulkan, Metal, DX12 or GL, whichever the machine offers).
    Wgpu,
}

impl From<Renderer> for eframe::Renderer {
    fn from(renderer: Renderer) -> Self {
        match renderer {
            Renderer::Glow => Self::Glow,
            Renderer::Wgpu => Self::Wgpu,
        }
    }
}

/// The window's icon, the one the desktop entry names.
const ICON_PNG: &[u8] = include_bytes!("../../assets/zieglerlab.png");

/// `viewport` with the window's icon (the desktop's default where the
/// picture cannot be read, which a unit test rules out).
fn with_icon(viewport: egui::ViewportBuilder) -> egui::ViewportBuilder {
    match eframe::icon_data::from_png_bytes(ICON_PNG) {
        Ok(icon) => viewport.with_icon(std::sync::Arc::new(icon)),
        Err(_) => viewport,
    }
}

/// The window's options: its title and sizes, drawn by `renderer`.
fn options(renderer: Renderer, inner_size: [f32; 2]) -> eframe::NativeOptions {
    eframe::NativeOptions {
        viewport: with_icon(
            egui::ViewportBuilder::default()
                .with_title(super::recorder::WINDOW_TITLE)
                // The desktop entry's name (its StartupWMClass): the desktop
                // groups the window under the entry and shows its icon.
                .with_app_id(APP_ID)
                .with_inner_size(inner_size)
                .with_min_inner_size(super::SMALLEST_WINDOW_POINTS),
        ),
        renderer: renderer.into(),
        // Dithering adds noise to every pixel's colour to hide banding in
        // gradients; there are none here, and on a CPU renderer it costs
        // about a tenth of the frame.
        dithering: false,
        ..Default::default()
    }
}

/// Opens the app window, drawn by `renderer`.
///
/// # Errors
/// When no window or graphics context can be created.
pub fn run(renderer: Renderer) -> eframe::Result {
    // eframe restores its own entries (zoom, window) before any of ours runs:
    // they are checked first, so a bad one cannot crash every launch.
    let notice = eframe::storage_dir(APP_ID)
        .map(|dir| dir.join("app.ron"))
        .and_then(|path| {
            // Before the store is read: the system's language.
            let words = crate::i18n::words(crate::i18n::Language::system());
            store_check::check_stored_file(&path, words)
        });
    eframe::run_native(
        APP_ID,
        options(renderer, [1280.0, 800.0]),
        Box::new(move |cc| {
            let mut app = ZieglerApp::from_storage(cc.storage);
            app.cleared_to_panel_fill = true;
            app.state.analyse_in_background();
            if let Some(notice) = notice {
                app.state.tell(Notice::warning(notice));
            }
            Ok(Box::new(app))
        }),
    )
}

/// Frames of the window timed by [`time_window_frames`].
#[derive(Clone, Debug, Default)]
pub struct WindowFrames {
    /// Wall time from the start of one frame to the start of the next, in
    /// ms: the app's logic, the egui pass, tessellation, drawing and the
    /// buffer swap, as the person at the window waits for them.
    pub intervals_ms: Vec<f64>,
}

/// Frames untimed at the start (fonts laid out, caches filled, the window
/// mapped and sized).
const WARMUP_FRAMES: usize = 30;

/// The default launch (the `roller` preset running, the locus tab) in a
/// real window of `inner_size` points drawn by `renderer`, repainted
/// continuously for `frames` timed frames and then closed. The app's stored
/// settings are neither read nor written. Needs a display.
///
/// # Errors
/// No display, no graphics context, or the app's defaults refused (they are
/// not).
pub fn time_window_frames(
    renderer: Renderer,
    inner_size: [f32; 2],
    frames: usize,
    settings: Settings,
) -> Result<WindowFrames, WindowTimingError> {
    let timed = Arc::new(Mutex::new(WindowFrames::default()));
    let shared = Arc::clone(&timed);
    let mut options = options(renderer, inner_size);
    options.persist_window = false;
    options.viewport = options.viewport.with_min_inner_size([64.0, 64.0]);
    let app = ZieglerApp::new(settings)?;
    eframe::run_native(
        "zieglerlab-bench",
        options,
        Box::new(move |_cc| {
            let mut app = app;
            app.cleared_to_panel_fill = true;
            app.state.analyse_in_background();
            Ok(Box::new(TimedWindow {
                app,
                frames,
                seen: 0,
                last: None,
                timed: shared,
            }))
        }),
    )
    .map_err(|e| WindowTimingError::Window(e.to_string()))?;
    let frames_timed = timed
        .lock()
        .map_err(|_| WindowTimingError::Panicked)?
        .clone();
    if frames_timed.intervals_ms.len() < frames {
        return Err(WindowTimingError::ClosedEarly {
            timed: frames_timed.intervals_ms.len(),
            asked: frames,
        });
    }
    Ok(frames_timed)
}

/// Why the window's frames could not be timed.
#[derive(Debug, thiserror::Error)]
pub enum WindowTimingError {
    #[error(transparent)]
    App(#[from] crate::sim::SimError),
    /// eframe's own error (no display, no graphics context), as it words it.
    #[error("{0}")]
    Window(String),
    #[error("the timed window panicked")]
    Panicked,
    #[error("the window closed after {timed} of {asked} timed frames")]
    ClosedEarly { timed: usize, asked: usize },
}

/// The app in a window that times its frames and closes itself.
struct TimedWindow {
    app: ZieglerApp,
    frames: usize,
    seen: usize,
    last: Option<Instant>,
    timed: Arc<Mutex<WindowFrames>>,
}

impl eframe::App for TimedWindow {
    fn logic(&mut self, ctx: &egui::Context, frame: &mut eframe::Frame) {
        let now = Instant::now();
        if let (Some(last), true) = (self.last, self.seen > WARMUP_FRAMES)
            && let Ok(mut timed) = self.timed.lock()
        {
            timed
                .intervals_ms
                .push(now.duration_since(last).as_secs_f64() * 1e3);
        }
        self.last = Some(now);
        self.seen += 1;
        if self.seen > WARMUP_FRAMES + self.frames {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        eframe::App::logic(&mut self.app, ctx, frame);
        ctx.request_repaint();
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        eframe::App::ui(&mut self.app, ui, frame);
    }

    fn clear_color(&self, visuals: &egui::Visuals) -> [f32; 4] {
        eframe::App::clear_color(&self.app, visuals)
    }

    /// A bench run leaves nothing of egui's memory behind.
    fn persist_egui_memory(&self) -> bool {
        false
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The icon built into the program is the square picture the desktop
    /// entry names.
    #[test]
    fn the_window_icon_is_a_square_picture() {
        let icon = eframe::icon_data::from_png_bytes(ICON_PNG).unwrap();
        assert_eq!((icon.width, icon.height), (256, 256));
        assert_eq!(icon.rgba.len(), 4 * 256 * 256);
    }
}
