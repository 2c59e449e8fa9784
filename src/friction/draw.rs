//! Drawing-board steps shared by the friction cases: labelled arrows, angle marks, the
//! friction cone at a contact, and the force triangle Q + P + R = 0 (or Q + P = R).

use crate::construct::{ConstructionError, Item, Recorder, Role, StepId};
use crate::geom::{rotate, Arc, DVec2, Line, Segment};

/// How far a construction line runs past the points it joins, mm.
const RUN_ON_MM: f64 = 6.0;

/// The friction cones' height on a scheme, mm: a scheme is drawn large enough that the
/// loads, R, the normal and the cone stand apart beside the body's 10 mm (issue 45: at 28 mm
/// they crowded it, and φ's arc was a few millimetres). P, parallel to R beside it on the
/// slider, is drawn shorter than R, so that their names stand at different heights.
pub(super) const CONE_MM: f64 = 42.0;

/// Record an arrowed vector with its label beside its middle, on the side `side` (a unit
/// direction, or zero for the left of the arrow).
pub(super) fn arrow(
    rec: &mut Recorder,
    note: &str,
    (from, to): (DVec2, DVec2),
    role: Role,
    label: &str,
    side: DVec2,
) -> StepId {
    let id = rec.draw(note, Item::Vector { from, to }, role, &[]);
    let along = (to - from).normalize_or(DVec2::X);
    let toward = if side == DVec2::ZERO {
        along.perp()
    } else {
        side
    };
    if !label.is_empty() {
        rec.label(id, label, from.lerp(to, 0.6), toward);
    }
    id
}

/// Record a thin construction line from `a` to `b`, run on past both ends.
pub(super) fn thin_line(rec: &mut Recorder, note: &str, a: DVec2, b: DVec2) -> StepId {
    let u = (b - a).normalize_or(DVec2::X) * RUN_ON_MM;
    rec.draw(
        note,
        Item::Segment(Segment::new(a - u, b + u)),
        Role::Construction,
        &[],
    )
}

/// Record an angle mark of radius `r` at `centre` from direction `from` to `to`, labelled.
pub(super) fn angle_mark(
    rec: &mut Recorder,
    note: &str,
    centre: DVec2,
    r: f64,
    (from, to): (DVec2, DVec2),
    label: &str,
) -> StepId {
    let arc = Arc::between(centre, r, from, to);
    let id = rec.draw(note, Item::Angle(arc), Role::Dimension, &[]);
    let mid = arc.eval(0.5);
    rec.label(id, label, mid, (mid - centre).normalize_or(DVec2::Y));
    id
}

/// How far the normal runs on past the friction cone's base, mm.
const NORMAL_PAST_BASE_MM: f64 = 6.0;

/// The friction cone at contact `c` with unit normal `n` and friction coefficient `f`: the
/// normal drawn `len` mm, the two generators at ±φ (their ends a distance `f·len` either
/// side of the normal's end) and the base joining them. Returns the generators' ends
/// (left, right of the normal) and the normal's end.
pub(super) fn cone(
    rec: &mut Recorder,
    c: DVec2,
    n: DVec2,
    f: f64,
    len: f64,
) -> (DVec2, DVec2, DVec2) {
    let top = c + n * len;
    let left = top + n.perp() * (f * len);
    let right = top - n.perp() * (f * len);
    // The normal from the contact runs on past the base, its name at its end: clear of the
    // base and of the generators, which meet the base there. Not on into the body under the
    // contact, where a load along it would be drawn twice (the screw's Q, case 4).
    let end = top + n * NORMAL_PAST_BASE_MM;
    let id = rec.draw(
        "the normal n–n at the contact",
        Item::Segment(Segment::new(c, end)),
        Role::Axis,
        &[],
    );
    rec.label(id, "n", end, n);
    rec.draw(
        "f·N laid across the normal: the base of the friction cone",
        Item::Segment(Segment::new(left, right)),
        Role::Construction,
        &[],
    );
    for (end, side) in [(left, "left"), (right, "right")] {
        rec.draw(
            format!("friction cone: the {side} generator at φ to the normal"),
            Item::Segment(Segment::new(c, end)),
            Role::Construction,
            &[],
        );
    }
    (left, right, top)
}

