//! `[gears]` → [`GearsSpec`]: the module (mm), the basic rack, the pair (`[gears.pair]`: tooth
//! numbers, shifts or a centre distance) and the wheels cut by the rack (`[[gears.rack]]`),
//! each checked with its key path and converted to SI. A pair that cannot work (interference,
//! a pointed tooth, ε_α < 1, an infeasible centre distance) and a wheel whose tooth is
//! pointed before its tip are refused with the key that makes them so.

use super::check::{item, join, number, Checker};
use super::gear_values::{module_mm, teeth};
use super::planetary::{planetary, RawPlanetary};
use crate::gears::blocking::{Blocking, BlockingStudy, Criterion};
use crate::gears::{
    BasicRack, Cutting, GearError, GearPair, GearsSpec, PairSeed, PairSpec, RackSpec,
    DEFAULT_POSITIONS,
};
use crate::scale::{Key, Quantity, Scale};
use serde::Deserialize;

/// The key path of the section.
const GEARS: &str = "gears";
/// The smallest figure a scene's μ_l may draw, mm (its natural size: the meshing picture's
/// a_w + r_a1 + r_a2, a generation's 4πm): below it the plate shows nothing legible.
const MIN_FIGURE_MM: f64 = 20.0;
/// The largest figure a scene's μ_l may draw, mm (5 m): far beyond any sheet, refused before
/// anything is constructed; a figure between the sheet and this is refused by the plate,
/// naming the largest μ_l that fits.
const MAX_FIGURE_MM: f64 = 5000.0;

/// The most rack positions a scene may ask for.
const MAX_POSITIONS: i64 = 5000;

/// `[gears]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawGears {
    pub module: Option<f64>,
    pub alpha: Option<f64>,
    pub ha: Option<f64>,
    pub c: Option<f64>,
    pub rho_f: Option<f64>,
    pub scale_l: Option<f64>,
    pub pair: Option<RawPair>,
    #[serde(default)]
    pub rack: Vec<RawRack>,
    pub seed: Option<RawSeed>,
}

/// `[gears.seed]`: what the source prints for the pair, checked and flagged, never matched.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawSeed {
    pub eps_alpha: Option<f64>,
    pub alpha_w: Option<f64>,
    pub cos_alpha_w: Option<f64>,
    pub a_w: Option<f64>,
    pub pitch: Option<f64>,
}

/// `[gears.pair]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPair {
    pub z: Option<Vec<i64>>,
    pub x: Option<Vec<f64>>,
    pub dy: Option<f64>,
    pub centre_distance: Option<f64>,
    pub choose: Option<String>,
    pub x_sum: Option<f64>,
    pub sa_min: Option<f64>,
}

/// `[[gears.rack]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawRack {
    pub name: Option<String>,
    pub z: Option<i64>,
    pub x: Option<f64>,
    pub module: Option<f64>,
    pub positions: Option<i64>,
    pub scale_l: Option<f64>,
    pub dy: Option<f64>,
}

/// A given μ_l must draw the figure of natural size `size` (m; `what` names it) between
/// [`MIN_FIGURE_MM`] and [`MAX_FIGURE_MM`] (legible, and within reach of a sheet).
fn figure(check: &mut Checker, key: &str, scale: Option<Scale>, size: f64, what: &str) {
    let range = (MIN_FIGURE_MM, MAX_FIGURE_MM);
    super::drawing::draws_within(check, key, scale, what, size, range);
}

/// A shift coefficient within ±3.
fn shift(check: &mut Checker, key: &str, v: f64) -> f64 {
    check.bounded(key, v, 3.0, "a shift coefficient within ±3")
}

/// Validate `[gears]` and `[planetary]` (either may be absent).
pub(crate) fn gear_sections(
    check: &mut Checker,
    raw: Option<&RawGears>,
    train: Option<&RawPlanetary>,
) -> Option<GearsSpec> {
    let before = check.problems.len();
    let planetary = train.and_then(|t| planetary(check, t));
    let mut spec = match raw {
        Some(g) => gears(check, g)?,
        None => GearsSpec {
            pair: None,
            chosen: None,
            seed: None,
            scale_l: None,
            racks: Vec::new(),
            planetary: None,
        },
    };
    spec.planetary = planetary;
    (check.problems.len() == before && (raw.is_some() || train.is_some())).then_some(spec)
}

