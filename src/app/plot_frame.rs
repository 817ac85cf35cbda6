//! What every plot of the app shares: axes whose tick labels stay readable
//! at any size, curves drawn through the fewest points the screen resolves
//! (Ramer-Douglas-Peucker in the view's pixels, once the view has settled),
//! and the view control of a tab (a "fit" button, how to zoom and pan, and
//! a refit when what the plots show changes).

use super::speak::Speak as _;
use crate::tr;
use eframe::egui::{self, WidgetText};
use egui_plot::{
    AxisHints, GridInput, GridMark, Line, Plot, PlotBounds, PlotPoint, PlotPoints, PlotResponse,
    PlotUi,
};

use crate::format::tick_text;

/// The gap between x tick labels, in points, below which they are hidden
/// and above which they are fully drawn (the plot crate's default, 60 to 80,
/// leaves a 300-point load axis with the single label "0").
const X_LABEL_SPACING: std::ops::RangeInclusive<f32> = 30.0..=45.0;
/// The same for y tick labels (text is less tall than wide).
const Y_LABEL_SPACING: std::ops::RangeInclusive<f32> = 22.0..=30.0;

/// The gap between grid lines, in points, below which they are hidden and
/// above which they are fully drawn (the plot crate's default starts at 8:
/// a line every 8 points is texture, not a scale, and costs a frame time).
const GRID_SPACING: std::ops::RangeInclusive<f32> = 16.0..=300.0;

/// A curve is drawn through a subset of its points that stays within this
/// distance on screen of every point left out (a tenth of the thinnest
/// line's width, far below what an eye resolves): a smooth branch a few
/// hundred pixels long then costs tens of segments, not hundreds, which a
/// CPU renderer pays for on every frame.
pub const CURVE_TOLERANCE_PX: f32 = 0.15;

/// What [`view_settled`] remembers of a plot's view between frames.
#[derive(Clone, Copy, PartialEq)]
struct SeenView {
    frame: egui::Rect,
    bounds: PlotBounds,
}

/// Whether `plot_ui`'s transform, which is the last frame's, is also the
/// one this frame is drawn with: the view is not `refit` now, the plot has
/// the same size, the view did not change between the last two frames, and
/// no pointer event reached the plot (a drag or a scroll moves the view
/// after the curves are handed over). Call it once per plot and frame.
pub fn view_settled(plot_ui: &PlotUi<'_>, refit: bool) -> bool {
    let transform = plot_ui.transform();
    let response = plot_ui.response();
    let seen = SeenView {
        frame: *transform.frame(),
        bounds: *transform.bounds(),
    };
    let id = response.id.with("view seen");
    let ctx = plot_ui.ctx();
    let before = ctx.data_mut(|data| {
        let before = data.get_temp::<SeenView>(id);
        data.insert_temp(id, seen);
        before
    });
    let touched = response.contains_pointer() && ctx.input(|input| !input.events.is_empty());
    !refit && !touched && response.rect == seen.frame && before == Some(seen)
}

/// A curve through `points` as drawn in `plot_ui`'s current view: through
/// a subset of them (Ramer-Douglas-Peucker) so that no point left out lies
/// farther than [`CURVE_TOLERANCE_PX`] from the polyline drawn. In pixels of
/// the view in use: zooming in brings the detail back. `settled` is
/// [`view_settled`]'s answer for the plot.
///
/// Drawn as a stroked line, not as the plot crate's bands (which merge the
/// points within a pixel column into a vertical band): a simplified curve
/// has long segments, and a band at a branch point's dense samples, whose
/// width is interpolated to the next point, drew a wedge along the whole
/// segment before it.
pub fn curve(
    plot_ui: &PlotUi<'_>,
    settled: bool,
    points: impl IntoIterator<Item = [f64; 2]>,
) -> Line<'static> {
    Line::new("", thinned(plot_ui, settled, points)).allow_band(false)
}

