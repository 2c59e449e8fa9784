//! A drawn path as DXF entities: each subpath one entity — a LINE, a CIRCLE or an ARC where
//! it is one, else an LWPOLYLINE (arcs as bulges, Bézier pieces flattened within the drawing's
//! precision) — and a filled path one solid HATCH whose loops are its subpaths.

use super::Flip;
use crate::construct::Item;
use crate::geom::curve;
use crate::geom::{bezier_at, DVec2};
use crate::plate::path::Map;
use crate::plate::path::{pieces, Seg};
use acadrust::entities::{
    Arc, BoundaryEdge, BoundaryPath, Circle, EntityType, Hatch, HatchPattern, HatchPatternLine,
    HatchPatternType, Line, LwPolyline, LwVertex, PolylineEdge, Wipeout,
};
use acadrust::types::{Vector2, Vector3};
use std::f64::consts::{PI, TAU};

/// How far a polyline written for a Bézier piece may stray from it, mm: the SVG's own
/// precision (it writes coordinates to 0.01 mm), halved.
pub const CURVE_TOLERANCE_MM: f64 = 0.005;

/// A closed subpath's last vertex this near its first is the first (a circle's last quarter
/// ends where it began, up to rounding), mm: far below the drawing's 0.01 mm precision.
const SAME_POINT_MM: f64 = 1e-6;

/// A subpath as the DXF draws it, in DXF coordinates (mm, y up).
#[derive(Debug, Clone, PartialEq)]
pub(super) enum Drawn {
    /// One straight piece.
    Line(DVec2, DVec2),
    /// A full circle: centre and radius.
    Circle(DVec2, f64),
    /// One arc: centre, radius, start and end angle counter-clockwise, radians.
    Arc(DVec2, f64, f64, f64),
    /// Anything else: vertices with the bulge of the piece each starts, closed or not.
    Poly(Vec<(DVec2, f64)>, bool),
}

/// The subpaths of `segs` (sheet mm) as drawn in the DXF; a subpath that draws nothing
/// (a lone move) is left out.
pub(super) fn subpaths(segs: &[Seg], sheet: &Flip) -> Vec<Drawn> {
    let mut out = Vec::new();
    let mut rest = segs;
    while let Some((Seg::Move(start), tail)) = rest.split_first().map(|(s, t)| (*s, t)) {
        let end = tail
            .iter()
            .position(|s| matches!(s, Seg::Move(_)))
            .unwrap_or(tail.len());
        out.extend(drawn(start, &tail[..end], sheet));
        rest = &tail[end..];
    }
    out
}

/// One subpath from `start` (sheet mm) as drawn.
fn drawn(start: DVec2, segs: &[Seg], sheet: &Flip) -> Option<Drawn> {
    let full = |sweep: f64| sweep.abs() >= TAU * (1.0 - 1e-12);
    match segs {
        [] | [Seg::Close] => None,
        [Seg::Line(b)] => Some(Drawn::Line(sheet.pt(start), sheet.pt(*b))),
        [Seg::Arc {
            center,
            radius,
            sweep,
            ..
        }]
        | [Seg::Arc {
            center,
            radius,
            sweep,
            ..
        }, Seg::Close]
            if full(*sweep) =>
        {
            Some(Drawn::Circle(sheet.pt(*center), *radius))
        }
        [Seg::Arc {
            center,
            radius,
            start: a0,
            sweep,
        }] => {
            // On the DXF's y up every angle turns the other way.
            let (a, b) = (-a0, -a0 - sweep);
            let (lo, hi) = if b > a { (a, b) } else { (b, a) };
            Some(Drawn::Arc(
                sheet.pt(*center),
                *radius,
                lo.rem_euclid(TAU),
                hi.rem_euclid(TAU),
            ))
        }
        _ => Some(polyline(start, segs, sheet)),
    }
}

