//! A stored model read number by number onto its preset's model: each
//! number that reads and keeps the model valid is taken, each other one is
//! named with the reason, so one bad entry does not cost the rest.

use std::collections::BTreeMap;

use ron::value::RawValue;
use serde::Deserialize;
use serde::de::{MapAccess, Visitor};

use super::super::entries::{Entry, Setter, Write, apply};
use crate::model::{Key, Load, Model, SpinInertia};

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
        // The names are not checked here: the reader names what it does not know.
        deserializer.deserialize_struct("Fields", &[], FieldsVisitor)
    }
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

/// Every number of a column, by its name in the stored text (the count of
/// rods is read as `--set rods` reads it, see [`read_model`]).
const COLUMN: [(&str, Setter); 6] = [
    ("tip_mass_kg", |m, v| m.column.tip_mass_kg = v),
    ("k1_nm_per_rad", |m, v| m.column.k1_nm_per_rad = v),
    ("k2_nm_per_rad", |m, v| m.column.k2_nm_per_rad = v),
    ("c1_nms_per_rad", |m, v| m.column.c1_nms_per_rad = v),
    ("c2_nms_per_rad", |m, v| m.column.c2_nms_per_rad = v),
    ("drag_ns_per_m2", |m, v| m.column.drag_ns_per_m2 = v),
];

/// Every number of rod 1 and rod 2 (lengths first: a centre of mass is
/// checked against its rod's length).
const RODS: [[(&str, Setter); 4]; 2] = [
    [
        ("length_m", |m, v| m.column.rod1.length_m = v),
        ("mass_kg", |m, v| m.column.rod1.mass_kg = v),
        ("com_m", |m, v| m.column.rod1.com_m = v),
        ("inertia_kg_m2", |m, v| m.column.rod1.inertia_kg_m2 = v),
    ],
    [
        ("length_m", |m, v| m.column.rod2.length_m = v),
        ("mass_kg", |m, v| m.column.rod2.mass_kg = v),
        ("com_m", |m, v| m.column.rod2.com_m = v),
        ("inertia_kg_m2", |m, v| m.column.rod2.inertia_kg_m2 = v),
    ],
];

/// Every number of the roller.
const ROLLER: [(&str, Setter); 5] = [
    ("mass_kg", |m, v| with_roller(m, |r| r.mass_kg = v)),
    ("radius_m", |m, v| with_roller(m, |r| r.radius_m = v)),
    ("mu", |m, v| with_roller(m, |r| r.mu = v)),
    ("normal_force_n", |m, v| {
        with_roller(m, |r| r.normal_force_n = v);
    }),
    ("band_speed_m_per_s", |m, v| {
        with_roller(m, |r| r.band_speed_m_per_s = v);
    }),
];

fn with_roller(model: &mut Model, set: impl FnOnce(&mut crate::model::Roller)) {
    if let Load::Roller(roller) = &mut model.load {
        set(roller);
    }
}

/// Moves each known number of `fields` into `entries` (named `prefix.name`),
/// naming the unknown and unreadable ones in `ignored`.
fn numbers(
    mut fields: Fields,
    prefix: &str,
    known: &[(&str, Setter)],
    entries: &mut Vec<Entry>,
    ignored: &mut Vec<String>,
) {
    for &(name, set) in known {
        let Some(raw) = fields.0.remove(name) else {
            continue;
        };
        let name = format!("{prefix}.{name}");
        if let Some(value) = field::<f64>(Some(&raw), &name, ignored) {
            entries.push(Entry {
                name,
                set: Write::Field(set),
                value,
            });
        }
    }
    ignored.extend(
        fields
            .0
            .into_keys()
            .map(|name| format!("{prefix}.{name} (not a field)")),
    );
}

/// The load's variant name and its contents as RON, e.g. `Roller` and
/// `(mass_kg: 0.1, ...)`.
fn variant(text: &str) -> Option<(&str, String)> {
    let text = text.trim();
    let open = text.find('(')?;
    let inner = text[open + 1..].strip_suffix(')')?.trim();
    let (name, inner) = (text[..open].trim(), inner.to_owned());
    // A struct variant writes its fields bare, a newtype one wraps them.
    let inner = if inner.starts_with('(') {
        inner
    } else {
        format!("({inner})")
    };
    Some((name, inner))
}

/// The stored `model` read onto `base` (the stored preset's model), number
/// by number. What could not be read or would make the model invalid is
/// named in `ignored` (as `model.column.k1_nm_per_rad (k1 = -1: ...)`).
pub fn read_model(raw: &RawValue, base: Model, ignored: &mut Vec<String>) -> Model {
    let Some(mut model_fields) = field::<Fields>(Some(raw), "model", ignored) else {
        return base;
    };
    let mut entries = Vec::new();
    if let Some(column) = model_fields.0.remove("column")
        && let Some(mut column) = field::<Fields>(Some(&column), "model.column", ignored)
    {
        for (i, rod) in RODS.iter().enumerate() {
            let name = format!("model.column.rod{}", i + 1);
            if let Some(raw) = column.0.remove(&format!("rod{}", i + 1))
                && let Some(rod_fields) = field::<Fields>(Some(&raw), &name, ignored)
            {
                numbers(rod_fields, &name, rod, &mut entries, ignored);
            }
        }
        if let Some(raw) = column.0.remove("rods")
            && let Some(value) = field::<f64>(Some(&raw), "model.column.rods", ignored)
        {
            entries.push(Entry {
                name: "model.column.rods".to_owned(),
                set: Write::Key(Key::Rods),
                value,
            });
        }
        numbers(column, "model.column", &COLUMN, &mut entries, ignored);
    }
    if let Some(load) = model_fields.0.remove("load") {
        read_load(&load, &base, &mut entries, ignored);
    }
    ignored.extend(
        model_fields
            .0
            .into_keys()
            .map(|name| format!("model.{name} (not a field)")),
    );
    apply(base, entries, ignored)
}

/// The load's numbers, when its kind is the preset's.
fn read_load(raw: &RawValue, base: &Model, entries: &mut Vec<Entry>, ignored: &mut Vec<String>) {
    let Some((kind, inner)) = variant(raw.get_ron()) else {
        ignored.push("model.load (not a load)".to_owned());
        return;
    };
    let expected = match base.load {
        Load::Follower { .. } => "Follower",
        Load::Roller(_) => "Roller",
    };
    if kind != expected {
        ignored.push(format!(
            "model.load (a {kind} load; the preset's is {expected})"
        ));
        return;
    }
    let Some(mut load) = RawValue::from_ron(&inner)
        .ok()
        .and_then(|raw| field::<Fields>(Some(raw), "model.load", ignored))
    else {
        return;
    };
    if kind == "Roller" {
        if let Some(spin) = load.0.remove("spin")
            && spin.into_rust::<SpinInertia>().ok() != base.roller().map(|r| r.spin)
        {
            ignored.push("model.load.spin (not the preset's spin inertia)".to_owned());
        }
        numbers(load, "model.load", &ROLLER, entries, ignored);
    } else {
        let force: [(&str, Setter); 2] = [
            ("force_n", |m, v| {
                if let Load::Follower { force_n, .. } = &mut m.load {
                    *force_n = v;
                }
            }),
            ("eta", |m, v| {
                if let Load::Follower { eta, .. } = &mut m.load {
                    *eta = v;
                }
            }),
        ];
        numbers(load, "model.load", &force, entries, ignored);
    }
}
