//! Loads drawn on a link's drawing or on the lever: each force its own arrow and its own
//! label, each couple its own arc. Two loads at one point along one line (the inertia force
//! and the useful resistance on the ram, the crank's reaction and the inner one at a block)
//! are two arrows — the second onto the point, or past the first — never one arrow with a
//! joint label `F_и5 ≡ F_пс` (issue 45).

use crate::construct::{Item, Recorder, Role, StepId};
use crate::geom::{Arc, DVec2, Segment};
use std::f64::consts::PI;

/// A line lies on another when both its ends are this close to the other's line and they
/// share more than [`SHARED_MM`] of their length, mm (a main line is 0.5 mm wide: closer,
/// two lines print as one).
pub const ON_LINE_MM: f64 = 1.0;
/// See [`ON_LINE_MM`], mm.
const SHARED_MM: f64 = 1.0;

/// Two arrows of a drawing whose ends lie this close to each other's line read as one arrow,
/// mm: a result's arrowhead is 4 mm long, and two heads nearer than its length print as one
/// doubled head (two forces from one point a few degrees apart: F_и5 and R₄₋₅ along the
/// V-engine's cylinder, their heads 1.4 mm apart, F_и3 and R₂₋₃ 2.6 mm — issue 45).
const HEADS_APART_MM: f64 = 4.0;

/// Whether the lines `a`–`b` and `p`–`q` lie on each other: one of them on the other
/// ([`lies_on`]; a short line on a long one that leaves it at a small angle is on it, though
/// the long one's far end is not near the short one's line).
pub fn overlap(a: DVec2, b: DVec2, (p, q): (DVec2, DVec2), near: f64) -> bool {
    lies_on(a, b, (p, q), near) || lies_on(p, q, (a, b), near)
}

/// Whether the line `a`–`b` lies on the drawn line `p`–`q`: both its ends within `near` mm
/// of that line, and the two sharing more than [`SHARED_MM`] of their length.
pub fn lies_on(a: DVec2, b: DVec2, line: (DVec2, DVec2), near: f64) -> bool {
    lies_along(a, b, line, (near, SHARED_MM))
}

/// Whether the line `a`–`b` lies on the line `p`–`q`, in any one unit: both its ends within
/// `near` of that line, and the two sharing more than `shared` of their length.
pub fn lies_along(a: DVec2, b: DVec2, (p, q): (DVec2, DVec2), (near, shared): (f64, f64)) -> bool {
    let Some(u) = (q - p).try_normalize() else {
        return false;
    };
    let off = |x: DVec2| (x - p).perp_dot(u).abs();
    if off(a) > near || off(b) > near {
        return false;
    }
    let (s0, s1) = ((a - p).dot(u), (b - p).dot(u));
    let (lo, hi) = (s0.min(s1), s0.max(s1));
    let len = (q - p).length();
    hi.min(len) - lo.max(0.0) > shared
}

/// The vectors drawn on `rec`: (tail, head), mm.
pub fn vectors(rec: &Recorder) -> Vec<(DVec2, DVec2)> {
    rec.steps()
        .iter()
        .filter_map(|s| match s.item {
            Item::Vector { from, to } => Some((from, to)),
            _ => None,
        })
        .collect()
}

