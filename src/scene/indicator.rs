//! `[[forces.indicator]]` → [`Indicator`]: the piston, the bore and the indicator diagram
//! unfolded against the cycle angle, each checked with its key path and converted to SI.

use super::check::{item, join, number, quoted, Checker};
use super::kinematics::{point, point_names};
use super::raw::RawIndicator;
use crate::forces::Indicator;
use crate::linkage::{Dyad, Mechanism};

/// The highest gas pressure a scene may give, MPa.
const MAX_MPA: f64 = 1e3;
/// Pa per MPa.
const PA_PER_MPA: f64 = 1e6;
/// Tolerance on the cycle's ends 0° and 360°, degrees.
const ENDS_DEG: f64 = 1e-9;

/// Validate one `[[forces.indicator]]` at `base` against `mechanism` (its point must be the
/// slider's joint of an RRP group).
pub(crate) fn indicator(
    check: &mut Checker,
    base: &str,
    raw: &RawIndicator,
    mechanism: Option<&Mechanism>,
) -> Option<Indicator> {
    let k = |s: &str| join(base, s);
    let names = mechanism.map(point_names);
    let name = check.required(
        &k("point"),
        raw.point.clone(),
        "the piston (the slider's joint of an RRP group)",
    );
    let name = match (name, mechanism) {
        (Some(n), Some(m)) => point(check, &k("point"), Some(n), names.as_deref()).and_then(|n| {
            let piston = m
                .groups
                .iter()
                .any(|g| matches!(&g.dyad, Dyad::Rrp { joint, .. } if *joint == n));
            if piston {
                Some(n)
            } else {
                check.push(
                    k("point"),
                    Some(quoted(&n)),
                    "expected the slider's joint of an RRP group (a piston)",
                );
                None
            }
        }),
        (n, _) => n,
    };
    let bore = check.length(&k("bore"), raw.bore);
    let offset = check.angle(&k("offset"), raw.offset, 0.0);
    let pressure = table(check, &k("pressure"), raw.pressure.as_ref());
    Some(Indicator {
        point: name?,
        bore,
        pressure: pressure?,
        offset,
    })
}

/// `pressure = [[θ°, p MPa], …]`: θ increasing from 0 to 360, p ≥ 0 and finite.
fn table(check: &mut Checker, key: &str, rows: Option<&Vec<Vec<f64>>>) -> Option<Vec<(f64, f64)>> {
    let rows = check.required(
        key,
        rows,
        "the indicator diagram [[θ°, p MPa], …] from θ = 0 to 360",
    )?;
    let mut out = Vec::with_capacity(rows.len());
    let mut ok = true;
    for (i, r) in rows.iter().enumerate() {
        let ki = item(key, i);
        let &[t, p] = r.as_slice() else {
            check.push(ki, Some(format!("{r:?}")), "expected a pair [θ°, p MPa]");
            ok = false;
            continue;
        };
        if !(t.is_finite() && (-ENDS_DEG..=360.0 + ENDS_DEG).contains(&t)) {
            check.push(
                ki.clone(),
                Some(number(t)),
                "expected a cycle angle θ from 0° to 360°",
            );
            ok = false;
        } else if let Some(&(prev, _)) = out.last() {
            if t.to_radians() <= prev {
                check.push(
                    ki.clone(),
                    Some(number(t)),
                    "expected cycle angles increasing row by row",
                );
                ok = false;
            }
        }
        if !(p.is_finite() && (0.0..=MAX_MPA).contains(&p)) {
            check.push(
                ki,
                Some(number(p)),
                "expected a gas pressure ≥ 0 MPa (gauge), at most 1000 MPa",
            );
            ok = false;
        }
        out.push((t.clamp(0.0, 360.0).to_radians(), p * PA_PER_MPA));
    }
    let spans = matches!(
        (rows.first().and_then(|r| r.first()), rows.last().and_then(|r| r.first())),
        (Some(a), Some(b)) if a.abs() <= ENDS_DEG && (b - 360.0).abs() <= ENDS_DEG
    );
    if ok && (rows.len() < 2 || !spans) {
        check.push(
            key,
            Some(format!("{} rows", rows.len())),
            "expected the whole cycle: the first row at θ = 0°, the last at θ = 360° (one turn of the crank: a two-stroke cycle)",
        );
        ok = false;
    }
    if ok {
        if let (Some(a), Some(b)) = (out.first(), out.last()) {
            if (a.1 - b.1).abs() > 1e-9 * a.1.abs().max(b.1.abs()).max(1.0) {
                check.push(
                    key,
                    Some(format!(
                        "{} ≠ {} MPa",
                        number(a.1 / PA_PER_MPA),
                        number(b.1 / PA_PER_MPA)
                    )),
                    "expected the same pressure at θ = 0° and 360° (the diagram is periodic)",
                );
                ok = false;
            }
        }
    }
    ok.then_some(out)
}
