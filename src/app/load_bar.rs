//! The load control for a lecture hall: a bar as wide as the window, coloured
//! by the stability ranges, that is itself the slider (click or drag it to
//! set the load), with the critical loads and a ramp's onsets marked on it.

use super::speak::Speak as _;
use crate::i18n::state_name;
use crate::tr;
use eframe::egui::{self, Align2, FontId, Rect, Sense, Stroke, pos2, vec2};

use super::action::{Action, Actions, Command};
use super::arrows::{keep_arrows, net_presses};
use super::state::AppState;
use super::theme::{Theme, color};
use crate::analysis::State;
use crate::format::{load_text, number_text};
use crate::model::Key;
use crate::plot::pattern;

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

/// The step of the bar's scale: the nearest round step (1, 2 or 5 times a
/// power of ten) to an eighth of the bar, or the next larger round step
/// that makes at most `fits` labels.
fn scale_step(load_max: f64, fits: f64) -> f64 {
    let mut step = round_step(load_max / 8.0);
    for _ in 0..12 {
        if (load_max / step * (1.0 - 1e-9)).floor() + 1.0 <= fits.max(2.0) {
            break;
        }
        let decade = 10f64.powf(step.log10().floor());
        let mantissa = (step / decade).round();
        step = decade
            * match mantissa {
                m if m < 2.0 => 2.0,
                m if m < 5.0 => 5.0,
                _ => 10.0,
            };
    }
    step
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
    let words = ui.words();
    ui.horizontal(|ui| {
        let label = ui.add_sized(
            vec2(6.0 * theme.text_size, bar_height + 2.0 * text_height),
            egui::Label::new(tr!(
                words,
                "load-bar",
                load = bar_load_text(p, state.load_max())
            )),
        );
        let size = vec2(ui.available_width(), bar_height + 2.0 * text_height);
        let (rect, response) = ui.allocate_exact_size(size, Sense::click_and_drag());
        let response = response
            .on_hover_text(tr!(words, "load-bar.tooltip"))
            .labelled_by(label.id);
        let name = tr!(words, "load-bar.name");
        response.widget_info(|| egui::WidgetInfo::slider(true, p, &name));
        describe(ui, &response, state);
        keys_ui(ui, &response, state, actions);
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
                    range_ui(&painter, r, range, &font, theme);
                }
                // Each critical load's value above its tick, kept inside the
                // bar's ends, and left out where it would cover the last one.
                let mut free_from = f32::NEG_INFINITY;
                for t in analysis.transitions.iter().filter(|t| t.load <= load_max) {
                    let tx = x(t.load);
                    painter.line_segment(
                        [pos2(tx, bar.top() - 3.0), pos2(tx, bar.bottom())],
                        Stroke::new(1.5, color(theme.palette.text)),
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
                            color(theme.palette.text),
                        );
                        free_from = left + width + 6.0;
                    }
                }
            }
            None => {
                painter.rect_filled(bar, 0.0, color(theme.palette.no_data));
            }
        }
        scale_ui(&painter, bar, load_max, &font, theme);
        marks_ui(&painter, bar, state, theme);
        // The focus ring: the keys move this bar now.
        if response.has_focus() {
            painter.rect_stroke(
                rect.shrink(1.5 * theme.stroke_scale),
                4.0,
                theme.focus_stroke(),
                egui::StrokeKind::Inside,
            );
        }
    });
}

/// The scale under the bar, at about eight round loads, fewer where their
/// numbers would touch (a chain's bar of 0 to 0.125 in large type).
fn scale_ui(painter: &egui::Painter, bar: Rect, load_max: f64, font: &FontId, theme: &Theme) {
    let widest = painter
        .layout_no_wrap(
            number_text(load_max * 0.987_654_3),
            font.clone(),
            color(theme.palette.axis),
        )
        .size()
        .x;
    let fits = f64::from(bar.width() / (widest + 0.6 * theme.text_size)).floor();
    let step = scale_step(load_max, fits);
    for load in (0..).map_while(|i: u32| {
        let load = f64::from(i) * step;
        (load <= load_max * (1.0 + 1e-9)).then_some(load)
    }) {
        painter.text(
            pos2(
                x_of_load(load, (bar.left(), bar.right()), load_max),
                bar.bottom() + 2.0,
            ),
            Align2::CENTER_TOP,
            number_text(load),
            font.clone(),
            color(theme.palette.axis),
        );
    }
}

