//! Settings in the earlier stored format (RON: the settings struct with the
//! whole model's fields), read once as a migration, field by field and the
//! model number by number: what can be read is kept, what cannot is named
//! with the reason. They are saved again as `name = value` text. A child
//! module of its own, to delete once no such file is left.

mod model;

use super::read::{Read, SettingsError, take_speed};
use crate::app::settings::Settings;
use crate::model::PresetId;
use model::{Fields, field, read_model};

/// Reads settings in the earlier format (RON), keeping every field that
/// reads and makes sense, and naming the others.
///
/// # Errors
/// Text that is not RON settings at all.
pub(super) fn read_ron(text: &str) -> Result<Read, SettingsError> {
    let Fields(mut fields) =
        ron::from_str(text).map_err(|e| SettingsError::NotSettings(e.to_string()))?;
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
        take_speed(&mut settings, speed, &mut ignored);
    }
    if let Some(projector) = field(projector_raw.as_deref(), "projector", &mut ignored) {
        settings.projector = projector;
    }
    Ok(Read { settings, ignored })
}
