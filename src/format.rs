//! Numbers for people: every formatter the app, the CLI and the error messages
//! use, in one place (pure; no UI).

/// A number for people and for editing: plain with up to six significant
/// digits from 1e-3 to 1e6, in exponent form outside (so 1e-6 is not shown
/// as 0.0000), "0" for zero.
#[must_use]
pub fn number_text(value: f64) -> String {
    let magnitude = value.abs();
    if value == 0.0 {
        // -0 too: a sign on nothing is noise to a reader.
        "0".to_owned()
    } else if !value.is_finite() {
        format!("{value}")
    } else if (1e-3..1e6).contains(&magnitude) {
        // Six significant digits, trailing zeros dropped.
        #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
        let decimals = (5 - magnitude.log10().floor() as i32).max(0);
        let text = format!("{value:.*}", decimals.unsigned_abs() as usize);
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_owned()
        } else {
            text
        }
    } else {
        let text = format!("{value:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

/// A word the user typed, as a message repeats it: at most `most_chars`
/// characters, and the length of the rest said (a 4096-character token is
/// not echoed whole).
#[must_use]
pub fn clipped(text: &str, most_chars: usize) -> String {
    let count = text.chars().count();
    if count <= most_chars {
        text.to_owned()
    } else {
        let head: String = text.chars().take(most_chars).collect();
        format!("{head}... ({count} characters)")
    }
}

/// A growth rate, signed: five decimals, or four significant digits when small.
#[must_use]
pub fn rate_text(rate: f64) -> String {
    if rate == 0.0 || rate.abs() >= 1e-3 {
        format!("{rate:+.5}")
    } else {
        format!("{rate:+.3e}")
    }
}

/// A measured value and its uncertainty as a measurement is written: the
/// uncertainty to two significant digits, the value to the same decimal
/// place, signed if `signed` (`+0.00042 ± 0.00030`, `0.9205 ± 0.0013`);
/// past six decimals a small value shares its uncertainty's exponent
/// (`(-1.33 ± 0.46)e-7`), and a larger one stops at the sixth
/// (`2.196425 ± <0.000001`).
#[must_use]
pub fn measured_text(value: f64, uncertainty: f64, signed: bool) -> String {
    const MOST_DECIMALS: i32 = 6;
    let fixed = |x: f64, decimals: usize, signed: bool| {
        if signed {
            format!("{x:+.decimals$}")
        } else {
            format!("{x:.decimals$}")
        }
    };
    // Two significant digits of the uncertainty: its decimal places.
    #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
    let places = |u: f64| (1 - u.log10().floor() as i32).max(0);
    if !(uncertainty.is_finite() && uncertainty > 0.0 && value.is_finite()) {
        return format!("{} ± ?", fixed(value, 6, signed));
    }
    let decimals = places(uncertainty);
    if decimals <= MOST_DECIMALS {
        let d = decimals.unsigned_abs() as usize;
        return format!(
            "{} ± {}",
            fixed(value, d, signed),
            fixed(uncertainty, d, false)
        );
    }
    if value.abs() >= 1e-3 {
        return format!("{} ± <0.000001", fixed(value, 6, signed));
    }
    #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
    let exponent = value.abs().max(uncertainty).log10().floor() as i32;
    let scale = 10f64.powi(-exponent);
    let d = places(uncertainty * scale)
        .min(MOST_DECIMALS)
        .unsigned_abs() as usize;
    format!(
        "({} ± {})e{exponent}",
        fixed(value * scale, d, signed),
        fixed(uncertainty * scale, d, false)
    )
}

/// A percentage: two decimals, or three significant digits when small.
#[must_use]
pub fn percent_text(percent: f64) -> String {
    if percent.abs() >= 0.01 {
        format!("{percent:.2}%")
    } else {
        format!("{percent:.2e}%")
    }
}

/// A time in s: one decimal from 10 s, three significant digits below.
#[must_use]
pub fn secs_text(secs: f64) -> String {
    if secs >= 10.0 {
        format!("{secs:.1}")
    } else if secs >= 1e-3 {
        format!("{secs:.3}")
    } else {
        format!("{secs:.2e}")
    }
}

/// A duration in the largest unit that keeps it readable: s below a
/// minute, then min, h, days and years (a growth at the onset of flutter
/// can take years to e-fold).
#[must_use]
pub fn duration_text(secs: f64) -> String {
    const MINUTE: f64 = 60.0;
    const HOUR: f64 = 60.0 * MINUTE;
    const DAY: f64 = 24.0 * HOUR;
    const YEAR: f64 = 365.25 * DAY;
    let magnitude = secs.abs();
    if !magnitude.is_finite() {
        return "forever".to_owned();
    }
    let (value, unit) = if magnitude < MINUTE {
        return format!("{} s", secs_text(secs));
    } else if magnitude < HOUR {
        (secs / MINUTE, "min")
    } else if magnitude < DAY {
        (secs / HOUR, "h")
    } else if magnitude < YEAR {
        (secs / DAY, "days")
    } else {
        (secs / YEAR, "years")
    };
    format!("{} {unit}", number_text(round_to_3(value)))
}

/// `value` to three significant digits.
fn round_to_3(value: f64) -> f64 {
    if value == 0.0 || !value.is_finite() {
        return value;
    }
    #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
    let digits = 2 - value.abs().log10().floor() as i32;
    let scale = 10f64.powi(digits);
    (value * scale).round() / scale
}

/// A load: four decimals, or three significant digits when it is below
/// 1e-3 (the roller's first flutter load scales with nu), five from 1e6.
#[must_use]
pub fn load_text(load: f64) -> String {
    let magnitude = load.abs();
    if load == 0.0 || (1e-3..1e6).contains(&magnitude) || !magnitude.is_finite() {
        format!("{load:.4}")
    } else if magnitude < 1e-3 {
        format!("{load:.2e}")
    } else {
        format!("{load:.4e}")
    }
}

/// An axis tick at `value` on a grid of spacing `step`, on an axis that
/// spans `span`: plain with as many decimals as the step needs when the axis
/// spans 0.01 to 1e5 ("0.25", "-1", "0"), in exponent form otherwise
/// ("8e-8", "1.2e-3"), so every tick of an axis has the same form and no
/// label runs to ten digits.
#[must_use]
pub fn tick_text(value: f64, step: f64, span: f64) -> String {
    let step = step.abs();
    if !value.is_finite() || !step.is_finite() || step == 0.0 {
        return format!("{value}");
    }
    // A tick within rounding of zero is zero (no "-0.0").
    if value.abs() < 1e-6 * step {
        return "0".to_owned();
    }
    // Digits after the step's leading digit (the tolerance keeps a step of
    // 0.09999999 from asking for one more).
    #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
    let step_exponent = (step.log10() + 1e-6).floor() as i32;
    if (1e-2..1e5).contains(&span.abs()) {
        format!(
            "{value:.*}",
            (-step_exponent).max(0).unsigned_abs() as usize
        )
    } else {
        #[expect(clippy::cast_possible_truncation, reason = "a small exponent")]
        let value_exponent = (value.abs().log10() + 1e-6).floor() as i32;
        format!(
            "{value:.*e}",
            (value_exponent - step_exponent).max(0).unsigned_abs() as usize
        )
    }
}

/// A number in a message: as Rust writes it for everyday magnitudes, in
/// exponent form beyond them, so no message prints 300 digits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shown(pub f64);

impl std::fmt::Display for Shown {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let magnitude = self.0.abs();
        if magnitude != 0.0 && magnitude.is_finite() && !(1e-4..1e7).contains(&magnitude) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", Exact(self.0))
        }
    }
}

