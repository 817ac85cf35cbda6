//! Every colour that carries meaning, as plain RGB named by what it stands
//! for: the window's two themes read it, and the figures read it on paper.

use crate::analysis::State;

/// A colour as red, green and blue bytes (opaque).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    pub const BLACK: Self = Self(0, 0, 0);
    pub const WHITE: Self = Self(255, 255, 255);

    /// A grey of `level`.
    #[must_use]
    pub const fn gray(level: u8) -> Self {
        Self(level, level, level)
    }
}

/// The colours of one theme, by meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Palette {
    pub background: Rgb,
    pub rod: Rgb,
    pub joint: Rgb,
    pub spring: Rgb,
    pub roller: Rgb,
    pub roller_mark: Rgb,
    pub band: Rgb,
    pub band_mark: Rgb,
    pub friction: Rgb,
    pub follower: Rgb,
    pub trail: Rgb,
    pub text: Rgb,
    pub stable: Rgb,
    pub flutter: Rgb,
    pub divergence: Rgb,
    pub axis: Rgb,
    /// Markers of the present: the current eigenvalues, the current load on
    /// the load bar, the current model's point on the map and the paradox plot.
    pub now: Rgb,
    /// The current load as a line across the plots against the load.
    pub load_line: Rgb,
    /// Eigenvalues measured from the run.
    pub measured: Rgb,
    /// The overlaid model's locus, behind the current one.
    pub overlay: Rgb,
    /// Cells and rows without data (not computed yet, or no analysis).
    pub no_data: Rgb,
    /// Curves that are neither states nor the scene's objects, in order.
    pub series: [Rgb; 6],
    /// The k-th curve of a plot (a damping level, an overlaid model), in
    /// colours that read on this theme's background.
    pub curves: [Rgb; 5],
    /// Notices: something refused or failed.
    pub error: Rgb,
    /// Notices and cautions: done, but not quite as asked, or not resolved.
    pub warning: Rgb,
    /// Notices: done as asked.
    pub info: Rgb,
}

impl Palette {
    /// The everyday theme, on a dark background.
    pub const NORMAL: Self = Self {
        background: Rgb(24, 26, 30),
        rod: Rgb(205, 210, 220),
        joint: Rgb(250, 250, 250),
        spring: Rgb(120, 170, 255),
        roller: Rgb(230, 170, 60),
        roller_mark: Rgb(90, 60, 20),
        band: Rgb(70, 74, 84),
        band_mark: Rgb(120, 126, 140),
        friction: Rgb(255, 90, 90),
        follower: Rgb(90, 220, 140),
        trail: Rgb(150, 110, 255),
        text: Rgb(225, 228, 235),
        stable: Rgb(70, 170, 100),
        flutter: Rgb(230, 150, 40),
        divergence: Rgb(215, 60, 60),
        axis: Rgb(200, 200, 200),
        now: Rgb::WHITE,
        load_line: Rgb(255, 90, 90),
        measured: Rgb(255, 90, 90),
        overlay: Rgb(120, 120, 120),
        no_data: Rgb::gray(40),
        series: [
            Rgb(120, 170, 255),
            Rgb(205, 210, 220),
            Rgb(255, 90, 90),
            Rgb(90, 220, 140),
            Rgb(230, 150, 40),
            Rgb(150, 110, 255),
        ],
        curves: [
            Rgb(120, 170, 255),
            Rgb(90, 220, 140),
            Rgb(230, 150, 40),
            Rgb(150, 110, 255),
            Rgb(255, 90, 90),
        ],
        error: Rgb(215, 60, 60),
        warning: Rgb(230, 150, 40),
        info: Rgb(120, 170, 255),
    };

    /// High contrast for a projector, on black.
    pub const PROJECTOR: Self = Self {
        background: Rgb::BLACK,
        rod: Rgb::WHITE,
        joint: Rgb::WHITE,
        spring: Rgb(80, 180, 255),
        roller: Rgb(255, 200, 0),
        roller_mark: Rgb::BLACK,
        band: Rgb(60, 60, 60),
        band_mark: Rgb(200, 200, 200),
        friction: Rgb(255, 60, 60),
        follower: Rgb(0, 255, 120),
        trail: Rgb(200, 140, 255),
        text: Rgb::WHITE,
        stable: Rgb(0, 200, 80),
        flutter: Rgb(255, 170, 0),
        divergence: Rgb(255, 50, 50),
        axis: Rgb::WHITE,
        now: Rgb::WHITE,
        load_line: Rgb(255, 60, 60),
        measured: Rgb(255, 60, 60),
        overlay: Rgb(120, 120, 120),
        no_data: Rgb::gray(40),
        series: [
            Rgb(80, 180, 255),
            Rgb::WHITE,
            Rgb(255, 60, 60),
            Rgb(0, 255, 120),
            Rgb(255, 170, 0),
            Rgb(200, 140, 255),
        ],
        curves: [
            Rgb(80, 180, 255),
            Rgb(0, 255, 120),
            Rgb(255, 170, 0),
            Rgb(200, 140, 255),
            Rgb(255, 60, 60),
        ],
        error: Rgb(255, 50, 50),
        warning: Rgb(255, 170, 0),
        info: Rgb(80, 180, 255),
    };

    /// A printed figure: black ink on white paper, the everyday theme's
    /// states, and curves that read on white (its light grey left out).
    pub const PAPER: Self = Self {
        background: Rgb::WHITE,
        text: Rgb::BLACK,
        axis: Rgb::gray(128),
        now: Rgb::BLACK,
        no_data: Rgb::gray(200),
        curves: [
            Rgb(120, 170, 255),
            Rgb(255, 90, 90),
            Rgb(150, 110, 255),
            Rgb(230, 150, 40),
            Rgb(90, 220, 140),
        ],
        ..Self::NORMAL
    };

    /// The colour that stands for a stability state.
    #[must_use]
    pub const fn state(&self, state: State) -> Rgb {
        match state {
            State::Stable => self.stable,
            State::Flutter => self.flutter,
            State::Divergence => self.divergence,
        }
    }
}

/// A colour for a load between `min` and `max`: from blue (low) through
/// green to red (high), so a locus plot shows where along the load each
/// point of a branch lies.
#[must_use]
pub fn load_color(load: f64, min: f64, max: f64) -> Rgb {
    let t = if max > min {
        ((load - min) / (max - min)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    #[expect(clippy::cast_possible_truncation, reason = "t in [0, 1]")]
    let t = t as f32;
    let lerp = |a: f32, b: f32, s: f32| a + (b - a) * s;
    let (r, g, b) = if t < 0.5 {
        let s = 2.0 * t;
        (
            lerp(60.0, 60.0, s),
            lerp(120.0, 200.0, s),
            lerp(255.0, 90.0, s),
        )
    } else {
        let s = 2.0 * t - 1.0;
        (
            lerp(60.0, 250.0, s),
            lerp(200.0, 70.0, s),
            lerp(90.0, 60.0, s),
        )
    };
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "channels in [0, 255]"
    )]
    Rgb(r as u8, g as u8, b as u8)
}
