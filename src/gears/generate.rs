//! Rack generation as a construction (seed 002 PZ1, the TMM-42 device): the basic rack,
//! shifted by x·m, is rolled along the pitch circle in N equal steps (rack step q ↔ wheel
//! turn q/r); at every position its outline is drawn in the wheel's frame, clipped to the
//! blank, and the points where it touches the envelope are found the textbook way — where
//! the rack's normal passes through the pole P — on the straight flank (the involute), on the
//! tip rounding (the fillet) and on the tip line (the root circle). The tooth is drawn
//! through the touching points as the French curve touching the envelope there (⊥ the
//! normal through P); undercut is detected where the drawn fillet crosses the
//! drawn involute, pointing where the tip thickness read off the drawing falls below 0.3m.

use super::detail::DetailMark;
use super::rack::{Cutting, Piece};
use super::trace::{outline_runs, polyline_crossing, refine, touching};
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
    pub piece: Piece,
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

/// Spacing of the undercut's hatching where it is read (its detail view, or the figure
/// when there is none), mm.
const UNDERCUT_HATCH_MM: f64 = 1.0;

/// The size of the undercut's detail view, mm: its zone is enlarged by the largest ГОСТ 2.302
/// enlargement that draws it at most this wide.
pub const DETAIL_MM: f64 = 150.0;

/// The enlargements of ГОСТ 2.302 (n:1), the smallest first.
const ENLARGEMENTS: [f64; 9] = [2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 40.0, 50.0, 100.0];

/// The zone of the detail view: the circle about the undercut's extent, this much wider.
const DETAIL_MARGIN: f64 = 1.4;

