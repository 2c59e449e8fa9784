//! The dimensions of a combined diagram's final elements (issue 45): r_min with its value,
//! a chosen r₀ under r_min, an offset follower's line x = −e and its e — each checked from
//! the plate's figure.

use super::{centre, segments, tol};
use tmm::cam::{Cam, Follower, E_LINE_NOTE, E_NOTE, R0_NOTE, R_MIN_NOTE};
use tmm::construct::{Drafting, Figure, Item, Role};

/// The number written after `key` in `text` (`r_{min} = 43,77 мм` → 43.77 for `r_{min} = `),
/// either decimal sign.
pub(super) fn number_after(text: &str, key: &str) -> Option<f64> {
    let rest = &text[text.find(key)? + key.len()..];
    let digits: String = rest
        .chars()
        .take_while(|c| c.is_ascii_digit() || *c == ',' || *c == '.')
        .collect();
    digits.replace(',', ".").parse().ok()
}

/// `written` (mm, as a sheet writes it to four significant digits) is `metres`.
pub(super) fn written_as(written: f64, metres: f64) -> bool {
    (written - metres * 1e3).abs() <= 5e-4 * (metres * 1e3).abs().max(1.0)
}

/// `written` (mm) is `metres` read to `step` (m; `None`: exactly, four digits): within half
/// the step (19,3 of 19,33 mm read to 0,25 mm).
pub(super) fn read_as(written: f64, metres: f64, step: Option<f64>) -> bool {
    written_as(written, metres)
        || step.is_some_and(|s| (written - metres * 1e3).abs() <= 0.5 * s * 1e3 * (1.0 + 1e-9))
}

/// The r_min dimension from O₁, its length read at the sheet's drafting equal to `graphical`
/// and its text `r_min = <that value> мм`, written to the reading's step `read_to` (m).
pub(super) fn r_min_dimensioned(
    f: &Figure,
    (graphical, read_to): (f64, Option<f64>),
    d: Drafting,
) -> Result<(), String> {
    let dims = segments(f, R_MIN_NOTE);
    let [(step, a, b)] = dims[..] else {
        return Err(format!("{} r_min dimensions", dims.len()));
    };
    let text = step.label.as_ref().map_or("", |l| l.text.as_str());
    if step.role != Role::Dimension || !text.starts_with("r_{min} = ") {
        return Err(format!(
            "the r_min dimension is not a dimension labelled r_min = …: “{text}”"
        ));
    }
    match number_after(text, "r_{min} = ") {
        Some(v) if read_as(v, graphical, read_to) => {}
        _ => {
            return Err(format!(
                "the r_min dimension reads “{text}”, the report's {graphical} m"
            ))
        }
    }
    let o = centre(f)?;
    if a.distance(o).min(b.distance(o)) > tol(f) {
        return Err("the r_min dimension does not start at O₁".into());
    }
    let read = f.scale.to_physical(d.read(a.distance(b)));
    if (read - graphical).abs() > 1e-9 * graphical.abs().max(1e-3) {
        return Err(format!(
            "r_min dimensioned {read} m, the report's {graphical} m"
        ));
    }
    Ok(())
}

/// A base radius the scene chose under the r_min read (cam-cusp's r₀ = 10 mm against 150):
/// its centre marked and r₀ dimensioned from it to the start of the rise, its length and its
/// text the scene's r₀; no such dimension where the profile takes r₀ ≥ r_min.
pub(super) fn chosen_r0_dimensioned(f: &Figure, cam: &Cam, d: Drafting) -> Result<(), String> {
    let dims = segments(f, R0_NOTE);
    let under = cam.spec.base_radius.filter(|&r0| r0 < cam.radius.graphical);
    let (r0, [(step, a, b)]) = (under, &dims[..]) else {
        return match (under, dims.len()) {
            (None, 0) => Ok(()),
            (r0, n) => Err(format!("r₀ {r0:?} under r_min, {n} r₀ dimensions")),
        };
    };
    let Some(r0) = r0 else {
        return Err("an r₀ dimension where r₀ ≥ r_min".into());
    };
    let text = step.label.as_ref().map_or("", |l| l.text.as_str());
    if !number_after(text, "r_{0} = ").is_some_and(|v| written_as(v, r0)) {
        return Err(format!(
            "the r₀ dimension reads “{text}”, the scene's {r0} m"
        ));
    }
    let read = f.scale.to_physical(d.read(a.distance(*b)));
    let at_start = a.length().min(b.length()) <= tol(f);
    if (read - r0).abs() > 1e-9 * r0 || !at_start {
        return Err(format!("r₀ dimensioned {read} m from {a} to {b}"));
    }
    Ok(())
}

