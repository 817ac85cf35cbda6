//! The tabs of the lower half of the window, each a [`View`] in a file of
//! its own: the root locus, the time histories, the stability map and the
//! paradox explorer.

mod histories;
mod locus;
pub mod map;
mod paradox;

use eframe::egui;

use super::View;
use super::action::{Action, Actions};
use super::state::AppState;

/// The choice of plots in the lower half of the window.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Tab {
    #[default]
    Locus,
    Histories,
    Map,
    Paradox,
}

impl From<crate::lesson::LessonTab> for Tab {
    fn from(tab: crate::lesson::LessonTab) -> Self {
        use crate::lesson::LessonTab;
        match tab {
            LessonTab::Locus => Self::Locus,
            LessonTab::Histories => Self::Histories,
            LessonTab::Map => Self::Map,
            LessonTab::Paradox => Self::Paradox,
        }
    }
}

impl Tab {
    /// Every tab, in the order the tab bar shows them.
    pub const ALL: [Self; 4] = [Self::Locus, Self::Histories, Self::Map, Self::Paradox];

    /// What the tab shows, for its tooltip.
    #[must_use]
    pub fn tooltip(self) -> &'static str {
        match self {
            Self::Locus => "the eigenvalues in the complex plane and against the load",
            Self::Histories => "the angles, the energy and the band's power over the run",
            Self::Map => "the stability of every load against a second parameter",
            Self::Paradox => {
                "the first critical load as the damping (or the roller's mass) vanishes"
            }
        }
    }

    /// The tab bar's name for it.
    #[must_use]
    pub fn title(self) -> &'static str {
        match self {
            Self::Locus => "root locus",
            Self::Histories => "time histories",
            Self::Map => "stability map",
            Self::Paradox => "paradox",
        }
    }
}

/// Every tab's view (the map and the paradox keep their background work).
#[derive(Default)]
pub struct Tabs {
    locus: locus::LocusTab,
    histories: histories::HistoriesTab,
    map: map::MapPanel,
    paradox: paradox::ParadoxPanel,
}

impl Tabs {
    /// The locus tab, for its complex plane alone.
    pub fn locus_mut(&mut self) -> &mut locus::LocusTab {
        &mut self.locus
    }

    /// The view that draws `tab`.
    pub fn view(&mut self, tab: Tab) -> &mut dyn View {
        match tab {
            Tab::Locus => &mut self.locus,
            Tab::Histories => &mut self.histories,
            Tab::Map => &mut self.map,
            Tab::Paradox => &mut self.paradox,
        }
    }

    /// The tab bar: a click shows another tab.
    pub fn bar_ui(ui: &mut egui::Ui, open: Tab, actions: &mut Actions) {
        ui.horizontal(|ui| {
            for tab in Tab::ALL {
                if ui
                    .selectable_label(open == tab, tab.title())
                    .on_hover_text(tab.tooltip())
                    .clicked()
                {
                    actions.push(Action::Tab(tab));
                }
            }
        });
    }

    /// The stability map's view (its axis choice).
    #[must_use]
    pub fn map(&self) -> &map::MapPanel {
        &self.map
    }

    /// The stability map's view, to choose its axis.
    pub fn map_mut(&mut self) -> &mut map::MapPanel {
        &mut self.map
    }

    /// Computes the background work of `tab` (the stability map, the
    /// paradox curves) for the current parameters and waits until it is
    /// complete (for pictures and tests). Other tabs' work is not started:
    /// a picture of the paradox on a chain once computed the map too.
    pub fn complete_background_work(&mut self, state: &AppState, tab: Tab) {
        let model = state.model();
        match tab {
            Tab::Map => {
                self.map.follow(model, model.load_bar_max_p());
                self.map.wait();
            }
            Tab::Paradox => self.paradox.wait(model),
            Tab::Locus | Tab::Histories => {}
        }
    }
}
