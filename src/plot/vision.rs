//! How far apart two colours look, to normal and to colour-deficient
//! vision: the CAM02-UCS colour difference (Luo, Cui and Li 2006, on
//! CIECAM02 under sRGB's viewing conditions) of colours as simulated for
//! full protanopia, deuteranopia and tritanopia (Machado, Oliveira and
//! Fernandes 2009, severity 1). The palettes' tests measure with it.

use nalgebra::{Matrix3, Vector3};

use super::Rgb;

/// A way of seeing colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Vision {
    Normal,
    /// No long-wavelength (red) cones.
    Protanopia,
    /// No medium-wavelength (green) cones.
    Deuteranopia,
    /// No short-wavelength (blue) cones.
    Tritanopia,
}

impl Vision {
    pub const ALL: [Self; 4] = [
        Self::Normal,
        Self::Protanopia,
        Self::Deuteranopia,
        Self::Tritanopia,
    ];

    /// Machado et al.'s matrix on linear sRGB at severity 1, none for
    /// normal vision.
    fn matrix(self) -> Option<Matrix3<f64>> {
        let rows = match self {
            Self::Normal => return None,
            Self::Protanopia => [
                [0.152_286, 1.052_583, -0.204_868],
                [0.114_503, 0.786_281, 0.099_216],
                [-0.003_882, -0.048_116, 1.051_998],
            ],
            Self::Deuteranopia => [
                [0.367_322, 0.860_646, -0.227_968],
                [0.280_085, 0.672_501, 0.047_413],
                [-0.011_820, 0.042_940, 0.968_881],
            ],
            Self::Tritanopia => [
                [1.255_528, -0.076_749, -0.178_779],
                [-0.078_411, 0.930_809, 0.147_602],
                [0.004_733, 0.691_367, 0.303_900],
            ],
        };
        Some(Matrix3::from_fn(|i, j| rows[i][j]))
    }

    /// `rgb` as seen with this vision, in linear sRGB (kept within the
    /// display's range, as a screen shows it).
    #[must_use]
    pub fn linear(self, rgb: Rgb) -> Vector3<f64> {
        let linear = Vector3::new(rgb.0, rgb.1, rgb.2).map(|c| decode(f64::from(c) / 255.0));
        match self.matrix() {
            None => linear,
            Some(m) => (m * linear).map(|c| c.clamp(0.0, 1.0)),
        }
    }
}

