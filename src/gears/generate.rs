//! Rack generation as a construction (seed 002 PZ1, the TMM-42 device): the basic rack,
//! shifted by x·m, is rolled along the pitch circle in N equal steps (rack step q ↔ wheel
//! turn q/r), set again in finer steps where the fillet turns into the root (a step of its
//! angle for every two equal ones, [`rack_states`]); at every position its outline is drawn
//! in the wheel's frame, clipped to the blank, and the points where it touches the envelope
//! are found the textbook way — where the rack's normal passes through the pole P — on the
//! straight flank (the involute), on the tip rounding (the fillet) and on the tip line (the
//! root circle). The tooth is drawn through the touching points as the French curve touching
//! the envelope there (⊥ the normal through P); undercut is detected where the drawn fillet
//! crosses the drawn involute, pointing where the tip thickness read off the drawing falls
//! below 0.3m.

use super::detail::DetailMark;
use super::numbers;
use super::rack::{Cutting, RackPiece};
use super::trace::{drawn_outline, polyline_crossing, refine, touching};
use super::{GearError, MIN_TIP};
use crate::construct::{Context, Figure, Item, Measured, Recorder, Role};
use crate::geom::{french_curve, rotate, DVec2, Segment};
use crate::scale::Scale;
use std::f64::consts::PI;

/// A point where a rack position touches the envelope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Touch {
    /// The rack's state (displacement), m.
    pub q: f64,
    /// The part of the rack touching.
    pub piece: RackPiece,
    /// The point in the wheel's frame as drawn, converted with μ, m.
    pub at: DVec2,
    /// The envelope's unit tangent there (⊥ the rack's normal through P), wheel frame.
    pub tangent: DVec2,
}

/// A generated wheel: the figure, the touching points and what was read off the drawing.
#[derive(Debug, Clone, PartialEq)]
pub struct Generation {
    /// The wheel and its analytic twin.
    pub cutting: Cutting,
    /// The number of equal rack steps N.
    pub steps: usize,
    /// μ_l of the figure.
    pub scale: Scale,
    /// The figure: the blank's circles, every rack position (position i in group i), the
    /// touching points, the tooth.
    pub figure: Figure,
    /// The groups of the positions drawn on the sheet ([`DRAWN_POSITIONS`] spread over the
    /// traced ones), numbered 1, 2, … in this order on the drawing ([`Generation::drawing`]).
    pub drawn: Vec<u32>,
    /// The undercut's detail view: its zone on the figure (figure mm) and its scale;
    /// `None` without undercut ([`Generation::detail_view`]).
    pub detail: Option<(crate::geom::Circle, Scale)>,
    /// What the detail view names and where (figure mm of [`Generation::figure`]): the
    /// involute, the limit point, the fillet, the undercut, r_b, the rack tip; empty
    /// without a detail.
    pub detail_marks: Vec<(DetailMark, DVec2)>,
    /// The touching points of the right half of the tooth (all positions, all pieces).
    pub touches: Vec<Touch>,
    /// The junction of the drawn involute and fillet, m (their crossing with undercut, the
    /// flank's end touching without).
    pub junction: DVec2,
    /// The drawn fillet crosses the drawn involute.
    pub undercut: bool,
    /// The tip chord between the two flanks as read, and the tip thickness (arc) from it, m.
    pub tip_chord: Measured,
    /// s_a from the drawing, m.
    pub sa: f64,
    /// s_a < 0.3m on the drawing.
    pub pointed: bool,
    /// The report form's readings (seed 002 PZ1, Tables 1.1/1.2), arcs from the chords read
    /// on the drawing, m: the tooth S_t and the space e_t on the pitch circle (the space
    /// between the tooth and its neighbour), and the tooth S_b on the base circle (`None`
    /// when the base circle lies inside the root circle).
    pub pitch_reading: (f64, f64),
    /// S_b on the base circle as read, m (see [`Generation::pitch_reading`]).
    pub sb: Option<f64>,
    /// The largest distance between the drawn tooth (the French curve through the touching
    /// points) and the exact envelope between them, m.
    pub deviation: f64,
    /// The mean of the largest distance of each drawn segment from the exact envelope, m.
    pub deviation_mean: f64,
    /// The largest distance of a touching point from its analytic twin, m.
    pub touch_error: f64,
}

