//! What the plots show, below both the window and the figures: each plot
//! described once as data ([`spec::Plot`]), the colours by meaning and the
//! arithmetic of where a plot looks (pure: no drawing).

pub mod bifurcation;
pub mod boundary;
pub mod describe;
pub mod locus;
pub mod map;
pub mod map_words;
pub mod palette;
pub mod paradox;
pub mod pattern;
pub mod spec;
pub mod view;
pub mod vision;

pub use palette::{Palette, Rgb};

use crate::i18n::Words;
use crate::model::Axis;
use crate::tr;

/// The second axis's words: its name and unit.
#[must_use]
pub fn axis_words(axis: &Axis, words: &'static Words) -> String {
    match axis {
        Axis::Key(key) if !key.spec().unit.is_empty() => {
            format!("{} ({})", key.name(), key.spec().unit)
        }
        Axis::DampingLevel => tr!(words, "axis-damping-level"),
        Axis::MassRatio => tr!(words, "axis-mass-ratio"),
        _ => axis.name().to_owned(),
    }
}