/// The letter of the undercut's detail view (ГОСТ 2.305: the zone on the figure and the
/// view are marked alike).
pub const DETAIL_LETTER: &str = "A";

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
    let (r, rb, ra, rf) = (c.r(), c.rb(), c.ra, c.rf());
    let mut rec = Recorder::in_context("generation", scale, ctx);
    let mm = |p: DVec2| p / mu;
    let o = rec.draw(
        "the radius of the tooth's axis",
        Item::Segment(Segment::new(
            DVec2::new(0.0, rf / mu - 2.0),
            DVec2::new(0.0, ra / mu + 2.0),
        )),
        Role::Axis,
        &[],
    );
    // The circles about the tooth, over three pitches.
    let pitch = 2.0 * PI / f64::from(c.z);
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
    let st = c.states();
    let (lo, hi) = c.span();
    let mut states: Vec<f64> = (0..steps)
        .map(|i| lo + (hi - lo) * i as f64 / (steps - 1) as f64)
        .collect();
    // The marks of the device: the flank's end, the tip, the rounding under P, and the
    // contact passing N (the foot of O on the line of action) when the flank reaches it.
    let q_n = st.q_p - r * c.rack.alpha.tan();
    let marks = [st.q_j, st.q_a, st.q_bottom, q_n];
    for q in marks.into_iter().filter(|q| *q >= st.q_j) {
        if !states.iter().any(|s| (s - q).abs() <= 1e-12 * c.module) {
            states.push(q);
        }
    }
    states.sort_by(f64::total_cmp);
    let drawn = spread(states.len(), DRAWN_POSITIONS);
    let mut touches = Vec::new();
    for (i, &q) in states.iter().enumerate() {
        rec.set_group(i as u32 + 1);
        let turn = q / r;
        let mut last = None;
        for run in outline_runs(&c, q) {
            let pts: Vec<DVec2> = run.into_iter().map(|p| mm(rotate(p, turn))).collect();
            last = pts.last().copied();
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
        // A drawn position's number at the outer end of its outline, out of the blank.
        if let (Some(k), Some(end)) = (drawn.iter().position(|d| *d == i), last) {
            let id = rec.draw(
                format!("the number of rack position {}", i + 1),
                Item::Text(end),
                Role::Dimension,
                &[],
            );
            rec.label(id, (k + 1).to_string(), end, end.normalize_or_zero());
        }
        for (piece, k) in touching(&c, q) {
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
    let by = |piece: Piece| -> Vec<Touch> {
        let mut v: Vec<Touch> = touches
            .iter()
            .copied()
            .filter(|t| t.piece == piece)
            .collect();
        v.sort_by(|a, b| a.q.total_cmp(&b.q));
        v
    };
    // The involute proper starts where the contact passes N; beyond N the flank traces the
    // branch the fillet cuts away.
    let flank: Vec<Touch> = by(Piece::Flank)
        .into_iter()
        .filter(|t| t.q >= q_n - 1e-12 * c.module)
        .collect();
    let fillet = by(Piece::Fillet);
    let root = by(Piece::Root);
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
    let tooth = whole_tooth(&right, ra);
    rec.draw(
        "the tooth: the envelope of the rack positions",
        Item::Polyline {
            points: tooth.iter().map(|p| mm(*p)).collect(),
            closed: false,
        },
        Role::Result,
        &[],
    );
    // The neighbouring teeth, cut alike a pitch either side, as the device's paper shows
    // three teeth: the spaces either side of the tooth.
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
    // The report form's readings: the chords where the drawn flanks cross the pitch and
    // base circles, read with a ruler and turned into arcs. The space: from the tooth's
    // right flank to its right neighbour's left flank.
    let mirror = |p: DVec2| DVec2::new(-p.x, p.y);
    let across = |radius: f64| {
        let k = circle_crossing(&right, radius)?;
        Some(chord_to_arc(
            rec.measure(mm(mirror(k)), mm(k)).value,
            radius,
        ))
    };
    let st_read = across(r).unwrap_or(0.0);
    let et_read = circle_crossing(&right, r).map_or(0.0, |k| {
        let next = rotate(mirror(k), -pitch);
        chord_to_arc(rec.measure(mm(k), mm(next)).value, r)
    });
    let sb = if rb > rf { across(rb) } else { None };
    let mut detail = None;
    let mut detail_marks = Vec::new();
    if undercut {
        // The undercut: uncut, the tooth would follow the involute down to the base circle
        // and the radial line below it; the fillet cuts into that outline from the junction
        // down to where it comes back to the radial line. That outline is drawn thin and
        // the material removed hatched, on both flanks.
        let lost: Vec<DVec2> = flank[..inv_from].iter().map(|t| t.at).collect();
        let off_axis = |p: DVec2| p.x.atan2(p.y);
        let edge = off_axis(lost.first().copied().unwrap_or(junction));
        let mut cut = Vec::new();
        let down: Vec<DVec2> = fi[..fil_to].iter().rev().copied().collect();
        for w in down.windows(2) {
            cut.push(w[0]);
            let (a, b) = (off_axis(w[0]), off_axis(w[1]));
            if b >= edge {
                let t = if b > a { (edge - a) / (b - a) } else { 1.0 };
                cut.push(w[0].lerp(w[1], t.clamp(0.0, 1.0)));
                break;
            }
        }
        let mut uncut = vec![junction];
        uncut.extend(lost.iter().rev());
        uncut.extend(cut.last());
        let region: Vec<DVec2> = uncut.iter().chain(cut.iter().rev()).copied().collect();
        // The undercut is a sliver: it is drawn again enlarged, as a detail view of the zone
        // about the right flank's, at the round scale that makes the zone about DETAIL_MM
        // across; the hatching is spaced for the scale it is read at.
        let (lo, hi) = region.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        let radius = 0.5 * (hi - lo).length() * DETAIL_MARGIN;
        let zone =
            crate::geom::Circle::new(mm(0.5 * (lo + hi)), radius / mu).filter(|z| z.radius > 0.0);
        let enlarged = detail_scale(2.0 * radius).filter(|d| d.value() < mu);
        let mut spacing = UNDERCUT_HATCH_MM;
        if let (Some(zone), Some(scale_d)) = (zone, enlarged) {
            spacing *= scale_d.value() / mu;
            let id = rec.draw(
                "the zone of the undercut's detail view",
                Item::Circle(zone),
                Role::Construction,
                &[],
            );
            let at = zone.center + DVec2::new(1.0, 1.0).normalize() * zone.radius;
            rec.label(id, DETAIL_LETTER, at, DVec2::new(1.0, 1.0));
            detail = Some((zone, scale_d));
            let drawn_states: Vec<f64> = drawn
                .iter()
                .filter_map(|i| states.get(*i))
                .copied()
                .collect();
            detail_marks =
                super::detail::marks(&c, mu, &zone, junction, &fi, &region, &drawn_states);
        }
        for side in [1.0, -1.0] {
            let flip = |p: DVec2| mm(DVec2::new(side * p.x, p.y));
            let edge = rec.draw(
                "the outline the undercut removed: the involute to r_b, the radial line",
                Item::Polyline {
                    points: uncut.iter().map(|p| flip(*p)).collect(),
                    closed: false,
                },
                Role::Construction,
                &[],
            );
            let outline: Vec<DVec2> = region.iter().map(|p| flip(*p)).collect();
            let strokes = crate::geom::hatch(&outline, spacing, side * PI / 4.0)
                .map_err(|e| GearError::Construction(format!("the undercut's hatching: {e}")))?;
            for stroke in strokes {
                rec.draw(
                    "hatching of the undercut",
                    Item::Segment(stroke),
                    Role::Hatch,
                    &[edge],
                );
            }
        }
    }
    // The tip thickness: the chord between the two flanks' tip points, read with a ruler.
    let tip = flank
        .iter()
        .find(|t| (t.q - st.q_a).abs() <= 1e-12 * c.module)
        .map_or(c.involute_at(st.q_a), |t| t.at);
    let tip_l = DVec2::new(-tip.x, tip.y);
    let tip_chord = rec.measure(mm(tip_l), mm(tip));
    let sa = chord_to_arc(tip_chord.value, ra);
    let pointed = sa < MIN_TIP * c.module;
    rec.draw(
        "s_a: the tip chord",
        Item::Dimension {
            from: mm(tip_l),
            to: mm(tip),
            offset: 4.0,
        },
        Role::Dimension,
        &[],
    );
    // The drawn polyline against the exact envelope, piece by piece.
    let (_, qi, qf) = c.junction();
    let real = |t: &Touch| match t.piece {
        Piece::Flank => t.q >= qi - 1e-12 * c.module && t.q <= st.q_a + 1e-12 * c.module,
        Piece::Fillet => t.q >= qf - 1e-12 * c.module,
        Piece::Root => t.q >= st.q_space - 1e-12 * c.module,
    };
    let twin = |piece: Piece, q: f64| match piece {
        Piece::Flank => c.involute_at(q),
        Piece::Fillet => c.trochoid_at(q),
        Piece::Root => c.root_at(q),
    };
    let mut deviation: f64 = 0.0;
    let (mut sum, mut count) = (0.0, 0usize);
    for list in [&flank, &fillet, &root] {
        let kept: Vec<&Touch> = list.iter().filter(|t| real(t)).collect();
        for w in kept.windows(2) {
            let curve = curve_through(&[*w[0], *w[1]]);
            let mut worst: f64 = 0.0;
            for k in 1..16 {
                let q = w[0].q + (w[1].q - w[0].q) * f64::from(k) / 16.0;
                let e = twin(w[0].piece, q);
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
    let touch_error = touches
        .iter()
        .map(|t| (t.at - twin(t.piece, t.q)).length())
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
        pitch_reading: (st_read, et_read),
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
}

/// The largest ГОСТ 2.302 enlargement n:1 that draws `size` (m) at most [`DETAIL_MM`] wide,
/// as μ_l = 0.001/n m/mm; `None` when even 2:1 draws it wider.
fn detail_scale(size: f64) -> Option<Scale> {
    ENLARGEMENTS
        .iter()
        .rev()
        .find(|n| size * 1e3 * *n <= DETAIL_MM)
        .and_then(|n| Scale::new(1e-3 / n, crate::scale::Quantity::Length))
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
