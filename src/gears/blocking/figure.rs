//! The drawing of a study's contour: the axes x₁, x₂ with their ticks, every traced curve
//! labelled, the admissible region's boundary bold, the scene's point and each choice.

use super::study::BlockingStudy;
use super::{levels, Kind};
use crate::construct::{Figure, Item, Label, Role, Step, StepId};
use crate::geom::{DVec2, Rect, Segment};
use crate::scale::{format_sig, Lang, Scale};
use crate::words::point_label;
use std::f64::consts::PI;

/// The words a drawing of the contour needs from the sheet's catalogue.
#[derive(Debug, Clone, Copy)]
pub struct Words<'a> {
    /// "interference" (with a wheel's fillet).
    pub interference: &'a str,
}

/// The steps of the figure being drawn.
#[derive(Default)]
struct Steps(Vec<Step>);

impl Steps {
    fn push(
        &mut self,
        note: String,
        item: Item,
        role: Role,
        label: Option<(String, DVec2, DVec2)>,
    ) {
        let id = StepId(self.0.len() as u32);
        let label = label.map(|(text, anchor, toward)| Label::on(&item, text, anchor, toward));
        self.0.push(Step {
            id,
            note,
            item,
            role,
            label,
            from: Vec::new(),
            group: 0,
        });
    }
}

/// The plotted plane: its lower corner, its span and figure mm per unit of x.
struct Plane {
    lo: DVec2,
    hi: DVec2,
    per_unit: f64,
}

impl Plane {
    fn to(&self, p: DVec2) -> DVec2 {
        (p - self.lo) * self.per_unit
    }
    /// The plane's window on the drawing, figure mm: what its curves are clipped to.
    fn window(&self) -> Rect {
        Rect::new(DVec2::ZERO, self.size())
    }

    fn size(&self) -> DVec2 {
        (self.hi - self.lo) * self.per_unit
    }
}

impl BlockingStudy {
    /// The drawing of the contour: the axes x₁, x₂ with ticks every 0.2 (0.1 on a small
    /// plane), every traced curve labelled (thin: the limits; dash-dot: the quality
    /// isolines s_a = 0.25m, 0.4m, ε_α = 1.2 and the line of equal sliding), the admissible
    /// region's boundary bold, the scene's point and each choice marked and labelled. Figure
    /// mm, a round 40–120 mm per unit of x (the larger side up to 220 mm).
    pub fn figure(&self, scale: Scale, lang: Lang, words: Words<'_>) -> Figure {
        let plane = self.plane();
        let mut steps = Steps::default();
        axes(&plane, lang, &mut steps);
        let (drawn, mut taken) = self.curves(&plane, lang, words, &mut steps);
        let size = plane.size();
        // The admissible region's boundary, bold.
        for ring in &self.contour.boundary {
            let ring: Vec<DVec2> = ring.iter().map(|p| plane.to(*p)).collect();
            for piece in plane.window().polyline_inside(&ring) {
                steps.push(
                    "the admissible region's boundary".into(),
                    Item::Polyline {
                        points: piece,
                        closed: false,
                    },
                    Role::Result,
                    None,
                );
            }
        }
        // The points.
        for (tag, ix) in self.points() {
            let at = plane.to(DVec2::from(ix.x));
            if !(at.x >= 0.0 && at.y >= 0.0 && at.x <= size.x && at.y <= size.y) {
                continue;
            }
            let room = |p: DVec2| room(&drawn, None, &taken, (p, p), size);
            // Toward the most room of eight directions, 6 mm out.
            let toward = (0..8)
                .map(|k| {
                    let a = PI / 4.0 * f64::from(k) + PI / 8.0;
                    DVec2::new(a.cos(), a.sin())
                })
                .max_by(|a, b| room(at + *a * 6.0).total_cmp(&room(at + *b * 6.0)))
                .unwrap_or(DVec2::new(1.0, 1.0));
            taken.push(at + toward * 6.0);
            steps.push(
                format!("the point {tag}"),
                Item::Point(at),
                Role::Given,
                Some((point_label(tag).to_string(), at, toward)),
            );
        }
        Figure {
            title: "blocking contour".into(),
            scale,
            steps: steps.0,
            readings: Vec::new(),
        }
    }