/// The bar as a screen reader reads it: a slider from 0 to the bar's end
/// in steps of a hundredth, its value said with the state at the load and
/// that state's range (not while a lesson hides the answer); the keys'
/// actions (increment, decrement, set value) move it as the arrows do.
fn describe(ui: &egui::Ui, response: &egui::Response, state: &AppState) {
    let load_max = state.load_max();
    let text = load_bar_description(state);
    ui.ctx().accesskit_node_builder(response.id, |node| {
        use egui::accesskit::Action as A;
        node.set_min_numeric_value(0.0);
        node.set_max_numeric_value(load_max);
        node.set_numeric_value_step(0.01 * load_max);
        node.set_value(text);
        for action in [A::Increment, A::Decrement, A::SetValue] {
            node.add_action(action);
        }
    });
}

/// The load and what the column does there, in words: "load p = 2.5 of 0
/// to 8: flutter, from p = 2.0900 to 4.2641".
#[must_use]
pub fn load_bar_description(state: &AppState) -> String {
    let words = state.words();
    let p = state.model().load_p();
    let load_max = state.load_max();
    let load = tr!(
        words,
        "load-bar-said",
        load = bar_load_text(p, load_max),
        end = number_text(load_max)
    );
    if state.answer_hidden() {
        return tr!(words, "load-bar-said-hidden", load = load);
    }
    let Some(analysis) = state.analysis() else {
        return tr!(words, "load-bar-said-analysing", load = load);
    };
    let here = analysis
        .ranges
        .iter()
        .find(|&&(start, end, _)| start <= p && p <= end);
    match here {
        Some(&(start, end, range)) => tr!(
            words,
            "load-bar-said-range",
            load = load,
            state = state_name(words, range),
            from = load_text(start),
            to = load_text(end)
        ),
        None => tr!(words, "load-bar-said-beyond", load = load),
    }
}

/// The focused bar's keys: left and right by a hundredth of the bar (a
/// tenth with shift), home and end to its ends. A screen reader's increment
/// and decrement are the load keys' commands (the state's step of a
/// hundredth), its "set value" the value asked (within the bar).
fn keys_ui(ui: &egui::Ui, response: &egui::Response, state: &AppState, actions: &mut Actions) {
    use egui::accesskit::{Action as A, ActionData};
    let p = state.model().load_p();
    let load_max = state.load_max();
    let keyed = if response.has_focus() {
        keyed_load(ui, response.id, p, load_max)
    } else {
        None
    };
    let id = response.id;
    let (ups, downs, set) = ui.input(|input| {
        let set = input.events.iter().find_map(|event| match event {
            egui::Event::AccessKitActionRequest(request)
                if request.action == A::SetValue && request.target_node == id.accesskit_id() =>
            {
                match request.data {
                    Some(ActionData::NumericValue(value)) if value.is_finite() => {
                        Some(value.clamp(0.0, load_max))
                    }
                    _ => None,
                }
            }
            _ => None,
        });
        (
            input.num_accesskit_action_requests(id, A::Increment),
            input.num_accesskit_action_requests(id, A::Decrement),
            set,
        )
    });
    if let Some(load) = keyed.or(set).filter(|&load| load != p) {
        actions.push(Action::Enter {
            key: Key::Load,
            value: load,
        });
    }
    let steps = std::iter::repeat_n(Command::LoadUp, ups)
        .chain(std::iter::repeat_n(Command::LoadDown, downs));
    for command in steps {
        actions.push(Action::Command(command));
    }
}

