//! The figure model: what a construction records — steps with their item, role, label and
//! provenance — and the figure they make up.

use super::item::Item;
use super::label::{Label, Names};
use super::reading::Reading;
use crate::geom::{Arc, Circle, DVec2, Segment, Side};
use crate::scale::Scale;

/// Index of a step within its figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct StepId(pub u32);

/// How a step is drawn (ГОСТ 2.303 line types are applied by the plate).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// Given data: links, pivots, guides (main line, thick).
    Given,
    /// Construction: arcs, notches, auxiliary lines (thin).
    Construction,
    /// A result: the constructed position or vector (thick; vectors arrowed).
    Result,
    /// Axis or centre line (thin dash-dot).
    Axis,
    /// Dimension and angle marks (thin, with arrows and text).
    Dimension,
    /// Hatching (thin).
    Hatch,
}

/// One recorded step.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// Its id (index in the figure).
    pub id: StepId,
    /// What the step does, in words ("arc from B, r = AB").
    pub note: String,
    /// What is drawn.
    pub item: Item,
    /// How it is drawn.
    pub role: Role,
    /// Its label, if any.
    pub label: Option<Label>,
    /// The steps it was derived from.
    pub from: Vec<StepId>,
    /// Group tag (e.g. the position number on a plan of positions); 0 when unused.
    pub group: u32,
}

/// A recorded construction drawn in one view at one scale.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// The figure's title (for the view caption), in label markup.
    pub title: String,
    /// μ of the figure's lengths.
    pub scale: Scale,
    /// The steps in drawing order.
    pub steps: Vec<Step>,
    /// The segments measured off it, in the order they were read; they draw nothing.
    pub readings: Vec<Reading>,
}

impl Figure {
    /// The figure mirrored in its y axis (x → −x): the same construction for a mechanism
    /// drawn the other way round (a cam turning clockwise). Arcs keep their ends, guides
    /// their hatched side and dimensions their side of the measured piece.
    pub fn mirrored_x(&self) -> Figure {
        self.moved(|p| DVec2::new(-p.x, p.y), true)
    }

    /// The figure moved by `offset`, mm: every item, label and anchor.
    pub fn translated(&self, offset: DVec2) -> Figure {
        self.moved(|p| p + offset, false)
    }

    /// This figure with `other`'s steps drawn after its own (their ids renumbered after
    /// this figure's): two constructions drawn on one drawing, such as the chords of the
    /// second differentiation drawn on the first derivative's curve. The title and μ are this
    /// figure's.
    pub fn joined(mut self, other: Figure) -> Figure {
        let n = u32::try_from(self.steps.len()).unwrap_or(u32::MAX);
        let shift = |id: StepId| StepId(id.0.saturating_add(n));
        self.steps.extend(other.steps.into_iter().map(|st| Step {
            id: shift(st.id),
            from: st.from.iter().copied().map(shift).collect(),
            ..st
        }));
        self.readings.extend(other.readings);
        self
    }