/// The rack positions drawn, as the textbook draws them: a few, thin, numbered. Every
/// position is traced (its touching points make the tooth); only these are left on the
/// drawing, spread evenly over the traced ones, the first and the last among them.
pub const DRAWN_POSITIONS: usize = 7;

/// Generate `cutting` by `steps` equal rack steps at the scale `scale` in `ctx`.
///
/// # Errors
/// [`GearError::Spec`] for fewer than 2 steps.
pub fn generate(
    cutting: &Cutting,
    steps: usize,
    scale: Scale,
    ctx: &Context,
) -> Result<Generation, GearError> {
    if steps < 2 {
        return Err(GearError::Spec {
            what: "positions",
            value: steps as f64,
            expected: "at least 2 rack positions",
        });
    }
    let mu = scale.value();
    let c = *cutting;
    let mut rec = Recorder::in_context("generation", scale, ctx);
    // The circles about the tooth, over three pitches.
    let pitch = 2.0 * PI / f64::from(c.z);
    circles(&mut rec, &c, mu, pitch);
    let st = c.states();
    let (states, q_n, drawn) = rack_states(&c, steps);
    let touches = trace(&mut rec, &c, &states, &drawn, mu);
    let [flank, fillet, root] = pieces(&c, &touches, q_n);
    // The junction on the drawing: the first crossing of the drawn fillet (from the root
    // up) with the drawn involute; the flank's end without one.
    let fl: Vec<DVec2> = flank.iter().map(|t| t.at).collect();
    let fi: Vec<DVec2> = fillet.iter().rev().map(|t| t.at).collect();
    let crossing = polyline_crossing(&fi, &fl);
    let undercut = crossing.is_some();
    // (junction, first involute point kept above it, fillet points kept below it).
    let (junction, inv_from, fil_to) = match crossing {
        Some((p, i_fi, j_fl)) => {
            // The rack set again between the two crossing steps, halving them until the
            // crossing is pinned: the junction as a student finds it with more positions.
            let n = fillet.len();
            let step = |i: usize| (fillet[n - 1 - i].q, fi[i]);
            let refined = refine(
                &c,
                [step(i_fi), step(i_fi + 1)],
                [(flank[j_fl].q, fl[j_fl]), (flank[j_fl + 1].q, fl[j_fl + 1])],
            );
            (refined.unwrap_or(p), j_fl + 1, i_fi + 1)
        }
        None => {
            let j = flank
                .iter()
                .find(|t| (t.q - st.q_j).abs() <= 1e-12 * c.module)
                .map_or(c.involute_at(st.q_j), |t| t.at);
            (j, 1, fi.len().saturating_sub(1))
        }
    };
    // The tooth's right half as drawn: the involute from the tip down to the junction, the
    // fillet from the junction to the root, the root circle to the space's centre.
    // Between the touching points of one piece the French curve touching the envelope's
    // tangents; the junction is a corner.
    let flank_drawn: Vec<Touch> = flank
        .get(inv_from..)
        .unwrap_or(&[])
        .iter()
        .rev()
        .copied()
        .collect();
    let fillet_drawn: Vec<Touch> = fillet.iter().rev().take(fil_to).rev().copied().collect();
    let root_drawn: Vec<Touch> = root
        .iter()
        .rev()
        .filter(|t| t.q >= st.q_space - 1e-12 * c.module)
        .copied()
        .collect();
    let mut right = curve_through(&flank_drawn);
    right.push(junction);
    right.extend(curve_through(&fillet_drawn));
    right.extend(curve_through(&root_drawn));
    let tooth = whole_tooth(&right, c.ra);
    draw_teeth(&mut rec, &tooth, pitch, mu);
    let (pitch_reading, sb) = readings(&mut rec, &c, &right, pitch, mu);
    let (detail, detail_marks) = if undercut {
        let drawn_states: Vec<f64> = drawn
            .iter()
            .filter_map(|i| states.get(*i))
            .copied()
            .collect();
        let lost: Vec<DVec2> = flank[..inv_from].iter().map(|t| t.at).collect();
        super::undercut::undercut(
            &mut rec,
            (&c, mu),
            &lost,
            (junction, &fi, fil_to),
            &drawn_states,
        )?
    } else {
        (None, Vec::new())
    };
    let (tip_chord, sa) = tip_reading(&mut rec, &c, &flank, mu);
    let pointed = sa < MIN_TIP * c.module;
    // The drawn polyline against the exact envelope, piece by piece.
    let (deviation, deviation_mean) = deviations(&c, [&flank, &fillet, &root]);
    let touch_error = touches
        .iter()
        .map(|t| (t.at - twin(&c, t.piece, t.q)).length())
        .fold(0.0, f64::max);
    Ok(Generation {
        cutting: c,
        steps,
        scale,
        figure: rec.finish(),
        drawn: drawn.iter().map(|i| *i as u32 + 1).collect(),
        detail,
        detail_marks,
        touches,
        junction,
        undercut,
        tip_chord,
        sa,
        pointed,
        pitch_reading,
        sb,
        deviation,
        deviation_mean,
        touch_error,
    })
}

