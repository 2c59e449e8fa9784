//! The cam study of the session (`[cam]`).

use super::*;

/// The cam's part of the report.
pub(super) const PART: Part = Part {
    has: |scene| scene.cam.is_some(),
    add: |session, rep| session.report_cam(rep),
};

/// The scene's cam.
struct Cams;
impl Cache for Cams {
    type Key = ();
    type Value = Cached<crate::cam::Cam>;
}

impl<'s> Session<'s> {
    /// The scene's cam (`[cam]`): its diagrams, minimum radius and profile, constructed once.
    pub fn cam(&self) -> Cached<crate::cam::Cam> {
        self.caches.get::<Cams>((), || {
            let spec = self
                .scene
                .cam
                .as_ref()
                .ok_or(StudyError::NoCam("the cam sheet"))?;
            let c = crate::cam::build(spec, &self.ctx()?)?;
            self.logged("profile by inversion", "", c.inversion.scale);
            Ok(Arc::new(c))
        })
    }

    fn report_cam(&self, rep: &mut Report) -> Result<(), StudyError> {
        let c = self.cam()?;
        rep.rows.extend(c.rows());
        rep.notes.extend(c.notes());
        Ok(())
    }
}
