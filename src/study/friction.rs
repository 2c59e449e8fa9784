//! The friction cases of the session (`[friction]`).

use super::*;
use crate::forces::friction;

impl<'s> Session<'s> {
    /// Every `[[friction.case]]` of the scene constructed and read (empty without a
    /// `[friction]` section).
    pub fn friction(&self) -> Cached<Vec<Solved>> {
        self.friction.get((), || {
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
}