impl Generation {
    /// The figure as the sheet draws it: the circles, the tooth, the undercut and s_a, and of
    /// the rack positions only the [`drawn`](Generation::drawn) ones, numbered.
    pub fn drawing(&self) -> Figure {
        self.figure.only_groups(&self.drawn)
    }

    /// The undercut's detail view: the zone of [`drawing`](Generation::drawing) about the
    /// right flank's undercut, enlarged, each of its [`marks`](Generation::detail_marks)
    /// named by `name` beside its object ([`super::detail::view`]); `None` without undercut.
    pub fn detail_view(&self, name: &dyn Fn(DetailMark) -> String) -> Option<Figure> {
        let (zone, scale) = self.detail?;
        let k = self.scale.value() / scale.value();
        let view = self.drawing().detail(&zone, scale);
        Some(super::detail::view(
            view,
            &zone,
            k,
            &self.detail_marks,
            name,
        ))
    }
}

/// The radius of the tooth's axis and the circles r, r_b, r_a, r_f of `c` over three
/// pitches about it, each named at its left end, clear of the rack positions.
fn circles(rec: &mut Recorder, c: &Cutting, mu: f64, pitch: f64) {
    let (r, rb, ra, rf) = (c.r(), c.rb(), c.ra, c.rf());
    let o = rec.draw(
        "the radius of the tooth's axis",
        Item::Segment(Segment::new(
            DVec2::new(0.0, rf / mu - 2.0),
            DVec2::new(0.0, ra / mu + 2.0),
        )),
        Role::Axis,
        &[],
    );
    for (radius, name) in [(r, "r"), (rb, "r_b"), (ra, "r_a"), (rf, "r_f")] {
        let arc = crate::geom::Arc {
            center: DVec2::ZERO,
            radius: radius / mu,
            start: PI / 2.0 - 1.5 * pitch,
            sweep: 3.0 * pitch,
        };
        let id = rec.draw(
            format!("circle {name}"),
            Item::Arc(arc),
            if name == "r" {
                Role::Axis
            } else {
                Role::Construction
            },
            &[o],
        );
        // Named at its left end, clear of the rack positions.
        let end = arc.end();
        rec.label(id, name, end, DVec2::new(-1.0, 0.0));
    }
}