/// A force triangle read off the drawing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Triangle {
    /// The start of Q.
    pub a: DVec2,
    /// The end of Q, start of P.
    pub b: DVec2,
    /// The end of P, start of R.
    pub c: DVec2,
    /// P as read, signed along its given direction, N.
    pub p: f64,
    /// R as read, signed along its given direction, N.
    pub r: f64,
    /// The crossing angle of the lines of P and R, degrees.
    pub crossing_deg: f64,
}

/// The names of a triangle's three forces (label markup).
pub(super) type Names<'a> = [&'a str; 3];

/// What a triangle's third side is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Third {
    /// A force that closes it, Q + P + R = 0: drawn from the end of P to the start of Q.
    Closes,
    /// The resultant of the first two, Q + P = R (the net force ΔP a slider's triangle
    /// reads): drawn from the start of Q to the end of P.
    Resultant,
}

/// The force triangle Q + P + R = 0 (or Q + P = R, [`Third::Resultant`]) at the recorder's
/// μ_F: Q (N, a vector) laid from `a`; through its end a line along `p_dir`, through `a` a
/// line along `r_dir` (the direction of R acting on the body, or of the resultant); their
/// intersection closes the triangle. P and R are measured.
pub(super) fn triangle(
    rec: &mut Recorder,
    a: DVec2,
    q: DVec2,
    (p_dir, r_dir): (DVec2, DVec2),
    names: Names<'_>,
    (role, third): (Role, Third),
) -> Result<Triangle, ConstructionError> {
    let mu = rec.scale().value();
    let b = a + q / mu;
    let [qn, pn, rn] = names;
    let centroid_guess = a + (b - a) * 0.5 + p_dir * 10.0;
    let out = |p: DVec2| (p - centroid_guess).normalize_or(DVec2::X);
    arrow(
        rec,
        &format!("{qn} laid at μ_F"),
        (a, b),
        Role::Given,
        qn,
        out(a.lerp(b, 0.5)),
    );
    // Both directions are unit vectors made from angles.
    let line_p = Line {
        point: b,
        direction: p_dir.normalize_or(DVec2::X),
    };
    let line_r = Line {
        point: a,
        direction: r_dir.normalize_or(DVec2::Y),
    };
    let (c, crossing, _) = rec.meet_lines(
        &format!("the triangle {qn}, {pn}, {rn}"),
        (pn, &line_p),
        (rn, &line_r),
    )?;
    thin_line(rec, &format!("line of {pn} through the end of {qn}"), b, c);
    thin_line(
        rec,
        &format!("line of {rn} through the start of {qn}"),
        c,
        a,
    );
    let centroid = (a + b + c) / 3.0;
    let side = |m: DVec2| (m - centroid).normalize_or(DVec2::X);
    arrow(rec, pn, (b, c), role, pn, side(b.lerp(c, 0.5)));
    let (r_from, r_to) = match third {
        Third::Closes => (c, a),
        Third::Resultant => (a, c),
    };
    arrow(rec, rn, (r_from, r_to), role, rn, side(c.lerp(a, 0.5)));
    let sign = |v: DVec2, d: DVec2| if v.dot(d) < 0.0 { -1.0 } else { 1.0 };
    let p = rec.measure(b, c).value * sign(c - b, p_dir);
    let r = rec.measure(r_from, r_to).value * sign(r_to - r_from, r_dir);
    Ok(Triangle {
        a,
        b,
        c,
        p,
        r,
        crossing_deg: crossing.to_degrees(),
    })
}

/// `v` turned by `angle` radians counter-clockwise (re-exported for the cases).
pub(super) fn turned(v: DVec2, angle: f64) -> DVec2 {
    rotate(v, angle)
}