    /// Every point through `m`, an isometry; `mirror` when it turns left into right (arcs
    /// run the other way, guides hatch the other side, label directions flip with it).
    fn moved(&self, m: impl Fn(DVec2) -> DVec2, mirror: bool) -> Figure {
        let seg = |s: &Segment| Segment::new(m(s.from), m(s.to));
        let arc = |a: &Arc| match mirror {
            true => Arc {
                center: m(a.center),
                radius: a.radius,
                start: std::f64::consts::PI - a.start,
                sweep: -a.sweep,
            },
            false => Arc {
                center: m(a.center),
                ..*a
            },
        };
        let turn = |v: DVec2| if mirror { DVec2::new(-v.x, v.y) } else { v };
        let steps = self
            .steps
            .iter()
            .map(|st| {
                let item = match &st.item {
                    Item::Point(p) => Item::Point(m(*p)),
                    Item::Joint { at, fixed } => Item::Joint {
                        at: m(*at),
                        fixed: *fixed,
                    },
                    Item::Segment(s) => Item::Segment(seg(s)),
                    Item::Circle(c) => Item::Circle(Circle {
                        center: m(c.center),
                        radius: c.radius,
                    }),
                    Item::Arc(a) => Item::Arc(arc(a)),
                    Item::Polyline { points, closed } => Item::Polyline {
                        points: points.iter().map(|p| m(*p)).collect(),
                        closed: *closed,
                    },
                    Item::Curve { points, closed } => Item::Curve {
                        points: points.iter().map(|p| m(*p)).collect(),
                        closed: *closed,
                    },
                    Item::Bezier {
                        start,
                        pieces,
                        closed,
                    } => Item::Bezier {
                        start: m(*start),
                        pieces: pieces.iter().map(|p| p.map(&m)).collect(),
                        closed: *closed,
                    },
                    Item::Vector { from, to } => Item::Vector {
                        from: m(*from),
                        to: m(*to),
                    },
                    Item::Slider { at, angle } => Item::Slider {
                        at: m(*at),
                        angle: if mirror {
                            std::f64::consts::PI - angle
                        } else {
                            *angle
                        },
                    },
                    // A mirror turns left into right.
                    Item::Guide { segment, hatch } => Item::Guide {
                        segment: seg(segment),
                        hatch: match (hatch, mirror) {
                            (Side::Left, true) => Side::Right,
                            (Side::Right, true) => Side::Left,
                            (h, false) => *h,
                        },
                    },
                    Item::Dimension { from, to, offset } => Item::Dimension {
                        from: m(*from),
                        to: m(*to),
                        offset: if mirror { -offset } else { *offset },
                    },
                    Item::Angle(a) => Item::Angle(arc(a)),
                    Item::Moment(a) => Item::Moment(arc(a)),
                    Item::Text(p) => Item::Text(m(*p)),
                    Item::Hatching {
                        outline,
                        spacing,
                        angle,
                    } => Item::Hatching {
                        outline: outline.iter().map(|p| m(*p)).collect(),
                        spacing: *spacing,
                        angle: if mirror {
                            std::f64::consts::PI - angle
                        } else {
                            *angle
                        },
                    },
                };
                let label = st.label.as_ref().map(|l| Label {
                    text: l.text.clone(),
                    anchor: m(l.anchor),
                    toward: turn(l.toward),
                    within_mm: l.within_mm,
                    column_mm: l.column_mm,
                    names: l.names,
                });
                Step {
                    item,
                    label,
                    ..st.clone()
                }
            })
            .collect();
        Figure {
            title: self.title.clone(),
            scale: self.scale,
            steps,
            readings: self.readings.iter().map(|r| r.moved(&m)).collect(),
        }
    }

    /// The figure with only the steps of group 0 and of the groups `keep`: a drawing of a
    /// few of the positions a construction traced (the others were traced all the same, and
    /// what they found stays in group 0). The steps keep their ids.
    pub fn only_groups(&self, keep: &[u32]) -> Figure {
        Figure {
            title: self.title.clone(),
            scale: self.scale,
            steps: self
                .steps
                .iter()
                .filter(|s| s.group == 0 || keep.contains(&s.group))
                .cloned()
                .collect(),
            readings: self
                .readings
                .iter()
                .filter(|r| r.group == 0 || keep.contains(&r.group))
                .copied()
                .collect(),
        }
    }

    /// The figure with a free text `text` (label markup) at `at`, written toward `toward`: a
    /// scale or a word a sheet writes beside a construction in the sheet's language.
    pub fn with_text(mut self, note: &str, at: DVec2, text: String, toward: DVec2) -> Figure {
        // After the last id (a figure of a few groups has gaps in its ids).
        let id = StepId(self.steps.iter().map(|s| s.id.0 + 1).max().unwrap_or(0));
        self.steps.push(Step {
            id,
            note: note.to_string(),
            item: Item::Text(at),
            role: Role::Dimension,
            label: Some(Label {
                text,
                anchor: at,
                toward,
                within_mm: None,
                column_mm: None,
                names: Names::Item,
            }),
            from: Vec::new(),
            group: 0,
        });
        self
    }

