//! Settings as text, stored and shared: the preset, then `name = value`
//! lines in the vocabulary of `--set` and the lessons, read line by line so
//! one bad line costs that line only. Text in the earlier format (RON, the
//! whole model's fields) is still read, once, as a migration.

mod entries;
mod read;
mod ron_migration;

use std::fmt::Write as _;

use super::settings::Settings;
use crate::format::clipped;
use crate::model::{Assignment, Key, Model, PresetId, apply_assignments};
use crate::sim::EngineKind;
use entries::{Entry, Write, apply};
use read::take_speed;
pub use read::{MOST_SETTINGS_BYTES, Read, SettingsError};
use ron_migration::read_ron;

/// The most characters of a line a message repeats.
const MOST_LINE_CHARS: usize = 60;

/// The most lines a message names as ignored; the rest are counted.
const MOST_IGNORED_NAMED: usize = 10;

impl Settings {
    /// The settings as text: the preset, every parameter that differs from
    /// the preset's (by the keys that write one number each, so the text
    /// reads back to the same model to the last bit), the engine, the speed
    /// and projector mode.
    #[must_use]
    pub fn to_text(&self) -> String {
        let preset = self.preset.model();
        let mut text = format!("preset = {}\n", self.preset);
        for &key in Key::all() {
            let spec = key.spec();
            if spec.derived || !spec.applies_to(&self.model) {
                continue;
            }
            let value = key.get(&self.model);
            // A chain's load is written whatever it is: read without it,
            // the load would start in place on the chain's bar.
            let chain_load =
                spec.stage == LOAD_STAGE && self.model.column.rods != preset.column.rods;
            if chain_load || value.to_bits() != key.get(&preset).to_bits() {
                // Writing to a String cannot fail.
                let _ = writeln!(text, "{key} = {value}");
            }
        }
        let _ = write!(
            text,
            "engine = {}\nspeed = {}\nprojector = {}\n",
            self.engine.name(),
            self.speed,
            self.projector
        );
        text
    }
}

/// Reads settings text: `name = value` lines (blank lines and `#` comments
/// skipped), or the earlier RON format. Every line that reads and makes
/// sense is kept; the others are named in [`Read::ignored`].
///
/// # Errors
/// Text with no settings in it at all.
pub fn read(text: &str) -> Result<Read, SettingsError> {
    if text.len() > MOST_SETTINGS_BYTES {
        return Err(SettingsError::TooLong { bytes: text.len() });
    }
    // Text saved by an editor that writes a byte-order mark reads the same.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut read = if text.trim_start().starts_with('(') {
        read_ron(text)?
    } else {
        read_lines(text)?
    };
    let more = read.ignored.len().saturating_sub(MOST_IGNORED_NAMED);
    if more > 0 {
        read.ignored.truncate(MOST_IGNORED_NAMED);
        read.ignored.push(format!("{more} more"));
    }
    Ok(read)
}

