//! The DXF side of the checks: a DXF read back by `acadrust`, and its comparison with the SVG
//! of the same sheet ([`super::svg`]): the count of entities per layer, every text's runs,
//! every item's coordinates.

use super::svg::{Drawn, Subpath};
use acadrust::entities::{EntityType, TextHorizontalAlignment};
use acadrust::{CadDocument, DxfReader};
use glam::DVec2;
use std::collections::BTreeMap;
use tmm::geom::{polygon_contains, Segment};
use tmm::plate::text::CAP_HEIGHT_EM;
use tmm::plate::DxfLayer;
use tmm::scale::Lang;

/// How far a DXF coordinate may lie from the SVG's, mm (the acceptance of issue 48).
pub const COORD_MM: f64 = 0.01;

/// What the SVG's own rounding (0.005 mm in x and in y) adds to the point of a text it turns
/// about another point: the turned offset between two rounded numbers, mm.
const TURNED_ROUNDING_MM: f64 = 0.005 * std::f64::consts::SQRT_2;

/// A DXF read back.
pub fn read(bytes: &[u8]) -> CadDocument {
    DxfReader::from_reader(std::io::Cursor::new(bytes.to_vec()))
        .and_then(|r| r.read())
        .expect("the DXF reads back")
}

/// The DXF's entities by layer name, in order.
fn by_layer(doc: &CadDocument) -> BTreeMap<String, Vec<&EntityType>> {
    let mut out: BTreeMap<String, Vec<&EntityType>> = BTreeMap::new();
    for e in doc.entities() {
        out.entry(e.common().layer.clone()).or_default().push(e);
    }
    out
}

/// How many entities the DXF writes for an SVG item.
fn expected_count(d: &Drawn) -> usize {
    match d {
        Drawn::Stroke(subs) => subs.len(),
        Drawn::White(subs) => subs.len() + subs.iter().filter(|s| masked(s)).count(),
        Drawn::Fill(subs) => usize::from(!subs.is_empty()),
        Drawn::Hatching(_) => 1,
        Drawn::Text { runs, .. } => runs.len(),
    }
}

/// The sheet point (y down) of a DXF point (y up).
fn sheet(p: DVec2, height: f64) -> DVec2 {
    DVec2::new(p.x, height - p.y)
}

fn near(a: DVec2, b: DVec2) -> bool {
    a.distance(b) <= COORD_MM
}

/// Compare the DXF `doc` of a sheet `height` mm high with the SVG's `items`: the same count
/// of entities per layer, each subpath's points on its entity, each text's runs intact at
/// their place. The first difference, described.
pub fn compare(
    doc: &CadDocument,
    items: &[(DxfLayer, Drawn)],
    lang: Lang,
    height: f64,
) -> Result<(), String> {
    let layers = by_layer(doc);
    let mut want: BTreeMap<String, usize> = BTreeMap::new();
    for (layer, d) in items {
        *want.entry(layer.name(lang).to_string()).or_default() += expected_count(d);
    }
    want.retain(|_, n| *n > 0);
    let have: BTreeMap<String, usize> = layers.iter().map(|(k, v)| (k.clone(), v.len())).collect();
    if want != have {
        return Err(format!("entities per layer: SVG {want:?}, DXF {have:?}"));
    }
    let mut next: BTreeMap<String, usize> = BTreeMap::new();
    for (layer, d) in items {
        let name = layer.name(lang).to_string();
        let start = next.entry(name.clone()).or_default();
        let n = expected_count(d);
        let mine = &layers[&name][*start..*start + n];
        *start += n;
        match d {
            Drawn::Stroke(subs) => {
                for (s, e) in subs.iter().zip(mine) {
                    stroke(s, e, height).map_err(|m| format!("{name}: {m}"))?;
                }
            }
            Drawn::White(subs) => {
                let mut next = mine.iter();
                for s in subs {
                    if masked(s) {
                        let e = next.next().expect("counted");
                        wipeout(s, e, height).map_err(|m| format!("{name}: {m}"))?;
                    }
                    let e = next.next().expect("counted");
                    stroke(s, e, height).map_err(|m| format!("{name}: {m}"))?;
                }
            }
            Drawn::Fill(subs) if n > 0 => fill(subs, mine[0], height)?,
            Drawn::Fill(_) => {}
            Drawn::Hatching(strokes) => {
                hatching(strokes, mine[0], height).map_err(|m| format!("{name}: {m}"))?
            }
            Drawn::Text { at, rotate, runs } => text(*at, *rotate, runs, mine, height)?,
        }
    }
    Ok(())
}

