//! What marks a state besides its colour, so that a grey print or a
//! colour-blind eye still reads it: divergence is striped ("/"), in the
//! background's colour, on the load bar and on the map, in the window and
//! on paper alike.

use crate::analysis::State;

/// Stripes per unit of the view (the map's stripes: one view's width holds
/// this many).
pub const MAP_STRIPES_PER_VIEW: f64 = 48.0;
/// The share of each stripe's period that is drawn.
pub const STRIPE_SHARE: f64 = 0.35;

/// Whether `state` is striped.
#[must_use]
pub const fn striped(state: State) -> bool {
    matches!(state, State::Divergence)
}

/// Whether the point (`x`, `y`) (y up) lies on a stripe of period
/// `spacing`: the stripes are the bands `0 <= (y - x) / spacing mod 1 <
/// STRIPE_SHARE`.
#[must_use]
pub fn on_stripe(x: f64, y: f64, spacing: f64) -> bool {
    // `v - floor(v)` is `v.rem_euclid(1.0)` (both the exact fractional
    // part, rounded once where v < 0), without fmod's call: a map's image
    // asks this of every striped pixel, half a million.
    let v = (y - x) / spacing;
    v - v.floor() < STRIPE_SHARE
}

/// The stripes of period `spacing` within the rectangle `x` by `y` (y up),
/// each a convex polygon: the bands `k s <= y - x <= (k + STRIPE_SHARE) s`
/// cut to the rectangle.
#[must_use]
pub fn stripes(x: (f64, f64), y: (f64, f64), spacing: f64) -> Vec<Vec<[f64; 2]>> {
    if !(spacing > 0.0 && x.1 > x.0 && y.1 > y.0) {
        return Vec::new();
    }
    let first = ((y.0 - x.1) / spacing - STRIPE_SHARE).ceil();
    let last = ((y.1 - x.0) / spacing).floor();
    if !(first.is_finite() && last.is_finite()) || last - first > 1e5 {
        return Vec::new();
    }
    let rectangle = vec![[x.0, y.0], [x.1, y.0], [x.1, y.1], [x.0, y.1]];
    let mut polygons = Vec::new();
    let mut k = first;
    while k <= last {
        let low = k * spacing;
        let high = (k + STRIPE_SHARE) * spacing;
        let band = cut(&cut(&rectangle, |p| p[1] - p[0] - low), |p| {
            high - (p[1] - p[0])
        });
        if band.len() >= 3 {
            polygons.push(band);
        }
        k += 1.0;
    }
    polygons
}

/// The part of the convex `polygon` where `side` is at least 0 (`side`
/// linear: one step of Sutherland and Hodgman's clipping).
fn cut(polygon: &[[f64; 2]], side: impl Fn([f64; 2]) -> f64) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(polygon.len() + 1);
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let (sa, sb) = (side(a), side(b));
        if sa >= 0.0 {
            out.push(a);
        }
        if (sa >= 0.0) != (sb >= 0.0) {
            let t = sa / (sa - sb);
            out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fractional part by `floor` is `rem_euclid(1.0)`'s, so the
    /// stripes fall on the same pixels as before: over a million values of
    /// both signs, from tiny to large, and the exact integers.
    #[test]
    fn the_stripe_test_is_rem_euclid_s_to_the_bit() {
        let spacing = 1.0 / 12.0;
        let mut checked = 0;
        for k in 0..1_000_000_u32 {
            let t = f64::from(k) / 1e6;
            for (x, y) in [
                (t, 0.3),
                (0.7, t),
                (-t * 1e3, t),
                (t * 1e-12, 0.0),
                (f64::from(k), 0.0),
            ] {
                let v = (y - x) / spacing;
                // Equal as numbers: at an integer rem_euclid's zero may be
                // -0, the compare below the same.
                assert!(v - v.floor() == v.rem_euclid(1.0), "v = {v:e}");
                checked += 1;
            }
        }
        assert_eq!(checked, 5_000_000);
        assert!(on_stripe(0.0, 0.0, spacing));
    }

    /// The area enclosed by `polygon`.
    fn area(polygon: &[[f64; 2]]) -> f64 {
        let n = polygon.len();
        0.5 * (0..n)
            .map(|i| {
                let (a, b) = (polygon[i], polygon[(i + 1) % n]);
                a[0] * b[1] - b[0] * a[1]
            })
            .sum::<f64>()
            .abs()
    }

    /// Every stripe lies inside the rectangle and on the pattern, and
    /// together they cover the stripes' share of it.
    #[test]
    fn the_stripes_lie_on_the_pattern_and_cover_their_share() {
        let (x, y, s) = ((2.0, 7.0), (-1.0, 1.5), 0.4);
        let polygons = stripes(x, y, s);
        let mut covered = 0.0;
        for polygon in &polygons {
            for p in polygon {
                assert!((x.0 - 1e-12..=x.1 + 1e-12).contains(&p[0]), "{p:?}");
                assert!((y.0 - 1e-12..=y.1 + 1e-12).contains(&p[1]), "{p:?}");
            }
            // The centroid is well inside its band.
            #[expect(clippy::cast_precision_loss, reason = "a few vertices")]
            let n = polygon.len() as f64;
            let c = polygon
                .iter()
                .fold([0.0, 0.0], |c, p| [c[0] + p[0] / n, c[1] + p[1] / n]);
            assert!(on_stripe(c[0], c[1], s), "{c:?}");
            covered += area(polygon);
        }
        let whole = (x.1 - x.0) * (y.1 - y.0);
        assert!(
            (covered / whole - STRIPE_SHARE).abs() < 0.03,
            "{}",
            covered / whole
        );
        // A square of whole periods is covered by exactly the share.
        let square: f64 = stripes((0.0, 4.0), (0.0, 4.0), 0.5)
            .iter()
            .map(|p| area(p))
            .sum();
        assert!((square / 16.0 - STRIPE_SHARE).abs() < 1e-12, "{square}");
    }

    /// Of a large square, the share on stripes is the stripes' share.
    #[test]
    fn the_stripes_cover_their_share() {
        let n = 400;
        let on = (0..n * n)
            .filter(|k| on_stripe(f64::from(k % n) / 40.0, f64::from(k / n) / 40.0, 0.7))
            .map(|_| 1.0)
            .sum::<f64>();
        let share = on / f64::from(n * n);
        assert!((share - STRIPE_SHARE).abs() < 0.01, "{share}");
    }

    #[test]
    fn an_empty_rectangle_or_spacing_has_no_stripes() {
        assert!(stripes((1.0, 1.0), (0.0, 1.0), 0.1).is_empty());
        assert!(stripes((0.0, 1.0), (0.0, 1.0), 0.0).is_empty());
        assert!(stripes((0.0, 1.0), (0.0, 1.0), f64::NAN).is_empty());
        assert!(striped(State::Divergence) && !striped(State::Flutter));
    }
}
