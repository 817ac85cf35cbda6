//! What the user arranged and expects to find again at the next launch:
//! the open tab, the overlay, the map's second axis and its range, the
//! language chosen from the menu; and how the window takes it up. Kept
//! apart from the settings, which describe a setup to share.

use serde::{Deserialize, Serialize};

use super::action::Action;
use super::notice::Notice;
use super::tabs::{self, Tab};
use crate::i18n::Language;
use crate::model::PresetId;
use crate::tr;

/// The window's arrangement, as stored. Every field has a default, so a
/// file from another version reads; a field that does not make sense for
/// the stored model is dropped when it is applied.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Layout {
    /// The open tab; one this version has not (or a layout from before tabs
    /// were stored by name) opens the first.
    #[serde(deserialize_with = "tab_or_first")]
    pub tab: Tab,
    /// The preset whose locus is drawn behind the current one.
    pub overlay: Option<String>,
    /// The stability map's second axis, by name, and its range.
    pub map_axis: Option<(String, f64, f64)>,
    /// The language chosen in the menu, by its code; none: the system's.
    pub language: Option<String>,
}

/// The stored tab if it names one, else the first: the rest of the layout
/// is kept either way.
fn tab_or_first<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<Tab, D::Error> {
    let stored = ron::Value::deserialize(deserializer)?;
    Ok(stored.into_rust::<Tab>().unwrap_or_default())
}

impl Layout {
    /// Reads a stored layout; text that is not one gives the default layout
    /// and says why.
    #[must_use]
    pub fn read(text: &str) -> (Self, Option<String>) {
        match ron::from_str(text) {
            Ok(layout) => (layout, None),
            Err(error) => (Self::default(), Some(error.code.to_string())),
        }
    }
}

impl super::ZieglerApp {
    /// The window's arrangement now, as it is stored.
    #[must_use]
    pub fn layout(&self) -> Layout {
        Layout {
            tab: self.tab,
            overlay: self.state.overlay_choice().map(|id| id.name().to_owned()),
            map_axis: self
                .tabs
                .get::<tabs::MapPanel>()
                .and_then(tabs::MapPanel::axis_choice),
            language: self
                .state
                .language_choice()
                .map(|language| language.code().to_owned()),
        }
    }

    /// Arranges the window as `layout` says; what does not fit the current
    /// model (an overlay or a map axis it has not) is left out, and said.
    pub fn arrange(&mut self, layout: &Layout) {
        self.tab = layout.tab;
        // The language chosen in the menu, if one was.
        match layout.language.as_deref().map(Language::from_code) {
            Some(Ok(language)) => self.apply(Action::Language(language)),
            Some(Err(why)) => self.state.tell(Notice::warning(tr!(
                self.state.words(),
                "notice-stored-language",
                why = why.to_string()
            ))),
            None => {}
        }
        if let Some(name) = &layout.overlay {
            match name.parse::<PresetId>() {
                Ok(id) => self.apply(Action::Overlay(Some(id))),
                Err(_) => self.state.tell(Notice::warning(tr!(
                    self.state.words(),
                    "notice-stored-overlay",
                    name = name.as_str()
                ))),
            }
        }
        if let Some((name, lo, hi)) = &layout.map_axis {
            let model = *self.state.model();
            if let Some(map) = self.tabs.get_mut::<tabs::MapPanel>()
                && let Err(why) = map.choose_axis(&model, (name, *lo, *hi))
            {
                let words = self.state.words();
                let why = why.words(words);
                self.state.tell(Notice::warning(tr!(
                    words,
                    "notice-stored-map-axis",
                    why = why
                )));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_layout_reads_back_and_an_old_tab_spelling_keeps_the_rest() {
        let layout = Layout {
            tab: Tab::Map,
            overlay: Some("beck".to_owned()),
            map_axis: Some(("nu".to_owned(), 0.0, 1.0)),
            language: Some("pl".to_owned()),
        };
        let text = ron::to_string(&layout).unwrap();
        assert_eq!(Layout::read(&text), (layout, None));
        let (old, note) = Layout::read("(tab: Map, overlay: Some(\"beck\"))");
        assert_eq!(note, None);
        assert_eq!(old.tab, Tab::Locus);
        assert_eq!(old.overlay.as_deref(), Some("beck"));
    }
}
