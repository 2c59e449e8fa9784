//! The balancing study of the session (`[balancing]`).

use super::*;

/// The balancing's part of the report.
pub(super) const PART: Part = Part {
    has: |scene| scene.balancing.is_some(),
    add: |session, rep| session.report_balancing(rep),
};
use crate::forces::balancing;

/// The scene's rotor balanced.
struct Balanced;
impl Cache for Balanced {
    type Key = ();
    type Value = Cached<Balancing>;
}

impl<'s> Session<'s> {
    /// The balancing of the scene's rotor (`[balancing]`), constructed once.
    pub fn balancing(&self) -> Cached<Balancing> {
        self.caches.get::<Balanced>((), || {
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

    fn report_balancing(&self, rep: &mut Report) -> Result<(), StudyError> {
        let b = self.balancing()?;
        rep.rows.extend(b.rows());
        rep.notes.extend(b.notes());
        Ok(())
    }
}