/// A stroked subpath against its entity: a LINE's ends, a CIRCLE's centre and radius, an
/// ARC's ends, a polyline's first (and, open, last) vertex, and every vertex of one of
/// straight pieces.
fn stroke(s: &Subpath, e: &EntityType, height: f64) -> Result<(), String> {
    let (first, last) = (s.points[0], s.points[s.points.len() - 1]);
    let ok = match e {
        EntityType::Line(l) => {
            let (a, b) = (
                sheet(DVec2::new(l.start.x, l.start.y), height),
                sheet(DVec2::new(l.end.x, l.end.y), height),
            );
            s.points.len() == 2 && near(a, first) && near(b, last)
        }
        EntityType::Circle(c) => {
            // The SVG's circle: four quarters from its rightmost point, whose mean is the centre.
            let ends = &s.points[1..];
            let centre = ends.iter().copied().sum::<DVec2>() / ends.len() as f64;
            let mine = sheet(DVec2::new(c.center.x, c.center.y), height);
            s.arcs_only && near(mine, centre) && (c.radius - s.radius).abs() <= COORD_MM
        }
        EntityType::Arc(a) => {
            let end = |t: f64| {
                let p = DVec2::new(a.center.x, a.center.y) + DVec2::from_angle(t) * a.radius;
                sheet(p, height)
            };
            let (p, q) = (end(a.start_angle), end(a.end_angle));
            !s.closed && ((near(p, first) && near(q, last)) || (near(p, last) && near(q, first)))
        }
        EntityType::LwPolyline(pl) => {
            let v = |k: usize| {
                let l = pl.vertices[k].location;
                sheet(DVec2::new(l.x, l.y), height)
            };
            let n = pl.vertices.len();
            // A closed outline that returns to its start by a piece of its own is written
            // without that last, repeated vertex.
            let mut points = s.points.clone();
            if s.closed && points.len() > 2 && near(first, last) {
                points.pop();
            }
            let every = !s.straight
                || (points.len() == n && points.iter().enumerate().all(|(k, p)| near(v(k), *p)));
            n >= 2
                && pl.is_closed == s.closed
                && near(v(0), first)
                && (s.closed || near(v(n - 1), last))
                && every
        }
        other => {
            let kind = format!("{other:?}");
            let kind = kind.split('(').next().unwrap_or_default().to_string();
            return Err(format!("{kind} for a stroked path"));
        }
    };
    match ok {
        true => Ok(()),
        false => Err(format!("{e:?} is not the SVG's {s:?}")),
    }
}

/// Whether the DXF masks a subpath the SVG fills white: a full circle, or closed of straight
/// pieces.
fn masked(s: &Subpath) -> bool {
    s.arcs_only || (s.closed && s.straight)
}

/// A white subpath against its WIPEOUT: a circle's every boundary vertex on the circle, a
/// polygon's boundary its vertices.
fn wipeout(s: &Subpath, e: &EntityType, height: f64) -> Result<(), String> {
    let EntityType::Wipeout(w) = e else {
        return Err(format!("{e:?} for the white inside of {s:?}"));
    };
    let mut boundary: Vec<DVec2> = w
        .world_boundary_vertices()
        .iter()
        .map(|v| sheet(DVec2::new(v.x, v.y), height))
        .collect();
    if boundary.len() > 1 && near(boundary[0], boundary[boundary.len() - 1]) {
        boundary.pop();
    }
    let ok = if s.arcs_only {
        let ends = &s.points[1..];
        let centre = ends.iter().copied().sum::<DVec2>() / ends.len() as f64;
        boundary.len() >= 3
            && boundary
                .iter()
                .all(|p| (p.distance(centre) - s.radius).abs() <= COORD_MM)
    } else {
        let mut points = s.points.clone();
        if points.len() > 1 && near(points[0], points[points.len() - 1]) {
            points.pop();
        }
        points.len() == boundary.len() && points.iter().zip(&boundary).all(|(a, b)| near(*a, *b))
    };
    match ok {
        true => Ok(()),
        false => Err(format!("WIPEOUT {boundary:?} is not the inside of {s:?}")),
    }
}

/// A filled path against its HATCH: a loop per subpath, each from the subpath's start.
fn fill(subs: &[Subpath], e: &EntityType, height: f64) -> Result<(), String> {
    let EntityType::Hatch(h) = e else {
        return Err(format!("{e:?} for a filled path"));
    };
    if !h.is_solid || h.paths.len() != subs.len() {
        return Err(format!("{h:?} is not a solid fill of {subs:?}"));
    }
    for (path, s) in h.paths.iter().zip(subs) {
        let first = path.edges.first().and_then(|edge| match edge {
            acadrust::entities::BoundaryEdge::Polyline(p) => p.vertices.first(),
            _ => None,
        });
        let Some(v) = first else {
            return Err(format!("a loop of {h:?} is no polyline"));
        };
        if !near(sheet(DVec2::new(v.x, v.y), height), s.points[0]) {
            return Err(format!(
                "loop starts at {v:?}, the SVG's at {:?}",
                s.points[0]
            ));
        }
    }
    Ok(())
}

