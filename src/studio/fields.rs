//! The studio's form: every value a scene's text sets, as a field with the meaning, unit and
//! default that the scene reference (`constructions/README.md`, embedded) documents for its
//! key; and one field set in the text, its comments and layout kept.

use serde::Serialize;
use std::collections::HashMap;
use std::sync::OnceLock;
use toml_edit::{DocumentMut, Item, Value};

/// The scene reference, whose tables document every key.
const REFERENCE: &str = include_str!("../../constructions/README.md");

/// Units a meaning names among its comma-separated parts (`crank length, mm, > 0`).
const UNITS: &[&str] = &[
    "mm",
    "degrees",
    "rad/s",
    "rpm",
    "kg",
    "kg·m²",
    "N",
    "N·m",
    "m/mm",
    "m/s²",
    "N/mm",
    "rad/mm",
    "(m/s)/mm",
    "(m/s²)/mm",
    "s",
    "Hz",
    "W",
    "J",
    "MPa",
    "bar",
];

/// A field of the form.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Field {
    /// The key path as the scene's messages write it (`mechanism.group[1].la`).
    pub key: String,
    /// The table it is in (`mechanism.group[1]`), the form's group.
    pub section: String,
    /// The value as written in the text (`140`, `"cw"`, `[0, 0]`).
    pub value: String,
    /// Whether the value is a number (the form offers a number box).
    pub number: bool,
    /// What the reference says the key is, with its range (empty when undocumented).
    pub meaning: String,
    /// Its unit, when the reference names one.
    pub unit: String,
    /// Its default as the reference gives it.
    pub default: String,
}

/// Why a field cannot be set.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FieldError {
    /// The text is not TOML.
    #[error("the scene is not TOML: {0}")]
    NotToml(String),
    /// The key is not a value of the text.
    #[error("{0}: no such value in the scene")]
    NoKey(String),
}

/// A documented key: its meaning, unit and default.
#[derive(Debug, Clone, Default)]
struct Doc {
    meaning: String,
    unit: String,
    default: String,
}

/// The reference's tables, by the key path without indices (`mechanism.group.la`).
fn reference() -> &'static HashMap<String, Doc> {
    static DOCS: OnceLock<HashMap<String, Doc>> = OnceLock::new();
    DOCS.get_or_init(|| parse_reference(REFERENCE))
}

/// The documented keys of a reference in the scene README's form: a heading naming its
/// table (`### \`[[mechanism.fixed]]\` — …`), then rows `| \`key\` | meaning | default |`
/// (or `| key | meaning | unit |`).
fn parse_reference(text: &str) -> HashMap<String, Doc> {
    let mut out = HashMap::new();
    let (mut table, mut third_is_unit) = (String::new(), false);
    for line in text.lines() {
        if line.starts_with('#') {
            if let Some(t) = line.split('`').nth(1) {
                table = t.trim_matches(|c| c == '[' || c == ']').to_string();
            }
            continue;
        }
        let cells: Vec<&str> = line
            .split(" | ")
            .map(|c| c.trim_matches('|').trim())
            .collect();
        if cells.len() < 3 {
            continue;
        }
        if cells[0] == "key" {
            third_is_unit = cells[2] == "unit";
            continue;
        }
        let Some(key) = cells[0].strip_prefix('`').and_then(|k| k.strip_suffix('`')) else {
            continue;
        };
        // The form shows the text plain: no Markdown code marks.
        let meaning = cells[1].replace("\\|", "|").replace('`', "");
        let third = cells[2].replace('`', "");
        let (unit, default) = match third_is_unit {
            true => (third, String::new()),
            false => (unit_of(&meaning), third),
        };
        let path = if table.is_empty() {
            key.to_string()
        } else {
            format!("{table}.{key}")
        };
        out.insert(
            path,
            Doc {
                meaning,
                unit,
                default,
            },
        );
    }
    out
}

/// The unit a meaning names, or empty.
fn unit_of(meaning: &str) -> String {
    meaning
        .split(", ")
        .map(str::trim)
        .find(|p| UNITS.contains(p))
        .unwrap_or_default()
        .to_string()
}

/// `mechanism.group[1].la` without its indices: `mechanism.group.la`.
fn unindexed(key: &str) -> String {
    let mut out = String::with_capacity(key.len());
    let mut depth = 0;
    for c in key.chars() {
        match c {
            '[' => depth += 1,
            ']' => depth -= 1,
            _ if depth == 0 => out.push(c),
            _ => {}
        }
    }
    out
}

/// Every value the scene text sets, in the text's order.
///
/// # Errors
/// The text is not TOML.
pub fn fields(text: &str) -> Result<Vec<Field>, FieldError> {
    let doc: DocumentMut = text
        .parse()
        .map_err(|e: toml_edit::TomlError| FieldError::NotToml(e.message().to_string()))?;
    let mut out = Vec::new();
    walk_table(doc.as_table(), "", &mut out);
    Ok(out)
}