/// `key` under `[gears]`.
fn key(k: &str) -> String {
    join(GEARS, k)
}

/// Validate `[gears]`.
fn gears(check: &mut Checker, raw: &RawGears) -> Option<GearsSpec> {
    let before = check.problems.len();
    let module = raw.module.map(|m| module_mm(check, &key("module"), m));
    let rack = basic_rack(check, raw);
    let scale_l = check.scale(
        Key::GearsScaleL.path(),
        raw.scale_l,
        Quantity::Length,
        "a scale μ_l > 0 m/mm",
    );
    if raw.pair.is_none() && raw.rack.is_empty() {
        check.push(
            GEARS,
            None,
            "expected a [gears.pair] or at least one [[gears.rack]]",
        );
    }
    // A rack that cannot be drawn is reported once, under its own key; the pair and the
    // wheels it would cut are not judged with it.
    let rack_ok = rack.validate().is_ok();
    let (pair, chosen) = raw
        .pair
        .as_ref()
        .filter(|_| rack_ok)
        .and_then(|p| pair(check, p, module, rack))
        .unzip();
    let chosen = chosen.flatten();
    let racks = racks(check, &raw.rack, module, rack);
    if let Some(p) = pair.and_then(|p| GearPair::working(p).ok()) {
        figure(
            check,
            Key::GearsScaleL.path(),
            scale_l,
            p.a_w + p.ra[0] + p.ra[1],
            "a_w + r_a1 + r_a2",
        );
    }
    let seed = raw.seed.as_ref().map(|s| seed(check, s));
    (check.problems.len() == before).then_some(GearsSpec {
        pair,
        chosen,
        seed,
        scale_l,
        racks,
        planetary: None,
    })
}

/// `[gears.seed]`: the printed values, SI (each positive; α_w in degrees below 90°, cos α_w
/// at most 1, a_w and p in mm).
fn seed(check: &mut Checker, raw: &RawSeed) -> PairSeed {
    let k = |name: &str| join(&key("seed"), name);
    let mut positive = |name: &str, v: Option<f64>, what: &str| {
        check.positive_opt(&k(name), v, &format!("the seed's {what}"))
    };
    let eps_alpha = positive("eps_alpha", raw.eps_alpha, "contact ratio ε_α > 0");
    let alpha_w = positive("alpha_w", raw.alpha_w, "α_w in degrees > 0");
    let cos_alpha_w = positive("cos_alpha_w", raw.cos_alpha_w, "cos α_w > 0");
    let a_w = positive("a_w", raw.a_w, "centre distance a_w in mm > 0");
    let pitch = positive("pitch", raw.pitch, "pitch p in mm > 0");
    let alpha_w = alpha_w.filter(|&a| {
        a < 90.0 || {
            check.push(
                k("alpha_w"),
                Some(number(a)),
                "expected the seed's α_w in degrees below 90",
            );
            false
        }
    });
    let cos_alpha_w = cos_alpha_w.filter(|&c| {
        c <= 1.0 || {
            check.push(
                k("cos_alpha_w"),
                Some(number(c)),
                "expected the seed's cos α_w at most 1",
            );
            false
        }
    });
    PairSeed {
        eps_alpha,
        alpha_w: alpha_w.map(f64::to_radians),
        cos_alpha_w,
        a_w: a_w.map(|a| a * 1e-3),
        pitch: pitch.map(|p| p * 1e-3),
    }
}