/// An offset roller follower's centre O₁ is chosen on the line x = −e parallel to the S
/// axis: that line drawn through O₁ up to B₀'s level, and e dimensioned between it and the
/// S axis at μ_S; none of either where e = 0 or the face is flat (the review: O₁ off
/// the axis by e, the line neither drawn nor dimensioned, cam-pz5).
pub(super) fn offset_line_drawn(f: &Figure, cam: &Cam) -> Result<(), String> {
    let e = match cam.spec.follower {
        Follower::Translating { offset } => offset,
        _ => 0.0,
    };
    let (lines, dims) = (segments(f, E_LINE_NOTE), segments(f, E_NOTE));
    if e == 0.0 {
        return match (lines.len(), dims.len()) {
            (0, 0) => Ok(()),
            (l, n) => Err(format!("e = 0 with {l} e lines, {n} e dimensions")),
        };
    }
    let ([(_, a, b)], [(_, p, q)]) = (&lines[..], &dims[..]) else {
        return Err(format!(
            "{} e lines, {} e dimensions",
            lines.len(),
            dims.len()
        ));
    };
    let o = centre(f)?;
    let t = tol(f);
    // O₁ stands e off the S axis, on the side the construction takes for the sign of e.
    let x = o.x;
    if (x.abs() - f.scale.to_mm(e.abs())).abs() > t {
        return Err(format!("O₁ {} mm off the S axis, e = {e} m", x.abs()));
    }
    let (lo, hi) = (a.y.min(b.y), a.y.max(b.y));
    if (a.x - x).abs() > t || (b.x - x).abs() > t {
        return Err(format!("the e line at x = {} and {}, O₁ at {x}", a.x, b.x));
    }
    if lo > o.y - t || hi < -t {
        return Err(format!("the e line from {lo} to {hi} mm, O₁ at {}", o.y));
    }
    // e is given, not read: its dimension spans the offset drawn at μ_S exactly.
    let ends = [p.x.min(q.x), p.x.max(q.x)];
    if (ends[0] - x.min(0.0)).abs() > t || (ends[1] - x.max(0.0)).abs() > t {
        return Err(format!(
            "e dimensioned from {p} to {q}, the line at x = {x}"
        ));
    }
    Ok(())
}

/// The combined diagram's two axes of a translating follower, through B₀ (the origin): the S
/// axis and the abscissa of the quantity laid off across it (dS/dφ; d²S/dφ² for a flat
/// face), each labelled, the abscissa spanning every point of the curve. A rocker's dS/dφ is
/// laid off along its arm's positions, with no abscissa.
pub(super) fn axes_drawn(f: &Figure, cam: &Cam) -> Result<(), String> {
    let across = match cam.spec.follower {
        Follower::Rocker { .. } => return Ok(()),
        Follower::Flat { .. } => "d^2S/dφ^2",
        Follower::Translating { .. } => "dS/dφ",
    };
    let labelled = |note: &str, text: &str| {
        let axes = segments(f, note);
        let [(s, a, b)] = axes[..] else {
            return Err(format!("{} {note}es drawn", axes.len()));
        };
        match &s.label {
            Some(l) if l.text == text => Ok((a, b)),
            _ => Err(format!("the {note} is not labelled {text}")),
        }
    };
    let (s0, s1) = labelled("S axis", "S")?;
    let (a, b) = labelled(&format!("{across} axis"), across)?;
    let t = tol(f);
    if a.y.abs() > t || b.y.abs() > t || s0.x.abs() > t || s1.x.abs() > t {
        return Err(format!(
            "the axes do not cross at B₀: S from {s0:?} to {s1:?}, {across} from {a:?} to {b:?}"
        ));
    }
    let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
    let curve = f
        .steps
        .iter()
        .filter(|s| s.role == Role::Result && s.note.starts_with("combined diagram"))
        .flat_map(|s| match &s.item {
            Item::Curve { points, .. } | Item::Polyline { points, .. } => points.clone(),
            _ => Vec::new(),
        });
    match curve.map(|p| p.x).find(|x| *x < lo || *x > hi) {
        Some(x) => Err(format!(
            "the curve reaches {x:.1} mm, past the {across} axis ({lo:.1} … {hi:.1} mm)"
        )),
        None => Ok(()),
    }
}