/// Draw the arrow of a force along the unit `e` at its point `x`, `len` mm long, and label
/// it `name` at its free end: from the point, or onto it (`onto`) — the first of these, then
/// the other, then past an arrow already there, that no arrow drawn on `rec` covers (lies
/// within [`HEADS_APART_MM`] of it along it: two arrows a few degrees apart are covered). The
/// label names the force ([`Recorder::label_item`]), never the point at its end.
pub fn arrow(
    rec: &mut Recorder,
    note: String,
    name: &str,
    (x, e, len): (DVec2, DVec2, f64),
    onto: bool,
) -> StepId {
    let (from, to) = placed(&vectors(rec), (x, e, len), onto);
    // The label at the end away from the point; an arrow drawn onto the point in place of
    // one from it is labelled beside its shaft, since its tail lies where the first arrow
    // would have been labelled (or at a neighbouring point).
    // An arrow drawn past another stands on its line of action away from its point: a thin
    // line joins it to the point (where an arm about the point ends).
    let near = if from.distance(x) < to.distance(x) {
        from
    } else {
        to
    };
    if near.distance(x) > ON_LINE_MM {
        rec.draw(
            format!("{note}: to its point"),
            Item::Segment(Segment::new(x, near)),
            Role::Construction,
            &[],
        );
    }
    let id = rec.draw(note, Item::Vector { from, to }, Role::Result, &[]);
    // Drawn onto the point in place of from it: the one placement ending at the point.
    if !onto && to == x {
        rec.label_item(id, name, from.lerp(to, 0.5), e.perp());
    } else if from.distance(x) < to.distance(x) {
        rec.label_item(id, name, to, e);
    } else {
        rec.label_item(id, name, from, -e);
    }
    id
}

/// Where [`arrow`] draws the arrow of a force along `e` at `x`, `len` mm long, among the
/// vectors `drawn` (tail, head): from the point, or onto it (`onto`) — the first of these,
/// then the other, then past an arrow already there, that no arrow of `drawn` covers.
pub fn placed(
    drawn: &[(DVec2, DVec2)],
    (x, e, len): (DVec2, DVec2, f64),
    onto: bool,
) -> (DVec2, DVec2) {
    let from_point = (x, x + e * len);
    let onto_point = (x - e * len, x);
    let (first, second) = if onto {
        (onto_point, from_point)
    } else {
        (from_point, onto_point)
    };
    let free = |(a, b): (DVec2, DVec2)| !drawn.iter().any(|&pq| overlap(a, b, pq, HEADS_APART_MM));
    // Past the arrows already there: one arrow's length further out each time, on the side
    // the force is drawn from.
    let past = (1..=drawn.len() + 1).map(|k| {
        let k = k as f64;
        if onto {
            (x - e * len * (k + 1.0), x - e * len * k)
        } else {
            (x + e * len * k, x + e * len * (k + 1.0))
        }
    });
    [first, second]
        .into_iter()
        .chain(past)
        .find(|&c| free(c))
        .unwrap_or(first)
}

/// Two arms this close at both ends are one arm, mm: drawn once, named once (and a force
/// whose arm's foot is this close to its point on the lever has its image's ray for arm).
pub const SAME_ARM_MM: f64 = 0.3;

/// An arm that would lie on a line already drawn (a link, a load's arrow) is dimensioned
/// this far beside it, mm (a second there this far again, up to [`ARMS_BESIDE`] deep).
pub const ARM_BESIDE_MM: f64 = 8.0;
/// See [`ARM_BESIDE_MM`].
const ARMS_BESIDE: usize = 4;