/// The basic rack: GOST 13755 unless given; one that cannot be drawn is reported under the
/// key of its first bad parameter (the default's, as such).
fn basic_rack(check: &mut Checker, raw: &RawGears) -> BasicRack {
    let g = BasicRack::GOST_13755;
    let rack = BasicRack {
        alpha: raw
            .alpha
            .map_or(g.alpha, |a| check.angle(&key("alpha"), Some(a), 20.0)),
        ha: raw.ha.unwrap_or(g.ha),
        c: raw.c.unwrap_or(g.c),
        rho: raw.rho_f.unwrap_or(g.rho),
    };
    if let Err(GearError::Rack {
        what,
        value,
        expected,
    }) = rack.validate()
    {
        let default = match what {
            "alpha" => raw.alpha.is_none(),
            "ha" => raw.ha.is_none(),
            "c" => raw.c.is_none(),
            _ => raw.rho_f.is_none(),
        };
        let shown = if default {
            format!("{} (the default)", number(value))
        } else {
            number(value)
        };
        check.push(key(what), Some(shown), format!("expected {expected}"));
    }
    rack
}

/// `[[gears.rack]]`: each wheel cut by the rack (a unique name, its module here or in
/// `[gears]`, z, x, the rack positions, μ_l), refused when it cannot be cut or its tooth is
/// pointed before its tip; none is judged with a rack that cannot be drawn.
fn racks(
    check: &mut Checker,
    raw: &[RawRack],
    module: Option<f64>,
    rack: BasicRack,
) -> Vec<RackSpec> {
    let rack_ok = rack.validate().is_ok();
    let mut names: Vec<String> = Vec::new();
    let mut racks = Vec::new();
    for (i, r) in raw.iter().enumerate() {
        let base = item(&key("rack"), i);
        let k = |s: &str| join(&base, s);
        let name = r.name.clone().unwrap_or_else(|| (i + 1).to_string());
        if name.trim().is_empty() || names.contains(&name) {
            check.push(
                k("name"),
                Some(format!("{name:?}")),
                "expected a non-empty name unique among [[gears.rack]]",
            );
        }
        names.push(name.clone());
        let m = match r.module {
            Some(v) => Some(module_mm(check, &k("module"), v)),
            None => module,
        };
        if m.is_none() {
            check.push(
                k("module"),
                None,
                "missing: expected the module in mm here or in [gears]",
            );
        }
        let z = match check.required(&k("z"), r.z, "a tooth number") {
            Some(z) => teeth(check, &k("z"), z),
            None => 5,
        };
        let x = shift(check, &k("x"), r.x.unwrap_or(0.0));
        let positions = positions(check, &k("positions"), r.positions);
        let scale = check.scale(
            &k("scale_l"),
            r.scale_l,
            Quantity::Length,
            "a scale μ_l > 0 m/mm",
        );
        // The blank's tip shortened by Δy (a pair's wheel: r_a = r + (h_a* + x − Δy)m).
        let dy = match r.dy {
            Some(v) if v.is_finite() && (0.0..=3.0).contains(&v) => v,
            Some(v) => {
                check.push(
                    k("dy"),
                    Some(number(v)),
                    "expected a shortening Δy from 0 to 3",
                );
                0.0
            }
            None => 0.0,
        };
        let Some(m) = m.filter(|m| *m > 0.0 && rack_ok) else {
            continue;
        };
        let tip = m * (f64::from(z) / 2.0 + rack.ha + x - dy);
        match Cutting::with_tip(m, z, x, rack, tip) {
            Ok(c) if c.sa() <= 0.0 => check.push(
                k("x"),
                Some(number(x)),
                format!(
                    "a shift that leaves a tip: with x = {x} the flanks of the {z}-tooth wheel meet below its tip circle (s_a = {:.4} mm); the feasible range ends at s_a = 0.3m",
                    c.sa() * 1e3
                ),
            ),
            Ok(c) => {
                figure(check, &k("scale_l"), scale, 4.0 * std::f64::consts::PI * c.module, "4πm");
                racks.push(RackSpec { name, cutting: c, positions, scale_l: scale })
            }
            Err(e) if dy > 0.0 => check.push(k("dy"), Some(number(dy)), format!("a blank above the root circle: {e}")),
            Err(e) => check.push(k("x"), Some(number(x)), format!("a wheel that can be cut: {e}")),
        }
    }
    racks
}

