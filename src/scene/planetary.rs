//! `[planetary]` → [`PlanetarySpec`]: wheels on named shafts, meshes by wheel names, the
//! input, output, fixed shaft, carrier and satellites by shaft name, each checked with its key
//! path; a train whose roles are not distinct, whose mobility is not the number of its inputs
//! or that is not coaxial (unless `closing_module` closes it) is refused with the key that
//! makes it so; `[planetary.seed]`, what the source prints, is kept for the notes.

use super::check::{item, join, Checker};
use super::gear_values::{module_mm, teeth_from};
use crate::gears::{Mesh, PlanetarySpec, Train, TrainSeed};
use crate::gears::{TrainError, Wheel};
use crate::scale::Key;
use serde::Deserialize;

/// `[planetary]`.
#[derive(Debug, Clone, PartialEq, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawPlanetary {
    pub module: Option<f64>,
    pub input: Option<String>,
    pub output: Option<String>,
    pub fixed: Option<String>,
    pub carrier: Option<String>,
    #[serde(default)]
    pub satellites: Vec<String>,
    pub n_input: Option<f64>,
    pub n_output: Option<f64>,
    pub input2: Option<String>,
    pub n_input2: Option<f64>,
    pub count: Option<i64>,
    pub closing_module: Option<bool>,
    pub seed: Option<RawTrainSeed>,
    #[serde(default)]
    pub wheel: Vec<RawWheel>,
    #[serde(default)]
    pub mesh: Vec<RawMesh>,
}

/// `[[planetary.wheel]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawWheel {
    pub name: Option<String>,
    pub z: Option<i64>,
    pub shaft: Option<String>,
    pub internal: Option<bool>,
    pub module: Option<f64>,
}

/// `[planetary.seed]`: what the source prints for the train.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawTrainSeed {
    pub u: Option<f64>,
    pub w: Option<i64>,
}

/// `[[planetary.mesh]]`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RawMesh {
    pub wheels: Option<Vec<String>>,
}

/// The key path of the section.
const P: &str = "planetary";

/// `key` under `[planetary]`.
fn key(k: &str) -> String {
    join(P, k)
}

/// Validate `[planetary]`: wheels on named shafts, meshes by wheel names, the input, output,
/// fixed shaft, carrier and satellites by shaft name; the train must have the mobility of its
/// inputs and be drawable (coaxial, or closed by `closing_module`).
pub(crate) fn planetary(check: &mut Checker, raw: &RawPlanetary) -> Option<PlanetarySpec> {
    let before = check.problems.len();
    let module = raw
        .module
        .map_or(0.001, |m| module_mm(check, Key::PlanetaryModule.path(), m));
    let (mut shafts, wheels) = wheels(check, raw);
    let meshes = meshes(check, raw, &wheels);
    let roles = [
        ("carrier", &raw.carrier, true),
        ("input", &raw.input, true),
        ("output", &raw.output, true),
        ("fixed", &raw.fixed, false),
        ("input2", &raw.input2, true),
    ];
    let [carrier, input, output, fixed, input2] =
        roles.map(|(k, v, add)| shaft_of(check, &mut shafts, &key(k), v.as_ref(), add));
    let satellites: Vec<usize> = raw
        .satellites
        .iter()
        .enumerate()
        .filter_map(|(i, s)| {
            shaft_of(
                check,
                &mut shafts,
                &item(&key("satellites"), i),
                Some(s),
                false,
            )
        })
        .collect();
    for (k, v) in [("input", input), ("output", output)] {
        if v.is_none() {
            check.push(key(k), None, "missing: expected a shaft name");
        }
    }
    distinct_shafts(check, raw, [input, output, fixed, carrier], &satellites);
    let (n_input, n_output, count) = speeds(check, raw);
    let seed = train_seed(check, raw);
    let second = second_input(check, raw, [input, output, fixed, input2], n_input);
    let (Some(input), Some(output)) = (input, output) else {
        return None;
    };
    if check.problems.len() != before {
        return None;
    }
    let train = Train {
        shafts,
        wheels,
        meshes,
        input,
        output,
        fixed,
        carrier,
        satellites,
        module,
        second,
    };
    let closing = raw.closing_module.unwrap_or(false);
    if !drawable(check, raw, &train, closing) {
        return None;
    }
    Some(PlanetarySpec {
        train,
        n_input,
        n_output,
        satellites: count,
        closing,
        seed,
    })
}