/// Draw the arm of a force from the moment centre `c` to the foot of the perpendicular on
/// its line `foot`, labelled `label` (`h_{n}`): a thin line labelled at its middle; where
/// that line is drawn already (a link, a load's arrow, another arm: drawn there it would
/// read as that line, and the label would name nothing one can see — issue 45), dimensioned
/// beside it instead, with extension lines from `c` and `foot`, one step further out for
/// each arm dimensioned there (the weights' arms on the lever all run level from the pole).
/// The one way every drawing of the force analysis draws an arm, so that [`arm_named`]
/// finds it.
pub fn arm(rec: &mut Recorder, note: String, (c, foot): (DVec2, DVec2), label: &str) -> StepId {
    let drawn = drawn_lines(rec);
    let on_ink = |a: DVec2, b: DVec2| drawn.iter().any(|&pq| lies_on(a, b, pq, ON_LINE_MM));
    if on_ink(c, foot) {
        // One side first, stacked outwards as baseline dimensions are, then the other: the
        // first place clear of the lines drawn whose dimension line leaves its text room
        // between the lines crossing it, else the first clear one.
        let n = (foot - c).normalize_or_zero().perp();
        let clear: Vec<f64> = [1.0, -1.0]
            .into_iter()
            .flat_map(|side| (1..=ARMS_BESIDE).map(move |k| side * k as f64 * ARM_BESIDE_MM))
            .filter(|&d| !on_ink(c + n * d, foot + n * d))
            .collect();
        // The named points, whose labels the dimension line keeps clear of.
        let points: Vec<DVec2> = rec
            .steps()
            .iter()
            .filter_map(|s| match (&s.item, &s.label) {
                (Item::Point(x), Some(_)) => Some(*x),
                _ => None,
            })
            .collect();
        let roomy = clear.iter().copied().find(|&d| {
            let (a, b) = (c + n * d, foot + n * d);
            let line = Segment::new(a, b);
            room(a, b, &drawn) >= TEXT_ROOM_MM
                && points.iter().all(|&x| line.distance_to(x) >= POINT_ROOM_MM)
        });
        let beside = roomy
            .or_else(|| clear.first().copied())
            .unwrap_or(ARM_BESIDE_MM);
        return rec.dimension(note, (c, foot, beside), label);
    }
    let id = rec.draw(
        note,
        Item::Segment(Segment::new(c, foot)),
        Role::Construction,
        &[],
    );
    rec.label(
        id,
        label,
        c.lerp(foot, 0.5),
        (foot - c).perp().normalize_or_zero(),
    );
    id
}

/// A dimension's text wants this much of its line free, mm, between the lines crossing it
/// and its arrowheads: its width (`h₁₂`, about 6 mm) and on each side more than its
/// distance from its own line, that no crossing line stands nearer to it.
const TEXT_ROOM_MM: f64 = 16.0;

/// A dimension line beside an arm passes at least this far from a named point, mm: clear
/// of the point's label.
const POINT_ROOM_MM: f64 = 6.0;

/// Room of an arrowhead at each end of a dimension line, mm.
const ARROWHEAD_MM: f64 = 3.0;

/// The longest stretch of the dimension line `a`–`b` between its arrowheads that no line of
/// `drawn` crosses, mm.
fn room(a: DVec2, b: DVec2, drawn: &[(DVec2, DVec2)]) -> f64 {
    let line = Segment::new(a, b);
    let length = a.distance(b);
    let (lo, hi) = (ARROWHEAD_MM, length - ARROWHEAD_MM);
    let mut cuts: Vec<f64> = drawn
        .iter()
        .filter_map(|&(p, q)| line.crossing(&Segment::new(p, q)))
        .map(|x| x.distance(a))
        .filter(|&t| t > lo && t < hi)
        .collect();
    cuts.extend([lo, hi]);
    cuts.sort_by(f64::total_cmp);
    cuts.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max)
}

/// The straight lines drawn on `rec`: links (segments and the sides of polylines), arrows,
/// thin lines and the dimension lines of arms ([`Item::straight_pieces`]).
fn drawn_lines(rec: &Recorder) -> Vec<(DVec2, DVec2)> {
    let mut out = Vec::new();
    for s in rec.steps() {
        s.item.straight_pieces(|a, b| out.push((a, b)));
    }
    out
}

/// The name of the arm from `c` to `foot` when one is drawn on `rec` already (two forces on
/// one line of action have one arm: `h₇`, not `h₇ ≡ h₈`).
pub fn arm_named(rec: &Recorder, c: DVec2, foot: DVec2) -> Option<String> {
    rec.steps().iter().find_map(|s| {
        let (a, b) = match s.item {
            Item::Segment(seg) => (seg.from, seg.to),
            Item::Dimension { from, to, .. } => (from, to),
            _ => return None,
        };
        let l = s.label.as_ref()?;
        (l.text.starts_with("h_")
            && a.distance(c) <= SAME_ARM_MM
            && b.distance(foot) <= SAME_ARM_MM)
            .then(|| l.text.clone())
    })
}

