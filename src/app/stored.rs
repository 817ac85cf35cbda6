//! Settings read back from text (eframe's store, or pasted) field by field,
//! the model number by number: what can be read is kept, what cannot is
//! named with the reason.

use std::collections::BTreeMap;

use ron::value::RawValue;
use serde::Deserialize;
use serde::de::{MapAccess, Visitor};

use super::notice::Notice;
use super::state::{AppState, Settings};
use super::stored_model::read_model;
use crate::model::PresetId;

use crate::sim::SPEED_RANGE;

/// The fields of a RON struct (the settings, or a part of the model), each
/// as unparsed RON, by name.
#[derive(Default)]
pub(super) struct Fields(pub(super) BTreeMap<String, Box<RawValue>>);

impl<'de> Deserialize<'de> for Fields {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct FieldsVisitor;
        impl<'de> Visitor<'de> for FieldsVisitor {
            type Value = Fields;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a struct, (name: value, ...)")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Fields, A::Error> {
                let mut fields = Fields::default();
                while let Some(name) = map.next_key::<String>()? {
                    let value = map.next_value()?;
                    fields.0.insert(name, value);
                }
                Ok(fields)
            }
        }
        deserializer.deserialize_struct("Settings", KNOWN, FieldsVisitor)
    }
}

/// The fields of [`Settings`].
const KNOWN: &[&str] = &["preset", "model", "engine", "speed", "projector"];

/// Settings read from text, and what was left at its default and why.
#[derive(Debug)]
pub struct Read {
    pub settings: Settings,
    pub ignored: Vec<String>,
}

/// One field as a `T`, or its reason for being ignored in `ignored`.
pub(super) fn field<T: for<'de> Deserialize<'de>>(
    raw: Option<&RawValue>,
    name: &str,
    ignored: &mut Vec<String>,
) -> Option<T> {
    let raw = raw?;
    match raw.into_rust::<T>() {
        Ok(value) => Some(value),
        Err(error) => {
            ignored.push(format!("{name} ({})", error.code));
            None
        }
    }
}

/// Reads settings written by the app (RON), keeping every field that reads
/// and makes sense, and naming the others.
///
/// # Errors
/// Text that is not settings at all.
pub fn read(text: &str) -> Result<Read, String> {
    // Text saved by an editor that writes a byte-order mark reads the same.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let Fields(mut fields) = ron::from_str(text).map_err(|e| format!("not settings text: {e}"))?;
    let mut ignored = Vec::new();
    let mut take = |name: &str| fields.remove(name);
    let (preset_raw, model_raw, engine_raw, speed_raw, projector_raw) = (
        take("preset"),
        take("model"),
        take("engine"),
        take("speed"),
        take("projector"),
    );
    // Whatever is left is not a field of this version's settings.
    ignored.extend(
        fields
            .into_keys()
            .map(|name| format!("{name} (not a setting)")),
    );
    let mut settings = Settings::default();
    let name: Option<String> = field(preset_raw.as_deref(), "preset", &mut ignored);
    match name.map(|name| name.parse::<PresetId>()) {
        Some(Ok(id)) => {
            settings.preset = id;
            settings.model = match model_raw.as_deref() {
                Some(raw) => read_model(raw, id.model(), &mut ignored),
                None => id.model(),
            };
        }
        Some(Err(error)) => {
            ignored.push(format!("preset ({error})"));
            if model_raw.is_some() {
                ignored.push("model (it belongs to that preset)".to_owned());
            }
        }
        None if model_raw.is_some() => {
            ignored.push("model (no preset says what it is)".to_owned());
        }
        None => {}
    }
    if let Some(engine) = field(engine_raw.as_deref(), "engine", &mut ignored) {
        settings.engine = engine;
    }
    if let Some(speed) = field::<f64>(speed_raw.as_deref(), "speed", &mut ignored) {
        if SPEED_RANGE.contains(&speed) {
            settings.speed = speed;
        } else {
            ignored.push(format!(
                "speed ({speed} is outside {} to {})",
                SPEED_RANGE.start(),
                SPEED_RANGE.end()
            ));
        }
    }
    if let Some(projector) = field(projector_raw.as_deref(), "projector", &mut ignored) {
        settings.projector = projector;
    }
    Ok(Read { settings, ignored })
}

impl AppState {
    /// The state from settings stored as text (RON, as eframe writes them):
    /// every field that reads and makes sense is kept, the others take their
    /// defaults, and a notice names them.
    #[must_use]
    pub fn from_stored_text(text: Option<&str>) -> Self {
        Self::from_stored_text_analysed(text, false)
    }

    /// [`AppState::from_stored_text`], the analysis of the stored column
    /// computed off the UI thread when `in_background` (the window's start).
    #[must_use]
    pub fn from_stored_text_analysed(text: Option<&str>, in_background: bool) -> Self {
        let Some(text) = text else {
            return Self::first_launch();
        };
        let (settings, note) = match read(text) {
            Ok(read) if read.ignored.is_empty() => (read.settings, None),
            Ok(read) => {
                let note = format!(
                    "stored settings: ignored {}; kept the rest",
                    read.ignored.join(", ")
                );
                (read.settings, Some(Notice::warning(note)))
            }
            Err(error) => (
                Settings::default(),
                Some(Notice::warning(format!(
                    "stored settings ignored ({error}); starting from the defaults"
                ))),
            ),
        };
        let started = if in_background {
            Self::new_analysing_in_background(settings)
        } else {
            Self::new(settings)
        };
        let mut state = match started {
            Ok(state) => state,
            Err(error) => {
                let mut state = Self::defaults();
                state.say(Notice::warning(format!(
                    "stored settings ignored ({error}); starting from the defaults"
                )));
                return state;
            }
        };
        if let Some(note) = note {
            // The note first: what was read comes before what starting did.
            let started = state.notice().cloned();
            state.say(note);
            if let Some(started) = started {
                state.tell(started);
            }
        }
        state
    }

    /// The default settings' state.
    #[must_use]
    pub fn defaults() -> Self {
        // The roller preset is valid by construction; this cannot fail.
        match Self::new(Settings::default()) {
            Ok(state) => state,
            Err(error) => unreachable!("the default settings are valid: {error}"),
        }
    }

    /// Loads settings from shared text; garbage leaves everything as it was
    /// and says why.
    pub fn paste_settings(&mut self, text: &str) {
        if text.trim().is_empty() {
            self.say(Notice::error(
                "nothing to paste: put settings text (from \"copy settings\") in the box first",
            ));
            return;
        }
        let settings = match read(text) {
            Ok(read) if read.ignored.is_empty() => read.settings,
            Ok(read) => {
                self.say(Notice::error(format!(
                    "pasted settings refused, nothing changed: {} not understood",
                    read.ignored.join(", ")
                )));
                return;
            }
            Err(error) => {
                self.say(Notice::error(format!(
                    "pasted settings not understood, nothing changed: {error}"
                )));
                return;
            }
        };
        // Taken in place: the analysis thread, the lesson, the overlay and
        // the tab stay (a new state dropped the thread, so every later change
        // was analysed on the UI thread).
        match self.take_settings(settings) {
            Ok(()) => self.say(Notice::info("settings pasted")),
            Err(error) => {
                self.say(Notice::error(format!(
                    "pasted settings refused, nothing changed: {error}"
                )));
            }
        }
    }
}
