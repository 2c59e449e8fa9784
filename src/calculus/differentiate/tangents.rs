//! The method of tangents (Fig. 8): a draughtsman's tangent at every node (one per piece at a
//! break), a ray from the pole parallel to each, the node points and the curve through them.

use super::*;

/// Differentiate `st.src` by the method of tangents. The tangent at a node is the
/// draughtsman's tangent: the line through the node parallel to the chord joining its two
/// neighbouring nodes (wrapping for a periodic diagram; at the ends of a non-periodic one,
/// the adjacent chord). It is drawn (thin) through the node; then, as for chords, a ray from
/// P parallel to it cuts the ordinate axis, the cut is projected to the node's ordinate and
/// the result point marked; the smooth curve goes through the node points. The scale of
/// `rec` must be μ_y/(H·μ_x).
///
/// # Errors
/// As for the method of chords.
pub(super) fn tangents(figs: &mut Figures<'_>, st: &Start) -> Result<Derivative, CalculusError> {
    let (n, run) = (st.n, st.run);
    let (src, layout) = (st.src, st.layout);
    let lines = tangent_lines(st);
    let given = figs.given();
    let tangents: Vec<StepId> = lines
        .iter()
        .map(|t| {
            let half = (t.to - t.from) * 0.5;
            let note = match (src.break_at(t.node), t.before) {
                (None, _) => format!("tangent at node {} ∥ chord of its neighbours", t.node),
                (Some(_), true) => format!("tangent at node {} ∥ the chord before it", t.node),
                (Some(_), false) => format!("tangent at node {} ∥ the chord after it", t.node),
            };
            thin(given, note, t.through - half, t.through + half, &[])
        })
        .collect();
    let tangents = figs.across(&tangents);
    let rec = figs.built();
    let dirs: Vec<DVec2> = lines.iter().map(|t| t.to - t.from).collect();
    let pc = pole_cuts(rec, layout, st.pole_mm, &dirs, run * n as f64, |_| {
        Vec::new()
    })?;
    let mut d = st.derivative(Derivation::Tangents, &pc);
    let o = layout.origin;
    let mut node_pts = vec![DVec2::ZERO; n + 1];
    let mut left_pts = Vec::with_capacity(src.breaks.len());
    for (i, t) in lines.iter().enumerate() {
        let x = o.x + t.node as f64 * run;
        let (ray, p) = ray_and_project(rec, &pc, i, x, tangents.get(i..=i).unwrap_or(&[]));
        rec.draw(
            format!("node point {}", t.node),
            Item::Point(p),
            Role::Result,
            &[ray],
        );
        let value = read_ordinate(rec, o, p).1;
        if t.before {
            d.breaks.push(Break {
                node: t.node,
                left: value,
            });
            left_pts.push(p);
        } else {
            d.node.push(value);
            node_pts[t.node] = p;
        }
        d.rays.push(ray);
    }
    if src.periodic {
        node_pts[n] = node_pts[0] + DVec2::new(run * n as f64, 0.0);
    }
    for (a, b) in src.spans() {
        let mut points = node_pts[a..b].to_vec();
        points.push(match src.break_index(b) {
            Some(i) => left_pts[i] + DVec2::new(if b == n { run * n as f64 } else { 0.0 }, 0.0),
            None => node_pts[b],
        });
        d.curve = rec.draw(
            format!("smooth curve {} through the node points", layout.name),
            Item::Curve {
                points,
                closed: false,
            },
            Role::Result,
            &d.rays,
        );
    }
    finish(d)
}

/// A draughtsman's tangent of the method of tangents.
struct Tangent {
    /// Its node.
    node: usize,
    /// It is the tangent of the piece ending at the node (a break's left side).
    before: bool,
    /// The chord it is parallel to, from and to (figure mm).
    from: DVec2,
    to: DVec2,
    /// The point it is drawn through.
    through: DVec2,
}

/// The tangent at every node, parallel to the chord joining its two neighbouring nodes
/// (wrapping for a periodic diagram; at the ends of an open one, the adjacent chord); at a
/// break one for each piece, parallel to the piece's chord at the node. A break's left side
/// comes before its right.
fn tangent_lines(st: &Start) -> Vec<Tangent> {
    let (n, src, pts, ends) = (st.n, st.src, &st.pts, &st.ends);
    let nodes = if src.periodic { n } else { n + 1 };
    let shift = DVec2::new(st.run * n as f64, 0.0);
    // The interval before node k (k > 0, or a periodic diagram's last): its start and end.
    let before = |k: usize| {
        if k == 0 {
            (pts[n - 1] - shift, ends[n - 1] - shift)
        } else {
            (pts[k - 1], ends[k - 1])
        }
    };
    let mut out = Vec::with_capacity(nodes + src.breaks.len());
    for k in 0..nodes {
        let tangent = |before: bool, (from, to): (DVec2, DVec2), through: DVec2| Tangent {
            node: k,
            before,
            from,
            to,
            through,
        };
        if src.break_at(k).is_some() {
            let (from, to) = before(k);
            out.push(tangent(true, (from, to), to));
            out.push(tangent(false, (pts[k], ends[k]), pts[k]));
            continue;
        }
        let chord = match (k, src.periodic) {
            (0, false) => (pts[0], ends[0]),
            (k, false) if k == n => before(n),
            (k, _) => (before(k).0, ends[k]),
        };
        out.push(tangent(false, chord, pts[k]));
    }
    out
}