/// A couple's arc arrow about `o` drawn by the shapers of link drawings: this radius, mm,
/// and each further couple about the same centre [`COUPLE_STEP_MM`] further out.
const COUPLE_MM: f64 = 9.0;
/// See [`COUPLE_MM`], mm.
const COUPLE_STEP_MM: f64 = 4.0;

/// A couple's arc stands in a sector this wide about its centre, rad.
const COUPLE_SWEEP: f64 = 1.6;
/// The usual sector begins here and ends there, rad: up and right of the centre.
const COUPLE_FROM: f64 = 0.3;
/// See [`COUPLE_FROM`], rad.
const COUPLE_TO: f64 = 1.9;
/// A line leaving the centre nearer the arc's tail or its arrowhead than this, rad, meets
/// it (at [`COUPLE_MM`] about 1,8 mm); a line crossing the arc's middle does not.
const COUPLE_CLEAR: f64 = 0.2;
/// The arc is turned by this step from its usual sector to clear its ends, rad.
const COUPLE_TURN: f64 = std::f64::consts::FRAC_PI_8;

/// Draw a couple `moment` (its sign: counter-clockwise positive) named `name` as an arc
/// arrow about `o`, outside every couple's arc already drawn about `o`, its ends clear of
/// the lines and arrows drawn from `o` ([`couple_turn`]), and label it at the arc's middle.
pub fn couple(rec: &mut Recorder, name: &str, o: DVec2, moment: f64) -> StepId {
    let around = rec
        .steps()
        .iter()
        .filter(|s| matches!(s.item, Item::Moment(a) if a.center.distance(o) < ON_LINE_MM))
        .count();
    let away: Vec<DVec2> = (drawn_lines(rec).into_iter())
        .filter_map(|(a, b)| leaving(o, a, b, ON_LINE_MM))
        .collect();
    let arc = couple_arc(o, moment, around, couple_turn(&away, moment, around));
    let id = rec.draw(name.to_string(), Item::Moment(arc), Role::Result, &[]);
    let mid = DVec2::from_angle(arc.start + arc.sweep / 2.0);
    rec.label_item(id, name, o + mid * arc.radius, mid);
    id
}

/// The direction a line from `a` to `b` leaves `o` in, when one of its ends is within `near`
/// of `o` and the other is not.
pub fn leaving(o: DVec2, a: DVec2, b: DVec2, near: f64) -> Option<DVec2> {
    let (close, far) = if a.distance(o) <= b.distance(o) {
        (a, b)
    } else {
        (b, a)
    };
    (close.distance(o) <= near && far.distance(o) > near).then(|| far - o)
}

