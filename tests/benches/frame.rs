//! Frame time of the whole app, headless, at 1280x800 while the nu slider
//! moves every frame (so the root locus and the critical loads are
//! recomputed each frame): the egui pass plus tessellation, reported as p50
//! and p99. The measurement is `zieglerlab::bench::frame_times_ms`, the one
//! `zieglerlab bench` reports.

use zieglerlab::app::Tab;
use zieglerlab::bench::{FRAMES, frame_times_ms, quantile};

fn main() {
    // `cargo bench` passes --bench; under `cargo test` (a debug build) a few
    // frames check that it runs.
    let frames = if std::env::args().any(|a| a == "--bench") {
        FRAMES
    } else {
        5
    };
    let times_ms = frame_times_ms(frames, Tab::Locus).expect("the app's defaults run");
    println!(
        "frame at 1280x800, nu dragged every frame, {frames} frames: p50 {:.2} ms, p99 {:.2} ms, max {:.2} ms",
        quantile(&times_ms, 0.5),
        quantile(&times_ms, 0.99),
        quantile(&times_ms, 1.0)
    );
}