fn join(section: &str, key: &str) -> String {
    if section.is_empty() {
        key.to_string()
    } else {
        format!("{section}.{key}")
    }
}

fn walk_table(t: &toml_edit::Table, section: &str, out: &mut Vec<Field>) {
    for (k, item) in t.iter() {
        let path = join(section, k);
        match item {
            Item::Table(t) => walk_table(t, &path, out),
            Item::ArrayOfTables(a) => {
                for (i, t) in a.iter().enumerate() {
                    walk_table(t, &format!("{path}[{i}]"), out);
                }
            }
            Item::Value(Value::InlineTable(t)) => {
                for (k, v) in t.iter() {
                    push(out, section, &join(&path, k), v);
                }
            }
            Item::Value(v) => push(out, section, &path, v),
            Item::None => {}
        }
    }
}

fn push(out: &mut Vec<Field>, section: &str, key: &str, v: &Value) {
    let doc = reference()
        .get(&unindexed(key))
        .cloned()
        .unwrap_or_default();
    // The value alone: without the spaces and the comment around it in the text.
    let mut bare = v.clone();
    bare.decor_mut().clear();
    out.push(Field {
        key: key.to_string(),
        section: section.to_string(),
        value: bare.to_string(),
        number: matches!(v, Value::Integer(_) | Value::Float(_)),
        meaning: doc.meaning,
        unit: doc.unit,
        default: doc.default,
    });
}

/// The text with the value of `key` (a path as [`Field::key`]) set to `value` — read as a
/// TOML value (`140`, `"cw"`, `[0, 0]`), else taken as a string — its comments kept.
///
/// # Errors
/// The text is not TOML, or it sets no value at `key`.
pub fn set(text: &str, key: &str, value: &str) -> Result<String, FieldError> {
    let mut doc: DocumentMut = text
        .parse()
        .map_err(|e: toml_edit::TomlError| FieldError::NotToml(e.message().to_string()))?;
    let no_key = || FieldError::NoKey(key.to_string());
    let slot = find(doc.as_table_mut(), key).ok_or_else(no_key)?;
    let mut new: Value = value
        .trim()
        .parse()
        .unwrap_or_else(|_| Value::from(value.trim()));
    // A length written `140.0` typed as `150` stays a float.
    if let (Value::Float(_), Value::Integer(i)) = (&*slot, &new) {
        new = Value::from(*i.value() as f64);
    }
    *new.decor_mut() = slot.decor().clone();
    *slot = new;
    Ok(doc.to_string())
}

/// The value at `key` in `t`.
fn find<'a>(t: &'a mut toml_edit::Table, key: &str) -> Option<&'a mut Value> {
    let (head, rest) = match key.split_once('.') {
        Some((h, r)) => (h, Some(r)),
        None => (key, None),
    };
    let (name, index) = match head.split_once('[') {
        Some((n, i)) => (n, Some(i.trim_end_matches(']').parse::<usize>().ok()?)),
        None => (head, None),
    };
    let item = t.get_mut(name)?;
    match (item, index, rest) {
        (Item::Table(t), None, Some(rest)) => find(t, rest),
        (Item::ArrayOfTables(a), Some(i), Some(rest)) => find(a.get_mut(i)?, rest),
        (Item::Value(Value::InlineTable(t)), None, Some(rest)) => {
            let v = t.get_mut(rest)?;
            (!v.is_inline_table()).then_some(v)
        }
        (Item::Value(v), None, None) if !v.is_inline_table() => Some(v),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_documents_the_crank_with_its_unit() {
        let d = &reference()["mechanism.crank.length"];
        assert_eq!(d.unit, "mm");
        assert!(d.meaning.contains("> 0"), "{}", d.meaning);
        assert_eq!(d.default, "required");
        assert_eq!(reference()["kinematics.scale_v"].unit, "(m/s)/mm");
    }

    #[test]
    fn every_value_of_the_shaper_is_a_field_and_one_is_set_keeping_comments() {
        let text = crate::studio::gallery::text("shaper").expect("shipped");
        let all = fields(text).expect("toml");
        let crank = all
            .iter()
            .find(|f| f.key == "mechanism.crank.length")
            .expect("crank");
        assert!(crank.number && crank.unit == "mm", "{crank:?}");
        let la = all
            .iter()
            .find(|f| f.key.starts_with("mechanism.group[1]."));
        assert!(la.is_some(), "an array table's index in the key");
        let changed = set(text, "mechanism.crank.length", "150").expect("set");
        let again = fields(&changed).expect("toml");
        let crank = again
            .iter()
            .find(|f| f.key == "mechanism.crank.length")
            .expect("crank");
        assert_eq!(crank.value, "150.0", "a float stays a float");
        assert_eq!(
            changed.matches('#').count(),
            text.matches('#').count(),
            "comments kept"
        );
        assert_eq!(
            set(text, "mechanism.crank.nope", "1"),
            Err(FieldError::NoKey("mechanism.crank.nope".into()))
        );
    }
}
