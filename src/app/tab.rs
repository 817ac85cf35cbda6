//! The tabs of the lower half of the window by name: the type every layer
//! that names a tab uses (the actions, the state, the lessons, the stored
//! layout), below the tabs themselves. Their registry, `tabs::TABS`, says
//! what each is.

/// A tab of the window: its row in [`super::tabs::TABS`] says everything else (a tab
/// without its row, or a row too many, does not compile).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, strum::EnumCount)]
pub enum Tab {
    /// The root locus (the first tab, shown at launch).
    #[default]
    Locus,
    Histories,
    Map,
    Paradox,
    PostCritical,
}

/// A name that is none of those known (a tab, a panel).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} '{name}': expected one of {known}")]
pub struct UnknownName {
    pub what: &'static str,
    pub name: String,
    pub known: String,
}