/// A number for a data file: every digit needed to read it back exactly
/// (Rust's shortest round-trip form), in exponent form beyond 1e16 and
/// below 1e-7 (plain, 1e150 is 151 digits and 1e-300 is 302), and zero
/// without a sign: a -0 from rounding means nothing and reads as a negative
/// number to a sign test.
pub struct Exact(pub f64);

/// Magnitudes [`Exact`] writes plain; outside, in exponent form.
const PLAIN_EXACT: std::ops::Range<f64> = 1e-7..1e16;

impl std::fmt::Display for Exact {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.0 == 0.0 {
            f.write_str("0")
        } else if self.0.is_finite() && !PLAIN_EXACT.contains(&self.0.abs()) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A measurement's digits stop where its uncertainty's second digit
    /// does.
    #[test]
    fn a_measurement_is_written_to_its_uncertainty() {
        assert_eq!(
            measured_text(0.000_423, 0.000_301, true),
            "+0.00042 ± 0.00030"
        );
        assert_eq!(measured_text(-0.0021, 0.0004, true), "-0.00210 ± 0.00040");
        assert_eq!(measured_text(0.920_512, 0.001_3, false), "0.9205 ± 0.0013");
        assert_eq!(measured_text(12.34, 25.0, false), "12 ± 25");
        assert_eq!(measured_text(-1.33e-7, 4.6e-8, true), "(-1.33 ± 0.46)e-7");
        assert_eq!(
            measured_text(2.196_424_868, 2.6e-8, false),
            "2.196425 ± <0.000001"
        );
        assert_eq!(measured_text(0.5, f64::NAN, false), "0.500000 ± ?");
    }

