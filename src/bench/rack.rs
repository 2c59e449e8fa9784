//! Rack generation: the drawn envelope's deviation from the exact tooth (involute, trochoidal
//! fillet, root circle) and the time of one generated tooth, for N = 12 … 720 rack positions
//! (seed 000's pinion z = 13, m = 14 mm, over the course's shifts: x = −0.5 and 0 undercut,
//! 0.5, and 0.8 nearly pointed).

use super::BenchRow;
use super::{best_time, Reps};
use crate::construct::{Context, Drafting};
use crate::gears::{generate, generation_scale, BasicRack, Cutting};

/// The rack positions swept.
pub const RACK_RESOLUTIONS: [usize; 7] = [12, 24, 48, 90, 180, 360, 720];

/// One row per wheel and N: max and mean deviation in modules, time per tooth.
pub(super) fn rack_rows(reps: Reps) -> Result<Vec<BenchRow>, super::BenchError> {
    let fail = |e: String| super::BenchError::Linkage {
        scene: "rack generation".into(),
        detail: e,
    };
    let ctx = Context::for_model_size(400.0, Drafting::EXACT)?;
    let mut out = Vec::new();
    for x in [-0.5, 0.0, 0.5, 0.8] {
        let c =
            Cutting::alone(0.014, 13, x, BasicRack::GOST_13755).map_err(|e| fail(e.to_string()))?;
        let scale = generation_scale(&c).map_err(|e| fail(e.to_string()))?;
        for n in RACK_RESOLUTIONS {
            let g = generate(&c, n, scale, &ctx).map_err(|e| fail(e.to_string()))?;
            let time = best_time(reps.best_of, || generate(&c, n, scale, &ctx))
                .map_err(|e| fail(e.to_string()))?;
            out.push(BenchRow {
                method: format!("rack N={n}"),
                resolution: n as u32,
                quantity: format!("envelope_deviation z=13 x={x}"),
                max_error: g.deviation / c.module,
                mean_error: g.deviation_mean / c.module,
                time_s: time,
                unit: "m (module)".into(),
            });
        }
    }
    Ok(out)
}
