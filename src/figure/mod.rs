//! Figures for a paper: any plot's [`Sheet`] (the root locus, Re and Im of
//! the eigenvalues against the load, the stability map, the paradox curves,
//! the limit cycles' bifurcation diagram) drawn with plotters at a
//! journal's size and font size, as SVG (vector) or PNG. What a figure
//! shows is decided by the sheet's builder in [`crate::plot`]; this module
//! lays out the page, styles each ink and sets the text.

mod clip;
mod glyphs;
mod layout;
mod plots;
mod style;

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::plot::spec::Sheet;
pub use style::Page;

/// The file format, from the output's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Svg,
    Png,
}

impl Format {
    /// The format named by `path`'s extension (`.svg` or `.png`, any case).
    #[must_use]
    pub fn of(path: &std::path::Path) -> Option<Self> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        match extension.as_str() {
            "svg" => Some(Self::Svg),
            "png" => Some(Self::Png),
            _ => None,
        }
    }
}

/// One plot of a figure: its data ranges and where they were drawn, in the
/// figure's units (SVG user units or PNG pixels), to map data to the page.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
    /// Left, right (x) and top, bottom (y) edges of the plotting area.
    pub x_px: (i32, i32),
    pub y_px: (i32, i32),
}

impl Panel {
    /// Where the data point `(x, y)` lies on the page.
    #[must_use]
    pub fn page_point(&self, x: f64, y: f64) -> (f64, f64) {
        let fraction = |v: f64, (lo, hi): (f64, f64)| (v - lo) / (hi - lo);
        let (left, right) = (f64::from(self.x_px.0), f64::from(self.x_px.1));
        let (top, bottom) = (f64::from(self.y_px.0), f64::from(self.y_px.1));
        (
            left + fraction(x, self.x_range) * (right - left),
            bottom - fraction(y, self.y_range) * (bottom - top),
        )
    }
}

/// A drawn figure: the file's bytes and its plots.
#[derive(Clone, Debug)]
pub struct Rendered {
    pub bytes: Vec<u8>,
    pub panels: Vec<Panel>,
    /// Said beside the figure: what the view leaves out, if anything.
    pub notes: Vec<String>,
}

/// Why no figure was drawn.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FigureError {
    #[error("{0}")]
    Page(String),
    #[error("nothing to draw: {0}")]
    Empty(String),
    #[error("drawing failed: {0}")]
    Draw(String),
}

/// A drawing step's error as a [`FigureError`].
fn drawing<T, E: std::fmt::Display>(result: Result<T, E>) -> Result<T, FigureError> {
    result.map_err(|e| FigureError::Draw(e.to_string()))
}

/// What a drawing of a sheet gives back.
pub(crate) struct Drawn {
    panels: Vec<Panel>,
    notes: Vec<String>,
}

/// `sheet` drawn on `page` as `format`: its legend at the top, its plots
/// stacked below, each as tall as the others.
///
/// # Errors
/// A page that cannot be drawn, or the drawing failing.
pub fn render(sheet: &Sheet, page: &Page, format: Format) -> Result<Rendered, FigureError> {
    style::register_fonts();
    let ink = page.ink(format)?;
    let (width, height) = ink.size_px;
    match format {
        Format::Svg => {
            let mut svg = String::new();
            let drawn = {
                let root = SVGBackend::with_string(&mut svg, (width, height)).into_drawing_area();
                let drawn = draw(&root, sheet, &ink)?;
                drawing(root.present())?;
                drawn
            };
            Ok(Rendered {
                bytes: physical_size(&svg, page).into_bytes(),
                panels: drawn.panels,
                notes: drawn.notes,
            })
        }
        Format::Png => {
            let mut rgb = vec![0u8; width as usize * height as usize * 3];
            let drawn = {
                let root = glyphs::Glyphs {
                    inner: BitMapBackend::with_buffer(&mut rgb, (width, height)),
                    font: glyphs::font()?,
                }
                .into_drawing_area();
                let drawn = draw(&root, sheet, &ink)?;
                drawing(root.present())?;
                drawn
            };
            let image = image::RgbImage::from_raw(width, height, rgb)
                .ok_or_else(|| FigureError::Draw("the picture has the wrong size".to_owned()))?;
            let mut bytes = Vec::new();
            drawing(image.write_to(
                &mut std::io::Cursor::new(&mut bytes),
                image::ImageFormat::Png,
            ))?;
            Ok(Rendered {
                bytes,
                panels: drawn.panels,
                notes: drawn.notes,
            })
        }
    }
}

/// Draws `sheet` on `root`, a white page.
fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    sheet: &Sheet,
    ink: &style::Ink,
) -> Result<Drawn, FigureError>
where
    DB::ErrorType: 'static,
{
    drawing(root.fill(&WHITE))?;
    plots::draw(root, &sheet.legend, &sheet.plots, ink)
}

/// The SVG with its page size in millimetres (plotters writes its units),
/// so that a journal's page takes it at the size asked for.
fn physical_size(svg: &str, page: &Page) -> String {
    let Some(start) = svg.find("<svg") else {
        return svg.to_owned();
    };
    let Some(width_at) = svg[start..].find("width=\"").map(|i| start + i) else {
        return svg.to_owned();
    };
    let Some(view_box_at) = svg[width_at..].find("viewBox=").map(|i| width_at + i) else {
        return svg.to_owned();
    };
    format!(
        "{}width=\"{}mm\" height=\"{}mm\" {}",
        &svg[..width_at],
        crate::format::number_text(page.width_mm),
        crate::format::number_text(page.height_mm),
        &svg[view_box_at..]
    )
}
