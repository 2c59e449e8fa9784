//! The detail views of a force polygon: the zone of its forces too short to read drawn again
//! at a larger μ_F.

use crate::construct::{Figure, Item, Role, Step, StepId};
use crate::geom::{Circle, DVec2};
use crate::scale::Scale;

/// A force shorter than this on its polygon, mm, is drawn again in the polygon's detail.
pub(super) const SMALL_FORCE_MM: f64 = 4.0;

/// The detail draws the smallest force about this long, mm.
const DETAIL_FORCE_MM: f64 = 12.0;

/// The detail's zone is drawn at most this wide, mm.
const DETAIL_MM: f64 = 110.0;

/// A detail's zone is drawn at least this large in radius, mm: room for its forces' labels.
const DETAIL_ROOM_MM: f64 = 30.0;

/// The zone about the small forces reaches this far past them (a share of their extent).
const DETAIL_MARGIN: f64 = 1.3;

/// A detail view (выносной элемент) of a force polygon: the zone of its small forces drawn
/// again at a larger μ_F, so that every force of the polygon can be read.
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonDetail {
    /// The zone on the polygon, polygon mm.
    pub zone: Circle,
    /// The zone enlarged: the vectors cut at its border, with their labels.
    pub figure: Figure,
    /// The finer details whose zones it circles: each one's index among the polygon's
    /// details and where its letter stands on this one, detail mm.
    pub finer: Vec<(usize, DVec2)>,
}

/// The direction a zone's letter stands in from its centre: up and right, on its circle.
pub fn letter_toward() -> DVec2 {
    DVec2::new(1.0, 1.0).normalize()
}

/// Where the letter of `zone` stands: on its circle, [`letter_toward`] its centre.
pub fn letter_at(zone: &Circle) -> DVec2 {
    zone.center + letter_toward() * zone.radius
}

/// A polygon has at most this many details.
const MAX_DETAILS: usize = 3;

/// The details of a polygon at `mu` about its forces `laid` (polygon mm) drawn shorter than
/// [`SMALL_FORCE_MM`]: from the shortest force not yet shown, the round μ_F that draws it
/// about [`DETAIL_FORCE_MM`], and a zone about it and the other small forces near enough to
/// share a detail [`DETAIL_MM`] wide; then the next. Empty when every force reads. A force
/// zero to the polygon's scale (shorter than [`crate::forces::ZERO_PART`] of its longest) is
/// drawn as the point it is, with no detail. `polygon` is the polygon as a detail at the
/// given μ_F shows it.
pub(super) fn details(
    mu: Scale,
    laid: &[(DVec2, DVec2)],
    polygon: &dyn Fn(Scale) -> Figure,
) -> Vec<PolygonDetail> {
    let longest = laid.iter().map(|(a, b)| a.distance(*b)).fold(0.0, f64::max);
    let zero = crate::forces::ZERO_PART * longest;
    let mut small: Vec<(DVec2, DVec2)> = laid
        .iter()
        .copied()
        .filter(|(a, b)| a.distance(*b) > zero && a.distance(*b) < SMALL_FORCE_MM)
        .collect();
    small.sort_by(|x, y| x.0.distance(x.1).total_cmp(&y.0.distance(y.1)));
    let mut out: Vec<PolygonDetail> = Vec::new();
    while let (Some(&(a, b)), true) = (small.first(), out.len() < MAX_DETAILS) {
        let Some(scale) =
            Scale::round_for(a.distance(b) * mu.value(), DETAIL_FORCE_MM, mu.quantity)
                .filter(|d| d.value() * 2.0 <= mu.value())
        else {
            break;
        };
        // The zone's largest radius on the polygon, and who fits in it with the margin.
        let reach =
            0.5 * DETAIL_MM * scale.value() / mu.value() / DETAIL_MARGIN / std::f64::consts::SQRT_2;
        let c = a.lerp(b, 0.5);
        let (members, rest): (Vec<_>, Vec<_>) = small
            .iter()
            .partition(|(p, q)| p.distance(c) <= reach && q.distance(c) <= reach);
        let (lo, hi) = members.iter().fold(
            (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY)),
            |(lo, hi), (p, q)| (lo.min(p.min(*q)), hi.max(p.max(*q))),
        );
        // At least a short force's room about it, at most the detail's width (drawing mm
        // of the detail turned into polygon mm).
        let k = mu.value() / scale.value();
        let radius = (0.5 * (hi - lo).length() * DETAIL_MARGIN)
            .max(DETAIL_ROOM_MM / k)
            .min(0.5 * DETAIL_MM / k);
        let Some(zone) = Circle::new(0.5 * (lo + hi), radius) else {
            break;
        };
        // The details before are finer (each from a shorter force): those it overlaps.
        let finer: Vec<usize> = (out.iter().enumerate())
            .filter(|(_, d)| d.zone.center.distance(zone.center) < d.zone.radius + zone.radius)
            .map(|(i, _)| i)
            .collect();
        let zones: Vec<Circle> = finer.iter().map(|&i| out[i].zone).collect();
        let (figure, letters) = nested(polygon(scale), &zones, &zone, scale);
        out.push(PolygonDetail {
            zone,
            figure,
            finer: finer.into_iter().zip(letters).collect(),
        });
        small = rest;
    }
    out
}

