//! The peer: the `four-bar` crate (KmolYuan's four-bar-rs, the fastest linkage solver
//! in `PEERS.md`) solving the positions of the same crank-rocker as the kernel, in the same
//! run. The crate comes with the `peer` feature only (`cargo run --release --features peer
//! -- bench`): a bench-only dependency, kept out of the default build (CI lints this code
//! with the feature on).

#[cfg(not(feature = "peer"))]
use super::{BenchError, Reps};
use super::{Subject, Throughput};

/// The peer's positions per second on a scene's crank-rocker, with the joint it was checked at.
pub(super) struct Peer {
    /// Positions per second.
    pub rate: f64,
    /// The joint whose positions were set against the kernel's.
    pub joint: String,
}

/// The peer's rate, or `None` when built without the `peer` feature.
#[cfg(not(feature = "peer"))]
pub(super) fn measure(_: &Subject, _: Reps) -> Result<Option<Peer>, BenchError> {
    Ok(None)
}

#[cfg(feature = "peer")]
pub(super) use with_peer::measure;

/// The peer's row (without the feature, how to get it).
pub(super) fn row(peer: Option<&Peer>, s: &Subject) -> Throughput {
    match peer {
        Some(p) => Throughput {
            name: format!("peer four-bar crate ({})", s.scene.stem),
            per_second: p.rate,
            note: format!("the `four-bar` crate (7): positions only (`pos`, one angle at a time, 1 core); its {} agrees with the kernel's at every 10°", p.joint),
        },
        None => Throughput {
            name: "peer four-bar crate".into(),
            per_second: f64::NAN,
            note: "not built: `cargo run --release --features peer -- bench` adds the `four-bar` crate's positions on the same crank-rocker".into(),
        },
    }
}

#[cfg(feature = "peer")]
mod with_peer {
    use super::super::rates::per_angle_rate;
    use super::super::{BenchError, Reps, Subject};
    use super::Peer;
    use crate::linkage::{Dyad, Pose};
    use four_bar::mech::{fb::UnNorm, CurveGen, Stat};
    use four_bar::{FourBar, NormFourBar};
    use std::convert::Infallible;
    use std::f64::consts::TAU;
    use std::hint::black_box;

    /// Angles at which the peer's joint is checked against the kernel's: every 10°.
    const CHECKS: usize = 36;

    pub(in super::super) fn measure(s: &Subject, reps: Reps) -> Result<Option<Peer>, BenchError> {
        let (fb, joint) = peer_of(s)?;
        let Ok(rate) = per_angle_rate::<Infallible>(s, reps, |phi| {
            black_box(fb.pos(phi));
            Ok(())
        });
        Ok(Some(Peer { rate, joint }))
    }

    /// The scene's crank-rocker as the crate's four-bar (ground, crank, coupler, rocker and the
    /// circuit its joint is on), and the joint's name; refused unless its joint matches the
    /// kernel's to 1e-9 of the linkage's size at every checked angle.
    fn peer_of(s: &Subject) -> Result<(FourBar, String), BenchError> {
        let m = &s.mechanism;
        let fixed = |name: &str| m.fixed.iter().find(|f| f.name == name).map(|f| f.at);
        let not_a_four_bar = || {
            s.fail("the peer solves a crank-rocker: a crank and one RRR group on it and on a fixed pivot")
        };
        let centre = fixed(&m.crank.centre).ok_or_else(not_a_four_bar)?;
        let (la, lb, pivot, joint) = match m.groups.first().map(|g| &g.dyad) {
            Some(Dyad::Rrr {
                a,
                la,
                b,
                lb,
                joint,
                ..
            }) if *a == m.crank.pin => (
                *la,
                *lb,
                fixed(b).ok_or_else(not_a_four_bar)?,
                joint.clone(),
            ),
            _ => return Err(not_a_four_bar()),
        };
        let at = s.prog.index(&joint).ok_or_else(not_a_four_bar)?;
        let ground = pivot - centre;
        let l1 = ground.length();
        let size = l1 + m.crank.length + la + lb;
        // The crate's crank angle is taken from its ground line.
        let rotation = ground.y.atan2(ground.x);
        let mut unnorm = UnNorm::from_driver(m.crank.length);
        unnorm.set_origin(centre.x, centre.y);
        unnorm.set_rotation(rotation);
        let mut pose = Pose::default();
        let ours: Vec<_> = (0..CHECKS)
            .map(|k| {
                let phi = TAU * k as f64 / CHECKS as f64;
                s.prog
                    .solve_into(phi, false, &mut pose)
                    .map(|()| (phi, pose.p[at]))
            })
            .collect::<Result<_, _>>()
            .map_err(|u| s.fail(u.detail))?;
        for stat in [Stat::C1B1, Stat::C2B1] {
            let norm = NormFourBar {
                l1,
                l3: la,
                l4: lb,
                l5: 0.0,
                g: 0.0,
                stat,
            };
            let fb = FourBar::new(unnorm.clone(), norm);
            let agrees = ours.iter().all(|&(phi, p)| {
                fb.pos(phi - rotation)
                    .is_some_and(|js| (js[3][0] - p.x).hypot(js[3][1] - p.y) <= 1e-9 * size)
            });
            if agrees {
                return Ok((fb, joint));
            }
        }
        Err(s.fail(format!(
            "the four-bar crate's {joint} differs from the kernel's on both circuits"
        )))
    }
}
