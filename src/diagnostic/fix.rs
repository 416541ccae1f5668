//! A fix: the edits that resolve one finding, in ruff's model. A safe fix keeps the
//! scene's meaning and applies under `--fix`; an unsafe one may change what the scene
//! shows or which browsers load it, and applies only with `--unsafe-fixes`.

use super::Span;

/// Whether a fix may change the scene's meaning.
#[derive(
    Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize, serde::Deserialize,
)]
#[serde(rename_all = "lowercase")]
pub enum Applicability {
    /// Keeps the scene's meaning: applied by `--fix` and offered as a preferred code action.
    Safe,
    /// May change what the scene means or which browsers accept it: applied only with
    /// `--unsafe-fixes`, offered as a code action an author chooses.
    Unsafe,
}

/// Replace the bytes of `span` in the checked file with `replacement` (an insertion when
/// the span is empty).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edit {
    pub span: Span,
    pub replacement: String,
}

/// The edits that resolve one finding. Edits of one fix never overlap.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Fix {
    /// What the fix does, as a code action's title ("Rename to `diffuseColor`").
    pub title: String,
    pub applicability: Applicability,
    pub edits: Vec<Edit>,
}
