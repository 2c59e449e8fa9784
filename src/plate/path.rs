//! SVG path data in sheet millimetres, every number rounded by [`num`].

use crate::geom::{Arc, DVec2};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::fmt::Write as _;

/// Format a coordinate for the SVG: rounded to 0.01 mm, no `-0`, no exponent; a non-finite
/// value is written as `0` so that a bad figure can never produce an unreadable file.
pub(crate) fn num(x: f64) -> String {
    Num(x).to_string()
}

/// A coordinate as [`num`] writes it, written straight into a formatter (a sheet's SVG is
/// hundreds of thousands of them).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Num(pub f64);

impl std::fmt::Display for Num {
    /// The shortest decimal of the value rounded to hundredths, r = k/100: below 10¹⁵
    /// hundredths that is k hundredths exactly (any shorter decimal is a hundredth or more
    /// away, far beyond r's rounding), written from the integer k.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let k = (self.0 * 100.0).round();
        let r = k / 100.0;
        if !r.is_finite() || r == 0.0 {
            return f.write_str("0");
        }
        if k.abs() >= 1e15 {
            return write!(f, "{r}");
        }
        let k = k as i64;
        let (whole, cents) = (k.unsigned_abs() / 100, k.unsigned_abs() % 100);
        let sign = if k < 0 { "-" } else { "" };
        match (cents, cents % 10) {
            (0, _) => write!(f, "{sign}{whole}"),
            (_, 0) => write!(f, "{sign}{whole}.{}", cents / 10),
            _ => write!(f, "{sign}{whole}.{cents:02}"),
        }
    }
}

/// The largest number of pieces a single drawn element is split into (hatch strokes, arc
/// quarters); guards against absurd figures producing unbounded output.
pub(crate) const MAX_PIECES: usize = 20_000;

/// How many pieces of `spacing` fit in `length`, bounded by [`MAX_PIECES`]; 0 for
/// non-finite or non-positive input.
pub(crate) fn pieces(length: f64, spacing: f64) -> usize {
    let n = length / spacing;
    if n.is_finite() && n > 0.0 {
        (n.floor() as usize).min(MAX_PIECES)
    } else {
        0
    }
}

/// The mapping from source coordinates to the sheet: a translation, with y flipped for
/// figures (y up) and kept for sheet furniture (y down).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Map {
    origin: DVec2,
    flip: bool,
}

impl Map {
    /// Sheet coordinates as they are.
    pub(crate) const SHEET: Map = Map {
        origin: DVec2::ZERO,
        flip: false,
    };

    /// Sheet coordinates (y down) whose (0, 0) lands at `origin`.
    pub(crate) fn sheet_at(origin: DVec2) -> Self {
        Self {
            origin,
            flip: false,
        }
    }
    /// Figure coordinates whose (0, 0) lands at `origin` on the sheet.
    pub(crate) fn figure(origin: DVec2) -> Self {
        Self { origin, flip: true }
    }
    /// A source point on the sheet.
    pub(crate) fn pt(&self, p: DVec2) -> DVec2 {
        if self.flip {
            DVec2::new(self.origin.x + p.x, self.origin.y - p.y)
        } else {
            self.origin + p
        }
    }
    /// A source direction on the sheet.
    pub(crate) fn dir(&self, v: DVec2) -> DVec2 {
        if self.flip {
            DVec2::new(v.x, -v.y)
        } else {
            v
        }
    }
}

/// One piece of a path as drawn, in sheet mm (y down), unrounded: what the DXF writer reads
/// (the SVG writes the same pieces as its `d` text).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Seg {
    /// Start a subpath at a point.
    Move(DVec2),
    /// A straight piece to a point.
    Line(DVec2),
    /// A cubic Bézier piece: two control points and its end.
    Cubic(DVec2, DVec2, DVec2),
    /// A circular arc from the current point: its centre and radius, the angle of its start
    /// and its sweep, radians, measured on the sheet (y down, so a positive sweep turns
    /// clockwise as seen).
    Arc {
        /// Centre.
        center: DVec2,
        /// Radius, mm.
        radius: f64,
        /// Angle of the start point about the centre.
        start: f64,
        /// Signed sweep.
        sweep: f64,
    },
    /// Close the subpath back to its start.
    Close,
}

