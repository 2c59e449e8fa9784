//! Reading a scene file: TOML → raw structs → one validation pass → [`Scene`].

use super::balancing::balancing;
use super::cam::cam;
use super::check::{item, quoted, Checker};
use super::dynamics::dynamics;
use super::error::{Problem, SceneError};
use super::forces::forces;
use super::friction::friction;
use super::gears::gear_sections;
use super::kinematics::kinematics;
use super::model::{AnswerItem, PlateKind, PositionSpec, Scene, Section, Start};
use super::raw::{RawPlates, RawPositions, RawScene, RawStart};
use super::source::Source;
use super::structure::mechanism;
use super::studies::{default_plates, plates_of, study_of, Study, STUDIES};
use super::text::{not_text, refused};
use super::toml_error::toml_error;
use crate::scale::{Key, Quantity, Scale};
use serde::Deserialize as _;
use std::path::Path;
use toml::de::{DeTable, DeValue};

/// The scene files (`*.toml`) of `dir`, sorted; an entry that cannot be read is passed over.
///
/// # Errors
/// The folder cannot be read.
pub fn files_in(dir: &Path) -> std::io::Result<Vec<std::path::PathBuf>> {
    let mut files: Vec<_> = std::fs::read_dir(dir)?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    Ok(files)
}

/// The default number of crank positions.
const DEFAULT_COUNT: i64 = 12;
/// The most crank positions a scene may ask for (one per degree).
const MAX_COUNT: i64 = 360;
/// The word for the extreme position that begins the working stroke.
const WORKING_STROKE: &str = "working-stroke";

/// The largest scene file, bytes (1 MiB; the largest scene of `constructions/` is 9 KiB).
pub const MAX_SCENE_BYTES: u64 = 1 << 20;

/// Read and validate the scene file at `path` (at most `MAX_SCENE_BYTES`: a larger file,
/// or an endless one such as `/dev/zero`, is refused after reading one byte more).
///
/// Lengths in the file are millimetres, angles degrees, `omega` rad/s or `n` rpm; the
/// [`Scene`] holds metres and radians. Every problem is reported with the file, the key path,
/// the value and what was expected (see `constructions/README.md` for the format).
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    parse(&read(path)?, path)
}

/// The text of the file at `path`, at most [`MAX_SCENE_BYTES`] of UTF-8 (a scene, or a
/// variant grid of `tmm batch`).
///
/// # Errors
/// [`SceneError::Read`] when it cannot be read or is not UTF-8; [`SceneError::TooLarge`].
pub fn read(path: &Path) -> Result<String, SceneError> {
    use std::io::Read as _;
    let read_err = |source| SceneError::Read {
        path: path.to_path_buf(),
        source,
    };
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(MAX_SCENE_BYTES + 1).read_to_end(&mut bytes))
        .map_err(read_err)?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(SceneError::TooLarge {
            path: path.to_path_buf(),
            limit: MAX_SCENE_BYTES,
        });
    }
    String::from_utf8(bytes).map_err(|e| {
        let byte = e.utf8_error().valid_up_to();
        let before = e.as_bytes().get(..byte).unwrap_or_default();
        let line = 1 + before.iter().filter(|b| **b == b'\n').count();
        SceneError::NotUtf8 {
            path: path.to_path_buf(),
            line,
            byte,
        }
    })
}

/// Validate the scene text `text`; `path` names it in messages and gives the default title
/// (the file stem).
///
/// The text is read as TOML once: its texts are checked on the document read (every string
/// and key, wherever it stands), and the document, with the places of its values, becomes the
/// raw scene, so that a bad key or value is reported at its line and column.
pub fn parse(text: &str, path: &Path) -> Result<Scene, SceneError> {
    #[cfg(test)]
    PARSES.with(|n| n.set(n.get() + 1));
    let document = toml::de::DeTable::parse(text).map_err(|e| toml_error(text, path, &e))?;
    // Every text (names, titles, notes, words) becomes SVG text: no control characters.
    let mut check = Checker::default();
    texts(&mut check, "", document.get_ref());
    let raw = RawScene::deserialize(toml::de::Deserializer::from(document))
        .map_err(|e| toml_error(text, path, &e))?;
    validate(check, raw, path)
}

