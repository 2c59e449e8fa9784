//! The English of a blocking contour's notes ([`BlockingNote`]).

use super::sig as num;
use crate::check::notes::blocking::{BlockingNote, Criterion, Kind, Level, PlanePoint, Traced};

/// The note in English.
pub(super) fn english(note: &BlockingNote) -> String {
    match note {
        BlockingNote::Traced(t) => traced(t),
        BlockingNote::Placed {
            chosen,
            point: p,
            admissible,
            outside,
        } => {
            let outside: Vec<String> = outside.iter().map(level).collect();
            format!(
                "blocking contour: the scene's point{} {}; {} (s_a ≥ 0.25m, ε_α ≥ 1, no undercut, no interference){}",
                chosen.map_or(String::new(), |c| format!(
                    ", chosen on the contour by {} (`choose`),",
                    criterion(c)
                )),
                point(p),
                if *admissible { "inside" } else { "outside" },
                if outside.is_empty() {
                    String::new()
                } else {
                    format!("; on the wrong side of {}", outside.join(", "))
                }
            )
        }
        BlockingNote::Margin { margin, eps } => format!(
            "blocking contour: each choice searches the whole region and keeps {margin} inside every hard limit (s_a ≥ (s_a,min + {margin})m, ε_α ≥ {}, x_i ≥ x_min,i + {margin}, N_iB_i ≥ ρ_l,i + {margin}m): on a limit itself the supremum can be a pair that does not work (the largest ε_α of 13/30 lies where the mate's tip reaches N₁, λ₁(B₁) = −∞)",
            num(*eps, 3),
        ),
        BlockingNote::Choice {
            criterion: c,
            result: Ok((p, on)),
        } => {
            let on: Vec<String> = on.iter().map(level).collect();
            format!(
                "blocking contour: {}: {}; on {}",
                criterion(*c),
                point(p),
                if on.is_empty() {
                    "no limit (an inner maximum)".to_string()
                } else {
                    on.join(", ")
                }
            )
        }
        BlockingNote::Choice {
            criterion: c,
            result: Err(e),
        } => format!("blocking contour: {}: none ({e})", criterion(*c)),
    }
}

/// How the contour was traced and checked.
fn traced(t: &Traced) -> String {
    let [[x1_lo, x1_hi], [x2_lo, x2_hi]] = t.window;
    format!(
        "blocking contour z₁ = {}, z₂ = {}: traced on a grid of spacing {} over x₁ ∈ [{}, {}], x₂ ∈ [{}, {}] (each point bracketed along a grid edge to 1e-13 of m or its index to 1e-14 of its limit; the region's corners, where the binding limit changes, solved by Newton's steps to 1e-12): {} curves, {} points; the admissible region {} ring(s) of {} points; at {} sampled points the twins (Pair::new, Cutting) give the limits to {:.1e}; undercut limit x_min = h_l* − z sin²α/2 with h_l* = {} (the flank's end): x_min1 = {}, x_min2 = {}",
        t.z[0],
        t.z[1],
        t.spacing,
        num(x1_lo, 4),
        num(x1_hi, 4),
        num(x2_lo, 4),
        num(x2_hi, 4),
        t.curves,
        t.points,
        t.rings,
        t.ring_points,
        t.sampled,
        t.twin_deviation,
        num(t.hl, 6),
        num(t.x_min[0], 5),
        num(t.x_min[1], 5),
    )
}

/// A point's indices.
fn point(p: &PlanePoint) -> String {
    let l = p.lambda.map_or("—".to_string(), |l| {
        format!("λ₁(B₁) = {}, λ₂(B₂) = {}", num(l[0], 5), num(l[1], 5))
    });
    format!(
        "x₁ = {}, x₂ = {}: α_w = {}°, y = {}, Δy = {}, ε_α = {}, s_a1 = {}m, s_a2 = {}m, {l}",
        num(p.x[0], 6),
        num(p.x[1], 6),
        num(p.alpha_w.to_degrees(), 6),
        num(p.y, 5),
        num(p.dy, 5),
        num(p.eps, 5),
        num(p.sa[0], 4),
        num(p.sa[1], 4),
    )
}

/// A criterion of the choice.
fn criterion(c: Criterion) -> String {
    match c {
        Criterion::LargestContactRatio => "the largest ε_α".into(),
        Criterion::EqualSliding { x_sum } => format!(
            "equal sliding λ₁(B₁) = λ₂(B₂) on x₁ + x₂ = {}",
            num(x_sum, 6)
        ),
        Criterion::GreatestSumWithTip { sa_min } => {
            format!("the greatest x₁ + x₂ with s_a ≥ {}m", num(sa_min, 3))
        }
    }
}

/// A limit, taken `inset` inside it.
fn level(v: &Level) -> String {
    let (l, by) = (num(v.limit, 4), num(v.inset, 4));
    match v.kind {
        Kind::Undercut(i) if v.inset == 0.0 => format!("x{0} ≥ x_min{0} = {l}", i + 1),
        Kind::Undercut(i) => format!("x{0} ≥ x_min{0} + {by} = {l}", i + 1),
        Kind::Tip(i) => format!("s_a{} ≥ {l}m", i + 1),
        Kind::ContactRatio => format!("ε_α ≥ {l}"),
        Kind::Interference(i) if v.inset == 0.0 => {
            format!("no interference with the fillet of wheel {}", i + 1)
        }
        Kind::Interference(i) => format!("N{0}B{0} ≥ ρ_l{0} + {by}m", i + 1),
        Kind::EqualSliding => "λ₁ = λ₂".into(),
    }
}
