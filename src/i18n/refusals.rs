//! The lower layers' refusals, failures and warnings in a language: the
//! data they return (what was refused and what it must be, why a run or an
//! analysis failed, why the stability is not resolved), worded.

use crate::analysis::{AnalysisError, LARGEST_MODE_SPAN, NotResolved};
use crate::format::{Shown, load_text};
use crate::model::{Allowed, LARGEST_DERIVED, ModelError, Quantity, Subject};
use crate::sim::{RAPIER_MAX_RATE_STEP, RampError, SimError};
use crate::tr;

use super::Words;

/// A refused model in `words`' language.
#[must_use]
pub fn model_error(words: &'static Words, error: &ModelError) -> String {
    match error {
        ModelError::Invalid {
            subject,
            value,
            allowed,
        } => refused(words, subject_words(words, *subject), *value, allowed),
        ModelError::UnknownPreset { name, known } => tr!(
            words,
            "refused-unknown-preset",
            name = name.as_str(),
            known = known.as_str()
        ),
        ModelError::UnknownKey { key, known } => tr!(
            words,
            "refused-unknown-key",
            key = key.as_str(),
            known = known.as_str()
        ),
        ModelError::Malformed { text, reason } => tr!(
            words,
            "refused-malformed",
            text = text.as_str(),
            reason = reason.as_str()
        ),
        ModelError::Conflict { first, second } => tr!(
            words,
            "refused-conflict",
            first = first.name(),
            second = second.name()
        ),
    }
}

/// A simulation refused or failed, in `words`' language.
#[must_use]
pub fn sim_error(words: &'static Words, error: &SimError) -> String {
    match error {
        SimError::Model(error) => model_error(words, error),
        SimError::Bad {
            what,
            value,
            allowed,
        } => refused(words, quantity_words(words, *what), *value, allowed),
        SimError::TooStiffForRapier {
            rate_per_s,
            step_secs,
        } => tr!(
            words,
            "engine-too-stiff",
            step = format!("{step_secs:.3e}"),
            rate = format!("{rate_per_s:.3e}"),
            need = format!("{:.3e}", RAPIER_MAX_RATE_STEP / rate_per_s)
        ),
        SimError::RapierWorld => tr!(words, "engine-rapier-world"),
    }
}

/// A failed analysis in `words`' language. The failures only the command
/// line's arguments can cause (a range, a sample count, a choice of
/// derivatives) keep the command line's English.
#[must_use]
pub fn analysis_error(words: &'static Words, error: &AnalysisError) -> String {
    match error {
        AnalysisError::Model(error) => model_error(words, error),
        AnalysisError::NotConverged { load } => tr!(
            words,
            "analysis-not-converged",
            load = Shown(*load).to_string()
        ),
        AnalysisError::TooManySamples { .. }
        | AnalysisError::NotCovered(_)
        | AnalysisError::BadRange { .. } => error.to_string(),
    }
}

/// A refused load ramp in `words`' language. The forms only the command
/// line's text can take (`FROM:TO:RATE` misread) keep its English.
#[must_use]
pub fn ramp_error(words: &'static Words, error: &RampError) -> String {
    let shown = |value: f64| Shown(value).to_string();
    match error {
        RampError::End { end, value } => tr!(
            words,
            "ramp-refused-end",
            end = ramp_end(words, end),
            value = shown(*value)
        ),
        RampError::Rate(rate) => tr!(words, "ramp-refused-rate", value = shown(*rate)),
        RampError::TooSlow(rate) => tr!(
            words,
            "ramp-refused-too-slow",
            value = shown(*rate),
            slowest = shown(crate::sim::SLOWEST_RATE_P_PER_S)
        ),
        RampError::TooLong {
            from_p,
            to_p,
            rate_p_per_s,
            secs,
        } => tr!(
            words,
            "ramp-refused-too-long",
            from = shown(*from_p),
            to = shown(*to_p),
            rate = shown(*rate_p_per_s),
            secs = crate::format::number_text(*secs),
            most = shown(crate::sim::LONGEST_RAMP_SECS)
        ),
        RampError::Refused { end, value, why } => tr!(
            words,
            "ramp-refused-model",
            end = ramp_end(words, end),
            value = shown(*value),
            why = model_error(words, why)
        ),
        RampError::Form(_) | RampError::NotANumber { .. } => error.to_string(),
    }
}

/// A ramp's end ("from" or "to") as the window's ramp fields are named.
fn ramp_end(words: &'static Words, end: &str) -> String {
    words.get(&format!("ramp-{end}.name")).into_owned()
}