/// The rack positions of a generation ([`DEFAULT_POSITIONS`] unless given).
fn positions(check: &mut Checker, key: &str, v: Option<i64>) -> usize {
    match v {
        None => DEFAULT_POSITIONS,
        Some(n) if (2..=MAX_POSITIONS).contains(&n) => {
            usize::try_from(n).unwrap_or(DEFAULT_POSITIONS)
        }
        Some(n) => {
            check.push(
                key,
                Some(n.to_string()),
                format!("expected 2 to {MAX_POSITIONS} rack positions"),
            );
            DEFAULT_POSITIONS
        }
    }
}

/// `[gears.pair] choose` with its `x_sum` or `sa_min`: the criterion of the choice of x₁, x₂
/// on the blocking contour.
fn criterion(check: &mut Checker, raw: &RawPair, name: &str) -> Option<Criterion> {
    let key = |k: &str| join(&join(GEARS, "pair"), k);
    let unused = |check: &mut Checker, k: &str, given: bool| {
        if given {
            check.push(key(k), None, format!("not used by choose = \"{name}\""));
        }
    };
    match name {
        "largest-contact-ratio" => {
            unused(check, "x_sum", raw.x_sum.is_some());
            unused(check, "sa_min", raw.sa_min.is_some());
            Some(Criterion::LargestContactRatio)
        }
        "equal-sliding" => {
            unused(check, "sa_min", raw.sa_min.is_some());
            let x_sum = check.required(&key("x_sum"), raw.x_sum.as_ref(), "x₁ + x₂ (within ±6)")?;
            let x_sum = check.bounded(&key("x_sum"), *x_sum, 6.0, "x₁ + x₂ within ±6");
            Some(Criterion::EqualSliding { x_sum })
        }
        "greatest-sum" => {
            unused(check, "x_sum", raw.x_sum.is_some());
            let sa_min = raw.sa_min.unwrap_or(BlockingStudy::HARD.sa_min);
            if !(0.0..=1.0).contains(&sa_min) {
                check.push(
                    key("sa_min"),
                    Some(number(sa_min)),
                    "the least tip thickness s_a/m, 0 … 1",
                );
                return None;
            }
            Some(Criterion::GreatestSumWithTip { sa_min })
        }
        _ => {
            check.push(
                key("choose"),
                Some(name.to_string()),
                "one of \"largest-contact-ratio\", \"equal-sliding\" (with x_sum), \"greatest-sum\" (with sa_min, default 0,25)",
            );
            None
        }
    }
}