/// The strokes the SVG draws for a hatched region against its HATCH: a pattern of one family
/// of continuous lines on one loop; every stroke along the pattern's lines, both its ends in
/// the loop (or on it), and the strokes one pattern spacing apart (or a whole number of
/// spacings, where the region narrows between them).
fn hatching(strokes: &[Subpath], e: &EntityType, height: f64) -> Result<(), String> {
    let EntityType::Hatch(h) = e else {
        return Err(format!("{e:?} for a hatching"));
    };
    let [line] = &h.pattern.lines[..] else {
        return Err(format!("{h:?} is not one family of lines"));
    };
    if h.is_solid || !line.dash_lengths.is_empty() || h.paths.len() != 1 {
        return Err(format!("{h:?} is not a hatching of one loop"));
    }
    let outline: Vec<DVec2> = h.paths[0]
        .edges
        .iter()
        .flat_map(|edge| match edge {
            acadrust::entities::BoundaryEdge::Polyline(p) => p.vertices.clone(),
            _ => Vec::new(),
        })
        .map(|v| sheet(DVec2::new(v.x, v.y), height))
        .collect();
    // On the sheet (y down) the pattern's direction and its normal.
    let u = DVec2::new(line.angle.cos(), -line.angle.sin());
    let spacing = DVec2::new(line.offset.x, line.offset.y).length();
    let mut across: Vec<f64> = Vec::new();
    for s in strokes {
        let [a, b] = s.points[..] else {
            return Err(format!("a hatch stroke {s:?} is not one straight piece"));
        };
        // How far b lies off the pattern's line through a, mm: the SVG's rounding of both
        // ends at most.
        let off_line = (b - a).perp_dot(u).abs();
        let within = |p: DVec2| polygon_contains(&outline, p) || on_outline(&outline, p);
        if off_line > 2.0 * COORD_MM || !within(a) || !within(b) {
            return Err(format!(
                "stroke {a}–{b} is not a line of {h:?} inside its loop"
            ));
        }
        across.push(a.dot(u.perp()));
    }
    // Two pieces of one line (an outline that is not convex cuts it) lie 0 spacings apart;
    // neighbouring lines one, or a whole number where the region narrows between them — and
    // somewhere exactly one, when there are two lines or more.
    across.sort_by(f64::total_cmp);
    let mut neighbours = false;
    for w in across.windows(2) {
        let k = (w[1] - w[0]) / spacing;
        if (k - k.round()).abs() * spacing > 2.0 * COORD_MM {
            return Err(format!(
                "strokes {:.3} mm apart, the pattern's spacing {spacing:.3} mm",
                w[1] - w[0]
            ));
        }
        neighbours |= k.round() == 1.0;
    }
    let lines = across
        .windows(2)
        .filter(|w| w[1] - w[0] > 2.0 * COORD_MM)
        .count()
        + 1;
    match neighbours || lines < 2 {
        true => Ok(()),
        false => Err(format!(
            "no two strokes one spacing ({spacing:.3} mm) apart"
        )),
    }
}

/// Whether `p` lies on an edge of the polygon `outline`, to [`COORD_MM`].
fn on_outline(outline: &[DVec2], p: DVec2) -> bool {
    let n = outline.len();
    (0..n).any(|i| Segment::new(outline[i], outline[(i + 1) % n]).distance_to(p) <= COORD_MM)
}

/// A text against its TEXTs: one per run, each run's characters and height, the first at the
/// text's point (turned as the SVG turns it).
fn text(
    at: DVec2,
    rotate: Option<(f64, DVec2)>,
    runs: &[(String, f64)],
    mine: &[&EntityType],
    height: f64,
) -> Result<(), String> {
    for (k, ((chars, size), e)) in runs.iter().zip(mine).enumerate() {
        let EntityType::Text(t) = e else {
            return Err(format!("{e:?} for the run {chars:?}"));
        };
        if t.value != *chars {
            return Err(format!("TEXT {:?}, the SVG's run {chars:?}", t.value));
        }
        if (t.height - size * CAP_HEIGHT_EM).abs() > COORD_MM {
            return Err(format!(
                "{chars:?}: height {}, SVG font size {size}",
                t.height
            ));
        }
        if k > 0 {
            continue;
        }
        let point = match t.horizontal_alignment {
            TextHorizontalAlignment::Left => t.insertion_point,
            _ => t.alignment_point.unwrap_or(t.insertion_point),
        };
        let mine = sheet(DVec2::new(point.x, point.y), height);
        let (svg, slack) = match rotate {
            Some((deg, about)) if about != at => (
                about + DVec2::from_angle(deg.to_radians()).rotate(at - about),
                TURNED_ROUNDING_MM,
            ),
            _ => (at, 0.0),
        };
        if mine.distance(svg) > COORD_MM + slack {
            return Err(format!("{chars:?} at {mine:?}, the SVG's at {svg:?}"));
        }
    }
    Ok(())
}
