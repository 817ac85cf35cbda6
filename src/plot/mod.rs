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
