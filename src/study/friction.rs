//! The friction cases of the session (`[friction]`).

use super::*;

/// The friction cases' part of the report.
pub(super) const PART: Part = Part {
    has: |scene| !scene.friction.is_empty(),
    add: |session, rep| session.report_friction(rep),
};
use crate::forces::friction;

/// The friction cases solved.
struct Cases;
impl Cache for Cases {
    type Key = ();
    type Value = Cached<Vec<Solved>>;
}

impl<'s> Session<'s> {
    /// Every `[[friction.case]]` of the scene constructed and read (empty without a
    /// `[friction]` section).
    pub fn friction(&self) -> Cached<Vec<Solved>> {
        self.caches.get::<Cases>((), || {
            let ctx = self.ctx()?;
            let solved = self
                .scene
                .friction
                .iter()
                .map(|c| friction::solve(c, &ctx))
                .collect::<Result<Vec<_>, _>>()?;
            for s in &solved {
                for d in &s.drawings {
                    self.logged("friction", &s.case.name, d.figure.scale);
                }
            }
            Ok(Arc::new(solved))
        })
    }

    fn report_friction(&self, rep: &mut Report) -> Result<(), StudyError> {
        for s in self.friction()?.iter() {
            rep.rows.extend(s.rows());
            rep.notes.extend(s.notes.iter().cloned());
        }
        Ok(())
    }
}
