//! The drawn practical profile against the exact envelope: the exact profile point, the
//! largest and mean normal distance of the French curve from it, and the profile by
//! inversion at another number of divisions (the bench's sweep).

use super::construct::Cam;
use super::follower::{flat_contact, to_cam, Placement};
use super::inversion::{invert, Inversion};
use super::motion::{motion, points, FollowerMotion, Point};
use super::{CamError, CamSpec, Follower};
use crate::construct::Context;
use crate::geom::{bezier_distance, french_piece, DVec2};

/// The exact practical-profile point at φ (cam frame): the roller's tangency or the flat
/// face's contact.
pub fn exact_profile(
    spec: &CamSpec,
    place: &Placement,
    base: f64,
    roller: f64,
    phi: f64,
    after: bool,
) -> DVec2 {
    let m = motion(spec, phi, after);
    let q = if matches!(spec.follower, Follower::Flat { .. }) {
        flat_contact(base, m).0
    } else {
        place.kin(m).roller_point(roller)
    };
    to_cam(q, phi)
}

/// Points of the exact envelope measured along each interval of the drawn profile.
const INTERVAL_SAMPLES: usize = 16;

/// The angles a drawn profile is measured against the exact envelope at: equally spaced,
/// both ends included, along each interval within a moving phase ([`INTERVAL_SAMPLES`] + 1
/// of them), each with its interval's index and whether it is taken after a jump of the law
/// there (the interval's first point's side).
pub(super) fn interval_samples(points: &[Point]) -> impl Iterator<Item = (usize, f64, bool)> + '_ {
    let moving = points.windows(2).enumerate();
    moving
        .filter(|(_, w)| w[0].phase == w[1].phase)
        .flat_map(|(i, w)| {
            let (p, q) = (w[0].phi, w[1].phi);
            let after = w[0].after;
            (0..=INTERVAL_SAMPLES).map(move |j| {
                let phi = p + (q - p) * j as f64 / INTERVAL_SAMPLES as f64;
                (i, phi, j == 0 && after)
            })
        })
}

/// The largest and the mean normal distance between the drawn practical profile (the French
/// curve between its points within each moving phase, drawn as the cubic it is; the dwells
/// are arcs) and the exact envelope, m.
pub fn deviation(
    cam_spec: &CamSpec,
    points: &[Point],
    inv: &Inversion,
    place: &Placement,
    base: f64,
    roller: f64,
) -> (f64, f64) {
    let (mut worst, mut sum, mut count) = (0.0f64, 0.0, 0usize);
    let (c, t) = (&inv.profile, &inv.tangents);
    let pieces: Vec<[DVec2; 3]> = (1..c.len())
        .map(|i| french_piece(c[i - 1], t[i - 1], c[i], t[i]))
        .collect();
    for (i, phi, after) in interval_samples(points) {
        let e = exact_profile(cam_spec, place, base, roller, phi, after);
        let d = bezier_distance(e, c[i], &pieces[i]);
        worst = worst.max(d);
        sum += d;
        count += 1;
    }
    (worst, sum / count.max(1) as f64)
}

/// The profile by inversion at `n` equal intervals per moving phase (2n + 2 positions, and
/// a division point on each break of a given d²S/dφ² between them) from the exact law, as read at drafting 0: the bench's sweep. Returns the task at that resolution,
/// its points and the inversion.
///
/// # Errors
/// As [`super::build`]'s inversion.
pub fn inversion_at(
    cam: &Cam,
    n: usize,
    ctx: &Context,
) -> Result<(CamSpec, Vec<Point>, Inversion), CamError> {
    let mut spec = cam.spec.clone();
    spec.divisions = n.max(2);
    // The cam's own μ_l: the profile at another N is drawn on the same scale.
    spec.scale_l = Some(cam.inversion.scale);
    let points = points(&spec);
    let read: Vec<FollowerMotion> = points
        .iter()
        .map(|p| motion(&spec, p.phi, p.after))
        .collect();
    let inv = invert(
        &spec,
        &points,
        &read,
        &cam.placement,
        (cam.base, cam.roller),
        ctx,
    )?;
    Ok((spec, points, inv))
}

/// [`inversion_at`] and the largest deviation of its profile from the exact envelope, m.
///
/// # Errors
/// As [`inversion_at`].
pub fn deviation_at(cam: &Cam, n: usize, ctx: &Context) -> Result<(Inversion, f64), CamError> {
    let (spec, points, inv) = inversion_at(cam, n, ctx)?;
    let (dev, _) = deviation(&spec, &points, &inv, &cam.placement, cam.base, cam.roller);
    Ok((inv, dev))
}
