//! A model that passed its checks, as a type: what takes a [`ValidModel`]
//! (the simulation, the linearization, the analysis) checks nothing again.

use std::ops::Deref;

use super::{Key, Model, ModelError};

/// A [`Model`] that [`Model::validate`] accepted. Made only by
/// [`ValidModel::new`] (or [`crate::model::apply_assignments`], which
/// validates), read through `Deref`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValidModel(Model);

impl ValidModel {
    /// `model` checked once.
    ///
    /// # Errors
    /// The first parameter out of its range, named (see [`Model::validate`]).
    pub fn new(model: Model) -> Result<Self, ModelError> {
        model.validate()?;
        Ok(Self(model))
    }

    /// The same column at another load `p`. Only what the load touches is
    /// checked (a number, not negative, within what the analysis squares):
    /// the rest was checked when this model was made.
    ///
    /// # Errors
    /// A load that is no number, negative, or beyond the analysis's range.
    pub fn at_load(&self, p: f64) -> Result<Self, ModelError> {
        if !(p.is_finite() && p >= 0.0) {
            return Err(ModelError::invalid(
                Key::Load,
                p,
                super::Allowed::NonNegative,
            ));
        }
        let model = self.0.at_load(p);
        // A roller's load is its friction mu R: a mu so small that R =
        // P / mu overflows is what the user typed, so it is named.
        if let Some(roller) = model.roller()
            && p > 0.0
            && !(1.0 / roller.mu).is_finite()
        {
            return Err(ModelError::invalid(
                Key::Mu,
                roller.mu,
                super::Allowed::FrictionTooSmall { load_p: p },
            ));
        }
        if let Some((what, value)) = model.beyond_analysis() {
            return Err(ModelError::invalid(
                what,
                value,
                super::Allowed::BeyondAnalysis,
            ));
        }
        Ok(Self(model))
    }

    /// The model itself.
    #[must_use]
    pub fn model(&self) -> &Model {
        &self.0
    }
}

impl Deref for ValidModel {
    type Target = Model;

    fn deref(&self) -> &Model {
        &self.0
    }
}

/// A model the simulation and the analysis can take: a [`ValidModel`] as
/// it is, a plain [`Model`] checked on the way in (the command line's and
/// the tests' models, made once and used once).
pub trait AsValid {
    /// The model as a [`ValidModel`].
    ///
    /// # Errors
    /// A plain model that fails [`Model::validate`].
    fn as_valid(&self) -> Result<ValidModel, ModelError>;

    /// [`AsValid::as_valid`], taking the model.
    ///
    /// # Errors
    /// As [`AsValid::as_valid`].
    fn into_valid(self) -> Result<ValidModel, ModelError>
    where
        Self: Sized,
    {
        self.as_valid()
    }
}

impl AsValid for ValidModel {
    fn as_valid(&self) -> Result<ValidModel, ModelError> {
        Ok(*self)
    }
}

impl AsValid for Model {
    fn as_valid(&self) -> Result<ValidModel, ModelError> {
        ValidModel::new(*self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::PresetId;

    /// A load change keeps a valid model valid where the load is a load,
    /// and is refused where it is not; the result equals the plain model's.
    #[test]
    fn a_valid_model_at_another_load_is_checked_for_the_load_only() {
        let valid = ValidModel::new(PresetId::Roller.model()).unwrap();
        let moved = valid.at_load(2.5).unwrap();
        assert_eq!(*moved, PresetId::Roller.model().at_load(2.5));
        assert_eq!(moved.as_valid().unwrap(), moved);
        for bad in [-1.0, f64::NAN, f64::INFINITY, 1e200] {
            assert!(valid.at_load(bad).is_err(), "{bad}");
        }
        let mut broken = PresetId::Roller.model();
        broken.column.k1_nm_per_rad = -1.0;
        assert_eq!(
            broken.as_valid().unwrap_err().key(),
            Some(Key::K1),
            "a plain model is checked on the way in"
        );
    }
}
