//! The train's kinematic scheme (seed 002 PZ2 §3.6 step 1, seed 000's reducer), drawn the
//! textbook way beside its velocity triangles and at their heights: the axes horizontal, each
//! wheel seen edge-on as its pitch diameter (ГОСТ 2.770: a line across the shaft with short
//! bars at its teeth; a ring as its rim and a cup-shaped disc), the wheels that mesh in one
//! plane, the carrier a cranked link holding the satellites' axle, every wheel named with its
//! z. Every shaft on the frame has its own support, named by the shaft: a bearing, or the
//! support wheel's shaft fixed to the frame (hatched). Shafts on one axis are nested, each
//! running out past the one around it to its support (the input's to the left, the output's
//! to the right, another's to the nearer side), so that no two supports, nor a support and a
//! wheel, are drawn over each other.

mod cups;
mod names;

use super::train::Train;
use crate::construct::{Item, Recorder, Role};
use crate::geom::{DVec2, Segment, Side};
use cups::{runs_through_ring, set_cups};
use names::name_rings_clear;

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
/// A bearing's distance inside its shaft's end, mm.
const BEARING_INSET_MM: f64 = 3.0;
/// Half height of the hatched fixing of the support wheel's shaft, mm.
const FIXING_MM: f64 = 3.0;
/// The room a support keeps about its point: left, right, below, above (the bearing's legs
/// and ground 8 mm wide and 7.6 mm deep, and its name above), mm.
const SUPPORT_ROOM_MM: [f64; 4] = [5.0, 5.0, 8.5, 7.0];
/// The width a name is given per character, mm (a 3.5 mm label's letters and digits).
const NAME_CHAR_MM: f64 = 2.4;
/// How far a shaft is run out at a time until its support is clear, mm.
const RUN_OUT_MM: f64 = 4.0;
/// The most a shaft is run out to clear its support, mm.
const RUN_OUT_MAX_MM: f64 = 120.0;

/// A box in figure mm: (lo, hi).
type Room = (DVec2, DVec2);

/// What a shaft holds along the axes ([`spans`]): its leftmost and rightmost, and how far it
/// runs past each.
#[derive(Debug, Clone, Copy)]
struct Span {
    lo: f64,
    hi: f64,
    stub: (f64, f64),
}

/// Whether two boxes overlap (a box of no height is a horizontal line: whether it crosses).
fn overlaps(a: &Room, b: &Room) -> bool {
    a.0.x < b.1.x && b.0.x < a.1.x && a.0.y < b.1.y && b.0.y < a.1.y
}

/// Where a shaft is drawn: its ends, its height, and its support (none for a satellite's
/// axle): the support's point and whether it is the fixed shaft's hatched fixing.
struct Run {
    ends: (f64, f64),
    y: f64,
    support: Option<(f64, bool)>,
}

/// A wheel as the scheme draws it: its plane's x, its axis's height, the heights of its
/// poles, a ring's disc (how far from its plane it stands, signed: `None` for an external
/// wheel), and where a ring's name stands: left of its cup (else right), and how far from
/// the axis up the cup (a fraction of the way to its pole).
struct WheelMark {
    x: f64,
    y: f64,
    ends: Vec<f64>,
    cup: Option<f64>,
    name_left: bool,
    name_up: f64,
}

impl WheelMark {
    /// The lowest and highest of its axis and poles.
    fn extent(&self) -> (f64, f64) {
        self.ends
            .iter()
            .fold((self.y, self.y), |(l, h), e| (l.min(*e), h.max(*e)))
    }

    /// The way its name is written from [`WheelMark::name_at`].
    fn name_toward(&self) -> DVec2 {
        DVec2::new(if self.name_left { -1.0 } else { 1.0 }, 0.0)
    }

    /// Where its name `z_i = N` is written: beside its line (a ring's cup), halfway to its
    /// farther pole.
    fn name_at(&self) -> DVec2 {
        if let Some(cup) = self.cup {
            let first = self.ends.first().copied().unwrap_or(self.y);
            return DVec2::new(self.x + cup, self.y + self.name_up * (first - self.y));
        }
        let (lo, hi) = self.extent();
        let top = if hi - self.y >= self.y - lo { hi } else { lo };
        DVec2::new(self.x, 0.5 * (self.y + top))
    }

    /// The boxes its lines and its name `name` take.
    fn rooms(&self, name: &str) -> Vec<Room> {
        let (lo, hi) = self.extent();
        let cup = self.cup.unwrap_or(0.0);
        let left = self.x + cup.min(0.0) - if cup < 0.0 { 0.5 } else { BAR_MM };
        let right = self.x + cup.max(0.0) + if cup > 0.0 { 0.5 } else { BAR_MM };
        vec![
            (DVec2::new(left, lo), DVec2::new(right, hi)),
            self.name_room(name),
        ]
    }