/// A load slider's keys while the widget `id` has the focus, from `load`
/// on a bar of 0 to `load_max`: left and right a hundredth of the bar (a
/// tenth with shift), home and end its ends; the new load if it moves. The
/// arrows stay with the widget (egui would move the focus on). The load
/// bar and a lesson's prediction slider both step so.
pub fn keyed_load(ui: &egui::Ui, id: egui::Id, load: f64, load_max: f64) -> Option<f64> {
    use egui::Key as K;
    keep_arrows(ui.ctx(), id, false);
    let target = ui.input(|input| {
        let fraction = if input.modifiers.shift { 0.1 } else { 0.01 };
        let steps = net_presses(input, K::ArrowRight, K::ArrowLeft);
        if input.key_pressed(K::Home) {
            Some(0.0)
        } else if input.key_pressed(K::End) {
            Some(load_max)
        } else if steps != 0.0 {
            // Beyond the bar (a typed load) the keys lead back into it.
            Some((load + steps * fraction * load_max).clamp(0.0, load_max.max(load)))
        } else {
            None
        }
    });
    target.filter(|&target| target != load)
}

/// A stability range of the bar: its colour, its stripes if it has them,
/// and its name where it fits, so that the bar reads without colour.
fn range_ui(painter: &egui::Painter, r: Rect, state: State, font: &FontId, theme: &Theme) {
    let fill = theme.state_color(state);
    painter.rect_filled(r, 0.0, fill);
    if pattern::striped(state) {
        let spacing = 10.0 * theme.stroke_scale;
        // The stripes stop a fifth of the bar above its foot: the range's
        // colour runs unbroken along the foot, to be read and measured
        // there (under the names, which break the rows they cross).
        let foot = r.bottom() - 0.2 * r.height();
        // The pattern's y is up: the screen's, negated.
        let stripes = pattern::stripes(
            (f64::from(r.left()), f64::from(r.right())),
            (-f64::from(foot), -f64::from(r.top())),
            f64::from(spacing),
        );
        #[expect(clippy::cast_possible_truncation, reason = "pixels")]
        for stripe in stripes {
            let points = stripe
                .iter()
                .map(|p| pos2(p[0] as f32, -p[1] as f32))
                .collect();
            painter.add(egui::Shape::convex_polygon(
                points,
                color(theme.palette.background),
                Stroke::NONE,
            ));
        }
    }
    let name = state_name(painter.ctx().words(), state);
    let galley = painter.layout_no_wrap(name, font.clone(), color(theme.palette.background));
    if galley.size().x + 12.0 <= r.width() && galley.size().y <= r.height() {
        let at = r.center() - 0.5 * galley.size();
        painter.rect_filled(
            Rect::from_min_size(at, galley.size()).expand2(vec2(4.0, 0.0)),
            2.0,
            fill,
        );
        painter.galley(at, galley, color(theme.palette.background));
    }
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
        for (load, color) in [
            (theory, color(theme.palette.text)),
            (run.seen_at_p, color(theme.palette.measured)),
        ] {
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
            Stroke::new(3.0 * theme.stroke_scale, color(theme.palette.info)),
        );
    }
    // The handle: a bar through the scale, and a knob.
    let hx = x(p);
    painter.line_segment(
        [pos2(hx, bar.top() - 4.0), pos2(hx, bar.bottom() + 4.0)],
        Stroke::new(4.0 * theme.stroke_scale, color(theme.palette.now)),
    );
    painter.circle_filled(
        pos2(hx, bar.center().y),
        0.45 * bar_height,
        color(theme.palette.now),
    );
    painter.circle_stroke(
        pos2(hx, bar.center().y),
        0.45 * bar_height,
        Stroke::new(1.5, color(theme.palette.background)),
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
    fn the_scale_makes_no_more_labels_than_fit() {
        assert_eq!(scale_step(8.0, 20.0), 1.0);
        assert_eq!(scale_step(0.125, 20.0), 0.01);
        // 13 labels of 0.01 do not fit in 6: 0.02 makes 7, 0.05 makes 3.
        assert_eq!(scale_step(0.125, 6.0), 0.05);
        assert_eq!(scale_step(0.125, 7.0), 0.02);
        assert_eq!(scale_step(0.125, 8.0), 0.02);
        assert_eq!(scale_step(8.0, 3.0), 5.0);
    }

    #[test]
    fn the_scale_steps_are_round() {
        assert_eq!(round_step(1.0), 1.0);
        assert_eq!(round_step(0.015_625), 0.01);
        assert_eq!(round_step(0.03), 0.02);
        assert_eq!(round_step(0.6), 0.5);
    }
}
