//! Detail views (ГОСТ 2.305 выносной элемент): a zone of a figure cut out by its circle and
//! drawn enlarged beside it.

use super::figure::{Figure, Role, Step, StepId};
use super::item::Item;
use super::label::{Label, Names};
use crate::geom::{bezier_points, Arc, Circle, DVec2, Segment};
use crate::scale::Scale;

impl Figure {
    /// A detail view (ГОСТ 2.305 выносной элемент) of the zone `zone` (figure mm) drawn at
    /// `scale`: what the figure draws inside the circle, enlarged by μ/μ_detail about its
    /// centre (the detail's origin), each line cut where it leaves the circle, and the circle
    /// itself, thin. Points and joints inside keep their place; vectors, sliders, guides,
    /// dimensions, angles, texts and labels stay on the main view. Each step notes the step
    /// it copies in `from`.
    pub fn detail(&self, zone: &Circle, scale: Scale) -> Figure {
        self.detail_keeping(zone, scale, false)
    }

    /// A detail view of a force polygon ([`detail`](Figure::detail)) that also keeps its
    /// vectors: each cut where it leaves the circle, its arrowhead kept when its end lies
    /// inside, its label set at the middle of the piece that shows.
    pub fn detail_with_vectors(&self, zone: &Circle, scale: Scale) -> Figure {
        self.detail_keeping(zone, scale, true)
    }

    fn detail_keeping(&self, zone: &Circle, scale: Scale, vectors: bool) -> Figure {
        let k = self.scale.value() / scale.value();
        let t = |p: DVec2| (p - zone.center) * k;
        let inside = |p: DVec2| p.distance(zone.center) <= zone.radius;
        let mut items: Vec<(&Step, Item, Option<Label>)> = Vec::new();
        let arc = |a: &Arc| {
            crate::geom::arc_in_circle(a, zone)
                .into_iter()
                .map(|a| {
                    Item::Arc(Arc {
                        center: t(a.center),
                        radius: a.radius * k,
                        ..a
                    })
                })
                .collect::<Vec<_>>()
        };
        let runs = |points: &[DVec2], closed: bool| {
            let mut pts = points.to_vec();
            if closed {
                pts.extend(points.first());
            }
            crate::geom::polyline_in_circle(&pts, zone)
                .into_iter()
                .map(|r| r.into_iter().map(t).collect::<Vec<_>>())
                .collect::<Vec<_>>()
        };
        for st in &self.steps {
            let copies: Vec<Item> = match &st.item {
                Item::Point(p) if inside(*p) => vec![Item::Point(t(*p))],
                Item::Joint { at, fixed } if inside(*at) => vec![Item::Joint {
                    at: t(*at),
                    fixed: *fixed,
                }],
                Item::Vector { from, to } if vectors => {
                    for r in runs(&[*from, *to], false) {
                        let (a, b) = (r[0], r[r.len() - 1]);
                        let item = if inside(*to) {
                            Item::Vector { from: a, to: b }
                        } else {
                            Item::Segment(Segment::new(a, b))
                        };
                        // Set at the middle of the piece that shows, it names the vector.
                        let label = st.label.as_ref().map(|l| Label {
                            anchor: a.lerp(b, 0.5),
                            names: Names::Item,
                            ..l.clone()
                        });
                        items.push((st, item, label));
                    }
                    Vec::new()
                }
                Item::Segment(s) => runs(&[s.from, s.to], false)
                    .into_iter()
                    .map(|r| Item::Segment(Segment::new(r[0], r[r.len() - 1])))
                    .collect(),
                Item::Circle(c) => arc(&Arc {
                    center: c.center,
                    radius: c.radius,
                    start: 0.0,
                    sweep: std::f64::consts::TAU,
                }),
                Item::Arc(a) => arc(a),
                Item::Polyline { points, closed } => lines(runs(points, *closed), false),
                Item::Curve { points, closed } => lines(runs(points, *closed), true),
                // Cut as the curve it is, in chords of a sixteenth of a piece.
                Item::Bezier {
                    start,
                    pieces,
                    closed,
                } => lines(runs(&bezier_points(*start, pieces, 16), *closed), false),
                // Its strokes, cut by the circle as lines are (an outline that is not finite
                // hatches nothing).
                Item::Hatching { .. } => st
                    .item
                    .hatch_strokes()
                    .iter()
                    .flat_map(|s| runs(&[s.from, s.to], false))
                    .map(|r| Item::Segment(Segment::new(r[0], r[r.len() - 1])))
                    .collect(),
                _ => Vec::new(),
            };
            items.extend(copies.into_iter().map(|item| (st, item, None)));
        }
        let mut steps: Vec<Step> = items
            .into_iter()
            .enumerate()
            .map(|(i, (st, item, label))| Step {
                id: StepId(i as u32),
                note: format!("detail: {}", st.note),
                item,
                role: st.role,
                label,
                from: vec![st.id],
                group: st.group,
            })
            .collect();
        steps.push(Step {
            id: StepId(steps.len() as u32),
            note: "detail: its border".into(),
            item: Item::Circle(Circle {
                center: DVec2::ZERO,
                radius: zone.radius * k,
            }),
            role: Role::Construction,
            label: None,
            from: Vec::new(),
            group: 0,
        });
        // The readings stay on the main view, where the segments are drawn whole.
        Figure {
            title: format!("detail of {}", self.title),
            scale,
            steps,
            readings: Vec::new(),
        }
    }
}

/// The pieces of a line inside a detail's zone, each a polyline or, `smooth`, a curve.
fn lines(runs: Vec<Vec<DVec2>>, smooth: bool) -> Vec<Item> {
    runs.into_iter()
        .map(|points| match smooth {
            true => Item::Curve {
                points,
                closed: false,
            },
            false => Item::Polyline {
                points,
                closed: false,
            },
        })
        .collect()
}