    /// Axis-aligned bounds (min, max) of everything drawn, mm; `None` for an empty figure.
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let mut add = |p: DVec2| {
            lo = lo.min(p);
            hi = hi.max(p);
        };
        for s in &self.steps {
            s.item.bounding_points(&mut add);
        }
        lo.is_finite().then_some((lo, hi))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scale::Quantity;

    #[test]
    fn a_mirrored_figure_is_the_mirror_image_and_twice_is_itself() {
        let arc = Arc {
            center: DVec2::new(2.0, 1.0),
            radius: 3.0,
            start: 0.3,
            sweep: 1.1,
        };
        let step = |id: u32, item: Item| Step {
            id: StepId(id),
            note: String::new(),
            item,
            role: Role::Construction,
            label: Some(Label {
                text: "A".into(),
                anchor: DVec2::new(1.0, 2.0),
                toward: DVec2::new(0.6, 0.8),
                within_mm: None,
                column_mm: None,
                names: Names::Point,
            }),
            from: Vec::new(),
            group: 0,
        };
        let f = Figure {
            title: "t".into(),
            scale: Scale::new(0.001, Quantity::Length).unwrap(),
            steps: vec![
                step(0, Item::Arc(arc)),
                step(
                    1,
                    Item::Guide {
                        segment: Segment::new(DVec2::ZERO, DVec2::X),
                        hatch: Side::Left,
                    },
                ),
                step(
                    2,
                    Item::Slider {
                        at: DVec2::new(4.0, -1.0),
                        angle: 0.2,
                    },
                ),
            ],
            readings: Vec::new(),
        };
        let g = f.mirrored_x();
        let Item::Arc(a) = &g.steps[0].item else {
            panic!()
        };
        for t in [0.0, 0.5, 1.0] {
            let (p, q) = (arc.eval(t), a.eval(t));
            assert!((p.x + q.x).abs() < 1e-12 && (p.y - q.y).abs() < 1e-12);
        }
        // The hatching stays on the same side in the plane: the mirrored left is the right.
        assert!(matches!(
            g.steps[1].item,
            Item::Guide {
                hatch: Side::Right,
                ..
            }
        ));
        let (lo, hi) = f.bounds().unwrap();
        let (glo, ghi) = g.bounds().unwrap();
        assert!((glo.x + hi.x).abs() < 1e-9 && (ghi.x + lo.x).abs() < 1e-9);
        assert_eq!(
            g.steps[0].label.as_ref().unwrap().toward,
            DVec2::new(-0.6, 0.8)
        );
        // Twice is the figure itself (angles to rounding).
        let back = g.mirrored_x();
        assert_eq!(back.steps[1], f.steps[1]);
        let (Item::Arc(b), Item::Slider { angle, .. }) = (&back.steps[0].item, &back.steps[2].item)
        else {
            panic!()
        };
        assert!((b.start - arc.start).abs() < 1e-15 && b.sweep == arc.sweep);
        assert!((angle - 0.2).abs() < 1e-15);
        // Moved and joined: the second copy's ids follow the first's, its `from` with them,
        // and everything of it (labels too) lies `d` away.
        let d = DVec2::new(10.0, -5.0);
        let mut moved = f.translated(d);
        moved.steps[2].from = vec![StepId(0)];
        let j = f.clone().joined(moved);
        assert_eq!(j.steps.len(), 6);
        assert_eq!(j.steps[5].id, StepId(5));
        assert_eq!(j.steps[5].from, vec![StepId(3)]);
        assert_eq!(
            j.steps[4].item,
            Item::Guide {
                segment: Segment::new(d, DVec2::X + d),
                hatch: Side::Left,
            }
        );
        let l = j.steps[3].label.as_ref().unwrap();
        assert_eq!(
            (l.anchor, l.toward),
            (DVec2::new(11.0, -3.0), DVec2::new(0.6, 0.8))
        );
        let (jlo, jhi) = j.bounds().unwrap();
        assert_eq!((jlo, jhi), (lo.min(lo + d), hi.max(hi + d)));
    }
}