/// Why the stability along the locus is not resolved, in `words`' language.
#[must_use]
pub fn not_resolved_words(words: &'static Words, why: &NotResolved) -> String {
    let id = format!("not-resolved-{}", why.id());
    let rate = |per_s: f64| format!("{per_s:.1e}");
    match *why {
        NotResolved::ModeSpan {
            load,
            fastest_per_s,
            slowest_per_s,
        } => tr!(
            words,
            &id,
            load = load_text(load),
            fastest = rate(fastest_per_s),
            slowest = rate(slowest_per_s),
            span = format!("{LARGEST_MODE_SPAN:.0e}")
        ),
        NotResolved::SlowModeLost {
            load,
            scale_per_s,
            slowest_per_s,
            tolerance_per_s,
        } => tr!(
            words,
            &id,
            load = load_text(load),
            scale = format!("{scale_per_s:.0e}"),
            slowest = rate(slowest_per_s),
            tolerance = rate(tolerance_per_s)
        ),
        NotResolved::MethodsDisagree { load } | NotResolved::RefinementCut { load } => {
            tr!(words, &id, load = load_text(load))
        }
        NotResolved::RoundingDecides { low, high } => {
            tr!(words, &id, low = load_text(low), high = load_text(high))
        }
    }
}

fn refused(words: &'static Words, subject: String, value: f64, allowed: &Allowed) -> String {
    tr!(
        words,
        "refused-value",
        subject = subject,
        value = Shown(value).to_string(),
        allowed = allowed_words(words, allowed)
    )
}

fn subject_words(words: &'static Words, subject: Subject) -> String {
    match subject {
        Subject::Key(key) => key.name().to_owned(),
        Subject::Derived(what) => quantity_words(words, what),
    }
}

/// A quantity's name in `words`' language.
#[must_use]
pub fn quantity_words(words: &'static Words, what: Quantity) -> String {
    words.get(&format!("quantity-{}", what.id())).into_owned()
}