/// Path data being built; points are given in source coordinates and mapped.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PathData {
    map: Map,
    d: String,
    segs: Vec<Seg>,
}

impl PathData {
    /// Empty data under `map`.
    pub(crate) fn new(map: Map) -> Self {
        Self {
            map,
            d: String::new(),
            segs: Vec::new(),
        }
    }
    /// True when nothing was drawn.
    pub(crate) fn is_empty(&self) -> bool {
        self.d.is_empty()
    }
    /// The `d` attribute.
    pub(crate) fn into_string(self) -> String {
        self.d
    }
    /// The pieces drawn, in sheet mm, in order.
    pub(crate) fn segs(&self) -> &[Seg] {
        &self.segs
    }

    fn cmd(&mut self, c: char, pts: &[DVec2]) -> &mut Self {
        if !self.d.is_empty() {
            self.d.push(' ');
        }
        self.d.push(c);
        for (i, p) in pts.iter().enumerate() {
            let q = self.map.pt(*p);
            let sep = if i == 0 { "" } else { " " };
            let _ = write!(self.d, "{sep}{},{}", Num(q.x), Num(q.y));
        }
        self
    }
    /// Start a subpath.
    pub(crate) fn move_to(&mut self, p: DVec2) -> &mut Self {
        self.segs.push(Seg::Move(self.map.pt(p)));
        self.cmd('M', &[p])
    }
    /// A straight piece.
    pub(crate) fn line_to(&mut self, p: DVec2) -> &mut Self {
        self.segs.push(Seg::Line(self.map.pt(p)));
        self.cmd('L', &[p])
    }
    /// A cubic Bézier piece.
    pub(crate) fn cubic_to(&mut self, c1: DVec2, c2: DVec2, p: DVec2) -> &mut Self {
        let m = self.map;
        self.segs.push(Seg::Cubic(m.pt(c1), m.pt(c2), m.pt(p)));
        self.cmd('C', &[c1, c2, p])
    }
    /// Close the subpath.
    pub(crate) fn close(&mut self) -> &mut Self {
        self.d.push_str(" Z");
        self.segs.push(Seg::Close);
        self
    }
    /// A separate straight stroke.
    pub(crate) fn segment(&mut self, a: DVec2, b: DVec2) -> &mut Self {
        self.move_to(a).line_to(b)
    }
    /// A closed polygon.
    pub(crate) fn polygon(&mut self, pts: &[DVec2]) -> &mut Self {
        self.polyline(pts);
        if pts.len() > 2 {
            self.close();
        }
        self
    }
    /// An axis-aligned rectangle.
    pub(crate) fn rect(&mut self, min: DVec2, max: DVec2) -> &mut Self {
        self.polygon(&[min, DVec2::new(max.x, min.y), max, DVec2::new(min.x, max.y)])
    }
    /// An open polyline (nothing for fewer than two points).
    pub(crate) fn polyline(&mut self, pts: &[DVec2]) -> &mut Self {
        if let [first, rest @ ..] = pts {
            if !rest.is_empty() {
                self.move_to(*first);
                rest.iter().for_each(|p| {
                    self.line_to(*p);
                });
            }
        }
        self
    }

