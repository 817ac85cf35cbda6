//! What the app tells the user, with how much it matters: information,
//! a warning, or an error (each drawn in the theme's colour for it).

/// How much a notice matters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// Done as asked ("settings pasted").
    Info,
    /// Done, but not quite as asked (an engine switched, entries ignored).
    Warning,
    /// Not done, and why.
    Error,
}

/// One thing to tell the user.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Notice {
    pub level: Level,
    pub text: String,
}

impl Notice {
    pub fn info(text: impl Into<String>) -> Self {
        Self {
            level: Level::Info,
            text: text.into(),
        }
    }

    pub fn warning(text: impl Into<String>) -> Self {
        Self {
            level: Level::Warning,
            text: text.into(),
        }
    }

    pub fn error(text: impl Into<String>) -> Self {
        Self {
            level: Level::Error,
            text: text.into(),
        }
    }

    /// This notice followed by `later`, at the higher of the two levels.
    #[must_use]
    pub fn and(mut self, later: &Self) -> Self {
        self.level = self.level.max(later.level);
        self.text = format!("{}; {}", self.text, later.text);
        self
    }
}