#[cfg(test)]
thread_local! {
    /// How many scene texts [`parse`] has read on this thread: the tests count the readings
    /// after a scene is loaded (none).
    pub(crate) static PARSES: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// The scene of the raw values `raw` of the file `path`, validated (`check` holds what the
/// reading found already). The scene keeps `raw` as its [`Source`], for the same scene at
/// another scale ([`Scene::with_scale`]).
pub(super) fn validate(
    mut check: Checker,
    raw: RawScene,
    path: &Path,
) -> Result<Scene, SceneError> {
    let source = Source::new(raw.clone());
    // The sections of the studies the file has, each asked of its row once.
    let studied: Vec<Section> = STUDIES
        .iter()
        .filter(|s| (s.present)(&raw))
        .map(|s| s.section)
        .collect();
    let stem = path
        .file_stem()
        .map_or_else(|| "scene".to_string(), |s| s.to_string_lossy().into_owned());
    let task = raw.task.unwrap_or_default();
    if task.title.is_none() && stem.chars().any(not_text) {
        check.push(
            "task.title",
            Some(quoted(&stem)),
            "missing: the title defaults to the file name, which holds a control character; expected a title",
        );
    }
    let title = super::task::title(&mut check, task, &stem);
    // Every section is optional; a section that studies the mechanism needs `[mechanism]`.
    let has_mechanism = raw.mechanism.is_some();
    if !has_mechanism {
        for (section, present) in [
            ("positions", raw.positions.is_some()),
            ("kinematics", raw.kinematics.is_some()),
            ("forces", raw.forces.is_some()),
            ("dynamics", raw.dynamics.is_some()),
        ] {
            if present {
                check.push(
                    section,
                    None,
                    format!("[{section}] studies a mechanism: expected a [mechanism] table"),
                );
            }
        }
    }
    let mut mechanism = raw
        .mechanism
        .as_ref()
        .and_then(|m| mechanism(&mut check, Some(m)));
    let scale_l = scale_l(&mut check, raw.mechanism.as_ref().and_then(|m| m.scale_l));
    let positions = positions(&mut check, raw.positions.unwrap_or_default());
    let has_forces = raw.forces.is_some();
    let gears = gear_sections(&mut check, raw.gears.as_ref(), raw.planetary.as_ref());
    let cam = raw.cam.as_ref().and_then(|c| cam(&mut check, c));
    let balancing = raw
        .balancing
        .as_ref()
        .and_then(|b| balancing(&mut check, b));
    let has_plates = raw.plates.is_some();
    let plates = plates(&mut check, raw.plates, STUDIES, |section| {
        studied.contains(&section)
    });
    let friction = friction(&mut check, raw.friction);
    let warnings = match &raw.kinematics {
        Some(_) if has_mechanism => undrawn_kinematics(has_plates, &plates),
        _ => Vec::new(),
    };
    let kinematics = kinematics(
        &mut check,
        raw.kinematics.unwrap_or_default(),
        mechanism.as_ref(),
        positions.count,
    );
    if let Some(m) = &mechanism {
        super::drawing::drawing_ranges(&mut check, m, scale_l, &kinematics);
    }
    let forces = raw
        .forces
        .map(|f| forces(&mut check, f, mechanism.as_ref(), positions.count));
    if let (Some(m), Some(f)) = (mechanism.as_mut(), forces.as_ref()) {
        m.driving = driving_output(m, &f.indicators);
    }
    let dynamics = raw
        .dynamics
        .map(|d| dynamics(&mut check, d, forces.as_ref(), has_forces));
    let answer_key = answer_key(&mut check, raw.answer_key.unwrap_or_default());
    let seed = raw
        .seed
        .unwrap_or_default()
        .iter()
        .enumerate()
        .filter_map(|(i, s)| super::seed::seed_value(&mut check, &format!("seed[{i}]"), s, None))
        .collect();
    if check.problems.is_empty() {
        Ok(Scene {
            path: path.to_path_buf(),
            stem,
            title,
            mechanism,
            scale_l,
            positions,
            plates,
            kinematics,
            forces,
            balancing,
            friction,
            dynamics,
            gears,
            cam,
            answer_key,
            seed,
            warnings,
            source,
        })
    } else {
        Err(SceneError::Invalid {
            path: path.to_path_buf(),
            problems: check.problems,
        })
    }
}

/// Refuse every string value under `table` (at key path `base`) that is not text
/// ([`refused`]) and every key that holds a character that is [`not_text`], naming its key.
fn texts(check: &mut Checker, base: &str, table: &DeTable<'_>) {
    for (key, value) in table {
        let key = key.get_ref();
        let path = if base.is_empty() {
            key.to_string()
        } else {
            format!("{base}.{key}")
        };
        if key.chars().any(not_text) {
            check.push(
                path.clone(),
                None,
                "expected a key without control characters",
            );
        }
        text_value(check, &path, value.get_ref());
    }
}

/// [`texts`] of one value.
fn text_value(check: &mut Checker, path: &str, value: &DeValue<'_>) {
    match value {
        DeValue::String(s) => {
            if let Some(why) = refused(s) {
                let shown: String = quoted(s).chars().take(80).collect();
                check.push(path, Some(shown), why);
            }
        }
        DeValue::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                text_value(check, &item(path, i), v.get_ref());
            }
        }
        DeValue::Table(t) => texts(check, path, t),
        _ => {}
    }
}

