//! The page a figure is drawn on (its size in millimetres, its font size in
//! points, a PNG's dots per inch), the strokes and fonts in the page's units,
//! and the palette's paper colours.

use plotters::style::{FontStyle, RGBColor, ShapeStyle, TextStyle};

use super::{FigureError, Format};
use crate::analysis::State;
use crate::plot::{Palette, Rgb};

/// Millimetres per inch.
const MM_PER_INCH: f64 = 25.4;
/// Points per inch.
const PT_PER_INCH: f64 = 72.0;
/// SVG user units per point: fine enough for whole-unit coordinates
/// (0.09 mm), and a stroke of 2 units is a hairline of 0.5 pt.
const SVG_UNITS_PER_PT: f64 = 4.0;
/// The most pixels a PNG figure may have (three bytes each in memory).
const MAX_PNG_PIXELS: f64 = 64.0e6;
/// The font every figure uses: egui's own, so the window and the figures
/// read alike, and nothing is looked for on the system.
const FONT: &str = "sans-serif";

/// The size of a figure: what a journal asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Page {
    pub width_mm: f64,
    pub height_mm: f64,
    pub font_pt: f64,
    /// Dots per inch of a PNG (an SVG has no pixels).
    pub dpi: f64,
}

impl Default for Page {
    /// A journal's column: 85 mm wide, 68 mm high, 8 pt text, 300 dpi.
    fn default() -> Self {
        Self {
            width_mm: 85.0,
            height_mm: 68.0,
            font_pt: 8.0,
            dpi: 300.0,
        }
    }
}

impl Page {
    pub const WIDTH_MM: (f64, f64) = (30.0, 500.0);
    pub const FONT_PT: (f64, f64) = (5.0, 24.0);
    pub const DPI: (f64, f64) = (50.0, 1200.0);

    /// Whether this page can be drawn as `format`.
    ///
    /// # Errors
    /// As [`Self::ink`].
    pub fn check(&self, format: Format) -> Result<(), FigureError> {
        self.ink(format).map(|_| ())
    }

    /// The strokes and fonts of this page drawn as `format`.
    ///
    /// # Errors
    /// A size, font size or resolution out of range, or a PNG too large.
    pub(super) fn ink(&self, format: Format) -> Result<Ink, FigureError> {
        let within = |what: &str, value: f64, (lo, hi): (f64, f64)| {
            if value.is_finite() && (lo..=hi).contains(&value) {
                Ok(())
            } else {
                Err(FigureError::Page(format!(
                    "{what} = {}: must be {lo} to {hi}",
                    crate::format::Shown(value)
                )))
            }
        };
        within("width-mm", self.width_mm, Self::WIDTH_MM)?;
        within("height-mm", self.height_mm, Self::WIDTH_MM)?;
        within("font-pt", self.font_pt, Self::FONT_PT)?;
        let per_pt = match format {
            Format::Svg => SVG_UNITS_PER_PT,
            Format::Png => {
                within("dpi", self.dpi, Self::DPI)?;
                self.dpi / PT_PER_INCH
            }
        };
        let to_units = |mm: f64| mm / MM_PER_INCH * PT_PER_INCH * per_pt;
        let (width, height) = (to_units(self.width_mm), to_units(self.height_mm));
        if format == Format::Png && width * height > MAX_PNG_PIXELS {
            let largest = (MAX_PNG_PIXELS / (width * height)).sqrt() * self.dpi;
            return Err(FigureError::Page(format!(
                "a {} x {} mm PNG at {} dpi has {:.0} million pixels, more than the {:.0} million a figure may have: use --dpi {} or less, or an SVG",
                self.width_mm,
                self.height_mm,
                self.dpi,
                width * height / 1e6,
                MAX_PNG_PIXELS / 1e6,
                largest.floor()
            )));
        }
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "checked ranges: at most a few ten thousand units"
        )]
        let size_px = (width.round() as u32, height.round() as u32);
        Ok(Ink {
            per_pt,
            font_pt: self.font_pt,
            size_px,
        })
    }
}

/// Strokes and fonts in the units of one drawing.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ink {
    per_pt: f64,
    font_pt: f64,
    pub size_px: (u32, u32),
}

impl Ink {
    /// A length of `pt` points in the drawing's units.
    #[expect(clippy::cast_possible_truncation, reason = "lengths on a page")]
    pub fn units(&self, pt: f64) -> i32 {
        (pt * self.per_pt).round() as i32
    }

    /// A line of `pt` points, at least one unit wide.
    pub fn stroke(&self, color: RGBColor, pt: f64) -> ShapeStyle {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a positive width on a page"
        )]
        let width = (pt * self.per_pt).round().max(1.0) as u32;
        ShapeStyle {
            color: color.into(),
            filled: false,
            stroke_width: width,
        }
    }

    /// The text of the page, `scale` times its font size (an em of that
    /// many points, in plotters' measure of size).
    pub fn text(&self, scale: f64) -> TextStyle<'static> {
        let em = self.font_pt * scale * self.per_pt;
        TextStyle::from((FONT, em * super::glyphs::SIZE_PER_EM, FontStyle::Normal))
    }

    /// The font size in the drawing's units.
    pub fn font_units(&self) -> i32 {
        self.units(self.font_pt)
    }

    /// The font size in points.
    pub fn font_pt(&self) -> f64 {
        self.font_pt
    }

    /// `units` of the drawing in millimetres on the page.
    pub fn mm(&self, units: f64) -> f64 {
        units / self.per_pt / PT_PER_INCH * MM_PER_INCH
    }
}

/// Registers the figures' font once (plotters looks fonts up by name).
pub(super) fn register_fonts() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        // The font is built in and known to parse; a failure would only
        // leave the text out, which the figure tests would see.
        let _ = plotters::style::register_font(
            FONT,
            FontStyle::Normal,
            epaint_default_fonts::UBUNTU_LIGHT,
        );
    });
}

/// A palette colour as plotters takes it.
pub(super) const fn rgb(color: Rgb) -> RGBColor {
    RGBColor(color.0, color.1, color.2)
}

/// The paper's ink: the text, the axes and the main model's curves.
pub(super) const INK: RGBColor = rgb(Palette::PAPER.text);

/// The colour of a state on paper.
pub(super) fn state_color(state: State) -> RGBColor {
    rgb(Palette::PAPER.state(state))
}

/// `color` as a pale tint: mixed with white, `strength` in [0, 1] of it.
pub(super) fn tint(color: RGBColor, strength: f64) -> RGBColor {
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a mix of two bytes"
    )]
    let mix = |c: u8| (255.0 - (255.0 - f64::from(c)) * strength.clamp(0.0, 1.0)).round() as u8;
    RGBColor(mix(color.0), mix(color.1), mix(color.2))
}
