//! The slotted link's rate on the plans when the pin passes through its pivot (RPR without
//! offset), the plans' own route: the limit of the rotation of the line from the pivot to
//! the pin, from the images of their relative motion.

use crate::construct::ConstructionError;
use crate::geom::DVec2;
use crate::linkage::plans::builder::Builder;
use crate::linkage::plans::names::plain;
use crate::linkage::plans::plan::PlanKind;

/// The slotted link's rate when the pin `a` passes through its pivot `c` (RPR without
/// offset): ω (velocity plan) or ε (acceleration plan) of link `j` as the limit of the
/// rotation of the line c → a, from the relative motion of `a` about `c`: with Δv, Δa, Δj
/// the relative velocity, acceleration and jerk, ω = [Δv × Δa]/(2|Δv|²) and
/// ε = [Δv × Δj]/(3|Δv|²) − ω·(Δv·Δa)/|Δv|². `None` away from the pivot: where the
/// crank travel h to the coincidence has h⁴ > 2δ/|w′| (δ the rounding of the positions,
/// w′ = Δv/ω₁), the reading off the plan loses fewer digits than the limit's O(h); and
/// where the pin passes the pivot at a distance beyond the rounding (the limit holds at
/// the coincidence only; beside it the plan gives the true, ill-conditioned rate).
/// Refused where the relative motion is not known from the crank alone.
pub(super) fn limit(
    bl: &Builder<'_>,
    step: &str,
    (a, c): (usize, usize),
    j: usize,
) -> Result<Option<f64>, ConstructionError> {
    let (w1, mu_l) = (bl.w1, bl.mu_l);
    let dv = if bl.kind == PlanKind::Velocity {
        (bl.image(a) - bl.image(c)) * bl.mu()
    } else {
        bl.vel_between(bl.vel_image(c), bl.vel_image(a))
    };
    let v2 = dv.length_squared() / (w1 * w1);
    let hp = bl.r(c, a).length();
    let at = (bl.b.p[a].length() + bl.b.p[c].length()) * mu_l;
    let delta = f64::EPSILON * (at + v2.sqrt());
    let bound = 2.0 * delta * v2 * v2.sqrt();
    if bound.is_nan() || hp.powi(4) > bound {
        return Ok(None);
    }
    let refuse = |why: String| ConstructionError::Other {
        step: format!("{step}: rate of the slotted link {j}"),
        message: format!(
            "the pin {} is {:.3e} m from the pivot {} (|v_{}{}| = {:.6} m/s): {why}",
            bl.name(a),
            hp,
            bl.name(c),
            plain(bl.name(a)),
            plain(bl.name(c)),
            dv.length()
        ),
    };
    if v2 == 0.0 {
        return Err(refuse("the line through them is not determined".into()));
    }
    // Acceleration and jerk of a point of the frame or the crank (constant ω₁).
    let motion = |k: usize| -> Option<(DVec2, DVec2)> {
        if k < bl.prog.fixed_count() {
            Some((DVec2::ZERO, DVec2::ZERO))
        } else if bl.prog.on_frame_or_crank(k) {
            let v = if bl.kind == PlanKind::Velocity {
                bl.image(k) * bl.mu()
            } else {
                bl.vel_image(k) * bl.known.mu_v
            };
            Some((-bl.r(bl.prog.centre(), k) * (w1 * w1), -v * (w1 * w1)))
        } else {
            None
        }
    };
    // The limit holds only where the pin passes through the pivot: its closest approach,
    // w − w′s + w″s²/2 with w′ = Δv/ω₁, w″ = Δa/ω₁², s = w·w′/|w′|², within the rounding
    // and the neglected O(s³). A pin that passes at a distance is read off the plan.
    let rel = bl.r(c, a);
    let w_d = dv / w1;
    let s = rel.dot(w_d) / v2;
    let (miss, neglected) = match (motion(a), motion(c)) {
        (Some((aa, ja)), Some((ac, jc))) => (
            (rel - w_d * s + (aa - ac) * (0.5 * s * s / (w1 * w1))).length(),
            ((ja - jc) / (w1 * w1 * w1)).length() * s.abs().powi(3),
        ),
        // Unknown curvature of the relative path: the first-order miss (across w′), which
        // an exact passage keeps within O(s²).
        _ => (rel.perp_dot(w_d).abs() / v2.sqrt(), v2.sqrt() * s * s),
    };
    if miss > 4.0 * delta + neglected {
        return Ok(None);
    }
    let (Some((aa, ja)), Some((ac, jc))) = (motion(a), motion(c)) else {
        return Err(refuse(format!(
            "the rate of link {j} is a limit that needs the relative acceleration and jerk, known only for points of the frame and the crank"
        )));
    };
    let dv2 = dv.length_squared();
    let da = aa - ac;
    let omega = dv.perp_dot(da) / (2.0 * dv2);
    Ok(Some(match bl.kind {
        PlanKind::Velocity => omega,
        PlanKind::Acceleration => {
            let omega = bl.known.vel.map_or(omega, |v| v.rate[j]);
            dv.perp_dot(ja - jc) / (3.0 * dv2) - omega * dv.dot(da) / dv2
        }
    }))
}
