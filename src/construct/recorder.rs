//! The recorder itself.

use super::error::ConstructionError;
use crate::geom::{
    circle_circle, line_circle, line_line, Arc, Circle, CircleCircle, DVec2, Line, LineCircle,
    LineLine, Segment, Side, Tolerances,
};
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

/// What a step draws, in figure millimetres (y up).
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// A marked point (a small dot).
    Point(DVec2),
    /// A revolute pair: a small circle; `fixed` adds the ground support symbol.
    Joint {
        /// Centre of the pair.
        at: DVec2,
        /// Attached to the frame.
        fixed: bool,
    },
    /// A straight piece: a link, a chord, a construction line.
    Segment(Segment),
    /// A full circle.
    Circle(Circle),
    /// An arc (compass notch, angle mark).
    Arc(Arc),
    /// A polyline through points.
    Polyline {
        /// Vertices.
        points: Vec<DVec2>,
        /// Join the last point to the first.
        closed: bool,
    },
    /// A smooth curve through points (trajectories, diagram curves).
    Curve {
        /// Points the curve passes through, in order.
        points: Vec<DVec2>,
        /// A closed curve.
        closed: bool,
    },
    /// An arrowed vector (plans, forces).
    Vector {
        /// Tail.
        from: DVec2,
        /// Head.
        to: DVec2,
    },
    /// A slider block centred at `at`, its long side along `angle` (radians).
    Slider {
        /// Centre.
        at: DVec2,
        /// Direction of sliding.
        angle: f64,
    },
    /// A fixed guide: the line piece with hatching on one side.
    Guide {
        /// The guide line piece.
        segment: Segment,
        /// Side of `segment` (from → to) that carries the hatching.
        hatch: Side,
    },
    /// A linear dimension between two points, its line offset by `offset` mm to the left
    /// of `from → to`; the label is the dimension text.
    Dimension {
        /// First point.
        from: DVec2,
        /// Second point.
        to: DVec2,
        /// Offset of the dimension line, mm (positive: left of from → to).
        offset: f64,
    },
    /// An angle mark: arc with arrows at both ends; the label is the angle's name.
    Angle(Arc),
    /// Free text anchored at a point (the label carries the text).
    Text(DVec2),
}

/// A textbook label. `text` uses the label markup: `_x` or `_{xy}` for a subscript,
/// `^x` or `^{xy}` for a superscript (`b_3`, `S_{3}`, `a^{k}`, `8′`).
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// The text, in label markup.
    pub text: String,
    /// The point the label belongs to.
    pub anchor: DVec2,
    /// Preferred direction from the anchor to the text (unit or zero for centred on the anchor).
    pub toward: DVec2,
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
}

impl Figure {
    /// Axis-aligned bounds (min, max) of everything drawn, mm; `None` for an empty figure.
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        let mut add = |p: DVec2| {
            lo = lo.min(p);
            hi = hi.max(p);
        };
        for s in &self.steps {
            match &s.item {
                Item::Point(p) | Item::Text(p) => add(*p),
                Item::Joint { at, .. } | Item::Slider { at, .. } => add(*at),
                Item::Segment(seg) | Item::Guide { segment: seg, .. } => {
                    add(seg.from);
                    add(seg.to)
                }
                Item::Circle(c) => {
                    add(c.center - DVec2::splat(c.radius));
                    add(c.center + DVec2::splat(c.radius))
                }
                Item::Arc(a) | Item::Angle(a) => {
                    for i in 0..=16 {
                        add(a.eval(i as f64 / 16.0));
                    }
                }
                Item::Polyline { points, .. } | Item::Curve { points, .. } => {
                    points.iter().for_each(|p| add(*p))
                }
                Item::Vector { from, to } => {
                    add(*from);
                    add(*to)
                }
                Item::Dimension { from, to, offset } => {
                    let n = (*to - *from).normalize_or_zero().perp() * *offset;
                    add(*from + n);
                    add(*to + n);
                }
            }
        }
        lo.is_finite().then_some((lo, hi))
    }
}

/// The drafting model: a length read off the drawing is rounded to `resolution_mm`
/// before μ converts it (0 = exact).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Drafting {
    resolution_mm: f64,
}

impl Drafting {
    /// Exact reading.
    pub const EXACT: Drafting = Drafting { resolution_mm: 0.0 };

