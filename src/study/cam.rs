//! The cam study of the session (`[cam]`).

use super::*;

impl<'s> Session<'s> {
    /// The scene's cam (`[cam]`): its diagrams, minimum radius and profile, constructed once.
    pub fn cam(&self) -> Cached<crate::cam::Cam> {
        self.cam.get((), || {
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
}
