//! The undercut's detail view «A (n:1)» named as the textbook names it: the involute above the
//! limit point where the fillet cuts into it, the fillet (the transition curve) below, the
//! undercut hatched between the fillet and the outline it removed, the base circle r_b, and
//! the rounding of the rack's tip that cut the fillet.

use super::rack::Cutting;
use crate::construct::{Figure, Item, Label, Names, Role, Step, StepId};
use crate::geom::{rotate, Circle, DVec2};
use std::f64::consts::PI;

/// The size of the undercut's detail view, mm: its zone is enlarged by the largest ГОСТ 2.302
/// enlargement that draws it at most this wide.
pub const DETAIL_MM: f64 = 150.0;

/// The letter of the undercut's detail view (ГОСТ 2.305: the zone on the figure and the
/// view are marked alike).
pub const DETAIL_LETTER: &str = "A";

/// The farthest a name stands from its object on the detail view, sheet mm.
pub const DETAIL_NAME_WITHIN_MM: f64 = 4.0;

/// The share of the zone's radius about its centre where a name's anchor is taken (clear of
/// the zone's circle, where every line of the view is cut).
const ANCHOR_ZONE: f64 = 0.8;

/// What the detail view names.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DetailMark {
    /// The involute flank above the limit point.
    Involute,
    /// The fillet (the transition curve) below it.
    Fillet,
    /// The limit point: where the fillet cuts the involute.
    Junction,
    /// The material the undercut removed (hatched).
    Undercut,
    /// The base circle r_b.
    BaseCircle,
    /// The rounding of the rack's tip at a drawn position: what cuts the fillet.
    RackTip,
}

impl DetailMark {
    /// Every mark, in the order the view names them.
    pub const ALL: [DetailMark; 6] = [
        DetailMark::Involute,
        DetailMark::Junction,
        DetailMark::Fillet,
        DetailMark::Undercut,
        DetailMark::BaseCircle,
        DetailMark::RackTip,
    ];
}

/// The anchors of the marks in the zone `zone` (main figure mm at `mu` m/mm): on the drawn
/// involute and fillet, at the junction, amid the undercut `region`, on r_b, and on the
/// rack tip's rounding of the drawn state nearest the zone's centre among `drawn_states`;
/// a mark whose object does not show in the zone is left out.
pub(super) fn marks(
    c: &Cutting,
    mu: f64,
    zone: &Circle,
    junction: DVec2,
    fillet: &[DVec2],
    region: &[DVec2],
    drawn_states: &[f64],
) -> Vec<(DetailMark, DVec2)> {
    let mm = |p: DVec2| p / mu;
    // A hair over the share: an anchor put at the share's own distance is shown (it was lost
    // to rounding, r_b of the shaper's pinion).
    let shows = |p: DVec2| p.distance(zone.center) <= ANCHOR_ZONE * zone.radius * (1.0 + 1e-9);
    let reach = zone.radius * mu;
    let mut out = vec![(DetailMark::Junction, mm(junction))];
    // The involute half way up the zone above the junction, or nearer when that is out.
    let ry = junction.length();
    if let Some(p) = [0.5, 0.3, 0.15, 0.08]
        .iter()
        .map(|k| mm(c.involute_at_radius((ry + k * reach).min(c.ra))))
        .find(|p| shows(*p))
    {
        out.push((DetailMark::Involute, p));
    }
    // The fillet's drawn point farthest below the junction within the zone.
    if let Some(p) = fillet
        .iter()
        .map(|p| mm(*p))
        .filter(|p| shows(*p) && p.length() < mm(junction).length())
        .max_by(|a, b| {
            a.distance(mm(junction))
                .total_cmp(&b.distance(mm(junction)))
        })
    {
        out.push((DetailMark::Fillet, p));
    }
    if !region.is_empty() {
        let mid = region.iter().fold(DVec2::ZERO, |s, p| s + *p) / region.len() as f64;
        out.push((DetailMark::Undercut, mm(mid)));
    }
    // r_b where it crosses the tooth's body (toward the tooth's axis), at least half the
    // zone's radius from its centre: clear of the flank, the fillet and the hatching.
    let rb = c.rb() / mu;
    let nearest = (zone.center.length() - rb).abs();
    let d = (nearest + 0.15 * zone.radius).clamp(0.5 * zone.radius, ANCHOR_ZONE * zone.radius);
    if let Some(p) = circle_at_distance(rb, zone.center, d.max(nearest)).filter(|p| shows(*p)) {
        out.push((DetailMark::BaseCircle, p));
    }
    // The left rounding of the tool tooth at u₀ (the one cutting the right flank's fillet)
    // at each drawn state, in the wheel's frame; its point farthest from the tooth within
    // the zone.
    let sh = c.shape();
    let base = c.r() + c.x * c.module;
    let rho = c.rack.rho * c.module;
    let tip = drawn_states
        .iter()
        .flat_map(|&q| {
            let centre = DVec2::new(c.u0() - sh.uc + q, base + sh.vc);
            (0..=16).map(move |k| {
                let a = PI + c.rack.alpha + (0.5 * PI - c.rack.alpha) * f64::from(k) / 16.0;
                mm(rotate(centre + DVec2::from_angle(a) * rho, q / c.r()))
            })
        })
        .filter(|p| p.distance(zone.center) <= 0.6 * zone.radius)
        .max_by(|a, b| {
            let off = |p: &DVec2| {
                fillet
                    .iter()
                    .map(|f| mm(*f).distance(*p))
                    .fold(f64::INFINITY, f64::min)
            };
            off(a).total_cmp(&off(b))
        });
    if let Some(p) = tip {
        out.push((DetailMark::RackTip, p));
    }
    out
}