    /// `None` unless finite and ≥ 0.
    pub fn new(resolution_mm: f64) -> Option<Self> {
        (resolution_mm.is_finite() && resolution_mm >= 0.0).then_some(Self { resolution_mm })
    }
    /// The resolution, mm.
    pub fn resolution_mm(&self) -> f64 {
        self.resolution_mm
    }
    /// A length as read with this resolution.
    pub fn read(&self, mm: f64) -> f64 {
        if self.resolution_mm > 0.0 {
            (mm / self.resolution_mm).round() * self.resolution_mm
        } else {
            mm
        }
    }
}

/// A measured segment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// Its exact drawn length, mm.
    pub drawn_mm: f64,
    /// The length as read under the drafting model, mm.
    pub read_mm: f64,
    /// The physical value: `read_mm × μ`.
    pub value: f64,
}

/// Which of two compass solutions to take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pick {
    /// Left of the directed line between the two arc centres (circle–circle).
    Left,
    /// Right of the directed line between the two arc centres (circle–circle).
    Right,
    /// Farther along the line's direction (line–circle).
    Forward,
    /// Farther back along the line's direction (line–circle).
    Backward,
    /// The solution nearest to a previous position (continuity), figure mm.
    Near(DVec2),
}

impl std::fmt::Display for Pick {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Pick::Left => f.write_str("left"),
            Pick::Right => f.write_str("right"),
            Pick::Forward => f.write_str("forward"),
            Pick::Backward => f.write_str("backward"),
            Pick::Near(p) => write!(f, "nearest to ({:.3}, {:.3})", p.x, p.y),
        }
    }
}

/// A compass setting: a named centre and a radius, both in figure mm.
#[derive(Debug, Clone, Copy)]
pub struct Compass<'a> {
    /// Name of the centre (for notes and diagnostics).
    pub name: &'a str,
    /// The centre.
    pub center: DVec2,
    /// The radius.
    pub radius: f64,
}

/// Records a construction into a [`Figure`].
#[derive(Debug, Clone)]
pub struct Recorder {
    figure: Figure,
    tol: Tolerances,
    drafting: Drafting,
    group: u32,
    notch_mm: f64,
}

impl Recorder {
    /// Start a figure at scale `scale` with tolerances in figure mm.
    pub fn new(
        title: impl Into<String>,
        scale: Scale,
        tol: Tolerances,
        drafting: Drafting,
    ) -> Self {
        Self {
            figure: Figure {
                title: title.into(),
                scale,
                steps: Vec::new(),
            },
            tol,
            drafting,
            group: 0,
            notch_mm: 4.0,
        }
    }

    /// The figure's scale.
    pub fn scale(&self) -> Scale {
        self.figure.scale
    }
    /// The tolerances in use.
    pub fn tolerances(&self) -> &Tolerances {
        &self.tol
    }
    /// The drafting model in use.
    pub fn drafting(&self) -> Drafting {
        self.drafting
    }
    /// Tag the following steps with `group` (e.g. a position number).
    pub fn set_group(&mut self, group: u32) {
        self.group = group;
    }
    /// Half-length of compass notches, mm (default 4).
    pub fn set_notch_mm(&mut self, mm: f64) {
        self.notch_mm = mm;
    }
    /// The steps so far.
    pub fn steps(&self) -> &[Step] {
        &self.figure.steps
    }
    /// Finish and return the figure.
    pub fn finish(self) -> Figure {
        self.figure
    }

    /// Record a step.
    pub fn draw(
        &mut self,
        note: impl Into<String>,
        item: Item,
        role: Role,
        from: &[StepId],
    ) -> StepId {
        let id = StepId(self.figure.steps.len() as u32);
        self.figure.steps.push(Step {
            id,
            note: note.into(),
            item,
            role,
            label: None,
            from: from.to_vec(),
            group: self.group,
        });
        id
    }

    /// Attach a label to a recorded step.
    pub fn label(&mut self, id: StepId, text: impl Into<String>, anchor: DVec2, toward: DVec2) {
        if let Some(step) = self.figure.steps.get_mut(id.0 as usize) {
            step.label = Some(Label {
                text: text.into(),
                anchor,
                toward,
            });
        }
    }

    /// Record a labelled point.
    pub fn point(
        &mut self,
        note: impl Into<String>,
        at: DVec2,
        role: Role,
        label: &str,
        toward: DVec2,
        from: &[StepId],
    ) -> StepId {
        let id = self.draw(note, Item::Point(at), role, from);
        if !label.is_empty() {
            self.label(id, label, at, toward);
        }
        id
    }