/// `[[planetary.wheel]]`: each wheel's name (unique), tooth number and shaft; gives the
/// shafts in order of first naming, and the wheels.
fn wheels(check: &mut Checker, raw: &RawPlanetary) -> (Vec<String>, Vec<Wheel>) {
    let mut shafts: Vec<String> = Vec::new();
    let mut wheels = Vec::new();
    if raw.wheel.is_empty() {
        check.push(
            key("wheel"),
            None,
            "missing: expected [[planetary.wheel]] (name, z, shaft)",
        );
    }
    for (i, w) in raw.wheel.iter().enumerate() {
        let base = item(&key("wheel"), i);
        let k = |s: &str| join(&base, s);
        let name = check.name(&k("name"), w.name.as_ref());
        if wheels.iter().any(|x: &Wheel| x.name == name) {
            check.push(
                k("name"),
                Some(format!("{name:?}")),
                "expected a wheel name unique in the train",
            );
        }
        // A train's wheel is counted, not cut: the textbook's pinion shaft of 4 teeth (PZ2
        // example 1) is allowed.
        let z = match check.required(&k("z"), w.z, "a tooth number") {
            Some(z) => teeth_from(check, &k("z"), z, 4),
            None => 5,
        };
        let module = w.module.map(|m| module_mm(check, &k("module"), m));
        let shaft = check.name(&k("shaft"), w.shaft.as_ref());
        let idx = shafts.iter().position(|s| *s == shaft).unwrap_or_else(|| {
            shafts.push(shaft.clone());
            shafts.len() - 1
        });
        wheels.push(Wheel {
            name,
            z: f64::from(z),
            shaft: idx,
            internal: w.internal.unwrap_or(false),
            module,
        });
    }
    (shafts, wheels)
}

/// A differential's second input (`input2` with `n_input2`, rpm, and `n_input`): its shaft and
/// its ω per unit ω_in; refused when it is the input, the output or the fixed shaft, or a
/// speed is missing.
fn second_input(
    check: &mut Checker,
    raw: &RawPlanetary,
    [input, output, fixed, input2]: [Option<usize>; 4],
    n_input: Option<f64>,
) -> Option<(usize, f64)> {
    let Some(k) = input2 else {
        if raw.n_input2.is_some() {
            check.push(
                key("input2"),
                None,
                "missing: expected the second input's shaft for n_input2",
            );
        }
        return None;
    };
    if [input, output, fixed].contains(&Some(k)) {
        check.push(
            key("input2"),
            raw.input2.as_ref().map(|s| format!("{s:?}")),
            "expected a shaft other than the input, the output and the fixed shaft",
        );
        return None;
    }
    let Some(n2) = raw.n_input2 else {
        check.push(
            key("n_input2"),
            None,
            "missing: expected the second input's speed in rpm",
        );
        return None;
    };
    let n2 = check.bounded(&key("n_input2"), n2, 1e6, "a speed in rpm within ±1e6");
    let Some(n1) = n_input else {
        check.push(
            key("n_input"),
            None,
            "missing: expected the first input's speed in rpm (a differential has two given speeds)",
        );
        return None;
    };
    (n1 != 0.0).then_some((k, n2 / n1))
}

/// `[[planetary.mesh]]`: two different wheels by name, not both internal.
fn meshes(check: &mut Checker, raw: &RawPlanetary, wheels: &[Wheel]) -> Vec<Mesh> {
    let mut meshes = Vec::new();
    for (i, m) in raw.mesh.iter().enumerate() {
        let k = join(&item(&key("mesh"), i), "wheels");
        match m.wheels.as_deref() {
            Some([a, b]) => {
                let find = |n: &str| wheels.iter().position(|w: &Wheel| w.name == n);
                match (find(a), find(b)) {
                    (Some(x), Some(y)) if x != y && !(wheels[x].internal && wheels[y].internal) => {
                        meshes.push(Mesh(x, y))
                    }
                    _ => check.push(
                        &k,
                        Some(format!("{:?}", [a, b])),
                        "expected two different wheels of [[planetary.wheel]], not both internal",
                    ),
                }
            }
            other => check.push(
                &k,
                other.map(|v| format!("{v:?}")),
                "expected two wheel names [a, b]",
            ),
        }
    }
    meshes
}

/// The shaft named `v` at key `k`: one of the wheels' shafts, or (with `add`) a new one.
fn shaft_of(
    check: &mut Checker,
    shafts: &mut Vec<String>,
    k: &str,
    v: Option<&String>,
    add: bool,
) -> Option<usize> {
    let v = v?;
    match shafts.iter().position(|s| s == v) {
        Some(i) => Some(i),
        None if add => {
            shafts.push(v.clone());
            Some(shafts.len() - 1)
        }
        None => {
            check.push(
                k,
                Some(format!("{v:?}")),
                "expected the shaft of a [[planetary.wheel]]",
            );
            None
        }
    }
}

/// The input's speed (rpm, not 0), the required output speed (rpm) and the number of
/// satellites (1 to 12), each when given.
fn speeds(check: &mut Checker, raw: &RawPlanetary) -> (Option<f64>, Option<f64>, Option<u32>) {
    let n_input = raw.n_input.map(|n| {
        let n = check.bounded(&key("n_input"), n, 1e6, "a speed in rpm within ±1e6, not 0");
        if n == 0.0 {
            check.push(
                key("n_input"),
                Some("0".into()),
                "expected a speed in rpm within ±1e6, not 0 (the input turns)",
            );
        }
        n
    });
    let n_output = raw.n_output.map(|n| {
        check.in_range(
            &key("n_output"),
            n,
            1e6,
            "a required output speed > 0 rpm, at most 1e6",
        )
    });
    let count = raw.count.and_then(|c| match u32::try_from(c) {
        Ok(k) if (1..=12).contains(&k) => Some(k),
        _ => {
            check.push(
                key("count"),
                Some(c.to_string()),
                "expected 1 to 12 satellites",
            );
            None
        }
    });
    (n_input, n_output, count)
}

