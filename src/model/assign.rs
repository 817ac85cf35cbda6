//! `key=value` read and applied to a model: each key checked, the keys put
//! in the order that sets the load last, the result validated.

use super::keys::{Key, KeySpec, Sign};
use super::params::Model;
use super::valid::ValidModel;
use super::{Allowed, ModelError};

/// A parsed `key=value`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Assignment {
    pub key: Key,
    pub value: f64,
}

/// Parses `key=value` with a decimal number (`nan` and `inf` parse and are
/// rejected later, with the key named).
///
/// # Errors
/// [`ModelError::Malformed`] when there is no `=` or the value is not a
/// number, [`ModelError::UnknownKey`] for a name that is no key.
pub fn parse_assignment(text: &str) -> Result<Assignment, ModelError> {
    let malformed = |reason: &str| ModelError::Malformed {
        text: text.to_owned(),
        reason: reason.to_owned(),
    };
    let (key, value) = text.split_once('=').ok_or_else(|| malformed("no '='"))?;
    let key = key.trim();
    if key.is_empty() {
        return Err(malformed("empty key"));
    }
    let value = value
        .trim()
        .parse::<f64>()
        .map_err(|_| malformed(&format!("'{}' is not a number", value.trim())))?;
    Ok(Assignment {
        key: key.parse()?,
        value,
    })
}

/// Keys that write the same quantity; setting both is ambiguous.
const CONFLICTS: [(Key, Key); 6] = [
    (Key::M3, Key::Nu),
    (Key::RollerRadius, Key::Rho),
    (Key::K1, Key::A),
    (Key::K2, Key::A),
    (Key::Load, Key::P),
    (Key::Load, Key::NormalForce),
];

/// Applies the assignments to `model` in the canonical order and validates the result.
///
/// # Errors
/// Unknown or inapplicable key, a key given twice or with a conflicting
/// partner, a value out of range (named by the key the user typed), or a
/// resulting model that [`Model::validate`] rejects. On success `model`
/// holds the result, and the same model comes back checked, as a
/// [`ValidModel`] the simulation and the analysis take without checking it
/// again.
pub fn apply_assignments(
    model: &mut Model,
    assignments: &[Assignment],
) -> Result<ValidModel, ModelError> {
    let mut specs: Vec<&KeySpec> = Vec::with_capacity(assignments.len());
    for assignment in assignments {
        let key = assignment.key;
        if !key.applies_to(model) {
            if let Some(why) = key.why_absent(model) {
                return Err(ModelError::invalid(key, assignment.value, why));
            }
            return Err(ModelError::UnknownKey {
                key: key.name().to_owned(),
                known: Key::names_for(model),
            });
        }
        let spec = key.spec();
        for earlier in &specs {
            let clash = earlier.key == spec.key
                || CONFLICTS.iter().any(|&(a, b)| {
                    (a, b) == (earlier.key, spec.key) || (b, a) == (earlier.key, spec.key)
                });
            if clash {
                return Err(ModelError::Conflict {
                    first: earlier.key,
                    second: spec.key,
                });
            }
        }
        specs.push(spec);
    }
    let mut order: Vec<(&KeySpec, f64)> = specs
        .into_iter()
        .zip(assignments.iter().map(|assignment| assignment.value))
        .collect();
    order.sort_by_key(|(spec, _)| spec.stage);
    for (spec, value) in order {
        check_sign(spec, value)?;
        (spec.set)(model, value);
        if let Some((what, _)) = model.beyond_analysis() {
            return Err(ModelError::invalid(
                spec.key,
                value,
                Allowed::MakesBeyondAnalysis(what),
            ));
        }
    }
    ValidModel::new(*model)
}

fn check_sign(spec: &KeySpec, value: f64) -> Result<(), ModelError> {
    #[expect(clippy::cast_precision_loss, reason = "small counts")]
    let ok = value.is_finite()
        && match spec.sign {
            Sign::Positive => value > 0.0,
            Sign::NonNegative => value >= 0.0,
            Sign::Count(min, max) => {
                value.fract() == 0.0 && (min as f64..=max as f64).contains(&value)
            }
        };
    if ok {
        Ok(())
    } else {
        Err(ModelError::invalid(
            spec.key,
            value,
            Allowed::KeyRange(spec.key),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `Key::spec` indexes `KEYS` by the variant: the two orders must agree,
    /// and every name reads back as its key.
    #[test]
    fn every_key_reads_back_from_its_name_and_finds_its_spec() {
        for &key in Key::all() {
            assert_eq!(key.spec().key, key);
            assert_eq!(key.name().parse::<Key>().unwrap(), key);
            assert_eq!(key.to_string(), key.name());
        }
        let unknown = "colour".parse::<Key>().unwrap_err();
        assert!(unknown.to_string().contains("unknown key 'colour'"));
        // r and R are different keys.
        assert_ne!("r".parse::<Key>().unwrap(), "R".parse::<Key>().unwrap());
    }

    #[test]
    fn a_key_of_another_load_is_refused_naming_the_model_s_keys() {
        let mut column = super::super::PresetId::UniformRods.model();
        let set_r = Assignment {
            key: Key::NormalForce,
            value: 3.0,
        };
        let error = apply_assignments(&mut column, &[set_r]).unwrap_err();
        let text = error.to_string();
        assert!(text.starts_with("unknown key 'R'"), "{text}");
        assert!(text.contains("load, a, l1"), "{text}");
        assert!(!text.contains("nu"), "{text}");
    }
}
