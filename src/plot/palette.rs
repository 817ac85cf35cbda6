//! Every colour that carries meaning, as plain RGB named by what it stands
//! for: the window's two themes read it, and the figures read it on paper.

use super::spec::Ink;
use crate::analysis::State;

/// A colour as red, green and blue bytes (opaque).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    pub const BLACK: Self = Self(0, 0, 0);
    pub const WHITE: Self = Self(255, 255, 255);

    /// A grey of `level`.
    #[must_use]
    pub const fn gray(level: u8) -> Self {
        Self(level, level, level)
    }
}

/// The colours of one theme, by meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Palette {
    pub background: Rgb,
    pub rod: Rgb,
    pub joint: Rgb,
    pub spring: Rgb,
    pub roller: Rgb,
    pub roller_mark: Rgb,
    pub band: Rgb,
    pub band_mark: Rgb,
    pub friction: Rgb,
    pub follower: Rgb,
    pub trail: Rgb,
    pub text: Rgb,
    pub stable: Rgb,
    pub flutter: Rgb,
    pub divergence: Rgb,
    pub axis: Rgb,
    /// Markers of the present: the current eigenvalues, the current load on
    /// the load bar, the current model's point on the map and the paradox plot.
    pub now: Rgb,
    /// The current load as a line across the plots against the load.
    pub load_line: Rgb,
    /// Eigenvalues measured from the run.
    pub measured: Rgb,
    /// The overlaid model's locus, behind the current one.
    pub overlay: Rgb,
    /// A value drawn for comparison (the undamped load, dashed).
    pub reference: Rgb,
    /// Cells and rows without data (not computed yet, or no analysis).
    pub no_data: Rgb,
    /// Curves that are neither states nor the scene's objects, in order.
    pub series: [Rgb; 6],
    /// The k-th curve of a plot (a damping level, an overlaid model), in
    /// colours that read on this theme's background.
    pub curves: [Rgb; 5],
    /// A ramp along a range (the load along a branch of the locus), its
    /// lightness rising for every colour vision; see [`Palette::along`].
    pub along: &'static [Rgb],
    /// Notices: something refused or failed.
    pub error: Rgb,
    /// Notices and cautions: done, but not quite as asked, or not resolved.
    pub warning: Rgb,
    /// Notices: done as asked.
    pub info: Rgb,
}

/// Okabe and Ito's colours for every colour vision (2008), and two of
/// their kin measured for the same purpose (see the tests).
mod ink {
    use super::Rgb;
    pub const SKY_BLUE: Rgb = Rgb(86, 180, 233);
    pub const YELLOW: Rgb = Rgb(240, 228, 66);
    pub const VERMILLION: Rgb = Rgb(213, 94, 0);
    pub const ORANGE: Rgb = Rgb(230, 159, 0);
    pub const BLUE: Rgb = Rgb(0, 114, 178);
    pub const REDDISH_PURPLE: Rgb = Rgb(204, 121, 167);
    pub const VIOLET: Rgb = Rgb(110, 80, 255);
    pub const PALE_GREEN: Rgb = Rgb(150, 230, 150);
    pub const CRIMSON: Rgb = Rgb(165, 0, 38);
    pub const NAVY: Rgb = Rgb(30, 40, 120);
}

/// viridis (van der Walt and Smith, public domain) at 0, 1/8, ..., 1: a
/// ramp whose lightness rises steadily for every colour vision.
const VIRIDIS: [Rgb; 9] = [
    Rgb(68, 1, 84),
    Rgb(72, 36, 117),
    Rgb(59, 82, 139),
    Rgb(44, 114, 142),
    Rgb(33, 145, 140),
    Rgb(40, 174, 128),
    Rgb(94, 201, 98),
    Rgb(173, 220, 48),
    Rgb(253, 231, 37),
];

impl Palette {
    /// The everyday theme, on a dark background.
    pub const NORMAL: Self = Self {
        background: Rgb(24, 26, 30),
        rod: Rgb(205, 210, 220),
        joint: Rgb(250, 250, 250),
        spring: Rgb(120, 170, 255),
        roller: Rgb(230, 170, 60),
        roller_mark: Rgb(90, 60, 20),
        band: Rgb(70, 74, 84),
        band_mark: Rgb(120, 126, 140),
        friction: Rgb(240, 110, 40),
        follower: Rgb(110, 200, 255),
        trail: Rgb(150, 110, 255),
        text: Rgb(225, 228, 235),
        stable: ink::SKY_BLUE,
        flutter: ink::YELLOW,
        divergence: ink::VERMILLION,
        axis: Rgb(200, 200, 200),
        now: Rgb::WHITE,
        load_line: ink::REDDISH_PURPLE,
        measured: ink::VIOLET,
        overlay: Rgb(120, 120, 120),
        reference: Rgb(120, 120, 120),
        no_data: Rgb::gray(40),
        series: [
            ink::SKY_BLUE,
            Rgb(205, 210, 220),
            ink::VERMILLION,
            ink::PALE_GREEN,
            ink::YELLOW,
            ink::VIOLET,
        ],
        curves: [
            ink::SKY_BLUE,
            ink::YELLOW,
            ink::VERMILLION,
            ink::VIOLET,
            ink::PALE_GREEN,
        ],
        along: &ALONG_ON_DARK,
        error: Rgb(240, 90, 60),
        warning: ink::YELLOW,
        info: ink::SKY_BLUE,
    };