    /// The box its name `name` takes.
    fn name_room(&self, name: &str) -> Room {
        let at = self.name_at();
        let half = 0.5 * SUPPORT_ROOM_MM[3];
        let wide = 1.0 + name_width(name);
        let x0 = if self.name_left { at.x - wide } else { at.x };
        (
            DVec2::new(x0, at.y - half),
            DVec2::new(x0 + wide, at.y + half),
        )
    }
}

/// The width a name in label markup takes, mm: its characters but the markup's.
fn name_width(name: &str) -> f64 {
    let shown = name
        .chars()
        .filter(|c| !matches!(c, '_' | '{' | '}'))
        .count();
    NAME_CHAR_MM * shown as f64
}

/// A wheel's name as the scheme writes it: `z_{i} = N`.
fn wheel_name(train: &Train, w: usize) -> String {
    format!("z_{{{}}} = {}", train.wheels[w].name, train.wheels[w].z)
}

/// Draw `train`'s scheme into `rec` with its right edge (its rightmost line, support or
/// name) at `right` (figure mm), the shafts at the heights `height(ys[k])` of the triangles,
/// the wheels reaching their mesh poles `poles` (one per mesh).
pub(super) fn draw_scheme(
    rec: &mut Recorder,
    train: &Train,
    (ys, poles): (&[f64], &[f64]),
    height: impl Fn(f64) -> f64,
    scale_l: f64,
    right: f64,
) {
    let planes = planes(train);
    // Plane p at p·PLANE_MM, the first plane leftmost; moved right of the edge at the end.
    let wheel_x: Vec<f64> = planes.iter().map(|&p| p as f64 * PLANE_MM).collect();
    // Shafts on one axis drawn apart, in the order of the shafts; each axis by its first
    // shaft.
    let coaxial = |a: f64, b: f64| (a - b).abs() <= 1e-9 * scale_l.max(b.abs());
    let axis: Vec<usize> = ys
        .iter()
        .map(|y| ys.iter().position(|v| coaxial(*v, *y)).unwrap_or(0))
        .collect();
    let mut drawn_y = vec![0.0; train.shafts.len()];
    for (k, y) in ys.iter().enumerate() {
        let same = (0..k).filter(|&j| axis[j] == axis[k]).count();
        drawn_y[k] = height(*y) - same as f64 * COAXIAL_MM;
    }
    let mut marks: Vec<WheelMark> = train
        .wheels
        .iter()
        .enumerate()
        .map(|(w, wheel)| WheelMark {
            x: wheel_x[w],
            y: drawn_y[wheel.shaft],
            ends: train
                .meshes
                .iter()
                .zip(poles)
                .filter(|(m, _)| m.0 == w || m.1 == w)
                .map(|(_, p)| height(*p))
                .collect(),
            cup: wheel.internal.then_some(CUP_MM),
            name_left: false,
            name_up: 0.5,
        })
        .collect();
    let arm = arm_x(train, &wheel_x);
    set_cups(&mut marks, train, arm, &drawn_y);
    let spans = spans(train, &marks, arm);
    // The shafts as far as their wheels reach (run out to their supports later).
    let shafts: Vec<Room> = (spans.iter().zip(&drawn_y))
        .filter_map(|(span, &y)| {
            let s = span.as_ref()?;
            Some((
                DVec2::new(s.lo - s.stub.0, y),
                DVec2::new(s.hi + s.stub.1, y),
            ))
        })
        .collect();
    name_rings_clear(&mut marks, train, &shafts);
    let mut taken: Vec<Room> = marks
        .iter()
        .enumerate()
        .flat_map(|(w, m)| m.rooms(&wheel_name(train, w)))
        .collect();
    let mut runs = runs(train, &marks, (&spans, &axis), &drawn_y, &mut taken);
    let edge = taken
        .iter()
        .map(|r| r.1.x)
        .chain(runs.iter().flatten().map(|r| r.ends.1))
        .fold(f64::NEG_INFINITY, f64::max);
    let dx = if edge.is_finite() { right - edge } else { 0.0 };
    for (w, mut mark) in marks.into_iter().enumerate() {
        mark.x += dx;
        draw_wheel(rec, train, w, &mark);
    }
    for run in runs.iter_mut().flatten() {
        run.ends = (run.ends.0 + dx, run.ends.1 + dx);
        if let Some((x, _)) = run.support.as_mut() {
            *x += dx;
        }
    }
    draw_shafts(rec, train, &runs, &drawn_y, arm.map(|x| x + dx));
}

