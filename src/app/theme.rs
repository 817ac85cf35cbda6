//! The window's themes: a palette with the strokes and text size of each,
//! and the palette's colours converted as egui draws them; the projector
//! theme (high contrast, large text, for a lecture hall) is just another
//! value.

use eframe::egui::{self, Color32};

use super::notice::Level;
use crate::analysis::State;
use crate::plot::{Palette, Rgb};

/// One theme: the palette's colours by meaning, the width of its strokes
/// and the size of its text. Each view looks its colour up in the palette
/// by meaning and converts it with [`color`]; nothing here copies it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    pub palette: &'static Palette,
    /// Line width multiplier for strokes in the scene.
    pub stroke_scale: f32,
    /// Font size of body text.
    pub text_size: f32,
}

impl Theme {
    /// The everyday theme, on egui's dark visuals.
    pub const NORMAL: Self = Self {
        palette: &Palette::NORMAL,
        stroke_scale: 1.0,
        text_size: 14.0,
    };

    /// High contrast and large text for a projector.
    pub const PROJECTOR: Self = Self {
        palette: &Palette::PROJECTOR,
        stroke_scale: 1.8,
        text_size: 22.0,
    };

    /// The colour that stands for a stability state.
    #[must_use]
    pub fn state_color(&self, state: State) -> Color32 {
        let p = self.palette;
        color(match state {
            State::Stable => p.stable,
            State::Flutter => p.flutter,
            State::Divergence => p.divergence,
        })
    }

    /// The colour of a notice of `level`.
    #[must_use]
    pub fn notice_color(&self, level: Level) -> Color32 {
        let p = self.palette;
        color(match level {
            Level::Info => p.info,
            Level::Warning => p.warning,
            Level::Error => p.error,
        })
    }

    /// The ring round the control that has the keys: in the text's colour
    /// and twice as wide as the theme's strokes, so it shows on a
    /// projector too (egui's own controls and ours alike).
    #[must_use]
    pub fn focus_stroke(&self) -> egui::Stroke {
        egui::Stroke::new(2.0 * self.stroke_scale, color(self.palette.text))
    }

    /// Applies the theme's visuals and text size to the context.
    pub fn apply(&self, ctx: &egui::Context) {
        let mut visuals = egui::Visuals::dark();
        visuals.panel_fill = color(self.palette.background);
        visuals.override_text_color = Some(color(self.palette.text));
        // egui draws a focused control as a pressed one: its ring is ours.
        visuals.widgets.active.bg_stroke = self.focus_stroke();
        visuals.selection.stroke.width = 2.0 * self.stroke_scale;
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

/// A palette colour as egui draws it.
#[must_use]
pub const fn color(rgb: Rgb) -> Color32 {
    Color32::from_rgb(rgb.0, rgb.1, rgb.2)
}
