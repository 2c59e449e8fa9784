//! The English of a gear study's notes ([`GearsNote`]).

use super::sig as num;
use crate::check::notes::gears::{Cut, GearsNote, Junction, PairIndices, WrongBase};
use crate::gears::{dms, TABLE_DIGITS};

/// The note in English.
pub(super) fn english(note: &GearsNote) -> String {
    match note {
        GearsNote::Pair(p) => pair(p),
        GearsNote::InvTable {
            inv,
            table,
            exact,
            printed,
        } => format!(
            "gears: by the inv table (a row every 1′ to {TABLE_DIGITS} decimals, read linearly): inv α_w = {inv:.6} → α_w = {} (exact {}){}",
            dms(*table, 0),
            dms(*exact, 1),
            printed.map_or_else(String::new, |a| format!(
                "; the seed prints {}, {}″ off the table's own reading: not reproduced",
                dms(a, 0),
                num(((a - table).abs().to_degrees() * 3600.0).round(), 3),
            ))
        ),
        GearsNote::Tables {
            dy,
            y,
            a_w,
            exact,
            y_exact,
        } => format!(
            "gears: by the tables: Δy = {} (table), y = x_Σ − Δy = {}, a_w = m(z_Σ/2 + y) = {} mm against the exact {} mm (y = {}); the tip radii take the table's Δy",
            num(*dy, 4),
            num(*y, 5),
            num(a_w * 1e3, 7),
            num(exact * 1e3, 7),
            num(*y_exact, 5),
        ),
        GearsNote::EpsFromWrongBase(w) => wrong_base(w),
        GearsNote::EpsNotReproduced { printed, eps } => format!(
            "gears: erratum: the seed's ε_α = {} is not reproducible; ε_α = {}",
            num(*printed, 4),
            num(*eps, 5),
        ),
        GearsNote::CosMisread {
            read,
            a_w_read,
            printed,
            cos,
            a_w,
        } => {
            let printed = printed.map_or_else(String::new, |a| {
                format!(" (the seed prints {} mm)", num(a * 1e3, 5))
            });
            format!(
                "gears: erratum: cos α_w read as {} (= cos {}°) gives a_w = {} mm{printed}; cos α_w = {} gives a_w = {} mm",
                num(*read, 4),
                num(read.clamp(-1.0, 1.0).acos().to_degrees(), 4),
                num(a_w_read * 1e3, 5),
                num(*cos, 4),
                num(a_w * 1e3, 5),
            )
        }
        GearsNote::AwNotReproduced { printed, a_w } => format!(
            "gears: erratum: the seed's a_w = {} mm is not reproducible; a_w = {} mm",
            num(printed * 1e3, 5),
            num(a_w * 1e3, 5),
        ),
        GearsNote::Pitch { printed, pitch } => format!(
            "gears: erratum: the printed \"p = {} mm\" contradicts p = πm = {} mm",
            num(printed * 1e3, 4),
            num(pitch * 1e3, 5),
        ),
        GearsNote::Compass { deviation, step } => format!(
            "gears: the compass involute of wheel 1 through P (N₁P in 4 parts) deviates from the exact one by {} mm (chord-vs-arc error of one step {} mm)",
            num(deviation * 1e3, 3),
            num(step * 1e3, 3),
        ),
        GearsNote::Cut(c) => cut(c),
        GearsNote::Shift {
            wheel,
            x_min,
            textbook,
            pointing,
        } => shift(wheel, *x_min, *textbook, *pointing),
        GearsNote::Junction(j) => junction(j),
        GearsNote::Tip {
            wheel,
            read,
            module,
            exact,
            pointed,
        } => format!(
            "gears: wheel {wheel}: tip thickness s_a = {} mm = {}·m read off the drawing ({} mm exact){}",
            num(read * 1e3, 5),
            num(read / module, 4),
            num(exact * 1e3, 5),
            if *pointed {
                ": pointed (s_a < 0.3m)"
            } else {
                ""
            }
        ),
    }
}

