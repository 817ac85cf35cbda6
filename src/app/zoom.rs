//! The window's zoom (egui's Ctrl+Plus, Ctrl+Minus and Ctrl+0, stored
//! with egui's memory between launches) kept from 75% to 200%, where the
//! layout holds: a zoom outside, typed or stored, is brought back and said.

use super::speak::Speak as _;
use crate::tr;
use std::ops::RangeInclusive;

use eframe::egui;

use super::notice::Notice;

/// The zooms the window takes.
pub const ZOOM_RANGE: RangeInclusive<f32> = 0.75..=2.0;

/// `zoom` as a percentage.
fn percent(zoom: f32) -> String {
    format!("{:.0}%", 100.0 * zoom)
}

/// Brings the zoom of `ctx` back into [`ZOOM_RANGE`] if it left it; the
/// notice that says so.
pub fn hold(ctx: &egui::Context) -> Option<Notice> {
    let zoom = ctx.zoom_factor();
    if ZOOM_RANGE.contains(&zoom) {
        return None;
    }
    let held = if zoom.is_finite() {
        zoom.clamp(*ZOOM_RANGE.start(), *ZOOM_RANGE.end())
    } else {
        1.0
    };
    ctx.set_zoom_factor(held);
    Some(Notice::warning(tr!(
        ctx.words(),
        "zoom-outside",
        zoom = percent(zoom),
        least = percent(*ZOOM_RANGE.start()),
        most = percent(*ZOOM_RANGE.end()),
        held = percent(held)
    )))
}