/// An sRGB channel in [0, 1] as linear light.
fn decode(c: f64) -> f64 {
    if c < 0.040_45 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// CIE XYZ (white's Y = 100) of linear sRGB: the inverse of IEC 61966-2-1's
/// matrix from XYZ.
fn xyz(linear: Vector3<f64>) -> Vector3<f64> {
    let to_srgb = Matrix3::new(
        3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.2040, 1.0570,
    );
    let from_srgb = to_srgb.try_inverse().unwrap_or_else(Matrix3::identity);
    100.0 * from_srgb * linear
}

/// CIECAM02's chromatic adaptation matrix.
fn m_cat02() -> Matrix3<f64> {
    Matrix3::new(
        0.7328, 0.4296, -0.1624, -0.7036, 1.6975, 0.0061, 0.0030, 0.0136, 0.9834,
    )
}

/// Hunt-Pointer-Estevez cone space.
fn m_hpe() -> Matrix3<f64> {
    Matrix3::new(
        0.389_71, 0.688_98, -0.078_68, -0.229_81, 1.183_40, 0.046_41, 0.0, 0.0, 1.0,
    )
}

/// sRGB's viewing conditions (IEC 61966-2-1): the white D65, a background
/// of Y = 20, an adapting luminance of 64/π/5 cd/m² and an average
/// surround.
struct Viewing {
    white: Vector3<f64>,
    background_y: f64,
    adapting_cd_m2: f64,
    f: f64,
    c: f64,
    n_c: f64,
}

const SRGB_VIEWING: Viewing = Viewing {
    white: Vector3::new(95.047, 100.0, 108.883),
    background_y: 20.0,
    adapting_cd_m2: 64.0 / std::f64::consts::PI / 5.0,
    f: 1.0,
    c: 0.69,
    n_c: 1.0,
};

/// The cone responses after adaptation, and the colour's hue angle in
/// radians, lightness J and colourfulness M (CIECAM02).
fn ciecam02(xyz: Vector3<f64>, v: &Viewing) -> (f64, f64, f64) {
    let cat = m_cat02();
    let rgb_w = cat * v.white;
    let degree =
        (v.f * (1.0 - (1.0 / 3.6) * ((-v.adapting_cd_m2 - 42.0) / 92.0).exp())).clamp(0.0, 1.0);
    let gain = rgb_w.map(|w| v.white.y * degree / w + 1.0 - degree);
    let k = 1.0 / (5.0 * v.adapting_cd_m2 + 1.0);
    let k4 = k.powi(4);
    let f_l = 0.2 * k4 * (5.0 * v.adapting_cd_m2)
        + 0.1 * (1.0 - k4).powi(2) * (5.0 * v.adapting_cd_m2).cbrt();
    let n = v.background_y / v.white.y;
    let z = 1.48 + n.sqrt();
    let n_bb = 0.725 * n.recip().powf(0.2);
    let to_cones = m_hpe() * cat.try_inverse().unwrap_or_else(Matrix3::identity);
    let adapted = |xyz: Vector3<f64>| -> Vector3<f64> {
        let cones = to_cones * (cat * xyz).component_mul(&gain);
        cones.map(|c| {
            let t = (f_l * c.abs() / 100.0).powf(0.42);
            400.0 * c.signum() * t / (t + 27.13) + 0.1
        })
    };
    let achromatic = |a: &Vector3<f64>| (2.0 * a.x + a.y + a.z / 20.0 - 0.305) * n_bb;
    let white = adapted(v.white);
    let colour = adapted(xyz);
    let a = colour.x - 12.0 * colour.y / 11.0 + colour.z / 11.0;
    let b = (colour.x + colour.y - 2.0 * colour.z) / 9.0;
    let hue = b.atan2(a);
    let lightness = 100.0 * (achromatic(&colour) / achromatic(&white)).powf(v.c * z);
    let eccentricity = 0.25 * ((hue + 2.0).cos() + 3.8);
    let t = (50_000.0 / 13.0 * v.n_c * n_bb * eccentricity * a.hypot(b))
        / (colour.x + colour.y + 21.0 / 20.0 * colour.z);
    let chroma = t.powf(0.9) * (lightness / 100.0).sqrt() * (1.64 - 0.29f64.powf(n)).powf(0.73);
    (hue, lightness, chroma * f_l.powf(0.25))
}

/// A colour in CAM02-UCS (J', a', b') as seen with `vision`.
#[must_use]
pub fn ucs(rgb: Rgb, vision: Vision) -> [f64; 3] {
    let (hue, j, m) = ciecam02(xyz(vision.linear(rgb)), &SRGB_VIEWING);
    let j_ucs = 1.7 * j / (1.0 + 0.007 * j);
    let m_ucs = (0.0228 * m).ln_1p() / 0.0228;
    [j_ucs, m_ucs * hue.cos(), m_ucs * hue.sin()]
}

/// How far apart `a` and `b` look to `vision`: their distance in CAM02-UCS
/// (about 1 is the smallest visible difference; 20 and more reads at a
/// glance).
#[must_use]
pub fn difference(a: Rgb, b: Rgb, vision: Vision) -> f64 {
    let (p, q) = (ucs(a, vision), ucs(b, vision));
    (0..3).map(|i| (p[i] - q[i]).powi(2)).sum::<f64>().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// colorspacious 1.1.2 (Smith and van der Walt), the reference
    /// implementation of CAM02-UCS: `cspace_convert([70, 170, 100] / 255,
    /// "sRGB1", "CAM02-UCS")`.
    #[test]
    fn cam02_ucs_agrees_with_colorspacious() {
        let got = ucs(Rgb(70, 170, 100), Vision::Normal);
        let want = [63.806_517_66, -22.330_610_07, 13.489_125_34];
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-6, "{got:?} vs {want:?}");
        }
    }

    /// colorspacious' simulation (`"sRGB1+CVD"`, severity 100, the same
    /// matrices) of (70, 170, 100), in sRGB in [0, 1].
    #[test]
    fn the_simulations_agree_with_colorspacious() {
        let cases = [
            (
                Vision::Protanopia,
                [0.669_915_03, 0.614_491_75, 0.372_626_05],
            ),
            (
                Vision::Deuteranopia,
                [0.617_541_15, 0.578_051_44, 0.410_033_28],
            ),
            (
                Vision::Tritanopia,
                [0.165_133_09, 0.656_234_23, 0.598_614_79],
            ),
        ];
        for (vision, want) in cases {
            let linear = vision.linear(Rgb(70, 170, 100));
            for (i, w) in want.into_iter().enumerate() {
                assert!(
                    (linear[i] - decode(w)).abs() < 1e-7,
                    "{vision:?}: {linear:?} vs {want:?}"
                );
            }
        }
    }

    #[test]
    fn a_colour_differs_from_itself_by_nothing_and_white_from_black_by_much() {
        for vision in Vision::ALL {
            assert_eq!(
                difference(Rgb(86, 180, 233), Rgb(86, 180, 233), vision),
                0.0
            );
            // White's J' is 100 by construction (to the rounding of sRGB's
            // matrix, whose white is not quite CIECAM02's D65), black's 0.
            let white = ucs(Rgb::WHITE, vision);
            assert!((white[0] - 100.0).abs() < 0.01, "{vision:?}: {white:?}");
            assert!(difference(Rgb::BLACK, Rgb::WHITE, vision) > 99.0);
        }
    }

    /// Protanopes and deuteranopes confuse red and green; tritanopes do not.
    #[test]
    fn red_and_green_merge_for_red_green_blindness_only() {
        let (red, green) = (Rgb(200, 90, 40), Rgb(110, 130, 40));
        let normal = difference(red, green, Vision::Normal);
        for vision in [Vision::Protanopia, Vision::Deuteranopia] {
            assert!(difference(red, green, vision) < 0.25 * normal, "{vision:?}");
        }
        assert!(difference(red, green, Vision::Tritanopia) > normal);
    }
}
