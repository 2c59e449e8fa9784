//! A force polygon laid off head to tail at μ_F, closed by two known directions, its
//! reactions read off under the drafting model.

use super::detail::{details, unname_read_elsewhere, PolygonDetail, SMALL_FORCE_MM};
use crate::construct::{ConstructionError, Context, Figure, Item, Recorder, Role};
use crate::forces::arrows::{overlap, vectors, ON_LINE_MM};
use crate::forces::loads::Load;
use crate::geom::{DVec2, Line, Segment};
use crate::scale::Scale;

/// A force polygon being laid off.
pub(super) struct Polygon {
    pub(super) rec: Recorder,
    pub(super) tip: DVec2,
    /// The forces laid off, polygon mm.
    pub(super) laid: Vec<(DVec2, DVec2)>,
    /// The vectors drawn beside another on its line.
    beside: Vec<Beside>,
}

/// A vector drawn beside the one whose line it shares: its step, the steps of the thin lines
/// joining its tail and its head to the polygon's points, and its shift off its line,
/// polygon mm.
struct Beside {
    vector: usize,
    joins: [usize; 2],
    shift: DVec2,
}

impl Polygon {
    pub(super) fn new(title: String, mu_f: Scale, ctx: &Context) -> Self {
        Self {
            rec: Recorder::in_context(title, mu_f, ctx),
            tip: DVec2::ZERO,
            laid: Vec::new(),
            beside: Vec::new(),
        }
    }

    /// The polygon `drawn` as a detail enlarging it `k` times shows it: each vector drawn
    /// beside another [`BESIDE_MM`] off it on the detail, not `k` times that (on a detail
    /// ten times larger it stood 20 mm off its point).
    fn enlarged(&self, drawn: &Figure, k: f64) -> Figure {
        let mut f = drawn.clone();
        for b in &self.beside {
            let back = b.shift - b.shift / k;
            if let Item::Vector { from, to } = f.steps[b.vector].item {
                f.steps[b.vector].item = Item::Vector {
                    from: from - back,
                    to: to - back,
                };
            }
            if let Item::Segment(s) = f.steps[b.joins[0]].item {
                f.steps[b.joins[0]].item = Item::Segment(Segment::new(s.from, s.to - back));
            }
            if let Item::Segment(s) = f.steps[b.joins[1]].item {
                f.steps[b.joins[1]].item = Item::Segment(Segment::new(s.from - back, s.to));
            }
        }
        f
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
        let mu = drawn.scale;
        let d = details(mu, &self.laid, &|detail: Scale| {
            self.enlarged(&drawn, mu.value() / detail.value())
        });
        for d in &d {
            self.rec.draw(
                "the zone of the polygon's detail",
                Item::Circle(d.zone),
                Role::Construction,
                &[],
            );
        }
        let mut polygon = self.rec.finish();
        let zones: Vec<_> = d.iter().map(|d| d.zone).collect();
        unname_read_elsewhere(&mut polygon, &zones);
        (polygon, d)
    }
    /// Lay off a force head to tail; returns its end.
    pub(super) fn lay(&mut self, name: &str, f: DVec2) -> DVec2 {
        let to = self.tip + f / self.rec.scale().value();
        if to != self.tip {
            self.laid.push((self.tip, to));
            self.vector(format!("lay off {name}"), name, (self.tip, to), Role::Given);
        }
        self.tip = to;
        to
    }

