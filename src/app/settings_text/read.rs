//! What reading settings text gives, for the reader of today's text and
//! the migration of the old one alike (a leaf below both): the settings and
//! what was ignored, or why the text holds no settings at all.

use crate::app::settings::Settings;
use crate::sim::SPEED_RANGE;

/// Settings read from text, and what was left at its default and why.
#[derive(Debug)]
pub struct Read {
    pub settings: Settings,
    pub ignored: Vec<String>,
}

/// Text that holds no settings at all.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum SettingsError {
    #[error("not settings text: {0}")]
    NotSettings(String),
    #[error(
        "the text holds {bytes} bytes; settings text is at most {MOST_SETTINGS_BYTES} (the longest the app writes is under 2000)"
    )]
    TooLong { bytes: usize },
}

/// The longest settings text read, in bytes: every parameter changed is
/// under 2 kB, so this is text of some other kind (and a reader bounded by
/// it never keeps the window waiting).
pub const MOST_SETTINGS_BYTES: usize = 16 * 1024;

/// Takes a speed within [`SPEED_RANGE`], naming one outside it.
pub(super) fn take_speed(settings: &mut Settings, speed: f64, ignored: &mut Vec<String>) {
    if SPEED_RANGE.contains(&speed) {
        settings.speed = speed;
    } else {
        ignored.push(format!(
            "speed ({} is outside {} to {})",
            crate::format::Shown(speed),
            SPEED_RANGE.start(),
            SPEED_RANGE.end()
        ));
    }
}
