//! The arrow keys a focused widget keeps for itself (egui would move the
//! focus on with them) and the presses it counts: what the load bar, the
//! scene and the plots share, below the actions that name them.

use eframe::egui;

/// Keeps the arrows with the focused widget `id` this frame (egui would
/// move the focus on with them): the horizontal ones, and the vertical
/// ones too where `vertical`.
pub fn keep_arrows(ctx: &egui::Context, id: egui::Id, vertical: bool) {
    ctx.memory_mut(|memory| {
        memory.set_focus_lock_filter(
            id,
            egui::EventFilter {
                horizontal_arrows: true,
                vertical_arrows: vertical,
                ..Default::default()
            },
        );
    });
}

/// How many times `up` was pressed this frame less how many times `down`
/// was (a key held repeats).
#[must_use]
pub fn net_presses(input: &egui::InputState, up: egui::Key, down: egui::Key) -> f64 {
    let presses = |key| f64::from(u32::try_from(input.num_presses(key)).unwrap_or(u32::MAX));
    presses(up) - presses(down)
}
