//! A force polygon laid off head to tail at μ_F, closed by two known directions, its
//! reactions read off under the drafting model.

use super::detail::{details, PolygonDetail};
use crate::construct::{ConstructionError, Context, Figure, Item, Recorder, Role};
use crate::forces::loads::Load;
use crate::geom::{DVec2, Line, Segment};
use crate::scale::Scale;

/// A force polygon being laid off.
pub(super) struct Polygon {
    pub(super) rec: Recorder,
    pub(super) tip: DVec2,
    /// The forces laid off, polygon mm.
    pub(super) laid: Vec<(DVec2, DVec2)>,
}

impl Polygon {
    pub(super) fn new(title: String, mu_f: Scale, ctx: &Context) -> Self {
        Self {
            rec: Recorder::in_context(title, mu_f, ctx),
            tip: DVec2::ZERO,
            laid: Vec::new(),
        }
    }

    /// The polygon as drawn, and the details its small forces need (their zones circled on
    /// the polygon).
    pub(super) fn finish(mut self) -> (Figure, Vec<PolygonDetail>) {
        let drawn = Figure {
            title: String::new(),
            scale: self.rec.scale(),
            steps: self.rec.steps().to_vec(),
            readings: Vec::new(),
        };
        let d = details(&drawn, &self.laid);
        for d in &d {
            self.rec.draw(
                "the zone of the polygon's detail",
                Item::Circle(d.zone),
                Role::Construction,
                &[],
            );
        }
        (self.rec.finish(), d)
    }
    /// Lay off a force head to tail; returns its end.
    pub(super) fn lay(&mut self, name: &str, f: DVec2) -> DVec2 {
        let to = self.tip + f / self.rec.scale().value();
        if to != self.tip {
            self.laid.push((self.tip, to));
            let id = self.rec.draw(
                format!("lay off {name}"),
                Item::Vector { from: self.tip, to },
                Role::Given,
                &[],
            );
            self.rec.label(
                id,
                name,
                self.tip.lerp(to, 0.5),
                (to - self.tip).perp().normalize_or_zero(),
            );
        }
        self.tip = to;
        to
    }
    pub(super) fn lay_all(&mut self, loads: &[&Load]) -> DVec2 {
        for l in loads {
            if !l.is_couple() {
                self.lay(&l.name, l.force);
            }
        }
        self.tip
    }
    /// Close the polygon: the line through `a.1` along `a.2` meets the line through `b.1`
    /// along `b.2` (each named `.0`); each drawn thin from its point to the closing point and
    /// a little past it, as the draughtsman draws them (a line drawn across the closing point
    /// would run through the label of the short reaction beside it).
    pub(super) fn close(
        &mut self,
        a: (&str, DVec2, DVec2),
        b: (&str, DVec2, DVec2),
    ) -> Result<DVec2, ConstructionError> {
        const STEP: &str = "closing the polygon";
        let line = |(name, p, d): (&str, DVec2, DVec2)| {
            Line::new(p, d).ok_or_else(|| ConstructionError::CoincidentPoints {
                step: STEP.into(),
                what: format!("direction {name}"),
                a: name.into(),
                b: name.into(),
            })
        };
        let (la, lb) = (line(a)?, line(b)?);
        let (h, _, _) = self.rec.meet_lines(STEP, (a.0, &la), (b.0, &lb))?;
        for (l, start) in [(la, a.1), (lb, b.1)] {
            let (t0, t1) = (l.project_t(start), l.project_t(h));
            let (from, to) = if (t1 - t0).abs() < CLOSING_PAST_MM {
                // The unknown is about nil: the direction drawn about the closing point.
                (l.eval(t1 - CLOSING_PAST_MM), l.eval(t1 + CLOSING_PAST_MM))
            } else {
                (
                    l.eval(t0),
                    l.eval(t1 + CLOSING_PAST_MM * (t1 - t0).signum()),
                )
            };
            self.rec.draw(
                format!("{STEP}: closing direction"),
                Item::Segment(Segment::new(from, to)),
                Role::Construction,
                &[],
            );
        }
        Ok(h)
    }
    /// Read a reaction off the polygon: the vector from `from` to `to`, its length read
    /// under the drafting model; drawn and labelled `name`.
    pub(super) fn read(&mut self, name: &str, from: DVec2, to: DVec2) -> DVec2 {
        let m = self.rec.measure(from, to);
        if m.drawn_mm > 0.0 {
            let id = self.rec.draw(
                format!("read {name}"),
                Item::Vector { from, to },
                Role::Result,
                &[],
            );
            self.rec.label(
                id,
                name,
                from.lerp(to, 0.5),
                (to - from).perp().normalize_or_zero(),
            );
        }
        (to - from).normalize_or_zero() * m.value
    }
}

/// How far a polygon's closing direction is drawn past the closing point, mm.
const CLOSING_PAST_MM: f64 = 5.0;
