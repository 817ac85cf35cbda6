//! The parts of the window a picture can show (`--panel`): the whole
//! window, the scene or one tab, by name, and the smallest area each is
//! laid out in.

use super::tabs::{self, Tab};

/// What a headless picture shows: the whole window, the scene, or one tab.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Panel {
    Window,
    Scene,
    Tab(Tab),
}

impl std::str::FromStr for Panel {
    type Err = tabs::UnknownName;

    fn from_str(name: &str) -> Result<Self, tabs::UnknownName> {
        match name {
            "window" => Ok(Self::Window),
            "scene" => Ok(Self::Scene),
            _ => Tab::named(name)
                .map(Self::Tab)
                .map_err(|_| tabs::UnknownName {
                    what: "panel",
                    name: name.to_owned(),
                    known: Self::names().join(", "),
                }),
        }
    }
}

/// The smallest window, in points: the window cannot be made smaller, and
/// the sidebar, the scene and the plots all fit in it.
pub const SMALLEST_WINDOW_POINTS: [f32; 2] = [1024.0, 700.0];

impl Panel {
    /// Every panel's name: the window, the scene, each tab's.
    #[must_use]
    pub fn names() -> Vec<&'static str> {
        ["window", "scene"].into_iter().chain(Tab::ids()).collect()
    }

    /// The smallest area, in points, this panel is laid out in without
    /// labels running into each other: the window's own minimum for the
    /// whole window, 480x300 for one panel.
    #[must_use]
    pub fn smallest_points(self) -> [f32; 2] {
        match self {
            Self::Window => SMALLEST_WINDOW_POINTS,
            Self::Scene | Self::Tab(_) => [480.0, 300.0],
        }
    }
}
