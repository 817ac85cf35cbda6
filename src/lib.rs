//! zieglerlab: flutter and divergence of the Ziegler column, with the ideal
//! follower force and with the real mechanism (a roller dragged by a moving band).
//!
//! `model` holds the physics, `analysis` the linear stability; both are pure f64.

pub mod analysis;
pub mod model;
