//! Text on a PNG figure, set as an SVG viewer sets it: each glyph where the
//! font places it (plotters' own rasterizer drops the glyphs' side bearings,
//! so "1952" read "1 952") and the font size as the em that the SVG gets
//! (plotters' rasterizer takes it as the line's height). Everything else is
//! the wrapped backend's.

use ab_glyph::{Font, FontRef, PxScale, ScaleFont, point};
use plotters_backend::text_anchor::{HPos, VPos};
use plotters_backend::{
    BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingBackend, DrawingErrorKind,
};

use super::FigureError;

/// plotters' font size over the em (its SVG writes `font-size` as the size
/// over this): every size given to plotters is this many ems.
pub const SIZE_PER_EM: f64 = 1.24;

/// The figures' font.
pub fn font() -> Result<FontRef<'static>, FigureError> {
    FontRef::try_from_slice(epaint_default_fonts::UBUNTU_LIGHT)
        .map_err(|e| FigureError::Draw(format!("the figures' font: {e}")))
}

/// The scale that gives `font` an em of `em_px` pixels.
fn scale(font: &FontRef<'static>, em_px: f64) -> PxScale {
    let per_em = font.units_per_em().unwrap_or(1000.0);
    #[expect(clippy::cast_possible_truncation, reason = "a font size")]
    PxScale::from((em_px * f64::from(font.height_unscaled() / per_em)) as f32)
}

/// The width and height of `text` at an em of `em_px` pixels.
pub fn text_size(font: &FontRef<'static>, em_px: f64, text: &str) -> (f64, f64) {
    let scaled = font.as_scaled(scale(font, em_px));
    let mut width = 0.0;
    let mut previous = None;
    for c in text.chars() {
        let id = scaled.glyph_id(c);
        if let Some(before) = previous {
            width += scaled.kern(before, id);
        }
        width += scaled.h_advance(id);
        previous = Some(id);
    }
    (f64::from(width), f64::from(scaled.height()))
}

/// A backend whose text is set by [`font`].
pub struct Glyphs<B> {
    pub inner: B,
    pub font: FontRef<'static>,
}

/// A size in whole pixels.
#[expect(
    clippy::cast_possible_truncation,
    clippy::cast_sign_loss,
    reason = "text sizes on a page"
)]
fn whole(v: f64) -> u32 {
    v.ceil().max(0.0) as u32
}

impl<B: DrawingBackend> DrawingBackend for Glyphs<B> {
    type ErrorType = B::ErrorType;

    fn get_size(&self) -> (u32, u32) {
        self.inner.get_size()
    }

    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.ensure_prepared()
    }

    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.present()
    }

    fn draw_pixel(
        &mut self,
        point: BackendCoord,
        color: BackendColor,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_pixel(point, color)
    }

    fn draw_line<S: BackendStyle>(
        &mut self,
        from: BackendCoord,
        to: BackendCoord,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_line(from, to, style)
    }

    fn draw_rect<S: BackendStyle>(
        &mut self,
        upper_left: BackendCoord,
        bottom_right: BackendCoord,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_rect(upper_left, bottom_right, style, fill)
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_path(path, style)
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        center: BackendCoord,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.draw_circle(center, radius, style, fill)
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        vert: I,
        style: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        self.inner.fill_polygon(vert, style)
    }

    fn estimate_text_size<S: BackendTextStyle>(
        &self,
        text: &str,
        style: &S,
    ) -> Result<(u32, u32), DrawingErrorKind<Self::ErrorType>> {
        let (width, height) = text_size(&self.font, style.size() / SIZE_PER_EM, text);
        Ok((whole(width), whole(height)))
    }

    fn draw_text<S: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &S,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let color = style.color();
        if color.alpha == 0.0 {
            return Ok(());
        }
        let font = self.font.clone();
        let em_px = style.size() / SIZE_PER_EM;
        let (width, height) = text_size(&font, em_px, text);
        #[expect(clippy::cast_possible_truncation, reason = "text sizes on a page")]
        let (width, height) = (width.round() as i32, height.round() as i32);
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -width,
            HPos::Center => -width / 2,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0,
            VPos::Center => -height / 2,
            VPos::Bottom => -height,
        };
        let transform = style.transform();
        let (w, h) = self.get_size();
        let (w, h) = (
            i32::try_from(w).unwrap_or(i32::MAX),
            i32::try_from(h).unwrap_or(i32::MAX),
        );
        let scaled = font.as_scaled(scale(&font, em_px));
        let mut caret = 0.0_f32;
        let mut previous = None;
        for c in text.chars() {
            let id = scaled.glyph_id(c);
            if let Some(before) = previous {
                caret += scaled.kern(before, id);
            }
            previous = Some(id);
            let glyph = id.with_scale_and_position(scaled.scale(), point(caret, scaled.ascent()));
            caret += scaled.h_advance(id);
            let Some(outline) = scaled.outline_glyph(glyph) else {
                continue;
            };
            let bounds = outline.px_bounds();
            let mut coverage = Vec::new();
            outline.draw(|x, y, c| coverage.push((x, y, c)));
            for (x, y, c) in coverage {
                #[expect(clippy::cast_possible_truncation, reason = "pixels on a page")]
                let (x, y) = (
                    bounds.min.x as i32 + x.cast_signed(),
                    bounds.min.y as i32 + y.cast_signed(),
                );
                let (x, y) = transform.transform(x + dx, y + dy);
                let (x, y) = (pos.0 + x, pos.1 + y);
                if (0..w).contains(&x) && (0..h).contains(&y) {
                    let ink = BackendColor {
                        alpha: color.alpha * f64::from(c),
                        rgb: color.rgb,
                    };
                    self.inner.draw_pixel((x, y), ink)?;
                }
            }
        }
        Ok(())
    }
}
