//! The English of a seed's printed value against the analysis ([`SeedNote`]).

use super::sig;
use crate::check::notes::seed::SeedNote;

/// The note in English: the seed's value, the analysis' and how far apart they are, or that
/// the report has no such row.
pub(super) fn english(note: &SeedNote) -> String {
    let s = &note.seed;
    let n = |x: f64| sig(x, 6);
    let method = s
        .method
        .map_or(String::new(), |m| format!(" ({})", m.key()));
    let at = s
        .position
        .as_ref()
        .map_or(String::new(), |p| format!("position {p}: "));
    match &note.row {
        Some(r) => {
            let a = r.analytic.abs();
            let off = if a > 0.0 {
                (s.value - a) / a * 100.0
            } else {
                f64::NAN
            };
            let unit = r.unit;
            let si = if s.printed.ends_with(&format!(" {unit}")) {
                String::new()
            } else {
                format!(" = {} {unit}", n(s.value))
            };
            format!(
                "{at}{}{method}: the seed prints {}{si} ({}); this analysis gives {} {unit} (analytic {} {unit}): the seed's value is {}{} % off and is not reproduced",
                s.quantity,
                s.printed,
                s.source,
                n(r.graphical.abs()),
                n(a),
                if off > 0.0 { "+" } else { "" },
                sig(off, 3),
            )
        }
        None => format!(
            "{at}{}{method}: the seed prints {} ({}), but this report has no such row",
            s.quantity, s.printed, s.source
        ),
    }
}