    /// A circular arc as SVG arc commands, in pieces of at most a quarter turn (so the
    /// large-arc flag is always 0 and the output does not depend on flag conventions).
    /// Sweeps beyond a full turn are clamped; degenerate arcs draw nothing.
    pub(crate) fn arc(&mut self, arc: &Arc) -> &mut Self {
        let sweep = arc.sweep.clamp(-TAU, TAU);
        let ok = arc.radius.is_finite() && arc.radius > 0.0 && sweep.is_finite() && sweep != 0.0;
        if !ok || !arc.start.is_finite() || !arc.center.is_finite() {
            return self;
        }
        let n = (sweep.abs() / FRAC_PI_2).ceil().max(1.0) as usize;
        // Counter-clockwise in source coordinates is the positive SVG sweep only when y is
        // not flipped.
        let flag = u8::from((sweep > 0.0) != self.map.flip);
        let r = num(arc.radius);
        let piece = Arc { sweep, ..*arc };
        self.move_to(piece.eval(0.0));
        let turn = self.map.dir(DVec2::from_angle(piece.start));
        self.segs.push(Seg::Arc {
            center: self.map.pt(piece.center),
            radius: piece.radius,
            start: turn.y.atan2(turn.x),
            sweep: if self.map.flip { -sweep } else { sweep },
        });
        for i in 1..=n {
            let q = self.map.pt(piece.eval(i as f64 / n as f64));
            let _ = write!(self.d, " A{r},{r} 0 0 {flag} {},{}", Num(q.x), Num(q.y));
        }
        self
    }

    /// A full circle.
    pub(crate) fn circle(&mut self, center: DVec2, radius: f64) -> &mut Self {
        self.arc(&Arc {
            center,
            radius,
            start: 0.0,
            sweep: TAU,
        });
        if !self.d.is_empty() {
            self.close();
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn num_rounds_to_hundredths_without_negative_zero() {
        assert_eq!(num(1.23456), "1.23");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(0.1 + 0.2), "0.3");
        assert_eq!(num(841.0), "841");
        assert_eq!(num(-12.345_001), "-12.35");
        assert_eq!(num(f64::NAN), "0");
        assert_eq!(num(1e20), "100000000000000000000");
        assert_eq!(num(-0.05), "-0.05");
        assert_eq!(num(12.3), "12.3");
        assert_eq!(num(-7.005_000_1), "-7.01");
    }

    #[test]
    fn num_writes_the_shortest_decimal_of_the_rounded_value() {
        // As `format!` writes k/100, over every magnitude a sheet or a bad figure has.
        let shortest = |x: f64| {
            let r = (x * 100.0).round() / 100.0;
            if !r.is_finite() || r == 0.0 {
                "0".to_string()
            } else {
                format!("{r}")
            }
        };
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        for i in 0..200_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let unit = (state >> 11) as f64 / (1u64 << 53) as f64;
            let x = (unit - 0.5) * 10f64.powi(i % 19 - 3);
            assert_eq!(num(x), shortest(x), "{x:e}");
        }
        for x in [
            0.005,
            -0.005,
            0.015,
            9_999_999_999_999.99,
            1e13,
            -1e15,
            0.125,
            2.675,
        ] {
            assert_eq!(num(x), shortest(x), "{x:e}");
        }
    }

    #[test]
    fn figure_map_flips_y() {
        let m = Map::figure(DVec2::new(100.0, 200.0));
        assert_eq!(m.pt(DVec2::new(10.0, 20.0)), DVec2::new(110.0, 180.0));
        let mut d = PathData::new(m);
        d.segment(DVec2::ZERO, DVec2::new(1.006, -2.0));
        assert_eq!(d.into_string(), "M100,200 L101.01,202");
    }

    #[test]
    fn arcs_split_into_quarters_with_flag_by_orientation() {
        let a = Arc {
            center: DVec2::ZERO,
            radius: 10.0,
            start: 0.0,
            sweep: std::f64::consts::PI,
        };
        let mut d = PathData::new(Map::figure(DVec2::ZERO));
        d.arc(&a);
        assert_eq!(
            d.into_string(),
            "M10,0 A10,10 0 0 0 0,-10 A10,10 0 0 0 -10,0"
        );
        let mut d = PathData::new(Map::SHEET);
        d.arc(&Arc {
            sweep: f64::NAN,
            ..a
        });
        assert!(d.is_empty());
    }

    #[test]
    fn pieces_are_bounded() {
        assert_eq!(pieces(10.0, 2.5), 4);
        assert_eq!(pieces(1e300, 2.5), MAX_PIECES);
        assert_eq!(pieces(f64::NAN, 2.5), 0);
        assert_eq!(pieces(-3.0, 2.5), 0);
    }
}
