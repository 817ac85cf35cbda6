//! The scene in words, for a screen reader: what the straight column does
//! at the load (stable, flutter, divergence, and how fast), and how far the
//! column swings now; refreshed at most twice a second.

use super::speak::status_words;
use crate::tr;
use eframe::egui;

use super::state::AppState;
use crate::analysis::{State, classify};
use crate::format::number_text;
use crate::sim::Status;

/// The least time between two changes of the words, in seconds: a screen
/// reader is not flooded by a number that changes every frame.
const REFRESH_SECS: f64 = 0.5;

/// Two significant digits of `value`.
fn rounded(value: f64) -> String {
    if value == 0.0 || !value.is_finite() {
        return number_text(value);
    }
    let digits = 1.0 - value.abs().log10().floor();
    #[expect(clippy::cast_possible_truncation, reason = "a handful of digits")]
    let scale = 10f64.powi(digits as i32);
    number_text((value * scale).round() / scale)
}

/// How far the column swings now, in radians: the largest of the rods'
/// amplitudes at the dominant frequency `omega_rad_per_s` (the angle and
/// the rate of a harmonic swing), or of their angles where it does not
/// oscillate.
fn swing_rad(state: &AppState, omega_rad_per_s: f64) -> f64 {
    let now = state.simulation().observe();
    now.angles_rad
        .iter()
        .zip(&now.rates_rad_per_s)
        .map(|(angle, rate)| {
            if omega_rad_per_s > 0.0 {
                angle.hypot(rate / omega_rad_per_s)
            } else {
                angle.abs()
            }
        })
        .fold(0.0, f64::max)
}

/// What the column does, in a sentence or two.
#[must_use]
pub fn scene_text(state: &AppState) -> String {
    let words = state.words();
    let stopped = match state.simulation().status() {
        Status::Running => None,
        status => Some(tr!(
            words,
            "scene-stopped",
            status = status_words(words, status)
        )),
    };
    let spectrum = state.current_spectrum();
    let stability = spectrum.map(|s| classify(&s.eigenvalues, s.scale_per_s));
    let omega = stability.map_or(0.0, |s| s.frequency_rad_per_s());
    let swing = tr!(words, "scene-swing", rad = rounded(swing_rad(state, omega)));
    let text = match stability {
        _ if state.answer_hidden() => tr!(words, "scene-hidden", swing = swing),
        None => tr!(words, "scene-analysing", swing = swing),
        Some(s) => {
            let rate = s.growth_rate_per_s();
            match s.state {
                State::Stable if rate < -s.tolerance_per_s => tr!(
                    words,
                    "scene-stable",
                    secs = rounded(100f64.ln() / -rate),
                    swing = swing
                ),
                State::Stable => tr!(words, "scene-undamped", swing = swing),
                State::Flutter => tr!(
                    words,
                    "scene-flutter",
                    secs = rounded(2f64.ln() / rate),
                    frequency = rounded(s.frequency_rad_per_s()),
                    swing = swing
                ),
                State::Divergence => tr!(
                    words,
                    "scene-divergence",
                    secs = rounded(2f64.ln() / rate),
                    swing = swing
                ),
            }
        }
    };
    match stopped {
        Some(stopped) => format!("{text}. {stopped}"),
        None => text,
    }
}

/// The words for the node `id`, kept for [`REFRESH_SECS`] before they
/// follow `now`'s: the time is egui's, the words the last ones given.
pub fn throttled(ctx: &egui::Context, id: egui::Id, now: impl FnOnce() -> String) -> String {
    let time = ctx.input(|input| input.time);
    let key = id.with("words");
    let kept: Option<(f64, String)> = ctx.data(|data| data.get_temp(key));
    match kept {
        Some((at, text)) if time - at < REFRESH_SECS && time >= at => text,
        _ => {
            let text = now();
            ctx.data_mut(|data| data.insert_temp(key, (time, text.clone())));
            text
        }
    }
}

#[cfg(test)]
mod tests {
    use super::rounded;

    #[test]
    fn two_significant_digits() {
        assert_eq!(rounded(0.123_4), "0.12");
        assert_eq!(rounded(2.71), "2.7");
        assert_eq!(rounded(41.2), "41");
        assert_eq!(rounded(0.0), "0");
    }
}
