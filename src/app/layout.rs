//! What the user arranged and expects to find again at the next launch:
//! the open tab, the overlay, the map's second axis and its range. Kept
//! apart from the settings, which describe a setup to share.

use serde::{Deserialize, Serialize};

use super::tabs::Tab;

/// The window's arrangement, as stored. Every field has a default, so a
/// file from another version reads; a field that does not make sense for
/// the stored model is dropped when it is applied.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Layout {
    pub tab: Tab,
    /// The preset whose locus is drawn behind the current one.
    pub overlay: Option<String>,
    /// The stability map's second axis, by name, and its range.
    pub map_axis: Option<(String, f64, f64)>,
}

impl Layout {
    /// Reads a stored layout; text that is not one gives the default layout
    /// and says why.
    #[must_use]
    pub fn read(text: &str) -> (Self, Option<String>) {
        match ron::from_str(text) {
            Ok(layout) => (layout, None),
            Err(error) => (
                Self::default(),
                Some(format!(
                    "stored window layout ignored ({}); the default layout is used",
                    error.code
                )),
            ),
        }
    }
}
