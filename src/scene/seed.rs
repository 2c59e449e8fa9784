//! `[[seed]]` and `[[forces.seed]]` → [`SeedValue`]: a value the seed prints for a row of
//! the report, with the unit it prints it in, where and what is wrong with it. The report
//! says how far off it is and the note's conclusions say why: a seed's error is flagged,
//! never matched.

use super::check::{join, number, quoted, Checker};
use super::raw::RawSeedValue;
use crate::check::Method;
use crate::check::SeedValue;
use crate::scale::{Localised, KGF};

/// The largest magnitude a seed's value may have in its SI unit.
const MAX_VALUE: f64 = 1e9;

/// Units a value may be printed in, each with its factor to SI.
type Units = &'static [(&'static str, f64)];

/// The quantities a seed's value may name, by the first part of the report's name, and the
/// units it may be printed in.
const UNITS: &[(&[&str], Units)] = &[
    (&["R", "F"], &[("N", 1.0), ("kgf", KGF)]),
    (&["M"], &[("N*m", 1.0), ("kgf*m", KGF)]),
    (&["h", "r", "s"], &[("m", 1.0), ("mm", 1e-3)]),
    (&["v"], &[("m/s", 1.0)]),
    (&["a"], &[("m/s^2", 1.0)]),
    (&["omega"], &[("rad/s", 1.0)]),
    (&["eps"], &[("rad/s^2", 1.0), ("1", 1.0)]),
    (&["J"], &[("kg*m^2", 1.0)]),
];

/// What a seed's quantity may be, for the message naming a wrong one.
const QUANTITY: &str = "a row of the report (R_1_2, F_bal, M_bal, h_0_5, v_S3, a_D, omega_3, eps_3, r_b1, J_red, eps_alpha)";

/// A seed's value at `base`: the report's quantity, the position (one of `positions` when
/// given: the force analysis's; required then), the method, the value with its unit, the
/// source and what is wrong in each language.
pub(super) fn seed_value(
    check: &mut Checker,
    base: &str,
    raw: &RawSeedValue,
    positions: Option<&[String]>,
) -> Option<SeedValue> {
    let k = |s: &str| join(base, s);
    let quantity = check.required(&k("quantity"), raw.quantity.clone(), QUANTITY)?;
    let head = quantity.split('_').next().unwrap_or_default();
    let Some((_, units)) = UNITS.iter().find(|(heads, _)| heads.contains(&head)) else {
        check.push(
            k("quantity"),
            Some(quoted(&quantity)),
            format!("expected {QUANTITY}"),
        );
        return None;
    };
    let position = match positions {
        Some(positions) => {
            let p = check.required(&k("position"), raw.position.clone(), "an analysed position");
            if let Some(p) = p.as_ref().filter(|p| !positions.contains(p)) {
                let list: Vec<String> = positions.iter().map(|p| quoted(p)).collect();
                check.push(
                    k("position"),
                    Some(quoted(p)),
                    format!("expected one of forces.positions ({})", list.join(", ")),
                );
            }
            Some(p?)
        }
        None => raw.position.clone(),
    };
    let methods: Vec<(&str, Method)> = Method::ALL.iter().map(|m| (m.key(), *m)).collect();
    let method = match raw.method.as_deref() {
        None => None,
        Some(_) => check.word(&k("method"), raw.method.as_ref(), &methods),
    };
    let value = check.required(&k("value"), raw.value, "the value the seed prints")?;
    let table: Vec<(&str, (&str, f64))> = units.iter().map(|u| (u.0, *u)).collect();
    let (unit, factor) = check.word(&k("unit"), raw.unit.as_ref(), &table)?;
    let magnitude = check.in_range(&k("value"), value.abs(), MAX_VALUE, "a finite value, not 0");
    let source = check.required(&k("source"), raw.source.clone(), "where the seed prints it")?;
    let why = match &raw.why {
        None => None,
        Some(w) => {
            const WHY: &str = "what is wrong with the value, in this language";
            let mut text = |lang: &str, t: &Option<String>| {
                check.required(&join(&k("why"), lang), t.clone(), WHY)
            };
            let (ru, uk, en) = (text("ru", &w.ru), text("uk", &w.uk), text("en", &w.en));
            Some(Localised {
                ru: ru?,
                uk: uk?,
                en: en?,
            })
        }
    };
    Some(SeedValue {
        quantity,
        position,
        method,
        value: magnitude * factor,
        printed: format!("{} {unit}", number(value)),
        printed_value: value,
        printed_unit: unit,
        source,
        why,
    })
}
