//! The animated column seen from above: clamp, rods, joint springs, the
//! roller spinning with psi over the band moving at V, force arrows, the
//! angle delta and a fading trail of the tip.

use super::speak::{Speak as _, status_words};
use crate::tr;
use std::collections::VecDeque;
use std::f64::consts::TAU;

use eframe::egui::{
    self, Align2, Color32, FontId, Pos2, Rect, Sense, Shape, Stroke, Vec2, emath::RectTransform,
    pos2, vec2,
};

use super::action::{Action, Actions};
use super::camera::{Camera, FOLLOW_SECS, WorldBox, target};
use super::grab::{GRAB_RADIUS, grab_angles};
use super::scene_access;
use super::state::{AppState, TRAIL_SECS};
use super::theme::{Theme, color};
use crate::model::Model;
use crate::sim::{Observables, Status};

/// What the scene draws besides the column itself.
struct SceneInput<'a> {
    pub model: &'a Model,
    pub now: &'a Observables,
    /// The joints from the clamp to the tip.
    pub joints_m: &'a [[f64; 2]],
    pub trail: &'a VecDeque<(f64, [f64; 2])>,
    pub status: Status,
    /// The world box the camera frames.
    pub framed: WorldBox,
    pub theme: &'a Theme,
}

fn p(x: f64, y: f64) -> Pos2 {
    #[expect(clippy::cast_possible_truncation, reason = "screen coordinates")]
    pos2(x as f32, y as f32)
}

/// World (m, y up) to screen (pixels, y down): the only y flip.
struct View {
    screen_from_world: RectTransform,
    pixels_per_m: f64,
}

impl View {
    fn to(&self, x: f64, y: f64) -> Pos2 {
        self.screen_from_world.transform_pos(p(x, y))
    }

    #[expect(clippy::cast_possible_truncation, reason = "pixels")]
    fn px(&self, meters: f64) -> f32 {
        (meters * self.pixels_per_m) as f32
    }
}

/// What the scene keeps from frame to frame: its camera, and the part of
/// the column the mouse holds.
#[derive(Default)]
pub struct SceneView {
    pub camera: Camera,
    /// The joint held: the end of rod k (1 to N, N the tip).
    grabbed: Option<usize>,
}

/// Draws the scene of the app's state in the space left in `ui`, framed
/// by the camera, with the camera's "whole reach" switch in its corner;
/// a drag from a joint or the tip displaces the column (held at rest while
/// the button is down), and letting go lets it move.
pub fn scene_ui(
    ui: &mut egui::Ui,
    state: &AppState,
    actions: &mut Actions,
    scene: &mut SceneView,
    theme: &Theme,
) {
    let camera = &mut scene.camera;
    let now = state.simulation().observe();
    let model = state.model();
    let reach_m = model.column.reach_m();
    let rods = model.column.rods;
    let joints_m = state.simulation().joints_m();
    let joint_m = joints_m[1];
    let recent = state
        .trail()
        .iter()
        .filter(|(t, _)| now.t_secs - t <= FOLLOW_SECS)
        .map(|&(_, tip)| tip);
    let framed = camera.frame(
        target(reach_m, joint_m, now.tip_m, recent, camera.whole_reach),
        reach_m,
    );
    let (rect, view, delta_badge) = draw(
        ui,
        &SceneInput {
            model,
            now: &now,
            joints_m: &joints_m,
            trail: state.trail(),
            status: state.simulation().status(),
            framed,
            theme,
        },
    );
    // No tooltip: the mouse rests over the scene in a lecture, and a
    // tooltip would cover the load bar. The corner says it instead.
    let drag = ui.interact(rect, ui.scope_id().with("drag the column"), Sense::drag());
    scene_access::keys_ui(ui, &drag, actions, theme);
    scene_access::describe_ui(ui, drag.id, state);
    if let Some(badge) = delta_badge {
        ui.interact(badge, ui.scope_id().with("delta"), Sense::hover())
            .on_hover_text(tr!(ui.words(), "scene-delta.tooltip"));
    }
    if !state.for_picture() {
        plate(
            ui.painter(),
            theme,
            rect.left_bottom() + vec2(10.0, -10.0),
            Align2::LEFT_BOTTOM,
            tr!(ui.words(), "scene-drag-hint"),
            color(theme.palette.axis),
        );
    }
    // What was under the button when it went down (the drag starts a few
    // points later).
    if drag.drag_started()
        && let Some(pointer) = ui.input(|i| i.pointer.press_origin())
    {
        // Any joint above the base, the tip included: the nearest.
        scene.grabbed = joints_m
            .iter()
            .enumerate()
            .skip(1)
            .map(|(held, at)| (held, view.to(at[0], at[1]).distance(pointer)))
            .filter(|&(_, d)| d <= GRAB_RADIUS)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(held, _)| held);
    }
    if let Some(held) = scene.grabbed {
        // Asked again only when the pointer moves: a still hand asks nothing.
        let moved = drag.drag_started() || drag.drag_delta() != Vec2::ZERO;
        if drag.dragged()
            && moved
            && let Some(pointer) = drag.interact_pointer_pos()
        {
            let world = view.screen_from_world.inverse().transform_pos(pointer);
            let point = [f64::from(world.x), f64::from(world.y)];
            let lengths_m: Vec<f64> = (0..rods).map(|i| model.column.rod(i).length_m).collect();
            let x = state.simulation().state();
            let angles_now_rad: Vec<f64> = x.rows(0, rods).iter().copied().collect();
            actions.push(Action::Hold {
                angles_rad: grab_angles(held, &lengths_m, &angles_now_rad, point),
            });
        }
        if drag.drag_stopped() {
            scene.grabbed = None;
            actions.push(Action::Release);
        }
    }
    camera_corner_ui(ui, &mut scene.camera, rect, theme);
}

