//! Axis-aligned rectangles: a sheet's boxes, a figure's window, what a segment or polyline
//! is clipped to.

use super::DVec2;

/// An axis-aligned rectangle: the corners `min` (the least x and y) and `max` (on a sheet,
/// millimetres with y down, the top-left and bottom-right corners).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    /// The corner of the least x and y.
    pub min: DVec2,
    /// The corner of the greatest x and y.
    pub max: DVec2,
}

impl Rect {
    /// The rectangle with corners `min` and `max`.
    pub fn new(min: DVec2, max: DVec2) -> Self {
        Self { min, max }
    }
    /// Width.
    pub fn width(&self) -> f64 {
        self.max.x - self.min.x
    }
    /// Height.
    pub fn height(&self) -> f64 {
        self.max.y - self.min.y
    }
    /// The centre.
    pub fn center(&self) -> DVec2 {
        (self.min + self.max) * 0.5
    }
    /// (width, height).
    pub fn size(&self) -> DVec2 {
        self.max - self.min
    }
    /// True when the two rectangles share interior points (touching edges do not count).
    pub fn intersects(&self, other: &Rect) -> bool {
        let s = self.max.min(other.max) - self.min.max(other.min);
        s.x > 0.0 && s.y > 0.0
    }
    /// True when the two rectangles share any point, edges and degenerate (zero-width or
    /// zero-height) rectangles included: the box of a horizontal line touches what it crosses.
    pub fn touches(&self, other: &Rect) -> bool {
        let s = self.max.min(other.max) - self.min.max(other.min);
        s.x >= 0.0 && s.y >= 0.0
    }
    /// Area of the common part.
    pub fn overlap(&self, other: &Rect) -> f64 {
        let s = self.max.min(other.max) - self.min.max(other.min);
        s.x.max(0.0) * s.y.max(0.0)
    }
    /// True when `other` lies inside this rectangle (edges included).
    pub fn contains(&self, other: &Rect) -> bool {
        other.min.cmpge(self.min).all() && other.max.cmple(self.max).all()
    }
    /// The smallest rectangle holding both.
    pub fn union(&self, other: &Rect) -> Rect {
        Rect::new(self.min.min(other.min), self.max.max(other.max))
    }
    /// The rectangle grown by `d` on every side (shrunk for a negative `d`).
    pub fn inflate(&self, d: f64) -> Rect {
        Rect::new(self.min - DVec2::splat(d), self.max + DVec2::splat(d))
    }
    /// The box of a set of points; `None` when there is no finite one.
    pub fn around(points: impl IntoIterator<Item = DVec2>) -> Option<Rect> {
        let (lo, hi) = points
            .into_iter()
            .filter(|p| p.is_finite())
            .fold((DVec2::INFINITY, DVec2::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p), hi.max(p))
            });
        lo.is_finite().then(|| Rect::new(lo, hi))
    }

    /// The parameter interval `[t0, t1]` ⊂ [0, 1] of the segment `a → b` inside the
    /// rectangle (its edges included), by Liang–Barsky; `None` when it misses it.
    pub fn segment_inside(&self, a: DVec2, b: DVec2) -> Option<(f64, f64)> {
        let d = b - a;
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for (p, q) in [
            (-d.x, a.x - self.min.x),
            (d.x, self.max.x - a.x),
            (-d.y, a.y - self.min.y),
            (d.y, self.max.y - a.y),
        ] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else {
                let t = q / p;
                if p < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
        (t0 <= t1).then_some((t0, t1))
    }

    /// The runs of the polyline `points` inside the rectangle, in order: a run breaks where
    /// the polyline leaves it (its pieces of fewer than two points dropped).
    pub fn polyline_inside(&self, points: &[DVec2]) -> Vec<Vec<DVec2>> {
        let mut out: Vec<Vec<DVec2>> = Vec::new();
        let mut cur: Vec<DVec2> = Vec::new();
        for s in points.windows(2) {
            let (a, b) = (s[0], s[1]);
            match self.segment_inside(a, b) {
                Some((t0, t1)) => {
                    let (a, b) = (a + (b - a) * t0, a + (b - a) * t1);
                    if cur.last().is_none_or(|l| (*l - a).length() > 1e-9) {
                        if cur.len() >= 2 {
                            out.push(std::mem::take(&mut cur));
                        }
                        cur = vec![a];
                    }
                    cur.push(b);
                }
                None => {
                    if cur.len() >= 2 {
                        out.push(std::mem::take(&mut cur));
                    }
                    cur.clear();
                }
            }
        }
        if cur.len() >= 2 {
            out.push(cur);
        }
        out
    }
}