/// [`read`] of the `name = value` form.
fn read_lines(text: &str) -> Result<Read, SettingsError> {
    let mut ignored = Vec::new();
    let lines = name_value_lines(text, &mut ignored);
    if lines.is_empty() {
        return Err(SettingsError::NotSettings(
            "no line of name = value (e.g. preset = roller)".to_owned(),
        ));
    }
    let mut settings = Settings::default();
    let mut seen = std::collections::HashSet::new();
    let mut entries = Vec::new();
    let mut preset = None;
    for (name, value) in lines {
        let value = clipped(value, MOST_LINE_CHARS);
        let value = value.as_str();
        if !seen.insert(name) {
            ignored.push(format!(
                "{} (given twice; the first is kept)",
                clipped(name, MOST_LINE_CHARS)
            ));
            continue;
        }
        match name {
            "preset" => match value.parse::<PresetId>() {
                Ok(id) => preset = Some(id),
                Err(error) => ignored.push(format!("preset ({error})")),
            },
            "engine" => match EngineKind::named(value) {
                Some(engine) => settings.engine = engine,
                None => ignored.push(format!(
                    "engine ('{value}' is none of {})",
                    crate::names::variant_names::<EngineKind>()
                )),
            },
            "speed" => match value.parse::<f64>() {
                Ok(speed) => take_speed(&mut settings, speed, &mut ignored),
                Err(_) => ignored.push(format!("speed ('{value}' is not a number)")),
            },
            "projector" => match value.parse::<bool>() {
                Ok(on) => settings.projector = on,
                Err(_) => ignored.push(format!("projector ('{value}' is not true or false)")),
            },
            _ => match (name.parse::<Key>(), value.parse::<f64>()) {
                (Ok(key), Ok(number)) => entries.push(Entry {
                    name: name.to_owned(),
                    set: Write::Key(key),
                    value: number,
                }),
                (Ok(_), Err(_)) => ignored.push(format!("{name} ('{value}' is not a number)")),
                (Err(_), _) => ignored.push(format!(
                    "{} (not a setting)",
                    clipped(name, MOST_LINE_CHARS)
                )),
            },
        }
    }
    let preset = preset.unwrap_or_else(|| {
        if !entries.is_empty() {
            ignored.push(format!(
                "the parameters ({}: no preset says what they belong to)",
                entries
                    .iter()
                    .map(|e| e.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
            entries.clear();
        }
        settings.preset
    });
    settings.preset = preset;
    settings.model = read_parameters(preset.model(), entries, &mut ignored);
    Ok(Read { settings, ignored })
}

/// The `name = value` lines of `text` (blank lines and `#` comments
/// skipped), naming in `ignored` each other line by its number.
fn name_value_lines<'a>(text: &'a str, ignored: &mut Vec<String>) -> Vec<(&'a str, &'a str)> {
    let mut lines = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        match line.split_once('=') {
            Some((name, value)) if !name.trim().is_empty() => {
                lines.push((name.trim(), value.trim()));
            }
            _ => ignored.push(format!(
                "line {} '{}' (not name = value)",
                number + 1,
                clipped(line, MOST_LINE_CHARS)
            )),
        }
    }
    lines
}

/// The parameters onto `base` (the preset's model) in the order that sets
/// the load last, each kept when the model stays valid: a key of another
/// load (`R` on a follower column) or a value out of range is named.
///
/// Rods set with no load start the load where the preset's stands on its
/// bar ([`Model::load_in_place_of`]), as rods typed in the window do:
/// `rods = 16` alone used to leave p = 2 on a bar of 0 to 0.125.
fn read_parameters(base: Model, mut entries: Vec<Entry>, ignored: &mut Vec<String>) -> Model {
    let sets = |wanted: &dyn Fn(Key) -> bool| {
        entries
            .iter()
            .any(|entry| matches!(entry.set, Write::Key(key) if wanted(key)))
    };
    let rods_without_load =
        sets(&|key| key == Key::Rods) && !sets(&|key| key.spec().stage == LOAD_STAGE);
    entries.sort_by_key(|entry| match entry.set {
        Write::Key(key) => key.spec().stage,
        Write::Field(_) => 0,
    });
    let mut model = apply(base, entries, ignored);
    if rods_without_load {
        let load = model.load_in_place_of(&base);
        let mut moved = model;
        if apply_assignments(
            &mut moved,
            &[Assignment {
                key: Key::Load,
                value: load,
            }],
        )
        .is_ok()
        {
            model = moved;
        }
    }
    model
}

/// The stage of the keys that set the load (`load`, `P`, `R`): the last.
const LOAD_STAGE: u8 = 5;

#[cfg(test)]
mod tests {
    use super::*;

    fn changed(id: PresetId, sets: &[(Key, f64)]) -> Settings {
        let mut model = id.model();
        let assignments: Vec<Assignment> = sets
            .iter()
            .map(|&(key, value)| Assignment { key, value })
            .collect();
        apply_assignments(&mut model, &assignments).unwrap();
        Settings {
            preset: id,
            model,
            engine: EngineKind::Reference,
            speed: 0.3,
            projector: true,
        }
    }

    /// Every preset with parameters changed the way a user changes them
    /// (groups that write several numbers, lengths that scale their rod)
    /// reads back to the same settings, bit for bit, with nothing ignored.
    #[test]
    fn every_preset_changed_reads_back_to_the_last_bit() {
        for &id in PresetId::all() {
            let roller = id.model().roller().is_some();
            let mut sets = vec![
                (Key::L2, 0.7 * id.model().column.rod2.length_m),
                (Key::C1, 0.013),
                (Key::CExt, 0.0021),
                (Key::A, 0.37),
                (Key::Load, 0.3 * id.model().load_bar_max_p() + 1e-9),
            ];
            if roller {
                sets.extend([(Key::Nu, 0.21), (Key::Rho, 0.11), (Key::V, 0.031)]);
            } else {
                sets.push((Key::Eta, 0.83));
            }
            let settings = changed(id, &sets);
            let text = settings.to_text();
            let read = read(&text).unwrap();
            assert_eq!(read.ignored, Vec::<String>::new(), "{id}: {text}");
            assert_eq!(read.settings, settings, "{id}: {text}");
            let bits = |m: &Model| {
                Key::all()
                    .iter()
                    .map(|k| k.get(m).to_bits())
                    .collect::<Vec<_>>()
            };
            assert_eq!(bits(&read.settings.model), bits(&settings.model), "{id}");
        }
    }

    /// The preset's own values are not repeated: the default settings are
    /// four lines. A chain's load is written even where it is the
    /// preset's (read without it, it would start in place on the chain's
    /// bar).
    #[test]
    fn only_what_differs_from_the_preset_is_written() {
        assert_eq!(
            Settings::default().to_text(),
            "preset = roller\nengine = rapier\nspeed = 1\nprojector = false\n"
        );
        let text = changed(PresetId::Ziegler1952, &[(Key::Rods, 4.0), (Key::M2, 1.0)]).to_text();
        assert_eq!(
            text,
            "preset = ziegler-1952\nm2 = 1\nrods = 4\nP = 0.1\nengine = reference\nspeed = 0.3\nprojector = true\n"
        );
    }

    /// One bad line costs that line: the rest is kept, and each refusal
    /// names its line and its reason.
    #[test]
    fn one_bad_line_costs_that_line_only() {
        let text = "# shared by a colleague\n\
                    preset = roller\n\
                    k1 = -1\n\
                    colour = blue\n\
                    s2 = 0.4\n\
                    l2 = 0.5\n\
                    R = lots\n\
                    this line has no equals sign\n\
                    speed = 2\n\
                    speed = 3\n\
                    eta = 0.5\n\
                    engine = bullet\n";
        let read = read(text).unwrap();
        let model = read.settings.model;
        assert_eq!(model.column.rod2.length_m, 0.5);
        assert_eq!(model.column.rod2.com_m, 0.4, "kept once l2 is in");
        assert_eq!(
            model.column.k1_nm_per_rad,
            PresetId::Roller.model().column.k1_nm_per_rad
        );
        assert_eq!(read.settings.speed, 2.0);
        let ignored = read.ignored.join("; ");
        for fragment in [
            "k1 (k1 = -1: must be",
            "colour (not a setting)",
            "R ('lots' is not a number)",
            "line 8 'this line has no equals sign' (not name = value)",
            "speed (given twice; the first is kept)",
            "eta (",
            "engine ('bullet' is none of rapier, reference)",
        ] {
            assert!(ignored.contains(fragment), "{fragment}: {ignored}");
        }
        assert_eq!(read.ignored.len(), 7, "{ignored}");
    }

    /// Text of many lines is read in one pass and named briefly: 16 kB
    /// of repeated or bad lines name ten and count the rest; longer text is
    /// refused by its size before any line is read.
    #[test]
    fn long_text_is_bounded_and_named_briefly() {
        let repeated = format!("preset = roller\n{}", "speed = 2\n".repeat(1500));
        assert!(repeated.len() <= MOST_SETTINGS_BYTES);
        let read = read(&repeated).unwrap();
        assert_eq!(read.settings.speed, 2.0);
        assert_eq!(read.ignored.len(), MOST_IGNORED_NAMED + 1);
        assert_eq!(read.ignored.last().unwrap(), "1489 more");
        let huge = "speed = 2\n".repeat(300_000);
        assert_eq!(
            super::read(&huge).unwrap_err(),
            SettingsError::TooLong { bytes: huge.len() }
        );
        assert!(
            super::read(&huge)
                .unwrap_err()
                .to_string()
                .contains("at most 16384")
        );
    }

    /// The vocabulary of `--set`: the load and the groups read as they do
    /// on the command line, whatever order they come in.
    #[test]
    fn the_groups_of_the_command_line_read_as_there() {
        let read = read("load = 2.5\nl1 = 2\npreset = ziegler-1952\n").unwrap();
        assert!(read.ignored.is_empty(), "{:?}", read.ignored);
        let mut expected = PresetId::Ziegler1952.model();
        apply_assignments(
            &mut expected,
            &[
                Assignment {
                    key: Key::L1,
                    value: 2.0,
                },
                Assignment {
                    key: Key::Load,
                    value: 2.5,
                },
            ],
        )
        .unwrap();
        assert_eq!(read.settings.model, expected);
        assert_eq!(read.settings.model.load_p(), 2.5);
    }

    /// Text with nothing of settings in it is an error, not the defaults
    /// quietly; parameters with no preset are named, not guessed.
    #[test]
    fn text_without_settings_is_refused_and_parameters_need_a_preset() {
        for text in ["", "   \n# only a comment\n", "{{ not a setup }}"] {
            let error = read(text).unwrap_err().to_string();
            assert!(error.starts_with("not settings text"), "{error}");
        }
        let read = read("k1 = 2\nspeed = 2").unwrap();
        assert_eq!(read.settings.model, PresetId::Roller.model());
        assert_eq!(read.settings.speed, 2.0);
        assert!(
            read.ignored[0].contains("k1: no preset says"),
            "{:?}",
            read.ignored
        );
    }

    /// Settings stored in the earlier RON format read to the same settings,
    /// and are then written as `name = value` text that reads back to them.
    #[test]
    fn the_earlier_format_is_read_once_and_written_anew() {
        let settings = changed(
            PresetId::Beck,
            &[(Key::Rods, 5.0), (Key::C2, 0.01), (Key::Load, 0.2)],
        );
        let old = ron::to_string(&settings).unwrap();
        let migrated = read(&old).unwrap();
        assert!(migrated.ignored.is_empty(), "{:?}", migrated.ignored);
        assert_eq!(migrated.settings, settings);
        let text = migrated.settings.to_text();
        assert!(text.starts_with("preset = beck\n"), "{text}");
        assert_eq!(read(&text).unwrap().settings, settings);
    }

    /// Rods with no load start the load where the preset's stands on its
    /// bar (a 16-rod chain's bar is 64 times shorter than two rods'); a
    /// load given is kept; a chain at the preset's own load is written
    /// with its load, so it reads back as it was.
    #[test]
    fn a_chain_without_a_load_starts_inside_its_bar() {
        let preset = PresetId::Tabletop.model();
        let read_model = |text: &str| read(text).unwrap().settings.model;
        let chain = read_model("preset = tabletop\nrods = 16\n");
        assert_eq!(chain.column.rods, 16);
        assert!(
            (chain.load_p() - preset.load_p() / 64.0).abs() < 1e-15,
            "{} against {}",
            chain.load_p(),
            preset.load_p()
        );
        assert!(chain.load_p() < chain.load_bar_max_p());
        let given = read_model("preset = tabletop\nrods = 16\nload = 0.1\n");
        assert!((given.load_p() - 0.1).abs() < 1e-15);
        let at_preset_load = changed(PresetId::Tabletop, &[(Key::Rods, 16.0)]);
        let text = at_preset_load.to_text();
        assert_eq!(read(&text).unwrap().settings, at_preset_load, "{text}");
    }
}