    /// Measure a drawn segment: exact length, length as read, physical value.
    pub fn measure(&self, from: DVec2, to: DVec2) -> Measured {
        let drawn_mm = from.distance(to);
        let read_mm = self.drafting.read(drawn_mm);
        Measured {
            drawn_mm,
            read_mm,
            value: self.figure.scale.to_physical(read_mm),
        }
    }

    fn phys(&self, mm: f64) -> f64 {
        self.figure.scale.to_physical(mm)
    }
    fn unit(&self) -> &'static str {
        si_unit(self.figure.scale.quantity)
    }

    /// Notch both arcs at the intersection of two compass settings and return the chosen
    /// point with the id of the recorded result point.
    pub fn meet_circles(
        &mut self,
        step: &str,
        a: Compass<'_>,
        b: Compass<'_>,
        pick: Pick,
    ) -> Result<(DVec2, f64, StepId), ConstructionError> {
        let ca = Circle {
            center: a.center,
            radius: a.radius,
        };
        let cb = Circle {
            center: b.center,
            radius: b.radius,
        };
        let (p, crossing) = match circle_circle(&ca, &cb, &self.tol) {
            CircleCircle::Two {
                left,
                right,
                crossing_angle,
            } => {
                let p = match pick {
                    Pick::Left => left,
                    Pick::Right => right,
                    Pick::Near(prev) => {
                        if left.distance_squared(prev) <= right.distance_squared(prev) {
                            left
                        } else {
                            right
                        }
                    }
                    Pick::Forward | Pick::Backward => {
                        return Err(ConstructionError::BadPick {
                            step: step.into(),
                            pick: pick.to_string(),
                            what: "two arcs",
                        })
                    }
                };
                (p, crossing_angle)
            }
            CircleCircle::Tangent { point } => (point, 0.0),
            CircleCircle::Disjoint {
                center_distance, ..
            } => {
                return Err(ConstructionError::CirclesDoNotMeet {
                    step: step.into(),
                    a: a.name.into(),
                    b: b.name.into(),
                    ra: self.phys(a.radius),
                    rb: self.phys(b.radius),
                    d: self.phys(center_distance),
                    unit: self.unit(),
                })
            }
            CircleCircle::Coincident => {
                return Err(ConstructionError::CirclesCoincide {
                    step: step.into(),
                    a: a.name.into(),
                    b: b.name.into(),
                    r: self.phys(a.radius),
                    unit: self.unit(),
                })
            }
        };
        let n1 = self.draw(
            format!("{step}: arc from {} r = {:.3} mm", a.name, a.radius),
            Item::Arc(Arc::notch(a.center, p, self.notch_mm)),
            Role::Construction,
            &[],
        );
        let n2 = self.draw(
            format!("{step}: arc from {} r = {:.3} mm", b.name, b.radius),
            Item::Arc(Arc::notch(b.center, p, self.notch_mm)),
            Role::Construction,
            &[],
        );
        let id = self.draw(
            format!("{step}: intersection of the arcs"),
            Item::Point(p),
            Role::Result,
            &[n1, n2],
        );
        Ok((p, crossing, id))
    }

    /// Notch a line with a compass arc and return the chosen point.
    pub fn meet_line_circle(
        &mut self,
        step: &str,
        line: (&str, &Line),
        c: Compass<'_>,
        pick: Pick,
    ) -> Result<(DVec2, f64, StepId), ConstructionError> {
        let circle = Circle {
            center: c.center,
            radius: c.radius,
        };
        let (p, crossing) = match line_circle(line.1, &circle, &self.tol) {
            LineCircle::Two {
                backward,
                forward,
                crossing_angle,
            } => {
                let p = match pick {
                    Pick::Forward => forward,
                    Pick::Backward => backward,
                    Pick::Near(prev) => {
                        if forward.distance_squared(prev) <= backward.distance_squared(prev) {
                            forward
                        } else {
                            backward
                        }
                    }
                    Pick::Left | Pick::Right => {
                        return Err(ConstructionError::BadPick {
                            step: step.into(),
                            pick: pick.to_string(),
                            what: "an arc and a line",
                        })
                    }
                };
                (p, crossing_angle)
            }
            LineCircle::Tangent { point } => (point, 0.0),
            LineCircle::Disjoint { distance, radius } => {
                return Err(ConstructionError::LineMissesCircle {
                    step: step.into(),
                    center: c.name.into(),
                    line: line.0.into(),
                    r: self.phys(radius),
                    distance: self.phys(distance),
                    unit: self.unit(),
                })
            }
        };
        let n = self.draw(
            format!("{step}: arc from {} r = {:.3} mm", c.name, c.radius),
            Item::Arc(Arc::notch(c.center, p, self.notch_mm)),
            Role::Construction,
            &[],
        );
        let id = self.draw(
            format!("{step}: arc meets {}", line.0),
            Item::Point(p),
            Role::Result,
            &[n],
        );
        Ok((p, crossing, id))
    }

    /// Intersect two straight lines (both assumed drawn) and return the point.
    pub fn meet_lines(
        &mut self,
        step: &str,
        a: (&str, &Line),
        b: (&str, &Line),
    ) -> Result<(DVec2, f64, StepId), ConstructionError> {
        match line_line(a.1, b.1, &self.tol) {
            LineLine::Point {
                point,
                crossing_angle,
                ..
            } => {
                let id = self.draw(
                    format!("{step}: {} meets {}", a.0, b.0),
                    Item::Point(point),
                    Role::Result,
                    &[],
                );
                Ok((point, crossing_angle, id))
            }
            LineLine::Parallel { distance } => Err(ConstructionError::LinesParallel {
                step: step.into(),
                a: a.0.into(),
                b: b.0.into(),
                distance: self.phys(distance),
                unit: self.unit(),
            }),
            LineLine::Coincident => Err(ConstructionError::LinesParallel {
                step: step.into(),
                a: a.0.into(),
                b: b.0.into(),
                distance: 0.0,
                unit: self.unit(),
            }),
        }
    }

    /// The straightedge line through two named points.
    pub fn line_through(
        &self,
        step: &str,
        a: (&str, DVec2),
        b: (&str, DVec2),
    ) -> Result<Line, ConstructionError> {
        Line::through(a.1, b.1).ok_or_else(|| ConstructionError::CoincidentPoints {
            step: step.into(),
            what: format!("line {}{}", a.0, b.0),
            a: a.0.into(),
            b: b.0.into(),
        })
    }
}