/// A subpath as polyline vertices with bulges (an arc in pieces of at most a half turn).
fn polyline(start: DVec2, segs: &[Seg], sheet: &Flip) -> Drawn {
    let mut verts = vec![(sheet.pt(start), 0.0)];
    let mut at = start;
    let mut closed = false;
    for seg in segs {
        match *seg {
            Seg::Move(_) => {}
            Seg::Line(p) => {
                verts.push((sheet.pt(p), 0.0));
                at = p;
            }
            Seg::Cubic(c1, c2, p) => {
                let piece = [c1, c2, p];
                let n = flat_pieces(at, &piece);
                for i in 1..=n {
                    let q = bezier_at(at, &piece, i as f64 / n as f64);
                    verts.push((sheet.pt(q), 0.0));
                }
                at = p;
            }
            Seg::Arc {
                center,
                radius,
                start: a0,
                sweep,
            } => {
                let n = (sweep.abs() / PI).ceil().max(1.0) as usize;
                let step = sweep / n as f64;
                for i in 1..=n {
                    if let Some(last) = verts.last_mut() {
                        // The sheet's clockwise is the DXF's counter-clockwise.
                        last.1 = (-step / 4.0).tan();
                    }
                    let q = center + DVec2::from_angle(a0 + step * i as f64) * radius;
                    verts.push((sheet.pt(q), 0.0));
                    at = q;
                }
            }
            Seg::Close => closed = true,
        }
    }
    if closed && verts.len() > 2 {
        let (first, last) = (verts[0].0, verts[verts.len() - 1].0);
        if first.distance(last) <= SAME_POINT_MM {
            verts.pop();
        }
    }
    Drawn::Poly(verts, closed)
}

/// Pieces a cubic from `start` is cut into so that its chords stray from it by at most
/// [`CURVE_TOLERANCE_MM`]: Wang's bound, √(¾·M / tol) with M the larger second difference
/// of its control points (bounded by [`pieces`]' cap).
fn flat_pieces(start: DVec2, p: &curve::Piece) -> usize {
    let m = (start - 2.0 * p[0] + p[1])
        .length()
        .max((p[0] - 2.0 * p[1] + p[2]).length());
    let n = (0.75 * m / CURVE_TOLERANCE_MM).sqrt().ceil();
    pieces(n.max(1.0), 1.0).max(1)
}

/// The entity of a stroked subpath.
pub(super) fn stroke_entity(d: Drawn) -> EntityType {
    let v3 = |p: DVec2| Vector3::new(p.x, p.y, 0.0);
    match d {
        Drawn::Line(a, b) => EntityType::Line(Line::from_points(v3(a), v3(b))),
        Drawn::Circle(c, r) => EntityType::Circle(Circle::from_center_radius(v3(c), r)),
        Drawn::Arc(c, r, a0, a1) => {
            EntityType::Arc(Arc::from_center_radius_angles(v3(c), r, a0, a1))
        }
        Drawn::Poly(verts, closed) => {
            let mut pl = LwPolyline::new();
            for (p, bulge) in verts {
                pl.add_vertex(LwVertex::with_bulge(Vector2::new(p.x, p.y), bulge));
            }
            pl.is_closed = closed;
            EntityType::LwPolyline(pl)
        }
    }
}

/// One solid HATCH filling `subpaths` (each a closed loop).
pub(super) fn fill_entity(subpaths: Vec<Drawn>) -> EntityType {
    let mut hatch = Hatch::solid();
    for d in subpaths {
        hatch.add_path(loop_path(loop_vertices(d)));
    }
    EntityType::Hatch(Box::new(hatch))
}

/// A HATCH's boundary: one closed polyline loop through `vertices` (DXF mm, each with the
/// bulge of the piece it starts).
fn loop_path(vertices: impl IntoIterator<Item = (DVec2, f64)>) -> BoundaryPath {
    let mut edge = PolylineEdge::new(Vec::new(), true);
    for (p, bulge) in vertices {
        edge.add_vertex(Vector2::new(p.x, p.y), bulge);
    }
    let mut path = BoundaryPath::external();
    path.add_edge(BoundaryEdge::Polyline(edge));
    path
}

