//! The pseudo-language: English accented and made 40% longer, so that a
//! layout test catches text that would not fit a longer language, and a
//! word left in the code shows up unaccented.

use std::borrow::Cow;

/// How much longer the pseudo-language is than English, at least, in
/// tenths (14: 40% longer).
pub const LONGER_TENTHS: usize = 14;

/// The accented letter for an ASCII one (Latin letters with diacritics,
/// which egui's fonts have).
fn accented(c: char) -> char {
    const FROM: &str = "aceinorsuyzACEINORSUYZ";
    const TO: &str = "áçéîñöřšûýžÁÇÉÎÑÖŘŠÛÝŽ";
    FROM.chars()
        .zip(TO.chars())
        .find_map(|(from, to)| (from == c).then_some(to))
        .unwrap_or(c)
}

/// `text` accented, each vowel doubled and the whole padded with `~` to at
/// least [`LONGER_TENTHS`] tenths of its length: the transform Fluent applies to the
/// pseudo-language's text (not to its placeables).
#[must_use]
pub fn transform(text: &str) -> Cow<'_, str> {
    let mut out = String::with_capacity(text.len() * 2);
    let mut chars = 0usize;
    for c in text.chars() {
        out.push(accented(c));
        chars += 1;
        if "aeiouAEIOU".contains(c) {
            out.push(accented(c));
        }
    }
    let mut length = out.chars().count();
    let wanted = (chars * LONGER_TENTHS).div_ceil(10);
    while length < wanted {
        out.push('~');
        length += 1;
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pseudo_language_is_accented_and_forty_percent_longer() {
        for text in ["flutter", "Load p", "rhythm", "", "a"] {
            let pseudo = transform(text);
            let (n, m) = (text.chars().count(), pseudo.chars().count());
            assert!(10 * m >= LONGER_TENTHS * n, "{text} -> {pseudo}");
        }
        assert_eq!(transform("flutter"), "flûûttééř~");
        assert_eq!(transform("rhythm"), "řhýthm~~~");
    }
}