/// The detail of `zone` at `scale` cut from `polygon` (polygon mm), the zones of the `finer`
/// details (those it overlaps) circled in it as on the polygon (ГОСТ 2.305: a detail of a detail),
/// and the forces read on them — shorter than [`SMALL_FORCE_MM`] here too — left without
/// their names, which the finer detail writes (the shaper's G₂, 2 mm at 10 N/mm, labelled
/// as a dot beside its 12 mm on the detail at 2 N/mm). Returns it with where each finer
/// zone's letter stands on it: at [`letter_at`], or where that falls past the border, at the
/// finer zone's point nearest the centre.
fn nested(polygon: Figure, finer: &[Circle], zone: &Circle, scale: Scale) -> (Figure, Vec<DVec2>) {
    let k = polygon.scale.value() / scale.value();
    let mut source = polygon;
    for z in finer {
        let id = StepId(source.steps.iter().map(|s| s.id.0 + 1).max().unwrap_or(0));
        source.steps.push(Step {
            id,
            note: "the zone of a finer detail".into(),
            item: Item::Circle(*z),
            role: Role::Construction,
            label: None,
            from: Vec::new(),
            group: 0,
        });
    }
    let mut detail = source.detail_with_vectors(zone, scale);
    // The finer zones in the detail's own mm (its origin the zone's centre).
    let own = |p: DVec2| (p - zone.center) * k;
    let zones: Vec<Circle> = (finer.iter())
        .filter_map(|z| Circle::new(own(z.center), z.radius * k))
        .collect();
    unname_read_elsewhere(&mut detail, &zones);
    let letters = finer
        .iter()
        .map(|z| {
            let at = letter_at(z);
            own(if at.distance(zone.center) > zone.radius {
                z.center + (zone.center - z.center).normalize_or_zero() * z.radius
            } else {
                at
            })
        })
        .collect();
    (detail, letters)
}

/// The forces of `figure` drawn shorter than [`SMALL_FORCE_MM`] inside one of `zones` (in
/// the figure's mm) left without their names and their heads: a detail names them and
/// shows their sense, where they read (the V engine's G₂, a dot named G₂ on its polygon at
/// 40 N/mm beside the circle of its detail Г; its G₄ and G₅, 0,3 mm, drawn as bare 4 mm
/// arrowheads at Б and Г). The polygon keeps each as the short line it is.
pub(super) fn unname_read_elsewhere(figure: &mut Figure, zones: &[Circle]) {
    let inside = |p: DVec2| zones.iter().any(|z| p.distance(z.center) <= z.radius);
    for st in &mut figure.steps {
        if let Item::Vector { from, to } = st.item {
            if from.distance(to) < SMALL_FORCE_MM && inside(from) && inside(to) {
                st.label = None;
                st.item = Item::Segment(crate::geom::Segment::new(from, to));
            }
        }
    }
}