/// The size of the camera's switch, in units of the text size.
const CAMERA_SWITCH_WIDTH_EM: f32 = 7.5;
const CAMERA_SWITCH_HEIGHT_EM: f32 = 1.6;

/// The camera's "whole reach" switch in the scene's corner.
fn camera_corner_ui(ui: &mut egui::Ui, camera: &mut Camera, rect: Rect, theme: &Theme) {
    let corner = Rect::from_min_size(
        rect.left_top() + vec2(8.0, 8.0),
        vec2(
            CAMERA_SWITCH_WIDTH_EM * theme.text_size,
            CAMERA_SWITCH_HEIGHT_EM * theme.text_size,
        ),
    );
    if ui
        .put(
            corner,
            egui::Button::selectable(camera.whole_reach, tr!(ui.words(), "scene-whole-reach")),
        )
        .on_hover_text(tr!(ui.words(), "scene-whole-reach.tooltip"))
        .clicked()
    {
        camera.whole_reach = !camera.whole_reach;
    }
}

/// Draws `input` in the space left in `ui`; returns where, the world's
/// place on the screen, and where the angle delta is said (a roller's).
fn draw(ui: &mut egui::Ui, input: &SceneInput<'_>) -> (Rect, View, Option<Rect>) {
    let SceneInput {
        model,
        now,
        joints_m: joints,
        trail,
        status,
        framed,
        theme,
    } = *input;
    let (response, painter) = ui.allocate_painter(ui.available_size(), Sense::hover());
    let rect = response.rect;
    let painter = painter.with_clip_rect(rect.intersect(painter.clip_rect()));
    // No background of its own: the scene lies on a panel of the theme's
    // background already (the window clears to it, a picture's panel is
    // filled with it). A second fill would cost a CPU renderer every pixel
    // of the scene once more (nearly half of a 16-rod chain's frame at
    // 1920x1080).
    let reach = model.column.reach_m();
    // The camera's box, with equal scales on both axes, centred.
    let margin = 0.12 * reach;
    let [world_w, world_h] = framed.size();
    let pixels_per_m = (f64::from(rect.width()) / world_w).min(f64::from(rect.height()) / world_h);
    let half_w = 0.5 * f64::from(rect.width()) / pixels_per_m;
    let half_h = 0.5 * f64::from(rect.height()) / pixels_per_m;
    let [center_x, center_y] = framed.center();
    let world = Rect::from_min_max(
        p(center_x - half_w, center_y + half_h),
        p(center_x + half_w, center_y - half_h),
    );
    let view = View {
        screen_from_world: RectTransform::from_to(world, rect),
        pixels_per_m,
    };
    let s = theme.stroke_scale;
    let band_label = model.roller().map(|roller| {
        band(
            &painter,
            theme,
            &view,
            (reach, margin),
            roller.band_speed_m_per_s,
            now.t_secs,
            rect,
        )
    });
    clamp(&painter, theme, &view, reach);
    trail_ui(&painter, theme, &view, trail);
    let angles_rad = &now.angles_rad;
    let last = joints.len() - 1;
    let spring_stroke = Stroke::new(1.5 * s, color(theme.palette.spring));
    let spring_size = view.px(0.06 * (model.column.rod1.length_m + model.column.rod2.length_m));
    for (i, angle) in angles_rad.iter().enumerate() {
        let bend = if i == 0 {
            *angle
        } else {
            angle - angles_rad[i - 1]
        };
        let [x, y] = joints[i];
        spring(&painter, view.to(x, y), spring_size, bend, spring_stroke);
    }
    let rod = Stroke::new(5.0 * s, color(theme.palette.rod));
    for pair in joints.windows(2) {
        painter.line_segment(
            [
                view.to(pair[0][0], pair[0][1]),
                view.to(pair[1][0], pair[1][1]),
            ],
            rod,
        );
    }
    for &[x, y] in &joints[..last] {
        painter.circle_filled(view.to(x, y), 6.0 * s, color(theme.palette.joint));
    }
    let last_rod_rad = angles_rad[angles_rad.len() - 1];
    // The force arrows at a length of the first two rods.
    let arrow_m = 0.35 * (model.column.rod1.length_m + model.column.rod2.length_m);
    forces(&painter, theme, &view, (model, now, last_rod_rad), arrow_m);
    if let Some(roller) = model.roller() {
        roller_ui(
            &painter,
            theme,
            &view,
            (now, last_rod_rad),
            roller.radius_m.max(0.02 * reach),
        );
    }
    // The angle delta under the band's label, in the scene's corner: beside
    // the tip it covered the roller and the band's label.
    let delta_badge = band_label.map(|above| {
        plate(
            &painter,
            theme,
            above.right_bottom() + vec2(-4.0, 8.0),
            Align2::RIGHT_TOP,
            delta_text(now.delta_rad),
            color(theme.palette.friction),
        )
    });
    notes(&painter, theme, rect, status, now.stick_slip);
    (rect, view, delta_badge)
}

