//! Enums looked up by the names people type (keys, presets, engines): the
//! variant of a name, and every name for a message that lists them.

use strum::VariantArray;

/// The variant of `T` whose name is `name` (case-sensitive).
pub fn variant_named<T>(name: &str) -> Option<T>
where
    T: VariantArray + Copy + Into<&'static str>,
{
    T::VARIANTS
        .iter()
        .copied()
        .find(|&variant| Into::<&'static str>::into(variant) == name)
}

/// Every name of `T`, in order, joined by ", ".
pub fn variant_names<T>() -> String
where
    T: VariantArray + Copy + Into<&'static str>,
{
    T::VARIANTS
        .iter()
        .map(|&variant| Into::<&'static str>::into(variant))
        .collect::<Vec<_>>()
        .join(", ")
}
