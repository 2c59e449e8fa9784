//! The gear study of the session (`[gears]`, `[planetary]`).

use super::*;

/// The gear study's part of the report.
pub(super) const PART: Part = |session, rep| session.report_gears(rep);

/// The gear study.
struct Wheels;
impl Cache for Wheels {
    type Key = ();
    type Value = Cached<crate::gears::GearStudy>;
}

impl<'s> Session<'s> {
    /// The gear study of the scene (`[gears]`): the pair's meshing picture and the wheels
    /// cut by the rack, constructed once.
    pub fn gears(&self) -> Cached<crate::gears::GearStudy> {
        self.caches.get::<Wheels>((), || {
            let spec = self
                .scene
                .gears
                .as_ref()
                .ok_or(StudyError::NoGears("the gear study"))?;
            let g = crate::gears::study(spec, &self.ctx()?, &self.shared.blocking)?;
            if let Some(p) = &g.pair {
                self.logged("meshing picture", "", p.meshing.scale);
            }
            for w in &g.racks {
                self.logged("rack generation", &w.name, w.generation.scale);
            }
            Ok(Arc::new(g))
        })
    }

    fn report_gears(&self, rep: &mut Report) -> Result<(), StudyError> {
        let g = self.gears()?;
        rep.rows.extend(g.rows());
        rep.notes.extend(g.notes());
        Ok(())
    }
}