    /// Where the point `x` = (x₁, x₂) lies on [`figure`](BlockingStudy::figure), figure mm.
    pub fn at(&self, x: DVec2) -> DVec2 {
        self.plane().to(x)
    }

    /// The plotted plane: the admissible region and the points, 0.25 about them, within the
    /// window, far enough to show where each wheel's tooth points (s_a = 0) beside the
    /// region (up to 0.5 more); rounded out to tenths; its scale a round 40–120 mm per unit
    /// with the larger side up to 220 mm.
    fn plane(&self) -> Plane {
        let c = &self.contour;
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let points = self.points();
        for p in c
            .boundary
            .iter()
            .flatten()
            .copied()
            .chain(points.iter().map(|(_, ix)| DVec2::from(ix.x)))
        {
            lo = lo.min(p);
            hi = hi.max(p);
        }
        let (wlo, whi) = c.blocking.window;
        if !lo.is_finite() || !hi.is_finite() {
            (lo, hi) = (wlo, whi);
        }
        let lo = (lo - DVec2::splat(0.25)).max(wlo);
        let mut hi = (hi + DVec2::splat(0.25)).min(whi);
        let lo = lo.min(hi - DVec2::splat(0.2));
        let (lo0, hi0) = (lo, hi);
        for cv in c.curves.iter().filter(|cv| cv.limit == 0.0) {
            for p in &cv.points {
                match cv.kind {
                    Kind::Tip(0) if p.y >= lo0.y && p.y <= hi0.y => hi.x = hi.x.max(p.x + 0.05),
                    Kind::Tip(1) if p.x >= lo0.x && p.x <= hi0.x => hi.y = hi.y.max(p.y + 0.05),
                    _ => {}
                }
            }
        }
        let hi = hi.min(hi0 + DVec2::splat(0.5));
        let lo = (lo.max(wlo) * 10.0).floor() / 10.0;
        let hi = (hi.min(whi) * 10.0).ceil() / 10.0;
        let span = (hi - lo).max(DVec2::splat(0.2));
        let per_unit = [40.0, 50.0, 60.0, 80.0, 100.0, 120.0]
            .into_iter()
            .rev()
            .find(|s| span.max_element() * s <= 220.0)
            .unwrap_or(40.0);
        Plane {
            lo,
            hi: lo + span,
            per_unit,
        }
    }