    #[test]
    fn long_words_are_clipped_with_their_length() {
        assert_eq!(clipped("roller", 40), "roller");
        assert_eq!(clipped(&"k".repeat(4096), 3), "kkk... (4096 characters)");
    }

    #[test]
    fn numbers_keep_their_significant_digits() {
        for (value, text) in [
            (0.0, "0"),
            (-0.0, "0"),
            (0.1, "0.1"),
            (0.123_456_789, "0.123457"),
            (1234.5, "1234.5"),
            (-0.001, "-0.001"),
            (1e-6, "1e-6"),
            (2.5e6, "2.5e6"),
            (3.0, "3"),
        ] {
            assert_eq!(number_text(value), text, "{value}");
            let read: f64 = text.parse().unwrap();
            assert!((read - value).abs() <= 5e-6 * value.abs(), "{value}");
        }
    }

    #[test]
    fn small_loads_rates_and_times_keep_three_significant_digits() {
        assert_eq!(load_text(2.085_786_437_626_9), "2.0858");
        assert_eq!(load_text(2.382e-4), "2.38e-4");
        assert_eq!(load_text(1e150), "1.0000e150");
        assert_eq!(rate_text(0.004_49), "+0.00449");
        assert_eq!(rate_text(-2.5e-5), "-2.500e-5");
        assert_eq!(percent_text(2.864), "2.86%");
        assert_eq!(percent_text(8.140_47e-6), "8.14e-6%");
        assert_eq!(secs_text(122.04), "122.0");
        assert_eq!(secs_text(1.234_56), "1.235");
        assert_eq!(secs_text(5e-4), "5.00e-4");
    }

    #[test]
    fn ticks_have_the_digits_their_step_needs() {
        for (value, step, span, text) in [
            (0.0, 1.0, 8.0, "0"),
            (1e-17, 0.1, 1.0, "0"),
            (3.0, 1.0, 8.0, "3"),
            (-0.2, 0.1, 1.0, "-0.2"),
            (0.3, 0.099_999_999, 1.0, "0.3"),
            (0.005, 0.005, 0.05, "0.005"),
            // An axis from 8e-4 to 1.4e-3: every tick in exponent form.
            (9e-4, 1e-4, 6e-4, "9e-4"),
            (0.001, 0.001, 6e-4, "1e-3"),
            (0.0012, 1e-4, 6e-4, "1.2e-3"),
            (8e-8, 1e-8, 9e-8, "8e-8"),
            (1.5e-7, 1e-8, 9e-8, "1.5e-7"),
            (2e5, 1e5, 1e6, "2e5"),
            (-1.0, 0.5, 3.0, "-1.0"),
        ] {
            assert_eq!(tick_text(value, step, span), text, "{value} on {step}");
        }
    }

    #[test]
    fn long_durations_are_given_in_readable_units() {
        assert_eq!(duration_text(6.826), "6.826 s");
        assert_eq!(duration_text(242.3), "4.04 min");
        assert_eq!(duration_text(7200.0), "2 h");
        assert_eq!(duration_text(3.0 * 86_400.0), "3 days");
        // Midpoint masses at the flutter onset: 122039455.4 s.
        assert_eq!(duration_text(122_039_455.4), "3.87 years");
        assert_eq!(duration_text(f64::INFINITY), "forever");
    }
}
