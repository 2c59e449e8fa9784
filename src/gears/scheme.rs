//! The train's kinematic scheme (seed 002 PZ2 §3.6 step 1, seed 000's reducer), drawn the
//! textbook way beside its velocity triangles and at their heights: the axes horizontal, each
//! wheel seen edge-on as its pitch diameter (ГОСТ 2.770: a line across the shaft with short
//! bars at its teeth; a ring as its rim and a cup-shaped disc), the wheels that mesh in one plane, each
//! shaft with its bearing on the frame, the carrier a cranked link holding the satellites'
//! axle, the support wheel fixed to the frame (hatched), every wheel named with its z.

use super::train::Train;
use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment, Side};

/// Spacing of the planes of meshing wheels along the axes, mm.
const PLANE_MM: f64 = 34.0;
/// How far a shaft runs past its outermost wheel, mm.
const SHAFT_END_MM: f64 = 6.0;
/// Half length of a wheel's end bars, mm.
const BAR_MM: f64 = 1.5;
/// Drawn distance between shafts on one axis (a hollow shaft over another), mm.
const COAXIAL_MM: f64 = 1.2;
/// How far a ring's disc stands past its plane, mm.
const CUP_MM: f64 = 10.0;
/// How far the carrier's arm stands past the satellites' plane (between it and a ring's cup,
/// leaving the room before the plane to the wheels' names), mm.
const ARM_MM: f64 = 5.0;

