//! The window's themes: the palette's colours as egui draws them, with the
//! strokes and text size of each; the projector theme (high contrast, large
//! text, for a lecture hall) is just another value.

use eframe::egui::{self, Color32};

use super::notice::Level;
use crate::analysis::State;
use crate::plot::{Palette, Rgb};

/// The palette of one theme.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    /// The colours as plain RGB, for what is computed from them (a ramp).
    pub palette: &'static Palette,
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
    /// The k-th curve of a plot (a damping level, an overlaid model).
    pub curves: [Color32; 5],
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
    pub const NORMAL: Self = Self::new(&Palette::NORMAL, 1.0, 14.0);

    /// High contrast and large text for a projector.
    pub const PROJECTOR: Self = Self::new(&Palette::PROJECTOR, 1.8, 22.0);

    /// The theme of `palette`'s colours, strokes `stroke_scale` times as
    /// wide as the everyday ones and body text of `text_size` points.
    const fn new(palette: &'static Palette, stroke_scale: f32, text_size: f32) -> Self {
        let p = palette;
        Self {
            palette,
            background: color(p.background),
            rod: color(p.rod),
            joint: color(p.joint),
            spring: color(p.spring),
            roller: color(p.roller),
            roller_mark: color(p.roller_mark),
            band: color(p.band),
            band_mark: color(p.band_mark),
            friction: color(p.friction),
            follower: color(p.follower),
            trail: color(p.trail),
            text: color(p.text),
            stable: color(p.stable),
            flutter: color(p.flutter),
            divergence: color(p.divergence),
            axis: color(p.axis),
            now: color(p.now),
            load_line: color(p.load_line),
            measured: color(p.measured),
            overlay: color(p.overlay),
            no_data: color(p.no_data),
            error: color(p.error),
            warning: color(p.warning),
            info: color(p.info),
            series: [
                color(p.series[0]),
                color(p.series[1]),
                color(p.series[2]),
                color(p.series[3]),
                color(p.series[4]),
                color(p.series[5]),
            ],
            curves: [
                color(p.curves[0]),
                color(p.curves[1]),
                color(p.curves[2]),
                color(p.curves[3]),
                color(p.curves[4]),
            ],
            stroke_scale,
            text_size,
        }
    }

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

    /// The ring round the control that has the keys: in the text's colour
    /// and twice as wide as the theme's strokes, so it shows on a
    /// projector too (egui's own controls and ours alike).
    #[must_use]
    pub fn focus_stroke(&self) -> egui::Stroke {
        egui::Stroke::new(2.0 * self.stroke_scale, self.text)
    }

    /// Applies the theme's visuals and text size to the context.
    pub fn apply(&self, ctx: &egui::Context) {
        let mut visuals = egui::Visuals::dark();
        visuals.panel_fill = self.background;
        visuals.override_text_color = Some(self.text);
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
