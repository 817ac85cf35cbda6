//! A focused plot's keys: the arrows pan it by a tenth of its view, + and -
//! zoom about its centre, Enter picks the point at the centre (a map's
//! cell), which a cross marks while the plot has the focus.

use eframe::egui::{self, Stroke};
use egui_plot::{HLine, LineStyle, PlotPoint, PlotUi, VLine};

use super::arrows::{keep_arrows, net_presses};
use super::theme::{Theme, color};

/// The share of the view one arrow press pans by.
const PAN_SHARE: f64 = 0.1;
/// The zoom of one press of + (and, inverted, of -).
const ZOOM_STEP: f32 = 1.25;

/// The key under which a plot's response id is known to take keys.
fn plot_key(id: egui::Id) -> egui::Id {
    id.with("takes the plot keys")
}

/// Whether the widget `id` is a plot that takes the keys (it was drawn by
/// [`keys_ui`] in the last frame).
#[must_use]
pub fn is_plot(ctx: &egui::Context, id: egui::Id) -> bool {
    ctx.data(|data| data.get_temp::<bool>(plot_key(id)))
        .unwrap_or(false)
}

/// The keys of the plot drawn in `plot_ui`, when it has the focus: returns
/// the view's centre when Enter picks it.
pub fn keys_ui(plot_ui: &mut PlotUi<'_>, theme: &Theme) -> Option<PlotPoint> {
    let response = plot_ui.response().clone();
    let ctx = plot_ui.ctx().clone();
    ctx.data_mut(|data| data.insert_temp(plot_key(response.id), true));
    if !response.has_focus() {
        return None;
    }
    keep_arrows(&ctx, response.id, true);
    let bounds = plot_ui.plot_bounds();
    let (width, height) = (bounds.width(), bounds.height());
    let centre = PlotPoint::new(
        0.5 * (bounds.min()[0] + bounds.max()[0]),
        0.5 * (bounds.min()[1] + bounds.max()[1]),
    );
    let (pan, zoom, picked) = ctx.input(|input| {
        use egui::Key as K;
        let pan = (
            PAN_SHARE * width * net_presses(input, K::ArrowRight, K::ArrowLeft),
            PAN_SHARE * height * net_presses(input, K::ArrowUp, K::ArrowDown),
        );
        let zoom_in = input.key_pressed(K::Plus) || input.key_pressed(K::Equals);
        let zoom_out = input.key_pressed(K::Minus);
        let zoom = match (zoom_in, zoom_out) {
            (true, false) => Some(ZOOM_STEP),
            (false, true) => Some(1.0 / ZOOM_STEP),
            _ => None,
        };
        (pan, zoom, input.key_pressed(K::Enter))
    });
    if pan != (0.0, 0.0) {
        #[expect(clippy::cast_possible_truncation, reason = "plot units")]
        plot_ui.translate_bounds(egui::vec2(pan.0 as f32, pan.1 as f32));
    }
    if let Some(factor) = zoom {
        plot_ui.zoom_bounds(egui::Vec2::splat(factor), centre);
    }
    // The cross at the centre: what Enter picks.
    let stroke = Stroke::new(1.5 * theme.stroke_scale, color(theme.palette.text));
    plot_ui.vline(
        VLine::new("", centre.x)
            .stroke(stroke)
            .style(LineStyle::dashed_dense()),
    );
    plot_ui.hline(
        HLine::new("", centre.y)
            .stroke(stroke)
            .style(LineStyle::dashed_dense()),
    );
    picked.then_some(centre)
}
