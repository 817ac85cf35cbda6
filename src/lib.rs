//! zieglerlab: flutter and divergence of the Ziegler column, with the ideal
//! follower force and with the real mechanism (a roller dragged by a moving band).
//!
//! `model` holds the physics, `analysis` the linear stability (both pure f64,
//! no UI, no clock), `sim` the time simulation, `app` the window and
//! `bench` the speed measurements.

// App code answers bad input with an error, never a panic (tests may unwrap).
#![deny(clippy::unwrap_used, clippy::expect_used)]

pub mod analysis;
pub mod app;
pub mod bench;
pub mod export;
pub mod figure;
pub mod files;
pub mod format;
pub mod i18n;
pub mod lesson;
pub mod model;
pub mod names;
pub mod plot;
pub mod recording;
pub mod sim;

/// The threads the machine runs at once (two when it cannot tell): what
/// the window and the command line give the analysis's long computations.
#[must_use]
pub fn machine_threads() -> usize {
    std::thread::available_parallelism().map_or(2, std::num::NonZero::get)
}
