//! The tabs of the lower half of the window, in one registry ([`TABS`]):
//! each tab is a file of its own with its [`TabSpec`], and the tab bar, the
//! lessons' `tab`, the command line's `--panel`, the stored layout and the
//! pictures all read the list. A new tab is one file, one line here, its
//! variant in `app/tab.rs` and its words in each language.

mod histories;
mod locus;
pub mod map;
mod map_readout;
mod paradox;
mod postcritical;

use std::any::Any;

pub use super::tab::{Tab, UnknownName};

use super::View;
use super::action::{Action, Actions, Table};
use super::speak::Speak as _;
use super::state::AppState;
use crate::i18n::Words;
use crate::tr;

/// A tab's view: it draws itself from the state (a [`View`]) and can finish
/// its background work for a picture.
pub trait TabView: View + Any {
    /// Computes this tab's background work for the current state and waits
    /// until it is complete (for pictures and tests; the window never waits).
    fn complete_background_work(&mut self, _state: &AppState) {}
}

/// What a tab is, for everything that names it.
pub struct TabSpec {
    /// The tab this row describes (its place in [`TABS`]).
    pub tab: Tab,
    /// The name lessons, `--panel` and the stored layout use; its title
    /// and tooltip are the messages `tab-ID` and `tab-ID.tooltip`.
    pub id: &'static str,
    /// Whether it computes something of its own off the window's thread (a
    /// picture waits for it, saying so).
    pub background: bool,
    /// Its view, as the window starts.
    pub make: fn() -> Box<dyn TabView>,
}

/// Every tab, in the tab bar's order.
pub const TABS: [TabSpec; <Tab as strum::EnumCount>::COUNT] = [
    locus::TAB,
    histories::TAB,
    map::TAB,
    paradox::TAB,
    postcritical::TAB,
];

// Each row sits at its tab's place: `Tab::spec` indexes the table.
const _: () = {
    let mut i = 0;
    while i < TABS.len() {
        assert!(TABS[i].tab as usize == i, "TABS out of order");
        i += 1;
    }
};

impl Tab {
    /// Every tab, in the tab bar's order.
    pub fn all() -> impl Iterator<Item = Self> {
        TABS.iter().map(|spec| spec.tab)
    }

    /// The tab `steps` places on in the tab bar's order, round the ends
    /// (Ctrl+Tab: 1, Ctrl+Shift+Tab: -1).
    #[must_use]
    pub fn cycled(self, steps: isize) -> Self {
        let count = TABS.len().cast_signed();
        let at = (self as usize).cast_signed() + steps;
        TABS[at.rem_euclid(count).cast_unsigned()].tab
    }

    /// The tab named `id`.
    ///
    /// # Errors
    /// No tab has that name: the message lists those that do.
    pub fn named(id: &str) -> Result<Self, UnknownName> {
        Self::all()
            .find(|tab| tab.id() == id)
            .ok_or_else(|| UnknownName {
                what: "tab",
                name: id.to_owned(),
                known: Self::ids().join(", "),
            })
    }

    /// Every tab's name, in order.
    #[must_use]
    pub fn ids() -> Vec<&'static str> {
        TABS.iter().map(|spec| spec.id).collect()
    }

    #[must_use]
    pub fn spec(self) -> &'static TabSpec {
        &TABS[self as usize]
    }

    #[must_use]
    pub fn id(self) -> &'static str {
        self.spec().id
    }

    /// The tab bar's name, in `words`' language (message `tab-ID`).
    #[must_use]
    pub fn title(self, words: &'static Words) -> String {
        words.get(&format!("tab-{}", self.id())).into_owned()
    }

    /// What it shows, the tab bar's tooltip.
    #[must_use]
    pub fn tooltip(self, words: &'static Words) -> String {
        words
            .get(&format!("tab-{}.tooltip", self.id()))
            .into_owned()
    }
}

impl std::fmt::Display for Tab {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

impl serde::Serialize for Tab {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.id())
    }
}

