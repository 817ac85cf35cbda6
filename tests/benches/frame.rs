//! Frame time of the whole app, headless, at 1280x800 while the nu slider
//! moves every frame (so the root locus and the critical loads are
//! recomputed each frame): the egui pass plus tessellation, over 300 frames,
//! reported as p50 and p99. A frame here is the CPU work of a real frame;
//! the GPU's share (a few thousand triangles) is not included.

#![expect(
    clippy::cast_precision_loss,
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "frame counts and quantile indices are small"
)]

use std::time::Instant;

use eframe::egui::{self, RawInput, Rect, pos2};
use zieglerlab::app::{Settings, ZieglerApp};

fn main() {
    // `cargo bench` passes --bench; under `cargo test` (a debug build) a few
    // frames check that it runs.
    let frames: usize = if std::env::args().any(|a| a == "--bench") {
        300
    } else {
        5
    };
    let ctx = egui::Context::default();
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut times_ms = Vec::with_capacity(frames);
    for frame in 0..frames + 10 {
        // nu sweeps 0.05 .. 0.35 and back, as a dragged slider does.
        let phase = (frame % 120) as f64 / 120.0;
        let nu = 0.05 + 0.3 * (1.0 - (2.0 * phase - 1.0).abs());
        let input = RawInput {
            screen_rect: Some(Rect::from_min_max(pos2(0.0, 0.0), pos2(1280.0, 800.0))),
            ..Default::default()
        };
        let start = Instant::now();
        app.set_parameter("nu", nu).unwrap();
        app.advance(1.0 / 60.0);
        let mut output = ctx.run_ui(input, |ui| app.contents_ui(ui));
        // No renderer takes the font atlas here.
        output.textures_delta.clear();
        let primitives = ctx.tessellate(output.shapes, output.pixels_per_point);
        std::hint::black_box(primitives);
        let elapsed = start.elapsed().as_secs_f64() * 1e3;
        // The first frames lay out fonts and caches once.
        if frame >= 10 {
            times_ms.push(elapsed);
        }
    }
    times_ms.sort_by(f64::total_cmp);
    let pick = |q: f64| times_ms[((q * (times_ms.len() - 1) as f64).round()) as usize];
    println!(
        "frame at 1280x800, nu dragged every frame, {frames} frames: p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
        pick(0.5),
        pick(0.99),
        pick(1.0)
    );
}