/// `[gears.pair]`: z = [z₁, z₂], x = [x₁, x₂] (or x = [x₁] with `centre_distance`, mm, or
/// chosen on the blocking contour by `choose`), the table's Δy; the pair is refused when it
/// cannot work. With `choose`, the criterion it was chosen by.
fn pair(
    check: &mut Checker,
    raw: &RawPair,
    module: Option<f64>,
    rack: BasicRack,
) -> Option<(PairSpec, Option<Criterion>)> {
    let key = |k: &str| join(&join(GEARS, "pair"), k);
    let before = check.problems.len();
    let Some(m) = module else {
        check.push(
            join(GEARS, "module"),
            None,
            "missing: expected the module in mm",
        );
        return None;
    };
    let z = match check.required(&key("z"), raw.z.as_ref(), "two tooth numbers [z1, z2]") {
        Some(v) if v.len() == 2 => [
            teeth(check, &item(&key("z"), 0), v[0]),
            teeth(check, &item(&key("z"), 1), v[1]),
        ],
        Some(v) => {
            check.push(
                key("z"),
                Some(format!("{v:?}")),
                "expected two tooth numbers [z1, z2]",
            );
            [5, 5]
        }
        None => [5, 5],
    };
    let criterion = raw.choose.as_ref().and_then(|c| criterion(check, raw, c));
    let xs = raw.x.clone().unwrap_or_else(|| vec![0.0, 0.0]);
    let want = if raw.centre_distance.is_some() { 1 } else { 2 };
    if raw.choose.is_some() {
        for (k, given) in [
            ("x", raw.x.is_some()),
            ("centre_distance", raw.centre_distance.is_some()),
        ] {
            if given {
                check.push(
                    key(k),
                    None,
                    "either the shifts or `choose` (the contour chooses them), not both",
                );
            }
        }
    } else if xs.len() != want {
        let expected = if want == 1 {
            "one shift [x1]: with `centre_distance` x2 follows from it"
        } else {
            "two shift coefficients [x1, x2]"
        };
        check.push(
            key("x"),
            Some(format!("{xs:?}")),
            format!("expected {expected}"),
        );
    }
    let x1 = shift(
        check,
        &item(&key("x"), 0),
        xs.first().copied().unwrap_or(0.0),
    );
    let x2 = shift(
        check,
        &item(&key("x"), 1),
        xs.get(1).copied().unwrap_or(0.0),
    );
    let dy = raw
        .dy
        .map(|d| check.bounded(&key("dy"), d, 3.0, "an equalising shift Δy within ±3"));
    if check.problems.len() != before || m <= 0.0 {
        return None;
    }
    let mut spec = PairSpec {
        module: m,
        z,
        x: [x1, x2],
        rack,
        dy_table: dy,
    };
    if let Some(c) = criterion {
        let chosen = Blocking::new(z, rack).and_then(|b| b.choose(c, BlockingStudy::HARD));
        match chosen {
            Ok(ch) => spec.x = ch.indices.x,
            Err(e) => {
                check.push(
                    key("choose"),
                    raw.choose.clone(),
                    format!("a criterion the contour can meet: {e}"),
                );
                return None;
            }
        }
    }
    if let Some(a) = raw.centre_distance {
        match spec.x2_for_centre_distance(a * 1e-3) {
            Ok(x2) => spec.x[1] = x2,
            Err(e) => {
                check.push(
                    key("centre_distance"),
                    Some(number(a)),
                    format!("a feasible centre distance: {e}"),
                );
                return None;
            }
        }
    }
    match GearPair::working(spec) {
        Ok(_) => Some((spec, criterion)),
        Err(e) => {
            let (k, value) = match &raw.choose {
                Some(c) if criterion.is_some() => (key("choose"), c.clone()),
                _ => blame(&e, raw, &spec, &xs),
            };
            check.push(k, Some(value), format!("a pair that can work: {e}"));
            None
        }
    }
}

/// The key (and its value as given) that makes the pair `spec` refuse to work with `e`: the
/// table's Δy when the pair works with the exact one (or the tip falls inside the base
/// circle with it), a tooth number for a datum of a wheel, the shifts otherwise (with
/// `centre_distance`, the x₂ it gives).
fn blame(e: &GearError, raw: &RawPair, spec: &PairSpec, xs: &[f64]) -> (String, String) {
    let key = |k: &str| join(&join(GEARS, "pair"), k);
    if let Some(dy) = raw.dy {
        let exact = PairSpec {
            dy_table: None,
            ..*spec
        };
        if matches!(e, GearError::TipInsideBase { .. }) || GearPair::working(exact).is_ok() {
            return (key("dy"), number(dy));
        }
    }
    let shifts = || {
        if raw.centre_distance.is_some() {
            format!("{xs:?} (x2 = {:.4} from the centre distance)", spec.x[1])
        } else {
            format!("{xs:?}")
        }
    };
    match e {
        GearError::Pointed { wheel, .. } => (item(&key("x"), wheel - 1), shifts()),
        GearError::Spec { what, value, .. } if what.starts_with('z') => {
            let wheel = usize::from(*what == "z2");
            (item(&key("z"), wheel), number(*value))
        }
        GearError::Spec { what, value, .. } | GearError::Rack { what, value, .. } => {
            (join(GEARS, what), number(*value))
        }
        _ => (key("x"), shifts()),
    }
}
