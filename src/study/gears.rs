//! The gear study of the session (`[gears]`, `[planetary]`).

use super::*;

impl<'s> Session<'s> {
    /// The gear study of the scene (`[gears]`): the pair's meshing picture and the wheels
    /// cut by the rack, constructed once.
    pub fn gears(&self) -> Cached<crate::gears::GearStudy> {
        self.gears.get((), || {
            let spec = self
                .scene
                .gears
                .as_ref()
                .ok_or(StudyError::NoGears("the gear study"))?;
            let g = crate::gears::study(spec, &self.ctx()?)?;
            if let Some((_, m)) = &g.pair {
                self.logged("meshing picture", "", m.scale);
            }
            for (name, r) in &g.racks {
                self.logged("rack generation", name, r.scale);
            }
            Ok(Arc::new(g))
        })
    }
}