/// The points of [`curve`].
fn thinned(
    plot_ui: &PlotUi<'_>,
    settled: bool,
    points: impl IntoIterator<Item = [f64; 2]>,
) -> PlotPoints<'static> {
    let tolerance_pt = CURVE_TOLERANCE_PX / plot_ui.ctx().pixels_per_point();
    let transform = plot_ui.transform();
    let points: Vec<[f64; 2]> = points.into_iter().collect();
    let screen: Vec<egui::Pos2> = points
        .iter()
        .map(|&[x, y]| transform.position_from_point(&PlotPoint::new(x, y)))
        .collect();
    let mut keep = simplified(&screen, tolerance_pt);
    // While the view changes, the plot's transform may belong to other
    // bounds, and a tolerance in its pixels may be far too coarse (it drew
    // chords beside the curves near branch points). The curve then also
    // keeps what a fine canvas of its own extent needs, so it is never
    // coarser than that; a settled view (every frame of a running column)
    // pays only for its own pixels.
    if !settled {
        let canvas = on_canvas(&points);
        for (keep, fine) in keep.iter_mut().zip(simplified(&canvas, CURVE_TOLERANCE_PX)) {
            *keep |= fine;
        }
    }
    PlotPoints::from(
        points
            .into_iter()
            .zip(keep)
            .filter_map(|(point, keep)| keep.then_some(point))
            .collect::<Vec<_>>(),
    )
}

/// The side of the canvas [`thinned`] also simplifies on, in pixels: finer
/// than any plot's.
const CANVAS_PX: f64 = 4000.0;

/// `points` on a square canvas of [`CANVAS_PX`] that their own extent fills.
fn on_canvas(points: &[[f64; 2]]) -> Vec<egui::Pos2> {
    let finite = points
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in finite {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let scale = |k: usize| {
        let range = hi[k] - lo[k];
        if range > 0.0 { CANVAS_PX / range } else { 0.0 }
    };
    let (sx, sy) = (scale(0), scale(1));
    #[expect(clippy::cast_possible_truncation, reason = "canvas pixels")]
    points
        .iter()
        .map(|p| egui::pos2(((p[0] - lo[0]) * sx) as f32, ((p[1] - lo[1]) * sy) as f32))
        .collect()
}

/// Which points of the polyline `points` to keep so that every other one
/// lies within `tolerance` of the kept polyline (Ramer-Douglas-Peucker; the
/// ends are always kept, and a point that is not finite splits the curve).
#[must_use]
pub fn simplified(points: &[egui::Pos2], tolerance: f32) -> Vec<bool> {
    let mut keep = vec![false; points.len()];
    let finite = |p: &egui::Pos2| p.x.is_finite() && p.y.is_finite();
    let mut start = 0;
    while start < points.len() {
        if !finite(&points[start]) {
            start += 1;
            continue;
        }
        let end = (start..points.len())
            .find(|&i| !finite(&points[i]))
            .unwrap_or(points.len());
        keep[start] = true;
        keep[end - 1] = true;
        let mut stack = vec![(start, end - 1)];
        while let Some((a, b)) = stack.pop() {
            if b <= a + 1 {
                continue;
            }
            let (pa, pb) = (points[a], points[b]);
            let farthest = (a + 1..b)
                .map(|i| (i, distance_to_segment(points[i], pa, pb)))
                .max_by(|x, y| x.1.total_cmp(&y.1));
            if let Some((i, distance)) = farthest
                && distance > tolerance
            {
                keep[i] = true;
                stack.push((a, i));
                stack.push((i, b));
            }
        }
        start = end;
    }
    keep
}

/// The distance from `p` to the segment from `a` to `b`.
fn distance_to_segment(p: egui::Pos2, a: egui::Pos2, b: egui::Pos2) -> f32 {
    let ab = b - a;
    let length_sq = ab.length_sq();
    let t = if length_sq > 0.0 {
        ((p - a).dot(ab) / length_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a + t * ab)
}

/// How to move about in a plot (the plot crate's bindings): its message,
/// with the rest of the bindings in `.more` (the fit button's tooltip).
pub const VIEW_HINT: &str = "view-hint";

/// The grid's steps, finest first: 1, 5, 10, 50 and 100 times the power of
/// ten just below `base_step` (the plot crate's minimum). Each divides the
/// next, so the labels of two levels never collide, and some level is
/// always 5 to 50 times the minimum: a short axis gets labelled ticks (the
/// plot crate's default has only three powers of ten, and an axis spanning
/// 1.8 showed the single tick "0").
#[must_use]
pub fn grid_steps(base_step: f64) -> [f64; 5] {
    let decade = 10f64.powf(base_step.max(f64::MIN_POSITIVE).log10().floor());
    [1.0, 5.0, 10.0, 50.0, 100.0].map(|m| m * decade)
}

/// The smallest of 1 or 5 times a power of ten at or above `value` (a
/// step of [`grid_steps`]): a symmetric plot this high on each side has a
/// labelled tick at its edges, where a short plot of small swings (0.03
/// rad) otherwise had the single tick "0".
#[must_use]
pub fn grid_ceil(value: f64) -> f64 {
    if !(value.is_finite() && value > 0.0) {
        return 1.0;
    }
    let decade = 10f64.powf(value.log10().floor());
    [1.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&step| step >= value * (1.0 - 1e-12))
        .unwrap_or(10.0 * decade)
}

/// The grid marks of `input`'s range: every multiple of each of
/// [`grid_steps`], each value once, with the coarsest step it is on (which
/// sets how strong its line and label are drawn).
#[expect(
    clippy::needless_pass_by_value,
    reason = "the signature the plot crate's grid spacer calls"
)]
fn grid_marks(input: GridInput) -> Vec<GridMark> {
    let steps = grid_steps(input.base_step_size);
    let (lo, hi) = input.bounds;
    let mut marks = Vec::new();
    for (level, &step) in steps.iter().enumerate() {
        // A multiple of the next step is that step's mark, not this one's.
        let ratio = steps.get(level + 1).map(|next| (next / step).round());
        #[expect(clippy::cast_possible_truncation, reason = "tick indices of one plot")]
        let (first, last) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
        for i in first..=last {
            #[expect(clippy::cast_precision_loss, reason = "tick indices of one plot")]
            let index = i as f64;
            if ratio.is_some_and(|r| index.rem_euclid(r) == 0.0) {
                continue;
            }
            marks.push(GridMark {
                value: index * step,
                step_size: step,
            });
        }
    }
    marks
}