/// The train has the mobility of its inputs and can be drawn (coaxial, or with
/// `closing_module` closed by [`Train::closing`]); otherwise refused under the key that makes
/// it so. A train that is not coaxial at its one module but that the closing module would
/// draw is refused with the key that asks for it.
fn drawable(check: &mut Checker, raw: &RawPlanetary, train: &Train, closing: bool) -> bool {
    let drawn = |closing: bool| {
        if closing {
            train.closing().map(|_| ())
        } else {
            train.layout().map(|_| ())
        }
    };
    let Err(e) = train.ratio().and_then(|_| drawn(closing)) else {
        return true;
    };
    let (k, value) = match &e {
        TrainError::InputLocked { input, .. } => ("input", Some(format!("{input:?}"))),
        TrainError::OutputAtRest => ("output", raw.output.as_ref().map(|o| format!("{o:?}"))),
        TrainError::NoCarrier(_) => ("carrier", None),
        _ => ("mesh", None),
    };
    let hint = if !closing && matches!(e, TrainError::Layout(_)) && drawn(true).is_ok() {
        format!(
            "; a source that gives one module for a stage whose tooth sums do not close (seed 002 PZ2 examples 1 and 2) is drawn with `{} = true`: the satellite's mesh taken at the module that closes the carrier's arm, named in the notes",
            key("closing_module")
        )
    } else {
        String::new()
    };
    check.push(
        key(k),
        value,
        format!("a train of mobility W with W inputs that can be drawn: {e}{hint}"),
    );
    false
}

/// `[planetary.seed]`: the printed ratio (finite, not 0) and mobility (0 … 100).
fn train_seed(check: &mut Checker, raw: &RawPlanetary) -> TrainSeed {
    let Some(s) = &raw.seed else {
        return TrainSeed::default();
    };
    let k = |name: &str| join(&key("seed"), name);
    let u = s.u.and_then(|u| {
        let v = check.bounded(&k("u"), u, 1e9, "the printed ratio, within ±1e9, not 0");
        if v == 0.0 && u.is_finite() {
            check.push(
                k("u"),
                Some("0".into()),
                "expected the printed ratio, not 0",
            );
        }
        (v != 0.0).then_some(v)
    });
    let w = s.w.and_then(|w| {
        let ok = (0..=100).contains(&w);
        if !ok {
            check.push(
                k("w"),
                Some(w.to_string()),
                "expected the printed mobility, 0 to 100",
            );
        }
        ok.then_some(w)
    });
    TrainSeed { u, w }
}

/// The roles of a train's shafts must be distinct: the output is not the input, neither is
/// fixed, a carrier has satellites (and satellites a carrier), a satellite is neither the
/// carrier nor the fixed shaft.
fn distinct_shafts(
    check: &mut Checker,
    raw: &RawPlanetary,
    [input, output, fixed, carrier]: [Option<usize>; 4],
    satellites: &[usize],
) {
    let shown = |v: Option<&String>| v.map(|s| format!("{s:?}"));
    if input.is_some() && input == output {
        check.push(
            key("output"),
            shown(raw.output.as_ref()),
            "expected a shaft other than the input (a train from a shaft to itself has no ratio)",
        );
    }
    if fixed.is_some() && fixed == input {
        check.push(
            key("fixed"),
            shown(raw.fixed.as_ref()),
            "expected a shaft other than the input (a fixed input cannot drive the train)",
        );
    }
    if fixed.is_some() && fixed == output {
        check.push(
            key("fixed"),
            shown(raw.fixed.as_ref()),
            "expected a shaft other than the output (a fixed output does not turn)",
        );
    }
    match (carrier, satellites.is_empty(), raw.satellites.is_empty()) {
        (Some(_), true, true) => check.push(
            key("satellites"),
            None,
            format!(
                "missing: expected the shafts of the satellites turning on the carrier {}",
                raw.carrier.as_deref().unwrap_or_default()
            ),
        ),
        (None, false, _) => check.push(
            key("carrier"),
            None,
            "missing: expected the carrier's shaft (the satellites turn on it)",
        ),
        _ => {}
    }
    for (i, s) in raw.satellites.iter().enumerate() {
        let same = |role: Option<&String>| role == Some(s);
        if same(raw.carrier.as_ref()) || same(raw.fixed.as_ref()) {
            check.push(
                item(&key("satellites"), i),
                Some(format!("{s:?}")),
                "expected a satellite's shaft, not the carrier nor the fixed shaft",
            );
        }
    }
}