/// True when the mechanism's first output is a slider pushed by a `[[forces.indicator]]`: an
/// engine's piston, whose working stroke is the expansion from its outer dead centre
/// ([`crate::linkage::Program::extremes`]).
fn driving_output(m: &crate::linkage::Mechanism, indicators: &[crate::forces::Indicator]) -> bool {
    match m.outputs.first() {
        Some(crate::linkage::Output::Slider { point, .. }) => {
            indicators.iter().any(|i| &i.point == point)
        }
        _ => false,
    }
}

/// `mechanism.scale_l`, m/mm, optional.
fn scale_l(check: &mut Checker, v: Option<f64>) -> Option<Scale> {
    check.scale(
        Key::MechanismScaleL.path(),
        v,
        Quantity::Length,
        "a scale μ_l > 0 m/mm",
    )
}

/// `[positions]`.
fn positions(check: &mut Checker, raw: RawPositions) -> PositionSpec {
    let count = raw.count.unwrap_or(DEFAULT_COUNT);
    if !(1..=MAX_COUNT).contains(&count) {
        let expected = format!("expected a number of positions from 1 to {MAX_COUNT}");
        check.push("positions.count", Some(count.to_string()), expected);
    }
    let start = match raw.start {
        None => Start::WorkingStroke,
        Some(RawStart::Word(w)) if w == WORKING_STROKE => Start::WorkingStroke,
        Some(RawStart::Word(w)) => {
            let expected = format!("expected {WORKING_STROKE:?} or a crank angle in degrees");
            check.push("positions.start", Some(quoted(&w)), expected);
            Start::WorkingStroke
        }
        Some(RawStart::Degrees(d)) => Start::Angle(check.angle("positions.start", Some(d), 0.0)),
    };
    let continuity = match raw.assembly.as_deref() {
        None | Some("side") => false,
        Some("continuity") => true,
        Some(other) => {
            check.push(
                "positions.assembly",
                Some(quoted(other)),
                "expected \"side\" or \"continuity\"",
            );
            false
        }
    };
    PositionSpec {
        count: u32::try_from(count).unwrap_or(0),
        start,
        other_extreme: raw.other_extreme.unwrap_or(true),
        continuity,
    }
}