/// How far the arc of a couple `moment` about its centre, `around` arcs out, is turned from
/// its usual sector, rad: not at all (up and right), unless a line leaving the centre in
/// one of the directions `away` meets its tail or its arrowhead (the shaper's rocker at
/// M_и3's head); then by the fewest [`COUPLE_TURN`] steps that every line clears, or, when
/// none does, by those whose ends they keep farthest from. A line may cross the arc's middle.
pub fn couple_turn(away: &[DVec2], moment: f64, around: usize) -> f64 {
    let clearance = |turn: f64| {
        let arc = couple_arc(DVec2::ZERO, moment, around, turn);
        let head = ARROWHEAD_MM / arc.radius;
        let run = arc.sweep.abs();
        (away.iter())
            .filter(|d| d.length_squared() > 0.0)
            .map(|d| {
                // How far along the arc the line leaves, from its tail, its way round.
                let u = ((d.y.atan2(d.x) - arc.start) * arc.sweep.signum() + PI)
                    .rem_euclid(2.0 * PI)
                    - PI;
                let past_head = (u - run).max(run - head - u).max(0.0);
                u.abs().min(past_head)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let tries = (0..16).map(|k: i32| {
        let steps = if k % 2 == 0 { -k / 2 } else { (k + 1) / 2 };
        f64::from(steps) * COUPLE_TURN
    });
    (tries.clone())
        .find(|&turn| clearance(turn) >= COUPLE_CLEAR)
        .or_else(|| tries.max_by(|a, b| clearance(*a).total_cmp(&clearance(*b))))
        .unwrap_or(0.0)
}

/// The arc arrow of a couple `moment` about `o` (mm) with `around` couples' arcs drawn
/// about `o` already, its sector turned by `turn` ([`couple_turn`]): see [`couple`].
pub fn couple_arc(o: DVec2, moment: f64, around: usize, turn: f64) -> Arc {
    let (start, sweep) = if moment > 0.0 {
        (COUPLE_FROM + turn, COUPLE_SWEEP)
    } else {
        (COUPLE_TO + turn, -COUPLE_SWEEP)
    };
    Arc {
        center: o,
        radius: COUPLE_MM + COUPLE_STEP_MM * around as f64,
        start,
        sweep,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::{Context, Drafting};
    use crate::scale::{Quantity, Scale};

    fn recorder() -> Recorder {
        let mu = Scale::new(0.0025, Quantity::Length).expect("a scale");
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
        Recorder::in_context("loads", mu, &ctx)
    }

    fn vectors(rec: &Recorder) -> Vec<(DVec2, DVec2, String)> {
        rec.steps()
            .iter()
            .filter_map(|s| match (&s.item, &s.label) {
                (Item::Vector { from, to }, Some(l)) => Some((*from, *to, l.text.clone())),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn two_forces_along_one_line_at_one_point_are_two_arrows() {
        let mut rec = recorder();
        let x = DVec2::new(10.0, 5.0);
        let e = DVec2::X;
        arrow(&mut rec, "a".into(), "F_{и5}", (x, e, 14.0), false);
        arrow(&mut rec, "b".into(), "F_{пс}", (x, e, 14.0), false);
        // A third along the same line, a hair off it: past the two.
        let tilted = DVec2::new(1.0, 0.02).normalize();
        arrow(&mut rec, "c".into(), "R", (x, tilted, 14.0), false);
        let v = vectors(&rec);
        assert_eq!(v[0], (x, x + e * 14.0, "F_{и5}".into()));
        // Onto the point, labelled beside its shaft.
        assert_eq!(v[1].0, x - e * 14.0);
        assert_eq!(v[1].1, x);
        assert!(v[2].0.distance(x + tilted * 14.0) < 1e-9, "{:?}", v[2]);
        // The third joined to its point by a thin line along its line of action.
        let joined: Vec<Segment> = rec
            .steps()
            .iter()
            .filter_map(|s| match s.item {
                Item::Segment(seg) => Some(seg),
                _ => None,
            })
            .collect();
        assert_eq!(joined, [Segment::new(x, v[2].0)]);
        let arrows = rec
            .steps()
            .iter()
            .filter(|s| matches!(s.item, Item::Vector { .. }));
        for (k, s) in arrows.enumerate() {
            let l = s.label.as_ref().expect("labelled");
            assert_eq!(l.names, crate::construct::Names::Item, "arrow {k}");
        }
        // Each label at its arrow's free end: three places.
        let ends: Vec<DVec2> = rec
            .steps()
            .iter()
            .filter_map(|s| s.label.as_ref().map(|l| l.anchor))
            .collect();
        assert_eq!(ends[1], x - e * 7.0);
        assert!(ends[0].distance(ends[2]) > 10.0);
    }

    #[test]
    fn two_forces_a_few_degrees_apart_at_one_point_are_two_arrows() {
        // F_и5 along the V-engine's cylinder and R₄₋₅ 5.6° off it, from one point: their
        // heads were 1.4 mm apart, one arrow with a doubled head.
        let mut rec = recorder();
        let x = DVec2::new(3.0, 4.0);
        let e = DVec2::from_angle(2.356);
        let r = DVec2::from_angle(2.356 + 0.098);
        arrow(&mut rec, "a".into(), "F_{и5}", (x, e, 14.0), false);
        arrow(&mut rec, "b".into(), "R_{4-5}", (x, r, 14.0), false);
        let v = vectors(&rec);
        let (from, to) = (v[1].0, v[1].1);
        // Not from the point: onto it, its head at the point and its tail away from F_и5's.
        assert_eq!((from, to), (x - r * 14.0, x));
        assert!(from.distance(x + e * 14.0) > 20.0);
    }

    #[test]
    fn an_opposite_force_at_the_point_keeps_its_own_side() {
        let mut rec = recorder();
        let x = DVec2::ZERO;
        arrow(&mut rec, "a".into(), "G", (x, -DVec2::Y, 14.0), false);
        arrow(&mut rec, "b".into(), "R", (x, DVec2::Y, 14.0), false);
        let v = vectors(&rec);
        assert_eq!(v[1], (x, DVec2::Y * 14.0, "R".into()));
    }

    #[test]
    fn two_couples_on_one_link_are_two_arcs() {
        let mut rec = recorder();
        let o = DVec2::new(3.0, 4.0);
        couple(&mut rec, "M_{и3}", o, 1.0);
        couple(&mut rec, "M_{пс}", o, 2.0);
        let radii: Vec<f64> = rec
            .steps()
            .iter()
            .filter_map(|s| match s.item {
                Item::Moment(a) => Some(a.radius),
                _ => None,
            })
            .collect();
        assert_eq!(radii, [COUPLE_MM, COUPLE_MM + COUPLE_STEP_MM]);
    }

    /// The arc of a couple drawn on `rec` about `o` (the first).
    fn arc_of(rec: &Recorder) -> Arc {
        (rec.steps().iter())
            .find_map(|s| match s.item {
                Item::Moment(a) => Some(a),
                _ => None,
            })
            .expect("an arc")
    }

    /// The shaper's M_и3 (issue 45): the rocker left its centre 8° from the usual arc's
    /// arrowhead, which stood on it. The arc turns until its head and tail are clear of every
    /// line drawn from the centre; a line across its middle leaves it where it is.
    #[test]
    fn a_couple_turns_its_arrowhead_off_the_link() {
        let o = DVec2::new(3.0, 4.0);
        let line = |rec: &mut Recorder, angle: f64| {
            let far = o + DVec2::from_angle(angle) * 40.0;
            rec.draw(
                "link",
                Item::Segment(Segment::new(o, far)),
                Role::Construction,
                &[],
            );
        };
        // Clockwise: the head at the usual sector's low end, 0,3 rad, its body above it.
        let mut rec = recorder();
        line(&mut rec, 0.45);
        couple(&mut rec, "M", o, -1.0);
        let a = arc_of(&rec);
        assert_ne!(a.start, COUPLE_TO, "turned: {a:?}");
        let head = a.start + a.sweep;
        let body = head - a.sweep.signum() * ARROWHEAD_MM / a.radius;
        for end in [a.start, head, body] {
            let off = ((0.45 - end + PI).rem_euclid(2.0 * PI) - PI).abs();
            assert!(off >= COUPLE_CLEAR - 1e-12, "{end} beside the line: {a:?}");
        }
        // Across the middle, or nothing drawn: the usual arc.
        for lines in [vec![1.1], vec![]] {
            let mut rec = recorder();
            for l in lines {
                line(&mut rec, l);
            }
            couple(&mut rec, "M", o, -1.0);
            let a = arc_of(&rec);
            assert_eq!((a.start, a.sweep), (COUPLE_TO, -COUPLE_SWEEP));
        }
        // Lines every eighth of a turn: the arc the lines keep farthest from.
        let mut rec = recorder();
        for k in 0..16 {
            line(&mut rec, f64::from(k) * COUPLE_TURN);
        }
        couple(&mut rec, "M", o, 1.0);
        assert!(arc_of(&rec).sweep > 0.0);
    }
}