/// The angle delta as the scene shows it: rounded first, then -0 turned
/// into 0, so that no "-0.00" is on the screen.
fn delta_text(delta_rad: f64) -> String {
    let degrees = (delta_rad.to_degrees() * 100.0).round() / 100.0 + 0.0;
    format!("δ = {degrees:+.2}°")
}

/// The clamp at O: a wall with hatching on the far side.
fn clamp(painter: &egui::Painter, theme: &Theme, view: &View, reach: f64) {
    let s = theme.stroke_scale;
    let wall = 0.08 * reach;
    painter.line_segment(
        [view.to(0.0, -wall), view.to(0.0, wall)],
        Stroke::new(3.0 * s, color(theme.palette.rod)),
    );
    for k in 0..6 {
        let y = -wall + 2.0 * wall * f64::from(k) / 5.0;
        let hatch = [view.to(0.0, y), view.to(-0.04 * reach, y - 0.04 * reach)];
        painter.line_segment(hatch, Stroke::new(1.5 * s, color(theme.palette.rod)));
    }
}

/// The tip's trail, fading with age.
fn trail_ui(
    painter: &egui::Painter,
    theme: &Theme,
    view: &View,
    trail: &VecDeque<(f64, [f64; 2])>,
) {
    let newest = trail.back().map_or(0.0, |(t, _)| *t);
    for (older, newer) in trail.iter().zip(trail.iter().skip(1)) {
        let age = (newest - newer.0) / TRAIL_SECS;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "alpha in [0, 255]"
        )]
        let alpha = ((1.0 - age).clamp(0.0, 1.0) * 220.0) as u8;
        let color = Color32::from_rgba_unmultiplied(
            color(theme.palette.trail).r(),
            color(theme.palette.trail).g(),
            color(theme.palette.trail).b(),
            alpha,
        );
        let segment = [
            view.to(older.1[0], older.1[1]),
            view.to(newer.1[0], newer.1[1]),
        ];
        painter.line_segment(segment, Stroke::new(2.0 * theme.stroke_scale, color));
    }
}

