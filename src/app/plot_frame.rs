//! What every plot of the app shares: axes whose tick labels stay readable
//! at any size, and the view control of a tab (a "fit" button, how to zoom
//! and pan, and a refit when what the plots show changes).

use eframe::egui::{self, Color32, Sense, Stroke, WidgetText, vec2};
use egui_plot::{AxisHints, GridInput, Plot, uniform_grid_spacer};

use crate::format::tick_text;

/// The gap between x tick labels, in points, below which they are hidden
/// and above which they are fully drawn (the plot crate's default, 60 to 80,
/// leaves a 300-point load axis with the single label "0").
const X_LABEL_SPACING: std::ops::RangeInclusive<f32> = 30.0..=45.0;
/// The same for y tick labels (the default, 20 to 30, stacks them densely).
const Y_LABEL_SPACING: std::ops::RangeInclusive<f32> = 28.0..=40.0;

/// The gap between grid lines, in points, below which they are hidden and
/// above which they are fully drawn (the plot crate's default starts at 8:
/// a line every 8 points is texture, not a scale, and costs a frame time).
const GRID_SPACING: std::ops::RangeInclusive<f32> = 16.0..=300.0;

/// How to move about in a plot (the plot crate's bindings).
pub const VIEW_HINT: &str = "drag: pan · Ctrl+scroll: zoom · double-click: fit";

/// The rest of the bindings, in the fit button's tooltip.
const VIEW_HINT_MORE: &str = "Show all the data again (as a double-click on a plot does).\n\
     Drag or scroll to pan, Ctrl+scroll to zoom, drag a box with the right button to zoom into it.";

/// The grid's three levels: the smallest step of 1, 2 or 5 times a power of
/// ten at least `input`'s minimum, and two coarser steps that it divides
/// (1-5-10, 2-10-20, 5-10-50), so the labels of two levels never collide.
/// The plot crate's default has only powers of ten, so a short axis
/// spanning 1.8 showed the single tick "0".
#[must_use]
#[expect(
    clippy::needless_pass_by_value,
    reason = "the signature the plot crate's grid spacer calls"
)]
pub fn nice_steps(input: GridInput) -> [f64; 3] {
    let base = input.base_step_size.max(f64::MIN_POSITIVE);
    let mut decade = 10f64.powf(base.log10().floor());
    let mantissa = [1_u8, 2, 5, 10]
        .into_iter()
        .find(|&m| f64::from(m) * decade >= base)
        .unwrap_or(10);
    if mantissa == 10 {
        decade *= 10.0;
    }
    match mantissa {
        2 => [2.0 * decade, 10.0 * decade, 20.0 * decade],
        5 => [5.0 * decade, 10.0 * decade, 50.0 * decade],
        _ => [decade, 5.0 * decade, 10.0 * decade],
    }
}

/// `plot` with labelled axes on a 1-2-5 grid (see [`nice_steps`]) whose ticks carry the digits
/// their spacing needs ("0.25", "8e-8") and are labelled whenever they fit.
pub fn axes(
    plot: Plot<'_>,
    x_label: impl Into<WidgetText>,
    y_label: impl Into<WidgetText>,
) -> Plot<'_> {
    plot.grid_spacing(GRID_SPACING)
        .x_grid_spacer(uniform_grid_spacer(nice_steps))
        .y_grid_spacer(uniform_grid_spacer(nice_steps))
        .custom_x_axes(vec![
            AxisHints::new_x()
                .label(x_label)
                .formatter(|mark, _| tick_text(mark.value, mark.step_size))
                .label_spacing(X_LABEL_SPACING),
        ])
        .custom_y_axes(vec![
            AxisHints::new_y()
                .label(y_label)
                .formatter(|mark, _| tick_text(mark.value, mark.step_size))
                .label_spacing(Y_LABEL_SPACING),
        ])
}

/// How a legend entry is drawn.
pub enum Swatch {
    /// A filled dot (a marker).
    Dot(Color32),
    /// A ring (an open marker).
    Ring(Color32),
    /// A short line (a curve).
    Line(Color32),
    /// A colour scale: the colours from one end to the other.
    Scale(Vec<Color32>),
}

/// A legend as a row of text above the plots, so that it never covers data.
pub fn legend_row(ui: &mut egui::Ui, entries: &[(Swatch, String)]) {
    ui.horizontal_wrapped(|ui| {
        for (swatch, text) in entries {
            let width = if matches!(swatch, Swatch::Scale(_)) {
                48.0
            } else {
                16.0
            };
            let (rect, _) = ui.allocate_exact_size(vec2(width, 12.0), Sense::hover());
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
            ui.add_space(8.0);
        }
    });
}