    /// Draw the polygon's vector `from`–`to` labelled `name` at its middle; where it would
    /// lie on a vector drawn already (two forces along one line, the second laid back over
    /// the first: F_д5 over F_и5 on the V-engine's cylinder), beside it, [`BESIDE_MM`] off
    /// on the first free side, its ends joined to the polygon's points by thin lines — the
    /// textbook's collinear vectors drawn side by side. The polygon's points stay where the
    /// forces put them. A force read on a detail ([`SMALL_FORCE_MM`]) stays on its line.
    fn vector(&mut self, note: String, name: &str, (from, to): (DVec2, DVec2), role: Role) {
        let drawn = vectors(&self.rec);
        let n = (to - from).perp().normalize_or_zero();
        let free = |d: &DVec2| {
            !drawn
                .iter()
                .any(|&pq| overlap(from + *d, to + *d, pq, ON_LINE_MM))
        };
        // The side it lies on already, off the lines it would lie on (R₃₋₄ 0,5 mm above
        // R₄₋₅ on the shaper's polygon 4–5): moved further that way, the two keep the order
        // their detail shows them in.
        let mid = from.lerp(to, 0.5);
        let lean: f64 = drawn
            .iter()
            .filter(|&&pq| overlap(from, to, pq, ON_LINE_MM))
            .map(|&(p, q)| {
                let u = (q - p).normalize_or_zero();
                let off = mid - p - u * (mid - p).dot(u);
                off.dot(n)
            })
            .sum();
        let sense = if lean < 0.0 { -1.0 } else { 1.0 };
        let beside = if from.distance(to) < SMALL_FORCE_MM {
            DVec2::ZERO
        } else {
            [0.0, 1.0, -1.0, 2.0, -2.0]
                .map(|k| n * (k * sense * BESIDE_MM))
                .into_iter()
                .find(free)
                .unwrap_or(DVec2::ZERO)
        };
        let mut joins = [0; 2];
        if beside != DVec2::ZERO {
            for (k, (a, b)) in [(from, from + beside), (to + beside, to)]
                .into_iter()
                .enumerate()
            {
                let id = self.rec.draw(
                    format!("{note}: beside the vector on its line"),
                    Item::Segment(Segment::new(a, b)),
                    Role::Construction,
                    &[],
                );
                joins[k] = id.0 as usize;
            }
        }
        let (a, b) = (from + beside, to + beside);
        let id = self
            .rec
            .draw(note, Item::Vector { from: a, to: b }, role, &[]);
        if beside != DVec2::ZERO {
            self.beside.push(Beside {
                vector: id.0 as usize,
                joins,
                shift: beside,
            });
        }
        // Labelled on its side, away from the vector it stands beside.
        let side = beside.try_normalize().unwrap_or(n);
        self.rec.label(id, name, a.lerp(b, 0.5), side);
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
            self.vector(format!("read {name}"), name, (from, to), Role::Result);
        }
        (to - from).normalize_or_zero() * m.value
    }
}

/// A vector of the polygon on the line of one drawn already is drawn this far beside it, mm
/// (a result's arrowhead is 1.2 mm wide: two heads side by side with a gap between them).
const BESIDE_MM: f64 = 2.0;

/// How far a polygon's closing direction is drawn past the closing point, mm.
const CLOSING_PAST_MM: f64 = 5.0;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Drafting;
    use crate::scale::Quantity;

    fn vectors(f: &Figure) -> Vec<(DVec2, DVec2)> {
        f.steps
            .iter()
            .filter_map(|s| match s.item {
                Item::Vector { from, to } => Some((from, to)),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn a_force_laid_back_along_another_is_drawn_beside_it() {
        let mu = Scale::new(40.0, Quantity::Force).expect("μ_F");
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
        let mut pol = Polygon::new("polygon".into(), mu, &ctx);
        let e = DVec2::from_angle(2.356);
        // F_и5 = 884 N up the cylinder, F_д5 = 5280 N back down it.
        let t = pol.lay("F_{и5}", e * 884.0);
        let end = pol.lay("F_{д5}", -e * 5280.0);
        // The polygon's points are where the forces put them.
        assert!(t.distance(e * 884.0 / 40.0) < 1e-9);
        assert!(end.distance(-e * (5280.0 - 884.0) / 40.0) < 1e-9);
        let (figure, _) = pol.finish();
        let v = vectors(&figure);
        assert_eq!(v[0], (DVec2::ZERO, t));
        // F_д5 beside F_и5, 2 mm off its line, parallel and as long as it is.
        let off = (v[1].0 - t).perp_dot(e);
        assert!((off.abs() - BESIDE_MM).abs() < 1e-9, "{off} mm off");
        assert!((v[1].1 - v[1].0 - (end - t)).length() < 1e-9);
        // Its ends joined to the polygon's points by thin lines.
        let joins = figure
            .steps
            .iter()
            .filter(|s| s.note.ends_with("beside the vector on its line"))
            .count();
        assert_eq!(joins, 2);
    }

    /// Two reactions laid back to one point along nearly one line (the shaper's R₃₋₄ 0,5 mm
    /// off R₄₋₅): the second moves further to the side it lies on, so the polygon shows the
    /// two in the order its detail, ten times larger, shows them.
    #[test]
    fn a_vector_beside_another_keeps_its_side() {
        let mu = Scale::new(20.0, Quantity::Force).expect("μ_F");
        let ctx = Context::for_model_size(300.0, Drafting::EXACT).expect("a context");
        for lean in [0.5, -0.5] {
            let mut pol = Polygon::new("polygon".into(), mu, &ctx);
            pol.lay("R_{3-4}", DVec2::new(-1750.0, 0.0));
            let drawn = (DVec2::new(0.0, lean), DVec2::new(-87.5, lean));
            pol.vector("read".into(), "R_{4-5}", drawn, Role::Result);
            let (figure, _) = pol.finish();
            let v = vectors(&figure);
            let off = v[1].0.y;
            assert!(
                off * lean > 0.0 && off.abs() > 1.5,
                "lean {lean}: drawn {off} mm off"
            );
        }
    }
}