/// Draw `train`'s scheme into `rec` with its rightmost plane at `right` (figure mm), the
/// shafts at the heights `height(ys[k])` of the triangles, the wheels reaching their mesh
/// poles `poles` (one per mesh).
pub(super) fn draw_scheme(
    rec: &mut Recorder,
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    height: impl Fn(f64) -> f64,
    scale_l: f64,
    right: f64,
) {
    let planes = planes(train);
    let count = planes.iter().copied().max().map_or(0, |p| p + 1);
    // Plane p at x, the first plane leftmost.
    let plane_x = |p: usize| right - (count - 1 - p) as f64 * PLANE_MM;
    // Shafts on one axis drawn apart, the input's at the axis.
    let mut drawn_y = vec![0.0; train.shafts.len()];
    let mut on_axis: Vec<(f64, usize)> = Vec::new();
    for (k, y) in ys.iter().enumerate() {
        let same = on_axis
            .iter()
            .filter(|(v, _)| (v - y).abs() <= 1e-9 * scale_l.max(y.abs()))
            .count();
        on_axis.push((*y, k));
        drawn_y[k] = height(*y) - same as f64 * COAXIAL_MM;
    }
    // The wheels, edge-on in their planes: from the axis to the poles where they mesh (the
    // half of the scheme on the side of the triangles; a satellite across its diameter).
    for (w, wheel) in train.wheels.iter().enumerate() {
        let x = plane_x(planes[w]);
        let y = height(ys[wheel.shaft]);
        let ends: Vec<f64> = train
            .meshes
            .iter()
            .zip(poles)
            .filter(|(m, _)| m.0 == w || m.1 == w)
            .map(|(_, p)| height(*p))
            .collect();
        let (lo, hi) = ends.iter().fold((y, y), |(l, h), e| (l.min(*e), h.max(*e)));
        if hi - lo <= 0.0 {
            continue;
        }
        if wheel.internal {
            // A ring: its rim at the poles in the plane, its disc a cup set off the plane
            // (so that the wheels inside it are not drawn over it).
            let cup = x + CUP_MM;
            let mut id = None;
            for &end in &ends {
                let rim = rec.draw(
                    format!("ring {}'s rim and cup", wheel.name),
                    Item::Polyline {
                        points: vec![DVec2::new(x, end), DVec2::new(cup, end), DVec2::new(cup, y)],
                        closed: false,
                    },
                    Role::Given,
                    &[],
                );
                rec.draw(
                    format!("ring {}'s teeth at the pole", wheel.name),
                    Item::Segment(Segment::new(
                        DVec2::new(x, end - BAR_MM),
                        DVec2::new(x, end + BAR_MM),
                    )),
                    Role::Given,
                    &[rim],
                );
                id.get_or_insert(rim);
            }
            if let Some(id) = id {
                rec.label(
                    id,
                    format!("z_{{{}}} = {}", wheel.name, wheel.z),
                    DVec2::new(cup, 0.5 * (y + ends[0])),
                    DVec2::new(1.0, 0.0),
                );
            }
            continue;
        }
        let id = rec.draw(
            format!("wheel {} edge-on, its pitch radius", wheel.name),
            Item::Segment(Segment::new(DVec2::new(x, lo), DVec2::new(x, hi))),
            Role::Given,
            &[],
        );
        for &end in &ends {
            // The bars across the line where the teeth are.
            rec.draw(
                format!("wheel {}'s end bar", wheel.name),
                Item::Segment(Segment::new(
                    DVec2::new(x - BAR_MM, end),
                    DVec2::new(x + BAR_MM, end),
                )),
                Role::Given,
                &[id],
            );
        }
        let top = if hi - y >= y - lo { hi } else { lo };
        // Named beside its line, in the room before the next plane.
        rec.label(
            id,
            format!("z_{{{}}} = {}", wheel.name, wheel.z),
            DVec2::new(x, 0.5 * (y + top)),
            DVec2::new(1.0, 0.0),
        );
    }
    // The shafts: from their first wheel's plane to their last, on bearings on the frame;
    // the carrier's from its arm.
    for (k, name) in train.shafts.iter().enumerate() {
        let xs: Vec<f64> = train
            .wheels
            .iter()
            .enumerate()
            .filter(|(_, w)| w.shaft == k)
            .map(|(i, _)| plane_x(planes[i]))
            .collect();
        let y = drawn_y[k];
        let carrier = train.carrier == Some(k);
        let satellite = train.satellites.contains(&k);
        let arm = carrier
            .then(|| {
                train
                    .wheels
                    .iter()
                    .enumerate()
                    .filter(|(_, w)| train.satellites.contains(&w.shaft))
                    .map(|(i, _)| plane_x(planes[i]))
                    .fold(f64::NEG_INFINITY, f64::max)
                    + ARM_MM
            })
            .filter(|x| x.is_finite());
        let (mut a, mut b) = xs
            .iter()
            .chain(arm.iter())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
                (l.min(*x), h.max(*x))
            });
        if !a.is_finite() {
            continue;
        }
        if satellite {
            // The axle of the satellite, on the carrier's arm.
            a -= BAR_MM;
            b += ARM_MM;
        } else {
            a -= SHAFT_END_MM;
            b += SHAFT_END_MM;
        }
        // The input's shaft comes in from the left, the output's leaves to the right.
        if k == train.input {
            a -= SHAFT_END_MM;
        }
        if k == train.output {
            b += SHAFT_END_MM;
        }
        let id = rec.draw(
            format!("the shaft {name}"),
            Item::Segment(Segment::new(DVec2::new(a, y), DVec2::new(b, y))),
            Role::Given,
            &[],
        );
        if satellite {
            continue;
        }
        let end = if k == train.output { b } else { a };
        if train.fixed == Some(k) {
            // The support wheel's shaft fixed to the frame.
            rec.draw(
                format!("the shaft {name} fixed to the frame"),
                Item::Guide {
                    segment: Segment::new(DVec2::new(end, y - 3.0), DVec2::new(end, y + 3.0)),
                    hatch: if k == train.output {
                        Side::Right
                    } else {
                        Side::Left
                    },
                },
                Role::Given,
                &[id],
            );
        } else {
            rec.draw(
                format!("the bearing of the shaft {name}"),
                Item::Joint {
                    at: DVec2::new(if k == train.output { b - 3.0 } else { a + 3.0 }, y),
                    fixed: true,
                },
                Role::Given,
                &[id],
            );
        }
        if carrier || k == train.input || k == train.output {
            rec.label(id, name.clone(), DVec2::new(end, y), DVec2::new(0.0, 1.0));
        }
        if let Some(x) = arm {
            // The carrier's arm up (or down) to its satellites' axles.
            for &s in &train.satellites {
                let arm = rec.draw(
                    format!("the carrier's arm to the axle of {}", train.shafts[s]),
                    Item::Segment(Segment::new(DVec2::new(x, y), DVec2::new(x, drawn_y[s]))),
                    Role::Given,
                    &[id],
                );
                rec.draw(
                    format!("the axle of {} turning on the carrier", train.shafts[s]),
                    Item::Joint {
                        at: DVec2::new(x, drawn_y[s]),
                        fixed: false,
                    },
                    Role::Given,
                    &[arm],
                );
            }
        }
    }
}

/// The plane of each wheel: wheels that mesh turn in one plane, numbered in the order of
/// their first mesh (a wheel that meshes nothing gets a plane of its own).
fn planes(train: &Train) -> Vec<usize> {
    let n = train.wheels.len();
    let mut plane: Vec<Option<usize>> = vec![None; n];
    let mut next = 0;
    for start in 0..n {
        if plane[start].is_some() {
            continue;
        }
        plane[start] = Some(next);
        // Every wheel meshing one already in the plane joins it.
        let mut grew = true;
        while grew {
            grew = false;
            for m in &train.meshes {
                for (a, b) in [(m.0, m.1), (m.1, m.0)] {
                    if plane[a] == Some(next) && plane[b].is_none() {
                        plane[b] = Some(next);
                        grew = true;
                    }
                }
            }
        }
        next += 1;
    }
    plane.into_iter().map(|p| p.unwrap_or(0)).collect()
}