    /// The curves, each labelled once on its longest piece (and on any other 15 mm long),
    /// where the label is farthest from the other curves and labels: the pieces drawn (by
    /// level) and the labels' places.
    fn curves(
        &self,
        plane: &Plane,
        lang: Lang,
        words: Words<'_>,
        steps: &mut Steps,
    ) -> (Vec<(usize, Vec<DVec2>)>, Vec<DVec2>) {
        let c = &self.contour;
        let size = plane.size();
        let levels = levels(&c.blocking.rack, c.blocking.z);
        let mut drawn: Vec<(usize, Vec<DVec2>)> = Vec::new();
        for (k, (kind, limit)) in levels.iter().enumerate() {
            let mut pieces: Vec<Vec<DVec2>> = c
                .curves
                .iter()
                .filter(|cv| cv.kind == *kind && cv.limit == *limit)
                .flat_map(|cv| {
                    let pts: Vec<DVec2> = cv.points.iter().map(|p| plane.to(*p)).collect();
                    plane.window().polyline_inside(&pts)
                })
                .collect();
            pieces.sort_by_key(|p| std::cmp::Reverse(p.len()));
            drawn.extend(pieces.into_iter().map(|p| (k, p)));
        }
        // The axes' names at their ends are taken.
        let mut taken = vec![
            DVec2::new(size.x + AXIS_END_MM, 0.0),
            DVec2::new(0.0, size.y + AXIS_END_MM),
        ];
        let mut first_of = vec![true; levels.len()];
        for (k, piece) in &drawn {
            let (kind, limit) = levels[*k];
            let dashed = matches!((kind, limit), (Kind::Tip(_), l) if l > 0.0)
                || (kind == Kind::ContactRatio && limit > 1.0)
                || kind == Kind::EqualSliding;
            let role = if dashed {
                Role::Axis
            } else {
                Role::Construction
            };
            let long = piece
                .windows(2)
                .map(|s| (s[1] - s[0]).length())
                .sum::<f64>()
                >= 15.0;
            let first = std::mem::replace(&mut first_of[*k], false);
            let label = (first || long).then(|| {
                let text = level_label(kind, limit, lang, words);
                let room = |b: (DVec2, DVec2)| room(&drawn, Some(*k), &taken, b, size);
                let (p, nrm, centre) = label_place(piece, label_extent(&text), room);
                taken.push(centre);
                (text, p, nrm)
            });
            steps.push(
                format!("the curve {}", level_name(kind, limit)),
                Item::Polyline {
                    points: piece.clone(),
                    closed: false,
                },
                role,
                label,
            );
        }
        (drawn, taken)
    }
}

/// How far each axis runs past the plane, figure mm.
const AXIS_END_MM: f64 = 6.0;
/// How far past the plane's upper and right edges a label may stand, figure mm (the ticks'
/// numbers take the room past its lower and left edges).
const PAST_EDGE_MM: f64 = 12.0;

/// The axes along the plane's lower and left edges, with their ticks every 0.2 (0.1 on a
/// plane of at most a unit).
fn axes(plane: &Plane, lang: Lang, steps: &mut Steps) {
    let size = plane.size();
    for (axis, end, toward) in [
        (
            0,
            DVec2::new(size.x + AXIS_END_MM, 0.0),
            DVec2::new(1.0, -0.6),
        ),
        (
            1,
            DVec2::new(0.0, size.y + AXIS_END_MM),
            DVec2::new(-0.6, 1.0),
        ),
    ] {
        steps.push(
            format!("the axis x{}", if axis == 0 { '₁' } else { '₂' }),
            Item::Segment(Segment::new(DVec2::ZERO, end)),
            Role::Construction,
            Some((format!("x_{}", axis + 1), end, toward)),
        );
    }
    let span = plane.hi - plane.lo;
    let step = if span.max_element() > 1.0 { 0.2 } else { 0.1 };
    for axis in 0..2 {
        let (a, b) = if axis == 0 {
            (plane.lo.x, plane.hi.x)
        } else {
            (plane.lo.y, plane.hi.y)
        };
        let mut k = (a / step).ceil() as i64;
        while (k as f64) * step <= b + 1e-9 {
            let v = k as f64 * step;
            let at = (v - a) * plane.per_unit;
            let (p, q, toward) = if axis == 0 {
                (DVec2::new(at, 0.0), DVec2::new(at, -2.0), DVec2::NEG_Y)
            } else {
                (DVec2::new(0.0, at), DVec2::new(-2.0, at), DVec2::NEG_X)
            };
            let text = if v.abs() < 1e-9 {
                "0".to_string()
            } else {
                format_sig(v, 3, lang)
            };
            steps.push(
                format!("a tick of x{} at {v:.1}", axis + 1),
                Item::Segment(Segment::new(p, q)),
                Role::Construction,
                Some((text, q, toward)),
            );
            k += 1;
        }
    }
}

