//! What a scene was validated from: the file's values as it gave them, read once, kept so
//! that the scene can be validated again at another scale (`Scene::with_scale`) without
//! reading or parsing the file again.

use super::raw::RawScene;
use std::sync::Arc;

/// What a scene was validated from: the file's values as it gave them, in its units.
#[derive(Debug, Clone, PartialEq)]
pub struct Source(pub(super) Arc<RawScene>);

impl Source {
    /// The source holding `raw`.
    pub(super) fn new(raw: RawScene) -> Self {
        Source(Arc::new(raw))
    }
}