/// What a refused value must be, in `words`' language.
#[must_use]
pub fn allowed_words(words: &'static Words, allowed: &Allowed) -> String {
    let id = format!("allowed-{}", allowed.id());
    let range = |key: crate::model::Key| words.get(&format!("key-{}.range", key.name()));
    let text = match *allowed {
        Allowed::KeyRange(key) if key.spec().counts() => {
            tr!(words, "allowed-key-count", range = range(key).into_owned())
        }
        Allowed::KeyRange(key) => tr!(
            words,
            &id,
            range = range(key).into_owned(),
            unit = key.spec().unit
        ),
        Allowed::Between { min, max, max_key } => tr!(
            words,
            &id,
            min = Shown(min).to_string(),
            max = Shown(max).to_string(),
            key = max_key.name()
        ),
        Allowed::Rods { most } => tr!(words, &id, most = most.to_string()),
        Allowed::FrictionTooSmall { load_p } => {
            tr!(words, &id, load = Shown(load_p).to_string())
        }
        Allowed::BeyondAnalysis => tr!(
            words,
            &id,
            smallest = format!("{:e}", 1.0 / LARGEST_DERIVED),
            largest = format!("{LARGEST_DERIVED:e}")
        ),
        Allowed::MakesBeyondAnalysis(what) => tr!(
            words,
            &id,
            what = quantity_words(words, what),
            smallest = format!("{:e}", 1.0 / LARGEST_DERIVED),
            largest = format!("{LARGEST_DERIVED:e}")
        ),
        _ => tr!(words, &id),
    };
    text.trim_end().to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::i18n::{Language, words};
    use crate::model::{Assignment, Key, PRESETS, apply_assignments};
    use strum::VariantArray;

    /// Every refusal the model makes, worded in English, reads as the
    /// command line's (the same data, the same words).
    #[test]
    fn english_words_match_the_command_line() {
        let en = words(Language::English);
        let mut seen = 0;
        for preset in PRESETS {
            for key in Key::VARIANTS.iter().copied() {
                for value in [-1.0, 0.0, 0.5, 1e200, f64::NAN, 1.5] {
                    let mut model = preset.model();
                    let assigned = [Assignment { key, value }];
                    if let Err(error) = apply_assignments(&mut model, &assigned) {
                        seen += 1;
                        let window = model_error(en, &error);
                        // The window says "set the load to 0" where the
                        // command line says "use load=0".
                        let cli = error.to_string().replace(
                            "use load=0 for an unloaded column",
                            "set the load to 0 for an unloaded column",
                        );
                        assert_eq!(window, cli, "{key:?} = {value}");
                    }
                }
            }
        }
        assert!(seen > 100, "only {seen} refusals tried");
    }

    /// One of each kind of [`Allowed`]: a kind added without a place
    /// here fails to compile (the match has no wildcard).
    fn every_allowed() -> Vec<Allowed> {
        let all = vec![
            Allowed::Finite,
            Allowed::Positive,
            Allowed::NonNegative,
            Allowed::KeyRange(Key::L1),
            Allowed::KeyRange(Key::Rods),
            Allowed::Between {
                min: 0.0,
                max: 1.0,
                max_key: Key::L2,
            },
            Allowed::Rods { most: 64 },
            Allowed::EtaRange,
            Allowed::FrictionlessBand,
            Allowed::FrictionTooSmall { load_p: 2.5 },
            Allowed::BeyondAnalysis,
            Allowed::MakesBeyondAnalysis(Quantity::Drag),
            Allowed::MassesTooUnequal,
            Allowed::MassMissing,
            Allowed::ChainMassless,
            Allowed::NeedsDampedJoint2,
            Allowed::InfiniteDamperRatio,
            Allowed::BandAtRest,
            Allowed::RollerHasNoEta,
            Allowed::StateLength,
            Allowed::TimeStep,
        ];
        for allowed in &all {
            match allowed {
                Allowed::Finite
                | Allowed::Positive
                | Allowed::NonNegative
                | Allowed::KeyRange(_)
                | Allowed::Between { .. }
                | Allowed::Rods { .. }
                | Allowed::EtaRange
                | Allowed::FrictionlessBand
                | Allowed::FrictionTooSmall { .. }
                | Allowed::BeyondAnalysis
                | Allowed::MakesBeyondAnalysis(_)
                | Allowed::MassesTooUnequal
                | Allowed::MassMissing
                | Allowed::ChainMassless
                | Allowed::NeedsDampedJoint2
                | Allowed::InfiniteDamperRatio
                | Allowed::BandAtRest
                | Allowed::RollerHasNoEta
                | Allowed::StateLength
                | Allowed::TimeStep => {}
            }
        }
        all
    }

    /// Every refusal and quantity has its message in every language, and
    /// English words each as the command line does.
    #[test]
    fn every_refusal_is_worded_in_every_language() {
        let en = words(Language::English);
        for allowed in every_allowed() {
            let cli = allowed.to_string().replace(
                "use load=0 for an unloaded column",
                "set the load to 0 for an unloaded column",
            );
            assert_eq!(allowed_words(en, &allowed), cli);
            for language in Language::CHOSEN_FROM {
                let words = words(language);
                if !matches!(allowed, Allowed::KeyRange(_)) {
                    assert!(
                        words.has(&format!("allowed-{}", allowed.id())),
                        "{allowed:?}"
                    );
                }
                let text = allowed_words(words, &allowed);
                assert!(
                    !text.is_empty() && !text.contains('{'),
                    "{language:?}: {text}"
                );
            }
        }
        for what in Quantity::VARIANTS {
            for language in Language::CHOSEN_FROM {
                assert!(
                    words(language).has(&format!("quantity-{}", what.id())),
                    "{what:?}"
                );
            }
        }
    }

    /// Why the stability is not resolved: in English as the command line
    /// says it (less its advice on the range, which the window has not),
    /// and in every language without a placeable left.
    #[test]
    fn not_resolved_reads_as_the_command_line() {
        let all = [
            NotResolved::ModeSpan {
                load: 1.5,
                fastest_per_s: 3e9,
                slowest_per_s: 2e-4,
            },
            NotResolved::SlowModeLost {
                load: 0.25,
                scale_per_s: 1e6,
                slowest_per_s: 3e-5,
                tolerance_per_s: 1e-4,
            },
            NotResolved::MethodsDisagree { load: 2.0 },
            NotResolved::RoundingDecides {
                low: 0.1,
                high: 0.2,
            },
            NotResolved::RefinementCut { load: 7.5 },
        ];
        for why in all {
            let cli = why.to_string().replace("; use a narrower range)", ")");
            assert_eq!(not_resolved_words(words(Language::English), &why), cli);
            for language in Language::CHOSEN_FROM {
                let text = not_resolved_words(words(language), &why);
                assert!(
                    !text.contains('{') && text.len() > 80,
                    "{language:?}: {text}"
                );
            }
        }
    }
}