/// The point of the circle of radius `r` about the origin at the distance `d` from `c` on
/// the side of smaller x (the tooth's axis is x = 0, the right flank at x > 0); `None` when
/// the circle does not come that near.
fn circle_at_distance(r: f64, c: DVec2, d: f64) -> Option<DVec2> {
    let l = c.length();
    if l <= 0.0 || l > r + d || l < (r - d).abs() {
        return None;
    }
    // Along c from the origin, then across it.
    let a = (r * r - d * d + l * l) / (2.0 * l);
    let h = (r * r - a * a).max(0.0).sqrt();
    let (u, n) = (c / l, (c / l).perp());
    let (p, q) = (u * a + n * h, u * a - n * h);
    Some(if p.x < q.x { p } else { q })
}

/// Name the marks on `view`, the zone `zone` of the main figure enlarged `k` times: each of
/// `marks` (main figure mm) named by `name` beside its object, the limit point a dot.
pub(super) fn view(
    mut view: Figure,
    zone: &Circle,
    k: f64,
    marks: &[(DetailMark, DVec2)],
    name: &dyn Fn(DetailMark) -> String,
) -> Figure {
    let mut next = view.steps.iter().map(|s| s.id.0 + 1).max().unwrap_or(0);
    for mark in DetailMark::ALL {
        let Some((_, at)) = marks.iter().find(|(m, _)| *m == mark) else {
            continue;
        };
        let at = (*at - zone.center) * k;
        // Written away from the zone's centre, off the flank that crosses it.
        let toward = match mark {
            DetailMark::Junction => DVec2::new(-1.0, -0.5),
            DetailMark::Involute => DVec2::new(-1.0, 0.5),
            DetailMark::Fillet => -DVec2::X,
            DetailMark::Undercut => DVec2::new(-1.0, -0.3),
            _ => at.normalize_or_zero(),
        };
        view.steps.push(Step {
            id: StepId(next),
            note: format!("detail A: the name of {mark:?}"),
            item: if mark == DetailMark::Junction {
                Item::Point(at)
            } else {
                Item::Text(at)
            },
            role: if mark == DetailMark::Junction {
                Role::Result
            } else {
                Role::Dimension
            },
            label: Some(Label {
                text: name(mark),
                anchor: at,
                toward,
                within_mm: Some(DETAIL_NAME_WITHIN_MM),
                column_mm: None,
                // The junction is a point; the other names name the curve they stand on.
                names: if mark == DetailMark::Junction {
                    Names::Point
                } else {
                    Names::Item
                },
            }),
            from: Vec::new(),
            group: 0,
        });
        next += 1;
    }
    view
}
