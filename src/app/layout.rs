//! What the user arranged and expects to find again at the next launch:
//! the open tab, the overlay, the map's second axis and its range, the
//! language chosen from the menu. Kept
//! apart from the settings, which describe a setup to share.

use serde::{Deserialize, Serialize};

use super::tabs::Tab;

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
