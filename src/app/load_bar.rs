//! The load control for a lecture hall: a bar as wide as the window, coloured
//! by the stability ranges, that is itself the slider (click or drag it to
//! set the load), with the critical loads and a ramp's onsets marked on it.

use eframe::egui::{self, Align2, FontId, Rect, Sense, Stroke, pos2, vec2};

use super::action::{Action, Actions};
use super::state::AppState;
use super::theme::Theme;
use crate::format::{load_text, number_text};
use crate::model::Key;

/// The load at horizontal position `x` of a bar spanning `left..right`
/// (the slider's range, ends included).
#[must_use]
pub fn load_at_x(x: f32, (left, right): (f32, f32), load_max: f64) -> f64 {
    let fraction = if right > left {
        ((x - left) / (right - left)).clamp(0.0, 1.0)
    } else {
        0.0
    };
    f64::from(fraction) * load_max
}

/// The nearest of 1, 2, 5 times a power of ten at or below `step`.
fn round_step(step: f64) -> f64 {
    let decade = 10f64.powf(step.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|&s| s <= step * (1.0 + 1e-9))
        .unwrap_or(decade)
}

/// The horizontal position of `load` on a bar spanning `left..right`.
#[must_use]
pub fn x_of_load(load: f64, (left, right): (f32, f32), load_max: f64) -> f32 {
    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    let fraction = (load / load_max).clamp(0.0, 1.0) as f32;
    left + (right - left) * fraction
}

/// The load as the bar's label says it: rounded to a hundredth of the
/// bar's span (to 0.01 on a bar of 0 to 8, to 0.001 on a chain's of 0 to
/// 0.125), and in full where that rounding would say 0 of a load that is not.
fn bar_load_text(load_p: f64, load_max: f64) -> String {
    let step = 10f64.powf((load_max / 100.0).log10().floor());
    let rounded = (load_p / step).round() * step;
    if !step.is_finite() || step <= 0.0 || (rounded == 0.0 && load_p != 0.0) {
        return crate::format::load_text(load_p);
    }
    number_text(rounded)
}

/// The bar across `ui`'s width: the load's value at its left, the ranges,
/// the critical loads above, the scale below, the handle at the load.
pub fn load_bar_ui(ui: &mut egui::Ui, state: &AppState, actions: &mut Actions, theme: &Theme) {
    let text_height = theme.text_size + 4.0;
    let bar_height = 1.4 * text_height;
    let font = FontId::proportional(theme.text_size);
    let p = state.model().load_p();
    ui.horizontal(|ui| {
        let label = ui.add_sized(
            vec2(6.0 * theme.text_size, bar_height + 2.0 * text_height),
            egui::Label::new(format!("load\np = {}", bar_load_text(p, state.load_max()))),
        );
        let size = vec2(ui.available_width(), bar_height + 2.0 * text_height);
        let (rect, response) = ui.allocate_exact_size(size, Sense::click_and_drag());
        let response = response
            .on_hover_text("the load p = P l/k: click or drag here, or use the arrow keys")
            .labelled_by(label.id);
        response.widget_info(|| egui::WidgetInfo::slider(true, p, "load slider"));
        let bar = Rect::from_min_max(
            pos2(rect.left() + 8.0, rect.top() + text_height),
            pos2(rect.right() - 8.0, rect.top() + text_height + bar_height),
        );
        if (response.clicked() || response.dragged())
            && let Some(pointer) = response.interact_pointer_pos()
        {
            let load = load_at_x(pointer.x, (bar.left(), bar.right()), state.load_max());
            // A still hand on the bar asks nothing more.
            if load != state.model().load_p() || response.clicked() {
                actions.push(Action::Enter {
                    key: Key::Load,
                    value: load,
                });
            }
        }
        let painter = ui.painter_at(rect);
        let load_max = state.load_max();
        let x = |load: f64| x_of_load(load, (bar.left(), bar.right()), load_max);
        // A lesson's prediction: the bar shows no ranges and no critical loads.
        let analysis = state.analysis().filter(|_| !state.answer_hidden());
        match analysis {
            Some(analysis) => {
                for &(start, end, range) in &analysis.ranges {
                    let r =
                        Rect::from_min_max(pos2(x(start), bar.top()), pos2(x(end), bar.bottom()));
                    painter.rect_filled(r, 0.0, theme.state_color(range));
                }
                // Each critical load's value above its tick, kept inside the
                // bar's ends, and left out where it would cover the last one.
                let mut free_from = f32::NEG_INFINITY;
                for t in analysis.transitions.iter().filter(|t| t.load <= load_max) {
                    let tx = x(t.load);
                    painter.line_segment(
                        [pos2(tx, bar.top() - 3.0), pos2(tx, bar.bottom())],
                        Stroke::new(1.5, theme.text),
                    );
                    let galley = painter.layout_no_wrap(
                        load_text(t.load),
                        font.clone(),
                        theme.state_color(t.to),
                    );
                    let width = galley.size().x;
                    let left = (tx - 0.5 * width)
                        .min(rect.right() - width)
                        .max(rect.left());
                    if left >= free_from {
                        painter.galley(
                            pos2(left, bar.top() - 3.0 - galley.size().y),
                            galley,
                            theme.text,
                        );
                        free_from = left + width + 6.0;
                    }
                }
            }
            None => {
                painter.rect_filled(bar, 0.0, theme.no_data);
            }
        }
        // The scale under the bar, at about eight round loads.
        let step = round_step(load_max / 8.0);
        for load in (0..).map_while(|i: u32| {
            let load = f64::from(i) * step;
            (load <= load_max * (1.0 + 1e-9)).then_some(load)
        }) {
            painter.text(
                pos2(x(load), bar.bottom() + 2.0),
                Align2::CENTER_TOP,
                number_text(load),
                font.clone(),
                theme.axis,
            );
        }
        marks_ui(&painter, bar, state, theme);
    });
}

