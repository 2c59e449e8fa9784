//! The cam's inversion sweep: seed 000's cam profiled by inversion at N intervals per rise
//! and return (2N + 2 follower positions), read exactly; the drawn practical profile's
//! largest deviation from the exact envelope beside the time of the recorded inversion.

use super::BenchRow;
use super::{best_time, BenchError, Reps};
use crate::cam::{self, Cam};
use crate::construct::{Context, Drafting};
use crate::scene;

/// The inversion resolutions swept (intervals per moving phase).
pub const INVERSION_STEPS: [usize; 8] = [12, 24, 48, 96, 192, 360, 720, 1440];

/// Largest extent of a profile drawing, mm.
const PROFILE_EXTENT_MM: f64 = 400.0;

/// The sweep's rows: method `inversion N=…`, quantity `profile_deviation` (m), the time of
/// one recorded inversion.
pub(super) fn inversion_rows(
    opts: &super::BenchOptions,
    reps: Reps,
) -> Result<Vec<BenchRow>, BenchError> {
    let stem = "shaper";
    let s = scene::load(&opts.scenes.join(format!("{stem}.toml")))?;
    let fail = |detail: String| BenchError::Plate {
        scene: stem.into(),
        plate: "cam".into(),
        detail,
    };
    let spec = s.cam.as_ref().ok_or_else(|| fail("no [cam]".into()))?;
    let ctx = Context::for_model_size(PROFILE_EXTENT_MM, Drafting::EXACT)?;
    let c: Cam = cam::build(spec, &ctx).map_err(|e| fail(e.to_string()))?;
    let mut rows = Vec::new();
    for n in INVERSION_STEPS {
        let (spec_n, points, inv) =
            cam::inversion_at(&c, n, &ctx).map_err(|e| fail(e.to_string()))?;
        let (max, mean) = cam::deviation(&spec_n, &points, &inv, &c.placement, c.base, c.roller);
        let time_s = best_time(reps.best_of, || cam::inversion_at(&c, n, &ctx))
            .map_err(|e| fail(e.to_string()))?;
        rows.push(BenchRow {
            method: format!("inversion N={n}"),
            resolution: u32::try_from(n).unwrap_or(u32::MAX),
            quantity: "profile_deviation".into(),
            max_error: max,
            mean_error: mean,
            time_s,
            unit: "m".into(),
        });
    }
    Ok(rows)
}