    /// High contrast for a projector, on black.
    pub const PROJECTOR: Self = Self {
        background: Rgb::BLACK,
        rod: Rgb::WHITE,
        joint: Rgb::WHITE,
        spring: Rgb(80, 180, 255),
        roller: Rgb(255, 200, 0),
        roller_mark: Rgb::BLACK,
        band: Rgb(60, 60, 60),
        band_mark: Rgb(200, 200, 200),
        friction: Rgb(255, 110, 30),
        follower: Rgb(110, 200, 255),
        trail: Rgb(200, 140, 255),
        text: Rgb::WHITE,
        axis: Rgb::WHITE,
        series: [
            ink::SKY_BLUE,
            Rgb::WHITE,
            ink::VERMILLION,
            ink::PALE_GREEN,
            ink::YELLOW,
            ink::VIOLET,
        ],
        ..Self::NORMAL
    };

    /// A printed figure: black ink on white paper, states and curves that
    /// read on white; an overlaid model is the first of the curves, the
    /// model's own point and a reference are in the ink.
    pub const PAPER: Self = Self {
        background: Rgb::WHITE,
        text: Rgb::BLACK,
        axis: Rgb::gray(128),
        now: Rgb::BLACK,
        reference: Rgb::BLACK,
        overlay: ink::SKY_BLUE,
        no_data: Rgb::gray(200),
        stable: ink::BLUE,
        flutter: ink::ORANGE,
        divergence: ink::CRIMSON,
        curves: [
            ink::SKY_BLUE,
            ink::ORANGE,
            ink::VIOLET,
            ink::CRIMSON,
            ink::NAVY,
        ],
        along: &ALONG_ON_PAPER,
        ..Self::NORMAL
    };

    /// The colour of what `ink` stands for, in this theme: the one mapping
    /// of meaning to colour, which both renderers convert.
    #[must_use]
    pub fn ink(&self, ink: &Ink) -> Rgb {
        match *ink {
            Ink::Main => self.text,
            Ink::Series(k) => self.curves[k % self.curves.len()],
            Ink::Overlay => self.overlay,
            Ink::Reference => self.reference,
            Ink::State(state) => self.state(state),
            Ink::Now => self.now,
            Ink::Measured => self.measured,
            Ink::LoadLine => self.load_line,
            Ink::Axis => self.axis,
            Ink::Along(t) => self.along(t),
            Ink::Cell(state, strength) => self.cell(state, strength),
            Ink::NoData => self.no_data,
        }
    }

    /// A stability map's cell: its state's colour mixed with the
    /// background, `strength` in [0, 1] from [`Self::FAINTEST_CELL`] of
    /// the colour to all of it (the faintest cells of two states stay as
    /// far apart as the tests ask of the states).
    #[must_use]
    pub fn cell(&self, state: State, strength: f64) -> Rgb {
        let share = Self::FAINTEST_CELL + (1.0 - Self::FAINTEST_CELL) * strength.clamp(0.0, 1.0);
        let (colour, under) = (self.state(state), self.background);
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a mix of two bytes"
        )]
        let mix =
            |c: u8, b: u8| (f64::from(b) + (f64::from(c) - f64::from(b)) * share).round() as u8;
        Rgb(
            mix(colour.0, under.0),
            mix(colour.1, under.1),
            mix(colour.2, under.2),
        )
    }

    /// The share of its state's colour in the faintest map cell.
    pub const FAINTEST_CELL: f64 = 0.55;

    /// The share of its state's colour in the tint of a stability range
    /// behind the plots (the rest is the background's): pale enough for
    /// the curves over it to keep their contrast.
    pub const RANGE_TINT: f64 = 0.18;

    /// The colour that stands for a stability state.
    #[must_use]
    pub const fn state(&self, state: State) -> Rgb {
        match state {
            State::Stable => self.stable,
            State::Flutter => self.flutter,
            State::Divergence => self.divergence,
        }
    }

    /// The colour a fraction `t` in [0, 1] of the way along the ramp (a
    /// branch's load from the smallest to the largest drawn).
    #[must_use]
    pub fn along(&self, t: f64) -> Rgb {
        let ramp = self.along;
        let last = ramp.len().saturating_sub(1);
        #[expect(clippy::cast_precision_loss, reason = "a handful of colours")]
        let x = if t.is_finite() {
            t.clamp(0.0, 1.0)
        } else {
            0.0
        } * last as f64;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "x in [0, last]"
        )]
        let i = (x.floor() as usize).min(last.saturating_sub(1));
        let (Some(a), Some(b)) = (ramp.get(i), ramp.get(i + 1).or(ramp.get(i))) else {
            return self.text;
        };
        #[expect(clippy::cast_precision_loss, reason = "a handful of colours")]
        let s = x - i as f64;
        let mix = |p: u8, q: u8| {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "between two bytes"
            )]
            let c = (f64::from(p) + (f64::from(q) - f64::from(p)) * s).round() as u8;
            c
        };
        Rgb(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
    }
}

/// viridis from a quarter of its way on: its darkest purples are lost on
/// a dark background.
const ALONG_ON_DARK: [Rgb; 7] = [
    VIRIDIS[2], VIRIDIS[3], VIRIDIS[4], VIRIDIS[5], VIRIDIS[6], VIRIDIS[7], VIRIDIS[8],
];

/// viridis up to three quarters of its way: its yellows are lost on
/// white.
const ALONG_ON_PAPER: [Rgb; 7] = [
    VIRIDIS[0], VIRIDIS[1], VIRIDIS[2], VIRIDIS[3], VIRIDIS[4], VIRIDIS[5], VIRIDIS[6],
];

#[cfg(test)]
mod tests;
