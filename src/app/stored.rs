//! Settings read back from text (eframe's store, or pasted) field by field,
//! the model number by number: what can be read is kept, what cannot is
//! named with the reason.

use super::settings::Settings;
use super::stored_model::{Fields, field, read_model};
use crate::model::PresetId;

use crate::sim::SPEED_RANGE;

/// Settings read from text, and what was left at its default and why.
#[derive(Debug)]
pub struct Read {
    pub settings: Settings,
    pub ignored: Vec<String>,
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
