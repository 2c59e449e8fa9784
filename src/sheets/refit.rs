//! The scale a refusal suggests, verified: a scale key can set several drawings on several
//! plates (μ_v sets every velocity plan and the Zhukovsky lever), so the value at which the
//! first drawing that overflows would fit need not fit the others. The suggestion is set on
//! the loaded scene ([`Scene::with_scale`]: its values validated again, no text read) and
//! every plate built again, raising it while any drawing at that key still overflows.

use super::{build_all, BuildError};
use crate::construct::Drafting;
use crate::scale::{Key, Lang, Scale};
use crate::scene::{RescaleError, Scene};
use crate::study::Session;

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
    /// The scene has no one value of the key to set, or no fit was found in [`MAX_TRIES`]
    /// rebuilds: the suggestion stands unverified.
    Unverified,
}

/// The scale `key` must take for every plate of `scene` to hold its drawings, starting from
/// the suggestion `first`.
pub fn verified_fit(scene: &Scene, key: Key, first: Scale, drafting: Drafting, lang: Lang) -> Fit {
    let mut fit = first;
    for _ in 0..MAX_TRIES {
        let scene = match scene.with_scale(key, fit.value()) {
            Ok(scene) => scene,
            Err(RescaleError::NotOne(_)) => return Fit::Unverified,
            Err(RescaleError::Refused(_)) => return Fit::Refused,
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

#[cfg(test)]
mod tests {
    use super::{verified_fit, Fit};
    use crate::construct::Drafting;
    use crate::scale::Key;
    use crate::scale::Lang;
    use crate::scene::{self, RescaleError};
    use std::path::Path;

    /// The shaper with μ_v = 0.002 (m/s)/mm, read from a text under a file name that does not
    /// exist: nothing but the loaded scene can serve its refit.
    fn too_fine_shaper() -> (String, scene::Scene) {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/constructions/shaper.toml");
        let text = std::fs::read_to_string(path)
            .expect("shaper")
            .replace("scale_v = 0.05 ", "scale_v = 0.002 ");
        let s = scene::parse(&text, Path::new("/nowhere/big.toml")).expect("scene");
        (text, s)
    }

    /// The scene at another value of a key is the scene the text with that value reads as
    /// (the file's route, an independent oracle); a value out of the key's range is refused
    /// as the file's would be; a key given per rack has no one value.
    #[test]
    fn a_scene_at_another_scale_is_the_scene_its_text_would_give() {
        let (text, s) = too_fine_shaper();
        let path = Path::new("/nowhere/big.toml");
        for v in ["0.025", "0.5"] {
            let written = text.replace("scale_v = 0.002 ", &format!("scale_v = {v} "));
            let want = scene::parse(&written, path).expect("scene");
            let value: f64 = v.parse().expect("number");
            let got = s
                .with_scale(Key::KinematicsScaleV, value)
                .expect("rescaled");
            assert_eq!(got, want, "{v}");
        }
        let refused = s.with_scale(Key::KinematicsScaleV, 1e40);
        assert!(
            matches!(refused, Err(RescaleError::Refused(_))),
            "{refused:?}"
        );
        let rack = s.with_scale(Key::GearsRackScaleL, 0.001);
        assert!(matches!(rack, Err(RescaleError::NotOne(_))), "{rack:?}");
    }

    /// A too-large scene rendered: its refit verifies 0.025 (every velocity plan and the
    /// lever fit; 0.01, the first suggestion, fits the plans only) without reading its text
    /// again — no scene text parsed after load, and its file need not exist.
    #[test]
    fn the_refit_parses_no_scene_text() {
        let (_, s) = too_fine_shaper();
        let before = scene::PARSES.with(std::cell::Cell::get);
        let err = crate::render::plates(&s, Lang::Ru, Drafting::EXACT).expect_err("too large");
        assert_eq!(
            scene::PARSES.with(std::cell::Cell::get),
            before,
            "parsed after load"
        );
        let crate::render::RenderError::Build {
            error:
                crate::sheets::BuildError::TooLarge {
                    fits: Some((key, fit)),
                    ..
                },
            ..
        } = err
        else {
            panic!("too large: {err}");
        };
        assert_eq!(key.key, Key::KinematicsScaleV);
        assert_eq!(fit.value(), 0.025);
        // From the given scale itself: raised the same way.
        assert_eq!(
            verified_fit(&s, key.key, key.scale, Drafting::EXACT, Lang::Ru),
            Fit::Verified(fit)
        );
    }
}
