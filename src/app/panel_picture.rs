//! The open tab's plots saved as a PNG: the file chosen in the desktop's
//! dialog, then the next frame drawn as for a picture (no hints, no view
//! buttons) and the tab's area cut out of the window's screenshot.

use super::speak::Speak as _;
use crate::tr;
use std::path::PathBuf;
use std::sync::{Arc, mpsc};

use eframe::egui::{self, ColorImage};

use super::file_dialog::{Closed, FileDialog, NOT_SAVED};
use super::notice::Notice;

/// A picture of the tab asked for, on its way.
#[derive(Default)]
pub struct PanelPicture {
    dialog: FileDialog,
    /// Asked for (the file name proposed), the dialog not opened yet.
    asked: Option<String>,
    /// The file chosen: this frame is drawn for the picture.
    chosen: Option<PathBuf>,
    /// The screenshot asked for: the file, the tab's area in points, the
    /// points' size in pixels, and where the screenshot comes.
    shot: Option<(PathBuf, egui::Rect, f32, mpsc::Receiver<Arc<ColorImage>>)>,
}

impl PanelPicture {
    /// A picture of the tab `id` (one at a time).
    pub fn ask(&mut self, id: &str) {
        if !self.dialog.is_open() && self.chosen.is_none() && self.shot.is_none() {
            self.asked = Some(format!("zieglerlab-{id}.png"));
        }
    }

    /// Whether this frame is drawn for the picture: from the file's choice
    /// until the screenshot comes (the window may take it of a later frame
    /// than the one that asked).
    #[must_use]
    pub fn capturing(&self) -> bool {
        self.chosen.is_some() || self.shot.is_some()
    }

    /// At a frame's start: opens the dialog asked for, takes its answer,
    /// and writes a screenshot that has come. What to tell the user.
    pub fn frame_start(&mut self, ctx: &egui::Context) -> Option<Notice> {
        if let Some(name) = self.asked.take() {
            self.dialog
                .save_file("zieglerlab: save the plots as PNG", &name, ctx);
        }
        self.dialog
            .typed_path_ui(ctx, &tr!(ctx.words(), "save-as-what-plots"));
        match self.dialog.answer() {
            Some(Closed::Chosen(path)) => {
                self.chosen = Some(path);
                ctx.request_repaint();
            }
            Some(Closed::NoneChosen) => {
                return Some(Notice::info(tr!(ctx.words(), NOT_SAVED)));
            }
            None => {}
        }
        let (path, rect, pixels_per_point, screenshot) = self.shot.as_ref()?;
        let Ok(image) = screenshot.try_recv() else {
            ctx.request_repaint();
            return None;
        };
        let notice = match write_cut(&image, *rect, *pixels_per_point, path) {
            Ok(()) => Notice::info(crate::tr!(
                ctx.words(),
                "notice-plots-saved",
                path = path.display().to_string()
            )),
            Err(why) => Notice::error(crate::tr!(
                ctx.words(),
                "notice-plots-not-saved",
                why = why.clone()
            )),
        };
        self.shot = None;
        Some(notice)
    }

    /// At a frame's end, with the tab's area in it: the screenshot of this
    /// frame asked for when it is drawn for the picture.
    pub fn frame_end(&mut self, ctx: &egui::Context, tab_rect: egui::Rect) {
        let Some(path) = self.chosen.take() else {
            return;
        };
        let (send, screenshot) = mpsc::channel();
        ctx.request_screenshot(move |image| {
            // A window closed meanwhile has dropped the receiver.
            let _ = send.send(image);
        });
        self.shot = Some((path, tab_rect, ctx.pixels_per_point(), screenshot));
    }
}

/// The part of `image` (a screenshot, in pixels) under `rect` (in points).
#[must_use]
pub fn cut(image: &ColorImage, rect: egui::Rect, pixels_per_point: f32) -> ColorImage {
    let [width, height] = image.size;
    let pixel = |x: f32, limit: usize| {
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "clamped to the image"
        )]
        let p = (x * pixels_per_point).round().max(0.0) as usize;
        p.min(limit)
    };
    let (x0, x1) = (pixel(rect.left(), width), pixel(rect.right(), width));
    let (y0, y1) = (pixel(rect.top(), height), pixel(rect.bottom(), height));
    let mut out = ColorImage::filled([x1 - x0.min(x1), y1 - y0.min(y1)], egui::Color32::BLACK);
    for y in y0..y1 {
        let row = &image.pixels[y * width + x0..y * width + x1];
        out.pixels[(y - y0) * (x1 - x0)..(y - y0 + 1) * (x1 - x0)].copy_from_slice(row);
    }
    out
}

/// The cut of `image` under `rect` as a PNG file at `path`.
fn write_cut(
    image: &ColorImage,
    rect: egui::Rect,
    pixels_per_point: f32,
    path: &std::path::Path,
) -> Result<(), String> {
    let part = cut(image, rect, pixels_per_point);
    let [width, height] = part.size;
    let bytes: Vec<u8> = part
        .pixels
        .iter()
        .flat_map(egui::Color32::to_array)
        .collect();
    let (Ok(width), Ok(height)) = (u32::try_from(width), u32::try_from(height)) else {
        return Err("the picture is too large".to_owned());
    };
    let picture = image::RgbaImage::from_raw(width, height, bytes)
        .ok_or_else(|| "the screenshot has no pixels there".to_owned())?;
    crate::files::write_png(path, &picture).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cut is the screenshot's pixels under the rectangle, in pixels of
    /// a screen with 2 pixels per point, clamped to the image.
    #[test]
    fn the_cut_is_the_pixels_under_the_area() {
        let mut image = ColorImage::filled([8, 6], egui::Color32::BLACK);
        for y in 0..6 {
            for x in 0..8 {
                image.pixels[y * 8 + x] =
                    egui::Color32::from_rgb(u8::try_from(x).unwrap(), u8::try_from(y).unwrap(), 0);
            }
        }
        let rect = egui::Rect::from_min_max(egui::pos2(1.0, 1.0), egui::pos2(3.0, 2.5));
        let part = cut(&image, rect, 2.0);
        assert_eq!(part.size, [4, 3]);
        assert_eq!(part.pixels[0], egui::Color32::from_rgb(2, 2, 0));
        assert_eq!(part.pixels[4 * 3 - 1], egui::Color32::from_rgb(5, 4, 0));
        let beyond = egui::Rect::from_min_max(egui::pos2(2.0, 2.0), egui::pos2(100.0, 100.0));
        assert_eq!(cut(&image, beyond, 2.0).size, [4, 2]);
        let folder = tempfile::tempdir().unwrap();
        let path = folder.path().join("plots.png");
        write_cut(&image, rect, 2.0, &path).unwrap();
        let read = image::open(&path).unwrap().to_rgba8();
        assert_eq!(read.dimensions(), (4, 3));
        assert_eq!(read.get_pixel(0, 0).0, [2, 2, 0, 255]);
    }
}