/// The rack's states traced: `steps` equal ones over the span; the marks of the device
/// (the flank's end, the tip, the rounding under P, and the contact passing N — the foot of
/// O on the line of action — when the flank reaches it); and the fillet's own states, where
/// the envelope bends: sorted, with that state at N and the indices of the drawn positions
/// (spread over the equal states).
///
/// The rounding touches where the ray from P through its centre meets it, at the angle β
/// below the pitch line (α at the flank's end, 90° under P): the state is
/// q_bottom − H·cot β, H the centre's depth under P. Equal states crowd the fillet's points
/// near the flank and leave them sparse where it turns into the root circle, fastest on a
/// wheel shifted far out (x = 0.8: the fillet is a twentieth of the span), so the fillet
/// is traced again at equal steps of β, one for every [`FILLET_SHARE`] equal states.
fn rack_states(c: &Cutting, steps: usize) -> (Vec<f64>, f64, Vec<usize>) {
    let st = c.states();
    let r = c.r();
    let (lo, hi) = c.span();
    let equal: Vec<f64> = (0..steps)
        .map(|i| lo + (hi - lo) * i as f64 / (steps - 1) as f64)
        .collect();
    let mut states = equal.clone();
    let q_n = st.q_p - r * c.rack.alpha.tan();
    let marks = [st.q_j, st.q_a, st.q_bottom, q_n];
    let depth = -(c.x * c.module + c.shape().vc);
    let alpha = c.rack.alpha;
    let fillet_steps = steps / FILLET_SHARE;
    let fillet = (1..fillet_steps).map(|k| {
        let beta = alpha + (0.5 * PI - alpha) * k as f64 / fillet_steps as f64;
        st.q_bottom - depth / beta.tan()
    });
    for q in marks.into_iter().filter(|q| *q >= st.q_j).chain(fillet) {
        if !states.iter().any(|s| (s - q).abs() <= 1e-12 * c.module) {
            states.push(q);
        }
    }
    states.sort_by(f64::total_cmp);
    let drawn = spread(steps, DRAWN_POSITIONS)
        .into_iter()
        .filter_map(|i| states.iter().position(|s| *s == equal[i]))
        .collect();
    (states, q_n, drawn)
}

/// The fillet is traced at one state for this many of the equal ones ([`rack_states`]).
const FILLET_SHARE: usize = 2;

/// The touching points by piece, each in the order of the rack's states: the flank (the
/// involute proper, from where the contact passes N at `q_n`: beyond N the flank traces the
/// branch the fillet cuts away), the fillet and the root.
fn pieces(c: &Cutting, touches: &[Touch], q_n: f64) -> [Vec<Touch>; 3] {
    let by = |piece: RackPiece| -> Vec<Touch> {
        let mut v: Vec<Touch> = touches
            .iter()
            .copied()
            .filter(|t| t.piece == piece)
            .collect();
        v.sort_by(|a, b| a.q.total_cmp(&b.q));
        v
    };
    let flank: Vec<Touch> = by(RackPiece::Flank)
        .into_iter()
        .filter(|t| t.q >= q_n - 1e-12 * c.module)
        .collect();
    let fillet = by(RackPiece::Fillet);
    let root = by(RackPiece::Root);
    [flank, fillet, root]
}

/// The tooth (wheel frame, m) drawn, and its neighbours cut alike a pitch either side, as
/// the device's paper shows three teeth: the spaces either side of the tooth.
fn draw_teeth(rec: &mut Recorder, tooth: &[DVec2], pitch: f64, mu: f64) {
    let mm = |p: DVec2| p / mu;
    rec.draw(
        "the tooth: the envelope of the rack positions",
        Item::Polyline {
            points: tooth.iter().map(|p| mm(*p)).collect(),
            closed: false,
        },
        Role::Result,
        &[],
    );
    for turn in [pitch, -pitch] {
        rec.draw(
            "the neighbouring tooth",
            Item::Polyline {
                points: tooth.iter().map(|p| mm(rotate(*p, turn))).collect(),
                closed: false,
            },
            Role::Result,
            &[],
        );
    }
}

/// The report form's readings: the chords where the drawn flanks (`right`, the tooth's right
/// half, m) cross the pitch and base circles, read with a ruler and turned into arcs — S_t
/// and the space e_t (from the tooth's right flank to its right neighbour's left flank) on
/// the pitch circle, S_b on the base circle when it lies outside the root circle.
fn readings(
    rec: &mut Recorder,
    c: &Cutting,
    right: &[DVec2],
    pitch: f64,
    mu: f64,
) -> ((f64, f64), Option<f64>) {
    let mm = |p: DVec2| p / mu;
    let (r, rb, rf) = (c.r(), c.rb(), c.rf());
    let mirror = |p: DVec2| DVec2::new(-p.x, p.y);
    let across = |rec: &mut Recorder, radius: f64| {
        let k = circle_crossing(right, radius)?;
        Some(chord_to_arc(
            rec.measure(mm(mirror(k)), mm(k)).value,
            radius,
        ))
    };
    let st_read = across(rec, r).unwrap_or(0.0);
    let et_read = circle_crossing(right, r).map_or(0.0, |k| {
        let next = rotate(mirror(k), -pitch);
        chord_to_arc(rec.measure(mm(k), mm(next)).value, r)
    });
    let sb = if rb > rf { across(rec, rb) } else { None };
    ((st_read, et_read), sb)
}