/// A hatched region as the sheet draws it: its outline (sheet mm, y down) and its lines'
/// spacing (mm) and direction on the sheet.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Hatching {
    outline: Vec<DVec2>,
    spacing: f64,
    along: DVec2,
}

impl Hatching {
    /// The region of a hatching step drawn under `map`; `None` for any other item.
    pub(super) fn of(item: &Item, map: Map) -> Option<Self> {
        let Item::Hatching {
            outline,
            spacing,
            angle,
        } = item
        else {
            return None;
        };
        // The strokes run at the angle, counterclockwise from the figure's +x.
        Some(Self {
            outline: outline.iter().map(|p| map.pt(*p)).collect(),
            spacing: *spacing,
            along: map.dir(DVec2::from_angle(*angle)),
        })
    }
}

/// A hatched region as one HATCH: a user-defined pattern of one family of continuous lines
/// at the region's angle and spacing (AutoCAD's "User defined", KOMPAS's hatch by angle and
/// step), on one polyline loop, the outline.
pub(super) fn hatching_entity(h: &Hatching, flip: &Flip) -> EntityType {
    let along = DVec2::new(h.along.x, -h.along.y);
    let angle = along.to_angle().rem_euclid(PI);
    let across = DVec2::from_angle(angle).perp() * h.spacing;
    let mut pattern = HatchPattern::new(USER_PATTERN);
    pattern.add_line(HatchPatternLine {
        angle,
        base_point: Vector2::new(0.0, 0.0),
        offset: Vector2::new(across.x, across.y),
        dash_lengths: Vec::new(),
    });
    let mut hatch = Hatch::with_pattern(pattern);
    hatch.pattern_type = HatchPatternType::UserDefined;
    hatch.pattern_angle = angle;
    // A user-defined pattern's "scale" is its spacing (group code 41).
    hatch.pattern_scale = h.spacing;
    hatch.add_path(loop_path(h.outline.iter().map(|p| (flip.pt(*p), 0.0))));
    EntityType::Hatch(Box::new(hatch))
}

/// Sides of the polygon a pair's circle is masked by, its vertices on the circle: the
/// chord's sag, r·(1 − cos(π/n)), is 0,013 mm for the 1,5 mm pair.
const WIPEOUT_SIDES: usize = 24;

/// The white inside of a closed subpath the SVG fills white (a pair's circle, a slider's
/// block): a polygonal WIPEOUT on it, which covers what lies under it as the SVG's fill
/// does (a CAD program draws entities in the order they were added, and the pairs are
/// added after the links). `None` for an open subpath or a curved one that is not a circle.
pub(super) fn wipeout_entity(d: &Drawn) -> Option<EntityType> {
    let mut polygon: Vec<DVec2> = match d {
        Drawn::Circle(c, r) => (0..WIPEOUT_SIDES)
            .map(|k| *c + DVec2::from_angle(TAU * k as f64 / WIPEOUT_SIDES as f64) * *r)
            .collect(),
        Drawn::Poly(verts, true) if verts.iter().all(|(_, bulge)| *bulge == 0.0) => {
            verts.iter().map(|(p, _)| *p).collect()
        }
        _ => return None,
    };
    // The boundary closed by its first vertex, as AutoCAD writes a polygonal clip.
    polygon.push(polygon[0]);
    let vertices: Vec<Vector2> = polygon.iter().map(|p| Vector2::new(p.x, p.y)).collect();
    Some(EntityType::Wipeout(Wipeout::polygonal(&vertices, 0.0)))
}

/// The name AutoCAD gives a user-defined hatch pattern.
pub const USER_PATTERN: &str = "_USER";

