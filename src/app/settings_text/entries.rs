//! A stored number on its way into a model, however it was stored (the
//! settings text, the earlier RON format): where it goes, and how a list of
//! them is applied so that one bad entry does not cost the rest.

use crate::model::{Assignment, Key, Model, ValidModel, apply_assignments};

/// Writes one number of a model.
pub(super) type Setter = fn(&mut Model, f64);

/// One stored number: where it goes, what it is called, its value.
pub(super) struct Entry {
    pub(super) name: String,
    pub(super) set: Write,
    pub(super) value: f64,
}

/// How a stored number is written: into its field, or as the key of
/// `--set` (checked as the command line checks it: `rods = 2.5: must be a
/// whole number from 2 to 64`).
#[derive(Clone, Copy)]
pub(super) enum Write {
    Field(Setter),
    Key(Key),
}

/// Applies the entries in order, each kept when the model stays valid and
/// within the analysis's range; a refused one is tried again once the others
/// are in (a centre of mass may need its rod's new length).
pub(super) fn apply(mut model: Model, entries: Vec<Entry>, ignored: &mut Vec<String>) -> Model {
    let mut pending = entries;
    for last_pass in [false, true] {
        let mut refused = Vec::new();
        for entry in pending {
            let mut candidate = model;
            // Validation covers the analysis's range too (`beyond_analysis`).
            let written = match entry.set {
                Write::Field(set) => {
                    set(&mut candidate, entry.value);
                    ValidModel::new(candidate)
                }
                Write::Key(key) => apply_assignments(
                    &mut candidate,
                    &[Assignment {
                        key,
                        value: entry.value,
                    }],
                ),
            };
            match written.map_err(|e| e.to_string()) {
                Ok(_) => model = candidate,
                Err(why) if last_pass => ignored.push(format!("{} ({why})", entry.name)),
                Err(_) => refused.push(entry),
            }
        }
        pending = refused;
    }
    model
}
