//! The window's panels (the status line, the sidebar, the central panel),
//! laid out at the smallest window's size and scrolled as a whole where
//! the window shows fewer points (zoomed to 200% on 1280x800).

use eframe::egui;

use super::theme::Theme;
use super::{SMALLEST_WINDOW_POINTS, View as _, ZieglerApp, action, record_menu, sidebar};

/// The egui memory key of the projector sidebar's foot's height.
const FOOT_HEIGHT_ID: &str = "sidebar foot height";

impl ZieglerApp {
    /// The panels in the space `ui` offers.
    pub(super) fn window_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        // Zoomed past what the window holds (200% on 1280x800 is 640x400
        // points): the layout keeps the smallest window's size and scrolls.
        let smallest = egui::Vec2::from(SMALLEST_WINDOW_POINTS);
        // The window's size, not the space inside its margins.
        let window = ui.ctx().content_rect().size();
        let shown = ui.available_size();
        if window.x < smallest.x || window.y < smallest.y {
            egui::ScrollArea::both()
                .id_salt("the whole window")
                .show(ui, |ui| {
                    // What the smallest window offers inside its margins.
                    let size = (smallest - (window - shown)).max(shown);
                    ui.allocate_ui(size, |ui| {
                        ui.set_min_size(size);
                        self.panels_ui(ui, theme);
                    });
                });
        } else {
            self.panels_ui(ui, theme);
        }
    }

    /// The status line, the sidebar and the central panel in `ui`.
    fn panels_ui(&mut self, ui: &mut egui::Ui, theme: &Theme) {
        let style = ui.style().clone();
        egui::Panel::bottom("status line")
            .frame(self.panel_frame(egui::Frame::side_top_panel(&style)))
            .exact_size(1.6 * theme.text_size + 8.0)
            .show(ui, |ui| {
                sidebar::status_line_ui(ui, &self.state, &mut self.actions, theme);
            });
        egui::Panel::left("controls")
            .frame(self.panel_frame(egui::Frame::side_top_panel(&style)))
            .resizable(false)
            .exact_size(320.0)
            .show(ui, |ui| {
                let (choice, recorder) = (&mut self.record_choice, &self.recorder);
                self.sidebar
                    .header_ui(ui, &self.state, &mut self.actions, |ui, actions| {
                        record_menu::record_ui(ui, choice, recorder, actions);
                    });
                ui.separator();
                // On a projector the foot keeps its place at the sidebar's
                // bottom, its height the last frame's: it is made after what
                // scrolls, so Tab reaches it in the order it is seen (made
                // first, it came right after the heading).
                let whole = ui.available_rect_before_wrap();
                let foot_height = if self.state.settings().projector {
                    ui.ctx()
                        .data(|data| data.get_temp::<f32>(egui::Id::unique(FOOT_HEIGHT_ID)))
                        .unwrap_or(0.0)
                        .min(whole.height())
                } else {
                    0.0
                };
                let (above, foot) = whole.split_top_bottom_at_y(whole.bottom() - foot_height);
                // Each lesson step's text read from its top.
                let step = self
                    .state
                    .lesson()
                    .map(|run| (run.lesson.title.clone(), run.step));
                ui.scope_builder(egui::UiBuilder::new().max_rect(above), |ui| {
                    egui::ScrollArea::vertical()
                        .id_salt(("sidebar", step))
                        .show(ui, |ui| {
                            action::scroll_to_new_focus(ui);
                            self.sidebar.ui(ui, &self.state, &mut self.actions, theme);
                        });
                });
                if self.state.settings().projector {
                    let shown = ui.scope_builder(egui::UiBuilder::new().max_rect(foot), |ui| {
                        sidebar::foot_ui(ui, &self.state, &mut self.actions, theme);
                    });
                    let needed = shown.response.rect.height();
                    if (needed - foot_height).abs() > 0.5 {
                        ui.ctx().data_mut(|data| {
                            data.insert_temp(egui::Id::unique(FOOT_HEIGHT_ID), needed);
                        });
                        // The frame laid out with the wrong height is not shown.
                        ui.ctx()
                            .request_discard("the sidebar's foot changed its height");
                    }
                }
            });
        egui::CentralPanel::default()
            .frame(self.panel_frame(egui::Frame::central_panel(&style)))
            .show(ui, |ui| self.central_ui(ui, theme));
    }
}