/// `plot` with labelled axes on a 1-2-5 grid (see [`grid_steps`]) whose ticks carry the digits
/// their spacing needs ("0.25", "8e-8") and are labelled whenever they fit.
pub fn axes(
    plot: Plot<'_>,
    x_label: impl Into<WidgetText>,
    y_label: impl Into<WidgetText>,
) -> Plot<'_> {
    plot.grid_spacing(GRID_SPACING)
        .x_grid_spacer(grid_marks)
        .y_grid_spacer(grid_marks)
        .custom_x_axes(vec![
            AxisHints::new_x()
                .label(x_label)
                .formatter(|mark, range| {
                    tick_text(mark.value, mark.step_size, range.end() - range.start())
                })
                .label_spacing(X_LABEL_SPACING),
        ])
        .custom_y_axes(vec![
            AxisHints::new_y()
                .label(y_label)
                .formatter(|mark, range| {
                    tick_text(mark.value, mark.step_size, range.end() - range.start())
                })
                .label_spacing(Y_LABEL_SPACING),
        ])
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
    /// The row above the plots: the tab's own buttons (`extra`), the "fit"
    /// button and the hint (none of them in a picture).
    pub fn bar_ui(
        &mut self,
        ui: &mut egui::Ui,
        for_picture: bool,
        extra: impl FnOnce(&mut egui::Ui),
    ) {
        if for_picture {
            return;
        }
        ui.horizontal(|ui| {
            extra(ui);
            let words = ui.words();
            self.asked |= ui
                .small_button(tr!(words, "view-fit"))
                .on_hover_text(tr!(words, "view-hint.more"))
                .clicked();
            // Cut to the row (its whole text on hover): at full length it
            // widened a projector's tab past the window's right edge.
            ui.add(egui::Label::new(egui::RichText::new(words.get(VIEW_HINT)).weak()).truncate());
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

/// Shows `plot` in `ui` on the theme's own background, as an exported
/// figure lies on its page: a range's tint is then the palette's (its share
/// of the state's colour over the background), the legend's swatch the same
/// colour. `egui_plot`'s background would first fill the rect with a darker
/// grey, each pixel shaded twice on a CPU renderer (a third of the plots'
/// pixels at 1920x1080); its frame is drawn here, in its place under the
/// plot's items.
pub fn show_framed<'a, R>(
    plot: Plot<'a>,
    ui: &mut egui::Ui,
    build: impl FnOnce(&mut PlotUi<'a>) -> R + 'a,
) -> PlotResponse<R> {
    let frame_at = ui.painter().add(egui::Shape::Noop);
    let shown = plot.show_background(false).show(ui, build);
    let rect = shown.response.rect;
    ui.painter().with_clip_rect(rect).set(
        frame_at,
        egui::epaint::RectShape::stroke(
            rect,
            2.0,
            ui.visuals().widgets.noninteractive.bg_stroke,
            egui::StrokeKind::Inside,
        ),
    );
    shown
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
    use eframe::egui::vec2;

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
    fn a_symmetric_height_lands_on_a_grid_step() {
        assert_eq!(grid_ceil(0.035), 0.05);
        assert_eq!(grid_ceil(0.05), 0.05);
        assert_eq!(grid_ceil(0.06), 0.1);
        assert_eq!(grid_ceil(1.0), 1.0);
        assert_eq!(grid_ceil(3.2), 5.0);
        assert_eq!(grid_ceil(0.0), 1.0);
        assert_eq!(grid_ceil(f64::NAN), 1.0);
    }

    #[test]
    fn grid_steps_nest_and_each_value_is_marked_once_on_its_coarsest_step() {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-9 * b.abs();
        let steps = grid_steps(0.15);
        for (got, want) in steps.iter().zip([0.1, 0.5, 1.0, 5.0, 10.0]) {
            assert!(close(*got, want), "{steps:?}");
        }
        assert!(close(grid_steps(7e-9)[0], 1e-9));
        let marks = grid_marks(GridInput {
            bounds: (-1.05, 2.0),
            base_step_size: 0.15,
        });
        let at = |value: f64| {
            let found: Vec<_> = marks
                .iter()
                .filter(|m| (m.value - value).abs() < 1e-9)
                .collect();
            assert_eq!(found.len(), 1, "{value}: {found:?}");
            found[0].step_size
        };
        assert!(close(at(0.3), 0.1));
        assert!(close(at(-0.5), 0.5));
        assert!(close(at(1.0), 1.0));
        assert!(close(at(0.0), 10.0), "zero is on every step");
        assert_eq!(marks.len(), 31, "-1.0 to 2.0 in steps of 0.1");
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

    #[test]
    fn a_simplified_curve_stays_within_the_tolerance_of_every_sample() {
        // A square-root branch point, as Im(lambda) near a flutter onset: a
        // vertical tangent at x = 100, a flat stretch after it.
        let points: Vec<egui::Pos2> = (0..=400u16)
            .map(|i| {
                let x = f32::from(i) * 0.5;
                egui::pos2(x, 40.0 * (100.0 - x).max(0.0).sqrt())
            })
            .collect();
        let keep = simplified(&points, 0.15);
        let kept: Vec<egui::Pos2> = points
            .iter()
            .zip(&keep)
            .filter_map(|(p, k)| k.then_some(*p))
            .collect();
        assert!(keep[0] && keep[400], "the ends");
        assert!(kept.len() < points.len() / 4, "{} kept", kept.len());
        for p in &points {
            let nearest = kept
                .windows(2)
                .map(|ab| distance_to_segment(*p, ab[0], ab[1]))
                .fold(f32::INFINITY, f32::min);
            assert!(nearest <= 0.15, "{p:?} is {nearest} away");
        }
        assert!(
            kept.contains(&egui::pos2(100.0, 0.0)),
            "the branch point itself"
        );
        // A point that is not finite splits the curve, and each piece keeps
        // its ends.
        let mut split = points[..5].to_vec();
        split[2] = egui::pos2(f32::NAN, 0.0);
        assert_eq!(simplified(&split, 0.15), [true, true, false, true, true]);
    }

    /// Whether the plot's view counted as settled in each of `frames`
    /// frames of a 400 x 300 window, refitted in the frames `refit` names.
    fn settled_in_frames(frames: usize, refit: impl Fn(usize) -> bool) -> Vec<bool> {
        let ctx = egui::Context::default();
        let mut answers = Vec::new();
        for frame in 0..frames {
            let input = egui::RawInput {
                screen_rect: Some(egui::Rect::from_min_size(
                    egui::Pos2::ZERO,
                    vec2(400.0, 300.0),
                )),
                ..Default::default()
            };
            let refit = refit(frame);
            let mut output = ctx.run_ui(input, |ui| {
                let plot = Plot::new("settling").default_x_bounds(0.0, 1.0);
                refit_if(plot, refit).show(ui, |plot_ui| {
                    answers.push(view_settled(plot_ui, refit));
                });
            });
            // No renderer takes the font atlas here.
            output.textures_delta.clear();
        }
        answers
    }

    #[test]
    fn a_plot_s_view_settles_when_two_frames_agree_and_never_in_a_refit() {
        let answers = settled_in_frames(10, |frame| frame == 5);
        // The first frames have no view before theirs (and the plot lays out
        // its axes in the first ones); a refit frame is never settled, and
        // the view settles again two frames after the last change.
        assert!(!answers[0] && !answers[1], "{answers:?}");
        assert!(answers[4], "settled before the refit: {answers:?}");
        assert!(!answers[5], "the refit: {answers:?}");
        assert!(answers[8] && answers[9], "settled again: {answers:?}");
    }
}