/// The pair's indices and clearances, ε_α against the course's 1.1.
fn pair(p: &PairIndices) -> String {
    format!(
        "gears: pair z = {}/{}, x = {}/{}: α_w = {}°, a_w = {} mm, y = {}, Δy = {}, ε_α = {}{}; radial clearances {} and {} mm (c*·m = {} mm)",
        p.z[0],
        p.z[1],
        num(p.x[0], 4),
        num(p.x[1], 4),
        num(p.alpha_w.to_degrees(), 7),
        num(p.a_w * 1e3, 7),
        num(p.y, 5),
        num(p.dy, 5),
        num(p.eps, 5),
        if p.eps < 1.1 { " (below the 1.1 the course asks for)" } else { "" },
        num(p.clearance[0] * 1e3, 5),
        num(p.clearance[1] * 1e3, 5),
        num(p.nominal * 1e3, 4),
    )
}

/// The seed's ε_α from the base radii r·cos α_w against the base pitch πm·cos α.
fn wrong_base(w: &WrongBase) -> String {
    format!(
        "gears: erratum: the seed's ε_α = {} comes from the base radii r·cos α_w = {}/{} mm and the base pitch πm·cos α_w = {} mm (ε_α = B₁B₂/(πm·cos α_w) = {}); the base pitch is πm·cos α = {} mm and ε_α = {}",
        num(w.printed, 4),
        num(w.radii[0] * 1e3, 5),
        num(w.radii[1] * 1e3, 5),
        num(w.pitch * 1e3, 5),
        num(w.eps_from, 4),
        num(w.p_b * 1e3, 5),
        num(w.eps, 5),
    )
}

/// A wheel cut by the rack: the undercut on the drawing and by the criterion.
fn cut(c: &Cut) -> String {
    format!(
        "gears: wheel {} (z = {}, x = {}) cut by the rack in {} steps: undercut {} on the drawing ({}), {} by the criterion (the flank's end {} mm below the pitch line, the limit r·sin²α = {} mm)",
        c.wheel,
        c.z,
        num(c.x, 4),
        c.steps,
        if c.drawn { "shown" } else { "not shown" },
        if c.drawn {
            "the fillet crosses the involute"
        } else {
            "the fillet meets the involute tangentially"
        },
        if c.undercut { "undercut" } else { "no undercut" },
        num(c.depth * 1e3, 5),
        num(c.limit * 1e3, 5),
    )
}

/// Where the involute meets the fillet, drawn and exact.
fn junction(j: &Junction) -> String {
    format!(
        "gears: wheel {}: the involute meets the fillet at r = {} mm on the drawing, {} mm exactly (the involute and the trochoid intersected{}): {}·m apart; the touching points lie on the exact curves to {}·m",
        j.wheel,
        num(j.drawn * 1e3, 6),
        num(j.exact * 1e3, 6),
        if j.undercut { "" } else { ": they meet tangentially at the flank's end" },
        num(j.apart, 3),
        num(j.touch, 2),
    )
}

/// x_min (and the textbook's rule where it holds) and the feasible shift up to pointing.
fn shift(wheel: &str, x_min: f64, textbook: Option<f64>, pointing: Option<f64>) -> String {
    let range = pointing.map_or_else(
        || "no shift gives s_a = 0.3m".to_string(),
        |x| {
            let empty = if x < x_min {
                " (empty: no shift avoids both undercut and pointing)"
            } else {
                ""
            };
            format!(
                "x_min = {} … x(s_a = 0.3m) = {}{empty}",
                num(x_min, 4),
                num(x, 4)
            )
        },
    );
    let rule = textbook.map_or_else(String::new, |x| {
        format!(" (the textbook's (17 − z)/17 = {})", num(x, 4))
    });
    format!(
        "gears: wheel {wheel}: x_min = h_a* − z·sin²α/2 = {}{rule}; feasible shift: {range}",
        num(x_min, 4),
    )
}