/// Forces at the tip: the ideal follower direction along the last rod (at
/// `last_rad`; dashed) and the actual force (the band's friction for the
/// roller), at one length, and the angle delta between them (eq. 23).
fn forces(
    painter: &egui::Painter,
    theme: &Theme,
    view: &View,
    (model, now, last_rad): (&Model, &Observables, f64),
    length_m: f64,
) {
    let s = theme.stroke_scale;
    let b = now.tip_m;
    let follower = [-last_rad.cos(), -last_rad.sin()];
    let force = now.tip_force_n;
    let magnitude = force[0].hypot(force[1]);
    if magnitude == 0.0 {
        return;
    }
    let tip = view.to(b[0], b[1]);
    let along = |d: [f64; 2]| view.to(b[0] + length_m * d[0], b[1] + length_m * d[1]) - tip;
    dashed_arrow(
        painter,
        tip,
        along(follower),
        Stroke::new(2.0 * s, color(theme.palette.follower)),
    );
    let unit = [force[0] / magnitude, force[1] / magnitude];
    painter.arrow(
        tip,
        along(unit),
        Stroke::new(3.0 * s, color(theme.palette.friction)),
    );
    if model.roller().is_some() {
        // The angle delta drawn between the two directions, from the
        // follower direction to the force.
        let start = follower[1].atan2(follower[0]);
        let arc: Vec<Pos2> = (0..=24)
            .map(|i| {
                let angle = start + now.delta_rad * f64::from(i) / 24.0;
                let r = 0.6 * length_m;
                view.to(b[0] + r * angle.cos(), b[1] + r * angle.sin())
            })
            .collect();
        painter.add(Shape::line(
            arc,
            Stroke::new(1.5 * s, color(theme.palette.friction)),
        ));
    }
}

/// The roller: a disc standing across the last rod (at `last_rad`), seen
/// from above as a rectangle; marks on its rim turn with psi.
fn roller_ui(
    painter: &egui::Painter,
    theme: &Theme,
    view: &View,
    (now, last_rad): (&Observables, f64),
    radius_m: f64,
) {
    let s = theme.stroke_scale;
    let (b, psi) = (now.tip_m, now.psi_rad);
    let t2 = [-last_rad.sin(), last_rad.cos()];
    let e2 = [last_rad.cos(), last_rad.sin()];
    let half_thick = 0.25 * radius_m;
    let corner =
        |u: f64, v: f64| view.to(b[0] + u * t2[0] + v * e2[0], b[1] + u * t2[1] + v * e2[1]);
    let outline = vec![
        corner(-radius_m, -half_thick),
        corner(radius_m, -half_thick),
        corner(radius_m, half_thick),
        corner(-radius_m, half_thick),
    ];
    painter.add(Shape::convex_polygon(
        outline,
        color(theme.palette.roller),
        Stroke::new(1.5 * s, color(theme.palette.roller_mark)),
    ));
    for k in 0..8 {
        let angle = psi + TAU * f64::from(k) / 8.0;
        // Only the marks on the upper half of the rim are seen from above.
        if angle.cos() > 0.0 {
            let u = radius_m * angle.sin();
            painter.line_segment(
                [corner(u, -half_thick), corner(u, half_thick)],
                Stroke::new(2.0 * s, color(theme.palette.roller_mark)),
            );
        }
    }
}

/// What the picture cannot show by itself, in words.
fn notes(painter: &egui::Painter, theme: &Theme, rect: Rect, status: Status, stick_slip: bool) {
    let mut lines = Vec::new();
    let words = painter.ctx().words();
    if status != Status::Running {
        lines.push((status_words(words, status), color(theme.palette.error)));
    }
    if stick_slip {
        lines.push((tr!(words, "scene-stick-slip"), color(theme.palette.warning)));
    }
    for (i, (text, color)) in lines.into_iter().enumerate() {
        #[expect(clippy::cast_precision_loss, reason = "a handful of lines")]
        let y = rect.top() + 10.0 + i as f32 * (theme.text_size + 6.0);
        plate(
            painter,
            theme,
            pos2(rect.left() + 10.0, y + 2.0 * theme.text_size),
            Align2::LEFT_TOP,
            text,
            color,
        );
    }
}

