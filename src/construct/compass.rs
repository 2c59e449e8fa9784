//! Compass and straightedge steps: two arcs, an arc and a line, two lines, the line through
//! two points. Each records its notches and result point, or returns a diagnostic error
//! whose numbers are physical values in the unit of the figure's μ.

use super::error::ConstructionError;
use super::figure::{Role, StepId};
use super::item::Item;
use super::recorder::Recorder;
use crate::geom::{
    circle_circle, line_circle, line_line, Arc, Circle, CircleCircle, DVec2, Line, LineCircle,
    LineLine,
};

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

impl Compass<'_> {
    fn circle(&self) -> Circle {
        Circle {
            center: self.center,
            radius: self.radius,
        }
    }
}

/// The solution `pick` names among two, each given with the pick that names it; `Near`
/// takes the nearer one (the first on a tie). `what` names the intersection for the error.
fn choose(
    step: &str,
    pick: Pick,
    two: [(Pick, DVec2); 2],
    what: &'static str,
) -> Result<DVec2, ConstructionError> {
    let [(_, first), (_, second)] = two;
    match pick {
        Pick::Near(prev) if first.distance_squared(prev) <= second.distance_squared(prev) => {
            Ok(first)
        }
        Pick::Near(_) => Ok(second),
        _ => two
            .iter()
            .find(|(named, _)| *named == pick)
            .map(|&(_, p)| p)
            .ok_or_else(|| ConstructionError::BadPick {
                step: step.into(),
                pick: pick.to_string(),
                what,
            }),
    }
}

impl Recorder {
    fn phys(&self, mm: f64) -> f64 {
        self.scale().to_physical(mm)
    }
    fn unit(&self) -> &'static str {
        self.scale().quantity.si_unit()
    }

    /// Record the compass notch of `c` at `p`.
    fn notch(&mut self, step: &str, c: Compass<'_>, p: DVec2) -> StepId {
        let notch_mm = self.context().notch_mm;
        self.draw(
            format!("{step}: arc from {} r = {:.3} mm", c.name, c.radius),
            Item::Arc(Arc::notch(c.center, p, notch_mm)),
            Role::Construction,
            &[],
        )
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
        let (p, crossing) = match circle_circle(&a.circle(), &b.circle(), self.tolerances()) {
            CircleCircle::Two {
                left,
                right,
                crossing_angle,
            } => {
                let two = [(Pick::Left, left), (Pick::Right, right)];
                (choose(step, pick, two, "two arcs")?, crossing_angle)
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
        let n1 = self.notch(step, a, p);
        let n2 = self.notch(step, b, p);
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
        let (p, crossing) = match line_circle(line.1, &c.circle(), self.tolerances()) {
            LineCircle::Two {
                backward,
                forward,
                crossing_angle,
            } => {
                let two = [(Pick::Forward, forward), (Pick::Backward, backward)];
                (
                    choose(step, pick, two, "an arc and a line")?,
                    crossing_angle,
                )
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
        let n = self.notch(step, c, p);
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
        match line_line(a.1, b.1, self.tolerances()) {
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
