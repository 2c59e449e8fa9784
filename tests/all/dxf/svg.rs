//! The SVG side of the DXF checks: what a sheet's SVG draws, read from its text (one element
//! a line, as the writer lays it out), each item with the layer the DXF must put it on —
//! worked out here from the group it is in and the plate model (a step's role, a label's
//! steps), not by the DXF writer.

use glam::DVec2;
use tmm::construct::{Item, Role};
use tmm::plate::{layout, DxfLayer, Plate};

/// A subpath of an SVG path: its points (the move, then each piece's end) and whether it is
/// closed and a full circle.
#[derive(Debug, Clone, PartialEq)]
pub struct Subpath {
    /// The move's point, then each piece's end, sheet mm.
    pub points: Vec<DVec2>,
    /// Ends with `Z`.
    pub closed: bool,
    /// Arcs only, back to its start: a full circle (closed by `Z` or not).
    pub arcs_only: bool,
    /// Its arcs' radius (of the last one), mm.
    pub radius: f64,
    /// Straight pieces only: every point is a vertex of its polyline.
    pub straight: bool,
}

/// What the SVG draws, in order.
#[derive(Debug, Clone, PartialEq)]
pub enum Drawn {
    /// A stroked path: one DXF entity per subpath.
    Stroke(Vec<Subpath>),
    /// A stroked path filled white (a pair, a slider's block): per subpath one entity, and
    /// before it a WIPEOUT when it is closed and a full circle or of straight pieces.
    White(Vec<Subpath>),
    /// A path filled black: one solid HATCH, a loop per subpath.
    Fill(Vec<Subpath>),
    /// The strokes of a hatched region (a step the plate model holds as a hatching): one
    /// patterned HATCH.
    Hatching(Vec<Subpath>),
    /// A text: its point before rotation, its rotation (degrees, about the point), its runs
    /// (the characters, the font size).
    Text {
        /// `x`, `y`.
        at: DVec2,
        /// The rotation and the point it turns about.
        rotate: Option<(f64, DVec2)>,
        /// Each run's characters and font size, mm.
        runs: Vec<(String, f64)>,
    },
}

/// Every item the SVG of `plate` draws with the layer it belongs on, in the SVG's order.
pub fn items(plate: &Plate, svg: &str) -> Vec<(DxfLayer, Drawn)> {
    let laid = layout(plate);
    let mut groups: Vec<String> = Vec::new();
    let mut out = Vec::new();
    let mut label_texts = std::collections::BTreeMap::<usize, usize>::new();
    for line in svg.lines() {
        if let Some(id) = line.strip_prefix("<g id=\"") {
            groups.push(id.trim_end_matches("\">").to_string());
            continue;
        }
        if line == "</g>" {
            groups.pop();
            continue;
        }
        let Some(group) = groups.last() else {
            continue;
        };
        let drawn = if line.starts_with("<path ") {
            path(line)
        } else if line.starts_with("<text ") {
            text(line)
        } else {
            continue;
        };
        let layer = layer_of(plate, &laid, group, &drawn, &mut label_texts);
        let drawn = match drawn {
            Drawn::Stroke(subs) if is_hatching(plate, group) => Drawn::Hatching(subs),
            d => d,
        };
        out.push((layer, drawn));
    }
    out
}

/// The layer of an item in `group`: the frame's, a step's role's, a label's (a dimension's
/// text with its dimension), or the texts'.
fn layer_of(
    plate: &Plate,
    laid: &tmm::plate::Layout,
    group: &str,
    drawn: &Drawn,
    label_texts: &mut std::collections::BTreeMap<usize, usize>,
) -> DxfLayer {
    if group == "sheet" || group == "title-block" {
        return DxfLayer::Frame;
    }
    let Some(rest) = group.strip_prefix("view-") else {
        return DxfLayer::Text;
    };
    let (k, rest) = rest.split_once('-').expect("view-K-…");
    let k: usize = k.parse().expect("a view's index");
    let view = &plate.views[k];
    let role_of = |id: u32| {
        view.figure
            .steps
            .iter()
            .find(|s| s.id.0 == id)
            .map(|s| s.role)
            .expect("the group's step")
    };
    if let Some(id) = rest.strip_prefix("step-") {
        return DxfLayer::Role(role_of(id.parse().expect("a step id")));
    }
    let Some(tail) = rest.strip_prefix("labels") else {
        return DxfLayer::Text;
    };
    // The n-th label of the view (1-based): its leader's group names it, its text is the
    // next text of the labels group.
    let n = match tail.strip_prefix("-leader-") {
        Some(n) => n.parse::<usize>().expect("a leader's number"),
        None if matches!(drawn, Drawn::Text { .. }) => {
            let count = label_texts.entry(k).or_insert(0);
            *count += 1;
            *count
        }
        None => panic!("a path in {group} outside a leader"),
    };
    let label = laid
        .labels
        .iter()
        .filter(|l| l.view == k)
        .nth(n - 1)
        .expect("the label");
    let dimension = !label.steps.is_empty()
        && label
            .steps
            .iter()
            .all(|id| role_of(id.0) == Role::Dimension);
    if dimension {
        DxfLayer::Role(Role::Dimension)
    } else {
        DxfLayer::Text
    }
}