/// The band: everywhere in the picture and at least under the whole disc
/// the tip can reach (the model's band is everywhere under the roller, so
/// the roller never leaves it, even with the column folded back), with
/// marks moving toward -x at V and a label saying which way it goes.
fn band(
    painter: &egui::Painter,
    theme: &Theme,
    view: &View,
    (reach, margin): (f64, f64),
    speed_m_per_s: f64,
    t_secs: f64,
    rect: Rect,
) -> Rect {
    let s = theme.stroke_scale;
    let to = |x, y| view.to(x, y);
    // Everywhere the camera looks, and at least the whole reach.
    let seen = view.screen_from_world.inverse();
    let (corner_a, corner_b) = (seen.transform_pos(rect.min), seen.transform_pos(rect.max));
    let x0 = f64::from(corner_a.x.min(corner_b.x)).min(-reach - 0.5 * margin);
    let x1 = f64::from(corner_a.x.max(corner_b.x)).max(reach + margin);
    let y0 = f64::from(corner_a.y.min(corner_b.y)).min(-reach - 0.5 * margin);
    let y1 = f64::from(corner_a.y.max(corner_b.y)).max(reach + 0.5 * margin);
    // A pixel beyond the picture on every side (clipped): its edge is never
    // blended with what lies outside.
    let covered = Rect::from_two_pos(to(x0, y0), to(x1, y1)).union(rect.expand(1.0));
    painter.rect_filled(covered, 0.0, color(theme.palette.band));
    let spacing = 0.08 * reach;
    let offset = (-speed_m_per_s * t_secs).rem_euclid(spacing);
    let mut x = x0 + offset;
    while x < x1 {
        painter.line_segment(
            [to(x, y0), to(x, y1)],
            Stroke::new(1.0 * s, color(theme.palette.band_mark)),
        );
        x += spacing;
    }
    // Where the band goes, in the scene's top right corner (the band's
    // own corner may be far out of the camera's frame), or under the
    // camera's switch when the two do not fit side by side (a projector's
    // narrow scene).
    let text = tr!(
        painter.ctx().words(),
        "scene-band",
        speed = crate::format::number_text(speed_m_per_s)
    );
    let width = painter
        .layout_no_wrap(
            text.clone(),
            FontId::proportional(theme.text_size),
            color(theme.palette.text),
        )
        .size()
        .x;
    let beside = rect.width() >= width + CAMERA_SWITCH_WIDTH_EM * theme.text_size + 40.0;
    let top = if beside {
        10.0
    } else {
        12.0 + CAMERA_SWITCH_HEIGHT_EM * theme.text_size
    };
    plate(
        painter,
        theme,
        rect.right_top() + vec2(-10.0, top),
        Align2::RIGHT_TOP,
        text,
        color(theme.palette.text),
    )
}

/// `text` on a plate of the scene's background, so that no stripe or rod
/// runs through it.
fn plate(
    painter: &egui::Painter,
    theme: &Theme,
    at: Pos2,
    align: Align2,
    text: String,
    text_color: Color32,
) -> Rect {
    let galley = painter.layout_no_wrap(text, FontId::proportional(theme.text_size), text_color);
    let inner = align.anchor_size(at, galley.size());
    // Kept inside the scene (a label beyond the tip may point out of it).
    let clip = painter.clip_rect().shrink(6.0);
    let shift = vec2(
        (clip.left() - inner.left()).max(0.0) + (clip.right() - inner.right()).min(0.0),
        (clip.top() - inner.top()).max(0.0) + (clip.bottom() - inner.bottom()).min(0.0),
    );
    let inner = inner.translate(shift);
    painter.rect_filled(inner.expand(4.0), 4.0, color(theme.palette.background));
    painter.galley(inner.min, galley, text_color);
    inner.expand(4.0)
}

/// A torsion spring at `center`: a spiral whose winding follows the joint's
/// relative angle, so it visibly tightens and loosens.
fn spring(painter: &egui::Painter, center: Pos2, radius: f32, angle_rad: f64, stroke: Stroke) {
    let turns = 2.5;
    let n = 60;
    let points: Vec<Pos2> = (0..=n)
        .map(|i| {
            let t = f64::from(i) / f64::from(n);
            let theta = angle_rad + t * (TAU * turns - angle_rad);
            #[expect(clippy::cast_possible_truncation, reason = "pixels")]
            let r = radius * (0.35 + 0.65 * t as f32);
            #[expect(clippy::cast_possible_truncation, reason = "pixels")]
            let (sin, cos) = (theta.sin() as f32, theta.cos() as f32);
            center + Vec2::new(r * cos, -r * sin)
        })
        .collect();
    painter.add(Shape::line(points, stroke));
}

fn dashed_arrow(painter: &egui::Painter, origin: Pos2, vector: Vec2, stroke: Stroke) {
    painter.extend(Shape::dashed_line(
        &[origin, origin + vector],
        stroke,
        8.0,
        6.0,
    ));
    let head = 10.0 * stroke.width.max(1.0) / 2.0;
    let dir = vector.normalized();
    let tip = origin + vector;
    let left = tip - head * dir + 0.6 * head * dir.rot90();
    let right = tip - head * dir - 0.6 * head * dir.rot90();
    painter.line_segment([tip, left], stroke);
    painter.line_segment([tip, right], stroke);
}
