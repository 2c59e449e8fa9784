//! The cam study of the session (`[cam]`): the turning cam ([`crate::cam::build`]), or the
//! flat-faced rocker and the translating cam ([`crate::cam::build_special`]), as the scene's
//! layout says.

use super::*;
use crate::cam::CamLayout;

/// The cam's part of the report.
pub(super) const PART: Part = |session, rep| session.report_cam(rep);

/// The scene's cam.
struct Cams;
impl Cache for Cams {
    type Key = ();
    type Value = Cached<crate::cam::Cam>;
}

/// The scene's flat-faced rocker or translating cam.
struct Specials;
impl Cache for Specials {
    type Key = ();
    type Value = MaybeCached<crate::cam::Special>;
}

impl<'s> Session<'s> {
    fn cam_spec(&self) -> Result<&'s crate::cam::CamSpec, StudyError> {
        self.scene
            .cam
            .as_ref()
            .ok_or(StudyError::NoCam("the cam sheet"))
    }

    /// The scene's cam (`[cam]`): its diagrams, minimum radius and profile, constructed once.
    /// A flat-faced rocker or a translating cam is [`Session::special_cam`].
    pub fn cam(&self) -> Cached<crate::cam::Cam> {
        self.caches.get::<Cams>((), || {
            let c = crate::cam::build(self.cam_spec()?, &self.ctx()?)?;
            self.logged("profile by inversion", "", c.inversion.scale);
            Ok(Arc::new(c))
        })
    }

    /// The scene's flat-faced rocker or translating cam (`[cam]` with `follower =
    /// "flat_rocker"` or a `travel`): its diagrams and profile, constructed once; `None` for
    /// the turning cam of [`Session::cam`].
    pub fn special_cam(&self) -> MaybeCached<crate::cam::Special> {
        self.caches.get::<Specials>((), || {
            let spec = self.cam_spec()?;
            if spec.layout == CamLayout::Turning {
                return Ok(None);
            }
            let c = crate::cam::build_special(spec, &self.ctx()?)?;
            self.logged("profile by inversion", "", c.scale);
            Ok(Some(Arc::new(c)))
        })
    }

    fn report_cam(&self, rep: &mut Report) -> Result<(), StudyError> {
        if let Some(c) = self.special_cam()? {
            rep.rows.extend(c.rows()?);
            rep.notes
                .extend(c.noted()?.into_iter().map(ReportNote::from));
            return Ok(());
        }
        let c = self.cam()?;
        rep.rows.extend(c.rows());
        rep.notes
            .extend(c.noted().into_iter().map(ReportNote::from));
        Ok(())
    }
}