/// Whether `group` is a step's whose item the plate model holds as a hatching.
fn is_hatching(plate: &Plate, group: &str) -> bool {
    let Some((k, id)) = group
        .strip_prefix("view-")
        .and_then(|r| r.split_once("-step-"))
    else {
        return false;
    };
    let (Ok(k), Ok(id)) = (k.parse::<usize>(), id.parse::<u32>()) else {
        return false;
    };
    plate.views[k]
        .figure
        .steps
        .iter()
        .any(|s| s.id.0 == id && matches!(s.item, Item::Hatching { .. }))
}

/// The value of attribute `name` on the element's line.
fn attr<'a>(line: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let start = line.find(&key)? + key.len();
    let end = line[start..].find('"')?;
    Some(&line[start..start + end])
}

fn pair(s: &str) -> DVec2 {
    let (x, y) = s.split_once(',').expect("x,y");
    DVec2::new(x.parse().expect("x"), y.parse().expect("y"))
}

/// A `<path>`: its subpaths, stroked or filled.
fn path(line: &str) -> Drawn {
    let d = attr(line, "d").expect("d");
    let mut subpaths: Vec<Subpath> = Vec::new();
    let mut tokens = d.split_whitespace();
    while let Some(tok) = tokens.next() {
        let (cmd, rest) = tok.split_at(1);
        match cmd {
            "M" => subpaths.push(Subpath {
                points: vec![pair(rest)],
                closed: false,
                arcs_only: true,
                radius: 0.0,
                straight: true,
            }),
            "L" | "C" | "A" => {
                let end = match cmd {
                    "L" => pair(rest),
                    "C" => {
                        tokens.next();
                        pair(tokens.next().expect("C's end"))
                    }
                    _ => {
                        let r = pair(rest).x;
                        let end = tokens.nth(3).expect("A's end");
                        subpaths.last_mut().expect("a subpath").radius = r;
                        pair(end)
                    }
                };
                let sub = subpaths.last_mut().expect("a subpath");
                sub.arcs_only &= cmd == "A";
                sub.straight &= cmd == "L";
                sub.points.push(end);
            }
            "Z" => subpaths.last_mut().expect("a subpath").closed = true,
            other => panic!("path command {other}"),
        }
    }
    // A lone move draws nothing.
    subpaths.retain(|s| s.points.len() > 1);
    for s in &mut subpaths {
        let back = s.points.first() == s.points.last();
        s.arcs_only &= back;
    }
    match attr(line, "fill") {
        Some("#000") => Drawn::Fill(subpaths),
        Some("#fff") => Drawn::White(subpaths),
        _ => Drawn::Stroke(subpaths),
    }
}

/// XML's escapes undone.
fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// A `<text>`: its point, rotation and runs (the bare text and each `<tspan>`).
fn text(line: &str) -> Drawn {
    let num = |name: &str| -> f64 { attr(line, name).expect(name).parse().expect(name) };
    let at = DVec2::new(num("x"), num("y"));
    let size = num("font-size");
    let rotate = attr(line, "transform").map(|t| {
        let inner = t.trim_start_matches("rotate(").trim_end_matches(')');
        let v: Vec<f64> = inner
            .split_whitespace()
            .map(|x| x.parse().expect("rotate's number"))
            .collect();
        (v[0], DVec2::new(v[1], v[2]))
    });
    let open = line.find('>').expect("<text …>") + 1;
    let body = line[open..].strip_suffix("</text>").expect("</text>");
    let mut runs = Vec::new();
    let mut rest = body;
    while !rest.is_empty() {
        match rest.strip_prefix("<tspan") {
            Some(span) => {
                let close = span.find('>').expect("<tspan …>");
                let tag = &span[..close];
                let run_size = attr(tag, "font-size").map_or(size, |s| s.parse().expect("size"));
                let end = span.find("</tspan>").expect("</tspan>");
                runs.push((unescape(&span[close + 1..end]), run_size));
                rest = &span[end + "</tspan>".len()..];
            }
            None => {
                let end = rest.find("<tspan").unwrap_or(rest.len());
                runs.push((unescape(&rest[..end]), size));
                rest = &rest[end..];
            }
        }
    }
    Drawn::Text { at, rotate, runs }
}