/// When a tab's plots go back to their default view: when the button is
/// pressed, and when what they show (`T`: the parameters, the axes) changes.
pub struct Fit<T> {
    shown: Option<T>,
    asked: bool,
}

impl<T> Default for Fit<T> {
    fn default() -> Self {
        Self {
            shown: None,
            asked: false,
        }
    }
}

impl<T: PartialEq> Fit<T> {
    /// The row above the plots: the "fit" button and the hint.
    pub fn bar_ui(&mut self, ui: &mut egui::Ui) {
        ui.horizontal(|ui| {
            self.asked |= ui
                .small_button("fit")
                .on_hover_text(VIEW_HINT_MORE)
                .clicked();
            ui.weak(VIEW_HINT);
        });
    }

    /// Whether the plots refit this frame, now that they show `shown`.
    pub fn refit(&mut self, shown: T) -> bool {
        let changed = self.shown.as_ref() != Some(&shown);
        self.shown = Some(shown);
        std::mem::take(&mut self.asked) || changed
    }
}

/// `plot`, reset to its default view when `refit`.
#[must_use]
pub fn refit_if(plot: Plot<'_>, refit: bool) -> Plot<'_> {
    if refit { plot.reset() } else { plot }
}

/// A click's action held until it is known not to be the first half of a
/// double-click: a double-click fits the view and does nothing else.
pub struct SingleClick<T> {
    pending: Option<(f64, T)>,
}

impl<T> Default for SingleClick<T> {
    fn default() -> Self {
        Self { pending: None }
    }
}

impl<T> SingleClick<T> {
    /// One frame at `now_secs`: `click`, a click's action this frame;
    /// `double`, whether this frame completed a double-click. Returns the
    /// action of a click no second click followed within `window_secs`.
    pub fn update(
        &mut self,
        click: Option<T>,
        double: bool,
        now_secs: f64,
        window_secs: f64,
    ) -> Option<T> {
        if double {
            self.pending = None;
        } else if let Some(action) = click {
            self.pending = Some((now_secs, action));
        }
        match &self.pending {
            Some((at, _)) if now_secs - at > window_secs => self.pending.take().map(|(_, a)| a),
            _ => None,
        }
    }

    /// Whether a click waits for its window to pass.
    #[must_use]
    pub fn waiting(&self) -> bool {
        self.pending.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_click_acts_after_the_double_click_window_and_a_double_click_never() {
        let mut click = SingleClick::default();
        assert_eq!(click.update(Some(1), false, 0.0, 0.3), None, "not yet");
        assert!(click.waiting());
        assert_eq!(click.update(None, false, 0.2, 0.3), None);
        assert_eq!(
            click.update(None, false, 0.31, 0.3),
            Some(1),
            "no second click"
        );
        assert!(!click.waiting());
        assert_eq!(click.update(None, false, 1.0, 0.3), None, "once");
        // A double-click: its first click is dropped, and so is its second.
        assert_eq!(click.update(Some(2), false, 2.0, 0.3), None);
        assert_eq!(click.update(Some(3), true, 2.1, 0.3), None);
        assert_eq!(click.update(None, false, 3.0, 0.3), None);
    }

    #[test]
    fn grid_steps_are_one_two_five_times_a_power_of_ten() {
        let steps = |base_step_size| {
            nice_steps(GridInput {
                bounds: (0.0, 1.0),
                base_step_size,
            })
        };
        let close =
            |a: [f64; 3], b: [f64; 3]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9 * y);
        for (base, expected) in [
            (0.06, [0.1, 0.5, 1.0]),
            (0.15, [0.2, 1.0, 2.0]),
            (0.3, [0.5, 1.0, 5.0]),
            (1.0, [1.0, 5.0, 10.0]),
            (7e-9, [1e-8, 5e-8, 1e-7]),
        ] {
            let got = steps(base);
            assert!(close(got, expected), "{base}: {got:?}");
            // Each level divides the next: labels of two levels never collide.
            for pair in got.windows(2) {
                let ratio = pair[1] / pair[0];
                assert!((ratio - ratio.round()).abs() < 1e-9, "{got:?}");
            }
        }
    }

    #[test]
    fn plots_refit_when_asked_or_when_what_they_show_changes() {
        let mut fit = Fit::default();
        assert!(fit.refit(1), "the first frame fits");
        assert!(!fit.refit(1), "the same data keeps the user's view");
        assert!(fit.refit(2), "new data fits");
        fit.asked = true;
        assert!(fit.refit(2), "the button fits");
        assert!(!fit.refit(2), "once");
    }
}
