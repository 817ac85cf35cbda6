//! A legend as a row of text above the plots, so that it never covers
//! data: each entry a swatch (a dot, a ring, a line, a dashed line, a
//! tinted box, a colour scale) and its words, wrapped to the panel.

use eframe::egui::{self, Color32, Sense, Stroke, vec2};

/// The space between two entries of a legend row, in points.
const ENTRY_GAP: f32 = 8.0;

/// How a legend entry is drawn.
pub enum Swatch {
    /// A filled dot (a marker).
    Dot(Color32),
    /// A ring (an open marker).
    Ring(Color32),
    /// A short line (a curve).
    Line(Color32),
    /// A short dashed line.
    Dashed(Color32),
    /// A tinted box (a range).
    Fill(Color32),
    /// A colour scale: the colours from one end to the other.
    Scale(Vec<Color32>),
}

/// A legend as a row of text above the plots, so that it never covers data.
pub fn legend_row(ui: &mut egui::Ui, entries: &[(Swatch, String)]) {
    ui.horizontal_wrapped(|ui| {
        for (k, (swatch, text)) in entries.iter().enumerate() {
            let width = if matches!(swatch, Swatch::Scale(_)) {
                48.0
            } else {
                16.0
            };
            // The gap between entries before each swatch, so that it wraps
            // with it: after the last label it ran past the panel's edge,
            // and widened every plot under the row by as much.
            let mut gap = if k == 0 { 0.0 } else { ENTRY_GAP };
            // A swatch starts a new row where its words' first would not
            // follow it on this one (a long entry's swatch was left at
            // the end of a row, its words below).
            let first_word = text.split_whitespace().next().unwrap_or_default();
            let font = egui::TextStyle::Body.resolve(ui.style());
            let word_width = ui
                .painter()
                .layout_no_wrap(first_word.to_owned(), font, Color32::WHITE)
                .size()
                .x;
            // (With a spacing's room to spare: a word that fitted to the
            // pixel was still wrapped.)
            let needed = gap + width + 2.0 * ui.spacing().item_spacing.x + word_width;
            if k > 0 && ui.available_size_before_wrap().x < needed {
                ui.end_row();
                gap = 0.0;
            }
            let (cell, _) = ui.allocate_exact_size(vec2(gap + width, 12.0), Sense::hover());
            let rect = egui::Rect::from_min_max(cell.min + vec2(gap, 0.0), cell.max);
            let painter = ui.painter();
            let (center, radius) = (rect.center(), 4.5);
            match swatch {
                Swatch::Dot(color) => {
                    painter.circle_filled(center, radius, *color);
                }
                Swatch::Ring(color) => {
                    painter.circle_stroke(center, radius, Stroke::new(1.5, *color));
                }
                Swatch::Line(color) => {
                    painter.line_segment(
                        [rect.left_center(), rect.right_center()],
                        Stroke::new(2.0, *color),
                    );
                }
                Swatch::Dashed(color) => {
                    let dash = rect.width() / 5.0;
                    for k in [0.0, 2.0, 4.0] {
                        let x = rect.left() + k * dash;
                        painter.line_segment(
                            [
                                egui::pos2(x, rect.center().y),
                                egui::pos2(x + dash, rect.center().y),
                            ],
                            Stroke::new(2.0, *color),
                        );
                    }
                }
                Swatch::Fill(color) => {
                    painter.rect_filled(rect.shrink2(vec2(0.0, 3.0)), 0.0, *color);
                }
                Swatch::Scale(colors) => {
                    #[expect(clippy::cast_precision_loss, reason = "a few colours")]
                    let step = rect.width() / colors.len().max(1) as f32;
                    for (i, color) in colors.iter().enumerate() {
                        #[expect(clippy::cast_precision_loss, reason = "a few colours")]
                        let x = rect.left() + step * i as f32;
                        let cell = egui::Rect::from_min_size(
                            egui::pos2(x, rect.top() + 3.0),
                            vec2(step + 0.5, rect.height() - 6.0),
                        );
                        painter.rect_filled(cell, 0.0, *color);
                    }
                }
            }
            ui.label(text);
        }
    });
}