/// A subpath as a loop of vertices with bulges.
fn loop_vertices(d: Drawn) -> Vec<(DVec2, f64)> {
    match d {
        Drawn::Line(a, b) => vec![(a, 0.0), (b, 0.0)],
        Drawn::Circle(c, r) => vec![(c + DVec2::X * r, 1.0), (c - DVec2::X * r, 1.0)],
        Drawn::Arc(c, r, a0, a1) => {
            let sweep = (a1 - a0).rem_euclid(TAU);
            vec![
                (c + DVec2::from_angle(a0) * r, (sweep / 4.0).tan()),
                (c + DVec2::from_angle(a1) * r, 0.0),
            ]
        }
        Drawn::Poly(verts, _) => verts,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::Arc as GeomArc;
    use crate::plate::path::{Map, PathData};

    fn sheet() -> Flip {
        Flip { height: 100.0 }
    }

    #[test]
    fn lines_circles_and_arcs_are_their_own_entities_with_y_up() {
        let mut d = PathData::new(Map::figure(DVec2::new(10.0, 50.0)));
        d.segment(DVec2::ZERO, DVec2::new(5.0, 5.0));
        d.circle(DVec2::new(1.0, 2.0), 3.0);
        d.arc(&GeomArc {
            center: DVec2::ZERO,
            radius: 4.0,
            start: 0.0,
            sweep: -PI / 2.0,
        });
        let drawn = subpaths(d.segs(), &sheet());
        assert_eq!(drawn.len(), 3);
        assert_eq!(
            drawn[0],
            Drawn::Line(DVec2::new(10.0, 50.0), DVec2::new(15.0, 55.0))
        );
        assert_eq!(drawn[1], Drawn::Circle(DVec2::new(11.0, 52.0), 3.0));
        // A figure arc clockwise from 0 to −90°: counter-clockwise from 270° to 360° (0).
        let Drawn::Arc(c, r, a0, a1) = drawn[2] else {
            panic!("{:?}", drawn[2]);
        };
        assert_eq!((c, r), (DVec2::new(10.0, 50.0), 4.0));
        assert!(
            (a0 - 1.5 * PI).abs() < 1e-12 && a1.abs() < 1e-12,
            "{a0} {a1}"
        );
    }

    #[test]
    fn curves_flatten_within_the_tolerance() {
        let mut d = PathData::new(Map::SHEET);
        let (a, c1, c2, b) = (
            DVec2::ZERO,
            DVec2::new(10.0, 40.0),
            DVec2::new(50.0, -30.0),
            DVec2::new(60.0, 0.0),
        );
        d.move_to(a).cubic_to(c1, c2, b);
        let Drawn::Poly(verts, false) = &subpaths(d.segs(), &sheet())[0] else {
            panic!("a polyline");
        };
        // Every point of the curve lies within the tolerance of the chords.
        let pts: Vec<DVec2> = verts.iter().map(|(p, _)| *p).collect();
        for i in 0..=1000 {
            let q = sheet().pt(bezier_at(a, &[c1, c2, b], f64::from(i) / 1000.0));
            let near = pts
                .windows(2)
                .map(|w| crate::geom::Segment::new(w[0], w[1]).distance_to(q))
                .fold(f64::INFINITY, f64::min);
            assert!(near <= CURVE_TOLERANCE_MM, "{i}: {near}");
        }
        assert!(pts.len() < 200, "{}", pts.len());
    }

    #[test]
    fn a_filled_circle_is_a_loop_of_two_half_turns() {
        let mut d = PathData::new(Map::SHEET);
        d.circle(DVec2::new(5.0, 5.0), 1.0);
        d.move_to(DVec2::ZERO)
            .line_to(DVec2::X)
            .line_to(DVec2::Y)
            .close();
        let drawn = subpaths(d.segs(), &sheet());
        let verts = loop_vertices(drawn[0].clone());
        assert_eq!(verts.len(), 2);
        assert!(verts.iter().all(|(_, b)| *b == 1.0));
        assert_eq!(
            drawn[1],
            Drawn::Poly(
                vec![
                    (DVec2::new(0.0, 100.0), 0.0),
                    (DVec2::new(1.0, 100.0), 0.0),
                    (DVec2::new(0.0, 99.0), 0.0)
                ],
                true
            )
        );
    }
}
