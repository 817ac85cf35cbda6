//! Every colour and stroke of the app in one place; the projector theme
//! (high contrast, large text, for a lecture hall) is just another value.

use eframe::egui::{self, Color32};

use super::notice::Level;
use crate::analysis::State;

/// The palette of one theme.
#[derive(Clone, Copy, Debug)]
pub struct Theme {
    pub background: Color32,
    pub rod: Color32,
    pub joint: Color32,
    pub spring: Color32,
    pub roller: Color32,
    pub roller_mark: Color32,
    pub band: Color32,
    pub band_mark: Color32,
    pub friction: Color32,
    pub follower: Color32,
    pub trail: Color32,
    pub text: Color32,
    pub stable: Color32,
    pub flutter: Color32,
    pub divergence: Color32,
    pub axis: Color32,
    /// Markers of the present: the current eigenvalues, the current load on
    /// the load bar, the current model's point on the map and the paradox plot.
    pub now: Color32,
    /// The current load as a line across the plots against the load.
    pub load_line: Color32,
    /// Eigenvalues measured from the run.
    pub measured: Color32,
    /// The overlaid model's locus, behind the current one.
    pub overlay: Color32,
    /// Cells and rows without data (not computed yet, or no analysis).
    pub no_data: Color32,
    /// Curves that are neither states nor the scene's objects, in order.
    pub series: [Color32; 6],
    /// Notices: something refused or failed.
    pub error: Color32,
    /// Notices and cautions: done, but not quite as asked, or not resolved.
    pub warning: Color32,
    /// Notices: done as asked.
    pub info: Color32,
    /// Line width multiplier for strokes in the scene.
    pub stroke_scale: f32,
    /// Font size of body text.
    pub text_size: f32,
}

impl Theme {
    /// The everyday theme, on egui's dark visuals.
    pub const NORMAL: Self = Self {
        background: Color32::from_rgb(24, 26, 30),
        rod: Color32::from_rgb(205, 210, 220),
        joint: Color32::from_rgb(250, 250, 250),
        spring: Color32::from_rgb(120, 170, 255),
        roller: Color32::from_rgb(230, 170, 60),
        roller_mark: Color32::from_rgb(90, 60, 20),
        band: Color32::from_rgb(70, 74, 84),
        band_mark: Color32::from_rgb(120, 126, 140),
        friction: Color32::from_rgb(255, 90, 90),
        follower: Color32::from_rgb(90, 220, 140),
        trail: Color32::from_rgb(150, 110, 255),
        text: Color32::from_rgb(225, 228, 235),
        stable: Color32::from_rgb(70, 170, 100),
        flutter: Color32::from_rgb(230, 150, 40),
        divergence: Color32::from_rgb(215, 60, 60),
        axis: Color32::from_rgb(200, 200, 200),
        now: Color32::WHITE,
        load_line: Color32::from_rgb(255, 90, 90),
        measured: Color32::from_rgb(255, 90, 90),
        overlay: Color32::from_rgb(120, 120, 120),
        no_data: Color32::from_gray(40),
        series: [
            Color32::from_rgb(120, 170, 255),
            Color32::from_rgb(205, 210, 220),
            Color32::from_rgb(255, 90, 90),
            Color32::from_rgb(90, 220, 140),
            Color32::from_rgb(230, 150, 40),
            Color32::from_rgb(150, 110, 255),
        ],
        error: Color32::from_rgb(215, 60, 60),
        warning: Color32::from_rgb(230, 150, 40),
        info: Color32::from_rgb(120, 170, 255),
        stroke_scale: 1.0,
        text_size: 14.0,
    };

    /// High contrast and large text for a projector.
    pub const PROJECTOR: Self = Self {
        background: Color32::BLACK,
        rod: Color32::WHITE,
        joint: Color32::WHITE,
        spring: Color32::from_rgb(80, 180, 255),
        roller: Color32::from_rgb(255, 200, 0),
        roller_mark: Color32::BLACK,
        band: Color32::from_rgb(60, 60, 60),
        band_mark: Color32::from_rgb(200, 200, 200),
        friction: Color32::from_rgb(255, 60, 60),
        follower: Color32::from_rgb(0, 255, 120),
        trail: Color32::from_rgb(200, 140, 255),
        text: Color32::WHITE,
        stable: Color32::from_rgb(0, 200, 80),
        flutter: Color32::from_rgb(255, 170, 0),
        divergence: Color32::from_rgb(255, 50, 50),
        axis: Color32::WHITE,
        now: Color32::WHITE,
        load_line: Color32::from_rgb(255, 60, 60),
        measured: Color32::from_rgb(255, 60, 60),
        overlay: Color32::from_rgb(120, 120, 120),
        no_data: Color32::from_gray(40),
        series: [
            Color32::from_rgb(80, 180, 255),
            Color32::WHITE,
            Color32::from_rgb(255, 60, 60),
            Color32::from_rgb(0, 255, 120),
            Color32::from_rgb(255, 170, 0),
            Color32::from_rgb(200, 140, 255),
        ],
        error: Color32::from_rgb(255, 50, 50),
        warning: Color32::from_rgb(255, 170, 0),
        info: Color32::from_rgb(80, 180, 255),
        stroke_scale: 1.8,
        text_size: 22.0,
    };

    /// The colour that stands for a stability state.
    #[must_use]
    pub fn state_color(&self, state: State) -> Color32 {
        match state {
            State::Stable => self.stable,
            State::Flutter => self.flutter,
            State::Divergence => self.divergence,
        }
    }

    /// The colour of a notice of `level`.
    #[must_use]
    pub fn notice_color(&self, level: Level) -> Color32 {
        match level {
            Level::Info => self.info,
            Level::Warning => self.warning,
            Level::Error => self.error,
        }
    }

    /// Applies the theme's visuals and text size to the context.
    pub fn apply(&self, ctx: &egui::Context) {
        let mut visuals = egui::Visuals::dark();
        visuals.panel_fill = self.background;
        visuals.override_text_color = Some(self.text);
        ctx.set_visuals(visuals);
        ctx.global_style_mut(|style| {
            for (text_style, font) in &mut style.text_styles {
                font.size = match text_style {
                    egui::TextStyle::Heading => self.text_size * 1.4,
                    egui::TextStyle::Small => self.text_size * 0.75,
                    _ => self.text_size,
                };
            }
        });
    }
}

/// A colour for a load between `min` and `max`: from blue (low) through
/// green to red (high), so a locus plot shows where along the load each
/// point of a branch lies.
#[must_use]
pub fn load_color(load: f64, min: f64, max: f64) -> Color32 {
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
    Color32::from_rgb(r as u8, g as u8, b as u8)
}