/// The SI unit of a scale's quantity (for diagnostics).
pub fn si_unit(q: crate::scale::Quantity) -> &'static str {
    use crate::scale::Quantity::*;
    match q {
        Length => "m",
        Velocity => "m/s",
        Acceleration => "m/s²",
        Angle => "rad",
        Time => "s",
        Force => "N",
        Moment => "N·m",
        Work => "J",
        Inertia => "kg·m²",
        AngularVelocity => "rad/s",
        AngularAcceleration => "rad/s²",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scale::Quantity;

    fn rec() -> Recorder {
        Recorder::new(
            "test",
            Scale::new(0.0025, Quantity::Length).unwrap(),
            Tolerances::for_model_size(300.0).unwrap(),
            Drafting::new(0.5).unwrap(),
        )
    }

    #[test]
    fn meet_circles_records_two_notches_and_the_point() {
        let mut r = rec();
        let (p, _, id) = r
            .meet_circles(
                "B",
                Compass {
                    name: "A",
                    center: DVec2::ZERO,
                    radius: 5.0,
                },
                Compass {
                    name: "C",
                    center: DVec2::new(8.0, 0.0),
                    radius: 5.0,
                },
                Pick::Left,
            )
            .unwrap();
        assert!((p - DVec2::new(4.0, 3.0)).length() < 1e-12);
        assert_eq!(r.steps().len(), 3);
        assert_eq!(r.steps()[id.0 as usize].from, vec![StepId(0), StepId(1)]);
    }

    #[test]
    fn meet_circles_failure_names_the_step_and_numbers_in_si() {
        let mut r = rec();
        let e = r
            .meet_circles(
                "position 7, B",
                Compass {
                    name: "A",
                    center: DVec2::ZERO,
                    radius: 56.0,
                },
                Compass {
                    name: "C",
                    center: DVec2::new(248.0, 0.0),
                    radius: 172.0,
                },
                Pick::Left,
            )
            .unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("position 7, B"), "{msg}");
        assert!(
            msg.contains("0.14000 m") && msg.contains("0.62000 m") && msg.contains("0.57000"),
            "{msg}"
        );
        assert!(r.steps().is_empty());
    }

    #[test]
    fn drafting_rounds_before_scaling() {
        let r = rec();
        let m = r.measure(DVec2::ZERO, DVec2::new(42.6, 0.0));
        assert_eq!(m.read_mm, 42.5);
        assert!((m.value - 42.5 * 0.0025).abs() < 1e-15);
        assert!(Drafting::new(-1.0).is_none());
    }
}
