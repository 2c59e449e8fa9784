//! The scale a refusal suggests, verified: a scale key can set several drawings on several
//! plates (μ_v sets every velocity plan and the Zhukovsky lever), so the value at which the
//! first drawing that overflows would fit need not fit the others. The suggestion is applied to
//! the scene's text and every plate built again, raising it while any drawing at that key
//! still overflows.

use super::{build_all, BuildError};
use crate::construct::Drafting;
use crate::scale::{Lang, Scale};
use crate::scene::Key;
use crate::study::Session;
use std::path::Path;

/// At most this many rebuilds with a raised scale.
const MAX_TRIES: usize = 8;

/// What a suggested scale comes to when the scene is built again with it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fit {
    /// Every plate holds its drawings at this scale.
    Verified(Scale),
    /// The scene refuses the scale at load (outside the key's range): no scale the scene
    /// accepts fits, the drawing is too large by its other data.
    Refused,
    /// The key cannot be set in the text, or no fit was found in [`MAX_TRIES`] rebuilds:
    /// the suggestion stands unverified.
    Unverified,
}

/// The scale `key` must take for every plate of the scene (`text`, read from `path`) to hold
/// its drawings, starting from the suggestion `first`.
pub fn verified_fit(
    text: &str,
    path: &Path,
    key: Key,
    first: Scale,
    drafting: Drafting,
    lang: Lang,
) -> Fit {
    let Ok(mut table) = text.parse::<toml::Table>() else {
        return Fit::Unverified;
    };
    let mut fit = first;
    for _ in 0..MAX_TRIES {
        let Some(text) =
            set(&mut table, key.path(), fit.value()).and_then(|()| toml::to_string(&table).ok())
        else {
            return Fit::Unverified;
        };
        let Ok(scene) = crate::scene::parse(&text, path) else {
            return Fit::Refused;
        };
        match build_all(&Session::new(&scene, drafting), lang) {
            Err((
                _,
                BuildError::TooLarge {
                    fits: Some((k, next)),
                    ..
                },
            )) if k.key == key && next.value() > fit.value() => {
                fit = next;
            }
            // Every drawing at this key fits (another failure is another key's or another
            // construction's).
            _ => return Fit::Verified(fit),
        }
    }
    Fit::Unverified
}

/// Set the number at the dotted `key` (`kinematics.scale_v`, `gears.rack[1].scale_l`) of a
/// scene's table; `None` when the path does not lead to a table.
fn set(table: &mut toml::Table, key: &str, value: f64) -> Option<()> {
    let mut parts: Vec<&str> = key.split('.').collect();
    let last = parts.pop()?;
    let mut at = table;
    for part in parts {
        let (name, index) = match part.split_once('[') {
            Some((name, rest)) => (name, Some(rest.strip_suffix(']')?.parse::<usize>().ok()?)),
            None => (part, None),
        };
        let entry = at
            .entry(name)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        at = match index {
            None => entry.as_table_mut()?,
            Some(i) => entry.as_array_mut()?.get_mut(i)?.as_table_mut()?,
        };
    }
    at.insert(last.to_string(), toml::Value::Float(value));
    Some(())
}

#[cfg(test)]
mod tests {
    use super::set;
    use crate::scene::Key;

    #[test]
    fn a_dotted_key_is_set_in_tables_and_arrays_of_tables() {
        let mut t: toml::Table =
            "[kinematics]\nscale_v = 1.0\n[[gears.rack]]\nz = 13\n[[gears.rack]]\nz = 20\n"
                .parse()
                .expect("toml");
        set(&mut t, Key::KinematicsScaleV.path(), 0.5).expect("set");
        set(&mut t, "gears.rack[1].scale_l", 0.25).expect("set");
        set(&mut t, Key::ForcesScaleF.path(), 4.0).expect("a new table");
        assert_eq!(t["kinematics"]["scale_v"].as_float(), Some(0.5));
        assert_eq!(t["gears"]["rack"][1]["scale_l"].as_float(), Some(0.25));
        assert!(t["gears"]["rack"][0].get("scale_l").is_none());
        assert_eq!(t["forces"]["scale_f"].as_float(), Some(4.0));
        assert!(set(&mut t, "gears.rack[5].scale_l", 1.0).is_none());
    }
}