/// What is marked on the bar: a ramp's onsets (the theory's, the seen one),
/// a lesson's predicted load, and the handle at the load.
fn marks_ui(painter: &egui::Painter, bar: Rect, state: &AppState, theme: &Theme) {
    let load_max = state.load_max();
    let x = |load: f64| x_of_load(load, (bar.left(), bar.right()), load_max);
    let bar_height = bar.height();
    let p = state.model().load_p();
    let analysis = state.analysis();
    // A ramp's onsets: the theory's (text colour, not while a lesson keeps
    // the answer) and the seen one.
    if let Some(run) = state.ramp() {
        let theory = analysis
            .filter(|_| !state.answer_hidden())
            .and_then(crate::app::analysis_cache::Analysis::first_instability);
        for (load, color) in [(theory, theme.text), (run.seen_at_p, theme.measured)] {
            if let Some(load) = load.filter(|&l| l <= load_max) {
                painter.line_segment(
                    [pos2(x(load), bar.top()), pos2(x(load), bar.bottom())],
                    Stroke::new(3.0 * theme.stroke_scale, color),
                );
            }
        }
    }
    // A lesson's predicted load: a ring on the bar.
    if let Some(predicted) = state.lesson().and_then(|run| run.predicted_load) {
        painter.circle_stroke(
            pos2(x(predicted), bar.center().y),
            0.35 * bar_height,
            Stroke::new(3.0 * theme.stroke_scale, theme.info),
        );
    }
    // The handle: a bar through the scale, and a knob.
    let hx = x(p);
    painter.line_segment(
        [pos2(hx, bar.top() - 4.0), pos2(hx, bar.bottom() + 4.0)],
        Stroke::new(4.0 * theme.stroke_scale, theme.now),
    );
    painter.circle_filled(pos2(hx, bar.center().y), 0.45 * bar_height, theme.now);
    painter.circle_stroke(
        pos2(hx, bar.center().y),
        0.45 * bar_height,
        Stroke::new(1.5, theme.background),
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_maps_its_width_onto_the_slider_s_range_and_back() {
        let bar = (100.0, 500.0);
        for max in [8.0, 0.125] {
            assert_eq!(load_at_x(100.0, bar, max), 0.0);
            assert_eq!(load_at_x(500.0, bar, max), max);
            assert_eq!(load_at_x(300.0, bar, max), 0.5 * max);
            assert_eq!(load_at_x(50.0, bar, max), 0.0, "left of the bar");
            for fraction in [0.0, 0.125, 0.3175, 1.0] {
                let load = fraction * max;
                let back = load_at_x(x_of_load(load, bar, max), bar, max);
                assert!((back - load).abs() < 1e-5 * max, "{load} -> {back}");
            }
        }
    }

    /// The label rounds to the bar's resolution, and never says 0 of a
    /// load that is not (a 16-rod chain's 7.8125e-4 was "p = 0").
    #[test]
    fn the_label_rounds_to_the_bar_s_resolution() {
        assert_eq!(bar_load_text(2.541_7, 8.0), number_text(2.54));
        assert_eq!(bar_load_text(0.073_42, 0.125), number_text(0.073));
        assert_eq!(bar_load_text(7.8125e-4, 0.125), number_text(0.001));
        assert_eq!(bar_load_text(1e-5, 0.125), crate::format::load_text(1e-5));
        assert_eq!(bar_load_text(0.0, 8.0), number_text(0.0));
    }

    #[test]
    fn the_scale_steps_are_round() {
        assert_eq!(round_step(1.0), 1.0);
        assert_eq!(round_step(0.015_625), 0.01);
        assert_eq!(round_step(0.03), 0.02);
        assert_eq!(round_step(0.6), 0.5);
    }
}