impl<'de> serde::Deserialize<'de> for Tab {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let id = String::deserialize(deserializer)?;
        Self::named(&id).map_err(serde::de::Error::custom)
    }
}

/// Every tab's view, made from the registry.
pub struct Tabs {
    views: Vec<Box<dyn TabView>>,
}

impl Default for Tabs {
    fn default() -> Self {
        Self {
            views: TABS.iter().map(|spec| (spec.make)()).collect(),
        }
    }
}

impl Tabs {
    /// The view that draws `tab`.
    pub fn view(&mut self, tab: Tab) -> &mut dyn TabView {
        self.views[tab as usize].as_mut()
    }

    /// The view of type `T` (the locus drawn beside the scene, the map's
    /// axis kept in the layout).
    #[must_use]
    pub fn get<T: TabView>(&self) -> Option<&T> {
        self.views
            .iter()
            .find_map(|view| (view.as_ref() as &dyn Any).downcast_ref())
    }

    /// [`Self::get`], to change.
    pub fn get_mut<T: TabView>(&mut self) -> Option<&mut T> {
        self.views
            .iter_mut()
            .find_map(|view| (view.as_mut() as &mut dyn Any).downcast_mut())
    }

    /// Computes the background work of `tab` for the current parameters and
    /// waits until it is complete (for pictures and tests). Other tabs'
    /// work is not started: a picture of the paradox on a chain once
    /// computed the map too.
    pub fn complete_background_work(&mut self, state: &AppState, tab: Tab) {
        self.view(tab).complete_background_work(state);
    }
}

pub use locus::LocusTab;
pub use map::MapPanel;

/// A tab's buttons that save its plots as a PNG and, when it has one, its
/// table as the command line writes it, each to a file chosen in the
/// desktop's dialog.
fn save_buttons(ui: &mut eframe::egui::Ui, table: Option<Table>, actions: &mut Actions) {
    let words = ui.words();
    if ui
        .small_button(tr!(words, "save-png"))
        .on_hover_text(tr!(words, "save-png.tooltip"))
        .clicked()
    {
        actions.push(Action::SavePicture);
    }
    if let Some(table) = table
        && ui
            .small_button(tr!(words, "save-csv"))
            .on_hover_text(tr!(words, "save-csv.tooltip"))
            .clicked()
    {
        actions.push(Action::SaveCsv(table));
    }
}

/// The tab bar: a click asks for another tab. Its titles wrap to a second
/// row where they do not fit one (German on a projector).
pub fn bar_ui(ui: &mut eframe::egui::Ui, open: Tab, actions: &mut Actions) {
    let words = ui.words();
    ui.horizontal_wrapped(|ui| {
        for tab in Tab::all() {
            if ui
                .selectable_label(open == tab, tab.title(words))
                .on_hover_text(tab.tooltip(words))
                .clicked()
            {
                actions.push(Action::Tab(tab));
            }
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The named tabs are the registry's, and names are unique.
    #[test]
    fn the_named_tabs_are_the_registry_s() {
        for (tab, id) in [
            (Tab::Locus, "locus"),
            (Tab::Histories, "histories"),
            (Tab::Map, "map"),
            (Tab::Paradox, "paradox"),
            (Tab::PostCritical, "post-critical"),
        ] {
            assert_eq!(tab.id(), id);
            assert_eq!(Tab::named(id), Ok(tab));
        }
        let mut ids = Tab::ids();
        ids.sort_unstable();
        ids.dedup();
        assert_eq!(ids.len(), TABS.len());
        assert!(
            Tab::named("plots")
                .unwrap_err()
                .to_string()
                .contains("locus")
        );
    }

    /// A tab is written and read by its name.
    #[test]
    fn a_tab_is_written_and_read_by_its_name() {
        assert_eq!(ron::to_string(&Tab::Map).unwrap(), "\"map\"");
        assert_eq!(ron::from_str::<Tab>("\"map\""), Ok(Tab::Map));
        assert!(ron::from_str::<Tab>("\"plots\"").is_err());
    }
}
