//! The balancing study of the session (`[balancing]`).

use super::*;
use crate::forces::balancing;

impl<'s> Session<'s> {
    /// The balancing of the scene's rotor (`[balancing]`), constructed once.
    pub fn balancing(&self) -> Cached<Balancing> {
        self.balancing.get((), || {
            let spec = self
                .scene
                .balancing
                .as_ref()
                .ok_or(StudyError::NoBalancing("the balancing of a rotor"))?;
            let b = balancing::balance(spec, &self.ctx()?)?;
            self.logged("polygon of static moments", "", b.scale_mr);
            Ok(Arc::new(b))
        })
    }
}