/// Where a curve's label goes: of twenty points along `piece` and the two sides of each, the
/// one whose label box (of `extent`, set a label's gap out along the curve's normal) has the
/// most `room` — a label fits where its whole box is clear, not its anchor. The point, the
/// side's normal and the box's centre.
fn label_place(
    piece: &[DVec2],
    extent: DVec2,
    room: impl Fn((DVec2, DVec2)) -> f64,
) -> (DVec2, DVec2, DVec2) {
    let n = piece.len() - 1;
    let half = extent * 0.5;
    let box_at = |p: DVec2, nrm: DVec2| {
        let out = LABEL_GAP_MM + nrm.x.abs() * half.x + nrm.y.abs() * half.y;
        let centre = p + nrm * out;
        ((p, nrm, centre), room((centre - half, centre + half)))
    };
    let along = (1..20).flat_map(|f| {
        let at = n * f / 20;
        let p = piece[at];
        let t = (piece[(at + 1).min(n)] - piece[at.saturating_sub(1)]).normalize_or_zero();
        [1.0, -1.0].map(|side| box_at(p, DVec2::new(-t.y, t.x) * side))
    });
    along
        .fold(
            None,
            |best: Option<((DVec2, DVec2, DVec2), f64)>, c| match best {
                Some(b) if b.1 >= c.1 => Some(b),
                _ => Some(c),
            },
        )
        .map_or((piece[n / 2], DVec2::Y, piece[n / 2]), |b| b.0)
}

/// Gap from a curve to its label's box, figure mm (the plate's label gap).
const LABEL_GAP_MM: f64 = 2.0;

/// The box a curve's label takes, figure mm: an estimate of the 3,5 mm label text (2,3 mm a
/// character, a subscript line's height) for choosing its place; the plate measures it.
fn label_extent(markup: &str) -> DVec2 {
    let chars = markup
        .chars()
        .filter(|c| !matches!(c, '_' | '{' | '}'))
        .count();
    DVec2::new(2.3 * chars as f64, 4.5)
}

/// The room about the box `lo`–`hi` (figure mm; a point when they are one): its distance to
/// the drawn curves (but the level `skip`), to the labels already placed and to the plane's
/// lower and left edges (`size`), and [`PAST_EDGE_MM`] past its upper and right ones; zero
/// where any of these enters it.
fn room(
    drawn: &[(usize, Vec<DVec2>)],
    skip: Option<usize>,
    taken: &[DVec2],
    (lo, hi): (DVec2, DVec2),
    size: DVec2,
) -> f64 {
    let others = drawn
        .iter()
        .filter(|(j, _)| Some(*j) != skip)
        .flat_map(|(_, q)| q.iter())
        .chain(taken.iter())
        .map(|q| (*q - q.clamp(lo, hi)).length())
        .fold(f64::INFINITY, f64::min);
    let past = size + DVec2::splat(PAST_EDGE_MM) - hi;
    others.min(lo.x).min(lo.y).min(past.x).min(past.y)
}

/// The label of a level in label markup.
fn level_label(kind: Kind, limit: f64, lang: Lang, words: Words<'_>) -> String {
    let l = format_sig(limit, 3, lang);
    match kind {
        Kind::Undercut(i) => format!("x_{{min{}}}", i + 1),
        Kind::Tip(i) if limit == 0.0 => format!("s_{{a{}}} = 0", i + 1),
        Kind::Tip(i) => format!("s_{{a{}}} = {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α = {l}"),
        Kind::Interference(i) => format!("{} {}", words.interference, i + 1),
        Kind::EqualSliding => "λ_1 = λ_2".into(),
    }
}

/// A level in the name of the step that draws its curve.
fn level_name(kind: Kind, limit: f64) -> String {
    let l = format_sig(limit, 4, Lang::En);
    match kind {
        Kind::Undercut(i) => format!("x{0} ≥ x_min{0} = {l}", i + 1),
        Kind::Tip(i) => format!("s_a{} ≥ {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α ≥ {l}"),
        Kind::Interference(i) => format!("no interference with the fillet of wheel {}", i + 1),
        Kind::EqualSliding => "λ₁ = λ₂".into(),
    }
}