/// Wheel `w` edge-on in its plane: from the axis to the poles where it meshes (the half of
/// the scheme on the side of the triangles; a satellite across its diameter), named.
fn draw_wheel(rec: &mut Recorder, train: &Train, w: usize, mark: &WheelMark) {
    let wheel = &train.wheels[w];
    let (x, y) = (mark.x, mark.y);
    let (lo, hi) = mark.extent();
    if hi - lo <= 0.0 {
        return;
    }
    let name = wheel_name(train, w);
    if let Some(cup) = mark.cup {
        // A ring: its rim at the poles in the plane, its disc a cup set off the plane (so
        // that the wheels inside it are not drawn over it).
        let cup = x + cup;
        let mut id = None;
        for &end in &mark.ends {
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
            rec.label(id, name, mark.name_at(), mark.name_toward());
        }
        return;
    }
    let id = rec.draw(
        format!("wheel {} edge-on, its pitch radius", wheel.name),
        Item::Segment(Segment::new(DVec2::new(x, lo), DVec2::new(x, hi))),
        Role::Given,
        &[],
    );
    for &end in &mark.ends {
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
    // Named beside its line, in the room before the next plane.
    rec.label(id, name, mark.name_at(), DVec2::new(1.0, 0.0));
}

/// The carrier's arm: past the satellites' last plane (`None` without a carrier or
/// satellites' wheels).
fn arm_x(train: &Train, wheel_x: &[f64]) -> Option<f64> {
    train.carrier?;
    let x = train
        .wheels
        .iter()
        .enumerate()
        .filter(|(_, w)| train.is_satellite(w.shaft))
        .map(|(i, _)| wheel_x[i])
        .fold(f64::NEG_INFINITY, f64::max)
        + ARM_MM;
    x.is_finite().then_some(x)
}

/// What each shaft holds along the axes, from its leftmost to its rightmost: its wheels'
/// planes, a ring's cup, the carrier's arm, each with the stub the shaft runs past it (past a
/// wheel; none past a cup or an arm, where the shaft ends) (`None`: nothing).
fn spans(train: &Train, marks: &[WheelMark], arm: Option<f64>) -> Vec<Option<Span>> {
    (0..train.shafts.len())
        .map(|k| {
            let mut xs: Vec<(f64, f64)> = (train.wheels.iter().zip(marks))
                .filter(|(w, _)| w.shaft == k)
                .map(|(_, m)| match m.cup {
                    Some(cup) => (m.x + cup, 0.0),
                    None => (m.x, SHAFT_END_MM),
                })
                .collect();
            if train.carrier == Some(k) {
                xs.extend(arm.map(|x| (x, 0.0)));
            }
            let lo = xs.iter().copied().min_by(|a, b| a.0.total_cmp(&b.0))?;
            let hi = xs.iter().copied().max_by(|a, b| a.0.total_cmp(&b.0))?;
            Some(Span {
                lo: lo.0,
                hi: hi.0,
                stub: (lo.1, hi.1),
            })
        })
        .collect()
}

/// The room a support at `at` takes with its name `name` above it.
fn support_room(at: DVec2, name: &str) -> Room {
    let [left, right, below, above] = SUPPORT_ROOM_MM;
    let named = at.x + name_width(name);
    (
        DVec2::new(at.x - left, at.y - below),
        DVec2::new((at.x + right).max(named), at.y + above),
    )
}

/// Each shaft's run: a satellite's axle from its wheels to the carrier's arm; a shaft on the
/// frame from its wheels out to its support on its side — the input's left, the output's
/// right, another's on the side where it holds nearer the end of its axis's wheels; the other
/// side where that one would run through the disc of another shaft's ring (`marks`) — run out
/// until its support and name are clear of every wheel and support already drawn (`taken`,
/// which it joins). The shafts of one axis and side are run out outermost first, so that each
/// inner shaft passes through the ones around it.
fn runs(
    train: &Train,
    marks: &[WheelMark],
    (spans, axis): (&[Option<Span>], &[usize]),
    drawn_y: &[f64],
    taken: &mut Vec<Room>,
) -> Vec<Option<Run>> {
    let n = train.shafts.len();
    let mut out: Vec<Option<Run>> = (0..n).map(|_| None).collect();
    // The side of each shaft on the frame: −1 left, +1 right.
    let axis_of = |k: usize| {
        (0..n)
            .filter(|&j| axis[j] == axis[k])
            .filter_map(|j| spans[j])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), s| {
                (l.min(s.lo), h.max(s.hi))
            })
    };
    let side = |k: usize, span: Span| -> f64 {
        let (a, b) = axis_of(k);
        let s = if k == train.input {
            -1.0
        } else if k == train.output || b - span.hi < span.lo - a {
            1.0
        } else {
            -1.0
        };
        // Never out through another shaft's ring.
        let pierces = |s: f64| {
            let beyond = |x: f64| if s > 0.0 { x > span.hi } else { x < span.lo };
            runs_through_ring(train, marks, k, drawn_y[k], beyond)
        };
        if pierces(s) && !pierces(-s) {
            -s
        } else {
            s
        }
    };
    let mut order: Vec<(usize, f64, f64)> = Vec::new();
    for k in 0..n {
        let Some(span) = spans[k] else {
            continue;
        };
        let (lo, hi) = (span.lo, span.hi);
        if train.is_satellite(k) {
            out[k] = Some(Run {
                ends: (lo - BAR_MM, hi + ARM_MM),
                y: drawn_y[k],
                support: None,
            });
            continue;
        }
        let s = side(k, span);
        // Outermost first: on the right the one that holds furthest right; the input and
        // the output last, so that they run out furthest.
        let last = if k == train.input || k == train.output {
            1e9
        } else {
            0.0
        };
        order.push((k, s, last + if s > 0.0 { -hi } else { lo }));
    }
    order.sort_by(|a, b| a.2.total_cmp(&b.2).then(a.0.cmp(&b.0)));
    for (k, s, _) in order {
        let Some(Span { lo, hi, stub }) = spans[k] else {
            continue;
        };
        let y = drawn_y[k];
        let fixed = train.fixed == Some(k);
        let extra = if k == train.input || k == train.output {
            SHAFT_END_MM
        } else {
            0.0
        };
        let inset = if fixed { 0.0 } else { BEARING_INSET_MM };
        let name = &train.shafts[k];
        let mut run_out = 0.0;
        let at = |run_out: f64| {
            let end = if s > 0.0 {
                hi + SHAFT_END_MM + extra + run_out
            } else {
                lo - SHAFT_END_MM - extra - run_out
            };
            (end, end - s * inset)
        };
        while run_out < RUN_OUT_MAX_MM {
            let room = support_room(DVec2::new(at(run_out).1, y), name);
            if !taken.iter().any(|t| overlaps(t, &room)) {
                break;
            }
            run_out += RUN_OUT_MM;
        }
        let (end, x) = at(run_out);
        taken.push(support_room(DVec2::new(x, y), name));
        let near = if s > 0.0 { lo - stub.0 } else { hi + stub.1 };
        out[k] = Some(Run {
            ends: (near.min(end), near.max(end)),
            y,
            support: Some((x, fixed)),
        });
    }
    out
}

