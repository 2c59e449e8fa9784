//! `[cam]`'s layout: the turning cam, the rocker with a flat face (`follower =
//! "flat_rocker"`: `centres` a, `offset` e of the face from O₂, `base_radius` r₀) or the
//! translating cam (`travel` X: the cam slides along its guide by X over the law's cycle and
//! drives a translating roller follower across it, `roller` r). Each key that belongs to
//! another layout is refused on its own path.

use super::cam_raw::{key, RawCam};
use super::check::{number, Checker};
use crate::cam::flat_rocker::{self, FlatRocker, FlatRockerError};
use crate::cam::sliding::Sliding;
use crate::cam::{CamLayout, CamSpec, Follower};

/// `spec` (validated so far, laid out as the turning cam) with the layout the scene's keys
/// ask for; `flat_rocker`: the follower is `"flat_rocker"`.
pub(super) fn laid_out(
    check: &mut Checker,
    raw: &RawCam,
    flat_rocker: bool,
    spec: CamSpec,
) -> CamSpec {
    if raw.centres.is_some() && !flat_rocker {
        check.push(
            key("centres"),
            None,
            "`centres` (the distance O₁O₂) belongs to the flat-faced rocker: expected follower = \"flat_rocker\"",
        );
    }
    if flat_rocker {
        flat_rocker_of(check, raw, spec)
    } else if raw.travel.is_some() {
        sliding_of(check, raw, spec)
    } else {
        spec
    }
}

/// Refuse `name` when the scene gives it: it has no meaning for `what`.
fn refuse<T>(check: &mut Checker, name: &str, given: Option<T>, what: &str) {
    if given.is_some() {
        check.push(
            key(name),
            None,
            format!("`{name}` has no meaning for {what}"),
        );
    }
}

/// The rocker with a flat face: a and r₀ required, e the face's offset from O₂; r₀ + e
/// between 0 and a; the face never turning as fast as the cam.
fn flat_rocker_of(check: &mut Checker, raw: &RawCam, spec: CamSpec) -> CamSpec {
    const WHAT: &str = "a flat-faced rocker";
    refuse(check, "roller", raw.roller, WHAT);
    refuse(check, "travel", raw.travel, WHAT);
    refuse(
        check,
        "rotation",
        raw.rotation.as_ref(),
        "a flat-faced rocker (it turns ccw)",
    );
    let centres = check.length(&key("centres"), raw.centres);
    let base = check.length(&key("base_radius"), raw.base_radius);
    let frame = FlatRocker {
        centres,
        // Checked finite by the follower's `offset` already.
        face_offset: raw.offset.filter(|e| e.is_finite()).unwrap_or(0.0) * 1e-3,
        base,
    };
    let spec = CamSpec {
        base_radius: None,
        roller: None,
        layout: CamLayout::FlatRocker(frame),
        ..spec
    };
    if centres <= 0.0 || base <= 0.0 || !matches!(spec.follower, Follower::Rocker { .. }) {
        return spec;
    }
    match flat_rocker::exact_rho_min(&spec, &frame) {
        Err(FlatRockerError::Frame { reach, centres }) => check.push(
            key("base_radius"),
            raw.base_radius.map(number),
            format!(
                "expected r₀ + e (= {} mm) between 0 and the centre distance a = {} mm",
                number(reach * 1e3),
                number(centres * 1e3)
            ),
        ),
        Err(FlatRockerError::Outruns { phi_deg, rate }) => check.push(
            key("swing"),
            raw.swing.map(number),
            format!(
                "expected a swing the face follows: at φ = {}° the face turns at {} of the cam's speed (σ·S′/L ≥ 1: its lines have no envelope); a smaller swing, a longer arm or longer phases",
                number(phi_deg),
                number(rate)
            ),
        ),
        _ => {}
    }
    spec
}

/// The translating cam: a translating roller follower (`roller` required, 0: a knife
/// edge), the travel X > 0; no offset, base circle or rotation.
fn sliding_of(check: &mut Checker, raw: &RawCam, spec: CamSpec) -> CamSpec {
    const WHAT: &str = "a translating cam (`travel`)";
    if !matches!(spec.follower, Follower::Translating { .. }) {
        check.push(
            key("travel"),
            raw.travel.map(number),
            "a translating cam (`travel`) drives a translating roller follower: expected follower = \"translating\"",
        );
    }
    refuse(check, "offset", raw.offset, WHAT);
    refuse(check, "base_radius", raw.base_radius, WHAT);
    refuse(check, "rotation", raw.rotation.as_ref(), WHAT);
    let travel = check.length(&key("travel"), raw.travel);
    let roller = check.required(
        &key("roller"),
        spec.roller,
        "the roller radius r ≥ 0 mm of the translating cam's follower (0: a knife edge)",
    );
    CamSpec {
        roller: None,
        layout: CamLayout::Sliding(Sliding {
            travel,
            roller: roller.unwrap_or(0.0),
        }),
        ..spec
    }
}