/// `[plates] wanted`, by default the default plates of every study of `table` whose section
/// the scene has (`["positions"]` for a mechanism, `["balancing"]` for a rotor, …). Every
/// plate draws from the section of the study that registers it, which `present` tells is
/// there.
pub(super) fn plates(
    check: &mut Checker,
    raw: Option<RawPlates>,
    table: &'static [Study],
    present: impl Fn(Section) -> bool,
) -> Vec<PlateKind> {
    let wanted = raw.and_then(|r| r.wanted).unwrap_or_else(|| {
        default_plates(table, &present)
            .into_iter()
            .map(|k| k.stem().to_string())
            .collect()
    });
    let mut out = Vec::new();
    for (i, stem) in wanted.iter().enumerate() {
        let row = plates_of(table)
            .find(|k| k.stem() == stem)
            .and_then(|k| study_of(table, k).map(|s| (k, s.section)));
        match row {
            Some((_, section)) if !present(section) => {
                let key = item("plates.wanted", i);
                check.push(
                    key,
                    Some(quoted(stem)),
                    format!(
                        "the {stem} plate draws from [{section}]: expected a [{section}] table"
                    ),
                );
            }
            Some((kind, _)) => out.push(kind),
            None => {
                let key = item("plates.wanted", i);
                let known: Vec<&str> = plates_of(table).map(|k| k.stem()).collect();
                let expected = format!("expected a plate kind ({})", known.join(", "));
                check.push(key, Some(quoted(stem)), expected);
            }
        }
    }
    out
}

/// `[kinematics]` that no sheet draws: the kinematics plate is not among the plates wanted
/// (`has_plates`: a `[plates]` table says so; else the default, `["positions"]`). Its scales
/// and choices still reach the report and the note, so the scene is read, with a warning.
fn undrawn_kinematics(has_plates: bool, plates: &[PlateKind]) -> Vec<Problem> {
    if plates.contains(&PlateKind::Kinematics) {
        return Vec::new();
    }
    let why = if has_plates {
        "[plates] wanted does not ask for the kinematics plate"
    } else {
        "the scene has no [plates] table, and the default plates are [\"positions\"]"
    };
    vec![Problem {
        key: "kinematics".into(),
        value: None,
        expected: format!(
            "no sheet draws it: {why}; its scales and choices reach only the report and the note: expected \"kinematics\" in [plates] wanted to draw its plans and diagrams"
        ),
    }]
}

/// `[answer_key] values`: each `quantity[@position][:method]`, every part a name of letters,
/// digits, `_`, `-` or `′` (the report's names); whether the scene's report has the row is
/// checked by `tmm batch` against the template.
fn answer_key(check: &mut Checker, raw: super::raw::RawAnswerKey) -> Vec<AnswerItem> {
    let word = |s: &str| {
        !s.is_empty()
            && s.chars()
                .all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '′'))
    };
    let mut items = Vec::new();
    for (k, value) in raw.values.iter().enumerate() {
        let (rest, method) = match value.split_once(':') {
            Some((r, m)) => (r, Some(m)),
            None => (value.as_str(), None),
        };
        let (quantity, position) = match rest.split_once('@') {
            Some((q, p)) => (q, Some(p)),
            None => (rest, None),
        };
        if !word(quantity) || !position.is_none_or(word) || !method.is_none_or(word) {
            check.push(
                format!("answer_key.values[{k}]"),
                Some(quoted(value)),
                "a report row as quantity[@position][:method], e.g. \"v_E@3\", \"M_bal@3:lever\", \"r_min\"",
            );
            continue;
        }
        let item = AnswerItem {
            quantity: quantity.into(),
            position: position.map(Into::into),
            method: method.map(Into::into),
        };
        if items.contains(&item) {
            check.push(
                format!("answer_key.values[{k}]"),
                Some(quoted(value)),
                "each value once",
            );
            continue;
        }
        items.push(item);
    }
    items
}