/// The shafts with their supports, each named; the carrier's arm to its satellites' axles.
fn draw_shafts(
    rec: &mut Recorder,
    train: &Train,
    runs: &[Option<Run>],
    drawn_y: &[f64],
    arm: Option<f64>,
) {
    for (k, name) in train.shafts.iter().enumerate() {
        let Some(run) = &runs[k] else { continue };
        let (a, b) = run.ends;
        let y = run.y;
        let id = rec.draw(
            format!("the shaft {name}"),
            Item::Segment(Segment::new(DVec2::new(a, y), DVec2::new(b, y))),
            Role::Given,
            &[],
        );
        let Some((x, fixed)) = run.support else {
            continue;
        };
        let (lo, hi) = if fixed {
            fixing_span(runs, k, x)
        } else {
            (y, y)
        };
        let support = if fixed {
            // The support wheel's shaft fixed to the frame at its end.
            rec.draw(
                format!("the shaft {name} fixed to the frame"),
                Item::Guide {
                    segment: Segment::new(DVec2::new(x, lo), DVec2::new(x, hi)),
                    hatch: if x > 0.5 * (a + b) {
                        Side::Right
                    } else {
                        Side::Left
                    },
                },
                Role::Given,
                &[id],
            )
        } else {
            rec.draw(
                format!("the bearing of the shaft {name}"),
                Item::Joint {
                    at: DVec2::new(x, y),
                    fixed: true,
                },
                Role::Given,
                &[id],
            )
        };
        rec.label(
            support,
            name.clone(),
            DVec2::new(x, hi),
            DVec2::new(0.0, 1.0),
        );
        if train.carrier != Some(k) {
            continue;
        }
        let Some(x) = arm else { continue };
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

/// The heights the hatched fixing of shaft `k` at `x` spans: [`FIXING_MM`] each side of
/// the shaft, or, where a shaft on its axis runs on through the fixing (the one it is nested
/// over), as far on the shaft's outer side only, so that the shaft running through stays
/// free.
fn fixing_span(runs: &[Option<Run>], k: usize, x: f64) -> (f64, f64) {
    let Some(run) = &runs[k] else {
        return (0.0, 0.0);
    };
    let y = run.y;
    let through = runs.iter().enumerate().find_map(|(j, r)| {
        let r = r.as_ref()?;
        (j != k && (r.y - y).abs() < FIXING_MM && r.ends.0 < x && x < r.ends.1).then_some(r.y)
    });
    match through {
        None => (y - FIXING_MM, y + FIXING_MM),
        Some(inner) if inner < y => (y, y + 2.0 * FIXING_MM),
        Some(_) => (y - 2.0 * FIXING_MM, y),
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