/// The tip thickness: the chord between the two flanks' tip points (the flank's touching
/// point at the tip, else the involute's), read with a ruler and dimensioned, and s_a from
/// it, m.
fn tip_reading(rec: &mut Recorder, c: &Cutting, flank: &[Touch], mu: f64) -> (Measured, f64) {
    let mm = |p: DVec2| p / mu;
    let st = c.states();
    let ra = c.ra;
    let tip = flank
        .iter()
        .find(|t| (t.q - st.q_a).abs() <= 1e-12 * c.module)
        .map_or(c.involute_at(st.q_a), |t| t.at);
    let tip_l = DVec2::new(-tip.x, tip.y);
    let tip_chord = rec.measure(mm(tip_l), mm(tip));
    let sa = chord_to_arc(tip_chord.value, ra);
    let dim = rec.draw(
        "s_a: the tip chord",
        Item::Dimension {
            from: mm(tip_l),
            to: mm(tip),
            offset: 4.0,
        },
        Role::Dimension,
        &[],
    );
    // Named on its dimension line, as the data line names its value (a dimension without
    // its text was the review's mark).
    let over = mm((tip_l + tip) * 0.5) + DVec2::Y * 4.0;
    rec.label(dim, "s_a", over, DVec2::Y);
    (tip_chord, sa)
}

/// Every rack position at its state in `states` drawn in the wheel's frame (each a group of
/// its own, the `drawn` ones numbered at the outer end of their outline) and the points
/// where its normal through P touches the envelope, with the envelope's tangent there.
fn trace(rec: &mut Recorder, c: &Cutting, states: &[f64], drawn: &[usize], mu: f64) -> Vec<Touch> {
    let r = c.r();
    let mm = |p: DVec2| p / mu;
    // Every position's outline in sheet mm, first: the drawn ones' outer ends place their
    // numbers together ([`numbers::places`]).
    let outlines: Vec<Vec<Vec<DVec2>>> = states.iter().map(|&q| drawn_outline(c, q, mu)).collect();
    let ends: Vec<Option<DVec2>> = drawn
        .iter()
        .map(|&i| outlines[i].last()?.last().copied())
        .collect();
    let places = numbers::places(&ends);
    let mut touches = Vec::new();
    for ((i, &q), runs) in states.iter().enumerate().zip(outlines) {
        rec.set_group(i as u32 + 1);
        let turn = q / r;
        for pts in runs {
            rec.draw(
                format!("rack position {}", i + 1),
                Item::Polyline {
                    points: pts,
                    closed: false,
                },
                Role::Construction,
                &[],
            );
        }
        // A drawn position's number at the outer end of its outline, out of the blank (or
        // carried out from it, [`numbers::places`]).
        if let Some((k, Some(place))) = drawn.iter().position(|d| *d == i).map(|k| (k, places[k])) {
            numbers::number(rec, i, k, place);
        }
        for (piece, k) in touching(c, q) {
            let at = mm(rotate(k, turn));
            rec.draw(
                format!("rack position {}: its normal through P touches", i + 1),
                Item::Point(at),
                Role::Construction,
                &[],
            );
            // The normal through P is the envelope's normal: its tangent is ⊥ it (the
            // flank's own direction where it touches at P itself).
            let flank = DVec2::new(-c.rack.alpha.sin(), c.rack.alpha.cos());
            let normal = k - DVec2::new(0.0, r);
            let tangent = normal.try_normalize().map_or(flank, DVec2::perp);
            touches.push(Touch {
                q,
                piece,
                at: at * mu,
                tangent: rotate(tangent, turn),
            });
        }
    }
    rec.set_group(0);
    touches
}

/// The exact envelope of `c` at the state `q` of the rack's `piece`, m.
fn twin(c: &Cutting, piece: RackPiece, q: f64) -> DVec2 {
    match piece {
        RackPiece::Flank => c.involute_at(q),
        RackPiece::Fillet => c.trochoid_at(q),
        RackPiece::Root => c.root_at(q),
    }
}

/// The drawn tooth (the French curve through each piece's touching points: the flank, the
/// fillet, the root) against the exact envelope of `c` between them: the largest distance
/// and the mean of each segment's largest, m. Only the points on the envelope's real part
/// count (the flank from the junction to the tip, the fillet below it, the root to the
/// space's centre).
fn deviations(c: &Cutting, pieces: [&[Touch]; 3]) -> (f64, f64) {
    let st = c.states();
    let (_, qi, qf) = c.junction();
    let real = |t: &Touch| match t.piece {
        RackPiece::Flank => t.q >= qi - 1e-12 * c.module && t.q <= st.q_a + 1e-12 * c.module,
        RackPiece::Fillet => t.q >= qf - 1e-12 * c.module,
        RackPiece::Root => t.q >= st.q_space - 1e-12 * c.module,
    };
    let mut deviation: f64 = 0.0;
    let (mut sum, mut count) = (0.0, 0usize);
    for list in pieces {
        let kept: Vec<&Touch> = list.iter().filter(|t| real(t)).collect();
        for w in kept.windows(2) {
            let curve = curve_through(&[*w[0], *w[1]]);
            let mut worst: f64 = 0.0;
            for k in 1..16 {
                let q = w[0].q + (w[1].q - w[0].q) * f64::from(k) / 16.0;
                let e = twin(c, w[0].piece, q);
                let d = curve
                    .windows(2)
                    .map(|p| Segment::new(p[0], p[1]).distance_to(e))
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(d);
            }
            deviation = deviation.max(worst);
            sum += worst;
            count += 1;
        }
    }
    let deviation_mean = if count > 0 { sum / count as f64 } else { 0.0 };
    (deviation, deviation_mean)
}

/// The indices of `count` of `n` items spread evenly, the first and the last among them
/// (all of them when `n ≤ count`).
fn spread(n: usize, count: usize) -> Vec<usize> {
    if n <= count || count < 2 {
        return (0..n.min(count)).collect();
    }
    let mut out: Vec<usize> = (0..count)
        .map(|k| (k * (n - 1) + (count - 1) / 2) / (count - 1))
        .collect();
    out.dedup();
    out
}

/// The whole tooth from its right half (tip → root → the space's centre): the mirrored left
/// half, the tip arc, the right half.
pub fn whole_tooth(right: &[DVec2], ra: f64) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = right.iter().rev().map(|p| DVec2::new(-p.x, p.y)).collect();
    if let (Some(l), Some(r)) = (out.last().copied(), right.first().copied()) {
        let (al, ar) = (l.y.atan2(l.x), r.y.atan2(r.x));
        for k in 1..8 {
            let a = al + (ar - al) * f64::from(k) / 8.0;
            out.push(DVec2::from_angle(a) * ra);
        }
    }
    out.extend_from_slice(right);
    out
}

/// Pieces of the French curve between two touching points.
const CURVE_PIECES: usize = 32;

/// The drawn curve through touching points of one piece, in their order: the French curve
/// touching the envelope's tangent at each.
fn curve_through(touches: &[Touch]) -> Vec<DVec2> {
    let mut out: Vec<DVec2> = touches.first().map(|t| t.at).into_iter().collect();
    for w in touches.windows(2) {
        let piece = french_curve(w[0].at, w[0].tangent, w[1].at, w[1].tangent, CURVE_PIECES);
        out.extend_from_slice(&piece[1..]);
    }
    out
}

/// The first point, from the tip, where the drawn half tooth `right` (tip → root) meets the
/// circle of radius `radius`, between its drawn points.
fn circle_crossing(right: &[DVec2], radius: f64) -> Option<DVec2> {
    right.windows(2).find_map(|w| {
        let (a, b) = (w[0].length(), w[1].length());
        (a >= radius && b < radius).then(|| w[0].lerp(w[1], (a - radius) / (a - b)))
    })
}

/// The arc on the circle of radius `radius` subtended by `chord`.
pub fn chord_to_arc(chord: f64, radius: f64) -> f64 {
    2.0 * radius * (chord / (2.0 * radius)).clamp(-1.0, 1.0).asin()
}
